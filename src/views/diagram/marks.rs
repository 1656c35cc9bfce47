//! The marks a lecture slide puts on a ray diagram, computed from the recorded
//! tree: the angles of reflection and refraction with their values, the
//! indices on either side of a refracting boundary, a badge where total
//! internal reflection happened, a cross where a shadow ray was blocked, a
//! note where the light was behind the surface, ticks of `t` along the rays,
//! and the step numbers of `raytree trace --steps`. Numbers come from the tree
//! (the angles from its `n·c` and Snell's record), never from the figure.

use glam::{DVec2, DVec3};

use crate::geometry::object::Object;
use crate::math::angle::angle_between;
use crate::tree::arithmetic::{Fate, RefractionRecord};
use crate::tree::ray_tree::{
    Branch, BranchRecord, HitRecord, RayKind, RayNode, RayTree, ShadowOutcomeRecord,
};
use crate::tree::steps::{Step, StepKind};
use crate::views::diagram::options::{Labels, Options};
use crate::views::diagram::projection::Projection;
use crate::views::numbers::{degrees, num};

/// Everything marked, in diagram coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Marks {
    /// Where shadow rays were blocked.
    pub blocked: Vec<Blocked>,
    /// Hits whose light was behind the surface: no shadow ray was cast.
    pub behind: Vec<Behind>,
    /// Angle arcs at reflections and refractions drawn in the plane.
    pub angles: Vec<Angle>,
    /// `n₁ | n₂` on either side of a refracting boundary.
    pub boundaries: Vec<Boundary>,
    /// Total internal reflections.
    pub tir: Vec<Tir>,
    /// Ticks of `t` along rays.
    pub ticks: Vec<Tick>,
    /// The hit object's other roots on a ray's line.
    pub roots: Vec<RootMark>,
    /// Step numbers.
    pub steps: Vec<StepNumber>,
}

/// A shadow ray's blocker.
#[derive(Clone, Debug, PartialEq)]
pub struct Blocked {
    /// Where the shadow ray met it.
    pub at: DVec2,
    /// The hit's node.
    pub node: usize,
    /// That node's depth.
    pub depth: u32,
    /// The blocking object.
    pub object: usize,
    /// Which of the node's shadow rays it blocked.
    pub shadow: usize,
}

/// A light behind the surface at a hit.
#[derive(Clone, Debug, PartialEq)]
pub struct Behind {
    /// The hit.
    pub at: DVec2,
    /// Toward the light, in the drawing (unit).
    pub toward: DVec2,
    /// The hit's node.
    pub node: usize,
}

/// An angle between two directions at a point.
#[derive(Clone, Debug, PartialEq)]
pub struct Angle {
    /// The vertex.
    pub at: DVec2,
    /// The arc runs from this unit direction …
    pub from: DVec2,
    /// … to this one, the short way.
    pub to: DVec2,
    /// What it is and its value: `θ₁ = 24.31°`.
    pub label: String,
    /// A side of the angle the figure does not otherwise draw (the normal's
    /// continuation into the second medium, for θ₂): drawn dotted.
    pub guide: Option<DVec2>,
    /// The node whose hit it is at.
    pub node: usize,
}

/// The indices on either side of a refracting boundary.
#[derive(Clone, Debug, PartialEq)]
pub struct Boundary {
    /// The hit.
    pub at: DVec2,
    /// The normal facing the incoming ray (n₁'s side), in the drawing (unit).
    pub normal: DVec2,
    /// The incoming side's label.
    pub n1: String,
    /// The far side's label.
    pub n2: String,
    /// The node whose hit it is.
    pub node: usize,
}

/// Where total internal reflection happened.
#[derive(Clone, Debug, PartialEq)]
pub struct Tir {
    /// The hit.
    pub at: DVec2,
    /// The badge's text.
    pub text: String,
    /// The node whose hit it is.
    pub node: usize,
}

/// A tick across a ray at a whole step of `t`.
#[derive(Clone, Debug, PartialEq)]
pub struct Tick {
    /// Where.
    pub at: DVec2,
    /// Across the ray (unit).
    pub across: DVec2,
    /// `t = 2`.
    pub label: String,
    /// The ray it is on.
    pub node: usize,
}

/// A root of the hit object's equation that is not the hit: where the line
/// leaves the object past the hit, or a crossing behind the ray's start.
#[derive(Clone, Debug, PartialEq)]
pub struct RootMark {
    /// The root's point on the line.
    pub at: DVec2,
    /// Where the drawn ray stops short of it (the hit, or the start): the
    /// line is drawn on from there, dotted.
    pub from: DVec2,
    /// The ray's kind, for its pen.
    pub kind: RayKind,
    /// `t = −1: behind S, rejected`.
    pub label: String,
    /// The ray whose line it is on.
    pub node: usize,
}

