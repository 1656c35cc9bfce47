//! A bounding volume hierarchy: the lecture's "avoid intersection tests". Objects
//! (or a mesh's triangles) are grouped into nested boxes; a ray that misses a box
//! skips everything inside it, so a ray costs about `log n` box tests instead of
//! `n` object tests.
//!
//! Each node has up to [`WIDTH`] children (Wald et al., "Getting Rid of Packets",
//! 2008; Embree's BVH4): one visit tests four boxes at once with SIMD, and the
//! tree is half as deep as a binary one. It is built with the binned surface
//! area heuristic, on all cores ([`crate::geometry::bvh_build`]). Traversal
//! visits the boxes a ray meets nearest first, so a closest-hit search shrinks
//! its interval early and skips boxes beyond the hit it has.
//!
//! The boxes are stored in single precision, rounded outward, which halves the
//! memory a ray walks through; primitives stay in double precision. The box test
//! is made robust in the manner of Ize ("Robust BVH Ray Traversal", JCGT 2013):
//! every rounding of the single-precision test is bounded, and the interval is
//! widened by that bound, so a ray that meets a box in exact arithmetic is never
//! culled ([`RayBox4`]).

use std::ops::ControlFlow;

use glam::DVec3;
use wide::f32x4;

use crate::geometry::bvh_build;
use crate::geometry::hit::TestCounts;
use crate::math::bounds::{Bounds, RayBox};

/// Leaves hold at most this many primitives.
pub const MAX_LEAF: usize = 4;
/// Children per node.
pub const WIDTH: usize = 4;
/// Room on the traversal stack: up to `WIDTH - 1` entries per level, and a tree
/// is at most `SAH_MAX_DEPTH` + log₄(2²⁸) levels deep.
const STACK: usize = (WIDTH - 1) * (bvh_build::SAH_MAX_DEPTH as usize + 16);

/// A child of a node: an inner node (its index) or a leaf (a run of primitives
/// in `order`), packed in 32 bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Child(pub(crate) u32);

const LEAF_BIT: u32 = 1 << 31;
const COUNT_SHIFT: u32 = 28;
/// Leaves can start anywhere below this index.
pub(crate) const MAX_PRIMITIVES: usize = 1 << COUNT_SHIFT;

impl Child {
    pub(crate) fn inner(node: usize) -> Child {
        Child(node as u32)
    }

    pub(crate) fn leaf(first: usize, count: usize) -> Child {
        debug_assert!((1..=MAX_LEAF).contains(&count) && first < MAX_PRIMITIVES);
        Child(LEAF_BIT | ((count as u32 - 1) << COUNT_SHIFT) | first as u32)
    }

    pub(crate) fn is_leaf(self) -> bool {
        self.0 & LEAF_BIT != 0
    }

    /// A leaf's primitives as a range of `order`.
    fn primitives(self) -> std::ops::Range<usize> {
        let first = (self.0 & (MAX_PRIMITIVES as u32 - 1)) as usize;
        let count = ((self.0 & !LEAF_BIT) >> COUNT_SHIFT) as usize + 1;
        first..first + count
    }
}

/// One node: the boxes of up to four children, lane by lane (`bounds[0]` the
/// lower corners, `bounds[1]` the upper, each as x, y, z rows of four lanes),
/// rounded outward to `f32`. Unused lanes hold an empty box, which no ray meets.
/// Two cache lines.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct Node {
    bounds: [[f32x4; 3]; 2],
    pub(crate) children: [Child; WIDTH],
    /// Children in use (the first `len` lanes).
    pub(crate) len: u8,
}

impl Node {
    /// The box of lane `lane`, as stored (rounded outward).
    fn lane(&self, lane: usize) -> Bounds {
        let corner = |c: usize| {
            DVec3::new(
                f64::from(self.bounds[c][0].to_array()[lane]),
                f64::from(self.bounds[c][1].to_array()[lane]),
                f64::from(self.bounds[c][2].to_array()[lane]),
            )
        };
        Bounds {
            min: corner(0),
            max: corner(1),
        }
    }

