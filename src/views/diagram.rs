//! Ray diagrams: a pixel's ray tree drawn in 2D over the scene, as a lecture
//! slide or a book page would show it. Reads the recorded tree (and the scene,
//! for the objects' shapes); draws with [`crate::views::figure`] through
//! [`crate::views::projection`].

use glam::{DVec2, DVec3};

use crate::scene::Scene;
use crate::shading::material::Pattern;
use crate::trace::recorder::RayKind;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::ShadowOutcomeRecord;
use crate::views::figure::{Anchor, Figure, Pen, Rgb, clip_line, clip_ray, clip_segment, palette};
use crate::views::projection::{Outline, Projection, View};

/// Which labels to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Labels {
    /// None: only the legend and caption.
    None,
    /// Objects, lights and the eye.
    Objects,
    /// Also hit points (P1, P2, … in the order they were found) and normals.
    All,
}

/// What to draw, and how big.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Figure width in pixels.
    pub width: u32,
    /// Figure height in pixels.
    pub height: u32,
    /// The projection.
    pub view: View,
    /// Draw only rays up to this depth (1: the primary ray).
    pub depth: Option<u32>,
    /// Draw shadow rays.
    pub shadows: bool,
    /// Which labels.
    pub labels: Labels,
    /// Which of the trace's samples to draw.
    pub sample: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            width: 1200,
            height: 800,
            view: View::Auto,
            depth: None,
            shadows: true,
            labels: Labels::All,
            sample: 0,
        }
    }
}

/// The pen a ray of this kind is drawn with.
pub fn ray_pen(kind: RayKind) -> Pen {
    let color = match kind {
        RayKind::Primary => palette::PRIMARY,
        RayKind::Reflected => palette::REFLECTED,
        RayKind::Refracted => palette::REFRACTED,
        RayKind::Shadow => palette::SHADOW_REACHES,
    };
    Pen::solid(color, 2.5)
}

const SHADOW_REACHES: Pen = Pen::solid(palette::SHADOW_REACHES, 1.0);
const SHADOW_BLOCKED: Pen = Pen::dashed(palette::SHADOW_BLOCKED, 1.2);
const NORMAL: Pen = Pen::solid(palette::NORMAL, 2.0);
const TEXT: f32 = 15.0;

/// One segment of the drawing, in diagram coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// Where it starts.
    pub from: DVec2,
    /// Where it ends; `None`: the ray leaves the scene and runs to the frame's edge.
    pub to: Option<DVec2>,
    /// Its direction.
    pub dir: DVec2,
    /// How it is drawn.
    pub pen: Pen,
    /// A ray (with an arrowhead), or a shadow ray.
    pub arrow: bool,
    /// The tree node it belongs to.
    pub node: usize,
}

/// A hit point, drawn as a dot with its normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitMark {
    /// The tree node whose hit it is.
    pub node: usize,
    /// Where.
    pub at: DVec2,
    /// The shading normal's direction in the drawing.
    pub normal: DVec2,
    /// The kind of the ray that hit.
    pub kind: RayKind,
}

/// Everything a diagram shows, projected, with the box to fit: what the PNG
/// figure and the inspector's diagram pane both draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// The projection.
    pub proj: Projection,
    /// Rays and shadow rays; shadow rays first.
    pub segments: Vec<Segment>,
    /// Hit points in the order they were found.
    pub hits: Vec<HitMark>,
    /// Every object's outline, by object index.
    pub outlines: Vec<Outline>,
    /// The objects the tree touches (hit, or blocking a shadow ray).
    pub touched: Vec<usize>,
    /// The eye.
    pub eye: DVec2,
    /// The image plane's cut (two ends) and the pixel on it.
    pub image_plane: Option<(DVec2, DVec2, DVec2)>,
    /// The lights.
    pub lights: Vec<DVec2>,
    /// The box the drawing should fit.
    pub lo: DVec2,
    /// See `lo`.
    pub hi: DVec2,
}

