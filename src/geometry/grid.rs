//! A uniform grid: the lecture's other way to avoid intersection tests. The
//! scene's box is cut into equal cells; each cell lists the primitives whose
//! boxes touch it, and a ray walks the cells it pierces, nearest first, testing
//! only what they list. A closest-hit search stops at the first cell beyond the
//! hit it has.
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
//!
//! **Traversal.** Amanatides & Woo, "A Fast Voxel Traversal Algorithm for Ray
//! Tracing" (Eurographics 1987): the ray is clipped to the grid, the first cell
//! found, and the 3D-DDA steps along the axis whose next boundary (`t_next`) is
//! nearest, adding `t_delta` to that axis's boundary parameter. The walk ends when
//! the next cell is entered beyond `*t_max`, so a hit shrinking it ends the walk.
//! A primitive in several cells is visited once per walk ([`Mailbox`]).
//!
//! **Why no cell the ray meets is skipped, in floating point.** Everything is
//! measured in cell units: `u(x) = (x − min) · inv` per axis, with `inv` the
//! stored reciprocal cell size. A primitive is listed in every cell from
//! `⌊u(lo)⌋` to `⌊u(hi)⌋` of its box, each clamped to the grid, with `u`
//! computed in floating point; since that rounded `u` is monotone in `x`, every
//! point of the box lies in a listed cell, and the computed `u` differs from the
//! exact one by at most `γ(2)·|u|`. The DDA itself only decides how the
//! ray's parameter range is cut into pieces `[t₀, t₁]` (consecutive pieces share
//! their end exactly, so the pieces cover the range whatever the DDA's rounding);
//! for each half of a piece the walk visits every cell between the smallest and
//! largest `u` the half reaches on each axis, widened by a bound on all those
//! roundings (`Walk::span`). Inside a piece that is the single cell the DDA
//! is in; at its ends, where the DDA's own rounded `t` may be off, it is also
//! the cell across the boundary, and the walk visits it rather than guess (the
//! halves keep those two doubts from adding the diagonal cell between them, and
//! a cell just visited is not visited again, so a walk visits about the cells
//! the ray pierces and no more). Clipping aims just outside the grid on every
//! side, by four times a bound on its own rounding (`Walk::new`). A ray
//! parallel to an axis has a constant `u` on it and is clipped by whether that
//! `u` lies in the grid so widened.

use std::cmp::Ordering;
use std::ops::ControlFlow;

use glam::DVec3;