    /// A node with no children yet: every lane an empty box.
    pub(crate) fn empty() -> Node {
        Node {
            bounds: [
                [f32x4::splat(f32::INFINITY); 3],
                [f32x4::splat(f32::NEG_INFINITY); 3],
            ],
            children: [Child(0); WIDTH],
            len: 0,
        }
    }
}

/// A hierarchy over primitives `0..n`, known by their bounding boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// The root is node 0, if there are any primitives.
    nodes: Vec<Node>,
    /// Primitive indices, leaf by leaf.
    order: Vec<u32>,
    /// The box around everything, in full precision.
    bounds: Bounds,
}

impl Bvh {
    /// Builds the hierarchy over primitives with these (non-empty) bounds (see
    /// [`crate::geometry::bvh_build`]).
    pub fn build(bounds: &[Bounds]) -> Bvh {
        let (nodes, order, bounds) = bvh_build::build(bounds);
        Bvh {
            nodes,
            order,
            bounds,
        }
    }

    /// The primitives as the leaves list them, leaf by leaf.
    pub fn leaf_order(&self) -> &[u32] {
        &self.order
    }

    /// Renames the primitives: leaf entry `i` becomes `name(i)`, so a hierarchy
    /// built over a subset can hand out the indices the caller uses, with no
    /// second lookup per visit.
    pub fn relabel(&mut self, name: impl Fn(u32) -> u32) {
        for p in &mut self.order {
            *p = name(*p);
        }
    }

    /// Bytes the flattened tree occupies.
    pub fn memory(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.order.len() * 4
    }

    /// Nodes in the tree (each with up to [`WIDTH`] boxes).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// The box around everything.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }

    /// Calls `visit(primitive, t_max)` for every primitive in a leaf whose box the
    /// ray meets within `(t_min, *t_max)`, nearer boxes first. `visit` may shrink
    /// `t_max` (a closest-hit search) or break (a shadow ray's any-hit). Every box
    /// tested is counted in `tested` (four to a node, less in a node not full).
    #[inline]
    pub fn traverse(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.traverse_seeing(ray, t_min, t_max, tested, |_, _| {}, visit)
    }

