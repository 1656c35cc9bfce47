//! An octree: the lecture's other way to avoid intersection tests. The scene's
//! box, made a cube, is split into eight equal children, and each child again,
//! until a cell holds few primitives. A primitive is listed in every cell its box
//! touches, so a ray only needs the primitives of the cells it passes through,
//! nearest cell first.
//!
//! **Build.** A node becomes a leaf when it holds at most [`LEAF_SIZE`]
//! primitives, when it is [`MAX_DEPTH`] levels deep, when splitting would not
//! make its fullest child hold fewer primitives than it does (every primitive
//! overlaps every child: splitting again would only copy the list eight times,
//! level after level), or when the split would take the entries of all leaves
//! past [`Octree::entry_cap`]. A primitive goes into every child whose closed
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

use std::collections::HashSet;
use std::ops::ControlFlow;

use arrayvec::ArrayVec;
use glam::{BVec3, DVec3};

use crate::geometry::hit::TestCounts;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

/// A node with at most this many primitives is not split: testing eight
/// primitives costs about as much as testing a node's eight children.
pub const LEAF_SIZE: usize = 8;

/// Nodes this deep are not split. A cell is then 1/1024 of the scene's side
/// (up to 8¹⁰ ≈ 10⁹ cells): finer cells rarely separate primitives that coarser
/// ones could not, only copying their lists, and the depth bounds the stack.
pub const MAX_DEPTH: u32 = 10;

/// Room on the traversal stack: at most seven children pushed per level (eight
/// met, the nearest walked into), one level below another.
const STACK: usize = 7 * (MAX_DEPTH as usize + 1) + 1;

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
}

impl Octree {
    /// The most entries the leaves may hold together over `n` primitives,
    /// `16·n + 1024`: a split that would go beyond it is not made, so memory
    /// stays linear in the scene whatever the boxes' overlap.
    pub fn entry_cap(n: usize) -> usize {
        16 * n + 1024
    }

