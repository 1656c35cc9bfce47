//! Building the BSP tree.
//!
//! pbrt's SAH k-d tree (Pharr, Jakob & Humphreys, *Physically Based
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

use crate::geometry::structures::bsp::{
    BspTree, EMPTY_BONUS, ENTRY_CAP, ISECT_COST, LEAF, MAX_LEAF, Node, SHARED, STACK,
    TRAVERSAL_COST,
};
use crate::math::bounds::Bounds;

impl BspTree {
    /// Builds over primitives `0..n` known by their (finite, non-empty) bounds,
    /// at most `8 + 1.3·log₂ N` levels deep.
    pub fn build(bounds: &[Bounds]) -> BspTree {
        BspTree::build_to_depth(bounds, None)
    }

    /// [`BspTree::build`] with leaves at most `depth_limit` levels below the root
    /// (`None`: pbrt's `8 + 1.3·log₂ N`), clamped so the walk's stack holds.
    pub fn build_to_depth(bounds: &[Bounds], depth_limit: Option<u32>) -> BspTree {
        let n = bounds.len();
        let mut tree = BspTree {
            nodes: Vec::new(),
            entries: Vec::new(),
            bounds: Bounds::EMPTY,
            primitives: n,
            depth: 0,
            depth_limit: 0,
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
        tree.depth_limit = depth_limit.unwrap_or(rule).min(STACK as u32 - 1);
        let mut builder = Builder {
            bounds,
            nodes: Vec::new(),
            entries: Vec::new(),
            depth: 0,
        };
        let all: Vec<u32> = (0..n as u32).collect();
        let budget = (ENTRY_CAP - 1) * n;
        builder.node(all, tree.bounds, 0, tree.depth_limit, 0, budget);
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
pub(super) fn goes(b: &Bounds, k: usize, pos: f64) -> (bool, bool) {
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
        depth_limit: u32,
        bad_refines: u32,
        budget: usize,
    ) -> u32 {
        let index = self.nodes.len() as u32;
        let n = prims.len();
        let leaf_cost = ISECT_COST * n as f64;
        let split = if n <= MAX_LEAF || depth >= depth_limit {
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
        let a = self.node(below, below_cell, depth + 1, depth_limit, bad, below_budget);
        let b = self.node(
            above,
            above_cell,
            depth + 1,
            depth_limit,
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
    use glam::DVec3;

    use crate::geometry::structures::bsp::{BspTree, ENTRY_CAP};
    use crate::geometry::structures::walk_tests::{cube, described};
    use crate::math::bounds::Bounds;

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
        let tree = BspTree::build(&boxes);
        assert!(
            tree.entries.len() <= ENTRY_CAP * boxes.len(),
            "{}",
            described(&tree)
        );
    }
}