/// Projects sample `options.sample` of `trace` (and `scene`) for drawing.
///
/// The box to fit holds a core (the eye, the image plane, the first hit and the
/// bounded objects the tree touches); farther points join it only when near,
/// and rays to the others run to the frame's edge, so one far bounce does not
/// shrink the interesting part to a speck.
pub fn layout(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Layout, String> {
    let sample = trace
        .samples
        .get(options.sample)
        .ok_or_else(|| format!("the trace has no sample {}", options.sample))?;
    let camera = scene.camera();
    let proj = Projection::new(options.view, trace, options.sample, &camera);
    let shown = |depth: u32| options.depth.is_none_or(|d| depth <= d);
    let mut segments = Vec::new();
    let mut hits = Vec::new();
    let eye = proj.point(camera.eye);
    let mut core = vec![eye];
    let mut points = Vec::new();
    let mut touched = Vec::new();
    if let Some(hit) = &sample.tree.nodes[0].hit {
        core.push(proj.point(hit.point));
    }
    for (i, node) in sample
        .tree
        .nodes
        .iter()
        .enumerate()
        .filter(|(_, n)| shown(n.depth))
    {
        let from = proj.point(node.origin);
        let to = node.hit.as_ref().map(|h| proj.point(h.point));
        segments.push(Segment {
            from,
            to,
            dir: proj.vector(node.direction),
            pen: ray_pen(node.kind),
            arrow: true,
            node: i,
        });
        points.push(from);
        points.extend(to);
        if let Some(h) = &node.hit {
            touched.push(h.object);
            hits.push(HitMark {
                node: i,
                at: proj.point(h.point),
                normal: proj.vector(h.shading_normal),
                kind: node.kind,
            });
        }
        if !options.shadows {
            continue;
        }
        for s in &node.shadow_rays {
            let (end, pen) = match &s.outcome {
                ShadowOutcomeRecord::FacesAway => continue,
                ShadowOutcomeRecord::Reaches { .. } => (s.origin + s.direction, SHADOW_REACHES),
                ShadowOutcomeRecord::Blocked { object, t, .. } => {
                    touched.push(*object);
                    (s.origin + *t * s.direction, SHADOW_BLOCKED)
                }
            };
            let (from, to) = (proj.point(s.origin), proj.point(end));
            points.extend([from, to]);
            segments.push(Segment {
                from,
                to: Some(to),
                dir: to - from,
                pen,
                arrow: false,
                node: i,
            });
        }
    }
    segments.sort_by_key(|s| s.arrow);
    let image_plane = image_plane_segment(&proj, trace, options.sample, &camera);
    core.extend(image_plane.map(|(a, b, _)| [a, b]).into_iter().flatten());
    let outlines: Vec<Outline> = scene.objects.iter().map(|o| proj.outline(o)).collect();
    for &i in &touched {
        if let Some((lo, hi)) = outlines[i].bounds() {
            core.extend([lo, hi]);
        }
    }
    let bounds = |ps: &[DVec2]| {
        (
            ps.iter()
                .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p)),
            ps.iter()
                .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p)),
        )
    };
    let (core_lo, core_hi) = bounds(&core);
    let reach = (core_hi - core_lo).max_element() * 0.75;
    let near: Vec<DVec2> = points
        .iter()
        .copied()
        .filter(|p| p.cmpge(core_lo - reach).all() && p.cmple(core_hi + reach).all())
        .collect();
    let (lo, hi) = bounds(&[core, near].concat());
    let lights = scene
        .lights
        .iter()
        .map(|l| proj.point(l.position))
        .collect();
    Ok(Layout {
        proj,
        segments,
        hits,
        outlines,
        touched,
        eye,
        image_plane,
        lights,
        lo,
        hi,
    })
}

