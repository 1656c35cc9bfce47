//! A ray diagram's layout: a pixel's rays, hits and the scene's objects
//! projected onto the drawing plane, honestly (each object's cut solid, its
//! silhouette a ghost, a ray's passes in front of or behind objects marked),
//! with the window worth framing. The PNG figure ([`crate::views::diagram`])
//! and the inspector's diagram pane both draw from it.

use glam::{DVec2, DVec3};

use crate::scene::Scene;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayKind, RayNode, ShadowOutcomeRecord};
use crate::tree::steps::{Step, StepKind};
use crate::views::boxes::{self, BoxMark};
use crate::views::diagram_frame;
use crate::views::marks::{self, Marks};
use crate::views::pen::{Pen, palette};
use crate::views::projection::{Outline, Projection, View};
use crate::views::section::{cross_section, passing};

/// Which labels to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Labels {
    /// None: only the legend and caption.
    None,
    /// Objects, lights and the eye.
    Objects,
    /// Also hit points (P1, P2, … in the order they were found), normals and angles.
    All,
}

/// What the figure frames.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Fit {
    /// The hits and the objects they are on, large: where the optics happen.
    #[default]
    Hits,
    /// The whole tree: the eye, the image plane, every ray near them.
    Tree,
    /// Every bounded object, the eye and the lights.
    Scene,
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
    /// What to frame.
    pub fit: Fit,
    /// An explicit window in drawing-plane coordinates (`lo`, `hi`), over `fit`.
    pub window: Option<(DVec2, DVec2)>,
    /// Tick marks along the rays at whole steps of `t`.
    pub ticks: bool,
    /// Step numbers, as `raytree trace --steps` numbers them.
    pub steps: bool,
    /// Show the algorithm only up to this step (0-based), as a step-through does.
    pub until_step: Option<usize>,
    /// Draw the hierarchy's boxes the drawn rays were tested against.
    pub boxes: bool,
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
            fit: Fit::default(),
            window: None,
            ticks: false,
            steps: false,
            until_step: None,
            boxes: false,
        }
    }
}

/// What a drawn line is; each kind differs by dash pattern as well as color.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    /// A ray of this kind.
    Ray(RayKind),
    /// A shadow ray that reaches its light.
    ShadowReaches,
    /// A shadow ray up to its blocker.
    ShadowBlocked,
    /// The rest of a blocked shadow ray, from the blocker to the light.
    ShadowPastBlocker,
}

impl Stroke {
    /// How it is drawn.
    pub fn pen(self) -> Pen {
        match self {
            Stroke::Ray(kind) => ray_pen(kind),
            Stroke::ShadowReaches => Pen::solid(palette::SHADOW_REACHES, 1.0),
            Stroke::ShadowBlocked => Pen::solid(palette::SHADOW_BLOCKED, 1.3),
            Stroke::ShadowPastBlocker => Pen::pattern(palette::SHADOW_BLOCKED, 1.0, &[2.0, 4.0]),
        }
    }

    /// Whether it ends in an arrowhead.
    pub fn arrow(self) -> bool {
        matches!(self, Stroke::Ray(_))
    }
}

/// The pen a ray of this kind is drawn with: color and dash pattern both differ,
/// so the kinds read apart in gray and for color-blind readers.
pub fn ray_pen(kind: RayKind) -> Pen {
    match kind {
        RayKind::Primary => Pen::solid(palette::PRIMARY, 2.5),
        RayKind::Reflected => Pen::pattern(palette::REFLECTED, 2.5, &[12.0, 5.0]),
        RayKind::Refracted => Pen::pattern(palette::REFRACTED, 2.5, &[12.0, 4.0, 2.5, 4.0]),
        RayKind::Shadow => Pen::solid(palette::SHADOW_REACHES, 1.0),
    }
}

/// The pen of surface normals.
pub const NORMAL: Pen = Pen::solid(palette::NORMAL, 2.0);

/// One drawn line, in diagram coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// Where it starts.
    pub from: DVec2,
    /// Where it ends: its hit, its light, or far out for a ray that leaves the scene.
    pub to: DVec2,
    /// The ray leaves the scene: it runs on to the frame's edge.
    pub leaves: bool,
    /// What it is.
    pub stroke: Stroke,
    /// The tree node it belongs to.
    pub node: usize,
    /// Parameter intervals of `from → to` where it only passes in front of or
    /// behind an object's silhouette: drawn faded and dotted.
    pub passing: Vec<[f64; 2]>,
    /// The 3D ends, for marks along it.
    pub ends: (DVec3, DVec3),
}

impl Segment {
    /// The line in pieces, in order: `(from, to, passing, last)`, where a
    /// piece is `passing` (drawn faint and dotted) inside one of the
    /// [`passing`](Self::passing) intervals and `last` when it ends the line.
    pub fn pieces(&self) -> impl Iterator<Item = (DVec2, DVec2, bool, bool)> + '_ {
        let at = |t: f64| self.from + (self.to - self.from) * t;
        let cuts: Vec<f64> = std::iter::once(0.0)
            .chain(self.passing.iter().flatten().copied())
            .chain(std::iter::once(1.0))
            .collect();
        (0..cuts.len() - 1)
            .map(move |k| (at(cuts[k]), at(cuts[k + 1]), k % 2 == 1, cuts[k + 1] == 1.0))
    }
}

