//! Materials: a color or a checkerboard, and the coefficients of the lecture's
//! local model and recursion.

use glam::DVec3;

/// Where a material's color comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pattern {
    /// One color.
    Solid(DVec3),
    /// Alternating boxes of sides `size`, in object space (rectangles on a plane).
    Checker {
        /// The two colors; `colors[0]` holds the cell at the origin.
        colors: [DVec3; 2],
        /// A cell's side along each axis (all three equal for cubes).
        size: DVec3,
    },
}

impl Pattern {
    /// The color at `p` (a surface's `pattern_point`).
    pub fn color_at(&self, p: DVec3) -> DVec3 {
        match *self {
            Pattern::Solid(c) => c,
            Pattern::Checker { colors, size } => colors[usize::from(odd_cell(p / size))],
        }
    }
}

/// Whether the unit cell holding `q` has an odd sum of integer coordinates. In
/// integers where the cells' coordinates fit (always, but for a point 2⁵¹ cells
/// out), which is exact and spares a `floor` and an `fmod` per hit; in floats
/// beyond, and for NaN, as the definition says.
#[inline]
fn odd_cell(q: DVec3) -> bool {
    const FITS: f64 = (1u64 << 51) as f64;
    if q.abs().cmplt(DVec3::splat(FITS)).all() {
        let floor = |x: f64| {
            let t = x as i64;
            if (t as f64) > x { t - 1 } else { t }
        };
        (floor(q.x) + floor(q.y) + floor(q.z)) & 1 == 1
    } else {
        let cell = q.floor();
        (cell.x + cell.y + cell.z).rem_euclid(2.0) != 0.0
    }
}

/// A surface's material. Colors are linear RGB; coefficients are plain factors.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Its name in the scene file.
    pub name: String,
    /// The surface color.
    pub pattern: Pattern,
    /// `k_a`: share of the ambient light reflected.
    pub ambient: f64,
    /// `k_d`: Lambertian (diffuse) reflection.
    pub diffuse: f64,
    /// `k_s`: Phong highlight strength.
    pub specular: f64,
    /// Phong exponent: larger is a smaller, sharper highlight.
    pub shininess: f64,
    /// `k_rfl`: weight of the reflected ray.
    pub reflective: f64,
    /// `k_rfa`: weight of the refracted ray; also the share of light a shadow ray
    /// keeps when it passes through this object.
    pub transparent: f64,
    /// Refractive index of the object's inside.
    pub ior: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checker_alternates_and_handles_negative_cells() {
        let c = Pattern::Checker {
            colors: [DVec3::X, DVec3::Y],
            size: DVec3::splat(2.0),
        };
        assert_eq!(c.color_at(DVec3::new(0.5, 0.0, 0.5)), DVec3::X);
        assert_eq!(c.color_at(DVec3::new(2.5, 0.0, 0.5)), DVec3::Y);
        assert_eq!(c.color_at(DVec3::new(-0.5, 0.0, 0.5)), DVec3::Y);
        assert_eq!(c.color_at(DVec3::new(-2.5, 0.0, -2.5)), DVec3::X);
        // On a cell boundary the cell above counts; far out and NaN take the float path.
        assert_eq!(c.color_at(DVec3::new(-2.0, 0.0, 0.0)), DVec3::Y);
        assert_eq!(c.color_at(DVec3::new(-0.0, 0.0, 0.0)), DVec3::X);
        assert_eq!(c.color_at(DVec3::new(1e300, 0.0, 0.0)), DVec3::X);
        assert_eq!(c.color_at(DVec3::NAN), DVec3::Y);
    }

    #[test]
    fn checker_cells_may_be_longer_along_one_axis() {
        // Cells 7 wide in x and 9 deep in z: x = 8 is in the second cell, z = 8 still in the first.
        let c = Pattern::Checker {
            colors: [DVec3::X, DVec3::Y],
            size: DVec3::new(7.0, 1.0, 9.0),
        };
        assert_eq!(c.color_at(DVec3::new(6.5, 0.0, 8.5)), DVec3::X);
        assert_eq!(c.color_at(DVec3::new(7.5, 0.0, 8.5)), DVec3::Y);
        assert_eq!(c.color_at(DVec3::new(6.5, 0.0, 9.5)), DVec3::Y);
        assert_eq!(c.color_at(DVec3::new(7.5, 0.0, -0.5)), DVec3::X);
    }
}
