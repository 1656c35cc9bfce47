//! The learner's rays paired with raytree's, by kind and order (the primary
//! ray, then each hit's reflected and refracted child), and every quantity
//! the learner gave compared within its tolerance. The differences come out
//! in the order raytree's algorithm ran, each with the step number `raytree
//! trace --steps` prints, so the first one is the first divergence.
//!
//! The tolerances are in [`crate::course::learner::measure`].

use glam::DVec3;

use crate::course::learner::diagnose::{self, Diagnosis};
use crate::course::learner::format::{LearnerRay, LearnerTrace};
use crate::course::learner::measure::{
    COLOR, Context, PER_LEVEL, before_light, same_color, same_direction, same_distance, same_point,
    shadow_roots, tolerance,
};
use crate::course::learner::terms;
use crate::trace::recorder::Branch;
use crate::tree::ray_tree::{RayNode, ShadowOutcomeRecord};
use crate::tree::steps::StepKind;
use crate::views::numbers::{color as color_words, num, vec3 as vec_words};

/// One difference between the learner's trace and raytree's.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// The ray, as its path from the primary ray: `primary → refracted d2`.
    pub ray: String,
    /// What differs: `direction`, `hit.t`, `shadows[1].blocked`, ….
    pub quantity: String,
    /// The learner's value, in words.
    pub learner: String,
    /// raytree's value, in words.
    pub ours: String,
    /// The step of raytree's trace where it arises (as `raytree trace --steps` numbers them).
    pub step: usize,
    /// The classic mistake its numbers show, if any.
    pub diagnosis: Option<Diagnosis>,
    /// `false`: a difference tolerated and only said (a branch raytree cut off).
    pub divergence: bool,
}

/// Every difference, in the order raytree's algorithm met them.
pub fn compare(ctx: &Context, learner: &LearnerTrace) -> Vec<Difference> {
    let mut out = Vec::new();
    let mut walk = Walk { ctx, out: &mut out };
    walk.ray(&learner.ray, 0, "primary", true);
    out.sort_by_key(|d| d.step);
    out
}

struct Walk<'c, 'a> {
    ctx: &'c Context<'a>,
    out: &'c mut Vec<Difference>,
}

impl Walk<'_, '_> {
    #[allow(clippy::too_many_arguments)]
    fn push(
        &mut self,
        ray: &str,
        quantity: impl Into<String>,
        learner: String,
        ours: String,
        step: usize,
        diagnosis: Option<Diagnosis>,
        divergence: bool,
    ) {
        self.out.push(Difference {
            ray: ray.to_owned(),
            quantity: quantity.into(),
            learner,
            ours,
            step,
            diagnosis,
            divergence,
        });
    }

