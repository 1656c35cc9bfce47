//! A bounding volume hierarchy: the lecture's "avoid intersection tests". Objects
//! (or a mesh's triangles) are grouped into nested boxes; a ray that misses a box
//! skips everything inside it, so a ray costs about `log n` box tests instead of
//! `n` object tests.
//!
//! Built top-down with the binned surface area heuristic (Wald, "On fast
//! Construction of SAH-based Bounding Volume Hierarchies", 2007; pbrt-v4 §7.3.2):
//! each split is the one of [`BINS`] candidate planes along the widest axis of the
//! centroids that minimizes the expected cost of a random ray, and a node stays a
//! leaf when no split is expected to pay for its extra box test. Flattened
//! depth-first into one array (pbrt's `LinearBVHNode`): a node's first child
//! follows it, the second is named by index, and traversal visits the child
//! nearer the ray first so the closest hit shrinks the interval early.

use std::ops::ControlFlow;

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::math::bounds::{Bounds, RayBox};

/// Candidate split planes per node.
pub const BINS: usize = 16;
/// Leaves hold at most this many primitives.
pub const MAX_LEAF: usize = 4;
/// Cost of a box test relative to a primitive test, for the heuristic.
const TRAVERSAL_COST: f64 = 0.5;

/// One node of the flattened tree, aligned to a cache line so visiting a node
/// never waits for two lines from memory (56 bytes would straddle half of them).
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(align(64))]
struct Node {
    bounds: Bounds,
    /// Leaf: first index into `order`. Interior: index of the second child.
    offset: u32,
    /// Primitives in a leaf; 0 for an interior node.
    count: u16,
    /// Interior: the axis it was split on.
    axis: u8,
}

/// A hierarchy over primitives `0..n`, known by their bounding boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Primitive indices, leaf by leaf.
    order: Vec<u32>,
}

/// A primitive while building: its box and its box's center.
#[derive(Clone, Copy)]
struct Item {
    bounds: Bounds,
    centroid: DVec3,
    index: u32,
}

impl Bvh {
    /// Builds the hierarchy over primitives with these (non-empty) bounds.
    pub fn build(bounds: &[Bounds]) -> Bvh {
        let mut items: Vec<Item> = bounds
            .iter()
            .enumerate()
            .map(|(i, b)| Item {
                bounds: *b,
                centroid: b.center(),
                index: u32::try_from(i).expect("fewer than 2³² primitives"),
            })
            .collect();
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * bounds.len().max(1)),
            order: Vec::with_capacity(bounds.len()),
        };
        if !items.is_empty() {
            bvh.build_node(&mut items);
        }
        bvh
    }

    /// Appends the subtree over `items` depth-first; returns its index.
    fn build_node(&mut self, items: &mut [Item]) -> usize {
        let bounds = items.iter().fold(Bounds::EMPTY, |b, it| b.union(it.bounds));
        let centroids = Bounds::around(items.iter().map(|it| it.centroid));
        let at = self.nodes.len();
        self.nodes.push(Node {
            bounds,
            offset: 0,
            count: 0,
            axis: 0,
        });
        let extent = centroids.max - centroids.min;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let split = if items.len() == 1 || extent[axis] <= 0.0 {
            // One primitive, or all centered on one point: no plane separates them.
            None
        } else {
            sah_split(items, &bounds, &centroids, axis)
        };
        let mid = match split {
            Some(mid) => mid,
            None if items.len() <= MAX_LEAF => {
                let first = self.order.len() as u32;
                self.order.extend(items.iter().map(|it| it.index));
                self.nodes[at].offset = first;
                self.nodes[at].count = items.len() as u16;
                return at;
            }
            // Too many to keep together: halve by centroid so leaves stay small.
            None => {
                let mid = items.len() / 2;
                items.select_nth_unstable_by(mid, |a, b| {
                    a.centroid[axis].total_cmp(&b.centroid[axis])
                });
                mid
            }
        };
        let (left, right) = items.split_at_mut(mid);
        self.build_node(left);
        let second = self.build_node(right);
        self.nodes[at].offset = second as u32;
        self.nodes[at].axis = axis as u8;
        at
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

    /// Nodes in the tree.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// The box around everything.
    pub fn bounds(&self) -> Bounds {
        self.nodes.first().map_or(Bounds::EMPTY, |n| n.bounds)
    }

    /// Calls `visit(primitive, t_max)` for every primitive in a leaf whose box the
    /// ray meets within `(t_min, *t_max)`, nearer children first. `visit` may
    /// shrink `t_max` (a closest-hit search) or break (a shadow ray's any-hit).
    /// Box tests are counted in `tested`.
    #[inline]
    pub fn traverse(
        &self,
        ray: &RayBox,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        if self.nodes.is_empty() {
            return ControlFlow::Continue(());
        }
        let mut stack = [0u32; 64];
        let mut top = 0;
        let mut at = 0usize;
        loop {
            let node = &self.nodes[at];
            tested.boxes += 1;
            if ray.hits(&node.bounds, t_min, *t_max) {
                if node.count > 0 {
                    let first = node.offset as usize;
                    for &p in &self.order[first..first + usize::from(node.count)] {
                        visit(p as usize, t_max)?;
                    }
                } else {
                    // Visit the near child now, keep the far one for later.
                    let (near, far) = if ray.dir_is_neg(usize::from(node.axis)) {
                        (node.offset as usize, at + 1)
                    } else {
                        (at + 1, node.offset as usize)
                    };
                    stack[top] = far as u32;
                    top += 1;
                    at = near;
                    continue;
                }
            }
            if top == 0 {
                return ControlFlow::Continue(());
            }
            top -= 1;
            at = stack[top] as usize;
        }
    }
}

