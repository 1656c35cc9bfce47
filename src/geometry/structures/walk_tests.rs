//! What the tests of the grid, the octree and the BSP tree share: a cube of
//! given half side, a structure's whole walk with an interval that never
//! shrinks, the reference sphere hit the closest-hit tests compare with, and
//! a structure's description for a failure's message.

use std::ops::ControlFlow;

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

/// The box of half side `half` around `at`.
pub fn cube(at: DVec3, half: f64) -> Bounds {
    Bounds {
        min: at - half,
        max: at + half,
    }
}

/// What the structure says of itself (empty if nothing).
pub fn described(structure: &impl Structure) -> String {
    structure.describe().unwrap_or_default()
}

/// Every primitive a walk hands out, in order, and the steps it counted, for
/// a walk given `t_max = ∞` that no visit shrinks or breaks. `walk` runs one
/// structure's `walk` with the `t_max`, the counts and the visit
/// it is given.
pub fn everything_visited(
    walk: impl FnOnce(
        &mut f64,
        &mut TestCounts,
        &mut dyn FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()>,
) -> (Vec<usize>, u32) {
    let mut visited = Vec::new();
    let mut tested = TestCounts::default();
    let mut t_max = f64::INFINITY;
    let flow = walk(&mut t_max, &mut tested, &mut |p, _| {
        visited.push(p);
        ControlFlow::Continue(())
    });
    assert_eq!(
        flow,
        ControlFlow::Continue(()),
        "nothing asked the walk to stop"
    );
    (visited, tested.boxes)
}

/// The nearest root of a sphere's quadratic beyond `t_min` (the lecture's
/// quadratic as written: the reference needs no stable form at these sizes).
pub fn sphere_hit(center: DVec3, radius: f64, ray: &Ray, t_min: f64) -> Option<f64> {
    let oc = ray.origin - center;
    let a = ray.dir.dot(ray.dir);
    let b = oc.dot(ray.dir);
    let c = oc.dot(oc) - radius * radius;
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    [(-b - s) / a, (-b + s) / a]
        .into_iter()
        .find(|&t| t > t_min)
}
