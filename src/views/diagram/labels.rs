//! The labels of a ray diagram: what each wants to name (points, objects,
//! angles, badges), what they must not cover, and drawing them once placed by
//! [`crate::figure::labels`].

use glam::DVec2;

use crate::figure::canvas::Figure;
use crate::figure::clip::clip_line;
use crate::figure::labels::{Label, Placed, PxRect, Target};
use crate::figure::pen::Rgb;
use crate::figure::pen::palette;
use crate::scene::Scene;
use crate::views::diagram::layout::Layout;
use crate::views::diagram::options::{Labels, Options};
use crate::views::diagram::projection::Outline;
use crate::views::diagram::reveal::Reveal;
use crate::views::diagram::style::Scale;
use crate::views::diagram::style::Stroke;
use crate::views::numbers::num;

/// Every label the figure wants, most important first.
pub(super) fn label_requests(
    fig: &Figure,
    scene: &Scene,
    lay: &Layout,
    options: &Options,
    scale: &Scale,
    offscreen: Vec<(DVec2, String)>,
    reveal: &Reveal,
) -> Vec<Label> {
    let size = scale.text;
    let text = |t: String, color: Rgb, target: Target| Label {
        text: t,
        size,
        color,
        target,
        boxed: false,
        optional: false,
        tag: String::new(),
    };
    let point = |p: DVec2, r: f64| Target::Point {
        at: fig.to_px(p),
        clearance: scale.px(r),
    };
    let mut out = Vec::new();
    if options.labels == Labels::None {
        return out;
    }
    for t in &lay.marks.tir {
        out.push(Label {
            boxed: true,
            size: size - 1.0,
            tag: reveal.label(t.node, true),
            ..text(t.text.clone(), palette::REFRACTED, point(t.at, 8.0))
        });
    }
    if options.labels == Labels::All {
        for (k, h) in lay.hits.iter().enumerate() {
            if fig.shows(h.at) {
                out.push(Label {
                    tag: reveal.label(h.node, true),
                    ..text(format!("P{}", k + 1), palette::INK, point(h.at, 5.0))
                });
            }
        }
        for b in &lay.marks.boundaries {
            // Each index on its own side of the boundary, along the normal.
            for (label, side) in [(&b.n1, 1.0), (&b.n2, -1.0)] {
                let at =
                    fig.to_px(b.at) + DVec2::new(b.normal.x, -b.normal.y) * side * scale.px(58.0);
                // An index belongs on its own side: left out rather than led
                // across the boundary when that side has no room.
                out.push(Label {
                    size: size - 2.0,
                    optional: true,
                    tag: reveal.label(b.node, true),
                    ..text(
                        label.clone(),
                        palette::OBJECT,
                        Target::Point {
                            at,
                            clearance: scale.px(2.0),
                        },
                    )
                });
            }
        }
        for a in &lay.marks.angles {
            let mid = (a.from + a.to).normalize_or(a.to);
            let at = fig.to_px(a.at) + DVec2::new(mid.x, -mid.y) * scale.px(30.0);
            out.push(Label {
                size: size - 2.0,
                tag: reveal.label(a.node, true),
                ..text(
                    a.label.clone(),
                    palette::INK,
                    Target::Point {
                        at,
                        clearance: scale.px(3.0),
                    },
                )
            });
        }
    }
    for (light, &p) in scene.lights.iter().zip(&lay.lights) {
        if fig.shows(p) {
            out.push(text(light.name.clone(), palette::INK, point(p, 14.0)));
        }
    }
    for (at, name) in offscreen {
        out.push(text(
            name,
            palette::INK,
            Target::Point {
                at,
                clearance: scale.px(6.0),
            },
        ));
    }
    if fig.shows(lay.eye) {
        out.push(text("eye".to_owned(), palette::INK, point(lay.eye, 6.0)));
    }
    if let Some((a, b, _)) = lay.image_plane {
        let end = if fig.shows(a) { a } else { b };
        if fig.shows(end) {
            out.push(Label {
                size: size - 2.0,
                ..text("image plane".to_owned(), palette::INK, point(end, 3.0))
            });
        }
    }
    out.extend(object_labels(fig, scene, lay, size));
    for t in &lay.marks.ticks {
        out.push(Label {
            size: size - 4.0,
            optional: true,
            tag: reveal.label(t.node, false),
            ..text(t.label.clone(), palette::INK, point(t.at, 5.0))
        });
    }
    for r in &lay.marks.roots {
        // Its open dot stays: where many bounces repeat the same roots, the
        // words that would need a leader across the crowd are left out.
        out.push(Label {
            size: size - 3.0,
            optional: true,
            tag: reveal.label(r.node, true),
            ..text(r.label.clone(), palette::INK, point(r.at, 5.0))
        });
    }
    for s in &lay.marks.steps {
        out.push(Label {
            size: size - 3.0,
            optional: true,
            boxed: true,
            ..text(s.number.to_string(), palette::INK, point(s.at, 6.0))
        });
    }
    for &(i, gap, on_ray, on_object) in &lay.near_misses {
        out.push(text(
            format!("misses '{}' by {}", scene.objects[i].name, num(gap)),
            palette::SHADOW_BLOCKED,
            point((on_ray + on_object) / 2.0, 3.0),
        ));
    }
    out
}