    /// Compares the learner's `l` with node `i`; returns what the learner's
    /// branches that raytree cut off add to `l`'s color, so that its color is
    /// compared with ours plus that. `upstream`: every ray and hit before this
    /// ray agreed.
    ///
    /// A diagnosis recomputes the learner's number from raytree's inputs with
    /// one mistake, so it is only sought while those inputs are the learner's
    /// too: once a ray's origin, direction or hit differs, what follows on it
    /// (its shadow rays, its colors, its children) is a consequence, listed
    /// without a diagnosis. (A tracer with its rows flipped hit the floor where
    /// raytree hit the mirror, and its shadow rays, blocked by the mirror, were
    /// taken for acne.)
    fn ray(&mut self, l: &LearnerRay, i: usize, path: &str, upstream: bool) -> DVec3 {
        let ctx = self.ctx;
        let tree = ctx.tree();
        let node = &tree.nodes[i];
        let tol = tolerance(node.depth);
        let spawn = if i == 0 {
            ctx.step(0, StepKind::Camera)
        } else {
            ctx.step(i, StepKind::Spawn)
        };
        let origin_agrees = same_point(l.origin, node.origin, node.origin, tol);
        if !origin_agrees {
            self.push(
                path,
                "origin",
                vec_words(l.origin),
                vec_words(node.origin),
                spawn,
                None,
                true,
            );
        }
        let direction_agrees = same_direction(l.direction, node.direction, tol);
        if !direction_agrees {
            let why = (upstream && origin_agrees)
                .then(|| diagnose::direction(ctx, l, i))
                .flatten();
            self.push(
                path,
                "direction (as a unit vector)",
                vec_words(l.direction.normalize()),
                vec_words(node.direction.normalize()),
                spawn,
                why,
                true,
            );
        }
        let ray_agrees = upstream && origin_agrees && direction_agrees;
        let agrees = self.hit(l, i, path, tol, ray_agrees) && ray_agrees;
        self.shadows(l, node, i, path, tol, agrees);
        let local_step = ctx.step(i, StepKind::Local);
        if let (Some(lc), Some(ours)) = (l.local, &node.local)
            && !same_color(lc, ours.total)
        {
            let why = agrees.then(|| diagnose::local(ctx, l, i)).flatten();
            self.push(
                path,
                "local color",
                color_words(lc),
                color_words(ours.total),
                local_step,
                why,
                true,
            );
        }
        let mut extra = DVec3::ZERO;
        for (name, k, ours_k, child, branch, kind) in [
            (
                "k_rfl",
                l.k_rfl,
                node.sum.k_rfl,
                &l.reflected,
                &node.reflected,
                StepKind::Reflect,
            ),
            (
                "k_rfa",
                l.k_rfa,
                node.sum.k_rfa,
                &l.refracted,
                &node.refracted,
                StepKind::Refract,
            ),
        ] {
            let step = ctx.step(i, kind);
            if let Some(k) = k
                && node.hit.is_some()
                && !same_color(k, DVec3::splat(ours_k))
            {
                let why = agrees
                    .then(|| diagnose::coefficient(ctx, i, refracted_direction(l)))
                    .flatten();
                // A number written as one is said as one.
                let yours = if k.x == k.y && k.y == k.z {
                    num(k.x)
                } else {
                    vec_words(k)
                };
                self.push(path, name, yours, num(ours_k), step, why, true);
            }
            let child_name = if kind == StepKind::Reflect {
                "reflected"
            } else {
                "refracted"
            };
            let traced = branch.as_ref().and_then(|b| b.node);
            match (child, traced) {
                (None | Some(None), None) => {}
                (Some(Some(c)), Some(j)) => {
                    let depth = tree.nodes[j].depth;
                    let sub = self.ray(c, j, &format!("{path} → {child_name} d{depth}"), agrees);
                    extra += branch.as_ref().map_or(0.0, |b| b.coefficient) * sub;
                }
                (Some(None), Some(j)) => self.push(
                    path,
                    child_name,
                    "not spawned".to_owned(),
                    format!("spawned (depth {})", tree.nodes[j].depth),
                    step,
                    None,
                    true,
                ),
                (None, Some(_)) => {}
                (Some(Some(c)), None) => {
                    extra += self.extra_branch(c, node, i, path, child_name, step, agrees)
                }
            }
        }
        if let Some(tir) = l.tir
            && node.hit.is_some()
        {
            let ours = node
                .refracted
                .as_ref()
                .is_some_and(|b| b.outcome == Branch::TotalInternalReflection);
            if tir != ours {
                let why = (!tir && agrees).then(|| diagnose::tir(ctx, i, refracted_direction(l)));
                let step = ctx.step(i, StepKind::Refract);
                self.push(
                    path,
                    "tir (total internal reflection)",
                    tir.to_string(),
                    ours.to_string(),
                    step,
                    why,
                    true,
                );
            }
        }
        if let Some(c) = l.color {
            let expected = node.color() + extra;
            if !same_color(c, expected) {
                // Consequences get no diagnosis: the sum is remade with
                // raytree's k_rfl and k_rfa, which are the learner's only
                // where the hit is.
                let why = agrees.then(|| diagnose::color(ctx, l, i)).flatten();
                let step = ctx.step(i, StepKind::Combine);
                self.push(
                    path,
                    "color",
                    color_words(c),
                    color_words(expected),
                    step,
                    why,
                    true,
                );
            }
        }
        extra
    }

    /// A child the learner traced where raytree did not: tolerated (and said)
    /// when raytree stopped for its depth, its weight or a zero coefficient,
    /// a divergence after total internal reflection. Returns what it adds to
    /// the parent's color. `agrees`: the parent's rays and hit agreed.
    #[allow(clippy::too_many_arguments)]
    fn extra_branch(
        &mut self,
        c: &LearnerRay,
        node: &RayNode,
        i: usize,
        path: &str,
        child_name: &str,
        step: usize,
        agrees: bool,
    ) -> DVec3 {
        let branch = if child_name == "reflected" {
            &node.reflected
        } else {
            &node.refracted
        };
        let at = format!("{path} → {child_name} d{}", node.depth + 1);
        let outcome = branch.as_ref().map(|b| b.outcome);
        let (why, divergence) = match outcome {
            Some(Branch::MaxDepth) => ("raytree stopped at the scene's max_depth", false),
            Some(Branch::WeightCutoff) => {
                ("raytree skipped it: its weight is below the cutoff", false)
            }
            Some(Branch::NoCoefficient) => ("raytree spawns none: its coefficient is 0", false),
            Some(Branch::TotalInternalReflection) => {
                ("total internal reflection: there is no refracted ray", true)
            }
            Some(Branch::Traced) | None => ("raytree's ray missed: it has no children", true),
        };
        let diagnosis = (outcome == Some(Branch::TotalInternalReflection) && agrees)
            .then(|| diagnose::tir(self.ctx, i, Some(c.direction)));
        self.push(
            &at,
            "ray",
            "spawned".to_owned(),
            format!("not spawned ({why})"),
            step,
            diagnosis,
            divergence,
        );
        let k = branch.as_ref().map_or(0.0, |b| b.coefficient);
        if divergence {
            DVec3::ZERO
        } else {
            k * c.color.unwrap_or(DVec3::ZERO)
        }
    }

