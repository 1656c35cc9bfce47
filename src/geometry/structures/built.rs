//! The structure a setting names, built: [`build`], and [`Built`], which holds
//! any of the four so that whoever keeps one never asks which. Each ray's walk
//! is dispatched by a `match` the compiler sees through (no `dyn`): the walks
//! are generic over their visits, which inline into them.

use std::ops::ControlFlow;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::geometry::structures::bsp::BspTree;
use crate::geometry::structures::bvh::Bvh;
use crate::geometry::structures::grid::Grid;
use crate::geometry::structures::octree::{self, Octree};
use crate::math::bounds::{Bounds, RayBox};
use crate::math::ray::Ray;
use crate::methods::{Accel, Level};

/// How finely the grid and the trees cut space: the settings `grid_res` and
/// `tree_depth` (the BVH takes neither).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Subdivision {
    /// The grid's cells along the scene's longest side.
    pub grid_res: Level,
    /// The octree's or the BSP tree's deepest level.
    pub depth_limit: Level,
}

/// One of the efficiency slide's structures, as [`build`] made it.
#[derive(Clone, Debug)]
pub enum Built {
    /// A bounding volume hierarchy.
    Bvh(Bvh),
    /// A uniform grid.
    Grid(Grid),
    /// An octree.
    Octree(Octree),
    /// A BSP tree (the axis-aligned one, a k-d tree).
    Bsp(BspTree),
}

/// Builds the structure `accel` names over primitives with these (finite,
/// non-empty) bounds, as finely as `subdivision` asks. `auto` and `none` are
/// the caller's to resolve (whether a structure pays, or none is wanted); given
/// here, they build the hierarchy `auto` would.
pub fn build(accel: Accel, bounds: &[Bounds], subdivision: Subdivision) -> Built {
    let depth_limit = match subdivision.depth_limit {
        Level::Auto => None,
        Level::Given(d) => Some(d),
    };
    match accel {
        Accel::Grid => Built::Grid(match subdivision.grid_res {
            Level::Auto => Grid::build(bounds),
            Level::Given(side) => Grid::build_with_side(bounds, side),
        }),
        Accel::Octree => Built::Octree(Octree::build_to_depth(
            bounds,
            depth_limit.unwrap_or(octree::DEPTH_LIMIT),
        )),
        Accel::Bsp => Built::Bsp(BspTree::build_to_depth(bounds, depth_limit)),
        Accel::Bvh | Accel::Auto | Accel::None => Built::Bvh(Bvh::build(bounds)),
    }
}

/// A caller's own item for each primitive, for [`Built::walk_items`]: the
/// items in the BVH's leaf order ([`Built::leaf_order`]), so that a leaf hands
/// out its run of them side by side; and for the other structures, which list
/// a primitive in several cells and hand it out once, the item of primitive
/// `i` as `named(i)`.
#[derive(Clone, Copy)]
pub struct Items<'a, T, F> {
    /// The items in the BVH's leaf order (empty for the other structures).
    pub in_leaf_order: &'a [T],
    /// The item of a primitive the other structures hand out.
    pub named: F,
}

impl Built {
    /// Which structure it is, by the setting's name.
    pub fn accel(&self) -> Accel {
        match self {
            Built::Bvh(_) => Accel::Bvh,
            Built::Grid(_) => Accel::Grid,
            Built::Octree(_) => Accel::Octree,
            Built::Bsp(_) => Accel::Bsp,
        }
    }

    /// The hierarchy, if it is one.
    pub fn bvh(&self) -> Option<&Bvh> {
        match self {
            Built::Bvh(bvh) => Some(bvh),
            _ => None,
        }
    }

    /// For a structure whose leaves are runs of one list of the primitives (the
    /// BVH), that list: a caller that keeps its items in this order has
    /// [`Built::walk_items`] hand out a leaf's items side by side.
    pub fn leaf_order(&self) -> Option<&[u32]> {
        self.bvh().map(Bvh::leaf_order)
    }

    /// [`Structure::walk`], handing `visit` the caller's item for each
    /// primitive rather than its index (see [`Items`]).
    #[inline]
    #[allow(clippy::too_many_arguments)] // the walk's own six, and the caller's items
    pub fn walk_items<T>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        items: Items<'_, T, impl Fn(usize) -> T>,
        mut visit: impl FnMut(&T, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let named = items.named;
        match self {
            Built::Bvh(bvh) => {
                let ray = RayBox::new(ray);
                bvh.traverse_leaves_seeing(&ray, t_min, t_max, tested, seen, |run, t| {
                    for item in &items.in_leaf_order[run] {
                        visit(item, t)?;
                    }
                    ControlFlow::Continue(())
                })
            }
            Built::Grid(g) => g.walk(ray, t_min, t_max, tested, seen, |i, t| visit(&named(i), t)),
            Built::Octree(o) => o.walk(ray, t_min, t_max, tested, seen, |i, t| visit(&named(i), t)),
            Built::Bsp(b) => b.walk(ray, t_min, t_max, tested, seen, |i, t| visit(&named(i), t)),
        }
    }

    /// [`Built::walk_items`] for a search that any hit ends and that never
    /// shrinks `t_max` (a shadow ray): the BVH takes the boxes a ray meets in
    /// their stored order, not nearest first (see [`Bvh::traverse_leaves_any`]);
    /// the others walk as ever.
    #[inline]
    pub fn walk_items_any<T>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        items: Items<'_, T, impl Fn(usize) -> T>,
        mut visit: impl FnMut(&T, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let Built::Bvh(bvh) = self else {
            return self.walk_items(ray, t_min, t_max, tested, |_, _| {}, items, visit);
        };
        let ray = RayBox::new(ray);
        bvh.traverse_leaves_any(&ray, t_min, t_max, tested, |run, t| {
            for item in &items.in_leaf_order[run] {
                visit(item, t)?;
            }
            ControlFlow::Continue(())
        })
    }
}

impl Structure for Built {
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
        match self {
            Built::Bvh(bvh) => bvh.walk(ray, t_min, t_max, tested, seen, visit),
            Built::Grid(g) => g.walk(ray, t_min, t_max, tested, seen, visit),
            Built::Octree(o) => o.walk(ray, t_min, t_max, tested, seen, visit),
            Built::Bsp(b) => b.walk(ray, t_min, t_max, tested, seen, visit),
        }
    }

    fn describe(&self) -> Option<String> {
        match self {
            Built::Bvh(bvh) => bvh.describe(),
            Built::Grid(g) => g.describe(),
            Built::Octree(o) => o.describe(),
            Built::Bsp(b) => b.describe(),
        }
    }

    fn memory(&self) -> usize {
        match self {
            Built::Bvh(bvh) => bvh.memory(),
            Built::Grid(g) => g.memory(),
            Built::Octree(o) => o.memory(),
            Built::Bsp(b) => b.memory(),
        }
    }
}
