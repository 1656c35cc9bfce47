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
    if options.labels == Labels::None {
        return Vec::new();
    }
    let ask = Ask { fig, scale, reveal };
    let mut out = tir_badges(&ask, lay);
    if options.labels == Labels::All {
        out.extend(hit_names(&ask, lay));
        out.extend(indices(&ask, lay));
        out.extend(angles(&ask, lay));
    }
    out.extend(scene_names(&ask, scene, lay, offscreen));
    out.extend(object_labels(fig, scene, lay, scale.text));
    out.extend(ray_marks(&ask, lay));
    out.extend(near_misses(&ask, scene, lay));
    out
}

/// What a label request needs: the figure, to name a point by its pixel;
/// the scale, for sizes; the reveal, to tag each with the step that shows it.
struct Ask<'a> {
    fig: &'a Figure,
    scale: &'a Scale,
    reveal: &'a Reveal,
}

impl Ask<'_> {
    /// A plain label at the figure's text size.
    fn text(&self, text: String, color: Rgb, target: Target) -> Label {
        Label {
            text,
            size: self.scale.text,
            color,
            target,
            boxed: false,
            optional: false,
            tag: String::new(),
        }
    }

    /// The point `p` (drawing units), kept clear by `r` (pixels at scale 1).
    fn point(&self, p: DVec2, r: f64) -> Target {
        Target::Point {
            at: self.fig.to_px(p),
            clearance: self.scale.px(r),
        }
    }

    /// The pixel `at`, kept clear by `r` (pixels at scale 1).
    fn pixel(&self, at: DVec2, r: f64) -> Target {
        Target::Point {
            at,
            clearance: self.scale.px(r),
        }
    }
}

/// A badge at each total internal reflection.
fn tir_badges(ask: &Ask, lay: &Layout) -> Vec<Label> {
    (lay.marks.tir.iter())
        .map(|t| Label {
            boxed: true,
            size: ask.scale.text - 1.0,
            tag: ask.reveal.label(t.node, true),
            ..ask.text(t.text.clone(), palette::REFRACTED, ask.point(t.at, 8.0))
        })
        .collect()
}

/// The hits in the frame, numbered P1, P2, … in the layout's order.
fn hit_names(ask: &Ask, lay: &Layout) -> Vec<Label> {
    (lay.hits.iter().enumerate())
        .filter(|(_, h)| ask.fig.shows(h.at))
        .map(|(k, h)| Label {
            tag: ask.reveal.label(h.node, true),
            ..ask.text(format!("P{}", k + 1), palette::INK, ask.point(h.at, 5.0))
        })
        .collect()
}

/// Each index of a refracting boundary on its own side, along the normal: left
/// out rather than led across the boundary when that side has no room.
fn indices(ask: &Ask, lay: &Layout) -> Vec<Label> {
    let mut out = Vec::new();
    for b in &lay.marks.boundaries {
        for (label, side) in [(&b.n1, 1.0), (&b.n2, -1.0)] {
            let at = ask.fig.to_px(b.at)
                + DVec2::new(b.normal.x, -b.normal.y) * side * ask.scale.px(58.0);
            out.push(Label {
                size: ask.scale.text - 2.0,
                optional: true,
                tag: ask.reveal.label(b.node, true),
                ..ask.text(label.clone(), palette::OBJECT, ask.pixel(at, 2.0))
            });
        }
    }
    out
}

/// Each angle's name and value, just outside its arc's middle.
fn angles(ask: &Ask, lay: &Layout) -> Vec<Label> {
    (lay.marks.angles.iter())
        .map(|a| {
            let mid = (a.from + a.to).normalize_or(a.to);
            let at = ask.fig.to_px(a.at) + DVec2::new(mid.x, -mid.y) * ask.scale.px(30.0);
            Label {
                size: ask.scale.text - 2.0,
                tag: ask.reveal.label(a.node, true),
                ..ask.text(a.label.clone(), palette::INK, ask.pixel(at, 3.0))
            }
        })
        .collect()
}

/// The scene's own names: the lights in the frame, the arrows toward those
/// outside it (`offscreen`, in pixels), the eye and the image plane.
fn scene_names(
    ask: &Ask,
    scene: &Scene,
    lay: &Layout,
    offscreen: Vec<(DVec2, String)>,
) -> Vec<Label> {
    let (fig, ink) = (ask.fig, palette::INK);
    let mut out = Vec::new();
    for (light, &p) in scene.lights.iter().zip(&lay.lights) {
        if fig.shows(p) {
            out.push(ask.text(light.name.clone(), ink, ask.point(p, 14.0)));
        }
    }
    for (at, name) in offscreen {
        out.push(ask.text(name, ink, ask.pixel(at, 6.0)));
    }
    if fig.shows(lay.eye) {
        out.push(ask.text("eye".to_owned(), ink, ask.point(lay.eye, 6.0)));
    }
    if let Some((a, b, _)) = lay.image_plane {
        let end = if fig.shows(a) { a } else { b };
        if fig.shows(end) {
            out.push(Label {
                size: ask.scale.text - 2.0,
                ..ask.text("image plane".to_owned(), ink, ask.point(end, 3.0))
            });
        }
    }
    out
}

/// The small marks along the rays, each optional: the ticks of `t`, the
/// roots passed over and the step numbers. A root's open dot stays: where
/// many bounces repeat the same roots, the words that would need a leader
/// across the crowd are left out.
fn ray_marks(ask: &Ask, lay: &Layout) -> Vec<Label> {
    let (size, ink) = (ask.scale.text, palette::INK);
    let ticks = lay.marks.ticks.iter().map(|t| Label {
        size: size - 4.0,
        optional: true,
        tag: ask.reveal.label(t.node, false),
        ..ask.text(t.label.clone(), ink, ask.point(t.at, 5.0))
    });
    let roots = lay.marks.roots.iter().map(|r| Label {
        size: size - 3.0,
        optional: true,
        tag: ask.reveal.label(r.node, true),
        ..ask.text(r.label.clone(), ink, ask.point(r.at, 5.0))
    });
    let steps = lay.marks.steps.iter().map(|s| Label {
        size: size - 3.0,
        optional: true,
        boxed: true,
        ..ask.text(s.number.to_string(), ink, ask.point(s.at, 6.0))
    });
    ticks.chain(roots).chain(steps).collect()
}

/// How far a ray that hit nothing passed each object nearest it.
fn near_misses(ask: &Ask, scene: &Scene, lay: &Layout) -> Vec<Label> {
    (lay.near_misses.iter())
        .map(|&(i, gap, on_ray, on_object)| {
            ask.text(
                format!("misses '{}' by {}", scene.objects[i].name, num(gap)),
                palette::SHADOW_BLOCKED,
                ask.point((on_ray + on_object) / 2.0, 3.0),
            )
        })
        .collect()
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
