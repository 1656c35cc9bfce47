//! A bounding volume hierarchy: the lecture's "avoid intersection tests". Objects
//! (or a mesh's triangles) are grouped into nested boxes; a ray that misses a box
//! skips everything inside it, so a ray costs about `log n` box tests instead of
//! `n` object tests.
//!
//! Each node has up to [`node::WIDTH`] children (Wald et al., "Getting Rid of Packets",
//! 2008; Embree's BVH4): one visit tests four boxes at once with SIMD, and the
//! tree is half as deep as a binary one. It is built with the binned surface
//! area heuristic, on all cores ([`build`]). Traversal
//! visits the boxes a ray meets nearest first, so a closest-hit search shrinks
//! its interval early and skips boxes beyond the hit it has; a shadow ray
//! through a scene's hierarchy, which any blocker ends, takes them in their
//! stored order ([`Bvh::traverse_leaves_any`]).
//!
//! The boxes are stored in single precision, rounded outward, which halves the
//! memory a ray walks through; primitives stay in double precision. The box test
//! is made robust in the manner of Ize ("Robust BVH Ray Traversal", JCGT 2013):
//! every rounding of the single-precision test is bounded, and the interval is
//! widened by that bound, so a ray that meets a box in exact arithmetic is never
//! culled ([`traverse::RayBox4`]).

pub mod node; // the node layout: four single-precision boxes, packed children
pub mod build; // building it: the binned surface area heuristic, on all cores
pub mod traverse; // walking it: nearer boxes first (or any order, for shadow rays), four at a time
#[cfg(test)]
mod tests;

use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::geometry::structures::bvh::node::Node;
use crate::math::bounds::{Bounds, RayBox};
use crate::math::ray::Ray;

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
    /// [`build`]).
    pub fn build(bounds: &[Bounds]) -> Bvh {
        let (nodes, order, bounds) = build::build(bounds);
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

    /// Nodes in the tree (each with up to [`node::WIDTH`] boxes).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// The box around everything.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }
}

impl Structure for Bvh {
    /// The boxes a ray meets, nearer first, each leaf's primitives in
    /// [`Bvh::leaf_order`] (see [`Bvh::traverse_leaves_seeing`]).
    #[inline]
    fn walk(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let ray = RayBox::new(ray);
        self.traverse_leaves_seeing(&ray, t_min, t_max, tested, seen, |leaf, t_max| {
            for &p in &self.order[leaf] {
                visit(p as usize, t_max)?;
            }
            ControlFlow::Continue(())
        })
    }

    /// Nothing: no setting shapes the hierarchy (its nodes and bytes are in
    /// the benchmarks, `cargo bench -p raytree-benches --bench scenes`).
    fn describe(&self) -> Option<String> {
        None
    }

    fn memory(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.order.len() * 4
    }
}