    /// Builds the octree over primitives with these (finite, non-empty) bounds.
    pub fn build(bounds: &[Bounds]) -> Octree {
        let n = bounds.len();
        if n == 0 {
            return Octree {
                nodes: Vec::new(),
                entries: Vec::new(),
                primitives: 0,
                depth: 0,
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
            depth: 0,
        };
        builder.node(0, (0..n as u32).collect(), 0);
        Octree {
            nodes: builder.nodes,
            entries: builder.entries,
            primitives: n,
            depth: builder.depth,
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
        let mut mailbox = Mailbox::default();
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
                        if mailbox.first_visit(p) {
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
            MAX_DEPTH,
            side,
            side / f64::from(1u32 << self.depth),
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
    depth: u32,
}

impl Builder<'_> {
    /// Makes node `at` (its cell already set) over `prims`, `depth` levels down.
    fn node(&mut self, at: usize, prims: Vec<u32>, depth: u32) {
        self.depth = self.depth.max(depth);
        if prims.len() > LEAF_SIZE && depth < MAX_DEPTH {
            let cells = octants(&self.nodes[at].cell);
            let parts: [Vec<u32>; 8] = cells.map(|cell| {
                prims
                    .iter()
                    .copied()
                    .filter(|&p| overlaps(&self.boxes[p as usize], &cell))
                    .collect()
            });
            let fullest = parts.iter().map(Vec::len).max().unwrap_or(0);
            let live = self.live - prims.len() + parts.iter().map(Vec::len).sum::<usize>();
            if fullest < prims.len() && live <= self.cap {
                self.live = live;
                let first = self.nodes.len();
                self.nodes.extend(cells.iter().map(|&cell| Node {
                    cell,
                    kind: Kind::Leaf { start: 0, len: 0 },
                }));
                self.nodes[at].kind = Kind::Inner {
                    first: first as u32,
                };
                drop(prims);
                for (i, part) in parts.into_iter().enumerate() {
                    self.node(first + i, part, depth + 1);
                }
                return;
            }
        }
        let start = self.entries.len() as u32;
        self.entries.extend_from_slice(&prims);
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

/// The primitives one traversal has visited: a short list searched in place,
/// and a hash set once a ray has met more than it holds. Local to the call, so
/// the octree stays shareable between threads and a `visit` may traverse
/// another structure (or this one) without confusing the marks.
#[derive(Default)]
struct Mailbox {
    recent: ArrayVec<u32, 32>,
    more: Option<HashSet<u32>>,
}

impl Mailbox {
    /// Marks `p`, returning whether it was unmarked.
    #[inline]
    fn first_visit(&mut self, p: u32) -> bool {
        if self.recent.contains(&p) {
            return false;
        }
        if self.recent.try_push(p).is_ok() {
            return true;
        }
        self.more.get_or_insert_with(HashSet::new).insert(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(at: DVec3, half: f64) -> Bounds {
        Bounds {
            min: at - half,
            max: at + half,
        }
    }

    /// Every primitive visited with an infinite, never-shrunk `t_max`, in order;
    /// and the traversal steps.
    fn walk(tree: &Octree, ray: &Ray, t_min: f64) -> (Vec<usize>, u32) {
        let mut visited = Vec::new();
        let mut tested = TestCounts::default();
        let flow = tree.traverse_seeing(
            ray,
            t_min,
            &mut { f64::INFINITY },
            &mut tested,
            |_, _| {},
            |p, _| {
                visited.push(p);
                ControlFlow::Continue(())
            },
        );
        assert_eq!(flow, ControlFlow::Continue(()));
        (visited, tested.boxes)
    }

    fn point(rng: &mut fastrand::Rng, lo: f64, hi: f64) -> DVec3 {
        DVec3::new(rng.f64(), rng.f64(), rng.f64()) * (hi - lo) + lo
    }

    /// A scene in the cube [0, 64]³ (one box is that cube, so cell planes fall
    /// on multiples of 64/2^k): many small boxes, a third of them on a grid of
    /// 0.5 so their faces lie in cell planes; a few huge ones; flat ones (half of
    /// them in the planes of the coarsest cells); single
    /// points; and copies of earlier boxes.
    fn mixed_scene(rng: &mut fastrand::Rng) -> Vec<Bounds> {
        let mut boxes = vec![Bounds {
            min: DVec3::ZERO,
            max: DVec3::splat(64.0),
        }];
        for i in 0..2600 {
            let mut min = point(rng, 0.0, 63.0);
            let mut size = point(rng, 0.01, 1.0);
            if i % 3 == 0 {
                min = (min * 2.0).floor() / 2.0;
                size = DVec3::splat(0.5);
            }
            boxes.push(Bounds {
                min,
                max: min + size,
            });
        }
        for _ in 0..10 {
            let min = point(rng, 0.0, 32.0);
            let max = (min + point(rng, 10.0, 60.0)).min(DVec3::splat(64.0));
            boxes.push(Bounds { min, max });
        }
        for i in 0..200 {
            let mut min = point(rng, 0.0, 60.0);
            let mut max = min + point(rng, 0.1, 4.0);
            if i % 2 == 0 {
                // In a plane of the coarse cells, as a floor or a wall may be.
                min[i % 3] = (min[i % 3] / 8.0).round() * 8.0;
            }
            max[i % 3] = min[i % 3];
            boxes.push(Bounds { min, max });
        }
        for _ in 0..20 {
            let p = point(rng, 0.0, 64.0);
            boxes.push(Bounds { min: p, max: p });
        }
        for _ in 0..150 {
            let b = boxes[rng.usize(..boxes.len())];
            boxes.push(b);
        }
        // Last, small cubes with a corner on a corner or an edge of the root,
        // which no cell outside the root shares.
        for i in 0..CORNERED {
            let mut c = DVec3::new(
                [0.0, 64.0][rng.usize(..2)],
                [0.0, 64.0][rng.usize(..2)],
                [0.0, 64.0][rng.usize(..2)],
            );
            if i % 2 == 0 {
                c[i % 3] = rng.f64() * 60.0 + 2.0;
            }
            let min = DVec3::select(c.cmpeq(DVec3::splat(64.0)), c - 0.5, c);
            boxes.push(Bounds {
                min,
                max: min + 0.5,
            });
        }
        boxes
    }

    /// How many boxes end [`mixed_scene`] with a corner on the root's surface.
    const CORNERED: usize = 40;

    /// A ray of one of several awkward kinds (`case` picks), over `boxes`.
    fn awkward_ray(rng: &mut fastrand::Rng, boxes: &[Bounds], case: usize) -> Ray {
        let b = boxes[rng.usize(..boxes.len())];
        let corner = |rng: &mut fastrand::Rng| {
            DVec3::new(
                [b.min.x, b.max.x][rng.usize(..2)],
                [b.min.y, b.max.y][rng.usize(..2)],
                [b.min.z, b.max.z][rng.usize(..2)],
            )
        };
        let outside = |rng: &mut fastrand::Rng| {
            let d = point(rng, -1.0, 1.0).normalize_or(DVec3::X);
            DVec3::splat(32.0) + 150.0 * d
        };
        let axis = rng.usize(..3);
        let sign = if rng.bool() { 1.0 } else { -1.0 };
        let zero = if rng.bool() { 0.0 } else { -0.0 };
        match case % 8 {
            // From inside, anywhere.
            0 => Ray::new(point(rng, 0.0, 64.0), point(rng, -1.0, 1.0)),
            // From outside, aimed inside.
            1 => {
                let o = outside(rng);
                Ray::new(o, point(rng, 0.0, 64.0) - o)
            }
            // Along an axis, the other coordinates on the 0.5 grid (in cell
            // planes and grid boxes' faces), from inside or outside.
            2 => {
                let mut o = (point(rng, -8.0, 72.0) * 2.0).floor() / 2.0;
                o[axis] = rng.f64() * 200.0 - 68.0;
                let mut dir = DVec3::splat(zero);
                dir[axis] = sign;
                Ray::new(o, dir)
            }
            // In the plane of a box's face, grazing it.
            3 => {
                let mut o = point(rng, -10.0, 74.0);
                o[axis] = [b.min[axis], b.max[axis]][rng.usize(..2)];
                let mut dir = point(rng, -1.0, 1.0);
                dir[axis] = zero;
                Ray::new(o, dir)
            }
            // At a box's corner, from inside or outside.
            4 => {
                let o = if rng.bool() {
                    outside(rng)
                } else {
                    point(rng, 0.0, 64.0)
                };
                Ray::new(o, corner(rng) - o)
            }
            // Along a box's edge: from beside a corner, parallel to an axis.
            5 => {
                let mut o = corner(rng);
                o[axis] -= sign * rng.f64() * 100.0;
                let mut dir = DVec3::splat(zero);
                dir[axis] = sign;
                Ray::new(o, dir)
            }
            // Touching a box at one corner only, on the root's surface: along
            // one axis the ray leaves the box and the root beyond the corner,
            // along another before it, so the ray meets every cell holding the
            // box at that point only, rounding decides, and the widening must
            // keep the cells.
            6 => {
                let b = boxes[boxes.len() - 1 - rng.usize(..CORNERED)];
                let c = DVec3::select(b.max.cmpeq(DVec3::splat(64.0)), b.max, b.min);
                let away = |i: usize| if c[i] == b.max[i] { 1.0 } else { -1.0 };
                let (i, j) = (axis, (axis + 1) % 3);
                let mut dir = point(rng, -1.0, 1.0);
                dir[i] = away(i) * (0.1 + rng.f64());
                dir[j] = -away(j) * (0.1 + rng.f64());
                Ray::new(c - (1.0 + 99.0 * rng.f64()) * dir, dir)
            }
            // Through a box's corner and the scene's centre, not axis-parallel.
            _ => {
                let c = corner(rng);
                Ray::new(c, DVec3::splat(32.0) - c + point(rng, -1e-9, 1e-9))
            }
        }
    }

    /// The reference: whether the ray meets the closed box at some `t ≥ t_min`,
    /// decided exactly for the axes the ray is parallel to, and by an `f64` slab
    /// test widened by 8ε (above its own rounding, about γ(4) ≈ 2ε, and below the
    /// octree's 32ε) for the others. (Not [`crate::math::bounds::RayBox::hits`]: a ray
    /// parallel to one slab and outside it, lying in the plane of another, gives
    /// it a NaN that its `min_element` lets through as a hit.)
    fn meets(ray: &Ray, b: &Bounds, t_min: f64) -> bool {
        let (mut enter, mut leave) = (t_min, f64::INFINITY);
        for axis in 0..3 {
            let (o, d) = (ray.origin[axis], ray.dir[axis]);
            if d == 0.0 {
                if o < b.min[axis] || o > b.max[axis] {
                    return false;
                }
                continue;
            }
            let t0 = (b.min[axis] - o) / d;
            let t1 = (b.max[axis] - o) / d;
            enter = enter.max(t0.min(t1));
            leave = leave.min(t0.max(t1));
        }
        enter <= leave + leave.abs() * 8.0 * f64::EPSILON
    }

    /// Can fail if rounding in the slab test or the cell split loses a cell the
    /// ray touches (a grazing ray, one in a cell plane, an axis-parallel one with
    /// its ±∞ and NaN parameters, a flat or point box), if a primitive is not
    /// listed in every cell its box touches, or if the mailbox lets one through
    /// twice. The reference is [`meets`].
    #[test]
    fn visits_every_primitive_the_ray_meets_exactly_once() {
        let mut rng = fastrand::Rng::with_seed(28);
        let boxes = mixed_scene(&mut rng);
        let tree = Octree::build(&boxes);
        assert!(tree.depth >= 3, "{}", tree.describe());
        let (mut met_total, mut visited_total) = (0, 0);
        for case in 0..8000 {
            let ray = awkward_ray(&mut rng, &boxes, case);
            let t_min = if case % 4 == 3 { rng.f64() * 0.5 } else { 0.0 };
            let (visited, _) = walk(&tree, &ray, t_min);
            let mut sorted = visited.clone();
            sorted.sort_unstable();
            sorted.dedup();
            assert_eq!(sorted.len(), visited.len(), "a primitive twice: {ray:?}");
            for (i, b) in boxes.iter().enumerate() {
                if meets(&ray, b, t_min) {
                    met_total += 1;
                    assert!(
                        sorted.binary_search(&i).is_ok(),
                        "case {case}: primitive {i} {b:?} missed by {ray:?} from {t_min}"
                    );
                }
            }
            visited_total += visited.len();
        }
        // Not vacuous, and not everything every time.
        assert!(met_total > 10_000, "{met_total}");
        assert!(
            visited_total < 8000 * boxes.len() / 2,
            "{visited_total} of {}",
            8000 * boxes.len()
        );
    }

    /// The nearest root of a sphere beyond `t_min`.
    fn sphere_hit(center: DVec3, radius: f64, ray: &Ray, t_min: f64) -> Option<f64> {
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

    /// Can fail if a closer sphere sits in a cell the walk skipped because a
    /// farther hit had shrunk `t_max` (cells out of order, or `reach` not
    /// widened enough), or if the walk stops early.
    #[test]
    fn closest_hit_matches_testing_every_sphere() {
        let mut rng = fastrand::Rng::with_seed(5);
        let spheres: Vec<(DVec3, f64)> = (0..2000)
            .map(|i| {
                let r = if i % 100 == 0 {
                    5.0 + rng.f64() * 15.0
                } else {
                    0.2 + rng.f64() * 2.0
                };
                (point(&mut rng, 0.0, 100.0), r)
            })
            .collect();
        // Padded by a hair: the rounded `c ± r` may fall just inside the sphere.
        let boxes: Vec<Bounds> = spheres
            .iter()
            .map(|&(c, r)| cube(c, r + 1e-9 * (c.abs().max_element() + r)))
            .collect();
        let tree = Octree::build(&boxes);
        let mut hits = 0;
        for case in 0..4000 {
            let origin = if case % 2 == 0 {
                point(&mut rng, 0.0, 100.0)
            } else {
                point(&mut rng, -200.0, 300.0)
            };
            let mut dir = point(&mut rng, 0.0, 100.0) - origin;
            if case % 10 == 0 {
                dir = DVec3::ZERO;
                dir[case / 10 % 3] = 1.0;
            }
            let ray = Ray::new(origin, dir);
            let t_min = 1e-9;
            let mut brute = (None, f64::INFINITY);
            for (i, &(c, r)) in spheres.iter().enumerate() {
                if let Some(t) = sphere_hit(c, r, &ray, t_min).filter(|&t| t < brute.1) {
                    brute = (Some(i), t);
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
                    let (c, r) = spheres[p];
                    if let Some(t) = sphere_hit(c, r, &ray, t_min).filter(|&t| t < *t_max) {
                        *t_max = t;
                        found = Some(p);
                    }
                    ControlFlow::Continue(())
                },
            );
            assert_eq!((found, t_max), brute, "case {case}: {ray:?}");
            hits += usize::from(found.is_some());
        }
        assert!(hits > 1000, "{hits}");
    }

    /// A row of 100 small cubes along x, and a ray down the row.
    fn row() -> (Vec<Bounds>, Ray) {
        let boxes = (0..100)
            .map(|i| cube(DVec3::new(f64::from(i), 0.0, 0.0), 0.25))
            .collect();
        (boxes, Ray::new(DVec3::new(-1.0, 0.01, -0.02), DVec3::X))
    }

    /// Can fail if the walk goes on after a break, or ignores a shrunk `t_max`
    /// (popping cells entered beyond it), or visits cells out of order.
    #[test]
    fn breaking_and_shrinking_stop_the_walk() {
        let (boxes, ray) = row();
        let tree = Octree::build(&boxes);
        let mut visited = 0;
        let flow = tree.traverse_seeing(
            &ray,
            0.0,
            &mut { f64::INFINITY },
            &mut TestCounts::default(),
            |_, _| {},
            |_, _| {
                visited += 1;
                ControlFlow::Break(())
            },
        );
        assert_eq!((flow, visited), (ControlFlow::Break(()), 1));

        // Every cube, front to back.
        let (all, full_steps) = walk(&tree, &ray, 0.0);
        assert_eq!(all, (0..100).collect::<Vec<_>>());

        // A closest-hit search: the first cube is hit at t = 0.75.
        let mut t_max = f64::INFINITY;
        let mut tested = TestCounts::default();
        let mut visited = Vec::new();
        let _ = tree.traverse_seeing(
            &ray,
            0.0,
            &mut t_max,
            &mut tested,
            |_, _| {},
            |p, t_max| {
                visited.push(p);
                let t = boxes[p].min.x - ray.origin.x;
                if t < *t_max {
                    *t_max = t;
                }
                ControlFlow::Continue(())
            },
        );
        assert_eq!(t_max, 0.75);
        assert!(visited.len() <= LEAF_SIZE, "{visited:?}");
        assert!(
            tested.boxes * 5 < full_steps,
            "{} steps against {full_steps}",
            tested.boxes
        );
    }

    /// Can fail if an empty tree is walked (index 0 of no nodes) or a single
    /// primitive's degenerate cube (here flat) loses it.
    #[test]
    fn empty_and_single() {
        let empty = Octree::build(&[]);
        let ray = Ray::new(DVec3::ZERO, DVec3::ONE);
        assert_eq!(walk(&empty, &ray, 0.0), (vec![], 0));
        assert_eq!(empty.describe(), "octree: empty");

        let flat = Bounds {
            min: DVec3::new(1.0, 2.0, 3.0),
            max: DVec3::new(2.0, 2.0, 4.0),
        };
        let one = Octree::build(&[flat]);
        let down = Ray::new(DVec3::new(1.5, 5.0, 3.5), DVec3::NEG_Y);
        assert_eq!(walk(&one, &down, 0.0), (vec![0], 1));
        let beside = Ray::new(DVec3::new(2.5, 5.0, 3.5), DVec3::NEG_Y);
        assert_eq!(walk(&one, &beside, 0.0).0, vec![] as Vec<usize>);
        let behind = Ray::new(DVec3::new(1.5, 5.0, 3.5), DVec3::Y);
        assert_eq!(walk(&one, &behind, 0.0).0, vec![] as Vec<usize>);
        assert!(
            one.describe().contains("1 primitives"),
            "{}",
            one.describe()
        );
    }

    /// Can fail if splitting goes on when it cannot separate the primitives (a
    /// pile of copies would be listed 8¹⁰ times), or the entry cap is ignored.
    #[test]
    fn memory_stays_bounded() {
        let pile = vec![cube(DVec3::ONE, 1.0); 500];
        let tree = Octree::build(&pile);
        assert_eq!((tree.nodes.len(), tree.entries.len()), (1, 500));

        // Long thin boxes crossing one another: each split separates them a
        // little, so only the cap and the depth stop it.
        let mut rng = fastrand::Rng::with_seed(3);
        let sticks: Vec<Bounds> = (0..3000)
            .map(|i| {
                let mut min = point(&mut rng, 0.0, 100.0);
                let mut max = min + 0.01;
                min[i % 3] = 0.0;
                max[i % 3] = 100.0;
                Bounds { min, max }
            })
            .collect();
        let tree = Octree::build(&sticks);
        assert!(tree.entries.len() <= Octree::entry_cap(3000));
        assert!(tree.depth <= MAX_DEPTH);
        let mut listed: Vec<u32> = tree.entries.clone();
        listed.sort_unstable();
        listed.dedup();
        assert_eq!(listed, (0..3000).collect::<Vec<u32>>());
    }
}