/// Draws sample `options.sample` of `trace` over `scene` (the scene it was traced
/// in, with the same settings).
pub fn draw(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Figure, String> {
    let Layout {
        proj,
        segments,
        hits,
        outlines,
        touched,
        eye,
        image_plane,
        lights,
        lo,
        hi,
    } = layout(trace, scene, options)?;
    let sample = &trace.samples[options.sample];
    let mut fig = Figure::new(options.width, options.height, 44.0, 12.0)
        .ok_or("the figure size must be at least 40×60 pixels")?;
    if fig.frame().width() < 40.0 || fig.frame().height() < 20.0 {
        return Err("the figure size must be at least 40×60 pixels".to_owned());
    }
    fig.fit(lo, hi, 0.08);
    let (vlo, vhi) = fig.visible();

    // Objects, under the rays. Those the tree does not touch may lie in front of
    // or behind the drawing's plane: dashed and faint, so no ray seems to cross them.
    for (i, (object, outline)) in scene.objects.iter().zip(&outlines).enumerate() {
        let material = &scene.materials[object.material];
        let (tint, alpha) = pale(material);
        let (fill, pen) = if touched.contains(&i) {
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
    if options.labels != Labels::None {
        for (object, outline) in scene.objects.iter().zip(&outlines) {
            match *outline {
                Outline::Ellipse { .. } | Outline::Polygon { .. } => {
                    // At the top-left corner of its box: off the outline, where rays arrive less often.
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

    // The eye, the image plane and the pixel.
    if let Some((a, b, pixel)) = image_plane {
        fig.line(a, b, Pen::solid(palette::INK, 2.0));
        fig.dot(pixel, 3.5, palette::PAPER, Some(palette::INK));
        if options.labels != Labels::None {
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
    fig.dot(eye, 5.0, palette::INK, None);
    if options.labels != Labels::None {
        fig.label(
            eye,
            DVec2::new(0.0, -10.0),
            "eye",
            TEXT,
            palette::INK,
            Anchor::Center,
        );
    }
    for (light, &p) in scene.lights.iter().zip(&lights) {
        fig.light(p);
        if options.labels != Labels::None {
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

    // Shadow rays first, then the rays, then hits and normals on top.
    for s in &segments {
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
    let normal_length = 45.0 / fig.scale();
    for (k, hit) in hits.iter().enumerate() {
        let p = hit.at;
        let tip = p + hit.normal * normal_length;
        fig.arrow(p, tip, NORMAL);
        fig.dot(p, 4.0, ray_pen(hit.kind).color, Some(palette::INK));
        if options.labels == Labels::All {
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

    fig.frame_border();
    let mut legend = vec![
        (ray_pen(RayKind::Primary), "primary ray"),
        (ray_pen(RayKind::Reflected), "reflected ray"),
        (ray_pen(RayKind::Refracted), "refracted ray"),
    ];
    if options.shadows {
        legend.extend([
            (SHADOW_REACHES, "shadow ray, reaches the light"),
            (SHADOW_BLOCKED, "shadow ray, blocked"),
        ]);
    }
    legend.push((NORMAL, "surface normal"));
    // The corner that hides the least: count the drawing's points under each.
    let mut marks: Vec<DVec2> = scene
        .lights
        .iter()
        .map(|l| proj.point(l.position))
        .chain([eye])
        .collect();
    for s in &segments {
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
    let what = match (&trace.pixel, &trace.ray) {
        (Some(p), _) if trace.samples.len() > 1 || trace.settings.spp > 1 => {
            format!("pixel {},{} (sample {})", p.x, p.y, sample.index)
        }
        (Some(p), _) => format!("pixel {},{}", p.x, p.y),
        _ => "one ray".to_owned(),
    };
    fig.caption(
        &format!("{what} of {} · {}", trace.scene.file, proj.caption()),
        TEXT + 1.0,
    );
    Ok(fig)
}

/// The image plane where the diagram plane through the pixel cuts it, clipped to
/// the image's rectangle, and the pixel's point on it.
fn image_plane_segment(
    proj: &Projection,
    trace: &TraceDocument,
    sample: usize,
    camera: &crate::scene::camera::Camera,
) -> Option<(DVec2, DVec2, DVec2)> {
    let root = &trace.samples[sample].tree.nodes[0];
    // The pixel's point on the image plane: where the primary ray crosses it.
    let denom = root.direction.dot(-camera.n);
    if denom <= 0.0 {
        return None;
    }
    let pixel = root.origin + root.direction * (camera.distance / denom);
    let along = camera.n.cross(proj.toward_viewer());
    let along = if along.length() < 1e-9 {
        camera.u
    } else {
        along.normalize()
    };
    // In the image plane's own coordinates (u, v), clip pixel + s·along to |u| ≤ W, |v| ≤ H.
    let rel = pixel - (camera.eye - camera.distance * camera.n);
    let (p2, d2) = (
        DVec2::new(rel.dot(camera.u), rel.dot(camera.v)),
        DVec2::new(along.dot(camera.u), along.dot(camera.v)),
    );
    let (a, b) = clip_line(
        p2,
        d2,
        DVec2::new(-camera.half_width, -camera.half_height),
        DVec2::new(camera.half_width, camera.half_height),
    )?;
    let world =
        |q: DVec2| camera.eye - camera.distance * camera.n + q.x * camera.u + q.y * camera.v;
    Some((
        proj.point(world(a)),
        proj.point(world(b)),
        proj.point(pixel),
    ))
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
