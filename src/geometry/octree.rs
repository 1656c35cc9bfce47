//! An octree: the lecture's other way to avoid intersection tests. The scene's
//! box, made a cube, is split into eight equal children, and each child again,
//! until a cell holds few primitives. A primitive is listed in every cell its box
//! touches, so a ray only needs the primitives of the cells it passes through,
//! nearest cell first.
//!
//! **Build.** A node becomes a leaf when it holds at most [`LEAF_SIZE`]
//! primitives, when it is [`MAX_DEPTH`] levels deep (or as deep as asked), when
//! every one of its primitives overlaps every child (splitting again would only
//! copy the list eight times, level after level), or when the split would take
//! the entries of all leaves past [`Octree::entry_cap`]. Nodes are split level
//! by level (breadth first), so when the cap stops the splitting it stops it at
//! about one depth everywhere; built depth first, the first corner of a scene
//! could spend the whole budget and leave the rest in leaves of thousands. (A
//! first version also stopped when all of a node's primitives fell into one
//! child: the sphereflake's 7,382 spheres, all in one corner of the root's
//! child, then stayed in one leaf and its rays tested 2,820 primitives each.)
//! A primitive goes into every child whose closed
//! box its closed box overlaps (touching counts). The nodes live in one `Vec`,
//! the eight children of a node consecutive; the leaves' lists in one `Vec<u32>`.
//!
//! **Traversal** is an ordered stack: at an inner node the ray's parametric
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
use glam::{BVec3, DVec3};

use crate::geometry::hit::TestCounts;
use crate::geometry::mailbox::Mailbox;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

/// A node with at most this many primitives is not split: testing eight
/// primitives costs about as much as testing a node's eight children.
pub const LEAF_SIZE: usize = 8;

/// Nodes this deep are not split. A cell is then 1/1024 of the scene's side
/// (up to 8¹⁰ ≈ 10⁹ cells): finer cells rarely separate primitives that coarser
/// ones could not, only copying their lists, and the depth bounds the stack.
pub const MAX_DEPTH: u32 = 10;

/// The deepest an octree may be asked to go ([`Octree::build_to_depth`]): its
/// cells are then 2⁻⁴⁸ of the scene's side, near the resolution of `f64`.
pub const DEEPEST: u32 = 48;

/// Room on the traversal stack: at most seven children pushed per level (eight
/// met, the nearest walked into), one level below another.
const STACK: usize = 7 * (DEEPEST as usize + 1) + 1;

/// The widening of a slab test's leaving parameter and of `t_max`: `32ε`
/// (see the module documentation; γ(6) ≈ 3ε is what the test needs).
const WIDEN: f64 = 32.0 * f64::EPSILON;

/// A node: its cell, and either its eight children or its primitives.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    /// The cell: a cube, up to rounding.
    cell: Bounds,
    kind: Kind,
}

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
    max_depth: u32,
}

impl Octree {
    /// The most entries the leaves may hold together over `n` primitives,
    /// `16·n + 1024`: a split that would go beyond it is not made, so memory
    /// stays linear in the scene whatever the boxes' overlap.
    pub fn entry_cap(n: usize) -> usize {
        16 * n + 1024
    }

    /// Builds the octree over primitives with these (finite, non-empty) bounds,
    /// at most [`MAX_DEPTH`] levels deep.
    pub fn build(bounds: &[Bounds]) -> Octree {
        Octree::build_to_depth(bounds, MAX_DEPTH)
    }

    /// [`Octree::build`] with leaves at most `max_depth` levels below the root
    /// (clamped to [`DEEPEST`]); 0 makes the root a leaf of every primitive.
    pub fn build_to_depth(bounds: &[Bounds], max_depth: u32) -> Octree {
        let max_depth = max_depth.min(DEEPEST);
        let n = bounds.len();
        if n == 0 {
            return Octree {
                nodes: Vec::new(),
                entries: Vec::new(),
                primitives: 0,
                depth: 0,
                max_depth,
            };
        }
        assert!(
            u32::try_from(Octree::entry_cap(n)).is_ok(),
            "too many primitives for an octree"
        );
        let scene = bounds.iter().fold(Bounds::EMPTY, |a, b| a.union(*b));
        let side = (scene.max - scene.min).max_element();
        // A cube at the scene's lower corner; `max` keeps it around the scene
        // box even where `min + side` rounds down.
        let root = Bounds {
            min: scene.min,
            max: (scene.min + side).max(scene.max),
        };
        let mut builder = Builder {
            boxes: bounds,
            nodes: vec![Node {
                cell: root,
                kind: Kind::Leaf { start: 0, len: 0 },
            }],
            entries: Vec::new(),
            live: n,
            cap: Octree::entry_cap(n),
            max_depth,
            depth: 0,
        };
        builder.build((0..n as u32).collect());
        Octree {
            nodes: builder.nodes,
            entries: builder.entries,
            primitives: n,
            depth: builder.depth,
            max_depth,
        }
    }