/// A step number of `raytree trace --steps`.
#[derive(Clone, Debug, PartialEq)]
pub struct StepNumber {
    /// Where.
    pub at: DVec2,
    /// The number.
    pub number: usize,
}

/// The objects that blocked a shadow ray.
pub fn blockers(tree: &RayTree) -> Vec<usize> {
    tree.nodes
        .iter()
        .flat_map(|n| &n.shadow_rays)
        .filter_map(|s| match s.outcome {
            ShadowOutcomeRecord::Blocked { object, .. } => Some(object),
            _ => None,
        })
        .collect()
}

/// The marks of `tree` as drawn through `proj`; `shown` limits them to the hits
/// a step-through has reached (`None`: all). Angles, indices and badges are
/// marked only where the rays lie in the drawing plane, so the drawn angle is
/// the true one.
pub fn marks(
    tree: &RayTree,
    steps: &[Step],
    proj: &Projection,
    options: &Options,
    shown: &Option<Vec<usize>>,
) -> Marks {
    let mut m = Marks::default();
    for (i, node, h) in drawn_hits(tree, options, shown) {
        if options.shadows {
            shadow_marks(node, i, proj, &mut m);
        }
        let seen = Seen::of(tree, i, h, proj, options);
        m.angles.extend(angles(&seen, h, proj));
        if let Some(r) = &h.refraction {
            refraction_marks(&seen, node, h, r, &mut m);
        }
    }
    if options.ticks {
        m.ticks = ticks(tree, proj, options, shown);
    }
    if options.roots {
        m.roots = other_roots(tree, proj, options, shown);
    }
    if options.steps {
        m.steps = step_numbers(tree, steps, proj, options, shown);
    }
    m
}

/// A hit as the drawing plane shows it: what its angles, badge and indices
/// need.
struct Seen {
    /// The hit's node.
    node: usize,
    /// The hit, drawn.
    at: DVec2,
    /// Back along the incoming ray, drawn (unit).
    back: DVec2,
    /// The normal the formulas use, drawn (unit).
    n: DVec2,
    /// The incoming ray and the normal lie in the drawing plane.
    flat: bool,
    /// Its angles and indices are named: every label asked for, a hit of the
    /// first two levels, in the plane.
    labelled: bool,
    /// The reflected ray's direction, when drawn, named and in the plane.
    reflected: Option<DVec3>,
    /// The refracted ray's direction and θ₂, when drawn, named and in the plane.
    refracted: Option<(DVec3, f64)>,
}

impl Seen {
    fn of(tree: &RayTree, i: usize, h: &HitRecord, proj: &Projection, options: &Options) -> Self {
        let node = &tree.nodes[i];
        let depth_ok = |d: u32| options.depth.is_none_or(|max| d <= max);
        let w = proj.toward_viewer();
        let in_plane = |v: DVec3| v.normalize_or_zero().dot(w).abs() < 1e-6;
        let flat = in_plane(h.incoming) && in_plane(h.shading_normal);
        let child_dir = |branch: &Option<BranchRecord>| {
            branch
                .as_ref()
                .and_then(|b| b.node)
                .filter(|&c| depth_ok(tree.nodes[c].depth))
                .map(|c| tree.nodes[c].direction)
        };
        let unit = |v: DVec3| proj.vector(v).normalize_or_zero();
        let labelled = options.labels == Labels::All && node.depth <= 2 && flat;
        Seen {
            node: i,
            at: proj.point(h.point),
            back: unit(-h.incoming),
            n: unit(h.shading_normal),
            flat,
            labelled,
            reflected: child_dir(&node.reflected).filter(|&v| labelled && in_plane(v)),
            refracted: child_dir(&node.refracted)
                .filter(|&t| labelled && in_plane(t))
                .zip(h.refraction.as_ref().and_then(|r| r.theta2)),
        }
    }
}

/// The arcs at a hit: the angle of incidence (one arc, named for both laws
/// when both apply), the angle of reflection, the angle of refraction.
fn angles(seen: &Seen, h: &HitRecord, proj: &Projection) -> Vec<Angle> {
    let unit = |v: DVec3| proj.vector(v).normalize_or_zero();
    let theta = angle_between(-h.incoming, h.shading_normal).to_degrees();
    let angle = |from: DVec2, to: DVec2, label: String, guide: Option<DVec2>| Angle {
        at: seen.at,
        from,
        to,
        label,
        guide,
        node: seen.node,
    };
    let mut out = Vec::new();
    let name = match (seen.reflected.is_some(), seen.refracted.is_some()) {
        (false, false) => None,
        (true, true) => Some("θ₁ = θᵢ"),
        (false, true) => Some("θ₁"),
        (true, false) => Some("θᵢ"),
    };
    if let Some(name) = name {
        let label = format!("{name} = {}", degrees(theta));
        out.push(angle(seen.back, seen.n, label, None));
    }
    if let Some(v) = seen.reflected {
        let label = format!("θᵣ = {}", degrees(theta));
        out.push(angle(seen.n, unit(v), label, None));
    }
    if let Some((t, theta2)) = seen.refracted {
        let label = format!("θ₂ = {}", degrees(theta2));
        out.push(angle(-seen.n, unit(t), label, Some(-seen.n)));
    }
    out
}

