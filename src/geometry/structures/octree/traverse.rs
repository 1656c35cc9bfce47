//! Walking the octree.
//!
//! An ordered stack: at an inner node the ray's parametric
//! interval is computed for each of the eight children by the slab test, the
//! children it meets are sorted by where it enters them, the farther ones are
//! pushed and the nearest is walked into; a node popped whose entry lies beyond
//! the current `t_max` is skipped. Because the cells of one level are disjoint,
//! this visits leaves front to back. It is the simple relative of Revelles, Ureña
//! & Lastra, "An Efficient Parametric Algorithm for Octree Traversal" (WSCG 2000),
//! which derives the children's parameters from the parent's and its mid-planes
//! instead of testing eight boxes; testing each child's own box keeps the
//! robustness argument below to one slab test. Since a primitive lies in several
//! leaves, a per-call mailbox ([`Mailbox`]) makes sure `visit` sees it once.
//!
//! **Why no cell the ray meets is skipped in floating point.**
//! 1. The children tile their parent exactly: the mid-point `m` is computed once
//!    and is both the upper bound of the lower children and the lower bound of
//!    the upper ones, so every point of the parent (its faces included) lies in a
//!    child. The root cube holds every primitive's box (its upper corner is at
//!    least the scene box's, whatever the rounding of `min + side`).
//! 2. So a point `x` of a primitive's box lies in a chain of cells from the root
//!    to a leaf, and the primitive is in each of them: assignment compares the
//!    stored coordinates exactly, closed on both sides.
//! 3. If the ray meets the primitive's box at `x` at parameter `t` in
//!    `(t_min, t_max)` (exactly), it meets every cell of that chain at `t`, and
//!    the widened slab test ([`Slabs::enter`]) keeps each of them: each slab
//!    parameter `(plane − origin) · (1/dir)` has at most three roundings, a
//!    relative error γ(3); entering at most leaving then survives if the leaving
//!    parameter is widened by a relative γ(6) (`(1+γ₃)/(1−γ₃) = 1+γ₆`, about
//!    3ε with ε = 2⁻⁵²), and we widen by `32ε`, which covers that and the
//!    widening's own two roundings with room (Ize, "Robust BVH Ray Traversal", JCGT 2013; pbrt-v4
//!    §6.1.2). `t_max` is widened the same way. A zero direction component gives
//!    ±∞ reciprocals, exact for a parallel ray; the `0 · ∞ = NaN` of a ray lying
//!    in a slab's plane is skipped by the comparisons (that slab then keeps the
//!    cell, as the closed slab does); a component so small that its reciprocal
//!    overflows is made NaN too, so that axis culls nothing. (The bounds assume
//!    no overflow or underflow: coordinates below 10³⁰⁰ and parameters above
//!    10⁻³⁰⁰.)

use std::ops::ControlFlow;

use arrayvec::ArrayVec;
use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::mailbox::Mailbox;
use crate::geometry::structures::octree::{DEEPEST, Kind, Octree};
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

/// Room on the traversal stack: at most seven children pushed per level (eight
/// met, the nearest walked into), one level below another.
const STACK: usize = 7 * (DEEPEST as usize + 1) + 1;

/// The widening of a slab test's leaving parameter and of `t_max`: `32ε`
/// (see the module documentation; γ(6) ≈ 3ε is what the test needs).
const WIDEN: f64 = 32.0 * f64::EPSILON;

