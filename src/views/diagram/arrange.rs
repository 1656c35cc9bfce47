//! Laying a recorded tree out on the drawing plane, honestly: each object's
//! cut solid, its silhouette a ghost, a ray's passes in front of or behind
//! objects marked, and the window worth framing.

use glam::{DVec2, DVec3};

use crate::geometry::object::Object;
use crate::scene::Scene;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayNode, RayTree, ShadowOutcomeRecord};
use crate::tree::steps::{Step, StepKind};
use crate::views::diagram::boxes::{self};
use crate::views::diagram::frame;
use crate::views::diagram::layout::{HitMark, Layout, ObjectShape, Segment};
use crate::views::diagram::marks::{self};
use crate::views::diagram::options::Options;
use crate::views::diagram::projection::Projection;
use crate::views::diagram::section::{cross_section, passing};
use crate::views::diagram::style::Stroke;

/// Which of the scene's objects a layout projects.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Objects {
    /// Every object: a figure shows the whole scene in the drawing plane.
    #[default]
    All,
    /// The objects the sample's rays were tested against, hit or were blocked
    /// by: with a hierarchy, those it put in the rays' way; without one, every
    /// object. So the work follows the tree, not the scene, for a view drawn
    /// again at every key (the inspector's, in a scene of a million objects).
    Met,
}

/// Projects sample `options.sample` of `trace` (and `scene`) for drawing.
pub fn layout(trace: &TraceDocument, scene: &Scene, options: &Options) -> Result<Layout, String> {
    layout_of(trace, scene, options, Objects::All)
}

/// [`layout`], projecting only `objects` of the scene's objects.
pub fn layout_of(
    trace: &TraceDocument,
    scene: &Scene,
    options: &Options,
    objects: Objects,
) -> Result<Layout, String> {
    let sample = trace
        .samples
        .get(options.sample)
        .ok_or_else(|| format!("the trace has no sample {}", options.sample + 1))?;
    let camera = scene.camera();
    let proj = Projection::new(options.view, trace, options.sample, &camera);
    let steps = trace.steps(options.sample);
    let shown = Shown::new(&steps, options);
    let drawn = match objects {
        Objects::All => (0..scene.objects.len()).collect(),
        Objects::Met => met(&sample.tree),
    };
    let among = Among {
        scene,
        objects: &drawn,
    };
    let rays = rays(&sample.tree, &among, &proj, &shown, options);
    let objects = object_shapes(&sample.tree, &among, &proj);
    let marks = marks::marks(&sample.tree, &steps, &proj, options, &shown.hits());
    let near_misses = marks::near_misses(&sample.tree.nodes[0], among.each())
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
        segments: rays.segments,
        hits: rays.hits,
        objects,
        eye,
        image_plane,
        lights,
        marks,
        window: (DVec2::ZERO, DVec2::ZERO),
        near_misses,
        boxes: rays.boxes,
        structure: trace.structure,
    };
    lay.window = options
        .window
        .unwrap_or_else(|| frame::frame(&lay, options.fit));
    Ok(lay)
}

/// What the tree's shown rays put on the drawing plane.
struct Rays {
    /// The rays and shadow rays, those with arrowheads last.
    segments: Vec<Segment>,
    /// The hits found.
    hits: Vec<HitMark>,
    /// The boxes the rays were tested against, when drawn.
    boxes: Vec<boxes::BoxMark>,
}

/// Each ray a step-through has reached, with its hit, its boxes and its
/// shadow rays as options ask.
fn rays(
    tree: &RayTree,
    among: &Among,
    proj: &Projection,
    shown: &Shown,
    options: &Options,
) -> Rays {
    let far = reach(among, proj);
    let mut out = Rays {
        segments: Vec::new(),
        hits: Vec::new(),
        boxes: Vec::new(),
    };
    for (i, node) in tree.nodes.iter().enumerate() {
        if !shown.ray(i, node) {
            continue;
        }
        out.segments.push(ray_segment(among, proj, i, node, far));
        if options.boxes {
            out.boxes.extend(boxes::project(i, &node.boxes, proj));
        }
        if let Some(h) = node.hit.as_ref().filter(|_| shown.hit(i)) {
            out.hits.push(HitMark {
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
                    out.segments.extend(shadow_segments(among, proj, (i, k), s));
                }
            }
        }
    }
    out.segments.sort_by_key(|s| s.stroke.arrow());
    out
}

