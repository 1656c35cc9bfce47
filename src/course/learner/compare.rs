//! The learner's rays paired with raytree's, by kind and order (the primary
//! ray, then each hit's reflected and refracted child), and every quantity
//! the learner gave compared within its tolerance. The differences come out
//! in the order raytree's algorithm ran, each with the step number `raytree
//! trace --steps` prints, so the first one is the first divergence.
//!
//! A diagnosis recomputes the learner's number from raytree's inputs with
//! one mistake, so it is only sought while those inputs are the learner's
//! too: once a ray's origin, direction or hit differs, what follows on it
//! (its shadow rays, its colors, its children) is a consequence, listed
//! without a diagnosis. (A tracer with its rows flipped hit the floor where
//! raytree hit the mirror, and its shadow rays, blocked by the mirror, were
//! taken for acne.)
//!
//! The tolerances are in [`crate::course::learner::tolerance`].

use glam::DVec3;

use crate::course::learner::context::{Context, before_light};
use crate::course::learner::diagnose;
use crate::course::learner::difference::{
    Child, Difference, NoChild, Quantity, RayPath, ShadowField, Value,
};
use crate::course::learner::format::{LearnerHit, LearnerRay, LearnerShadow, LearnerTrace};
use crate::course::learner::mistakes::Diagnosis;
use crate::course::learner::tolerance::{
    COLOR, PER_LEVEL, same_color, same_direction, same_distance, same_point, tolerance,
};
use crate::trace::recorder::Branch;
use crate::tree::ray_tree::{HitRecord, ShadowOutcomeRecord, ShadowRecord};
use crate::tree::steps::StepKind;

/// Every difference, in the order raytree's algorithm met them.
pub fn compare(ctx: &Context, learner: &LearnerTrace) -> Vec<Difference> {
    let mut out = Vec::new();
    let mut walk = Walk { ctx, out: &mut out };
    walk.ray(&learner.ray, 0, &RayPath::primary(), true);
    out.sort_by_key(|d| d.step);
    out
}

struct Walk<'c, 'a> {
    ctx: &'c Context<'a>,
    out: &'c mut Vec<Difference>,
}

/// Where the walk is: the learner's ray, raytree's node `i` it pairs with,
/// the ray's path and its geometric tolerance.
struct At<'r> {
    l: &'r LearnerRay,
    i: usize,
    path: &'r RayPath,
    tol: f64,
}

/// One of the learner's shadow rays beside raytree's: the `k`th, of step `step`.
struct Cast<'r> {
    k: usize,
    step: usize,
    s: &'r LearnerShadow,
    ours: &'r ShadowRecord,
}

impl Walk<'_, '_> {
    /// A divergence of `quantity` at `at`'s ray, the learner's value and
    /// ours, diagnosed as `why`.
    fn push(
        &mut self,
        at: &At,
        step: usize,
        quantity: Quantity,
        (learner, ours): (Value, Value),
        why: Option<Diagnosis>,
    ) {
        self.out
            .push(Difference::new(at.path, step, quantity, learner, ours).because(why));
    }

    /// Compares the learner's `l` with node `i`; returns what the learner's
    /// branches that raytree cut off add to `l`'s color, so that its color is
    /// compared with ours plus that. `upstream`: every ray and hit before this
    /// ray agreed.
    fn ray(&mut self, l: &LearnerRay, i: usize, path: &RayPath, upstream: bool) -> DVec3 {
        let tol = tolerance(self.ctx.tree().nodes[i].depth);
        let at = At { l, i, path, tol };
        let ray_agrees = self.origin_and_direction(&at, upstream);
        let agrees = self.hit(&at, ray_agrees) && ray_agrees;
        self.shadows(&at, agrees);
        self.local(&at, agrees);
        let mut extra = DVec3::ZERO;
        for child in [Child::Reflected, Child::Refracted] {
            if let Some(add) = self.child(&at, child, agrees) {
                extra += add;
            }
        }
        self.tir(&at, agrees);
        self.color(&at, extra, agrees);
        extra
    }