    /// Compares the learner's hit with raytree's, diagnosing a difference when
    /// `diagnose` (the ray itself agreed); returns whether the hit agreed (or
    /// was not given).
    fn hit(&mut self, l: &LearnerRay, i: usize, path: &str, tol: f64, diagnose: bool) -> bool {
        let ctx = self.ctx;
        let node = &ctx.tree().nodes[i];
        let Some(given) = &l.hit else { return true };
        let why = |f: fn(&Context, &LearnerRay, usize) -> Option<Diagnosis>| {
            diagnose.then(|| f(ctx, l, i)).flatten()
        };
        let before = self.out.len();
        let step = ctx.step(
            i,
            if node.hit.is_some() {
                StepKind::Hit
            } else {
                StepKind::Miss
            },
        );
        let (h, ours) = match (given, &node.hit) {
            (None, None) => return true,
            (Some(h), Some(ours)) => (h, ours),
            (None, Some(ours)) => {
                let why = why(diagnose::hit);
                let ours = format!(
                    "'{}' at distance {}",
                    ours.name,
                    num(ours.t * node.direction.length())
                );
                self.push(path, "hit", "missed".to_owned(), ours, step, why, true);
                return false;
            }
            (Some(h), None) => {
                let why = why(diagnose::hit);
                let what = h
                    .object
                    .as_deref()
                    .map_or("something".to_owned(), |o| format!("'{o}'"));
                self.push(path, "hit", what, "missed".to_owned(), step, why, true);
                return false;
            }
        };
        if let Some(o) = &h.object
            && *o != ours.name
        {
            let why = why(diagnose::hit);
            self.push(
                path,
                "hit.object",
                format!("'{o}'"),
                format!("'{}'", ours.name),
                step,
                why,
                true,
            );
            return false;
        }
        if let Some(t) = h.t {
            let (dl, d) = (t * l.direction.length(), ours.t * node.direction.length());
            if !same_distance(dl, d, node.origin, tol) {
                let why = why(diagnose::hit);
                self.push(
                    path,
                    "hit.t (as a distance, t·|direction|)",
                    num(dl),
                    num(d),
                    step,
                    why,
                    true,
                );
            }
        }
        if let Some(p) = h.point
            && !same_point(p, ours.point, node.origin, tol)
        {
            self.push(
                path,
                "hit.point",
                vec_words(p),
                vec_words(ours.point),
                step,
                None,
                true,
            );
        }
        if let Some(n) = h.normal
            && !same_direction(n, ours.shading_normal, tol)
        {
            let why = diagnose.then(|| diagnose::normal(ctx, n, i)).flatten();
            self.push(
                path,
                "hit.normal (as a unit vector)",
                vec_words(n.normalize()),
                vec_words(ours.shading_normal),
                step,
                why,
                true,
            );
        }
        if let Some(e) = h.entering
            && e != ours.entering
        {
            let words = |e: bool| if e { "entering" } else { "leaving" }.to_owned();
            self.push(
                path,
                "hit.entering",
                words(e),
                words(ours.entering),
                step,
                None,
                true,
            );
        }
        self.out.len() == before
    }

