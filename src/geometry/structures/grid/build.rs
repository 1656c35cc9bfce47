//! Building the grid.
//!
//! **Resolution.** About `λ·N` cells for `N` primitives, each axis proportional
//! to the box's extent `d`, so cells are near cubes:
//! `n_x = ⌈d_x · (λN/V)^{1/3}⌉` (the `O(N)` cells of Cleary & Wyvill, "Analysis
//! of an algorithm for fast ray tracing using uniform space subdivision", 1988,
//! in the form the grid papers around Wald et al., "Ray Tracing Animated Scenes
//! using Coherent Grid Traversal", 2006, write it; pbrt-v1's grid accelerator
//! scales the same way, `3·∛N` cells along the widest axis). An axis the rule
//! would give less than one cell (a flat or nearly flat scene) gets one, and the
//! others share `λN` in two (or one) dimensions. Ize, Shirley & Parker ("Grid
//! Creation Strategies for Efficient Ray Tracing", RT 2007) show `O(N)` cells is
//! best for well-behaved models; the constant is a tuning choice, and
//! [`LAMBDA`] = 4 is a value in the single digits that literature uses, not a
//! measurement of ours ([`Grid::build_with_resolution`] is there to sweep it).
//! Each axis is clamped to `[1, MAX_AXIS]` and the total to [`MAX_CELLS`] so
//! memory stays bounded.
//!
//! **Storage.** Compressed rows: cell `c` lists `items[start[c]..start[c + 1]]`,
//! built in two passes over the primitives (count, then fill).

use glam::DVec3;

use crate::geometry::structures::grid::{
    Grid, LAMBDA, MAX_AXIS, MAX_AXIS_SWEEP, MAX_CELLS, MAX_GIVEN_SIDE, clamp_cell,
};
use crate::math::bounds::Bounds;

impl Grid {
    /// Builds over primitives `0..n` known by their (finite, non-empty) bounds,
    /// at the resolution the module's rule gives.
    pub fn build(bounds: &[Bounds]) -> Grid {
        let scene = bounds.iter().fold(Bounds::EMPTY, |a, b| a.union(*b));
        let res = if bounds.is_empty() {
            [0; 3]
        } else {
            resolution(scene.max - scene.min, bounds.len())
        };
        Grid::with(bounds, scene, res)
    }

    /// Builds at a given resolution, each axis clamped to `[1, MAX_AXIS_SWEEP]`
    /// and the total to [`MAX_CELLS`] (the largest axis halved until it fits).
    pub fn build_with_resolution(bounds: &[Bounds], res: [usize; 3]) -> Grid {
        let scene = bounds.iter().fold(Bounds::EMPTY, |a, b| a.union(*b));
        let res = if bounds.is_empty() {
            [0; 3]
        } else {
            capped(res.map(|n| n.clamp(1, MAX_AXIS_SWEEP)))
        };
        Grid::with(bounds, scene, res)
    }

    /// Builds with `side` cells (1 to [`MAX_GIVEN_SIDE`]) along the scene box's
    /// longest side and the other sides in proportion, rounded up (at least one
    /// cell each), so cells are near cubes as with the automatic rule.
    pub fn build_with_side(bounds: &[Bounds], side: u32) -> Grid {
        let scene = bounds.iter().fold(Bounds::EMPTY, |a, b| a.union(*b));
        let d = scene.max - scene.min;
        let longest = d.max_element();
        let side = side.clamp(1, MAX_GIVEN_SIDE);
        let res = [0, 1, 2].map(|a| {
            let share = if longest > 0.0 { d[a] / longest } else { 1.0 };
            ((f64::from(side) * share).ceil() as usize).clamp(1, side as usize)
        });
        Grid::build_with_resolution(bounds, res)
    }

