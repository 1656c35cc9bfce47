//! A transformed object's normal (lesson 6), recognised in the hit's
//! normal: the object-space normal carried to the world like a point (by
//! `M`) or by `M⁻¹` itself, where the lecture's rule is the inverse transpose
//! `(M⁻¹)ᵀ`; for a rotation and a scale together the three differ. (The
//! normal used at the length `(M⁻¹)ᵀ` leaves it shows in the local color:
//! [`crate::course::learner::mistakes::phong`].)

use glam::DVec3;

use crate::course::learner::context::Context;
use crate::course::learner::mistakes::{Diagnosis, Mistake};
use crate::course::learner::tolerance::{same_direction, tolerance};

/// The learner's normal `n` at node `i`'s hit, found to be the object-space
/// normal carried by `M` or `M⁻¹` (either way round).
pub fn normal(ctx: &Context, n: DVec3, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let h = node.hit.as_ref()?;
    let tol = tolerance(node.depth);
    let object_normal = h.object_normal?;
    let t = ctx
        .scene
        .objects
        .get(h.object)
        .and_then(|o| o.transform.as_deref())?;
    let by_point = t.to_world.matrix3 * object_normal;
    let by_inverse = t.to_object.matrix3 * object_normal;
    let correct = h.shading_normal;
    for (wrong, how) in [(by_point, "M, like a point"), (by_inverse, "M⁻¹")] {
        let wrong = wrong.normalize_or_zero();
        if !same_direction(wrong, correct, tol)
            && !same_direction(wrong, -correct, tol)
            && (same_direction(n, wrong, tol) || same_direction(n, -wrong, tol))
        {
            return Some(Diagnosis::new(
                Mistake::NormalTransform,
                format!(
                    "your normal at '{}' is its object-space normal carried by {how}: a normal goes to the world by the inverse transpose (M⁻¹)ᵀ, so that it stays perpendicular to the stretched surface",
                    h.name
                ),
            ));
        }
    }
    None
}