    /// The shadow rays, diagnosed only when `agrees` (the ray and its hit
    /// agreed, so the learner's shadow rays start where raytree's do).
    #[allow(clippy::too_many_arguments)]
    fn shadows(
        &mut self,
        l: &LearnerRay,
        node: &RayNode,
        i: usize,
        path: &str,
        tol: f64,
        agrees: bool,
    ) {
        let ctx = self.ctx;
        let (Some(list), Some(_)) = (&l.shadows, &node.hit) else {
            return;
        };
        if list.len() != node.shadow_rays.len() {
            let step = ctx.step(i, StepKind::Shadow(0));
            self.push(
                path,
                "shadows (one per light)",
                list.len().to_string(),
                node.shadow_rays.len().to_string(),
                step,
                None,
                true,
            );
            return;
        }
        for (k, (s, ours)) in list.iter().zip(&node.shadow_rays).enumerate() {
            let step = ctx.step(i, StepKind::Shadow(k));
            let q = |f: &str| format!("shadows[{k}].{f}");
            if s.light != ours.name {
                let learner = if ctx.scene.lights.iter().any(|l| l.name == s.light) {
                    format!("'{}'", s.light)
                } else {
                    format!("'{}' (the scene has no light of that name)", s.light)
                };
                let ours = format!("'{}' (the scene's light number {k})", ours.name);
                self.push(path, q("light"), learner, ours, step, None, true);
                continue;
            }
            let ours_by = match &ours.outcome {
                // The light is behind the surface: it adds nothing, whatever a shadow ray finds.
                ShadowOutcomeRecord::FacesAway => continue,
                ShadowOutcomeRecord::Blocked { name, .. } => Some(name.as_str()),
                ShadowOutcomeRecord::Reaches { .. } => None,
            };
            // The ray before what it found, as for every other ray: a
            // shadow ray sent the wrong way finds the wrong things.
            let mut cast_agrees = agrees;
            if let Some(o) = s.origin
                && !same_point(o, ours.origin, ours.origin, tol + PER_LEVEL)
            {
                cast_agrees = false;
                self.push(
                    path,
                    q("origin"),
                    vec_words(o),
                    vec_words(ours.origin),
                    step,
                    None,
                    true,
                );
            }
            if let Some(d) = s.direction
                && !same_direction(d, ours.direction, tol + PER_LEVEL)
            {
                let why = cast_agrees
                    .then(|| {
                        crate::course::learner::signs::shadow_direction(s, d, ours, tol + PER_LEVEL)
                    })
                    .flatten();
                cast_agrees = false;
                self.push(
                    path,
                    q("direction (as a unit vector)"),
                    vec_words(d.normalize()),
                    vec_words(ours.direction.normalize()),
                    step,
                    why,
                    true,
                );
            }
            if s.blocked != ours_by.is_some() {
                let why = cast_agrees
                    .then(|| diagnose::shadow(ctx, s, i, k))
                    .flatten();
                let words = |b: Option<&str>| {
                    b.map_or("reaches the light".to_owned(), |o| {
                        format!("blocked by '{o}'")
                    })
                };
                let learner = match (s.blocked, s.by.clone().flatten()) {
                    (true, Some(by)) => words(Some(&by)),
                    (true, None) => "blocked (no blocker named)".to_owned(),
                    (false, _) => words(None),
                };
                self.push(path, q("blocked"), learner, words(ours_by), step, why, true);
                continue;
            }
            if let (Some(Some(by)), Some(o)) = (&s.by, ours_by)
                && by != o
                && !blocks(ctx, by, ours)
            {
                self.push(
                    path,
                    q("by"),
                    format!("'{by}'"),
                    format!("'{o}'"),
                    step,
                    None,
                    true,
                );
            }
            if let (Some(t), ShadowOutcomeRecord::Reaches { transmitted }) =
                (s.transmitted, &ours.outcome)
                && (t - transmitted).abs() > COLOR
            {
                let why = cast_agrees
                    .then(|| terms::transmitted(ctx, s, t, ours, *transmitted))
                    .flatten();
                self.push(
                    path,
                    q("transmitted"),
                    num(t),
                    num(*transmitted),
                    step,
                    why,
                    true,
                );
            }
        }
    }
}

/// The direction of the learner's refracted child, when it has one.
fn refracted_direction(l: &LearnerRay) -> Option<DVec3> {
    l.refracted.as_ref()?.as_ref().map(|c| c.direction)
}

/// Whether object `by` is opaque and meets raytree's shadow ray `ours`
/// between the point and the light ([`before_light`]: 0 < t < its `t_max`, just short of the
/// light, as raytree's own shadow test):
/// where two opaque objects stand in the way, a tracer may name either.
fn blocks(ctx: &Context, by: &str, ours: &crate::tree::ray_tree::ShadowRecord) -> bool {
    let Some(i) = ctx.scene.objects.iter().position(|o| o.name == by) else {
        return false;
    };
    ctx.scene.material_of(i).transparent == 0.0
        && shadow_roots(ctx, i, ours)
            .as_slice()
            .iter()
            .any(|&t| before_light(t, ours))
}
