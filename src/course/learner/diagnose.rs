//! Which recognisers a difference asks, in order: a wrong direction asks the
//! camera's (a primary ray), the reflection's or the refraction's; a wrong
//! hit the offset's and the roots'; and so on. Each lesson's recognisers are
//! in its file of [`crate::course::learner::mistakes`]; the first that
//! matches names the mistake.

use glam::DVec3;

use crate::course::learner::context::Context;
use crate::course::learner::format::{Kind, LearnerRay, LearnerShadow};
use crate::course::learner::mistakes::{
    Diagnosis, camera, phong, recursion, reflection, refraction, shadows, sphere, transforms,
};
use crate::course::learner::tolerance::{same_direction, tolerance};
use crate::tree::ray_tree::ShadowRecord;

/// A wrong primary or secondary direction of node `i`'s ray.
pub fn direction(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let tol = tolerance(ctx.tree().nodes[i].depth);
    let same =
        |d: Option<DVec3>| d.is_some_and(|d| d.is_finite() && same_direction(l.direction, d, tol));
    if i == 0 {
        return camera::primary(ctx, &same);
    }
    let (parent, h) = ctx.parent_hit(i)?;
    match l.kind {
        Kind::Reflected => reflection::direction(ctx, h, &same),
        Kind::Refracted => refraction::direction(ctx, parent, h, &same),
        Kind::Primary => None,
    }
}

/// A wrong hit of node `i`'s ray: the surface it starts on, or another root
/// of the same quadratic.
pub fn hit(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let h = l.hit.as_ref()?.as_ref()?;
    let t = h.t?;
    let ours = ctx.tree().nodes[i].hit.as_ref();
    let name = h.object.as_deref().or(ours.map(|o| o.name.as_str()))?;
    let met = (name, t * l.direction.length());
    shadows::own_surface(ctx, l.kind, i, met).or_else(|| sphere::root(ctx, i, met))
}

/// A wrong normal `n` at node `i`'s hit: transformed the wrong way, or
/// facing the wrong side.
pub fn normal(ctx: &Context, n: DVec3, i: usize) -> Option<Diagnosis> {
    transforms::normal(ctx, n, i).or_else(|| refraction::normal_side(ctx, n, i))
}

/// A wrong local color at node `i`'s hit.
pub fn local(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    phong::local(ctx, l, i)
}

/// A shadow ray's wrong direction `d` (raytree's is `ours`), within `tol`.
pub fn shadow_direction(
    s: &LearnerShadow,
    d: DVec3,
    ours: &ShadowRecord,
    tol: f64,
) -> Option<Diagnosis> {
    shadows::reversed(s, d, ours, tol)
}

/// The `k`th shadow ray of node `i` blocked where raytree's reaches the light.
pub fn shadow(ctx: &Context, s: &LearnerShadow, i: usize, k: usize) -> Option<Diagnosis> {
    shadows::blocked(ctx, s, i, k)
}

/// A shadow ray's share `got` of the light, where raytree's is `transmitted`.
pub fn transmitted(
    ctx: &Context,
    s: &LearnerShadow,
    got: f64,
    ours: &ShadowRecord,
    transmitted: f64,
) -> Option<Diagnosis> {
    shadows::per_surface(ctx, s, got, ours, transmitted)
}

/// A refracted ray (along `refracted`) where raytree finds total internal
/// reflection at node `i`'s hit.
pub fn tir(ctx: &Context, i: usize, refracted: Option<DVec3>) -> Diagnosis {
    refraction::tir(ctx, i, refracted)
}

/// A wrong coefficient at node `i`'s hit.
pub fn coefficient(ctx: &Context, i: usize, refracted: Option<DVec3>) -> Option<Diagnosis> {
    refraction::coefficient(ctx, i, refracted)
}

/// A wrong color of node `i`'s ray, its local color and children right.
pub fn color(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    recursion::color(ctx, l, i)
}
