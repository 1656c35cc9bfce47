//! Floating-point error bounds and the robust ray-origin offset.
//!
//! A hit point computed in floating point lies a little off the surface. A new ray
//! started there can hit the same surface again ("shadow acne"); the textbook fix is
//! to move the origin by a fixed epsilon, which is too small for a large scene and
//! too large for a small one. Instead each hit carries a bound on its own error and
//! secondary rays start just outside that bound, on the side they leave into
//! (pbrt-v4, Pharr, Jakob & Humphreys, §6.8.4–6.8.6). No scene needs an epsilon.

use glam::DVec3;

/// Half an ULP at 1.0: the unit roundoff of an f64 operation.
pub const MACHINE_EPSILON: f64 = f64::EPSILON * 0.5;

/// pbrt's γ(n) = nε / (1 − nε): the relative error bound after n rounded operations.
pub fn gamma(n: u32) -> f64 {
    let ne = f64::from(n) * MACHINE_EPSILON;
    ne / (1.0 - ne)
}

/// Moves `p` off its surface along the unit normal `n` by the error bound
/// `p_error`, toward the side that direction `w` leaves into, then rounds each
/// component one more ULP away (pbrt-v4's `OffsetRayOrigin`). Unlike pbrt, the
/// last ULP is taken even when the bound is zero, so the origin always leaves the
/// surface.
#[inline]
pub fn offset_ray_origin(p: DVec3, p_error: DVec3, n: DVec3, w: DVec3) -> DVec3 {
    let side = if w.dot(n) < 0.0 { -n } else { n };
    let po = p + n.abs().dot(p_error) * side;
    DVec3::new(
        one_ulp_toward(po.x, side.x),
        one_ulp_toward(po.y, side.y),
        one_ulp_toward(po.z, side.z),
    )
}

/// `x` moved one ULP in the direction of `s`'s sign (not at all for a zero `s`).
#[inline(always)]
fn one_ulp_toward(x: f64, s: f64) -> f64 {
    if s > 0.0 {
        x.next_up()
    } else if s < 0.0 {
        x.next_down()
    } else {
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_moves_to_the_side_the_ray_leaves_into() {
        let p = DVec3::new(1.0, 0.0, 2.0);
        let err = DVec3::splat(1e-12);
        let n = DVec3::Y;
        let up = offset_ray_origin(p, err, n, DVec3::new(0.3, 1.0, 0.0));
        let down = offset_ray_origin(p, err, n, DVec3::new(0.3, -1.0, 0.0));
        assert!(up.y > 1e-12 && down.y < -1e-12, "{up} {down}");
        // Only the normal's component moves.
        assert_eq!((up.x, up.z), (p.x, p.z));
    }

    #[test]
    fn offset_moves_even_with_zero_error() {
        let p = DVec3::new(0.5, 3.0, -1.0);
        let po = offset_ray_origin(p, DVec3::ZERO, DVec3::Y, DVec3::Y);
        assert!(po.y > p.y);
    }

    #[test]
    fn gamma_grows_with_the_number_of_operations() {
        assert!(gamma(1) > MACHINE_EPSILON && gamma(3) > 2.9 * MACHINE_EPSILON);
        assert!(gamma(5) < 5.1 * MACHINE_EPSILON);
    }
}