/// At a refracting hit: a badge where total internal reflection happened
/// (the first one with its angles), and the indices either side.
fn refraction_marks(
    seen: &Seen,
    node: &RayNode,
    h: &HitRecord,
    r: &RefractionRecord,
    m: &mut Marks,
) {
    let tir = node
        .refracted
        .as_ref()
        .is_some_and(|b| b.outcome == Branch::TotalInternalReflection);
    if tir && seen.flat {
        let text = if m.tir.is_empty() {
            format!(
                "total internal reflection: θ₁ = {} > critical angle {}",
                degrees(r.theta1),
                r.critical.map_or(String::new(), degrees)
            )
        } else {
            "total internal reflection".to_owned()
        };
        m.tir.push(Tir {
            at: seen.at,
            text,
            node: seen.node,
        });
    }
    if seen.labelled {
        m.boundaries.push(Boundary {
            at: seen.at,
            normal: seen.n,
            n1: format!("n₁ = {}", num(h.n1)),
            n2: format!("n₂ = {}", num(h.n2)),
            node: seen.node,
        });
    }
}

fn shadow_marks(node: &RayNode, i: usize, proj: &Projection, m: &mut Marks) {
    let Some(h) = &node.hit else { return };
    for (k, s) in node.shadow_rays.iter().enumerate() {
        match s.outcome {
            ShadowOutcomeRecord::Blocked { object, t, .. } => m.blocked.push(Blocked {
                at: proj.point(s.origin + t * s.direction),
                node: i,
                depth: node.depth,
                object,
                shadow: k,
            }),
            ShadowOutcomeRecord::FacesAway => m.behind.push(Behind {
                at: proj.point(h.point),
                toward: proj.vector(s.direction).normalize_or_zero(),
                node: i,
            }),
            ShadowOutcomeRecord::Reaches { .. } => {}
        }
    }
}

/// The hits a diagram draws, with their nodes: within its depth, and
/// reached by a step-through's step (`shown`, `None` for all).
fn drawn_hits<'t>(
    tree: &'t RayTree,
    options: &Options,
    shown: &Option<Vec<usize>>,
) -> impl Iterator<Item = (usize, &'t RayNode, &'t HitRecord)> {
    let depth = options.depth;
    let shown = shown.clone();
    tree.nodes.iter().enumerate().filter_map(move |(i, node)| {
        let h = node.hit.as_ref()?;
        let drawn =
            depth.is_none_or(|d| node.depth <= d) && shown.as_ref().is_none_or(|s| s.contains(&i));
        drawn.then_some((i, node, h))
    })
}

/// Ticks along each ray: at every whole `t` while the ray ends within
/// [`WHOLE_TICKS`] (`1 < t ≤ 10`), so a learner can count the lengths of `c`;
/// otherwise ([`tick_step`]) about five ticks at a round step, with t = 1
/// always ticked on a primary ray, where it crosses the image plane.
fn ticks(
    tree: &RayTree,
    proj: &Projection,
    options: &Options,
    shown: &Option<Vec<usize>>,
) -> Vec<Tick> {
    let mut out = Vec::new();
    for (i, node, h) in drawn_hits(tree, options, shown) {
        let step = tick_step(h.t);
        let across = proj.vector(node.direction).normalize_or_zero().perp();
        let tick = |t: f64| Tick {
            at: proj.point(node.origin + t * node.direction),
            across,
            label: format!("t = {}", num(t)),
            node: i,
        };
        let primary = node.kind == RayKind::Primary && h.t > 1.0 && step != 1.0;
        if primary {
            out.push(tick(1.0));
        }
        let mut k = 1.0;
        while k * step < h.t * (1.0 - 1e-9) {
            let t = k * step;
            // Ticks crowding the image plane's would overlap its label.
            if !(primary && (t - 1.0).abs() < step / 2.0) {
                out.push(tick(t));
            }
            k += 1.0;
        }
    }
    out
}