    /// The grid over `bounds` (whose box is `scene`) at resolution `res`, its
    /// cells' lists filled.
    fn with(bounds: &[Bounds], scene: Bounds, res: [usize; 3]) -> Grid {
        if bounds.is_empty() {
            return Grid {
                res,
                bounds: Bounds::EMPTY,
                inv: DVec3::ZERO,
                start: vec![0],
                items: Vec::new(),
                n: 0,
            };
        }
        // An axis of no extent (everything flat in it) gets a thin slab, so the
        // cell size is finite and a ray off that plane is still clipped away.
        let d = scene.max - scene.min;
        let widest = d.max_element();
        let mut grid_box = scene;
        for axis in 0..3 {
            if d[axis] <= 0.0 {
                let h = (widest * 2f64.powi(-20))
                    .max(scene.min[axis].abs() * 2f64.powi(-40))
                    .max(1e-300);
                grid_box.min[axis] -= h;
                grid_box.max[axis] += h;
            }
        }
        let extent = grid_box.max - grid_box.min;
        let inv = DVec3::new(
            res[0] as f64 / extent.x,
            res[1] as f64 / extent.y,
            res[2] as f64 / extent.z,
        );
        let mut grid = Grid {
            res,
            bounds: grid_box,
            inv,
            start: Vec::new(),
            items: Vec::new(),
            n: bounds.len(),
        };
        let cells = res[0] * res[1] * res[2];
        // Pass 1: how many primitives each cell lists (shifted by one, so the
        // prefix sum leaves each cell's start in place).
        let mut start = vec![0u32; cells + 1];
        for b in bounds {
            let (lo, hi) = (grid.cell_of(b.min), grid.cell_of(b.max));
            for z in lo[2]..=hi[2] {
                for y in lo[1]..=hi[1] {
                    for x in lo[0]..=hi[0] {
                        start[grid.index([x, y, z]) + 1] += 1;
                    }
                }
            }
        }
        for c in 0..cells {
            start[c + 1] += start[c];
        }
        // Pass 2: fill, each cell's cursor starting at its start.
        let mut items = vec![0u32; start[cells] as usize];
        let mut cursor = start.clone();
        for (p, b) in bounds.iter().enumerate() {
            let (lo, hi) = (grid.cell_of(b.min), grid.cell_of(b.max));
            for z in lo[2]..=hi[2] {
                for y in lo[1]..=hi[1] {
                    for x in lo[0]..=hi[0] {
                        let c = grid.index([x, y, z]);
                        items[cursor[c] as usize] = p as u32;
                        cursor[c] += 1;
                    }
                }
            }
        }
        grid.start = start;
        grid.items = items;
        grid
    }

    /// The cell holding a point, clamped to the grid.
    pub(super) fn cell_of(&self, p: DVec3) -> [usize; 3] {
        let u = self.u(p);
        [0, 1, 2].map(|a| clamp_cell(u[a], self.res[a]))
    }
}

/// `n_i = ⌈d_i · (λN/V)^{1/k}⌉` over the `k` axes that get more than one cell,
/// then clamped and capped (see the module's notes). Done in logarithms, so
/// extents near the ends of f64's range neither overflow nor underflow.
pub(super) fn resolution(d: DVec3, n: usize) -> [usize; 3] {
    let mut active = [0, 1, 2].map(|a| d[a] > 0.0);
    let mut scale = 0.0;
    loop {
        let k = active.iter().filter(|&&a| a).count();
        if k == 0 {
            break;
        }
        let log_volume: f64 = (0..3).filter(|&a| active[a]).map(|a| d[a].ln()).sum();
        scale = ((LAMBDA * n as f64).ln() - log_volume) / k as f64;
        // An axis the rule gives under one cell gets one; the rest share λN.
        let thin = (0..3).filter(|&a| active[a] && d[a].ln() + scale < 0.0);
        let thin: Vec<usize> = thin.collect();
        if thin.is_empty() {
            break;
        }
        for a in thin {
            active[a] = false;
        }
    }
    let res = [0, 1, 2].map(|a| {
        if active[a] {
            let cells = (d[a].ln() + scale).exp().ceil();
            if cells.is_finite() {
                (cells as usize).clamp(1, MAX_AXIS)
            } else {
                MAX_AXIS
            }
        } else {
            1
        }
    });
    capped(res)
}

/// The largest axis halved (rounding up) until the cells number at most [`MAX_CELLS`].
pub(super) fn capped(mut res: [usize; 3]) -> [usize; 3] {
    while res.iter().product::<usize>() > MAX_CELLS {
        let a = (0..3).max_by_key(|&a| res[a]).expect("three axes");
        res[a] = res[a].div_ceil(2);
    }
    res
}
