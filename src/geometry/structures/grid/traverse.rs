//! Walking the grid.
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
use crate::geometry::structures::grid::{Grid, clamp_cell};
use crate::geometry::structures::mailbox::Mailbox;
use crate::math::bounds::Bounds;
use crate::math::float::gamma;
use crate::math::ray::Ray;

impl Grid {
    /// Calls `visit(primitive, t_max)` for every primitive listed in a cell the
    /// ray meets within `(t_min, *t_max)`, nearer cells first, each primitive at
    /// most once. `visit` may shrink `t_max` (closest hit) or break (any hit); the
    /// walk stops at the first cell entered beyond `*t_max`. Every cell visited
    /// is counted in `tested.boxes` and shown to `seen(cell, true)`.
    pub(super) fn traverse(
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
}

/// Whether cell index `c` lies in `[lo, hi]`.
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