    /// [`Bvh::traverse`], also calling `seen(bounds, met)` for every box tested
    /// (as stored, rounded outward) and whether the ray met it: what a recorded
    /// ray keeps so a diagram can draw the boxes it visited. With a `seen` that
    /// does nothing, this is `traverse` exactly.
    #[inline]
    pub fn traverse_seeing(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
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
                for &p in &self.order[at.primitives()] {
                    visit(p as usize, t_max)?;
                }
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
                    sort_descending(&mut near[..n]);
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

/// Up to four (entry, child) pairs sorted by entry, farthest first (insertion sort).
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

/// Stores `b` in lane `lane` of the node, rounded outward to `f32`.
pub(crate) fn set_lane(node: &mut Node, lane: usize, b: &Bounds) {
    for axis in 0..3 {
        let mut lo = node.bounds[0][axis].to_array();
        let mut hi = node.bounds[1][axis].to_array();
        lo[lane] = round_down(b.min[axis]);
        hi[lane] = round_up(b.max[axis]);
        node.bounds[0][axis] = f32x4::from(lo);
        node.bounds[1][axis] = f32x4::from(hi);
    }
}

/// The largest `f32` at most `x` (−∞ below the `f32` range).
fn round_down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x { f.next_down() } else { f }
}

/// The smallest `f32` at least `x` (+∞ above the `f32` range).
fn round_up(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x { f.next_up() } else { f }
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
    fn reach(t_max: f64) -> f32 {
        const GAMMA4: f32 = 4.0 * f32::EPSILON * 0.5 / (1.0 - 4.0 * f32::EPSILON * 0.5);
        (t_max as f32) * (1.0 + 4.0 * f32::EPSILON) * (1.0 + 2.0 * GAMMA4)
    }

    /// Which of the node's four boxes the ray meets within `(t_min, t_max)` (bit
    /// `i` for lane `i`), and where it enters each; `reach` is [`RayBox4::reach`]
    /// of `t_max`. A NaN distance (a ray lying in a slab's plane) is skipped by
    /// `max` and `min`, so that slab keeps the box.
    #[inline]
    fn hits(&self, node: &Node, t_min: f32, reach: f32) -> (u32, [f32; WIDTH]) {
        const GAMMA4: f32 = 4.0 * f32::EPSILON * 0.5 / (1.0 - 4.0 * f32::EPSILON * 0.5);
        let mut enter = f32x4::splat(t_min);
        let mut leave = f32x4::splat(f32::INFINITY);
        for axis in 0..3 {
            let near = node.bounds[self.near[axis]][axis];
            let far = node.bounds[1 - self.near[axis]][axis];
            let t0 = (near - self.origin_near[axis]) * self.inv_dir[axis];
            let t1 = (far - self.origin_far[axis]) * self.inv_dir[axis];
            enter = enter.max(t0);
            leave = leave.min(t1);
        }
        let leave = (leave * f32x4::splat(1.0 + 2.0 * GAMMA4)).min(f32x4::splat(reach));
        (enter.simd_le(leave).to_bitmask(), enter.to_array())
    }
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
    use crate::math::ray::Ray;
    use glam::DVec3;

    fn cube(at: DVec3) -> Bounds {
        Bounds {
            min: at - 0.25,
            max: at + 0.25,
        }
    }

    /// 1,000 small cubes on a 10 × 10 × 10 grid of spacing 1.
    fn ten_by_ten_by_ten() -> Vec<Bounds> {
        (0..1000)
            .map(|i| {
                cube(DVec3::new(
                    (i % 10) as f64,
                    (i / 10 % 10) as f64,
                    (i / 100) as f64,
                ))
            })
            .collect()
    }

    /// Every primitive a brute-force slab test says the ray meets.
    fn met(boxes: &[Bounds], ray: &Ray) -> Vec<usize> {
        let rb = RayBox::new(ray);
        (0..boxes.len())
            .filter(|&i| rb.hits(&boxes[i], 0.0, f64::INFINITY))
            .collect()
    }

    #[test]
    fn every_primitive_is_in_exactly_one_leaf() {
        let boxes = ten_by_ten_by_ten();
        let bvh = Bvh::build(&boxes);
        let mut seen = bvh.order.clone();
        seen.sort_unstable();
        assert_eq!(seen, (0..1000).collect::<Vec<u32>>());
        for node in &bvh.nodes {
            for c in &node.children[..usize::from(node.len)] {
                assert!(!c.is_leaf() || c.primitives().len() <= MAX_LEAF);
            }
        }
    }

    #[test]
    fn traversal_visits_every_box_the_ray_meets_and_few_others() {
        let boxes = ten_by_ten_by_ten();
        let bvh = Bvh::build(&boxes);
        let ray = Ray::new(DVec3::new(-1.0, 4.1, 3.9), DVec3::new(1.0, 0.01, 0.02));
        let mut visited = Vec::new();
        let mut tested = TestCounts::default();
        let _ = bvh.traverse(
            &RayBox::new(&ray),
            0.0,
            &mut { f64::INFINITY },
            &mut tested,
            |p, _| {
                visited.push(p);
                ControlFlow::Continue(())
            },
        );
        let expected = met(&boxes, &ray);
        assert!(!expected.is_empty());
        for p in &expected {
            assert!(visited.contains(p), "primitive {p} was skipped");
        }
        // One row of ten cubes: the hierarchy should look at far fewer than 1000.
        assert!(
            visited.len() < 50 && tested.boxes < 200,
            "{visited:?} {tested:?}"
        );
    }

    /// The single-precision test keeps every box the double-precision one does
    /// (which is exact but for a widening of a few ULPs of f64), at every scale,
    /// for rays aimed right at corners and edges, starting on faces, or parallel
    /// to an axis, and for boxes flat in one axis.
    #[test]
    fn single_precision_boxes_lose_no_hit() {
        let mut rng = fastrand::Rng::with_seed(7);
        let mut kept_more = 0;
        for scale in [1e-3, 1.0, 1e4, 1e7] {
            for case in 0..20_000 {
                let at = |r: &mut fastrand::Rng| {
                    DVec3::new(r.f64(), r.f64(), r.f64()) * 2.0 * scale - scale
                };
                let (a, b) = (at(&mut rng), at(&mut rng));
                let mut bounds = Bounds {
                    min: a.min(b),
                    max: a.max(b),
                };
                if case % 7 == 0 {
                    bounds.max.y = bounds.min.y;
                }
                let corner = DVec3::new(
                    [bounds.min.x, bounds.max.x][case % 2],
                    [bounds.min.y, bounds.max.y][case / 2 % 2],
                    [bounds.min.z, bounds.max.z][case / 4 % 2],
                );
                let mut origin = at(&mut rng) * 3.0;
                if case % 5 == 0 {
                    origin.x = bounds.min.x;
                }
                let mut dir = match case % 3 {
                    0 => corner - origin,
                    1 => 0.5 * (corner + bounds.center()) - origin,
                    _ => at(&mut rng),
                };
                if case % 11 == 0 {
                    dir.z = 0.0;
                }
                let ray = RayBox::new(&Ray::new(origin, dir));
                let mut node = Node {
                    bounds: [
                        [f32x4::splat(f32::INFINITY); 3],
                        [f32x4::splat(f32::NEG_INFINITY); 3],
                    ],
                    children: [Child(0); WIDTH],
                    len: 1,
                };
                set_lane(&mut node, 0, &bounds);
                let t_max = if case % 4 == 0 {
                    f64::INFINITY
                } else {
                    rng.f64() * 4.0
                };
                let exact = ray.hits(&bounds, 0.0, t_max);
                let (mask, _) = RayBox4::new(&ray).hits(&node, 0.0, RayBox4::reach(t_max));
                assert!(
                    !exact || mask == 1,
                    "box {bounds:?} lost: ray {origin} + t·{dir}, t < {t_max}"
                );
                kept_more += usize::from(!exact && mask == 1);
            }
        }
        // Conservative, but not by much: the widening admits few extra boxes.
        assert!(kept_more < 800, "{kept_more} of 80,000 kept without need");
    }

    #[test]
    fn empty_lanes_are_never_hit() {
        let node = Node {
            bounds: [
                [f32x4::splat(f32::INFINITY); 3],
                [f32x4::splat(f32::NEG_INFINITY); 3],
            ],
            children: [Child(0); WIDTH],
            len: 0,
        };
        for dir in [
            DVec3::X,
            DVec3::NEG_Y,
            DVec3::new(0.0, -0.0, 1.0),
            DVec3::ONE,
        ] {
            let ray = RayBox::new(&Ray::new(DVec3::ZERO, dir));
            let (mask, _) = RayBox4::new(&ray).hits(&node, 0.0, f32::INFINITY);
            assert_eq!(mask, 0, "{dir}");
        }
    }

    #[test]
    fn breaking_stops_the_traversal() {
        let boxes: Vec<Bounds> = (0..100)
            .map(|i| cube(DVec3::new(i as f64, 0.0, 0.0)))
            .collect();
        let bvh = Bvh::build(&boxes);
        let ray = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
        let mut visited = 0;
        let flow = bvh.traverse(
            &RayBox::new(&ray),
            0.0,
            &mut { f64::INFINITY },
            &mut TestCounts::default(),
            |_, _| {
                visited += 1;
                ControlFlow::Break(())
            },
        );
        assert_eq!((flow, visited), (ControlFlow::Break(()), 1));
    }
}
