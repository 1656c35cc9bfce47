//! A k-d tree: the lecture's binary space partitioning (BSP) tree with every
//! splitting plane perpendicular to an axis.
//!
//! Why the axis-aligned BSP tree: a general BSP tree may split along any plane,
//! but a ray's crossing of an axis-aligned plane costs one subtraction and one
//! division (`(p − o_k) / d_k`), cells stay boxes (so a diagram can draw them and
//! the surface area heuristic can price them by their areas), and the candidate
//! planes are finite and obvious: the faces of the primitives' boxes. That makes
//! the tree buildable by the surface area heuristic (SAH), which is what makes a
//! k-d tree fast (Havran's thesis; Wald & Havran 2006).
//!
//! Build: pbrt's SAH k-d tree (Pharr, Jakob & Humphreys, *Physically Based
//! Rendering*, "Kd-Tree Accelerator"): at each node every face of every
//! primitive box strictly inside the cell, on all three axes, is a candidate;
//! it costs `traversal + (1 − bonus)·isect·(P(below)·N_below + P(above)·N_above)`,
//! the probabilities being the children's surface areas over the cell's and the
//! bonus rewarding cutting off empty space. A node becomes a leaf when its
//! best split would be the third on its path to cost more than a leaf
//! (`isect·N`; pbrt's bad refinements), at depth `8 + 1.3·log₂ N`, or when the
//! split would copy more straddling primitives than its share of the entry
//! budget: all leaves together hold at most [`ENTRY_CAP`] entries per
//! primitive (which bounds memory), the budget being shared between two
//! children by their sizes so the subtrees built last are not starved. The edges are
//! sorted at every node: O(N log² N) (Wald & Havran's first algorithm).
//! A primitive goes to every child whose cell its box reaches into, and one
//! lying in a splitting plane goes below ([`goes`]): every point of its box
//! then lies in the closed cell of some leaf that holds it.
//!
//! Traversal: front to back with the ray's interval (pbrt's
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
use crate::geometry::mailbox::Mailbox;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

/// The cost of one primitive test, against one traversal step (pbrt's defaults).
pub const ISECT_COST: f64 = 80.0;
/// The cost of one traversal step.
pub const TRAVERSAL_COST: f64 = 1.0;
/// How much cheaper a split with one empty side is priced (pbrt's 0.5).
pub const EMPTY_BONUS: f64 = 0.5;
/// A node with this many primitives or fewer is a leaf (pbrt's `maxPrims`).
pub const MAX_LEAF: usize = 1;
/// The tree holds at most this many leaf entries per primitive: primitives
/// straddling planes are stored once per leaf, and huge ones would otherwise
/// fill every leaf. Past the cap, nodes become leaves.
pub const ENTRY_CAP: usize = 8;

/// Marks a leaf entry whose primitive is stored in more than one leaf: only
/// those go through the mailbox.
const SHARED: u32 = 1 << 31;
/// The `axis` of a leaf node.
const LEAF: u32 = 3;
/// Room on the traversal stack: one far child per level, and the depth limit is
/// `8 + 1.3·log₂ N` < 50 for any `N` below 2³¹.
const STACK: usize = 64;

/// A node of the flattened tree.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    /// The split's axis (0, 1, 2), or [`LEAF`].
    axis: u32,
    /// A split: the child below the plane. A leaf: where its entries start.
    a: u32,
    /// A split: the child above the plane. A leaf: where its entries end.
    b: u32,
    /// A split: the plane's coordinate along `axis`.
    pos: f64,
}

/// A k-d tree over primitives `0..n`, known by their bounding boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct KdTree {
    /// The root is node 0, if there are any primitives.
    nodes: Vec<Node>,
    /// Primitive indices, leaf by leaf, [`SHARED`] set on those in several leaves.
    entries: Vec<u32>,
    /// The box around everything: the root's cell.
    bounds: Bounds,
    /// Primitives built over.
    primitives: usize,
    /// The deepest leaf's depth (the root's is 0).
    depth: u32,
    /// The depth limit `8 + 1.3·log₂ N`.
    max_depth: u32,
}

impl KdTree {
    /// Builds over primitives `0..n` known by their (finite, non-empty) bounds,
    /// at most `8 + 1.3·log₂ N` levels deep.
    pub fn build(bounds: &[Bounds]) -> KdTree {
        KdTree::build_to_depth(bounds, None)
    }

