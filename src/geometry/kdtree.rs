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

use std::collections::HashSet;
use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
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
    /// Builds over primitives `0..n` known by their (finite, non-empty) bounds.
    pub fn build(bounds: &[Bounds]) -> KdTree {
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
        tree.max_depth = (8.0 + 1.3 * f64::from(n.ilog2())).round() as u32;
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
        let mut mailbox = Mailbox::new();
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
                    if e & SHARED != 0 && !mailbox.first_visit(p) {
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

/// The primitives already reported in one traversal, among those stored in
/// several leaves: the first few in an array on the stack, any more in a set
/// (a ray that walks a long way through big straddling primitives).
struct Mailbox {
    few: [u32; 16],
    len: usize,
    many: Option<HashSet<u32>>,
}

impl Mailbox {
    fn new() -> Mailbox {
        Mailbox {
            few: [0; 16],
            len: 0,
            many: None,
        }
    }

    /// Whether `p` is new to this traversal (and now recorded).
    #[inline]
    fn first_visit(&mut self, p: u32) -> bool {
        if self.few[..self.len].contains(&p) {
            return false;
        }
        if self.len < self.few.len() {
            self.few[self.len] = p;
            self.len += 1;
            return true;
        }
        self.many.get_or_insert_with(HashSet::new).insert(p)
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
mod tests {
    use super::*;
    use glam::DVec3;

    /// Every primitive `traverse_seeing` reports, in order, with an interval
    /// that never shrinks.
    fn visited(tree: &KdTree, ray: &Ray, t_min: f64) -> (Vec<usize>, u32) {
        let mut out = Vec::new();
        let mut tested = TestCounts::default();
        let flow = tree.traverse_seeing(
            ray,
            t_min,
            &mut { f64::INFINITY },
            &mut tested,
            |_, _| {},
            |p, _| {
                out.push(p);
                ControlFlow::Continue(())
            },
        );
        assert_eq!(flow, ControlFlow::Continue(()));
        (out, tested.boxes)
    }

    fn cube(at: DVec3, half: f64) -> Bounds {
        Bounds {
            min: at - half,
            max: at + half,
        }
    }

    /// A box on an integer grid ("ticks"): its coordinates times a power of two
    /// are exact in f64, so the exact test below decides what the tree must find.
    #[derive(Clone, Copy, Debug)]
    struct IBox {
        min: [i64; 3],
        max: [i64; 3],
    }

    /// Whether `o + t·d` meets the closed box for some `t ≥ t_min` (a fraction
    /// `num/den`, `den > 0`), in exact integer arithmetic: every entering
    /// parameter is at most every leaving one, compared as fractions.
    fn exact_meets(b: &IBox, o: [i64; 3], d: [i64; 3], t_min: (i128, i128)) -> bool {
        let mut enter = vec![t_min];
        let mut leave = Vec::new();
        for k in 0..3 {
            let (lo, hi, o, d) = (
                i128::from(b.min[k]),
                i128::from(b.max[k]),
                i128::from(o[k]),
                i128::from(d[k]),
            );
            match d.signum() {
                0 if o < lo || o > hi => return false,
                0 => {}
                1 => {
                    enter.push((lo - o, d));
                    leave.push((hi - o, d));
                }
                _ => {
                    enter.push((o - hi, -d));
                    leave.push((o - lo, -d));
                }
            }
        }
        enter
            .iter()
            .all(|&(n0, d0)| leave.iter().all(|&(n1, d1)| n0 * d1 <= n1 * d0))
    }

    /// Random boxes in ticks within ±`l`: mostly small, a few huge, some flat in
    /// one axis, some coincident with earlier ones, many with faces on a coarse
    /// grid so that they share planes with each other and with ray origins.
    fn random_boxes(rng: &mut fastrand::Rng, count: usize, l: i64) -> Vec<IBox> {
        let mut boxes: Vec<IBox> = Vec::with_capacity(count);
        for i in 0..count {
            let kind = rng.u32(0..100);
            let b = if kind < 5 && i > 0 {
                boxes[rng.usize(0..i)]
            } else if kind < 8 {
                let mut b = IBox {
                    min: [0; 3],
                    max: [0; 3],
                };
                for k in 0..3 {
                    b.min[k] = -l + rng.i64(0..l / 4);
                    b.max[k] = l - rng.i64(0..l / 4);
                }
                b
            } else {
                let coarse = kind < 40;
                let mut b = IBox {
                    min: [0; 3],
                    max: [0; 3],
                };
                for k in 0..3 {
                    let (mut c, mut h) = (rng.i64(-l..=l), rng.i64(0..=512));
                    if coarse {
                        c = c / 1024 * 1024;
                        h = h / 256 * 256 + 512;
                    }
                    b.min[k] = (c - h).max(-l);
                    b.max[k] = (c + h).min(l);
                }
                if kind.is_multiple_of(7) {
                    let k = rng.usize(0..3);
                    b.max[k] = b.min[k];
                }
                b
            };
            boxes.push(b);
        }
        boxes
    }

    /// The containment test: every primitive whose box the ray meets (decided
    /// exactly) is visited, and none twice. It fails if rounding in the clip to
    /// the scene box or in a plane crossing skips a cell the ray enters (most
    /// likely for rays grazing a face or an edge, lying in a splitting plane,
    /// parallel to an axis, or starting on a plane), if a primitive touching a
    /// cell only on its boundary (flat, coincident, sharing a plane with the
    /// split) was not stored on both sides, or if the mailbox lets a primitive
    /// stored in several leaves through twice. Run at three scales (the same
    /// configuration times 2⁻⁴⁸, 2⁻⁸, 2³²) since relative bounds must hold at all.
    #[test]
    fn every_box_met_is_visited_exactly_once() {
        let mut rng = fastrand::Rng::with_seed(28);
        let l: i64 = 1 << 14;
        let boxes = random_boxes(&mut rng, 3000, l);
        let mut extra = 0usize;
        let mut needed = 0usize;
        for scale in [(-48f64).exp2(), (-8f64).exp2(), 32f64.exp2()] {
            let f = |v: [i64; 3]| DVec3::new(v[0] as f64, v[1] as f64, v[2] as f64) * scale;
            let bounds: Vec<Bounds> = boxes
                .iter()
                .map(|b| Bounds {
                    min: f(b.min),
                    max: f(b.max),
                })
                .collect();
            let tree = KdTree::build(&bounds);
            let mut count = vec![0u32; boxes.len()];
            for case in 0..1500 {
                let pick = |rng: &mut fastrand::Rng, r: i64| {
                    [rng.i64(-r..=r), rng.i64(-r..=r), rng.i64(-r..=r)]
                };
                // Inside, outside, or on a box's face plane.
                let mut o = match case % 3 {
                    0 => pick(&mut rng, l),
                    1 => pick(&mut rng, 3 * l),
                    _ => {
                        let b = boxes[rng.usize(0..boxes.len())];
                        let mut o = pick(&mut rng, l);
                        let k = rng.usize(0..3);
                        o[k] = if rng.bool() { b.min[k] } else { b.max[k] };
                        o
                    }
                };
                if case % 13 == 0 {
                    o = o.map(|v| v / 1024 * 1024);
                }
                // Random, through a box's corner or edge midpoint (grazing), or
                // axis-parallel (one or two components zero).
                let b = boxes[rng.usize(0..boxes.len())];
                let mut d = match case % 4 {
                    0 => pick(&mut rng, 256),
                    1 => {
                        let c = [0, 1, 2].map(|k| if rng.bool() { b.min[k] } else { b.max[k] });
                        [0, 1, 2].map(|k| c[k] - o[k])
                    }
                    2 => {
                        let c = [0, 1, 2].map(|k| match rng.u32(0..3) {
                            0 => b.min[k],
                            1 => b.max[k],
                            _ => (b.min[k] + b.max[k]) / 2,
                        });
                        [0, 1, 2].map(|k| c[k] - o[k])
                    }
                    _ => pick(&mut rng, 256),
                };
                if case % 5 == 0 {
                    d[rng.usize(0..3)] = 0;
                }
                if case % 17 == 0 {
                    let k = rng.usize(0..3);
                    d = [0; 3];
                    d[k] = if rng.bool() { 1 } else { -1 };
                }
                if d == [0; 3] {
                    d = [1, 0, 0];
                }
                let t_min = if case % 6 == 0 { (1, 2) } else { (0, 1) };
                let ray = Ray::new(f(o), f(d));
                let (seen, _) = visited(&tree, &ray, t_min.0 as f64 / t_min.1 as f64);
                for &p in &seen {
                    count[p] += 1;
                }
                for (p, b) in boxes.iter().enumerate() {
                    let must = exact_meets(b, o, d, t_min);
                    assert!(
                        !must || count[p] == 1,
                        "box {p} {b:?} visited {} times: ray {o:?} + t·{d:?}, t ≥ {t_min:?}, scale {scale}",
                        count[p]
                    );
                    assert!(count[p] <= 1, "box {p} visited {} times", count[p]);
                    needed += usize::from(must);
                    extra += usize::from(!must && count[p] == 1);
                }
                for &p in &seen {
                    count[p] = 0;
                }
            }
        }
        // Not a requirement, but a tree visiting everything would pass the above:
        // the leaves the ray passes hold few boxes it misses.
        assert!(
            extra < 3 * needed,
            "{extra} extra visits for {needed} needed"
        );
    }

    /// The same containment with rays from far away aimed (in f64) at corners
    /// and edges of small boxes with full-precision coordinates: here `p − o`
    /// rounds, so computed crossings of different planes can fall out of their
    /// exact order, which only the widening in [`crossing`] makes up for (on the
    /// tick grid above every subtraction is exact and a rounded quotient keeps
    /// the order). Every value is a multiple of 2⁻³⁰ below 2³¹, so the exact
    /// test runs on integers.
    #[test]
    fn far_rays_grazing_fine_boxes_lose_nothing() {
        const GRID: f64 = 1073741824.0; // 2³⁰
        let ticks = |v: DVec3| {
            v.to_array().map(|c| {
                let s = c * GRID;
                assert!(s.fract() == 0.0 && s.abs() < 2f64.powi(62), "{c}");
                s as i64
            })
        };
        let fine = |rng: &mut fastrand::Rng, r: f64| {
            let mut c = || ((rng.f64() * 2.0 - 1.0) * r * GRID).round() / GRID;
            DVec3::new(c(), c(), c())
        };
        let mut rng = fastrand::Rng::with_seed(1);
        let mut bounds = Vec::new();
        for i in 0..2000 {
            let (a, h) = (fine(&mut rng, 4.0), fine(&mut rng, 0.25).abs());
            let mut b = Bounds {
                min: a - h,
                max: a + h,
            };
            if i % 9 == 0 {
                b.max.z = b.min.z;
            }
            if i % 5 == 0 && i > 0 {
                // Share a plane with an earlier box.
                let other: Bounds = bounds[rng.usize(0..i)];
                b.min.x = other.max.x;
                b.max.x = b.max.x.max(b.min.x);
            }
            bounds.push(b);
        }
        let boxes: Vec<IBox> = bounds
            .iter()
            .map(|b| IBox {
                min: ticks(b.min),
                max: ticks(b.max),
            })
            .collect();
        let tree = KdTree::build(&bounds);
        let mut count = vec![0u32; boxes.len()];
        for case in 0..3000 {
            let far = |rng: &mut fastrand::Rng| {
                // Far enough that a difference with a fine coordinate is a
                // multiple of 2⁻³⁰ (its ULP is at least that), and mostly rounds.
                let e = rng.i32(22..30);
                let m = 1.0 + f64::from(rng.u32(0..1024)) / 1024.0;
                if rng.bool() {
                    m * 2f64.powi(e)
                } else {
                    -m * 2f64.powi(e)
                }
            };
            let o = if case % 4 == 0 {
                fine(&mut rng, 4.0)
            } else {
                DVec3::new(far(&mut rng), far(&mut rng), far(&mut rng))
            };
            let b = bounds[rng.usize(0..bounds.len())];
            let pick = |rng: &mut fastrand::Rng, k: usize| match rng.u32(0..3) {
                0 => b.min[k],
                1 => b.max[k],
                _ => (b.center()[k] * GRID).floor() / GRID,
            };
            let target = DVec3::new(pick(&mut rng, 0), pick(&mut rng, 1), pick(&mut rng, 2));
            let mut d = target - o;
            if case % 7 == 0 {
                d[rng.usize(0..3)] = 0.0;
            }
            if d == DVec3::ZERO {
                continue;
            }
            let ray = Ray::new(o, d);
            let (seen, _) = visited(&tree, &ray, 0.0);
            for &p in &seen {
                count[p] += 1;
            }
            let (oi, di) = (ticks(o), ticks(d));
            for (p, b) in boxes.iter().enumerate() {
                assert!(
                    count[p] == 1 || (count[p] == 0 && !exact_meets(b, oi, di, (0, 1))),
                    "box {p} {:?} visited {} times: ray {o:?} + t·{d:?}",
                    bounds[p],
                    count[p]
                );
            }
            for &p in &seen {
                count[p] = 0;
            }
        }
    }

    /// Four boxes in a 2 × 2 square, so the cells' corners are the boxes'
    /// corners, and rays from far off aimed (in f64) near the corner `c`
    /// of the box at the origin, `c` just above (1, 1) with low bits set so
    /// that `c − o` rounds: each ray passes within a rounding of the corner,
    /// clipping the box or not, and whether the walk enters the box's cell turns
    /// on the order of two crossings `t_x`, `t_y` equal but for rounding. (With
    /// exact subtractions a correctly rounded quotient keeps that order, and no
    /// widening would be needed.) It fails if the crossings are taken as exact.
    #[test]
    fn rays_through_a_cell_corner_keep_the_box() {
        const GRID: f64 = 1073741824.0; // 2³⁰
        let ticks = |v: DVec3| {
            v.to_array().map(|c| {
                let s = c * GRID;
                assert!(s.fract() == 0.0 && s.abs() < 2f64.powi(62), "{c}");
                s as i64
            })
        };
        let mut rng = fastrand::Rng::with_seed(3);
        let (mut met, mut missed) = (0, 0);
        for case in 0..400 {
            let fine = |rng: &mut fastrand::Rng| 1.0 + f64::from(rng.u32(1..1 << 20) | 1) / GRID;
            let c = DVec3::new(fine(&mut rng), fine(&mut rng), 1.0);
            // Four boxes tiling [0, 2]² meeting at `c`: the only planes to split
            // on inside the scene pass through `c`.
            let quad = |x: [f64; 2], y: [f64; 2]| Bounds {
                min: DVec3::new(x[0], y[0], 0.0),
                max: DVec3::new(x[1], y[1], 1.0),
            };
            let (lo_x, hi_x, lo_y, hi_y) = ([0.0, c.x], [c.x, 2.0], [0.0, c.y], [c.y, 2.0]);
            let bounds = [
                quad(lo_x, lo_y),
                quad(hi_x, lo_y),
                quad(lo_x, hi_y),
                quad(hi_x, hi_y),
            ];
            let tree = KdTree::build(&bounds);
            let a = IBox {
                min: ticks(bounds[0].min),
                max: ticks(bounds[0].max),
            };
            for _ in 0..50 {
                // Up and to the left of the corner, at 2²²…2³⁰ so that a
                // difference with `c` is a multiple of 2⁻³⁰ and mostly rounds.
                let e = rng.i32(22..30);
                let far = |rng: &mut fastrand::Rng| (1.0 + rng.f64()) * 2f64.powi(e);
                let o = DVec3::new(-far(&mut rng), far(&mut rng), 0.5);
                // Aimed a few 2⁻³⁰ off the corner: aimed right at it, the
                // computed crossings would both be `(c − o) / (c − o)` = 1.
                let off = |rng: &mut fastrand::Rng| f64::from(rng.i32(-4..=4)) / GRID;
                let d = DVec3::new(c.x + off(&mut rng), c.y + off(&mut rng), 0.5) - o;
                let must = exact_meets(&a, ticks(o), ticks(d), (0, 1));
                let got = visited(&tree, &Ray::new(o, d), 0.0).0.contains(&0);
                assert!(
                    got || !must,
                    "box lost: ray {o:?} + t·{d:?}, corner {c:?} ({case})"
                );
                met += usize::from(must);
                missed += usize::from(!must);
            }
        }
        // The rays fall on both sides of the corner.
        assert!(met > 100 && missed > 100, "{met} met, {missed} missed");
    }

    /// The nearest root of a sphere's quadratic above `t_min`.
    fn sphere_hit(c: DVec3, r: f64, ray: &Ray, t_min: f64) -> Option<f64> {
        let oc = ray.origin - c;
        let a = ray.dir.length_squared();
        let b = oc.dot(ray.dir);
        let disc = b * b - a * (oc.length_squared() - r * r);
        if disc < 0.0 {
            return None;
        }
        let s = disc.sqrt();
        [(-b - s) / a, (-b + s) / a]
            .into_iter()
            .find(|&t| t > t_min)
    }

    /// A closest-hit search through the tree finds what the lecture's loop over
    /// every sphere finds. It fails if the walk stops too early once `t_max`
    /// shrinks (a cell still to visit holding a nearer hit was skipped, e.g.
    /// a far child pushed with the wrong interval), if cells are visited out of
    /// order so that the stop is taken before a nearer cell, or if a sphere is
    /// missing from a leaf its box reaches.
    #[test]
    fn closest_hit_matches_testing_every_sphere() {
        let mut rng = fastrand::Rng::with_seed(5);
        let spheres: Vec<(DVec3, f64)> = (0..2000)
            .map(|i| {
                let c = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 200.0 - 100.0;
                let r = if i % 50 == 0 {
                    20.0
                } else {
                    0.2 + 2.0 * rng.f64()
                };
                (c, r)
            })
            .collect();
        let bounds: Vec<Bounds> = spheres.iter().map(|&(c, r)| cube(c, r)).collect();
        let tree = KdTree::build(&bounds);
        let mut hits = 0;
        for case in 0..4000 {
            let o = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 300.0 - 150.0;
            let mut d = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 2.0 - 1.0;
            if case % 7 == 0 {
                d.y = 0.0;
            }
            let t_min = if case % 2 == 0 { 0.0 } else { 1e-9 };
            let ray = Ray::new(o, d);
            let mut expected = None;
            for (i, &(c, r)) in spheres.iter().enumerate() {
                if let Some(t) = sphere_hit(c, r, &ray, t_min)
                    && expected.is_none_or(|(_, best)| t < best)
                {
                    expected = Some((i, t));
                }
            }
            let mut found = None;
            let mut t_max = f64::INFINITY;
            let _ = tree.traverse_seeing(
                &ray,
                t_min,
                &mut t_max,
                &mut TestCounts::default(),
                |_, _| {},
                |p, t_max| {
                    if let Some(t) = sphere_hit(spheres[p].0, spheres[p].1, &ray, t_min)
                        && t < *t_max
                    {
                        *t_max = t;
                        found = Some((p, t));
                    }
                    ControlFlow::Continue(())
                },
            );
            assert_eq!(found, expected, "ray {o} + t·{d}");
            hits += usize::from(found.is_some());
        }
        assert!(hits > 500, "only {hits} rays hit anything");
    }

    /// A row of 100 cubes along x.
    fn row() -> Vec<Bounds> {
        (0..100)
            .map(|i| cube(DVec3::new(i as f64, 0.0, 0.0), 0.25))
            .collect()
    }

    /// After a break nothing more is visited, and the break is returned. Fails
    /// if the leaf loop or the walk goes on after `visit` breaks.
    #[test]
    fn breaking_stops_the_traversal() {
        let tree = KdTree::build(&row());
        let ray = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
        let mut calls = Vec::new();
        let flow = tree.traverse_seeing(
            &ray,
            0.0,
            &mut { f64::INFINITY },
            &mut TestCounts::default(),
            |_, _| {},
            |p, _| {
                calls.push(p);
                ControlFlow::Break(())
            },
        );
        assert_eq!((flow, calls), (ControlFlow::Break(()), vec![0]));
    }

    /// A hit shrinking `t_max` ends the walk: no cell beyond the hit is visited,
    /// far fewer steps than the whole row, and the first cube is visited first.
    /// Fails if the walk ignores the shrunk `t_max` when taking far children off
    /// its stack, or visits cells back to front.
    #[test]
    fn a_near_hit_stops_the_walk() {
        let tree = KdTree::build(&row());
        let ray = Ray::new(DVec3::new(-1.0, 0.01, 0.02), DVec3::X);
        let (all, full_steps) = visited(&tree, &ray, 0.0);
        assert_eq!(all.len(), 100);
        assert!(
            all.windows(2).all(|w| w[0] < w[1]),
            "not front to back: {all:?}"
        );
        let mut tested = TestCounts::default();
        let mut calls = 0;
        let mut t_max = f64::INFINITY;
        let hit = std::cell::Cell::new(false);
        let _ = tree.traverse_seeing(
            &ray,
            0.0,
            &mut t_max,
            &mut tested,
            |cell, _| {
                // Once the hit at t = 0.75 (x = −0.25) is known, no cell the
                // ray enters beyond it is visited.
                assert!(
                    !hit.get() || cell.min.x <= -0.25 + 1e-9,
                    "{cell:?} visited beyond the hit"
                );
            },
            |p, t_max| {
                hit.set(true);
                calls += 1;
                // The cube at x = p is entered at t = p + 0.75.
                *t_max = t_max.min(p as f64 + 0.75);
                ControlFlow::Continue(())
            },
        );
        assert_eq!(t_max, 0.75);
        assert!(
            calls <= 2 && tested.boxes * 5 < full_steps,
            "{calls} visits, {} steps of {full_steps}",
            tested.boxes
        );
    }

    /// A grid of small cubes: a ray along one row visits few of them and takes
    /// few steps, and every step shows its cell. Fails if the build makes no
    /// useful splits (a leaf of everything passes the containment test).
    #[test]
    fn a_row_in_a_grid_takes_few_steps() {
        let boxes: Vec<Bounds> = (0..1000)
            .map(|i| {
                let at = DVec3::new((i % 10) as f64, (i / 10 % 10) as f64, (i / 100) as f64);
                cube(at, 0.25)
            })
            .collect();
        let tree = KdTree::build(&boxes);
        let ray = Ray::new(DVec3::new(-1.0, 4.1, 3.9), DVec3::new(1.0, 0.01, 0.02));
        let mut cells = 0;
        let mut tested = TestCounts::default();
        let mut seen = Vec::new();
        let _ = tree.traverse_seeing(
            &ray,
            0.0,
            &mut { f64::INFINITY },
            &mut tested,
            |_, met| {
                assert!(met);
                cells += 1;
            },
            |p, _| {
                seen.push(p);
                ControlFlow::Continue(())
            },
        );
        assert_eq!(cells, tested.boxes);
        assert!(seen.len() < 30 && tested.boxes < 200, "{seen:?} {tested:?}");
        assert!(tree.depth > 5, "{}", tree.describe());
    }

    /// No primitives: nothing is visited, no step taken. One primitive: it is
    /// visited by a ray that meets its box and not by one that misses the
    /// scene. Fails on an unguarded root, or a one-leaf tree clipped wrongly.
    #[test]
    fn empty_and_single() {
        let ray = Ray::new(DVec3::ZERO, DVec3::new(1.0, 0.5, 0.25));
        let empty = KdTree::build(&[]);
        assert_eq!(visited(&empty, &ray, 0.0), (Vec::new(), 0));
        assert!(empty.describe().contains("0 primitives"));
        let one = KdTree::build(&[cube(DVec3::new(4.0, 2.0, 1.0), 0.5)]);
        assert_eq!(visited(&one, &ray, 0.0), (vec![0], 1));
        assert_eq!(
            visited(&one, &Ray::new(DVec3::ZERO, -ray.dir), 0.0).0,
            Vec::<usize>::new()
        );
        // From inside the box, parallel to an axis.
        let inside = Ray::new(DVec3::new(4.0, 2.0, 1.0), DVec3::Z);
        assert_eq!(visited(&one, &inside, 0.0).0, vec![0]);
        // Lying in its face, parallel to two axes.
        let face = Ray::new(DVec3::new(0.0, 1.5, 1.5), DVec3::X);
        assert_eq!(visited(&one, &face, 0.0).0, vec![0]);
    }

    /// The entry cap bounds memory: boxes that all overlap would otherwise be
    /// copied into every leaf.
    #[test]
    fn entries_are_capped() {
        let boxes: Vec<Bounds> = (0..500)
            .map(|i| {
                cube(
                    DVec3::new(i as f64 * 0.01, 0.0, 0.0),
                    10.0 + i as f64 * 0.001,
                )
            })
            .collect();
        let tree = KdTree::build(&boxes);
        assert!(
            tree.entries.len() <= ENTRY_CAP * boxes.len(),
            "{}",
            tree.describe()
        );
    }
}
