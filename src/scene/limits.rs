//! The ranges a scene's numbers must lie in, documented in `scenes/README.md`.
//! Within them every number the tracer computes stays finite, so a trace never
//! holds an infinity or a NaN (JSON has no way to write either):
//!
//! - Coordinates within ±1e9 and lengths from 1e-9 to 1e9: a distance is below
//!   4e9 and its square below 2e19; the unit-sphere test divides by a radius of
//!   at least 1e-9, so its numbers stay below 1e40. The same holds for every
//!   entry of a transform and of its inverse (at most 1e12), and for OBJ
//!   vertices.
//! - A field of view from 0.001° to 179.999° keeps `W` between 1e-5 and 2e5.
//! - Refractive indices from 0.01 to 100: `n₁/n₂` is at most 1e4, its square
//!   far from overflowing in Snell's law.
//! - Colors up to 1e6 and coefficients (`ambient`, `diffuse`, `specular`,
//!   `shininess`) up to 1e6: one light adds at most about 1e18 to a point's
//!   local color. With `reflective + transparent ≤ 1` a ray's weight never
//!   exceeds 1, so a pixel is at most `max_depth` (≤ 1000) local colors: even
//!   with a billion lights, below 1e30, where f64 reaches 1.8e308.

use glam::{DAffine3, DVec3};

/// Largest magnitude of a coordinate (a point's, a translation's, an OBJ vertex's).
pub const MAX_COORDINATE: f64 = 1e9;
/// Smallest length (a radius, a checker cell, the camera's `W`, `H`, `N`, a scale factor).
pub const MIN_LENGTH: f64 = 1e-9;
/// Largest length.
pub const MAX_LENGTH: f64 = 1e9;
/// Largest magnitude of an entry of an object's transform or of its inverse.
pub const MAX_TRANSFORM_ENTRY: f64 = 1e12;
/// Largest color component.
pub const MAX_COLOR: f64 = 1e6;
/// Largest `ambient`, `diffuse`, `specular` and `shininess`.
pub const MAX_COEFFICIENT: f64 = 1e6;
/// Refractive indices, smallest and largest.
pub const IOR: (f64, f64) = (0.01, 100.0);
/// Field of view in degrees, smallest and largest.
pub const FOV: (f64, f64) = (0.001, 179.999);

/// A point: every coordinate finite and within ±[`MAX_COORDINATE`].
pub fn point(p: DVec3) -> Result<DVec3, String> {
    if p.is_finite() && p.abs().max_element() <= MAX_COORDINATE {
        Ok(p)
    } else {
        Err(format!(
            "every coordinate must be within ±{MAX_COORDINATE:e}, got {}",
            show(p)
        ))
    }
}

/// A direction: within the coordinate range, not zero; returned as a unit vector.
pub fn direction(d: DVec3) -> Result<DVec3, String> {
    point(d)?
        .try_normalize()
        .ok_or_else(|| "must not be zero".to_owned())
}

/// A length from [`MIN_LENGTH`] to [`MAX_LENGTH`].
pub fn length(x: f64) -> Result<f64, String> {
    within(x, MIN_LENGTH, MAX_LENGTH)
}

/// `x` in `[low, high]`, or why not.
pub fn within(x: f64, low: f64, high: f64) -> Result<f64, String> {
    if (low..=high).contains(&x) {
        Ok(x)
    } else {
        Err(format!(
            "must be from {} to {}, got {}",
            num(low),
            num(high),
            num(x)
        ))
    }
}

/// A color: every component from 0 to [`MAX_COLOR`].
pub fn color(c: DVec3) -> Result<DVec3, String> {
    if c.is_finite() && c.min_element() >= 0.0 && c.max_element() <= MAX_COLOR {
        Ok(c)
    } else {
        Err(format!(
            "a color's components must be from 0 to {MAX_COLOR:e}, got {}",
            show(c)
        ))
    }
}

/// A scale step: each factor's size from [`MIN_LENGTH`] to [`MAX_LENGTH`]
/// (negative factors mirror).
pub fn scale(s: DVec3) -> Result<DVec3, String> {
    let a = s.abs();
    if s.is_finite() && a.min_element() >= MIN_LENGTH && a.max_element() <= MAX_LENGTH {
        Ok(s)
    } else {
        Err(format!(
            "each factor's size must be from {MIN_LENGTH:e} to {MAX_LENGTH:e}, got {}",
            show(s)
        ))
    }
}

/// A transform whose every entry, and every entry of its inverse, is at most
/// [`MAX_TRANSFORM_ENTRY`] in size.
pub fn transform(m: &DAffine3, inverse: &DAffine3) -> Result<(), String> {
    let largest = |a: &DAffine3| {
        a.to_cols_array()
            .iter()
            .fold(0.0f64, |acc, x| acc.max(x.abs()))
    };
    let (big, big_inverse) = (largest(m), largest(inverse));
    if big.is_finite() && big_inverse.is_finite() && big.max(big_inverse) <= MAX_TRANSFORM_ENTRY {
        Ok(())
    } else {
        Err(format!(
            "scales or moves too far: its entries and its inverse's must be at most {MAX_TRANSFORM_ENTRY:e} in size, got {:e} and {:e}",
            big, big_inverse
        ))
    }
}

/// A vector as the scene file writes it.
fn show(v: DVec3) -> String {
    format!("[{}, {}, {}]", num(v.x), num(v.y), num(v.z))
}

/// A number as short as it reads: `1e9`, `0.001`, `0.0001`, `-2`, `1e-5`,
/// `1e-300` (never 300 digits): how an error quotes a number. Written out
/// unless that takes more than two characters beyond the scientific form.
pub fn num(x: f64) -> String {
    let plain = format!("{x}");
    let sci = format!("{x:e}");
    if plain.len() > sci.len() + 2 {
        sci
    } else {
        plain
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_and_messages() {
        assert_eq!(point(DVec3::splat(1e9)), Ok(DVec3::splat(1e9)));
        assert_eq!(
            point(DVec3::new(2e9, 0.0, -1.0)).unwrap_err(),
            "every coordinate must be within ±1e9, got [2e9, 0, -1]"
        );
        assert_eq!(direction(DVec3::ZERO).unwrap_err(), "must not be zero");
        assert_eq!(direction(DVec3::new(0.0, 3.0, 0.0)), Ok(DVec3::Y));
        assert_eq!(length(0.0).unwrap_err(), "must be from 1e-9 to 1e9, got 0");
        assert_eq!(within(0.5, 0.01, 100.0), Ok(0.5));
        for (x, shown) in [(1e-300, "1e-300"), (-1e300, "-1e300"), (1e-4, "0.0001")] {
            assert_eq!(num(x), shown);
        }
        assert!(color(DVec3::new(0.0, 1e7, 0.0)).is_err());
        assert!(color(DVec3::new(0.0, -0.1, 0.0)).is_err());
        assert!(scale(DVec3::new(-2.0, 1.0, 1.0)).is_ok());
        assert!(scale(DVec3::new(0.0, 1.0, 1.0)).is_err());
        let m = DAffine3::from_scale(DVec3::splat(1e-9))
            * DAffine3::from_translation(DVec3::splat(1e9));
        assert!(transform(&m, &m.inverse()).is_ok());
        let far = DAffine3::from_translation(DVec3::splat(1e9))
            * DAffine3::from_scale(DVec3::splat(1e-9));
        assert!(transform(&far, &far.inverse()).is_err());
    }
}