    /// [`KdTree::build`] with leaves at most `max_depth` levels below the root
    /// (`None`: pbrt's `8 + 1.3·log₂ N`), clamped so the walk's stack holds.
    pub fn build_to_depth(bounds: &[Bounds], max_depth: Option<u32>) -> KdTree {
        let n = bounds.len();
        let mut tree = KdTree {
            nodes: Vec::new(),
            entries: Vec::new(),
            bounds: Bounds::EMPTY,
            primitives: n,
            depth: 0,
            max_depth: 0,
        };
        if n == 0 {
            return tree;
        }
        assert!(
            n < SHARED as usize,
            "a k-d tree holds fewer than 2³¹ primitives"
        );
        tree.bounds = bounds.iter().fold(Bounds::EMPTY, |a, &b| a.union(b));
        // pbrt: 8 + 1.3·Log2Int(N), rounded.
        let rule = (8.0 + 1.3 * f64::from(n.ilog2())).round() as u32;
        tree.max_depth = max_depth.unwrap_or(rule).min(STACK as u32 - 1);
        let mut builder = Builder {
            bounds,
            nodes: Vec::new(),
            entries: Vec::new(),
            depth: 0,
        };
        let all: Vec<u32> = (0..n as u32).collect();
        let budget = (ENTRY_CAP - 1) * n;
        builder.node(all, tree.bounds, 0, tree.max_depth, 0, budget);
        // Mark the primitives stored in more than one leaf.
        let mut count = vec![0u8; n];
        for &e in &builder.entries {
            count[e as usize] = count[e as usize].saturating_add(1);
        }
        for e in &mut builder.entries {
            if count[*e as usize] > 1 {
                *e |= SHARED;
            }
        }
        tree.nodes = builder.nodes;
        tree.entries = builder.entries;
        tree.depth = builder.depth;
        tree
    }