/// The roots of each drawn hit's object that the tracer passed over (not the
/// surface a ray starts on, which lies at its start).
fn other_roots(
    tree: &RayTree,
    proj: &Projection,
    options: &Options,
    shown: &Option<Vec<usize>>,
) -> Vec<RootMark> {
    let mut out = Vec::new();
    for (i, node, h) in drawn_hits(tree, options, shown) {
        let Some(test) = node.tests.iter().find(|t| t.object == h.object) else {
            continue;
        };
        for r in &test.roots {
            let why = match r.fate {
                Fate::Chosen => continue,
                _ if r.at_start => continue,
                Fate::Farther => "past the hit, not the first",
                Fate::Behind => "behind S, rejected",
                Fate::Beyond => "past the ray's end, rejected",
            };
            out.push(RootMark {
                at: proj.point(node.origin + r.t * node.direction),
                from: proj.point(if r.t > h.t { h.point } else { node.origin }),
                kind: node.kind,
                label: format!("t = {}: {why}", num(r.t)),
                node: i,
            });
        }
    }
    out
}

/// Up to this `t`, a ray is ticked at every whole `t`.
pub const WHOLE_TICKS: f64 = 10.0;

/// The step between ticks on a ray that ends at `t_end`: 1 when
/// `1 < t_end ≤ WHOLE_TICKS`, else the smallest 1, 2 or 5 times a power of ten
/// that leaves at most five ticks (a longer ray's whole steps would crowd, a
/// ray shorter than 1 has none).
pub fn tick_step(t_end: f64) -> f64 {
    if t_end > 1.0 && t_end <= WHOLE_TICKS {
        return 1.0;
    }
    let raw = t_end / 5.0;
    let power = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|&s| s >= raw)
        .unwrap_or(10.0 * power)
}

/// The spawn step's number at a third of each ray, and the hit step's at the hit.
fn step_numbers(
    tree: &RayTree,
    steps: &[Step],
    proj: &Projection,
    options: &Options,
    shown: &Option<Vec<usize>>,
) -> Vec<StepNumber> {
    let mut out = Vec::new();
    for (k, step) in steps.iter().enumerate() {
        let node = &tree.nodes[step.node];
        if options.depth.is_some_and(|d| node.depth > d)
            || shown.as_ref().is_some_and(|s| !s.contains(&step.node))
        {
            continue;
        }
        let at = match (step.kind, &node.hit) {
            (StepKind::Spawn, Some(h)) => proj.point(node.origin + (h.point - node.origin) / 3.0),
            (StepKind::Hit, Some(h)) => proj.point(h.point),
            _ => continue,
        };
        out.push(StepNumber { at, number: k + 1 });
    }
    out
}

/// How a ray that hit nothing passed an object: the gap, and the two points
/// of closest approach (on the ray, and on the object's surface).
#[derive(Clone, Debug, PartialEq)]
pub struct NearMiss {
    /// The object.
    pub object: usize,
    /// The gap between the ray and the object's surface.
    pub gap: f64,
    /// The ray's point nearest the object.
    pub on_ray: DVec3,
    /// The object's surface point nearest the ray.
    pub on_object: DVec3,
}

/// For a ray that hit nothing, the two bounded objects of `objects` (with
/// their indices) it passed nearest: exact
/// for untransformed spheres, from the bounding box's center and half-diagonal
/// otherwise.
pub fn near_misses<'o>(
    root: &RayNode,
    objects: impl Iterator<Item = (usize, &'o Object)>,
) -> Vec<NearMiss> {
    if root.hit.is_some() {
        return Vec::new();
    }
    let d = root.direction.normalize();
    let mut near: Vec<NearMiss> = objects
        .filter_map(|(i, o)| {
            let b = o.bounds()?;
            let (center, radius) = match (&o.shape, &o.transform) {
                (crate::geometry::object::Shape::Sphere(s), None) => (s.center, s.radius),
                _ => (b.center(), (b.max - b.min).length() / 2.0),
            };
            let on_ray = root.origin + (center - root.origin).dot(d).max(0.0) * d;
            let out = (on_ray - center).normalize_or(DVec3::Y);
            Some(NearMiss {
                object: i,
                gap: ((on_ray - center).length() - radius).max(0.0),
                on_ray,
                on_object: center + radius * out,
            })
        })
        .collect();
    near.sort_by(|a, b| a.gap.total_cmp(&b.gap));
    near.truncate(2);
    near
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_steps_are_whole_up_to_ten_then_round() {
        // Every whole t from just past the image plane to t = 10.
        assert_eq!(tick_step(1.5), 1.0);
        assert_eq!(tick_step(5.014), 1.0);
        assert_eq!(tick_step(10.0), 1.0);
        // Beyond, or short of 1: about five ticks at a round step.
        assert_eq!(tick_step(10.5), 5.0);
        assert_eq!(tick_step(30.0), 10.0);
        assert_eq!(tick_step(1.0), 0.2);
        assert_eq!(tick_step(0.15), 0.05);
    }
}