    /// Calls `visit(primitive, t_max)` for every primitive the ray may meet in
    /// `(t_min, *t_max)`, those of nearer cells first, each at most once. `visit`
    /// may shrink `t_max` (a closest-hit search), after which cells entered
    /// beyond it are skipped, or break (a shadow ray's any-hit), which ends the
    /// walk at once. Every node walked into counts in `tested.boxes` and is
    /// passed to `seen(cell, true)`.
    pub fn traverse_seeing(
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

    /// The octree's own numbers: primitives, nodes, leaves, depth, the finest
    /// cell's side, entries.
    pub fn describe(&self) -> String {
        let Some(root) = self.nodes.first() else {
            return "octree: empty".to_string();
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
        format!(
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
            self.max_depth,
            side,
            side / 2f64.powi(self.depth as i32),
            self.entries.len(),
            self.entries.len() as f64 / self.primitives as f64,
            Octree::entry_cap(self.primitives),
        )
    }
}

/// The state of a build: the nodes and entries so far, and the entries all
/// current leaves would hold (`live`), kept at most `cap`.
struct Builder<'a> {
    boxes: &'a [Bounds],
    nodes: Vec<Node>,
    entries: Vec<u32>,
    live: usize,
    cap: usize,
    max_depth: u32,
    depth: u32,
}

impl Builder<'_> {
    /// Makes the root (node 0, its cell set) over `all`, and every node under
    /// it, a level at a time.
    fn build(&mut self, all: Vec<u32>) {
        let mut level = vec![(0usize, all)];
        let mut depth = 0;
        while !level.is_empty() {
            self.depth = depth;
            let mut next = Vec::new();
            for (at, prims) in level {
                match self.split(at, &prims, depth) {
                    Some(children) => next.extend(children),
                    None => self.leaf(at, &prims),
                }
            }
            level = next;
            depth += 1;
        }
    }

    /// Splits node `at` over `prims`, `depth` levels down, into eight children
    /// (returned with their primitives), unless it should stay a leaf.
    fn split(&mut self, at: usize, prims: &[u32], depth: u32) -> Option<Vec<(usize, Vec<u32>)>> {
        if prims.len() <= LEAF_SIZE || depth >= self.max_depth {
            return None;
        }
        let cells = octants(&self.nodes[at].cell);
        let parts: [Vec<u32>; 8] = cells.map(|cell| {
            prims
                .iter()
                .copied()
                .filter(|&p| overlaps(&self.boxes[p as usize], &cell))
                .collect()
        });
        let everywhere = parts.iter().all(|part| part.len() == prims.len());
        let live = self.live - prims.len() + parts.iter().map(Vec::len).sum::<usize>();
        if everywhere || live > self.cap {
            return None;
        }
        self.live = live;
        let first = self.nodes.len();
        self.nodes.extend(cells.iter().map(|&cell| Node {
            cell,
            kind: Kind::Leaf { start: 0, len: 0 },
        }));
        self.nodes[at].kind = Kind::Inner {
            first: first as u32,
        };
        Some(
            parts
                .into_iter()
                .enumerate()
                .map(|(i, part)| (first + i, part))
                .collect(),
        )
    }

    /// Makes node `at` a leaf listing `prims`.
    fn leaf(&mut self, at: usize, prims: &[u32]) {
        let start = self.entries.len() as u32;
        self.entries.extend_from_slice(prims);
        self.nodes[at].kind = Kind::Leaf {
            start,
            len: prims.len() as u32,
        };
    }
}

/// The eight children of a cell, split at its mid-point; the children share
/// that one mid-point, so together they cover the cell exactly.
fn octants(cell: &Bounds) -> [Bounds; 8] {
    let mid = cell.center();
    std::array::from_fn(|i| {
        let upper = BVec3::new(i & 1 != 0, i & 2 != 0, i & 4 != 0);
        Bounds {
            min: DVec3::select(upper, mid, cell.min),
            max: DVec3::select(upper, cell.max, mid),
        }
    })
}

/// Whether two closed boxes share a point (touching counts).
fn overlaps(a: &Bounds, b: &Bounds) -> bool {
    a.min.cmple(b.max).all() && a.max.cmpge(b.min).all()
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

#[cfg(test)]
#[path = "octree_tests.rs"]
mod tests;
