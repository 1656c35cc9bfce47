//! A BSP tree: the lecture's binary space partitioning, space split in two by
//! a plane and each side again, here with every plane perpendicular to an
//! axis: the axis-aligned BSP tree, which the literature calls a k-d tree
//! (pbrt's `KdTreeAggregate`).
//!
//! Why the axis-aligned BSP tree: a general BSP tree may split along any plane,
//! but a ray's crossing of an axis-aligned plane costs one subtraction and one
//! division (`(p − o_k) / d_k`), cells stay boxes (so a diagram can draw them and
//! the surface area heuristic can price them by their areas), and the candidate
//! planes are finite and obvious: the faces of the primitives' boxes. That makes
//! the tree buildable by the surface area heuristic (SAH), which is what makes
//! such a tree fast (Havran's thesis; Wald & Havran 2006).
//!
//! How the planes are chosen (the surface area heuristic): [`build`]. How a
//! ray walks the cells front to back, and why no cell it meets is skipped in
//! floating point: [`traverse`].

use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

pub mod build; // pbrt's SAH k-d tree: every box face a candidate plane, an entry budget
pub mod traverse; // front to back with the ray's interval, each plane crossing widened
#[cfg(test)]
mod tests;

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

/// A BSP tree over primitives `0..n`, known by their bounding boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct BspTree {
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
    depth_limit: u32,
}

impl Structure for BspTree {
    /// The cells the ray's segment meets, front to back (see [`traverse`]).
    #[inline]
    fn walk(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.traverse(ray, t_min, t_max, tested, seen, visit)
    }

    /// Its primitives, nodes, leaves, depth and its limit, entries.
    fn describe(&self) -> Option<String> {
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
        Some(format!(
            "k-d tree: {} primitives, {} nodes ({} leaves, {} empty), depth {} (limit {}), \
             {} entries ({per:.2} per primitive; {shared} primitives in more than one leaf), \
             largest leaf {largest}",
            self.primitives,
            self.nodes.len(),
            leaves.len(),
            empty,
            self.depth,
            self.depth_limit,
            self.entries.len(),
        ))
    }

    /// The nodes and the leaves' lists.
    fn memory(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.entries.len() * 4
    }
}
