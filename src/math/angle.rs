//! The angle between two directions, accurate at every angle.

use glam::DVec3;

/// The angle between `a` and `b`, in radians: `θ = atan2(|a × b|, a·b)`, for
/// vectors of any length.
///
/// The textbook `acos(a·b)` fails for nearly parallel vectors: `cos θ =
/// 1 − θ²/2 + …` is 1 to within the spacing of doubles near 1 once θ is below
/// about 1.5e-8 rad, so every such angle comes out 0, and even above that acos
/// magnifies the rounding of `a·b` by `1/sin θ` (pbrt-v4, §3.3.2, whose
/// `AngleBetween` uses `2·asin(|a − b|/2)` for unit vectors instead). Here
/// `|a × b|` carries `sin θ` and `a·b` carries `cos θ`, each with an error of a
/// few ULPs of `|a||b|`, and atan2 of the two keeps that accuracy at every
/// angle from 0 to π (Kahan, "Computing Cross-Products and Rotations in 2- and
/// 3-Dimensional Euclidean Spaces", §13, on accurate arctan formulas for the
/// angle between two vectors).
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_angles_are_resolved_where_acos_gives_zero() {
        // 1e-10 rad off the y axis: acos(cos θ) is acos(1) = 0. Tolerance:
        // the vectors are exact, so only atan2's rounding, ~1e-16 relative.
        let (a, b) = (DVec3::Y, DVec3::new(1e-10, 1.0, 0.0));
        assert_eq!(a.dot(b).acos(), 0.0);
        assert!((angle_between(a, b) / 1e-10 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn right_straight_and_scaled() {
        assert_eq!(
            angle_between(DVec3::X, DVec3::Y),
            std::f64::consts::FRAC_PI_2
        );
        assert_eq!(angle_between(DVec3::X, -DVec3::X), std::f64::consts::PI);
        assert_eq!(angle_between(DVec3::X, DVec3::X), 0.0);
        // Lengths do not matter: 45° between (2, 0, 0) and (3, 3, 0).
        let q = angle_between(DVec3::new(2.0, 0.0, 0.0), DVec3::new(3.0, 3.0, 0.0));
        assert!((q - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    }
}
