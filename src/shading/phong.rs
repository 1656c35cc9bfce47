//! The local illumination model: `I = I_ambient + I_diffuse + I_specular` (lecture,
//! "Directly From Light Source"), with Phong's specular term (Bui Tuong Phong,
//! "Illumination for Computer Generated Pictures", CACM 1975): the highlight is
//! `k_s · (R·V)^shininess`, with `R` the light direction mirrored about the normal.

use glam::DVec3;

use crate::shading::material::Material;

/// `k_a · color · ambient_light`: the light that arrives from everywhere.
pub fn ambient(material: &Material, color: DVec3, ambient_light: DVec3) -> DVec3 {
    material.ambient * color * ambient_light
}

/// What one light adds at a point its shadow ray reached, with the vectors and
/// dot products it was made from (the ray tree shows them so the sum can be
/// checked by hand).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Direct {
    /// `L`: the unit vector from the point to the light.
    pub to_light: DVec3,
    /// `V`: the unit vector from the point to the viewer.
    pub to_viewer: DVec3,
    /// The light's color as it arrives (after what the shadow ray let through).
    pub light: DVec3,
    /// `N·L`: the cosine of the light's angle to the normal; nothing is added where it is ≤ 0.
    pub n_dot_l: f64,
    /// `R = 2(N·L)N - L`: the light's direction mirrored about the normal (zero where `N·L ≤ 0`).
    pub mirrored: DVec3,
    /// `R·V`, at least 0: how close the viewer is to the mirror direction.
    pub r_dot_v: f64,
    /// `k_d · color · light · (N·L)`.
    pub diffuse: DVec3,
    /// `k_s · light · (R·V)^shininess`.
    pub specular: DVec3,
}

/// The diffuse and specular terms for unit normal `n` (facing the viewer), unit
/// direction to the light `l`, unit direction to the viewer `v`, and the light's
/// color as it arrives (already scaled by what the shadow ray let through).
#[inline]
pub fn direct(
    material: &Material,
    color: DVec3,
    n: DVec3,
    l: DVec3,
    v: DVec3,
    light: DVec3,
) -> Direct {
    let n_dot_l = n.dot(l);
    let unlit = Direct {
        to_light: l,
        to_viewer: v,
        light,
        n_dot_l,
        ..Direct::default()
    };
    if n_dot_l <= 0.0 {
        return unlit;
    }
    let r = mirrored(n, l, n_dot_l);
    let r_dot_v = r.dot(v).max(0.0);
    let (diffuse, specular) = Reflectance::of(material, color).terms(n_dot_l, r_dot_v, light);
    Direct {
        mirrored: r,
        r_dot_v,
        diffuse,
        specular,
        ..unlit
    }
}

/// `R = 2(N·L)N − L`: the direction to the light `l` mirrored about the unit
/// normal `n`, given their cosine `n_dot_l`.
#[inline]
pub fn mirrored(n: DVec3, l: DVec3, n_dot_l: f64) -> DVec3 {
    2.0 * n_dot_l * n - l
}

/// What Phong's direct terms read of the surface at a hit: its color there and
/// the material's `k_d`, `k_s` and shininess. The tracer makes one from the
/// material ([`Reflectance::of`]); the learner check from the recorded local
/// color, so that a diagnosis remakes the tracer's own terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflectance {
    /// The surface's color at the hit.
    pub color: DVec3,
    /// `k_d`, the diffuse coefficient.
    pub k_d: f64,
    /// `k_s`, the specular coefficient.
    pub k_s: f64,
    /// The highlight's exponent.
    pub shininess: f64,
}

impl Reflectance {
    /// The material's coefficients, with its color at the hit.
    #[inline]
    pub fn of(material: &Material, color: DVec3) -> Self {
        Reflectance {
            color,
            k_d: material.diffuse,
            k_s: material.specular,
            shininess: material.shininess,
        }
    }

    /// `k_d · (N·L) · color · light`, Lambert's term, unclamped: [`Self::terms`]
    /// adds nothing where `N·L ≤ 0`, a tracer that forgets the clamp adds this.
    #[inline]
    pub fn diffuse(&self, n_dot_l: f64, light: DVec3) -> DVec3 {
        self.k_d * n_dot_l * self.color * light
    }