/// The index that splits `items` (partitioned in place) at the binned SAH's best
/// plane along `axis`, or `None` when a leaf is expected to be cheaper.
fn sah_split(
    items: &mut [Item],
    bounds: &Bounds,
    centroids: &Bounds,
    axis: usize,
) -> Option<usize> {
    let lo = centroids.min[axis];
    let scale = BINS as f64 / (centroids.max[axis] - lo);
    let bin_of = |c: DVec3| (((c[axis] - lo) * scale) as usize).min(BINS - 1);
    let mut count = [0usize; BINS];
    let mut boxes = [Bounds::EMPTY; BINS];
    for it in items.iter() {
        let b = bin_of(it.centroid);
        count[b] += 1;
        boxes[b] = boxes[b].union(it.bounds);
    }
    // Cost of splitting after bin i: sweep from the right, then from the left.
    let mut right_cost = [0.0; BINS];
    let (mut acc, mut n) = (Bounds::EMPTY, 0);
    for i in (1..BINS).rev() {
        acc = acc.union(boxes[i]);
        n += count[i];
        right_cost[i - 1] = n as f64 * acc.area();
    }
    let (mut acc, mut n) = (Bounds::EMPTY, 0);
    let mut best = (f64::INFINITY, 0);
    for i in 0..BINS - 1 {
        acc = acc.union(boxes[i]);
        n += count[i];
        let cost = n as f64 * acc.area() + right_cost[i];
        if n > 0 && n < items.len() && cost < best.0 {
            best = (cost, i);
        }
    }
    let area = bounds.area();
    let split_cost = TRAVERSAL_COST + best.0 / area;
    let leaf_cost = items.len() as f64;
    if best.0.is_infinite() || (items.len() <= MAX_LEAF && split_cost >= leaf_cost) {
        return None;
    }
    let mut mid = 0;
    for i in 0..items.len() {
        if bin_of(items[i].centroid) <= best.1 {
            items.swap(i, mid);
            mid += 1;
        }
    }
    Some(mid)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::ray::Ray;

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
        assert!(bvh.nodes.iter().all(|n| usize::from(n.count) <= MAX_LEAF));
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