    /// The ray itself, its origin and its direction, the direction diagnosed
    /// while every ray before agreed and its origin does. Returns whether
    /// both agree and every ray before did.
    fn origin_and_direction(&mut self, at: &At, upstream: bool) -> bool {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let node = &ctx.tree().nodes[i];
        let spawn = if i == 0 {
            ctx.step(0, StepKind::Camera)
        } else {
            ctx.step(i, StepKind::Spawn)
        };
        let origin_agrees = same_point(l.origin, node.origin, node.origin, at.tol);
        if !origin_agrees {
            let values = (Value::Vector(l.origin), Value::Vector(node.origin));
            self.push(at, spawn, Quantity::Origin, values, None);
        }
        let direction_agrees = same_direction(l.direction, node.direction, at.tol);
        if !direction_agrees {
            let why = (upstream && origin_agrees)
                .then(|| diagnose::direction(ctx, l, i))
                .flatten();
            let values = (
                Value::Vector(l.direction.normalize()),
                Value::Vector(node.direction.normalize()),
            );
            self.push(at, spawn, Quantity::Direction, values, why);
        }
        upstream && origin_agrees && direction_agrees
    }

    /// Compares the learner's hit with raytree's, diagnosing a difference when
    /// `sought` (the ray itself agreed); returns whether the hit agreed (or
    /// was not given).
    fn hit(&mut self, at: &At, sought: bool) -> bool {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let node = &ctx.tree().nodes[i];
        let Some(given) = &l.hit else { return true };
        let why = || sought.then(|| diagnose::hit(ctx, l, i)).flatten();
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
                let at_distance = Value::HitAt {
                    object: ours.name.clone(),
                    distance: ours.t * node.direction.length(),
                };
                let values = (Value::Missed, at_distance);
                self.push(at, step, Quantity::Hit, values, why());
                return false;
            }
            (Some(h), None) => {
                let what = h.object.clone().map_or(Value::Something, Value::Named);
                self.push(at, step, Quantity::Hit, (what, Value::Missed), why());
                return false;
            }
        };
        if let Some(o) = &h.object
            && *o != ours.name
        {
            let values = (Value::Named(o.clone()), Value::Named(ours.name.clone()));
            self.push(at, step, Quantity::HitObject, values, why());
            return false;
        }
        let before = self.out.len();
        self.hit_fields(at, step, (h, ours), sought);
        self.out.len() == before
    }

    /// The fields of a hit on the object raytree's ray hit too: its t, point,
    /// normal and side, the t and the normal diagnosed when `sought`.
    fn hit_fields(
        &mut self,
        at: &At,
        step: usize,
        (h, ours): (&LearnerHit, &HitRecord),
        sought: bool,
    ) {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let node = &ctx.tree().nodes[i];
        if let Some(t) = h.t {
            let (dl, d) = (t * l.direction.length(), ours.t * node.direction.length());
            if !same_distance(dl, d, node.origin, at.tol) {
                let why = sought.then(|| diagnose::hit(ctx, l, i)).flatten();
                let values = (Value::Number(dl), Value::Number(d));
                self.push(at, step, Quantity::HitT, values, why);
            }
        }
        if let Some(p) = h.point
            && !same_point(p, ours.point, node.origin, at.tol)
        {
            let values = (Value::Vector(p), Value::Vector(ours.point));
            self.push(at, step, Quantity::HitPoint, values, None);
        }
        if let Some(n) = h.normal
            && !same_direction(n, ours.shading_normal, at.tol)
        {
            let why = sought.then(|| diagnose::normal(ctx, n, i)).flatten();
            let values = (
                Value::Vector(n.normalize()),
                Value::Vector(ours.shading_normal),
            );
            self.push(at, step, Quantity::HitNormal, values, why);
        }
        if let Some(e) = h.entering
            && e != ours.entering
        {
            let values = (Value::Entering(e), Value::Entering(ours.entering));
            self.push(at, step, Quantity::HitEntering, values, None);
        }
    }

    /// The shadow rays, diagnosed only when `agrees` (the ray and its hit
    /// agreed, so the learner's shadow rays start where raytree's do).
    fn shadows(&mut self, at: &At, agrees: bool) {
        let ctx = self.ctx;
        let node = &ctx.tree().nodes[at.i];
        let (Some(list), Some(_)) = (&at.l.shadows, &node.hit) else {
            return;
        };
        if list.len() != node.shadow_rays.len() {
            let step = ctx.step(at.i, StepKind::Shadow(0));
            let values = (
                Value::Count(list.len()),
                Value::Count(node.shadow_rays.len()),
            );
            self.push(at, step, Quantity::ShadowCount, values, None);
            return;
        }
        for (k, (s, ours)) in list.iter().zip(&node.shadow_rays).enumerate() {
            let step = ctx.step(at.i, StepKind::Shadow(k));
            self.shadow(at, &Cast { k, step, s, ours }, agrees);
        }
    }

    /// One shadow ray: its light, then the ray before what it found, as for
    /// every other ray (a shadow ray sent the wrong way finds the wrong things).
    fn shadow(&mut self, at: &At, cast: &Cast, agrees: bool) {
        let (s, ours, k) = (cast.s, cast.ours, cast.k);
        if s.light != ours.name {
            let learner = if self.ctx.scene.lights.iter().any(|l| l.name == s.light) {
                Value::Named(s.light.clone())
            } else {
                Value::UnknownLight(s.light.clone())
            };
            let raytree = Value::SceneLight {
                name: ours.name.clone(),
                number: k,
            };
            let quantity = Quantity::Shadow(k, ShadowField::Light);
            self.push(at, cast.step, quantity, (learner, raytree), None);
            return;
        }
        // The light is behind the surface: it adds nothing, whatever a shadow ray finds.
        if matches!(ours.outcome, ShadowOutcomeRecord::FacesAway) {
            return;
        }
        let cast_agrees = self.shadow_cast(at, cast, agrees);
        self.shadow_outcome(at, cast, cast_agrees);
    }

    /// A shadow ray's origin and direction; returns whether they agree (and
    /// `agrees`, everything before them).
    fn shadow_cast(&mut self, at: &At, cast: &Cast, agrees: bool) -> bool {
        let (s, ours, k) = (cast.s, cast.ours, cast.k);
        let tol = at.tol + PER_LEVEL;
        let mut cast_agrees = agrees;
        if let Some(o) = s.origin
            && !same_point(o, ours.origin, ours.origin, tol)
        {
            cast_agrees = false;
            let values = (Value::Vector(o), Value::Vector(ours.origin));
            let quantity = Quantity::Shadow(k, ShadowField::Origin);
            self.push(at, cast.step, quantity, values, None);
        }
        if let Some(d) = s.direction
            && !same_direction(d, ours.direction, tol)
        {
            let why = cast_agrees
                .then(|| diagnose::shadow_direction(s, d, ours, tol))
                .flatten();
            cast_agrees = false;
            let values = (
                Value::Vector(d.normalize()),
                Value::Vector(ours.direction.normalize()),
            );
            let quantity = Quantity::Shadow(k, ShadowField::Direction);
            self.push(at, cast.step, quantity, values, why);
        }
        cast_agrees
    }

    /// What a shadow ray found: blocked or not, by what, and the share of the
    /// light it let through, diagnosed when `cast_agrees`.
    fn shadow_outcome(&mut self, at: &At, cast: &Cast, cast_agrees: bool) {
        let ctx = self.ctx;
        let (s, ours, k) = (cast.s, cast.ours, cast.k);
        let ours_by = match &ours.outcome {
            ShadowOutcomeRecord::Blocked { name, .. } => Some(name.as_str()),
            _ => None,
        };
        if s.blocked != ours_by.is_some() {
            let why = cast_agrees
                .then(|| diagnose::shadow(ctx, s, at.i, k))
                .flatten();
            let learner = if s.blocked {
                Value::Blocked(s.by.clone().flatten())
            } else {
                Value::Reaches
            };
            let raytree = ours_by.map_or(Value::Reaches, |o| Value::Blocked(Some(o.to_owned())));
            let quantity = Quantity::Shadow(k, ShadowField::Blocked);
            self.push(at, cast.step, quantity, (learner, raytree), why);
            return;
        }
        if let (Some(Some(by)), Some(o)) = (&s.by, ours_by)
            && by != o
            && !blocks(ctx, by, ours)
        {
            let values = (Value::Named(by.clone()), Value::Named(o.to_owned()));
            let quantity = Quantity::Shadow(k, ShadowField::By);
            self.push(at, cast.step, quantity, values, None);
        }
        if let (Some(t), ShadowOutcomeRecord::Reaches { transmitted }) =
            (s.transmitted, &ours.outcome)
            && (t - transmitted).abs() > COLOR
        {
            let why = cast_agrees
                .then(|| diagnose::transmitted(ctx, s, t, ours, *transmitted))
                .flatten();
            let values = (Value::Number(t), Value::Number(*transmitted));
            let quantity = Quantity::Shadow(k, ShadowField::Transmitted);
            self.push(at, cast.step, quantity, values, why);
        }
    }

    /// The local color, diagnosed when `agrees`.
    fn local(&mut self, at: &At, agrees: bool) {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let node = &ctx.tree().nodes[i];
        let step = ctx.step(i, StepKind::Local);
        if let (Some(lc), Some(ours)) = (l.local, &node.local)
            && !same_color(lc, ours.total)
        {
            let why = agrees.then(|| diagnose::local(ctx, l, i)).flatten();
            let values = (Value::Color(lc), Value::Color(ours.total));
            self.push(at, step, Quantity::LocalColor, values, why);
        }
    }

    /// The child `child` of `at`'s ray: its coefficient, then the child
    /// itself. Returns what it adds to the learner's color beyond raytree's
    /// (`None`: nothing, not even zero).
    fn child(&mut self, at: &At, child: Child, agrees: bool) -> Option<DVec3> {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let tree = ctx.tree();
        let node = &tree.nodes[i];
        let (k, ours_k, mine, branch, kind) = match child {
            Child::Reflected => (
                l.k_rfl,
                node.sum.k_rfl,
                &l.reflected,
                &node.reflected,
                StepKind::Reflect,
            ),
            Child::Refracted => (
                l.k_rfa,
                node.sum.k_rfa,
                &l.refracted,
                &node.refracted,
                StepKind::Refract,
            ),
        };
        let step = ctx.step(i, kind);
        if let Some(k) = k
            && node.hit.is_some()
            && !same_color(k, DVec3::splat(ours_k))
        {
            let why = agrees
                .then(|| diagnose::coefficient(ctx, i, refracted_direction(l)))
                .flatten();
            let values = (Value::Coefficient(k), Value::Number(ours_k));
            self.push(at, step, Quantity::Coefficient(child), values, why);
        }
        let traced = branch.as_ref().and_then(|b| b.node);
        match (mine, traced) {
            (None | Some(None), None) | (None, Some(_)) => None,
            (Some(Some(c)), Some(j)) => {
                let depth = tree.nodes[j].depth;
                let sub = self.ray(c, j, &at.path.child(child.kind(), depth), agrees);
                Some(branch.as_ref().map_or(0.0, |b| b.coefficient) * sub)
            }
            (Some(None), Some(j)) => {
                let values = (
                    Value::NotSpawned(None),
                    Value::Spawned(Some(tree.nodes[j].depth)),
                );
                self.push(at, step, Quantity::Spawned(child), values, None);
                None
            }
            (Some(Some(c)), None) => Some(self.extra_branch(at, c, child, step, agrees)),
        }
    }

    /// A child the learner traced where raytree did not: tolerated (and said)
    /// when raytree stopped for its depth, its weight or a zero coefficient,
    /// a divergence after total internal reflection. Returns what it adds to
    /// the parent's color. `agrees`: the parent's rays and hit agreed.
    fn extra_branch(
        &mut self,
        at: &At,
        c: &LearnerRay,
        child: Child,
        step: usize,
        agrees: bool,
    ) -> DVec3 {
        let node = &self.ctx.tree().nodes[at.i];
        let branch = match child {
            Child::Reflected => &node.reflected,
            Child::Refracted => &node.refracted,
        };
        let outcome = branch.as_ref().map(|b| b.outcome);
        let why = NoChild::of(outcome);
        let diagnosis = (outcome == Some(Branch::TotalInternalReflection) && agrees)
            .then(|| diagnose::tir(self.ctx, at.i, Some(c.direction)));
        let path = at.path.child(child.kind(), node.depth + 1);
        let values = (Value::Spawned(None), Value::NotSpawned(Some(why)));
        let mut said =
            Difference::new(&path, step, Quantity::Ray, values.0, values.1).because(diagnosis);
        said.divergence = !why.tolerated();
        self.out.push(said);
        let k = branch.as_ref().map_or(0.0, |b| b.coefficient);
        if why.tolerated() {
            k * c.color.unwrap_or(DVec3::ZERO)
        } else {
            DVec3::ZERO
        }
    }

    /// Total internal reflection at the hit, diagnosed when the learner
    /// found none and `agrees`.
    fn tir(&mut self, at: &At, agrees: bool) {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let node = &ctx.tree().nodes[i];
        let Some(tir) = l.tir else { return };
        if node.hit.is_none() {
            return;
        }
        let ours = node
            .refracted
            .as_ref()
            .is_some_and(|b| b.outcome == Branch::TotalInternalReflection);
        if tir != ours {
            let why = (!tir && agrees).then(|| diagnose::tir(ctx, i, refracted_direction(l)));
            let step = ctx.step(i, StepKind::Refract);
            let values = (Value::Flag(tir), Value::Flag(ours));
            self.push(at, step, Quantity::Tir, values, why);
        }
    }

    /// The ray's color against raytree's plus `extra` (what the learner's
    /// branches raytree cut off add), diagnosed when `agrees`.
    fn color(&mut self, at: &At, extra: DVec3, agrees: bool) {
        let (ctx, l, i) = (self.ctx, at.l, at.i);
        let Some(c) = l.color else { return };
        let expected = ctx.tree().nodes[i].color() + extra;
        if !same_color(c, expected) {
            // Consequences get no diagnosis: the sum is remade with
            // raytree's k_rfl and k_rfa, which are the learner's only
            // where the hit is.
            let why = agrees.then(|| diagnose::color(ctx, l, i)).flatten();
            let step = ctx.step(i, StepKind::Combine);
            let values = (Value::Color(c), Value::Color(expected));
            self.push(at, step, Quantity::Color, values, why);
        }
    }
}

/// The direction of the learner's refracted child, when it has one.
fn refracted_direction(l: &LearnerRay) -> Option<DVec3> {
    l.refracted.as_ref()?.as_ref().map(|c| c.direction)
}

/// Whether object `by` is opaque and meets raytree's shadow ray `ours`
/// between the point and the light ([`before_light`]: 0 < t < its `t_max`,
/// just short of the light, as raytree's own shadow test): where two opaque
/// objects stand in the way, a tracer may name either.
fn blocks(ctx: &Context, by: &str, ours: &ShadowRecord) -> bool {
    let Some(i) = ctx.scene.objects.iter().position(|o| o.name == by) else {
        return false;
    };
    ctx.scene.material_of(i).transparent == 0.0
        && ctx
            .shadow_roots(i, ours)
            .as_slice()
            .iter()
            .any(|&t| before_light(t, ours))
}