/// Each object projected: its silhouette, what the drawing plane cuts of it,
/// and whether the tree hit it or a shadow ray was blocked by it.
fn object_shapes(tree: &RayTree, among: &Among, proj: &Projection) -> Vec<ObjectShape> {
    let mut touched: Vec<usize> = tree
        .nodes
        .iter()
        .filter_map(|n| n.hit.as_ref().map(|h| h.object))
        .collect();
    touched.extend(marks::blockers(tree));
    among
        .each()
        .map(|(i, o)| ObjectShape {
            object: i,
            silhouette: proj.outline(o),
            section: cross_section(proj, o),
            touched: touched.contains(&i),
        })
        .collect()
}

/// The scene with the objects a layout projects.
struct Among<'a> {
    scene: &'a Scene,
    /// Indices into the scene's objects, in order.
    objects: &'a [usize],
}

impl Among<'_> {
    /// The objects projected, with their indices.
    fn each(&self) -> impl Iterator<Item = (usize, &Object)> + '_ {
        self.objects.iter().map(|&i| (i, &self.scene.objects[i]))
    }
}

/// The objects `tree`'s rays were tested against, hit or were blocked by
/// (a shadow ray records only its blocker and the object it tried first), in
/// order.
fn met(tree: &RayTree) -> Vec<usize> {
    let mut met: Vec<usize> = tree
        .nodes
        .iter()
        .flat_map(|n| {
            let shadows = n.shadow_rays.iter().filter_map(|s| s.recent.as_ref());
            n.tests
                .iter()
                .map(|t| t.object)
                .chain(n.hit.as_ref().map(|h| h.object))
                .chain(shadows.map(|r| r.object))
        })
        .collect();
    met.extend(marks::blockers(tree));
    met.sort_unstable();
    met.dedup();
    met
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

/// A 3D length that runs past every bounded object projected: how far a ray
/// that leaves the scene is drawn (the frame's edge clips it).
fn reach(scene: &Among, proj: &Projection) -> f64 {
    let extent = scene
        .each()
        .filter_map(|(_, o)| o.bounds())
        .map(|b| {
            (b.max - proj.origin)
                .abs()
                .max_element()
                .max((b.min - proj.origin).abs().max_element())
        })
        .fold(1.0, f64::max);
    let lights = scene
        .scene
        .lights
        .iter()
        .map(|l| (l.position - proj.origin).length())
        .fold(0.0, f64::max);
    4.0 * extent.max(lights)
}

/// A ray from its origin to its hit, or far out when it leaves the scene.
fn ray_segment(scene: &Among, proj: &Projection, i: usize, node: &RayNode, far: f64) -> Segment {
    let end = node.hit.as_ref().map_or_else(
        || node.origin + far * node.direction.normalize(),
        |h| h.point,
    );
    segment(
        scene,
        proj,
        (i, None),
        Stroke::Ray(node.kind),
        (node.origin, end),
        node.hit.is_none(),
    )
}

/// A shadow ray to its light, or to its blocker and on, faint, to the light;
/// none when the light is behind the surface (a mark shows that instead).
fn shadow_segments(
    scene: &Among,
    proj: &Projection,
    (i, k): (usize, usize),
    s: &crate::tree::ray_tree::ShadowRecord,
) -> Vec<Segment> {
    let light = s.origin + s.direction;
    match &s.outcome {
        ShadowOutcomeRecord::FacesAway => Vec::new(),
        ShadowOutcomeRecord::Reaches { .. } => {
            vec![segment(
                scene,
                proj,
                (i, Some(k)),
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
                    (i, Some(k)),
                    Stroke::ShadowBlocked,
                    (s.origin, blocker),
                    false,
                ),
                segment(
                    scene,
                    proj,
                    (i, Some(k)),
                    Stroke::ShadowPastBlocker,
                    (blocker, light),
                    false,
                ),
            ]
        }
    }
}

fn segment(
    scene: &Among,
    proj: &Projection,
    (node, shadow): (usize, Option<usize>),
    stroke: Stroke,
    (a, b): (DVec3, DVec3),
    leaves: bool,
) -> Segment {
    let mut pieces: Vec<[f64; 2]> = scene
        .each()
        .flat_map(|(_, o)| passing(proj, o, (a, b)))
        .collect();
    pieces.sort_by(|x, y| x[0].total_cmp(&y[0]));
    Segment {
        from: proj.point(a),
        to: proj.point(b),
        leaves,
        stroke,
        node,
        shadow,
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
    let (a, b) = crate::figure::clip::clip_line(
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
