//! A uniform grid: the lecture's other way to avoid intersection tests. The
//! scene's box is cut into equal cells; each cell lists the primitives whose
//! boxes touch it, and a ray walks the cells it pierces, nearest first, testing
//! only what they list. A closest-hit search stops at the first cell beyond the
//! hit it has.
//!
//! How many cells, and how they list the primitives: [`build`]. How a ray
//! walks them (Amanatides & Woo's 3D-DDA), and why no cell it meets is skipped
//! in floating point: [`traverse`].

use std::ops::ControlFlow;

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;

pub mod build; // the resolution rule, and the cells' lists filled in two passes
pub mod traverse; // the 3D-DDA, each step widened by a bound on its rounding
#[cfg(test)]
mod tests;

/// Cells per primitive the automatic resolution aims at (see [`build`]).
pub const LAMBDA: f64 = 4.0;

/// The most cells along one axis for the automatic resolution.
pub const MAX_AXIS: usize = 128;

/// The most cells along one axis for [`Grid::build_with_resolution`].
pub const MAX_AXIS_SWEEP: usize = 1024;

/// The most cells in all: 4 M cells, 16 MB of row starts.
pub const MAX_CELLS: usize = 1 << 22;

/// The most cells a user may ask for along the scene's longest side
/// ([`Grid::build_with_side`]): 160³ cells stay under [`MAX_CELLS`], so a
/// resolution asked for is always the one built.
pub const MAX_GIVEN_SIDE: u32 = 160;

/// A uniform grid over primitives `0..n`, known by their bounding boxes.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// Cells along each axis (all 0 for no primitives).
    res: [usize; 3],
    /// The grid's box: the primitives' box, an axis of no extent widened a little.
    bounds: Bounds,
    /// Cells per unit length, per axis: `u(x) = (x − bounds.min) · inv`.
    inv: DVec3,
    /// Cell `c` (x fastest, then y, then z) lists `items[start[c]..start[c + 1]]`.
    start: Vec<u32>,
    /// Primitive indices, cell by cell.
    items: Vec<u32>,
    /// Primitives.
    n: usize,
}

impl Grid {
    /// A point's position in cell units on each axis, rounded: monotone in the
    /// point, and within `γ(2)·|u|` of the exact `(x − min) · inv`.
    #[inline]
    fn u(&self, p: DVec3) -> DVec3 {
        (p - self.bounds.min) * self.inv
    }

    /// Cell `[x, y, z]`'s place in the rows (x fastest, then y, then z).
    #[inline]
    fn index(&self, [x, y, z]: [usize; 3]) -> usize {
        x + self.res[0] * (y + self.res[1] * z)
    }

    /// Cells along each axis.
    pub fn resolution(&self) -> [usize; 3] {
        self.res
    }
}

impl Structure for Grid {
    /// The cells the ray pierces, nearest first (see [`traverse`]).
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

    /// The cells along each axis, how many are empty, and the entries.
    fn describe(&self) -> Option<String> {
        let cells = self.start.len() - 1;
        let empty = (0..cells)
            .filter(|&c| self.start[c] == self.start[c + 1])
            .count();
        let [x, y, z] = self.res;
        Some(format!(
            "grid {x}×{y}×{z} = {cells} cells ({empty} empty), {} primitives, {} entries \
             ({:.2} per primitive), {} bytes",
            self.n,
            self.items.len(),
            self.items.len() as f64 / self.n.max(1) as f64,
            self.memory()
        ))
    }

    /// The cell rows and their entries.
    fn memory(&self) -> usize {
        (self.start.len() + self.items.len()) * 4
    }
}

/// A position in cell units turned into a cell index clamped to `0..n` (a
/// NaN, which a finite grid and finite boxes never make, to cell 0). For
/// `u ≥ 0` truncation is the floor, and below 0 both clamp to cell 0, so no
/// `floor` call is needed: without SSE4.1 it is a call into libm, which was
/// an eighth of the grid's instructions.
#[inline]
fn clamp_cell(u: f64, n: usize) -> usize {
    if u >= n as f64 {
        n - 1
    } else if u >= 0.0 {
        u as usize
    } else {
        0
    }
}
