//! How numbers are written for a learner: short enough to read, precise enough
//! to follow the arithmetic, and readable at any scene scale. The JSON trace
//! keeps every digit; the text views use these.

use glam::DVec3;

/// Four significant digits; scientific notation outside 0.001–99999.
pub fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 {
        "0".to_owned()
    } else if !(1e-3..1e5).contains(&a) {
        format!("{x:.3e}")
    } else {
        let decimals = (3 - a.log10().floor() as i32).clamp(0, 6) as usize;
        let s = format!("{x:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            s
        }
    }
}

/// A vector or color as `(x, y, z)`.
pub fn vec3(v: DVec3) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// Below this, a color component cannot change any 8-bit pixel: one sRGB level
/// near black is about 3e-4 of linear light (1/255/12.92), so 1e-9 is far below
/// it. Views show such values as "≈ 0"; the JSON trace keeps them exact.
pub const NEGLIGIBLE: f64 = 1e-9;

/// A color component, or "≈ 0" when it is [`NEGLIGIBLE`] (but not exactly 0).
pub fn level(x: f64) -> String {
    if x != 0.0 && x.abs() < NEGLIGIBLE {
        "≈ 0".to_owned()
    } else {
        num(x)
    }
}

/// A color as `(r, g, b)`, negligible components as "≈ 0".
pub fn color(c: DVec3) -> String {
    format!("({}, {}, {})", level(c.x), level(c.y), level(c.z))
}

/// A number written as a factor in a product: negative ones in parentheses,
/// so `2 × (-0.9)` never reads as a subtraction.
pub fn factor(x: f64) -> String {
    if x < 0.0 {
        format!("({})", num(x))
    } else {
        num(x)
    }
}

/// An angle in degrees: `27.25°`.
pub fn degrees(x: f64) -> String {
    format!("{}°", num(x))
}

/// A count with thousands separators, `1234567` as `1,234,567`: how the
/// counts a learner compares (rays, tests, photons) are printed.
pub fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, d) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(d);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_grouped_by_thousands() {
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(thousands(1_234_567), "1,234,567");
    }

    #[test]
    fn numbers_keep_four_significant_digits() {
        assert_eq!(num(3.11849), "3.118");
        assert_eq!(num(0.5), "0.5");
        assert_eq!(num(12.0), "12");
        assert_eq!(num(-0.012345), "-0.01235");
        assert_eq!(num(1234.567), "1235");
        assert_eq!(num(2.5e-7), "2.500e-7");
        assert_eq!(num(0.0), "0");
        assert_eq!(vec3(DVec3::new(1.0, 0.25, -2.0)), "(1, 0.25, -2)");
        assert_eq!(color(DVec3::new(0.5, 2.1e-185, 0.0)), "(0.5, ≈ 0, 0)");
        assert_eq!(level(4.5e-8), "4.500e-8");
    }
}
