//! The reflected ray's mistakes (lesson 9), recognised in its direction:
//! `c + 2(n·c)n`, the sign turned, and the formula with `n = P − center`,
//! not of unit length.

use crate::course::learner::context::Context;
use crate::course::learner::mistakes::{Diagnosis, Formula, Mistake, Same};
use crate::shading::optics::reflect;
use crate::tree::ray_tree::HitRecord;

/// A reflected direction accepted by `same`, made at the parent's hit `h`.
pub fn direction(ctx: &Context, h: &HitRecord, same: &Same) -> Option<Diagnosis> {
    let (c, n) = (h.incoming, h.shading_normal);
    if same(Some(c + 2.0 * n.dot(c) * n)) {
        return Some(Diagnosis::new(
            Mistake::ReflectionSign,
            "your reflected direction is c + 2(n·c)n: the lecture's is v = c − 2(n·c)n (n·c < 0, so −2(n·c)n pushes away from the surface)",
        ));
    }
    let r = ctx.sphere_radius(h.object)?;
    same(Some(reflect(c, n * r))).then(|| {
        Diagnosis::new(
            Mistake::NotNormalized(Formula::Reflection),
            format!(
                "your reflected direction is c − 2(n·c)n with n = P − center, of length r = {r}: the formula assumes a unit normal"
            ),
        )
    })
}
