//! A ray diagram's layout: a pixel's rays, hits and the scene's objects
//! projected onto the drawing plane, with the box worth framing. The PNG
//! figure ([`crate::views::diagram`]) and the inspector's diagram pane both
//! draw from it.

use glam::DVec2;

use crate::scene::Scene;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayKind, RayTree, ShadowOutcomeRecord, ShadowRecord};
use crate::views::clip::clip_line;
use crate::views::figure::{Pen, palette};
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

pub(crate) const SHADOW_REACHES: Pen = Pen::solid(palette::SHADOW_REACHES, 1.0);
pub(crate) const SHADOW_BLOCKED: Pen = Pen::dashed(palette::SHADOW_BLOCKED, 1.2);
pub(crate) const NORMAL: Pen = Pen::solid(palette::NORMAL, 2.0);
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
    let rays = project_rays(&sample.tree, &proj, options);
    let eye = proj.point(camera.eye);
    let image_plane = image_plane_segment(&proj, trace, options.sample, &camera);
    let outlines: Vec<Outline> = scene.objects.iter().map(|o| proj.outline(o)).collect();
    let mut core = vec![eye];
    core.extend(
        sample.tree.nodes[0]
            .hit
            .as_ref()
            .map(|h| proj.point(h.point)),
    );
    core.extend(image_plane.map(|(a, b, _)| [a, b]).into_iter().flatten());
    for &i in &rays.touched {
        if let Some((lo, hi)) = outlines[i].bounds() {
            core.extend([lo, hi]);
        }
    }
    let (lo, hi) = frame_box(&core, &rays.points);
    let lights = scene
        .lights
        .iter()
        .map(|l| proj.point(l.position))
        .collect();
    Ok(Layout {
        proj,
        segments: rays.segments,
        hits: rays.hits,
        outlines,
        touched: rays.touched,
        eye,
        image_plane,
        lights,
        lo,
        hi,
    })
}

/// The rays of a tree, projected: what [`project_rays`] finds.
struct ProjectedRays {
    /// Shadow rays first, then rays.
    segments: Vec<Segment>,
    hits: Vec<HitMark>,
    /// Objects hit or blocking a shadow ray.
    touched: Vec<usize>,
    /// Every end of every segment.
    points: Vec<DVec2>,
}

/// Every ray (to the depth asked) and shadow ray of `tree` as a segment, every
/// hit as a mark, and the objects they touch.
fn project_rays(tree: &RayTree, proj: &Projection, options: &Options) -> ProjectedRays {
    let mut out = ProjectedRays {
        segments: Vec::new(),
        hits: Vec::new(),
        touched: Vec::new(),
        points: Vec::new(),
    };
    let shown = |depth: u32| options.depth.is_none_or(|d| depth <= d);
    for (i, node) in tree
        .nodes
        .iter()
        .enumerate()
        .filter(|(_, n)| shown(n.depth))
    {
        let from = proj.point(node.origin);
        let to = node.hit.as_ref().map(|h| proj.point(h.point));
        out.segments.push(Segment {
            from,
            to,
            dir: proj.vector(node.direction),
            pen: ray_pen(node.kind),
            arrow: true,
            node: i,
        });
        out.points.push(from);
        out.points.extend(to);
        if let Some(h) = &node.hit {
            out.touched.push(h.object);
            out.hits.push(HitMark {
                node: i,
                at: proj.point(h.point),
                normal: proj.vector(h.shading_normal),
                kind: node.kind,
            });
        }
        if options.shadows {
            for s in &node.shadow_rays {
                project_shadow_ray(s, i, proj, &mut out);
            }
        }
    }
    out.segments.sort_by_key(|s| s.arrow);
    out
}

/// A shadow ray as a segment to its light, or to its blocker.
fn project_shadow_ray(s: &ShadowRecord, node: usize, proj: &Projection, out: &mut ProjectedRays) {
    let (end, pen) = match &s.outcome {
        ShadowOutcomeRecord::FacesAway => return,
        ShadowOutcomeRecord::Reaches { .. } => (s.origin + s.direction, SHADOW_REACHES),
        ShadowOutcomeRecord::Blocked { object, t, .. } => {
            out.touched.push(*object);
            (s.origin + *t * s.direction, SHADOW_BLOCKED)
        }
    };
    let (from, to) = (proj.point(s.origin), proj.point(end));
    out.points.extend([from, to]);
    out.segments.push(Segment {
        from,
        to: Some(to),
        dir: to - from,
        pen,
        arrow: false,
        node,
    });
}

/// The box around the `core` points and the other `points` near it.
fn frame_box(core: &[DVec2], points: &[DVec2]) -> (DVec2, DVec2) {
    let bounds = |ps: &[DVec2]| {
        (
            ps.iter()
                .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p)),
            ps.iter()
                .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p)),
        )
    };
    let (core_lo, core_hi) = bounds(core);
    let reach = (core_hi - core_lo).max_element() * 0.75;
    let near = points
        .iter()
        .copied()
        .filter(|p| p.cmpge(core_lo - reach).all() && p.cmple(core_hi + reach).all());
    bounds(&core.iter().copied().chain(near).collect::<Vec<_>>())
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