impl Octree {
    /// Calls `visit(primitive, t_max)` for every primitive the ray may meet in
    /// `(t_min, *t_max)`, those of nearer cells first, each at most once. `visit`
    /// may shrink `t_max` (a closest-hit search), after which cells entered
    /// beyond it are skipped, or break (a shadow ray's any-hit), which ends the
    /// walk at once. Every node walked into counts in `tested.boxes` and is
    /// passed to `seen(cell, true)`.
    pub(super) fn traverse(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let Some(root) = self.nodes.first() else {
            return ControlFlow::Continue(());
        };
        let slabs = Slabs::new(ray);
        let mut reach = widen(*t_max);
        if slabs.enter(&root.cell, t_min, reach).is_none() {
            return ControlFlow::Continue(());
        }
        let mut mailbox = Mailbox::new(self.primitives);
        // Nodes still to walk into, with where the ray enters them.
        let mut stack = ArrayVec::<(u32, f64), STACK>::new();
        let mut at = 0u32;
        loop {
            let node = &self.nodes[at as usize];
            tested.boxes += 1;
            seen(node.cell, true);
            match node.kind {
                Kind::Leaf { start, len } => {
                    let start = start as usize;
                    for &p in &self.entries[start..start + len as usize] {
                        if mailbox.first_time(p) {
                            visit(p as usize, t_max)?;
                        }
                    }
                    reach = widen(*t_max);
                }
                Kind::Inner { first } => {
                    let mut met = ArrayVec::<(f64, u32), 8>::new();
                    for child in first..first + 8 {
                        let c = &self.nodes[child as usize];
                        if matches!(c.kind, Kind::Leaf { len: 0, .. }) {
                            continue; // an empty leaf: nothing to visit
                        }
                        if let Some(entry) = slabs.enter(&c.cell, t_min, reach) {
                            met.push((entry, child));
                        }
                    }
                    // Farthest first onto the stack; go on with the nearest.
                    met.sort_unstable_by(|a, b| b.0.total_cmp(&a.0));
                    if let Some((_, nearest)) = met.pop() {
                        stack.extend(met.iter().map(|&(entry, child)| (child, entry)));
                        at = nearest;
                        continue;
                    }
                }
            }
            loop {
                let Some((child, entry)) = stack.pop() else {
                    return ControlFlow::Continue(());
                };
                if entry <= reach {
                    at = child;
                    break;
                }
            }
        }
    }
}

/// `t` moved outward by the relative [`WIDEN`]: up for a positive `t`, so a
/// leaving parameter or `t_max` computed a little short still reaches.
#[inline]
fn widen(t: f64) -> f64 {
    if t > 0.0 {
        t * (1.0 + WIDEN)
    } else {
        t * (1.0 - WIDEN)
    }
}

/// A ray prepared for slab tests against cells.
#[derive(Clone, Copy, Debug)]
struct Slabs {
    origin: DVec3,
    inv_dir: DVec3,
    /// Per axis: whether the ray enters a slab at its upper plane.
    neg: [bool; 3],
}

impl Slabs {
    fn new(ray: &Ray) -> Slabs {
        let mut inv_dir = ray.dir.recip();
        for axis in 0..3 {
            // A component so small its reciprocal overflows: not parallel, so
            // ±∞ would be wrong; NaN makes the axis cull nothing.
            if inv_dir[axis].is_infinite() && ray.dir[axis] != 0.0 {
                inv_dir[axis] = f64::NAN;
            }
        }
        Slabs {
            origin: ray.origin,
            inv_dir,
            neg: [0, 1, 2].map(|axis| ray.dir[axis].is_sign_negative()),
        }
    }

    /// Where the ray enters `cell` (at least `t_min`), if it meets it within
    /// `(t_min, t_max)` with `reach` = `widen(t_max)`; conservative: see the
    /// module documentation. NaN parameters fail every comparison and so leave
    /// the interval as it was.
    #[inline]
    fn enter(&self, cell: &Bounds, t_min: f64, reach: f64) -> Option<f64> {
        let mut enter = t_min;
        let mut leave = f64::INFINITY;
        for axis in 0..3 {
            let (near, far) = if self.neg[axis] {
                (cell.max[axis], cell.min[axis])
            } else {
                (cell.min[axis], cell.max[axis])
            };
            let t0 = (near - self.origin[axis]) * self.inv_dir[axis];
            let t1 = (far - self.origin[axis]) * self.inv_dir[axis];
            if t0 > enter {
                enter = t0;
            }
            if t1 < leave {
                leave = t1;
            }
        }
        (enter <= widen(leave) && enter <= reach).then_some(enter)
    }
}
