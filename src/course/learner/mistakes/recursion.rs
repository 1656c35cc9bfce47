//! The recursive sum's mistake (lesson 11), recognised in a ray's color:
//! the children's colors summed without their coefficients, or with them
//! applied twice.

use glam::DVec3;

use crate::course::learner::context::Context;
use crate::course::learner::format::LearnerRay;
use crate::course::learner::mistakes::{Diagnosis, Mistake};
use crate::course::learner::tolerance::same_color;
use crate::tree::ray_tree::BranchRecord;

/// The learner's color of node `i`'s ray, summed without its coefficients,
/// or with them twice.
pub fn color(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let tree = ctx.tree();
    let node = &tree.nodes[i];
    let got = l.color?;
    node.hit.as_ref()?;
    let child = |mine: &Option<Option<Box<LearnerRay>>>, b: &Option<BranchRecord>| {
        mine.as_ref()
            .and_then(|c| c.as_ref())
            .and_then(|c| c.color)
            .or_else(|| b.as_ref()?.node.map(|j| tree.nodes[j].color()))
            .unwrap_or(DVec3::ZERO)
    };
    let local = l.local.unwrap_or(node.sum.local);
    let (rfl, rfa) = (
        child(&l.reflected, &node.reflected),
        child(&l.refracted, &node.refracted),
    );
    let (k1, k2) = (node.sum.k_rfl, node.sum.k_rfa);
    // A sum the lecture's way from the learner's own terms is no mistake in the
    // sum: a wrong local color or child shows there already (and a ray with no
    // children gives the same sum every way).
    if same_color(got, local + k1 * rfl + k2 * rfa) {
        return None;
    }
    for (sum, what) in [
        (
            local + rfl + rfa,
            "without k_rfl and k_rfa: local + reflected + refracted",
        ),
        (
            local + k1 * k1 * rfl + k2 * k2 * rfa,
            "with k_rfl and k_rfa applied twice (once to the child's color, once in the sum)",
        ),
    ] {
        if !same_color(sum, node.color()) && same_color(got, sum) {
            return Some(Diagnosis::new(
                Mistake::Coefficients,
                format!(
                    "your color is summed {what}; the lecture's is color = local + k_rfl·reflected + k_rfa·refracted, each child's color weighted once"
                ),
            ));
        }
    }
    None
}
