//! The efficiency slide: four structures that hand a ray only the objects it
//! may meet, so it skips most intersection tests. Side by side, one folder each:
//!
//! - `bvh/`, the bounding volume hierarchy: objects grouped into nested boxes;
//! - `grid/`, the uniform grid: space cut into equal cells, walked by the 3D-DDA;
//! - `octree/`, the octree: a cube split in eight, and again, where it is full;
//! - `bsp/`, the BSP tree: space split in two by a plane, and again (the
//!   axis-aligned one, a k-d tree).
//!
//! Each holds its layout (`mod.rs`), its builder (`build.rs`), its walk
//! (`traverse.rs`) and its tests. All four answer to one [`Structure`] (as
//! pbrt-v4's aggregates share one interface); [`build`] makes the one a setting
//! names. A primitive listed in several cells is handed to a ray once
//! ([`mailbox`]).

use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

pub mod bvh; // objects grouped into nested boxes (node layout, build, traversal)
pub mod grid; // a uniform grid of cells, walked by the 3D-DDA
pub mod octree; // a cube split in eight, cells walked nearest first
pub mod bsp; // the axis-aligned BSP tree (a k-d tree): built by the surface area heuristic, walked front to back
pub mod mailbox; // a primitive listed in several cells is handed to a ray once
mod built; // the one a setting names: build(), and the enum that holds any of the four
#[cfg(test)]
mod walk_tests; // what the structures' tests share: cubes, a whole walk, a reference sphere hit

pub use built::{Built, Items, Subdivision, build};

/// What each structure of the efficiency slide does for the tracer, over
/// primitives `0..n` known by their bounding boxes.
pub trait Structure {
    /// Calls `visit(primitive, t_max)` for every primitive the ray may meet in
    /// `(t_min, *t_max)`, those of nearer cells first, each once. `visit` may
    /// shrink `t_max` (a closest-hit search), after which cells entered beyond
    /// it are skipped, or break (a shadow ray's any-hit), which ends the walk.
    /// Every box or cell tested counts in `tested.boxes` and is shown to
    /// `seen(its bounds, whether the ray met it)`, for a diagram.
    fn walk(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()>;

    /// What was built, in the structure's own numbers, as `render --stats`
    /// prints it: what the settings `grid_res` and `tree_depth` chose (the
    /// grid's cells, a tree's nodes, leaves and depth). `None` for the BVH,
    /// which no setting shapes.
    fn describe(&self) -> Option<String>;

    /// Bytes its nodes or cells and their lists of primitives occupy.
    fn memory(&self) -> usize;
}
