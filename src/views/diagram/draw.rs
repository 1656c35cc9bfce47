//! Ray diagrams: a pixel's ray tree drawn in 2D over the scene, as a lecture
//! slide or a book page would show it. Reads the recorded tree (and the scene,
//! for the objects' shapes); draws with [`crate::figure::canvas`] what
//! [`crate::views::diagram::layout`] projected, honestly: what the drawing plane
//! cuts of an object is solid, the rest of its outline a faint ghost, and a ray
//! that only passes in front of or behind an object is dotted there. Labels go
//! through [`crate::figure::labels`], so none collides.

use glam::DVec2;

use crate::figure::canvas::Figure;
use crate::figure::clip::{clip_line, clip_segment};
use crate::figure::labels::{self, Label, Placed, PxRect};
use crate::figure::pen::Rgb;
use crate::figure::pen::{Pen, palette};
use crate::scene::Scene;
use crate::tree::document::TraceDocument;
use crate::views::diagram::arrange::layout;
use crate::views::diagram::labels::{blocked, draw_label, label_requests, lines_px};
use crate::views::diagram::layout::{Layout, ObjectShape};
use crate::views::diagram::legend::draw_legend;
use crate::views::diagram::options::Options;
use crate::views::diagram::projection::Outline;
use crate::views::diagram::reveal::Reveal;
use crate::views::diagram::style::{MET_BOX, MISSED_BOX, NORMAL, ray_pen};
use crate::views::diagram::style::{Scale, pale};
use crate::views::numbers::num;
use crate::views::text;

/// What a drawn figure holds, for tests: where each label went.
pub struct Drawn {
    /// The figure.
    pub figure: Figure,
    /// Every label placed, with its box and what it names.
    pub labels: Vec<Placed>,
    /// The labels that found no room: optional ones (ticks, step numbers,
    /// the indices either side of a boundary) that would have needed a
    /// leader, and any other with no free spot at all.
    pub left_out: Vec<Label>,
    /// The legend's box (pixels).
    pub legend: PxRect,
    /// The frame (pixels).
    pub frame: PxRect,
    /// The legend's entries, in order: only what is drawn.
    pub legend_entries: Vec<String>,
}

