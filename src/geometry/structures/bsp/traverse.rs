//! Walking the BSP tree.
//!
//! Front to back with the ray's interval (pbrt's
//! `KdTreeAccel::Intersect`, Havran's TA_rec_B): the near child over
//! `[t_min, t_plane]`, the far one over `[t_plane, t_max]`, a small stack of
//! far children, and a far child skipped when a hit found meanwhile lies before
//! it. Every primitive met is reported at most once (mailboxing: only the
//! primitives stored in more than one leaf are checked, see [`Mailbox`]).
//!
//! Conservative in floating point: a ray that meets a primitive's box in exact
//! arithmetic always reaches a leaf holding it. The only rounded quantities are
//! the plane crossings `t_plane` (of splits, and of the scene box's faces that
//! clip the ray at the start); each is replaced by an interval `[lo, hi]` that
//! holds the exact crossing ([`crossing`]), the near child is walked up to `hi`
//! and the far one from `lo`. So when `t_plane` is within its rounding bound of
//! an end of the ray's interval, *both* sides are visited: the crossing might
//! lie on either side of the end in exact arithmetic, and picking one could skip
//! the cell the ray really enters. The interval ends themselves are only ever
//! taken as `min`/`max` of such bounds, which is exact. Rays parallel to a
//! plane (`d_k = ±0`) get an infinite crossing of the right sign from IEEE
//! division, so they stay on their origin's side; a ray lying *in* the plane
//! (`0/0`, NaN) visits both sides over its whole interval.

use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::bsp::{BspTree, LEAF, SHARED, STACK};
use crate::geometry::structures::mailbox::Mailbox;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

impl BspTree {
    /// Calls `visit(primitive, t_max)` for every primitive the ray may meet in
    /// `(t_min, *t_max)`: those in the leaves whose cells the ray's segment meets,
    /// nearer cells first, each primitive at most once per call. `visit` may
    /// shrink `*t_max` (a closest-hit search) or break (a shadow ray's any-hit);
    /// cells entered beyond `*t_max` are then skipped, and a break ends the walk.
    /// Every node visited (split or leaf) is counted in `tested.boxes` and shown
    /// to `seen(its cell, true)`.
    pub(super) fn traverse(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        if self.nodes.is_empty() {
            return ControlFlow::Continue(());
        }
        let o = ray.origin.to_array();
        let d = ray.dir.to_array();
        let neg = [
            d[0].is_sign_negative(),
            d[1].is_sign_negative(),
            d[2].is_sign_negative(),
        ];
        // Clip the interval to the scene box: entered no earlier than the latest
        // lower bound of an entering face, left no later than the earliest upper
        // bound of a leaving one.
        let (mut enter, mut leave) = (t_min, *t_max);
        let (lo_corner, hi_corner) = (self.bounds.min.to_array(), self.bounds.max.to_array());
        for k in 0..3 {
            let (near, far) = if neg[k] {
                (hi_corner[k], lo_corner[k])
            } else {
                (lo_corner[k], hi_corner[k])
            };
            enter = enter.max(crossing(near, o[k], d[k]).0);
            leave = leave.min(crossing(far, o[k], d[k]).1);
        }
        if !(enter <= leave && enter < f64::INFINITY) {
            return ControlFlow::Continue(());
        }
        let mut mailbox = Mailbox::new(self.primitives);
        // Far children still to visit: node, the ray's interval in it, its cell.
        let mut stack = arrayvec::ArrayVec::<(u32, f64, f64, Bounds), STACK>::new();
        let (mut at, mut a, mut b, mut cell) = (0u32, enter, leave, self.bounds);
        loop {
            tested.boxes += 1;
            seen(cell, true);
            let node = self.nodes[at as usize];
            let mut next = None;
            if node.axis == LEAF {
                for &e in &self.entries[node.a as usize..node.b as usize] {
                    let p = e & !SHARED;
                    if e & SHARED != 0 && !mailbox.first_time(p) {
                        continue;
                    }
                    visit(p as usize, t_max)?;
                }
            } else {
                let k = node.axis as usize;
                let (lo, hi) = crossing(node.pos, o[k], d[k]);
                let (mut below, mut above) = (cell, cell);
                below.max[k] = node.pos;
                above.min[k] = node.pos;
                let (near, far) = if neg[k] {
                    ((node.b, above), (node.a, below))
                } else {
                    ((node.a, below), (node.b, above))
                };
                // The near side holds the ray up to the crossing, the far side
                // from it on; with the crossing's bounds both may be visited.
                let near_b = b.min(hi);
                let far_a = a.max(lo);
                let go_near = a <= near_b;
                let go_far = far_a <= b && far_a < f64::INFINITY;
                if go_near {
                    if go_far {
                        stack.push((far.0, far_a, b, far.1));
                    }
                    next = Some((near.0, a, near_b, near.1));
                } else if go_far {
                    next = Some((far.0, far_a, b, far.1));
                }
            }
            if next.is_none() {
                // The nearest far child not beyond a hit found meanwhile.
                while let Some((n, na, nb, ncell)) = stack.pop() {
                    if na <= *t_max {
                        next = Some((n, na, nb.min(*t_max), ncell));
                        break;
                    }
                }
            }
            match next {
                Some(n) => (at, a, b, cell) = n,
                None => return ControlFlow::Continue(()),
            }
        }
    }
}

/// Bounds `lo ≤ t ≤ hi` on where the ray `o + t·d` (one axis of it) crosses the
/// plane at `p`, in exact arithmetic.
///
/// `t' = (p − o) / d` is two roundings from the exact `t`, so
/// `|t' − t| ≤ γ(2)·|t| + η` (η ≤ 2⁻¹⁰⁷⁵ if the quotient underflows; a subnormal
/// difference is exact). Widening by `2γ(4)·|t'| + 2⁻¹⁰²²` covers that, the
/// rounding of the widening and of `t' ± e` with room to spare. A zero `d` gives
/// `±∞` of the right sign (the ray never crosses: it stays on `o`'s side), kept
/// as is; `0/0` (the ray lies in the plane) gives everything, `(−∞, ∞)`. A
/// quotient overflowing to `±∞` means `|t|` is beyond `f64::MAX`, beyond any
/// interval the tracer asks about.
#[inline]
pub(super) fn crossing(p: f64, o: f64, d: f64) -> (f64, f64) {
    const EPS: f64 = f64::EPSILON * 0.5;
    const GAMMA4: f64 = 4.0 * EPS / (1.0 - 4.0 * EPS);
    let t = (p - o) / d;
    if t.is_finite() {
        let e = t.abs() * (2.0 * GAMMA4) + f64::MIN_POSITIVE;
        (t - e, t + e)
    } else if t.is_nan() {
        (f64::NEG_INFINITY, f64::INFINITY)
    } else {
        (t, t)
    }
}
