//! Walking the hierarchy: nearer boxes first (a shadow ray's in their stored
//! order), four boxes a visit with SIMD, each single-precision box test
//! widened by its rounding bound so that a ray that meets a box in exact
//! arithmetic is never culled ([`RayBox4`]).

use std::ops::{ControlFlow, Range};

use wide::f32x4;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::bvh::Bvh;
use crate::geometry::structures::bvh::build::SAH_DEPTH_LIMIT;
use crate::geometry::structures::bvh::node::{Child, Node, WIDTH, round_down};
use crate::math::bounds::{Bounds, RayBox};

/// Room on the traversal stack: up to `WIDTH - 1` entries per level, and a tree
/// is at most `SAH_DEPTH_LIMIT` + log₄(2²⁸) levels deep.
const STACK: usize = (WIDTH - 1) * (SAH_DEPTH_LIMIT as usize + 16);

impl Bvh {
    /// Calls `visit(leaf, t_max)` for every leaf whose box the ray meets within
    /// `(t_min, *t_max)`, nearer boxes first, with the leaf's run of
    /// [`Bvh::leaf_order`]: a caller that keeps its primitives in that order (a
    /// mesh's triangles) reads them side by side, with no index per primitive,
    /// and may test them together. `visit` may shrink `t_max` (a closest-hit
    /// search) or break (a shadow ray's any-hit). Every box tested is counted
    /// in `tested` (four to a node, less in a node not full).
    #[inline]
    pub fn traverse_leaves(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        visit: impl FnMut(Range<usize>, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.walk_boxes::<true>(ray, t_min, t_max, tested, |_, _| {}, visit)
    }

    /// [`Bvh::traverse_leaves`] with the boxes met taken in the node's order,
    /// not nearest first: for a search that stops at any hit and never
    /// shrinks `t_max` (a scene's shadow rays). The nearest box often holds
    /// only the object the ray leaves: without the sorting the 2,000-sphere
    /// render made 4 % fewer tests and took 5 % less time. A mesh's shadow
    /// rays keep the nearest first: a mesh shadows itself close to where they
    /// start, and the Gaspra render made 2 % more tests without it.
    #[inline]
    pub fn traverse_leaves_any(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        visit: impl FnMut(Range<usize>, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.walk_boxes::<false>(ray, t_min, t_max, tested, |_, _| {}, visit)
    }

    /// [`Bvh::traverse_leaves`], also calling `seen(bounds, met)` for every box
    /// tested (as stored, rounded outward) and whether the ray met it: what a
    /// recorded ray keeps so a diagram can draw the boxes it visited.
    #[inline]
    pub fn traverse_leaves_seeing(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        visit: impl FnMut(Range<usize>, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.walk_boxes::<true>(ray, t_min, t_max, tested, seen, visit)
    }

    #[inline(always)]
    fn walk_boxes<const NEAREST_FIRST: bool>(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(Range<usize>, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        if self.nodes.is_empty() {
            return ControlFlow::Continue(());
        }
        let ray = RayBox4::new(ray);
        let t_min = round_down(t_min);
        // Boxes still to visit, with where the ray enters them: a box entered
        // beyond a closer hit found meanwhile is skipped when it comes up.
        let mut stack = arrayvec::ArrayVec::<(Child, f32), STACK>::new();
        let mut at = Child::inner(0);
        let mut reach = RayBox4::reach(*t_max);
        loop {
            if at.is_leaf() {
                visit(at.primitives(), t_max)?;
                reach = RayBox4::reach(*t_max);
            } else {
                let node = &self.nodes[at.0 as usize];
                tested.boxes += u32::from(node.len);
                let (mask, enter) = ray.hits(node, t_min, reach);
                for lane in 0..usize::from(node.len) {
                    seen(node.lane(lane), mask & (1 << lane) != 0);
                }
                let mut near = [(0.0f32, Child(0)); WIDTH];
                let mut n = 0;
                for (lane, entry) in enter.iter().enumerate() {
                    if mask & (1 << lane) != 0 {
                        near[n] = (*entry, node.children[lane]);
                        n += 1;
                    }
                }
                if n > 0 {
                    // Farthest first onto the stack; go on with the nearest.
                    if NEAREST_FIRST {
                        sort_descending(&mut near[..n]);
                    }
                    for &(entry, child) in &near[..n - 1] {
                        stack.push((child, entry));
                    }
                    at = near[n - 1].1;
                    continue;
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

/// Up to four (entry, child) pairs sorted by entry, farthest first (insertion
/// sort). A branch-free network with shortcuts for one and two boxes met was
/// tried: 11 % faster on random rays through a mesh, but 25 % slower on
/// coherent ones (primary rays into a thousand spheres or the Gaspra mesh),
/// whose branches a predictor learns from ray to ray; and whole renders were
/// 4 % slower with it (docs/performance.md).
#[inline]
fn sort_descending(hits: &mut [(f32, Child)]) {
    for i in 1..hits.len() {
        let mut j = i;
        while j > 0 && hits[j - 1].0 < hits[j].0 {
            hits.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// A ray prepared for testing four single-precision boxes at once.
///
/// In exact arithmetic the slab test with the origin moved toward the box by up
/// to the origin's rounding (`origin_near` for the entering planes, `origin_far`
/// for the leaving ones) only widens the interval, so the ray's rounding to
/// `f32` loses no box. What remains is the rounding of the test itself: each
/// slab distance `(plane − origin) · (1/dir)` is off by at most three roundings,
/// a relative γ(3) (the reciprocal, the subtraction, the product), so a box is
/// kept when the entering distance is at most the leaving one (or the ray's
/// `t_max`) times `1 + 2γ(4)` (Ize, JCGT 2013; pbrt-v4 §6.1.2), the fourth
/// rounding being that product's own.
#[derive(Clone, Copy, Debug)]
pub struct RayBox4 {
    origin_near: [f32x4; 3],
    origin_far: [f32x4; 3],
    inv_dir: [f32x4; 3],
    /// Per axis: which row of a node's bounds holds the entering planes.
    near: [usize; 3],
}

impl RayBox4 {
    /// Prepares `ray`.
    #[inline]
    pub fn new(ray: &RayBox) -> RayBox4 {
        let (o, inv) = (ray.origin(), ray.inv_dir());
        // The origin rounded to f32, then moved at least one ULP down and up
        // (|f|·2⁻²³ is one to two ULPs of f; 2⁻¹²⁶ covers zero and subnormals):
        // the true origin lies between `lo` and `hi`.
        let f = f32x4::new([o.x as f32, o.y as f32, o.z as f32, 0.0]);
        let step = f.abs() * f32x4::splat(f32::EPSILON) + f32x4::splat(f32::MIN_POSITIVE);
        let (lo, hi) = ((f - step).to_array(), (f + step).to_array());
        let axis = |i: usize| {
            let neg = ray.dir_is_neg(i);
            // Entering planes: moving the origin toward the box can only lower the
            // entering distance; leaving planes: away from it, raising the leaving one.
            let (o_near, o_far) = if neg { (lo[i], hi[i]) } else { (hi[i], lo[i]) };
            (
                f32x4::splat(o_near),
                f32x4::splat(o_far),
                f32x4::splat(reciprocal(inv[i])),
                usize::from(neg),
            )
        };
        let (x, y, z) = (axis(0), axis(1), axis(2));
        RayBox4 {
            origin_near: [x.0, y.0, z.0],
            origin_far: [x.1, y.1, z.1],
            inv_dir: [x.2, y.2, z.2],
            near: [x.3, y.3, z.3],
        }
    }

    /// How far a box may be entered and still count, for a ray whose interval
    /// ends at `t_max`: `t_max` rounded up to f32 (at least it: one rounding of
    /// 2⁻²⁴ made up by 2⁻²²), grown by the test's rounding bound.
    #[inline]
    pub(super) fn reach(t_max: f64) -> f32 {
        const GAMMA4: f32 = 4.0 * f32::EPSILON * 0.5 / (1.0 - 4.0 * f32::EPSILON * 0.5);
        (t_max as f32) * (1.0 + 4.0 * f32::EPSILON) * (1.0 + 2.0 * GAMMA4)
    }

    /// Which of the node's four boxes the ray meets within `(t_min, t_max)` (bit
    /// `i` for lane `i`), and where it enters each; `reach` is [`RayBox4::reach`]
    /// of `t_max`. A NaN distance (a ray lying in a slab's plane) is skipped by
    /// `max` and `min`, so that slab keeps the box.
    #[inline]
    pub(super) fn hits(&self, node: &Node, t_min: f32, reach: f32) -> (u32, [f32; WIDTH]) {
        const GAMMA4: f32 = 4.0 * f32::EPSILON * 0.5 / (1.0 - 4.0 * f32::EPSILON * 0.5);
        let mut enter = f32x4::splat(t_min);
        let mut leave = f32x4::splat(f32::INFINITY);
        for axis in 0..3 {
            let near = node.bounds[self.near[axis]][axis];
            let far = node.bounds[1 - self.near[axis]][axis];
            let t0 = (near - self.origin_near[axis]) * self.inv_dir[axis];
            let t1 = (far - self.origin_far[axis]) * self.inv_dir[axis];
            enter = max_skipping_nan(enter, t0);
            leave = min_skipping_nan(leave, t1);
        }
        // Neither is NaN: `leave` starts at +∞ and skips NaNs, `reach` comes
        // from a `t_max` that is never NaN.
        let leave = (leave * f32x4::splat(1.0 + 2.0 * GAMMA4)).fast_min(f32x4::splat(reach));
        (enter.simd_le(leave).to_bitmask(), enter.to_array())
    }
}

/// `acc` raised to `t` lane by lane, a lane where `t` is NaN left as it was
/// (`acc` never is NaN). With SSE that is one `maxps` with `t` first: it gives
/// its second operand when either is NaN, which is the skip itself, where
/// `f32x4::max` spends four more instructions finding the NaNs. The two differ
/// only for equal lanes (a zero's sign), which every later comparison treats
/// alike.
#[inline(always)]
fn max_skipping_nan(acc: f32x4, t: f32x4) -> f32x4 {
    #[cfg(target_feature = "sse")]
    let m = t.fast_max(acc);
    #[cfg(not(target_feature = "sse"))]
    let m = acc.max(t);
    m
}

/// `acc` lowered to `t` lane by lane, a lane where `t` is NaN left as it was
/// (see [`max_skipping_nan`]).
#[inline(always)]
fn min_skipping_nan(acc: f32x4, t: f32x4) -> f32x4 {
    #[cfg(target_feature = "sse")]
    let m = t.fast_min(acc);
    #[cfg(not(target_feature = "sse"))]
    let m = acc.min(t);
    m
}

/// A reciprocal direction component in `f32`. One too large for `f32` (the
/// direction's component is below 2⁻¹²⁸ but not zero) becomes NaN, which the box
/// test skips: that axis then culls nothing, where an infinity would cull boxes
/// the ray reaches after all. A true infinity (a zero component) stays: the ray
/// is parallel to those slabs, and infinite arithmetic gets that right.
#[inline]
fn reciprocal(inv: f64) -> f32 {
    let f = inv as f32;
    if f.is_infinite() && inv.is_finite() {
        f32::NAN
    } else {
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The one-instruction skip keeps what `f32x4::max` and `min` keep, up to
    /// the sign of a zero, NaNs included.
    #[test]
    fn skipping_nan_matches_max_and_min() {
        let values = [
            f32::NAN,
            0.0,
            -0.0,
            1.0,
            -2.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        for &a in &values[1..] {
            for &t in &values {
                let (acc, t4) = (f32x4::splat(a), f32x4::splat(t));
                let pairs = [
                    (max_skipping_nan(acc, t4), acc.max(t4)),
                    (min_skipping_nan(acc, t4), acc.min(t4)),
                ];
                for (fast, slow) in pairs {
                    let (fast, slow) = (fast.to_array()[0], slow.to_array()[0]);
                    assert!(fast == slow, "{a} with {t}: {fast} against {slow}");
                }
            }
        }
    }
}