/// Draws sample `options.sample` of `trace` over `scene` (the scene it was traced
/// in, with the same settings).
pub fn draw(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Figure, String> {
    draw_with_labels(trace, scene, options).map(|d| d.figure)
}

/// [`draw`], also returning where the labels went.
pub fn draw_with_labels(
    trace: &TraceDocument,
    scene: &Scene,
    options: &Options,
) -> Result<Drawn, String> {
    let lay = layout(trace, scene, options)?;
    let scale = Scale::of(options.width, options.height);
    let caption = caption(trace, &lay, options);
    let margin = scale.px(12.0) as f32;
    let lines = Figure::wrap(
        &caption,
        scale.text + 1.0,
        options.width as f32 - 2.0 * margin,
    );
    let top = (f64::from(scale.text + 1.0) * (1.3 * lines.len() as f64 + 0.9)) as f32 + 8.0;
    // The frame Figure::new makes: the page less the caption and margins.
    let w = options.width as f32 - 2.0 * margin;
    let h = options.height as f32 - top - margin;
    if w < 40.0 || h < 40.0 {
        return Err(format!(
            "a {}×{} figure leaves {:.0}×{:.0} pixels to draw in under its caption; the drawing needs at least 40×40 (try 400x300 or more)",
            options.width,
            options.height,
            w.max(0.0),
            h.max(0.0)
        ));
    }
    let mut fig = Figure::new(options.width, options.height, top, margin)
        .ok_or("the figure cannot be allocated")?;
    if options.svg {
        fig = fig.with_svg();
    }
    fig.fit(lay.window.0, lay.window.1, 0.0);
    let reveal = Reveal::of(trace, options.sample);
    draw_objects(&mut fig, scene, &lay, &scale);
    draw_boxes(&mut fig, &lay, &scale, &reveal);
    draw_eye_and_image_plane(&mut fig, &lay, &scale);
    for &p in &lay.lights {
        if fig.shows(p) {
            fig.light(p);
        }
    }
    draw_rays(&mut fig, &lay, &scale, &reveal);
    draw_marks(&mut fig, &lay, &scale, &reveal);
    draw_hits(&mut fig, &lay, &scale, &reveal);
    let offscreen = draw_off_frame(&mut fig, scene, &lay, &scale);
    fig.frame_border();
    let (legend, legend_entries) = draw_legend(&mut fig, &lay, &scale);
    let requests = label_requests(&fig, scene, &lay, options, &scale, offscreen, &reveal);
    let frame = PxRect::frame_of(&fig);
    let (placed, left_out) = labels::place_all(
        requests,
        &blocked(&fig, &lay, legend, &scale),
        &lines_px(&fig, &lay, &scale),
        frame,
    );
    for p in &placed {
        draw_label(&mut fig, p, &scale);
    }
    fig.caption(&lines, scale.text + 1.0);
    Ok(Drawn {
        figure: fig,
        labels: placed,
        left_out,
        legend,
        frame,
        legend_entries,
    })
}

/// What the figure shows, and the honesty rule it follows.
fn caption(trace: &TraceDocument, lay: &Layout, options: &Options) -> String {
    let sample = &trace.samples[options.sample];
    let what = match (&trace.pixel, &trace.ray) {
        (Some(p), _) if let Some(which) = text::sample_name(trace, options.sample) => {
            format!("pixel {},{}, {which}", p.x, p.y)
        }
        (Some(p), _) => format!("pixel {},{}", p.x, p.y),
        _ => "one ray".to_owned(),
    };
    let view = if sample.tree.nodes[0].hit.is_none() {
        let passed: Vec<String> = lay
            .near_misses
            .iter()
            .map(|&(_, gap, _, _)| num(gap))
            .collect();
        format!(
            "the ray hits nothing and returns the background; view: the plane of the ray and world up{}",
            if passed.is_empty() {
                String::new()
            } else {
                format!(" (nearest objects passed {} away)", passed.join(" and "))
            }
        )
    } else {
        lay.proj.caption().to_owned()
    };
    format!(
        "{what} of {} · {view} · solid: what the drawing plane cuts; faint: an outline seen through it; dotted: a ray passing in front of or behind an object",
        trace.scene.file
    )
}

/// The hierarchy's boxes the rays were tested against, under the rays: the
/// ones a ray entered solid, the ones it missed (whole subtrees never opened)
/// dotted and fainter.
fn draw_boxes(fig: &mut Figure, lay: &Layout, scale: &Scale, reveal: &Reveal) {
    for b in lay.boxes.iter().filter(|b| !b.met) {
        fig.tag(&reveal.visit(b.node, b.index));
        fig.polygon(&b.outline, None, Some(scale.pen(MISSED_BOX)));
    }
    for b in lay.boxes.iter().filter(|b| b.met) {
        fig.tag(&reveal.visit(b.node, b.index));
        fig.polygon(
            &b.outline,
            Some((palette::BOX, 18)),
            Some(scale.pen(MET_BOX)),
        );
    }
    fig.tag("");
}

/// Objects, under the rays, farthest first: each one's silhouette as a faint
/// ghost, then what the drawing plane cuts of it, solid.
fn draw_objects(fig: &mut Figure, scene: &Scene, lay: &Layout, scale: &Scale) {
    let (vlo, vhi) = fig.visible();
    let w = lay.proj.toward_viewer();
    let mut order: Vec<&ObjectShape> = lay.objects.iter().collect();
    let depth = |s: &ObjectShape| (scene.objects[s.object].center() - lay.proj.origin).dot(w);
    order.sort_by(|&a, &b| depth(a).total_cmp(&depth(b)));
    let ghost = scale.pen(Pen::dashed([170, 170, 170], 1.1));
    let cut = scale.pen(Pen::solid(palette::OBJECT, 1.6));
    for shape in order {
        let (tint, alpha) = pale(&scene.materials[scene.objects[shape.object].material]);
        draw_outline(
            fig,
            &shape.silhouette,
            Some((tint, alpha / 5)),
            Some(ghost),
            (vlo, vhi),
        );
        if let Some(section) = &shape.section {
            draw_outline(fig, section, Some((tint, alpha)), Some(cut), (vlo, vhi));
        }
    }
}

fn draw_outline(
    fig: &mut Figure,
    outline: &Outline,
    fill: Option<(Rgb, u8)>,
    pen: Option<Pen>,
    (vlo, vhi): (DVec2, DVec2),
) {
    match outline {
        Outline::Ellipse { center, axes } => fig.ellipse(*center, *axes, fill, pen),
        Outline::Polygon { points } => fig.polygon(points, fill, pen),
        Outline::Segments { segments } => {
            if let Some(pen) = pen {
                for [a, b] in segments {
                    fig.line(*a, *b, pen);
                }
            }
        }
        Outline::Line {
            point,
            dir,
            outward,
        } => {
            if let Some((a, b)) = clip_line(*point, *dir, vlo, vhi) {
                let inside = half_plane(vlo, vhi, *point, *outward);
                fig.polygon(&inside, fill, None);
                if let Some(pen) = pen {
                    fig.line(a, b, pen);
                }
            }
        }
        Outline::Parallel => {
            if let Some((tint, alpha)) = fill {
                fig.polygon(
                    &[vlo, DVec2::new(vhi.x, vlo.y), vhi, DVec2::new(vlo.x, vhi.y)],
                    Some((tint, alpha / 2)),
                    None,
                );
            }
        }
    }
}

fn draw_eye_and_image_plane(fig: &mut Figure, lay: &Layout, scale: &Scale) {
    if let Some((a, b, pixel)) = lay.image_plane {
        fig.line(a, b, scale.pen(Pen::solid(palette::INK, 2.0)));
        fig.dot(
            pixel,
            scale.px(3.5) as f32,
            palette::PAPER,
            Some(palette::INK),
        );
    }
    fig.dot(lay.eye, scale.px(5.0) as f32, palette::INK, None);
}

/// Each line in pieces: solid where it is what it seems, faint and dotted where
/// it only passes in front of or behind an object; arrowheads at rays' ends.
fn draw_rays(fig: &mut Figure, lay: &Layout, scale: &Scale, reveal: &Reveal) {
    let (vlo, vhi) = fig.visible();
    for s in lay
        .segments
        .iter()
        .filter(|s| s.shadow.is_none() && !s.leaves)
    {
        let Some(tag) = reveal.pending(s.node) else {
            continue;
        };
        // A short arrow from where it enters the frame, never past half the
        // way to the hit: a ray not yet traced crosses nothing it will
        // miss, nor tells where it stops.
        if let Some((a, b)) = clip_segment(s.from, s.to, vlo, vhi) {
            let stub = ((b - a).length() / 2.0).min((vhi - vlo).length() / 14.0);
            fig.tag(&tag);
            // Faint in its kind's own dashes: dotted would read as passing.
            let pen = Pen {
                alpha: 110,
                ..scale.pen(s.stroke.pen())
            };
            fig.svg_only_arrow(a, a + (b - a).normalize_or_zero() * stub, pen);
        }
    }
    for s in &lay.segments {
        fig.tag(&match s.shadow {
            Some(k) => reveal.shadow(s.node, k),
            None => reveal.ray(s.node),
        });
        let pen = scale.pen(s.stroke.pen());
        for (from, to, passing, last) in s.pieces() {
            let Some((a, b)) = clip_segment(from, to, vlo, vhi) else {
                continue;
            };
            let pen = if passing { pen.passing() } else { pen };
            if s.stroke.arrow() && last && !passing {
                fig.arrow(a, b, pen);
            } else {
                fig.line(a, b, pen);
            }
        }
    }
    fig.tag("");
}

/// How a ray that hit nothing passed the objects nearest it: a dotted gap
/// from the ray to each one's surface.
fn draw_near_misses(fig: &mut Figure, lay: &Layout, scale: &Scale) {
    for &(_, _, on_ray, on_object) in &lay.near_misses {
        let pen = scale.pen(Pen::pattern(palette::SHADOW_BLOCKED, 1.2, &[3.0, 3.0]));
        fig.line(on_ray, on_object, pen);
        fig.dot(
            on_object,
            scale.px(2.5) as f32,
            palette::SHADOW_BLOCKED,
            None,
        );
    }
}

/// The near misses, then blockers, lights behind surfaces, angle arcs, the
/// other roots and ticks.
fn draw_marks(fig: &mut Figure, lay: &Layout, scale: &Scale, reveal: &Reveal) {
    draw_near_misses(fig, lay, scale);
    let m = &lay.marks;
    for b in &m.blocked {
        fig.tag(&reveal.shadow(b.node, b.shadow));
        fig.cross(
            b.at,
            scale.px(6.0),
            scale.pen(Pen::solid(palette::INK, 2.0)),
        );
    }
    for b in &m.behind {
        fig.tag(&reveal.hit(b.node));
        let stub = b.at + b.toward * scale.px(26.0) / fig.scale();
        fig.line(
            b.at,
            stub,
            scale.pen(Pen::pattern(palette::SHADOW_BLOCKED, 1.3, &[2.0, 3.0])),
        );
        fig.cross(
            stub,
            scale.px(3.5),
            scale.pen(Pen::solid(palette::SHADOW_BLOCKED, 1.3)),
        );
    }
    for a in &m.angles {
        fig.tag(&reveal.hit(a.node));
        if let Some(g) = a.guide {
            let end = a.at + g * scale.px(45.0) / fig.scale();
            fig.line(
                a.at,
                end,
                scale.pen(Pen::pattern(palette::NORMAL, 1.0, &[2.0, 3.0])),
            );
        }
        fig.arc(
            a.at,
            scale.px(30.0),
            a.from,
            a.to,
            scale.pen(Pen::solid(palette::INK, 1.2)),
        );
    }
    for r in &m.roots {
        fig.tag(&reveal.hit(r.node));
        fig.line(r.from, r.at, scale.pen(ray_pen(r.kind).passing()));
        fig.dot(
            r.at,
            scale.px(3.5) as f32,
            palette::PAPER,
            Some(palette::INK),
        );
    }
    for t in &m.ticks {
        fig.tag(&reveal.label(t.node, false));
        let half = t.across * scale.px(5.0) / fig.scale();
        fig.line(
            t.at - half,
            t.at + half,
            scale.pen(Pen::solid(palette::INK, 1.2)),
        );
    }
    fig.tag("");
}

/// Hit points on top, with the normal the formulas use.
fn draw_hits(fig: &mut Figure, lay: &Layout, scale: &Scale, reveal: &Reveal) {
    let normal_length = scale.px(45.0) / fig.scale();
    for hit in &lay.hits {
        fig.tag(&reveal.hit(hit.node));
        let tip = hit.at + hit.normal * normal_length;
        fig.arrow(hit.at, tip, scale.pen(NORMAL));
        fig.dot(
            hit.at,
            scale.px(4.0) as f32,
            ray_pen(hit.kind).color,
            Some(palette::INK),
        );
    }
    fig.tag("");
}

/// A small arrow at the frame's edge toward each light (and the eye) outside
/// it; returns where each went, with its name, for the labels.
fn draw_off_frame(
    fig: &mut Figure,
    scene: &Scene,
    lay: &Layout,
    scale: &Scale,
) -> Vec<(DVec2, String)> {
    let (lo, hi) = fig.visible();
    let center = (lo + hi) / 2.0;
    let mut out = Vec::new();
    let named = scene
        .lights
        .iter()
        .map(|l| l.name.clone())
        .zip(lay.lights.iter().copied())
        .chain([("eye".to_owned(), lay.eye)]);
    for (name, p) in named {
        if fig.shows(p) {
            continue;
        }
        let Some((_, edge)) = clip_segment(center, p, lo, hi) else {
            continue;
        };
        let dir = (p - center).normalize_or_zero();
        let inset = scale.px(14.0) / fig.scale();
        let tip = edge - dir * inset * 0.2;
        fig.arrow(
            tip - dir * inset * 1.6,
            tip,
            scale.pen(Pen::solid(palette::INK, 1.8)),
        );
        out.push((fig.to_px(tip - dir * inset), name));
    }
    out
}

/// The part of the box `lo..hi` inside the solid of a plane drawn as a line
/// through `point` with outward normal `outward` (Sutherland–Hodgman on one edge).
fn half_plane(lo: DVec2, hi: DVec2, point: DVec2, outward: DVec2) -> Vec<DVec2> {
    let corners = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
    let side = |p: DVec2| (p - point).dot(outward);
    let mut out = Vec::new();
    for i in 0..4 {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        let (sa, sb) = (side(a), side(b));
        if sa <= 0.0 {
            out.push(a);
        }
        if (sa < 0.0) != (sb < 0.0) && sa != sb {
            out.push(a + (b - a) * (sa / (sa - sb)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_plane_keeps_the_inside() {
        // The line y = 2 with outside up, in the box 0..4: the inside is 0..4 × 0..2.
        let poly = half_plane(
            DVec2::ZERO,
            DVec2::splat(4.0),
            DVec2::new(0.0, 2.0),
            DVec2::Y,
        );
        let (lo, hi) = poly
            .iter()
            .fold((DVec2::splat(9.0), DVec2::splat(-9.0)), |(l, h), &p| {
                (l.min(p), h.max(p))
            });
        assert_eq!((lo, hi), (DVec2::ZERO, DVec2::new(4.0, 2.0)));
    }
}