use crate::geometry::hit::TestCounts;
use crate::geometry::mailbox::Mailbox;
use crate::math::bounds::Bounds;
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// Cells per primitive the automatic resolution aims at (see the module's notes).
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

    /// A point's position in cell units on each axis, rounded: monotone in the
    /// point, and within `γ(2)·|u|` of the exact `(x − min) · inv`.
    #[inline]
    fn u(&self, p: DVec3) -> DVec3 {
        (p - self.bounds.min) * self.inv
    }

    /// The cell holding a point, clamped to the grid.
    fn cell_of(&self, p: DVec3) -> [usize; 3] {
        let u = self.u(p);
        [0, 1, 2].map(|a| clamp_cell(u[a], self.res[a]))
    }

    #[inline]
    fn index(&self, [x, y, z]: [usize; 3]) -> usize {
        x + self.res[0] * (y + self.res[1] * z)
    }

    /// The box of a cell (for a diagram).
    fn cell_bounds(&self, cell: [usize; 3]) -> Bounds {
        let size = (self.bounds.max - self.bounds.min)
            / DVec3::new(self.res[0] as f64, self.res[1] as f64, self.res[2] as f64);
        let at = DVec3::new(cell[0] as f64, cell[1] as f64, cell[2] as f64);
        Bounds {
            min: self.bounds.min + at * size,
            max: self.bounds.min + (at + 1.0) * size,
        }
    }

    /// Cells along each axis.
    pub fn resolution(&self) -> [usize; 3] {
        self.res
    }

    /// Bytes the cell rows and their entries occupy.
    pub fn memory(&self) -> usize {
        (self.start.len() + self.items.len()) * 4
    }

    /// Calls `visit(primitive, t_max)` for every primitive listed in a cell the
    /// ray meets within `(t_min, *t_max)`, nearer cells first, each primitive at
    /// most once. `visit` may shrink `t_max` (closest hit) or break (any hit); the
    /// walk stops at the first cell entered beyond `*t_max`. Every cell visited
    /// is counted in `tested.boxes` and shown to `seen(cell, true)`.
    pub fn traverse_seeing(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        if self.n == 0 {
            return ControlFlow::Continue(());
        }
        let Some(walk) = Walk::new(self, ray, t_min, *t_max) else {
            return ControlFlow::Continue(());
        };
        let mut mailbox = Mailbox::new(self.n);
        let mut dda = walk.dda;
        let mut t0 = walk.t_start;
        // The spans of the last two half-pieces: their cells are visited already.
        let mut recent: [Option<[[usize; 2]; 3]>; 2] = [None, None];
        loop {
            let t_end = walk.t_end.min(*t_max);
            if t0 > t_end {
                return ControlFlow::Continue(());
            }
            let axis = dda.nearest_axis();
            let last = dda.t_next[axis].partial_cmp(&t_end) != Some(Ordering::Less);
            let t1 = if last {
                t_end
            } else {
                dda.t_next[axis].max(t0)
            };
            // Each half of the piece on its own: the widening at the piece's start
            // (the cell before, across the boundary just crossed) and at its end
            // (the cell after) then never combine into a diagonal neighbour the
            // ray does not pass, as one box over the whole piece would.
            let t_mid = 0.5 * t0 + 0.5 * t1;
            for (from, to) in [(t0, t_mid), (t_mid, t1)] {
                let span = walk.span(self, from, to);
                for z in span[2][0]..=span[2][1] {
                    for y in span[1][0]..=span[1][1] {
                        for x in span[0][0]..=span[0][1] {
                            let cell = [x, y, z];
                            let done = |r: &Option<[[usize; 2]; 3]>| {
                                r.is_some_and(|r| (0..3).all(|a| within(cell[a], r[a])))
                            };
                            if recent.iter().any(done) {
                                continue;
                            }
                            tested.boxes += 1;
                            seen(self.cell_bounds(cell), true);
                            let c = self.index(cell);
                            let listed =
                                &self.items[self.start[c] as usize..self.start[c + 1] as usize];
                            for &p in listed {
                                if mailbox.first_time(p) {
                                    visit(p as usize, t_max)?;
                                }
                            }
                        }
                    }
                }
                recent = [recent[1], Some(span)];
            }
            if last {
                return ControlFlow::Continue(());
            }
            dda.step(axis, self.res[axis]);
            t0 = t1;
        }
    }

    /// The grid's own numbers for a summary.
    pub fn describe(&self) -> String {
        let cells = self.start.len() - 1;
        let empty = (0..cells)
            .filter(|&c| self.start[c] == self.start[c + 1])
            .count();
        let [x, y, z] = self.res;
        format!(
            "grid {x}×{y}×{z} = {cells} cells ({empty} empty), {} primitives, {} entries \
             ({:.2} per primitive), {} bytes",
            self.n,
            self.items.len(),
            self.items.len() as f64 / self.n.max(1) as f64,
            self.memory()
        )
    }
}

