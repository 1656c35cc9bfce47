//! How close is close enough: the check's tolerances, and what a comparison
//! works with (the scene, raytree's trace, the pixel, its step numbers).
//!
//! The tolerances, and why:
//! - **The primary ray and its hit: 10⁻⁶ relative.** The camera and the first
//!   intersection are a few dozen operations; two correct tracers in double
//!   precision (whatever root formula they use) agree to about 10⁻¹², one in
//!   single precision to about 10⁻⁷. Half a pixel, the smallest classic
//!   mistake here, moves a direction by about 10⁻³ at 640 pixels across.
//! - **Each level below: 10⁻³ more.** A tracer may start its secondary rays a
//!   little off the surface against acne (the classic ε of 10⁻⁴ to 10⁻³
//!   along the normal, where raytree moves a few ULPs): every bounce inherits
//!   that much. The mistakes diagnosed below change a direction by a tenth
//!   or more.
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

use crate::geometry::hit::Roots;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::shading::phong::power;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{LocalRecord, RayTree, ShadowRecord};
use crate::tree::steps::StepKind;

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

/// What the comparison works with.
pub struct Context<'a> {
    /// The scene, with the settings the pixel was traced with.
    pub scene: &'a Scene,
    /// raytree's trace of the pixel (one sample).
    pub trace: &'a TraceDocument,
    /// The pixel, image coordinates.
    pub pixel: (u32, u32),
}

impl Context<'_> {
    /// raytree's tree.
    pub fn tree(&self) -> &RayTree {
        &self.trace.samples[0].tree
    }

    /// The 1-based number of node `node`'s step `kind` (the last one of its
    /// node when the tree has no such step).
    pub fn step(&self, node: usize, kind: StepKind) -> usize {
        let steps = self.trace.steps(0);
        steps
            .iter()
            .position(|s| s.node == node && s.kind == kind)
            .or_else(|| steps.iter().rposition(|s| s.node == node))
            .map_or(1, |i| i + 1)
    }
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

/// One light's diffuse and specular terms at a hit of `rec`'s surface, from
/// the cosines N·L and R·V (R = 2(N·L)N − L) and the light `arriving`: the
/// lecture's Phong ("Directly From Light Source"),
/// k_d·(N·L)·color·light + k_s·(R·V)^shininess·light, nothing where N·L ≤ 0
/// and no highlight where R·V ≤ 0, as [`crate::shading::phong::direct`]
/// computes it. One function, so every diagnosis that remakes a local color
/// remakes the tracer's.
pub fn phong(rec: &LocalRecord, n_dot_l: f64, r_dot_v: f64, arriving: DVec3) -> (DVec3, DVec3) {
    if n_dot_l <= 0.0 {
        return (DVec3::ZERO, DVec3::ZERO);
    }
    let diffuse = rec.k_d * n_dot_l * rec.color * arriving;
    let specular = if rec.k_s > 0.0 && r_dot_v > 0.0 {
        rec.k_s * power(r_dot_v, rec.shininess) * arriving
    } else {
        DVec3::ZERO
    };
    (diffuse, specular)
}

/// What [`phong`]'s clamps at 0 remove: the diffuse term of a negative N·L,
/// or, where N·L ≥ 0, the highlight of a negative R·V, as a tracer that
/// forgets `max(0, …)` adds them. A negative R·V to a fractional shininess
/// has no real power (`powf` gives NaN): that highlight is left out, as the
/// clamp would.
pub fn unclamped_extra(
    rec: &LocalRecord,
    n_dot_l: f64,
    r_dot_v: f64,
    arriving: DVec3,
) -> (DVec3, DVec3) {
    if n_dot_l < 0.0 {
        return (rec.k_d * n_dot_l * rec.color * arriving, DVec3::ZERO);
    }
    let highlight = power(r_dot_v, rec.shininess);
    if r_dot_v < 0.0 && highlight.is_finite() {
        return (DVec3::ZERO, rec.k_s * highlight * arriving);
    }
    (DVec3::ZERO, DVec3::ZERO)
}

/// Object `index`'s roots along raytree's shadow ray `ours`, found with the
/// scene's intersection methods, as the tracer found them.
pub fn shadow_roots(ctx: &Context, index: usize, ours: &ShadowRecord) -> Roots {
    let ray = Ray::new(ours.origin, ours.direction);
    ctx.scene.objects[index].roots(&ray, ctx.scene.settings.intersection_methods())
}

/// Whether root `t` of raytree's shadow ray `ours` lies between the point and
/// the light: `0 < t < t_max`, `t_max` just short of the light at `t = 1`, as
/// the tracer's own shadow test takes it.
pub fn before_light(t: f64, ours: &ShadowRecord) -> bool {
    t > 0.0 && t < ours.t_max
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A negative R·V to the power 2.5 is NaN; the clamp a tracer forgot
    /// removes nothing there that a diagnosis could match.
    #[test]
    fn a_fractional_power_of_a_negative_cosine_adds_nothing() {
        let rec = LocalRecord {
            color: DVec3::ONE,
            k_a: 0.0,
            k_d: 0.5,
            k_s: 0.5,
            shininess: 2.5,
            ambient_light: DVec3::ZERO,
            ambient: DVec3::ZERO,
            lights: Vec::new(),
            total: DVec3::ZERO,
        };
        assert!((-0.5f64).powf(2.5).is_nan());
        assert_eq!(
            unclamped_extra(&rec, 0.5, -0.5, DVec3::ONE),
            (DVec3::ZERO, DVec3::ZERO)
        );
        let whole = LocalRecord {
            shininess: 3.0,
            ..rec.clone()
        };
        assert_eq!(
            unclamped_extra(&whole, 0.5, -0.5, DVec3::ONE).1,
            DVec3::splat(-0.0625)
        );
        assert_eq!(
            phong(&rec, 0.5, -0.5, DVec3::ONE),
            (DVec3::splat(0.25), DVec3::ZERO)
        );
    }
}