/// A hit point, drawn as a dot with its normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitMark {
    /// The tree node whose hit it is.
    pub node: usize,
    /// That node's depth.
    pub depth: u32,
    /// The object hit.
    pub object: usize,
    /// Where.
    pub at: DVec2,
    /// The normal the formulas use, in the drawing.
    pub normal: DVec2,
    /// The kind of the ray that hit.
    pub kind: RayKind,
}

/// An object as drawn: its silhouette (a ghost) and what the drawing plane cuts of it.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectShape {
    /// The outline of everything it hides.
    pub silhouette: Outline,
    /// Its cross-section with the drawing plane; `None` when the plane misses it.
    pub section: Option<Outline>,
    /// A ray hit it or it blocked a shadow ray.
    pub touched: bool,
}

/// Everything a diagram shows, projected, with the window to fit.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// The projection.
    pub proj: Projection,
    /// Shadow rays first, then rays.
    pub segments: Vec<Segment>,
    /// Hit points in the order they were found.
    pub hits: Vec<HitMark>,
    /// Every object, by index.
    pub objects: Vec<ObjectShape>,
    /// The eye.
    pub eye: DVec2,
    /// The image plane's cut (two ends) and the pixel on it.
    pub image_plane: Option<(DVec2, DVec2, DVec2)>,
    /// The lights.
    pub lights: Vec<DVec2>,
    /// The angles, indices, badges and marks a slide needs.
    pub marks: Marks,
    /// The window the drawing should fit: `(lo, hi)`.
    pub window: (DVec2, DVec2),
    /// For a ray that hit nothing: the objects it passed nearest, each with its
    /// gap and the closest approach drawn (from the ray, to the object).
    pub near_misses: Vec<(usize, f64, DVec2, DVec2)>,
    /// With `boxes`: the hierarchy's boxes the drawn rays were tested against.
    pub boxes: Vec<BoxMark>,
}