/// Labels for the objects worth naming: those the tree touches, and the rest
/// too when there are few; each touches its own outline where it is in the frame.
pub(super) fn object_labels(fig: &Figure, scene: &Scene, lay: &Layout, size: f32) -> Vec<Label> {
    let (vlo, vhi) = fig.visible();
    let few = lay
        .objects
        .iter()
        .filter(|o| o.silhouette.bounds().is_some())
        .count()
        <= 12;
    let mut out = Vec::new();
    for shape in &lay.objects {
        let object = &scene.objects[shape.object];
        if !(shape.touched || few) {
            continue;
        }
        let outline = shape.section.as_ref().unwrap_or(&shape.silhouette);
        let samples: Vec<DVec2> = match outline {
            Outline::Ellipse { center, axes } => (0..24)
                .map(|k| {
                    // From the top-left round, so names sit above-left where rays arrive least.
                    let t = std::f64::consts::TAU * f64::from(k) / 24.0 + 2.2;
                    *center + t.cos() * axes[0] + t.sin() * axes[1]
                })
                .collect(),
            Outline::Polygon { points } => points.clone(),
            Outline::Segments { segments } => segments.iter().take(24).map(|s| s[0]).collect(),
            Outline::Line { point, dir, .. } => clip_line(*point, *dir, vlo, vhi)
                .map(|(a, b)| (1..8).map(|k| a + (b - a) * (f64::from(k) / 8.0)).collect())
                .unwrap_or_default(),
            Outline::Parallel => Vec::new(),
        };
        let inside: Vec<DVec2> = samples
            .iter()
            .copied()
            .filter(|p| p.cmpge(vlo).all() && p.cmple(vhi).all())
            .collect();
        if inside.is_empty() {
            continue;
        }
        let center = match outline {
            Outline::Line { outward, .. } => {
                inside[inside.len() / 2] - *outward * (vhi - vlo).length()
            }
            _ => outline
                .bounds()
                .map_or(inside[0], |(lo, hi)| (lo + hi) / 2.0),
        };
        out.push(Label {
            text: object.name.clone(),
            size,
            color: palette::OBJECT,
            target: Target::Outline {
                points: inside.iter().map(|&p| fig.to_px(p)).collect(),
                inside: fig.to_px(center),
            },
            boxed: false,
            optional: false,
            tag: String::new(),
        });
    }
    out
}

/// What a label must not cover: the legend, dots, lights, arrowheads, crosses,
/// the ticks along the rays and the other roots' open dots.
pub(super) fn blocked(fig: &Figure, lay: &Layout, legend: PxRect, scale: &Scale) -> Vec<PxRect> {
    let mut out = vec![legend];
    let dot = |p: DVec2, r: f64| PxRect::around(fig.to_px(p), scale.px(r));
    out.extend(lay.hits.iter().map(|h| dot(h.at, 6.0)));
    out.extend(lay.marks.ticks.iter().map(|t| dot(t.at, 4.0)));
    out.extend(lay.marks.roots.iter().map(|r| dot(r.at, 4.5)));
    out.extend(lay.lights.iter().map(|&p| dot(p, 14.0)));
    out.push(dot(lay.eye, 6.0));
    out.extend(lay.marks.blocked.iter().map(|b| dot(b.at, 7.0)));
    for s in lay
        .segments
        .iter()
        .filter(|s| s.stroke.arrow() && !s.leaves)
    {
        out.push(dot(s.to, 9.0));
    }
    let normal_length = scale.px(45.0) / fig.scale();
    out.extend(
        lay.hits
            .iter()
            .map(|h| dot(h.at + h.normal * normal_length, 7.0)),
    );
    out
}

/// The drawn lines in pixels, which labels would rather not cover, each with
/// how much covering it costs: the rays and the angle arcs most, the edges of
/// what the drawing plane cuts of each object less, shadow rays least.
pub(super) fn lines_px(fig: &Figure, lay: &Layout, scale: &Scale) -> Vec<([DVec2; 2], usize)> {
    let (ray, arc, edge, shadow) = (4, 4, 2, 1);
    let mut out: Vec<([DVec2; 2], usize)> = lay
        .segments
        .iter()
        .map(|s| {
            let w = if matches!(s.stroke, Stroke::Ray(_)) {
                ray
            } else {
                shadow
            };
            ([fig.to_px(s.from), fig.to_px(s.to)], w)
        })
        .collect();
    for a in &lay.marks.angles {
        // The arc as drawn (radius 30 at the figure's scale), in eight chords.
        let (c, r) = (fig.to_px(a.at), scale.px(30.0));
        let (from, to) = (a.from.y.atan2(a.from.x), a.to.y.atan2(a.to.x));
        let mut sweep = to - from;
        if sweep > std::f64::consts::PI {
            sweep -= std::f64::consts::TAU;
        } else if sweep < -std::f64::consts::PI {
            sweep += std::f64::consts::TAU;
        }
        let at = |k: u32| {
            let t = from + sweep * f64::from(k) / 8.0;
            c + DVec2::new(t.cos(), -t.sin()) * r
        };
        out.extend((0..8).map(|k| ([at(k), at(k + 1)], arc)));
    }
    for section in lay.objects.iter().filter_map(|o| o.section.as_ref()) {
        if let Outline::Ellipse { center, axes } = section {
            let at = |k: u32| {
                let t = std::f64::consts::TAU * f64::from(k) / 32.0;
                fig.to_px(*center + t.cos() * axes[0] + t.sin() * axes[1])
            };
            out.extend((0..32).map(|k| ([at(k), at(k + 1)], edge)));
        }
        if let Outline::Polygon { points } = section {
            out.extend((0..points.len()).map(|k| {
                (
                    [
                        fig.to_px(points[k]),
                        fig.to_px(points[(k + 1) % points.len()]),
                    ],
                    edge,
                )
            }));
        }
    }
    out
}

pub(super) fn draw_label(fig: &mut Figure, p: &Placed, scale: &Scale) {
    p.draw(fig, scale.k as f32);
}