    /// `k_s · (R·V)^shininess`, the highlight's strength, unclamped (for a
    /// negative `R·V` and a fractional shininess it is NaN).
    #[inline]
    pub fn highlight(&self, r_dot_v: f64) -> f64 {
        self.k_s * power(r_dot_v, self.shininess)
    }

    /// One light's diffuse and specular terms from the cosines `N·L` and `R·V`
    /// and the light as it arrives: the lecture's
    /// `k_d·(N·L)·color·light + k_s·(R·V)^shininess·light`, nothing where
    /// `N·L ≤ 0` and no highlight where `R·V ≤ 0` (or `k_s` is 0).
    #[inline]
    pub fn terms(&self, n_dot_l: f64, r_dot_v: f64, light: DVec3) -> (DVec3, DVec3) {
        if n_dot_l <= 0.0 {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        let highlight = if self.k_s > 0.0 && r_dot_v > 0.0 {
            self.highlight(r_dot_v)
        } else {
            0.0
        };
        (self.diffuse(n_dot_l, light), highlight * light)
    }
}

/// `x^e`: by repeated squaring (`powi`) when the exponent is a whole number, as
/// Phong exponents nearly always are, which costs a few multiplications instead
/// of a general `powf`. The two can differ in the last bits, far below what an
/// 8-bit pixel shows.
#[inline]
pub fn power(x: f64, e: f64) -> f64 {
    if e == e.trunc() && e.abs() <= 4096.0 {
        x.powi(e as i32)
    } else {
        x.powf(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shading::material::Pattern;

    fn material() -> Material {
        Material {
            name: "m".into(),
            pattern: Pattern::Solid(DVec3::ONE),
            ambient: 0.1,
            diffuse: 0.6,
            specular: 0.5,
            shininess: 10.0,
            reflective: 0.0,
            transparent: 0.0,
            ior: 1.0,
        }
    }

    #[test]
    fn diffuse_follows_lamberts_cosine_and_highlight_peaks_at_the_mirror_direction() {
        let m = material();
        let color = DVec3::new(1.0, 0.5, 0.25);
        let n = DVec3::Y;
        // Light 60° from the normal: N·L = cos 60° = 0.5, diffuse = 0.6·0.5·color.
        let l = DVec3::new(60f64.to_radians().sin(), 60f64.to_radians().cos(), 0.0);
        // Viewer exactly along the mirror direction R = (-sin 60°, cos 60°, 0): R·V = 1.
        let v = DVec3::new(-l.x, l.y, 0.0);
        let d = direct(&m, color, n, l, v, DVec3::ONE);
        assert!((d.diffuse - 0.3 * color).length() < 1e-15);
        assert!((d.specular - DVec3::splat(0.5)).length() < 1e-15);
        // Viewer straight above: R·V = cos 60° = 0.5, highlight 0.5·0.5¹⁰.
        let d = direct(&m, color, n, l, DVec3::Y, DVec3::ONE);
        assert!((d.specular.x - 0.5 * 0.5f64.powi(10)).abs() < 1e-15);
    }

    #[test]
    fn whole_exponents_by_squaring_agree_with_powf() {
        // Tolerance: each squaring doubles the relative error carried so far, so the
        // roundings add up to about e half-ULPs: e·ε relative (9e-13 at e = 4096,
        // 4.4e-14 at 200, where an 8-bit pixel resolves 4e-3).
        for e in [1.0, 2.0, 10.0, 200.0, 4096.0, 2.5] {
            for x in [0.1, 0.5, 0.9232, 0.999] {
                let (fast, exact) = (power(x, e), x.powf(e));
                let tolerance = e.max(1.0) * f64::EPSILON * exact;
                assert!((fast - exact).abs() <= tolerance, "{x}^{e}: {fast} {exact}");
            }
        }
    }

    #[test]
    fn light_behind_the_surface_adds_nothing() {
        let d = direct(
            &material(),
            DVec3::ONE,
            DVec3::Y,
            DVec3::NEG_Y,
            DVec3::Y,
            DVec3::ONE,
        );
        assert_eq!((d.diffuse, d.specular), (DVec3::ZERO, DVec3::ZERO));
        assert_eq!(d.n_dot_l, -1.0);
    }
}