/// `n_i = ⌈d_i · (λN/V)^{1/k}⌉` over the `k` axes that get more than one cell,
/// then clamped and capped (see the module's notes). Done in logarithms, so
/// extents near the ends of f64's range neither overflow nor underflow.
fn resolution(d: DVec3, n: usize) -> [usize; 3] {
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
fn capped(mut res: [usize; 3]) -> [usize; 3] {
    while res.iter().product::<usize>() > MAX_CELLS {
        let a = (0..3).max_by_key(|&a| res[a]).expect("three axes");
        res[a] = res[a].div_ceil(2);
    }
    res
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

#[inline]
fn within(c: usize, [lo, hi]: [usize; 2]) -> bool {
    lo <= c && c <= hi
}

/// One ray's walk: its line in cell units, `u(t) = a + t·b` per axis, and the
/// part of it to walk.
struct Walk {
    a: DVec3,
    b: DVec3,
    t_start: f64,
    t_end: f64,
    dda: Dda,
}

impl Walk {
    /// The ray clipped to the grid, widened on each axis by `m = 2γ(8)·(|a| + n + 1)`
    /// cell units, or `None` if it misses that within `(t_min, t_max)`. A box's
    /// point has an exact `u` in `[0, n·(1 + γ(2))]` (the cell size rounds); the
    /// clip's `t = (−m − a)/b` rounds twice, so the exact `u` there is within
    /// `γ(2)·(|a| + n + m)` of its target; and `a` itself is within `γ(2)·|a|`.
    /// Together under `γ(4)·(|a| + n + 1)`: the margin is four times that, and
    /// so small (for an origin near the grid) that the walk hardly leaves it.
    fn new(grid: &Grid, ray: &Ray, t_min: f64, t_max: f64) -> Option<Walk> {
        let a = grid.u(ray.origin);
        let b = ray.dir * grid.inv;
        let (mut lo, mut hi) = (t_min, t_max);
        for axis in 0..3 {
            let n = grid.res[axis] as f64;
            let m = 2.0 * gamma(8) * (a[axis].abs() + n + 1.0);
            if b[axis] == 0.0 {
                // Parallel to this axis: u is constant along the ray.
                if !(a[axis] >= -m && a[axis] <= n + m) {
                    return None;
                }
            } else {
                let t0 = (-m - a[axis]) / b[axis];
                let t1 = (n + m - a[axis]) / b[axis];
                lo = lo.max(t0.min(t1));
                hi = hi.min(t0.max(t1));
            }
        }
        if !matches!(lo.partial_cmp(&hi), Some(Ordering::Less | Ordering::Equal)) {
            return None;
        }
        let u = |axis: usize| at(a[axis], b[axis], lo);
        let dda = Dda::new(
            [0, 1, 2].map(|axis| clamp_cell(u(axis), grid.res[axis])),
            a,
            b,
        );
        Some(Walk {
            a,
            b,
            t_start: lo,
            t_end: hi,
            dda,
        })
    }

    /// The cells, per axis as `[first, last]`, that the piece `[t0, t1]` of the
    /// ray may be in. The exact `u` is linear in `t`, so on the piece it lies
    /// between its values at the ends. Each end is computed as `a + t·b`, where
    /// `a` carries two roundings (a difference, a product) and `b` one, then the
    /// product `t·b` and the sum one each: within `γ(5)·(|a| + |t·b|)` of exact.
    /// The primitives were listed by a `u` within `γ(2)·|u|` of exact, and
    /// subtracting or adding the slack rounds once more: eight roundings, so the
    /// slack `γ(8)·(|a| + |t·b|)` (and one more ULP of the slack's own rounding,
    /// covered by doubling it) keeps every cell a listed primitive can share with
    /// the piece.
    fn span(&self, grid: &Grid, t0: f64, t1: f64) -> [[usize; 2]; 3] {
        let slack = 2.0 * gamma(8);
        [0, 1, 2].map(|axis| {
            let (a, b) = (self.a[axis], self.b[axis]);
            let ends = [t0, t1].map(|t| {
                let u = at(a, b, t);
                let s = slack * (a.abs() + if b == 0.0 { 0.0 } else { (t * b).abs() });
                (u - s, u + s)
            });
            let lo = ends[0].0.min(ends[1].0);
            let hi = ends[0].1.max(ends[1].1);
            let n = grid.res[axis];
            [clamp_cell(lo, n), clamp_cell(hi, n)]
        })
    }
}

/// `a + t·b`, and `a` alone on an axis the ray is parallel to (where `t` may be
/// infinite).
#[inline]
fn at(a: f64, b: f64, t: f64) -> f64 {
    if b == 0.0 { a } else { a + t * b }
}

/// Amanatides & Woo's 3D-DDA state: the cell the walk is in, the parameter at
/// which the ray crosses that cell's next boundary on each axis (`t_next`, their
/// tMax), and the parameter between boundaries (`t_delta`).
#[derive(Clone, Copy, Debug)]
struct Dda {
    cell: [usize; 3],
    t_next: [f64; 3],
    t_delta: [f64; 3],
    up: [bool; 3],
}

impl Dda {
    fn new(cell: [usize; 3], a: DVec3, b: DVec3) -> Dda {
        let mut t_next = [f64::INFINITY; 3];
        let mut t_delta = [f64::INFINITY; 3];
        for axis in 0..3 {
            let b = b[axis];
            if b != 0.0 {
                let j = cell[axis] as f64;
                let boundary = if b > 0.0 { j + 1.0 } else { j };
                t_next[axis] = (boundary - a[axis]) / b;
                t_delta[axis] = 1.0 / b.abs();
            }
        }
        Dda {
            cell,
            t_next,
            t_delta,
            up: [0, 1, 2].map(|axis| b[axis] > 0.0),
        }
    }

    /// The axis whose next boundary the ray crosses first.
    #[inline]
    fn nearest_axis(&self) -> usize {
        let t = self.t_next;
        if t[0] <= t[1] && t[0] <= t[2] {
            0
        } else if t[1] <= t[2] {
            1
        } else {
            2
        }
    }

    /// Into the next cell along `axis`; past the grid's last cell that axis has
    /// no more boundaries to cross.
    #[inline]
    fn step(&mut self, axis: usize, n: usize) {
        let c = self.cell[axis];
        let leaves = if self.up[axis] { c + 1 >= n } else { c == 0 };
        if leaves {
            self.t_next[axis] = f64::INFINITY;
        } else {
            self.cell[axis] = if self.up[axis] { c + 1 } else { c - 1 };
            self.t_next[axis] += self.t_delta[axis];
        }
    }
}

#[cfg(test)]
#[path = "grid_tests.rs"]
mod tests;
