//! How close is close enough: the check's tolerances, and why.
//!
//! - **The primary ray and its hit: 10⁻⁶ relative.** The camera and the first
//!   intersection are a few dozen operations; two correct tracers in double
//!   precision (whatever root formula they use) agree to about 10⁻¹², one in
//!   single precision to about 10⁻⁷. Half a pixel, the smallest classic
//!   mistake here, moves a direction by about 10⁻³ at 640 pixels across.
//! - **Each level below: 10⁻³ more.** A tracer may start its secondary rays a
//!   little off the surface against acne (the classic ε of 10⁻⁴ to 10⁻³
//!   along the normal, where raytree moves a few ULPs): every bounce inherits
//!   that much. The classic mistakes change a direction by a tenth or
//!   more.
//! - **Sizes:** a point or a distance is compared relative to
//!   `max(1, |ours|, |the ray's origin|)`, so a scene far from the origin or
//!   a long ray is held to the same relative accuracy as a small one.
//! - **Directions** are compared as unit vectors, whatever length the learner
//!   gave (`|û − v̂|`, about the angle in radians); `t` counts in units of the
//!   ray's own direction, so it is compared as a distance, `t·|direction|`.
//! - **Colors and coefficients: 2·10⁻³ of `max(1, |ours|)`**, linear RGB:
//!   half an 8-bit level where the color is 1, far above float noise and an
//!   offset's effect, below every mistake diagnosed.

use glam::DVec3;

/// Geometry's tolerance at the primary ray.
pub const PRIMARY: f64 = 1e-6;
/// What each level below the primary ray adds to it.
pub const PER_LEVEL: f64 = 1e-3;
/// Colors' and coefficients' tolerance, relative to `max(1, |ours|)`.
pub const COLOR: f64 = 2e-3;

/// The geometric tolerance of a ray at `depth` (1 is the primary ray).
pub fn tolerance(depth: u32) -> f64 {
    PRIMARY + PER_LEVEL * f64::from(depth.saturating_sub(1))
}

/// `|a − b| ≤ tol·max(1, |b|, |origin|)`: a point of a ray from `origin`.
pub fn same_point(a: DVec3, b: DVec3, origin: DVec3, tol: f64) -> bool {
    a.distance(b) <= tol * 1f64.max(b.length()).max(origin.length())
}

/// `|a − b| ≤ tol·max(1, |b|, |origin|)`: distances along a ray from
/// `origin`, held to the same relative accuracy as [`same_point`]'s points.
pub fn same_distance(a: f64, b: f64, origin: DVec3, tol: f64) -> bool {
    (a - b).abs() <= tol * 1f64.max(b.abs()).max(origin.length())
}

/// The same direction, whatever the lengths.
pub fn same_direction(a: DVec3, b: DVec3, tol: f64) -> bool {
    a.normalize().distance(b.normalize()) <= tol
}

/// Colors (or coefficients) within [`COLOR`].
pub fn same_color(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().max_element() <= COLOR * 1f64.max(b.abs().max_element())
}