    /// Calls `visit(primitive, t_max)` for every primitive the ray may meet in
    /// `(t_min, *t_max)`: those in the leaves whose cells the ray's segment meets,
    /// nearer cells first, each primitive at most once per call. `visit` may
    /// shrink `*t_max` (a closest-hit search) or break (a shadow ray's any-hit);
    /// cells entered beyond `*t_max` are then skipped, and a break ends the walk.
    /// Every node visited (split or leaf) is counted in `tested.boxes` and shown
    /// to `seen(its cell, true)`.
    pub fn traverse_seeing(
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

    /// The tree's own numbers for a summary.
    pub fn describe(&self) -> String {
        let leaves: Vec<&Node> = self.nodes.iter().filter(|n| n.axis == LEAF).collect();
        let empty = leaves.iter().filter(|n| n.a == n.b).count();
        let largest = leaves.iter().map(|n| n.b - n.a).max().unwrap_or(0);
        let shared = {
            let mut s: Vec<u32> = self
                .entries
                .iter()
                .filter(|&&e| e & SHARED != 0)
                .map(|&e| e & !SHARED)
                .collect();
            s.sort_unstable();
            s.dedup();
            s.len()
        };
        let per = if self.primitives == 0 {
            0.0
        } else {
            self.entries.len() as f64 / self.primitives as f64
        };
        format!(
            "k-d tree: {} primitives, {} nodes ({} leaves, {} empty), depth {} (limit {}), \
             {} entries ({per:.2} per primitive; {shared} primitives in more than one leaf), \
             largest leaf {largest}",
            self.primitives,
            self.nodes.len(),
            leaves.len(),
            empty,
            self.depth,
            self.max_depth,
            self.entries.len(),
        )
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
fn crossing(p: f64, o: f64, d: f64) -> (f64, f64) {
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

/// Building the tree depth first into flat vectors.
struct Builder<'a> {
    bounds: &'a [Bounds],
    nodes: Vec<Node>,
    entries: Vec<u32>,
    /// The deepest leaf so far.
    depth: u32,
}

/// A face of a primitive's box along one axis, or both faces of a box flat in it.
#[derive(Clone, Copy)]
enum Edge {
    Start,
    End,
    Flat,
}

/// Which sides of the plane at `pos` on axis `k` a primitive with box `b` is
/// stored on: below if it reaches below the plane, above if it reaches above;
/// one lying in the plane goes below. A box that only touches the plane from one
/// side is not copied to the other: each of its points on the plane lies in the
/// closed cell of its own side too, which a ray through that point visits.
#[inline]
fn goes(b: &Bounds, k: usize, pos: f64) -> (bool, bool) {
    let above = b.max[k] > pos;
    (b.min[k] < pos || !above, above)
}

/// A candidate split.
struct Split {
    axis: usize,
    pos: f64,
    cost: f64,
    below: usize,
    above: usize,
}

impl Builder<'_> {
    /// Builds the subtree over `prims` (those whose boxes reach into `cell`)
    /// and returns its root's index. Its splits may add at most `budget`
    /// entries by copying straddling primitives; what a split leaves of it is
    /// shared between the children by their sizes, so the cap does not starve
    /// the subtrees built last.
    fn node(
        &mut self,
        prims: Vec<u32>,
        cell: Bounds,
        depth: u32,
        max_depth: u32,
        bad_refines: u32,
        budget: usize,
    ) -> u32 {
        let index = self.nodes.len() as u32;
        let n = prims.len();
        let leaf_cost = ISECT_COST * n as f64;
        let split = if n <= MAX_LEAF || depth >= max_depth {
            None
        } else {
            self.best_split(&prims, &cell)
        };
        let mut bad = bad_refines;
        let split = split.filter(|s| {
            if s.cost > leaf_cost {
                bad += 1;
            }
            let growth = s.below + s.above - n;
            !((s.cost > 4.0 * leaf_cost && n < 16) || bad >= 3 || growth > budget)
        });
        let Some(split) = split else {
            let start = self.entries.len() as u32;
            self.entries.extend_from_slice(&prims);
            self.nodes.push(Node {
                axis: LEAF,
                a: start,
                b: self.entries.len() as u32,
                pos: 0.0,
            });
            self.depth = self.depth.max(depth);
            return index;
        };
        let budget = budget - (split.below + split.above - n);
        let below_budget =
            (budget as u128 * split.below as u128 / (split.below + split.above) as u128) as usize;
        let k = split.axis;
        let (below, above): (Vec<u32>, Vec<u32>) = {
            let side = |p: u32| goes(&self.bounds[p as usize], k, split.pos);
            (
                prims.iter().copied().filter(|&p| side(p).0).collect(),
                prims.iter().copied().filter(|&p| side(p).1).collect(),
            )
        };
        debug_assert_eq!((below.len(), above.len()), (split.below, split.above));
        drop(prims);
        self.nodes.push(Node {
            axis: k as u32,
            a: 0,
            b: 0,
            pos: split.pos,
        });
        let (mut below_cell, mut above_cell) = (cell, cell);
        below_cell.max[k] = split.pos;
        above_cell.min[k] = split.pos;
        let a = self.node(below, below_cell, depth + 1, max_depth, bad, below_budget);
        let b = self.node(
            above,
            above_cell,
            depth + 1,
            max_depth,
            bad,
            budget - below_budget,
        );
        self.nodes[index as usize].a = a;
        self.nodes[index as usize].b = b;
        index
    }

    /// The cheapest plane through a face of a primitive's box strictly inside
    /// `cell`, on any axis, with how many primitives it puts on each side
    /// ([`goes`]).
    fn best_split(&self, prims: &[u32], cell: &Bounds) -> Option<Split> {
        let total = cell.area();
        if total.is_nan() || total <= 0.0 {
            return None;
        }
        let size = cell.max - cell.min;
        let n = prims.len();
        let mut best: Option<Split> = None;
        let mut edges: Vec<(f64, Edge)> = Vec::with_capacity(2 * n);
        for axis in 0..3 {
            let (lo, hi) = (cell.min[axis], cell.max[axis]);
            if lo >= hi {
                continue;
            }
            let (o0, o1) = ((axis + 1) % 3, (axis + 2) % 3);
            edges.clear();
            for &p in prims {
                let b = &self.bounds[p as usize];
                if b.min[axis] == b.max[axis] {
                    edges.push((b.min[axis], Edge::Flat));
                } else {
                    edges.push((b.min[axis], Edge::Start));
                    edges.push((b.max[axis], Edge::End));
                }
            }
            edges.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
            // The counts [`goes`] gives for a plane at t: below, the boxes
            // starting before t and those flat at t; above, those ending after t.
            let (mut min_before, mut max_before) = (0usize, 0usize);
            let mut i = 0;
            while i < edges.len() {
                let t = edges[i].0;
                let (mut starts_at, mut ends_at, mut flat_at) = (0, 0, 0);
                while i < edges.len() && edges[i].0 == t {
                    match edges[i].1 {
                        Edge::Start => starts_at += 1,
                        Edge::End => ends_at += 1,
                        Edge::Flat => flat_at += 1,
                    }
                    i += 1;
                }
                if t > lo && t < hi {
                    let below = min_before + flat_at;
                    let above = n - max_before - ends_at - flat_at;
                    let area = |len: f64| 2.0 * (size[o0] * size[o1] + len * (size[o0] + size[o1]));
                    let (p_below, p_above) = (area(t - lo) / total, area(hi - t) / total);
                    let bonus = if below == 0 || above == 0 {
                        EMPTY_BONUS
                    } else {
                        0.0
                    };
                    let cost = TRAVERSAL_COST
                        + ISECT_COST
                            * (1.0 - bonus)
                            * (p_below * below as f64 + p_above * above as f64);
                    if best.as_ref().is_none_or(|b| cost < b.cost) {
                        best = Some(Split {
                            axis,
                            pos: t,
                            cost,
                            below,
                            above,
                        });
                    }
                }
                min_before += starts_at + flat_at;
                max_before += ends_at + flat_at;
            }
        }
        best
    }
}

#[cfg(test)]
#[path = "kdtree_tests.rs"]
mod tests;
#[cfg(test)]
#[path = "kdtree_walk_tests.rs"]
mod walk_tests;
