//! The ray tree read as the algorithm ran (after the camera stage that made a
//! pixel's primary ray, which the trace document adds): spawn a ray, search
//! for its closest hit (visiting the structure's boxes or cells, testing objects), take
//! the closest hit (or miss), cast each shadow ray, sum the local color, spawn
//! the reflected ray (and everything under it), spawn the refracted ray,
//! combine, return. Derived from the tree alone, so every view steps through the
//! same list; [`crate::views::text`] writes each step out with its numbers.

use crate::tree::ray_tree::{RayNode, RayTree};

/// What kind of step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepKind {
    /// The camera makes a sample's primary ray: pixel → (c, r) → (u_c, v_r) → P(r, c).
    Camera,
    /// A ray is spawned.
    Spawn,
    /// The search visits one box or cell of the scene's structure (a BVH box
    /// tested, a grid cell walked, an octree or k-d tree node entered): the
    /// index into the node's `boxes`.
    Visit(usize),
    /// One object is tested: the index into the node's `tests`.
    Test(usize),
    /// The closest hit is chosen.
    Hit,
    /// Nothing was hit.
    Miss,
    /// A shadow ray toward one light: the index into the node's `shadow_rays`.
    Shadow(usize),
    /// The local color is summed.
    Local,
    /// The reflected branch.
    Reflect,
    /// The refracted branch.
    Refract,
    /// `color = local + k_rfl·reflected + k_rfa·refracted`.
    Combine,
    /// The color goes back to the parent (or the pixel).
    Return,
}

/// One step of the algorithm.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Step {
    /// Index of the node (ray) it belongs to.
    pub node: usize,
    /// What kind of step.
    pub kind: StepKind,
}

/// How many objects the search tested right after visit `k` of `node` (before
/// its next visit): a grid cell's new objects, a BVH leaf's, none for an
/// inner box or an empty cell.
pub fn visit_tests(node: &RayNode, k: usize) -> usize {
    let next = node
        .boxes
        .get(k + 1)
        .map_or(node.tests.len(), |b| b.after_tests);
    next.saturating_sub(node.boxes[k].after_tests)
}

/// The steps of `tree` in execution order.
pub fn steps(tree: &RayTree) -> Vec<Step> {
    let mut out = Vec::new();
    if !tree.nodes.is_empty() {
        walk(tree, 0, &mut out);
    }
    out
}

fn walk(tree: &RayTree, i: usize, out: &mut Vec<Step>) {
    let node = &tree.nodes[i];
    let step = |kind| Step { node: i, kind };
    out.push(step(StepKind::Spawn));
    // The structure's visits interleave with the tests, as the search ran them.
    let mut visits = node.boxes.iter().enumerate().peekable();
    for k in 0..node.tests.len() {
        while let Some((v, _)) = visits.next_if(|(_, b)| b.after_tests <= k) {
            out.push(step(StepKind::Visit(v)));
        }
        out.push(step(StepKind::Test(k)));
    }
    out.extend(visits.map(|(v, _)| step(StepKind::Visit(v))));
    if node.hit.is_none() {
        out.extend([step(StepKind::Miss), step(StepKind::Return)]);
        return;
    }
    out.push(step(StepKind::Hit));
    out.extend((0..node.shadow_rays.len()).map(|k| step(StepKind::Shadow(k))));
    if node.local.is_some() {
        out.push(step(StepKind::Local));
    }
    // Children interleave with the branch steps, as the recursion runs them.
    for (kind, branch) in [
        (StepKind::Reflect, &node.reflected),
        (StepKind::Refract, &node.refracted),
    ] {
        let Some(branch) = branch else { continue };
        out.push(step(kind));
        if let Some(child) = branch.node {
            walk(tree, child, out);
        }
    }
    out.extend([step(StepKind::Combine), step(StepKind::Return)]);
}
