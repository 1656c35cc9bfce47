//! An octree: the lecture's other way to avoid intersection tests. The scene's
//! box, made a cube, is split into eight equal children, and each child again,
//! until a cell holds few primitives. A primitive is listed in every cell its box
//! touches, so a ray only needs the primitives of the cells it passes through,
//! nearest cell first.
//!
//! When a node is split, and how: [`build`]. How a ray walks the cells nearest
//! first, and why no cell it meets is skipped in floating point: [`traverse`].

use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

pub mod build; // split level by level, while it pays and within the entry cap
pub mod traverse; // the children a ray meets, nearest first, each slab test widened
#[cfg(test)]
mod tests;

/// A node with at most this many primitives is not split: testing eight
/// primitives costs about as much as testing a node's eight children.
pub const LEAF_SIZE: usize = 8;

/// Nodes this deep are not split. A cell is then 1/1024 of the scene's side
/// (up to 8¹⁰ ≈ 10⁹ cells): finer cells rarely separate primitives that coarser
/// ones could not, only copying their lists, and the depth bounds the stack.
pub const DEPTH_LIMIT: u32 = 10;

/// The deepest an octree may be asked to go ([`Octree::build_to_depth`]): its
/// cells are then 2⁻⁴⁸ of the scene's side, near the resolution of `f64`.
pub const DEEPEST: u32 = 48;

/// A node: its cell, and either its eight children or its primitives.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    /// The cell: a cube, up to rounding.
    cell: Bounds,
    kind: Kind,
}

/// What a node holds.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Children at `first..first + 8`; child `i` has the upper half in x if bit
    /// 0 of `i` is set, in y for bit 1, in z for bit 2.
    Inner { first: u32 },
    /// Primitives at `entries[start..start + len]`.
    Leaf { start: u32, len: u32 },
}

/// An octree over primitives `0..n`, known by their bounding boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct Octree {
    /// The root is node 0, if there are any primitives.
    nodes: Vec<Node>,
    /// The leaves' primitive lists, leaf by leaf.
    entries: Vec<u32>,
    /// Primitives it was built over.
    primitives: usize,
    /// The deepest leaf's level (the root's is 0).
    depth: u32,
    /// The deepest level allowed.
    depth_limit: u32,
}

impl Octree {
    /// The most entries the leaves may hold together over `n` primitives,
    /// `16·n + 1024`: a split that would go beyond it is not made, so memory
    /// stays linear in the scene whatever the boxes' overlap.
    pub fn entry_cap(n: usize) -> usize {
        16 * n + 1024
    }
}

impl Structure for Octree {
    /// The cells the ray passes through, nearest first (see [`traverse`]).
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

    /// Its primitives, nodes, leaves, depth, the finest cell's side, entries.
    fn describe(&self) -> Option<String> {
        let Some(root) = self.nodes.first() else {
            return Some("octree: empty".to_string());
        };
        let leaves: Vec<u32> = self
            .nodes
            .iter()
            .filter_map(|n| match n.kind {
                Kind::Leaf { len, .. } => Some(len),
                Kind::Inner { .. } => None,
            })
            .collect();
        let empty = leaves.iter().filter(|&&l| l == 0).count();
        let fullest = leaves.iter().max().copied().unwrap_or(0);
        let side = (root.cell.max - root.cell.min).max_element();
        Some(format!(
            "octree: {} primitives; {} nodes, {} leaves ({} empty, fullest {}, split above {}); \
             depth {} of at most {}, root side {:.4}, finest cells {:.4}; \
             {} entries ({:.2} a primitive, cap {})",
            self.primitives,
            self.nodes.len(),
            leaves.len(),
            empty,
            fullest,
            LEAF_SIZE,
            self.depth,
            self.depth_limit,
            side,
            side / 2f64.powi(self.depth as i32),
            self.entries.len(),
            self.entries.len() as f64 / self.primitives as f64,
            Octree::entry_cap(self.primitives),
        ))
    }

    /// The nodes and the leaves' lists.
    fn memory(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.entries.len() * 4
    }
}
