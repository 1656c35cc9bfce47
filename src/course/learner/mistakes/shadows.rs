//! The shadow ray's mistakes (lesson 8): a ray meeting the surface it starts
//! on (acne, for want of the offset the lesson introduces; a reflected or
//! refracted ray shows it too), a shadow ray sent from the light instead of
//! toward it, blocked by an object beyond the light or by a transparent one,
//! and a transparent object's k_rfa applied at each surface crossed.

use glam::DVec3;

use crate::course::learner::context::{Context, before_light};
use crate::course::learner::format::{Kind, LearnerShadow};
use crate::course::learner::mistakes::{Diagnosis, Mistake};
use crate::course::learner::tolerance::{COLOR, same_direction, same_distance, tolerance};
use crate::tree::ray_tree::{ShadowOutcomeRecord, ShadowRecord};

/// The learner's `kind` ray of node `i` meeting object `name` at `distance`
/// (t·|direction|) ≈ 0, the surface it starts on.
pub fn own_surface(
    ctx: &Context,
    kind: Kind,
    i: usize,
    (name, distance): (&str, f64),
) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let (_, parent) = ctx.parent_hit(i)?;
    (parent.name == name && same_distance(distance, 0.0, node.origin, tolerance(node.depth)))
        .then(|| {
            Diagnosis::new(
                Mistake::NoOffset,
                format!(
                    "your {} ray hits '{name}', the surface it starts on, at distance {distance:.3e}: start secondary rays a little off the surface (or ignore t ≈ 0), or they meet their own surface (acne)",
                    kind.name()
                ),
            )
        })
}

/// A shadow ray's direction `d` that differs from raytree's `ours`: the
/// learner's is `origin − light` (the lecture's is `light − origin`), within
/// `tol` as a unit vector.
pub fn reversed(s: &LearnerShadow, d: DVec3, ours: &ShadowRecord, tol: f64) -> Option<Diagnosis> {
    same_direction(d, -ours.direction, tol).then(|| {
        Diagnosis::new(
            Mistake::ShadowReversed,
            format!(
                "your shadow ray toward '{}' points away from the light: its direction is origin − light, where the lecture's is light − origin (t = 1 at the light), so it tests the objects behind the point instead of those before the light",
                s.light
            ),
        )
    })
}

/// The learner's `k`th shadow ray of node `i` blocked where raytree's
/// reaches the light: by the surface it starts from, by an object beyond the
/// light, or by a transparent object.
pub fn blocked(ctx: &Context, s: &LearnerShadow, i: usize, k: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let h = node.hit.as_ref()?;
    let by = s.by.clone().flatten()?;
    if !s.blocked {
        return None;
    }
    if by == h.name {
        return Some(Diagnosis::new(
            Mistake::NoOffset,
            format!(
                "your shadow ray toward '{}' is blocked by '{by}', the surface it starts from: start it a little off the surface, or ignore t ≈ 0 (acne)",
                s.light
            ),
        ));
    }
    let ours = &node.shadow_rays[k];
    let index = ctx.scene.objects.iter().position(|o| o.name == by)?;
    let roots = ctx.shadow_roots(index, ours);
    let before = roots.as_slice().iter().any(|&t| before_light(t, ours));
    let beyond = roots.as_slice().iter().any(|&t| t >= 1.0);
    if beyond && !before {
        return Some(Diagnosis::new(
            Mistake::ShadowBeyondLight,
            format!(
                "'{by}' meets your shadow ray toward '{}' only beyond the light (t > 1 with t = 1 at the light): only objects between the point and the light cast a shadow",
                s.light
            ),
        ));
    }
    let k_rfa = ctx.scene.material_of(index).transparent;
    (before && k_rfa > 0.0 && matches!(ours.outcome, ShadowOutcomeRecord::Reaches { .. })).then(|| {
        Diagnosis::new(
            Mistake::TransparentBlocks,
            format!(
                "your shadow ray toward '{}' stops at '{by}', which is transparent (k_rfa = {k_rfa}): a transparent object lets its share of the light through (the light arriving is multiplied by k_rfa) and the shadow ray goes on",
                s.light
            ),
        )
    })
}

/// A shadow ray's `transmitted` share `got` that is the product of each
/// transparent object's k_rfa raised to the number of its surfaces the ray
/// crosses before the light (0.88² through a glass ball), where raytree
/// applies each object's once (`transmitted` along its shadow ray `ours`).
pub fn per_surface(
    ctx: &Context,
    s: &LearnerShadow,
    got: f64,
    ours: &ShadowRecord,
    transmitted: f64,
) -> Option<Diagnosis> {
    let mut per_surface = 1.0;
    for i in 0..ctx.scene.objects.len() {
        let k = ctx.scene.material_of(i).transparent;
        let crossed = ctx
            .shadow_roots(i, ours)
            .as_slice()
            .iter()
            .filter(|&&t| before_light(t, ours))
            .count();
        if k > 0.0 && crossed > 0 {
            per_surface *= k.powi(crossed as i32);
        }
    }
    ((per_surface - transmitted).abs() > COLOR && (got - per_surface).abs() <= COLOR).then(|| {
        Diagnosis::new(
            Mistake::TransparentPerSurface,
            format!(
                "your shadow ray toward '{}' keeps {got:.4} of the light, each transparent object's k_rfa applied at every surface it crosses: raytree applies an object's k_rfa once, however many of its surfaces the ray crosses ({transmitted:.4} here)",
                s.light
            ),
        )
    })
}