/// Projects sample `options.sample` of `trace` (and `scene`) for drawing.
pub fn layout(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Layout, String> {
    let sample = trace
        .samples
        .get(options.sample)
        .ok_or_else(|| format!("the trace has no sample {}", options.sample + 1))?;
    let camera = scene.camera();
    let proj = Projection::new(options.view, trace, options.sample, &camera);
    let steps = trace.steps(options.sample);
    let shown = Shown::new(&steps, options);
    let far = reach(scene, &proj);
    let mut segments = Vec::new();
    let mut hits = Vec::new();
    let mut boxes = Vec::new();
    for (i, node) in sample.tree.nodes.iter().enumerate() {
        if !shown.ray(i, node) {
            continue;
        }
        segments.push(ray_segment(scene, &proj, i, node, far));
        if options.boxes {
            boxes.extend(boxes::project(i, &node.boxes, &proj));
        }
        if let Some(h) = node.hit.as_ref().filter(|_| shown.hit(i)) {
            hits.push(HitMark {
                node: i,
                depth: node.depth,
                object: h.object,
                at: proj.point(h.point),
                normal: proj.vector(h.shading_normal),
                kind: node.kind,
            });
        }
        if options.shadows {
            for (k, s) in node.shadow_rays.iter().enumerate() {
                if shown.shadow(i, k) {
                    segments.extend(shadow_segments(scene, &proj, i, s));
                }
            }
        }
    }
    segments.sort_by_key(|s| s.stroke.arrow());
    let mut touched: Vec<usize> = sample
        .tree
        .nodes
        .iter()
        .filter_map(|n| n.hit.as_ref().map(|h| h.object))
        .collect();
    touched.extend(marks::blockers(&sample.tree));
    let objects: Vec<ObjectShape> = scene
        .objects
        .iter()
        .enumerate()
        .map(|(i, o)| ObjectShape {
            silhouette: proj.outline(o),
            section: cross_section(&proj, o),
            touched: touched.contains(&i),
        })
        .collect();
    let marks = marks::marks(&sample.tree, &steps, &proj, options, &shown.hits());
    let near_misses = marks::near_misses(&sample.tree.nodes[0], scene)
        .into_iter()
        .map(|m| {
            (
                m.object,
                m.gap,
                proj.point(m.on_ray),
                proj.point(m.on_object),
            )
        })
        .collect();
    let image_plane = image_plane_segment(&proj, trace, options.sample, &camera);
    let eye = proj.point(camera.eye);
    let lights = scene
        .lights
        .iter()
        .map(|l| proj.point(l.position))
        .collect();
    let mut lay = Layout {
        proj,
        segments,
        hits,
        objects,
        eye,
        image_plane,
        lights,
        marks,
        window: (DVec2::ZERO, DVec2::ZERO),
        near_misses,
        boxes,
    };
    lay.window = options
        .window
        .unwrap_or_else(|| diagram_frame::frame(&lay, options.fit));
    Ok(lay)
}

/// Which parts of the tree a step-through has reached so far (everything when
/// not stepping): a ray once spawned, its hit once found, a shadow ray once cast.
struct Shown {
    spawned: Vec<usize>,
    found: Vec<usize>,
    cast: Vec<(usize, usize)>,
    depth: Option<u32>,
    all: bool,
}

impl Shown {
    fn new(steps: &[Step], options: &Options) -> Self {
        let upto = options
            .until_step
            .map_or(steps.len(), |s| (s + 1).min(steps.len()));
        let done = &steps[..upto];
        Self {
            spawned: done
                .iter()
                .filter(|s| s.kind == StepKind::Spawn)
                .map(|s| s.node)
                .collect(),
            found: done
                .iter()
                .filter(|s| s.kind == StepKind::Hit)
                .map(|s| s.node)
                .collect(),
            cast: done
                .iter()
                .filter_map(|s| match s.kind {
                    StepKind::Shadow(k) => Some((s.node, k)),
                    _ => None,
                })
                .collect(),
            depth: options.depth,
            all: options.until_step.is_none(),
        }
    }

    fn ray(&self, i: usize, node: &RayNode) -> bool {
        self.depth.is_none_or(|d| node.depth <= d) && (self.all || self.spawned.contains(&i))
    }

    fn hit(&self, i: usize) -> bool {
        self.all || self.found.contains(&i)
    }

    fn shadow(&self, i: usize, k: usize) -> bool {
        self.all || self.cast.contains(&(i, k))
    }

    /// The nodes whose hits are shown, or `None` for all.
    fn hits(&self) -> Option<Vec<usize>> {
        (!self.all).then(|| self.found.clone())
    }
}

/// A 3D length that runs past every bounded object: how far a ray that leaves
/// the scene is drawn (the frame's edge clips it).
fn reach(scene: &Scene, proj: &Projection) -> f64 {
    let extent = scene
        .objects
        .iter()
        .filter_map(|o| o.bounds())
        .map(|b| {
            (b.max - proj.origin)
                .abs()
                .max_element()
                .max((b.min - proj.origin).abs().max_element())
        })
        .fold(1.0, f64::max);
    let lights = scene
        .lights
        .iter()
        .map(|l| (l.position - proj.origin).length())
        .fold(0.0, f64::max);
    4.0 * extent.max(lights)
}

/// A ray from its origin to its hit, or far out when it leaves the scene.
fn ray_segment(scene: &Scene, proj: &Projection, i: usize, node: &RayNode, far: f64) -> Segment {
    let end = node.hit.as_ref().map_or_else(
        || node.origin + far * node.direction.normalize(),
        |h| h.point,
    );
    segment(
        scene,
        proj,
        i,
        Stroke::Ray(node.kind),
        (node.origin, end),
        node.hit.is_none(),
    )
}

/// A shadow ray to its light, or to its blocker and on, faint, to the light;
/// none when the light is behind the surface (a mark shows that instead).
fn shadow_segments(
    scene: &Scene,
    proj: &Projection,
    i: usize,
    s: &crate::tree::ray_tree::ShadowRecord,
) -> Vec<Segment> {
    let light = s.origin + s.direction;
    match &s.outcome {
        ShadowOutcomeRecord::FacesAway => Vec::new(),
        ShadowOutcomeRecord::Reaches { .. } => {
            vec![segment(
                scene,
                proj,
                i,
                Stroke::ShadowReaches,
                (s.origin, light),
                false,
            )]
        }
        ShadowOutcomeRecord::Blocked { t, .. } => {
            let blocker = s.origin + *t * s.direction;
            vec![
                segment(
                    scene,
                    proj,
                    i,
                    Stroke::ShadowBlocked,
                    (s.origin, blocker),
                    false,
                ),
                segment(
                    scene,
                    proj,
                    i,
                    Stroke::ShadowPastBlocker,
                    (blocker, light),
                    false,
                ),
            ]
        }
    }
}

fn segment(
    scene: &Scene,
    proj: &Projection,
    node: usize,
    stroke: Stroke,
    (a, b): (DVec3, DVec3),
    leaves: bool,
) -> Segment {
    let mut pieces: Vec<[f64; 2]> = scene
        .objects
        .iter()
        .flat_map(|o| passing(proj, o, (a, b)))
        .collect();
    pieces.sort_by(|x, y| x[0].total_cmp(&y[0]));
    Segment {
        from: proj.point(a),
        to: proj.point(b),
        leaves,
        stroke,
        node,
        passing: merge(pieces),
        ends: (a, b),
    }
}

/// Overlapping intervals joined, in order.
fn merge(sorted: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    let mut out: Vec<[f64; 2]> = Vec::new();
    for [a, b] in sorted {
        match out.last_mut() {
            Some(last) if a <= last[1] => last[1] = last[1].max(b),
            _ => out.push([a, b]),
        }
    }
    out
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
    let (a, b) = crate::views::clip::clip_line(
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
