//! Ray diagrams: a pixel's ray tree drawn in 2D over the scene, as a lecture
//! slide or a book page would show it. Reads the recorded tree (and the scene,
//! for the objects' shapes); draws with [`crate::views::figure`] through
//! [`crate::views::projection`].

use glam::{DVec2, DVec3};

use crate::scene::Scene;
use crate::shading::material::Pattern;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::RayKind;
use crate::views::clip::{clip_line, clip_ray, clip_segment};
use crate::views::diagram_layout::{
    Labels, Layout, NORMAL, Options, SHADOW_BLOCKED, SHADOW_REACHES, layout, ray_pen,
};
use crate::views::figure::{Anchor, Figure, Pen, Rgb, palette};
use crate::views::projection::Outline;

const TEXT: f32 = 15.0;

/// Draws sample `options.sample` of `trace` over `scene` (the scene it was traced
/// in, with the same settings).
pub fn draw(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Figure, String> {
    let lay = layout(trace, scene, options)?;
    let mut fig = Figure::new(options.width, options.height, 44.0, 12.0)
        .ok_or("the figure size must be at least 40×60 pixels")?;
    if fig.frame().width() < 40.0 || fig.frame().height() < 20.0 {
        return Err("the figure size must be at least 40×60 pixels".to_owned());
    }
    fig.fit(lay.lo, lay.hi, 0.08);
    let labels = options.labels;
    draw_objects(&mut fig, scene, &lay);
    if labels != Labels::None {
        label_objects(&mut fig, scene, &lay);
    }
    draw_eye_and_image_plane(&mut fig, &lay, labels);
    draw_lights(&mut fig, scene, &lay, labels);
    draw_rays(&mut fig, &lay);
    draw_hits(&mut fig, &lay, labels);
    fig.frame_border();
    draw_legend(&mut fig, scene, &lay, options.shadows);
    let sample = &trace.samples[options.sample];
    let what = match (&trace.pixel, &trace.ray) {
        (Some(p), _) if trace.samples.len() > 1 || trace.settings.spp > 1 => {
            format!("pixel {},{} (sample {})", p.x, p.y, sample.index)
        }
        (Some(p), _) => format!("pixel {},{}", p.x, p.y),
        _ => "one ray".to_owned(),
    };
    fig.caption(
        &format!("{what} of {} · {}", trace.scene.file, lay.proj.caption()),
        TEXT + 1.0,
    );
    Ok(fig)
}

/// Objects, under the rays. Those the tree does not touch may lie in front of
/// or behind the drawing's plane: dashed and faint, so no ray seems to cross them.
fn draw_objects(fig: &mut Figure, scene: &Scene, lay: &Layout) {
    let (vlo, vhi) = fig.visible();
    for (i, (object, outline)) in scene.objects.iter().zip(&lay.outlines).enumerate() {
        let material = &scene.materials[object.material];
        let (tint, alpha) = pale(material);
        let (fill, pen) = if lay.touched.contains(&i) {
            ((tint, alpha), Pen::solid(palette::OBJECT, 1.5))
        } else {
            ((tint, alpha / 3), Pen::dashed([150, 150, 150], 1.2))
        };
        match *outline {
            Outline::Ellipse { center, axes } => fig.ellipse(center, axes, Some(fill), Some(pen)),
            Outline::Polygon { ref points } => fig.polygon(points, Some(fill), Some(pen)),
            Outline::Line {
                point,
                dir,
                outward,
            } => {
                if let Some((a, b)) = clip_line(point, dir, vlo, vhi) {
                    let inside = half_plane(vlo, vhi, point, outward);
                    fig.polygon(&inside, Some(fill), None);
                    fig.line(a, b, pen);
                }
            }
            Outline::Parallel => fig.polygon(
                &[vlo, DVec2::new(vhi.x, vlo.y), vhi, DVec2::new(vlo.x, vhi.y)],
                Some((tint, alpha / 2)),
                None,
            ),
        }
    }
}

/// Each object's name: a bounded one at the top-left corner of its box (off
/// the outline, where rays arrive less often), a plane at its left end.
fn label_objects(fig: &mut Figure, scene: &Scene, lay: &Layout) {
    let (vlo, vhi) = fig.visible();
    for (object, outline) in scene.objects.iter().zip(&lay.outlines) {
        match *outline {
            Outline::Ellipse { .. } | Outline::Polygon { .. } => {
                let Some((lo, hi)) = outline.bounds() else {
                    continue;
                };
                fig.label(
                    DVec2::new(lo.x, hi.y),
                    DVec2::ZERO,
                    &object.name,
                    TEXT,
                    palette::OBJECT,
                    Anchor::Right,
                );
            }
            Outline::Line { point, dir, .. } => {
                if let Some((a, b)) = clip_line(point, dir, vlo, vhi) {
                    let left = if a.x <= b.x { a } else { b };
                    fig.label(
                        left,
                        DVec2::new(8.0, -6.0),
                        &object.name,
                        TEXT,
                        palette::OBJECT,
                        Anchor::Left,
                    );
                }
            }
            Outline::Parallel => {}
        }
    }
}

/// The eye, the image plane and the pixel on it.
fn draw_eye_and_image_plane(fig: &mut Figure, lay: &Layout, labels: Labels) {
    if let Some((a, b, pixel)) = lay.image_plane {
        fig.line(a, b, Pen::solid(palette::INK, 2.0));
        fig.dot(pixel, 3.5, palette::PAPER, Some(palette::INK));
        if labels != Labels::None {
            fig.label(
                a,
                DVec2::new(6.0, 16.0),
                "image plane",
                TEXT - 2.0,
                palette::INK,
                Anchor::Left,
            );
        }
    }
    fig.dot(lay.eye, 5.0, palette::INK, None);
    if labels != Labels::None {
        fig.label(
            lay.eye,
            DVec2::new(0.0, -10.0),
            "eye",
            TEXT,
            palette::INK,
            Anchor::Center,
        );
    }
}

/// Each light as a small sun with its name.
fn draw_lights(fig: &mut Figure, scene: &Scene, lay: &Layout, labels: Labels) {
    for (light, &p) in scene.lights.iter().zip(&lay.lights) {
        fig.light(p);
        if labels != Labels::None {
            fig.label(
                p,
                DVec2::new(16.0, 5.0),
                &light.name,
                TEXT,
                palette::INK,
                Anchor::Left,
            );
        }
    }
}

/// Shadow rays first, then the rays with their arrowheads; a ray that leaves
/// the scene runs to the frame's edge.
fn draw_rays(fig: &mut Figure, lay: &Layout) {
    let (vlo, vhi) = fig.visible();
    for s in &lay.segments {
        let end = match s.to {
            Some(to) => clip_segment(s.from, to, vlo, vhi),
            None => clip_ray(s.from, s.dir, vlo, vhi, 0.0),
        };
        if let Some((a, b)) = end {
            if s.arrow {
                fig.arrow(a, b, s.pen)
            } else {
                fig.line(a, b, s.pen)
            }
        }
    }
}

/// Hit points on top, with their normals, named P1, P2, … in the order found.
fn draw_hits(fig: &mut Figure, lay: &Layout, labels: Labels) {
    let normal_length = 45.0 / fig.scale();
    for (k, hit) in lay.hits.iter().enumerate() {
        let p = hit.at;
        let tip = p + hit.normal * normal_length;
        fig.arrow(p, tip, NORMAL);
        fig.dot(p, 4.0, ray_pen(hit.kind).color, Some(palette::INK));
        if labels == Labels::All {
            fig.label(
                p,
                DVec2::new(8.0, 16.0),
                &format!("P{}", k + 1),
                TEXT - 1.0,
                palette::INK,
                Anchor::Left,
            );
            fig.label(
                tip,
                DVec2::new(4.0, -4.0),
                "N",
                TEXT - 2.0,
                palette::NORMAL,
                Anchor::Left,
            );
        }
    }
}

/// The legend, in the corner of the frame that hides the fewest of the
/// drawing's points.
fn draw_legend(fig: &mut Figure, scene: &Scene, lay: &Layout, shadows: bool) {
    let mut legend = vec![
        (ray_pen(RayKind::Primary), "primary ray"),
        (ray_pen(RayKind::Reflected), "reflected ray"),
        (ray_pen(RayKind::Refracted), "refracted ray"),
    ];
    if shadows {
        legend.extend([
            (SHADOW_REACHES, "shadow ray, reaches the light"),
            (SHADOW_BLOCKED, "shadow ray, blocked"),
        ]);
    }
    legend.push((NORMAL, "surface normal"));
    let (vlo, vhi) = fig.visible();
    let mut marks: Vec<DVec2> = scene
        .lights
        .iter()
        .map(|l| lay.proj.point(l.position))
        .chain([lay.eye])
        .collect();
    for s in &lay.segments {
        let to =
            s.to.unwrap_or(s.from + s.dir.normalize_or_zero() * (vhi - vlo).length());
        marks.extend((0..=20).map(|k| s.from + (to - s.from) * (f64::from(k) / 20.0)));
    }
    let marks: Vec<DVec2> = marks.into_iter().map(|p| fig.to_px(p)).collect();
    let boxes = fig.legend_boxes(&legend, TEXT - 2.0);
    let covered = |(o, wh): (DVec2, DVec2)| {
        marks
            .iter()
            .filter(|p| p.cmpge(o - 10.0).all() && p.cmple(o + wh + 10.0).all())
            .count()
    };
    let corner = (0..4).min_by_key(|&c| (covered(boxes[c]), c)).unwrap_or(0);
    fig.legend(&legend, TEXT - 2.0, corner);
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

/// A pale fill that hints at the material: glass blue, mirrors gray, others a
/// washed-out version of their color.
fn pale(material: &crate::shading::material::Material) -> (Rgb, u8) {
    if material.transparent > 0.0 {
        return ([200, 225, 250], 150);
    }
    if material.reflective >= 0.5 {
        return ([215, 215, 220], 200);
    }
    let c = match material.pattern {
        Pattern::Solid(c) => c,
        Pattern::Checker { colors, .. } => (colors[0] + colors[1]) / 2.0,
    };
    let srgb = crate::io::image::rgb8(c.min(DVec3::ONE));
    (
        srgb.map(|v| (255 - (255 - u16::from(v)) * 35 / 100) as u8),
        255,
    )
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
