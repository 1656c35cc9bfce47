//! Which root is the hit (lesson 5), recognised in the hit's t: another
//! root of the object's recorded quadratic, the far one or one behind the
//! ray's origin, where the hit is the smallest positive root.

use crate::course::learner::context::Context;
use crate::course::learner::mistakes::{Diagnosis, Mistake};
use crate::course::learner::tolerance::{same_distance, tolerance};

/// The learner's hit of object `name` at `distance` (t·|direction|) along
/// node `i`'s ray, found to be one of the object's other recorded roots.
pub fn root(ctx: &Context, i: usize, (name, distance): (&str, f64)) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let tol = tolerance(node.depth);
    let test = node.tests.iter().find(|r| r.name == name)?;
    let ours = node.hit.as_ref().filter(|o| o.name == name).map(|o| o.t);
    // Distances along raytree's ray, compared as the hit's t is.
    let along = |t: f64| t * node.direction.length();
    let root = test.roots.iter().map(|r| r.t).find(|&r| {
        same_distance(distance, along(r), node.origin, tol)
            && ours.is_none_or(|o| !same_distance(along(o), along(r), node.origin, tol))
    })?;
    // The t here counts in raytree's direction; the report above, distances.
    let length = node.direction.length();
    let units = if (length - 1.0).abs() > 1e-9 {
        format!(
            " (t counts in units of raytree's direction, of length {length:.4}; the distances above are t·{length:.4})"
        )
    } else {
        String::new()
    };
    Some(if root < 0.0 {
        Diagnosis::new(
            Mistake::NegativeRoot,
            format!(
                "your t = {root:.4} for '{name}' is its negative root, behind the ray's origin: only roots with t > 0 are hits (lecture: the smallest positive t){units}"
            ),
        )
    } else {
        Diagnosis::new(
            Mistake::FarRoot,
            format!(
                "your t = {root:.4} for '{name}' is its far root; the closest hit is the smallest positive root{}{units}",
                ours.map_or(String::new(), |o| format!(", t = {o:.4}"))
            ),
        )
    })
}
