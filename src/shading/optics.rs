//! The optics of the secondary rays: the mirror reflection, Snell's refraction
//! and total internal reflection, how a transparent surface shares its light
//! between the two (the lecture's constant weights, Schlick, Fresnel), and the
//! stack of media a ray is inside.

use glam::DVec3;

use crate::methods::Weights;
use crate::shading::material::Material;

/// The lecture's reflected direction `v = c - 2(n·c)n` for incoming direction `c`
/// and unit normal `n` (either side; the formula is the same).
pub fn reflect(c: DVec3, n: DVec3) -> DVec3 {
    c - 2.0 * n.dot(c) * n
}

/// The refracted direction by Snell's law `n₁ sin θ₁ = n₂ sin θ₂` in vector form
/// (Heckbert's derivation; pbrt-v4 §9.3.2): for unit incoming `i`, unit normal `n`
/// facing it (`n·i < 0`) and `eta = n₁/n₂`,
/// `t = eta·i + (eta·cos θ₁ - cos θ₂)·n` with `cos θ₂ = √(1 - eta²(1 - cos² θ₁))`.
/// `None` is total internal reflection: `sin θ₂` would exceed 1.
pub fn refract(i: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let cos_i = -n.dot(i);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(eta * i + (eta * cos_i - cos_t) * n)
}

/// What a surface passes on: the directions of its reflected and refracted rays
/// and their weights in `color = local + k_rfl·reflected + k_rfa·refracted`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shares {
    /// Weight of the reflected ray.
    pub k_rfl: f64,
    /// Weight of the refracted ray.
    pub k_rfa: f64,
    /// The mirror direction `v = c - 2(n·c)n`.
    pub reflected: DVec3,
    /// The refracted direction; `None` for an opaque surface or total internal reflection.
    pub refracted: Option<DVec3>,
    /// The material's `k_rfa` before it was split: the share a total internal
    /// reflection hands to the reflected ray.
    pub transmitted: f64,
    /// The refracted ray is impossible (`sin θ₂` would exceed 1): its share went
    /// to the reflected ray.
    pub total_internal: bool,
}

/// The shares at a surface of `material` for unit incoming `c`, unit normal `n`
/// facing it, and indices `n1 → n2`. With reflectance `R` (0 for the lecture's
/// constant weights, 1 under total internal reflection), the reflected ray gets
/// `k_rfl + k_rfa·R` and the refracted ray `k_rfa·(1 - R)`: the transmitted
/// light is never lost or doubled.
#[inline(always)]
pub fn shares(
    c: DVec3,
    n: DVec3,
    (n1, n2): (f64, f64),
    material: &Material,
    weights: Weights,
) -> Shares {
    let (mut k_rfl, mut k_rfa) = (material.reflective, material.transparent);
    let refracted = if k_rfa > 0.0 {
        refract(c, n, n1 / n2)
    } else {
        None
    };
    let total_internal = k_rfa > 0.0 && refracted.is_none();
    if k_rfa > 0.0 {
        let r = if total_internal {
            1.0
        } else {
            reflectance(weights, -c.dot(n), n1, n2)
        };
        k_rfl += k_rfa * r;
        k_rfa *= 1.0 - r;
    }
    Shares {
        k_rfl,
        k_rfa,
        reflected: reflect(c, n),
        refracted,
        transmitted: material.transparent,
        total_internal,
    }
}

/// The reflectance `R` under `weights` for light arriving at `cos_i` (cosine of
/// the angle to the normal, on the incoming side) from index `n1` into index `n2`.
pub fn reflectance(weights: Weights, cos_i: f64, n1: f64, n2: f64) -> f64 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let eta = n1 / n2;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    match weights {
        Weights::Constant => 0.0,
        Weights::Schlick => schlick(cos_i, cos_t, n1, n2),
        Weights::Fresnel => fresnel_dielectric(cos_i, cos_t, n1, n2),
    }
}

/// Schlick's approximation ("An Inexpensive BRDF Model for Physically-based
/// Rendering", 1994): `R = R₀ + (1 - R₀)(1 - cos θ)⁵`, `R₀ = ((n₁ - n₂)/(n₁ + n₂))²`.
/// Going into a less dense medium, θ is the transmitted angle (de Greve,
/// "Reflections and Refractions in Ray Tracing", 2006), else it misses the
/// rise of `R` toward the critical angle.
pub fn schlick(cos_i: f64, cos_t: f64, n1: f64, n2: f64) -> f64 {
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    let c = if n1 > n2 { cos_t } else { cos_i };
    r0 + (1.0 - r0) * (1.0 - c).powi(5)
}

/// The Fresnel equations for unpolarized light at a dielectric boundary (pbrt-v4
/// §9.3.2, `FrDielectric`): the mean of the parallel and perpendicular reflectances
/// `r∥ = (n₂ cos θᵢ - n₁ cos θₜ)/(n₂ cos θᵢ + n₁ cos θₜ)`,
/// `r⊥ = (n₁ cos θᵢ - n₂ cos θₜ)/(n₁ cos θᵢ + n₂ cos θₜ)`.
pub fn fresnel_dielectric(cos_i: f64, cos_t: f64, n1: f64, n2: f64) -> f64 {
    let parallel = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    let perpendicular = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    (parallel * parallel + perpendicular * perpendicular) / 2.0
}

/// How deep transparent objects may nest (glass in water in glass…) before the
/// innermost are no longer tracked.
pub const MAX_NESTED_MEDIA: usize = 8;

/// The transparent objects a ray is inside, innermost last. The medium a ray
/// travels through is the innermost's; outside all of them it is air (n = 1).
/// A small copyable stack so each ray carries its own without allocating.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Media {
    len: u8,
    objects: [u32; MAX_NESTED_MEDIA],
}

impl Media {
    /// The objects, outermost first.
    pub fn as_slice(&self) -> &[u32] {
        &self.objects[..usize::from(self.len)]
    }

    /// Whether the ray is inside `object`, as far as the stack knows.
    pub fn holds(&self, object: usize) -> bool {
        self.as_slice().contains(&(object as u32))
    }

    /// Whether the stack is full: an object entered now would not be kept, so
    /// an object it lacks may still be around the ray.
    pub fn is_full(&self) -> bool {
        usize::from(self.len) == MAX_NESTED_MEDIA
    }

    /// The innermost object, if any.
    pub fn innermost(&self) -> Option<usize> {
        self.as_slice().last().map(|&o| o as usize)
    }

    /// The stack after entering `object`.
    pub fn entered(mut self, object: usize) -> Self {
        if usize::from(self.len) < MAX_NESTED_MEDIA {
            self.objects[usize::from(self.len)] = object as u32;
            self.len += 1;
        }
        self
    }

    /// The stack on the far side of `object`'s surface: entered, or left.
    pub fn crossed(self, object: usize, entering: bool) -> Self {
        if entering {
            self.entered(object)
        } else {
            self.left(object)
        }
    }

    /// The stack after leaving `object` (wherever it sits in the stack: media
    /// need not be left in the order they were entered).
    pub fn left(mut self, object: usize) -> Self {
        if let Some(pos) = self.as_slice().iter().rposition(|&o| o as usize == object) {
            self.objects
                .copy_within(pos + 1..usize::from(self.len), pos);
            self.len -= 1;
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_mirrors_about_the_normal() {
        // Down-right onto a floor: (1, -1, 0) reflects to (1, 1, 0).
        assert_eq!(
            reflect(DVec3::new(1.0, -1.0, 0.0), DVec3::Y),
            DVec3::new(1.0, 1.0, 0.0)
        );
        // Same result with the normal flipped.
        assert_eq!(
            reflect(DVec3::new(1.0, -1.0, 0.0), DVec3::NEG_Y),
            DVec3::new(1.0, 1.0, 0.0)
        );
        // Head-on: straight back.
        assert_eq!(reflect(DVec3::NEG_Z, DVec3::Z), DVec3::Z);
    }

    #[test]
    fn snell_bends_toward_the_normal_entering_glass() {
        // 45° from air (1.0) into glass (1.5): sin θ₂ = sin 45° / 1.5 = 0.4714045.
        let i = DVec3::new(1.0, -1.0, 0.0).normalize();
        let t = refract(i, DVec3::Y, 1.0 / 1.5).unwrap();
        assert!((t.length() - 1.0).abs() < 1e-15);
        let sin_t = t.x;
        // Tolerance: a few ULPs of the arithmetic above.
        assert!(
            (sin_t - 45f64.to_radians().sin() / 1.5).abs() < 1e-15,
            "{sin_t}"
        );
        assert!(t.y < 0.0);
        // Head-on passes straight through.
        assert!(
            refract(DVec3::NEG_Y, DVec3::Y, 1.0 / 1.5)
                .unwrap()
                .abs_diff_eq(DVec3::NEG_Y, 1e-15)
        );
    }

    #[test]
    fn total_internal_reflection_at_and_around_the_critical_angle() {
        // Glass to air: critical angle asin(1/1.5) = 41.81°.
        let eta: f64 = 1.5;
        let critical = (1.0 / eta).asin();
        let dir = |theta: f64| DVec3::new(theta.sin(), -theta.cos(), 0.0);
        // Just below: refracts, leaving almost along the surface (sin θ₂ near 1).
        let below = refract(dir(critical - 1e-6), DVec3::Y, eta).unwrap();
        assert!(below.x > 0.999_99 && below.y <= 0.0, "{below}");
        // Just above and far above: no refracted ray.
        assert!(refract(dir(critical + 1e-6), DVec3::Y, eta).is_none());
        assert!(refract(dir(80f64.to_radians()), DVec3::Y, eta).is_none());
        // Into a denser medium there is never total internal reflection.
        assert!(refract(dir(89.9f64.to_radians()), DVec3::Y, 1.0 / eta).is_some());
    }

    #[test]
    fn fresnel_matches_known_values() {
        // Head-on into glass: ((1 - 1.5)/(1 + 1.5))² = 0.04, for both methods.
        assert!((reflectance(Weights::Fresnel, 1.0, 1.0, 1.5) - 0.04).abs() < 1e-15);
        assert!((reflectance(Weights::Schlick, 1.0, 1.0, 1.5) - 0.04).abs() < 1e-15);
        // Brewster's angle atan(1.5) = 56.31°: the parallel part vanishes, so R = r⊥²/2.
        // r⊥ = (cos θᵢ - 1.5 cos θₜ)/(cos θᵢ + 1.5 cos θₜ) with θₜ = 90° - θᵢ: (0.5547 - 1.5·0.8321)/(0.5547 + 1.5·0.8321) = -0.3846.
        let brewster = 1.5f64.atan();
        let r = reflectance(Weights::Fresnel, brewster.cos(), 1.0, 1.5);
        assert!((r - 0.384_615_4f64.powi(2) / 2.0).abs() < 1e-7, "{r}");
        // Grazing: everything reflects.
        assert!(reflectance(Weights::Fresnel, 1e-9, 1.0, 1.5) > 0.999_999);
        // Beyond the critical angle from inside glass: total internal reflection under every method.
        for w in [Weights::Constant, Weights::Schlick, Weights::Fresnel] {
            assert_eq!(reflectance(w, 0.5, 1.5, 1.0), 1.0);
        }
        assert_eq!(reflectance(Weights::Constant, 0.9, 1.0, 1.5), 0.0);
    }

    #[test]
    fn shares_hand_the_transmitted_light_to_the_reflection_under_total_internal_reflection() {
        let glass = Material {
            name: "glass".into(),
            pattern: crate::shading::material::Pattern::Solid(DVec3::ONE),
            ambient: 0.0,
            diffuse: 0.0,
            specular: 0.0,
            shininess: 1.0,
            reflective: 0.1,
            transparent: 0.8,
            ior: 1.5,
        };
        let at = |degrees: f64| {
            let a = degrees.to_radians();
            DVec3::new(a.sin(), -a.cos(), 0.0)
        };
        // 60° inside glass (n 1.5 → 1) is beyond the critical angle 41.81°.
        let s = shares(at(60.0), DVec3::Y, (1.5, 1.0), &glass, Weights::Constant);
        assert!(s.total_internal && s.refracted.is_none());
        assert_eq!((s.k_rfl, s.k_rfa, s.transmitted), (0.1 + 0.8, 0.0, 0.8));
        assert_eq!(s.reflected, reflect(at(60.0), DVec3::Y));
        // 30° refracts: the lecture's constant weights stay as they are.
        let s = shares(at(30.0), DVec3::Y, (1.5, 1.0), &glass, Weights::Constant);
        assert!(!s.total_internal && s.refracted.is_some());
        assert_eq!((s.k_rfl, s.k_rfa), (0.1, 0.8));
        // An opaque surface has no refracted ray and no total internal reflection.
        let mirror = Material {
            transparent: 0.0,
            ..glass
        };
        let s = shares(at(30.0), DVec3::Y, (1.0, 1.0), &mirror, Weights::Fresnel);
        assert!(!s.total_internal && s.refracted.is_none() && s.k_rfa == 0.0);
    }

    #[test]
    fn media_stack_enters_and_leaves_in_any_order() {
        let m = Media::default().entered(3).entered(5);
        assert_eq!(m.innermost(), Some(5));
        assert_eq!(m.left(5).innermost(), Some(3));
        assert_eq!(m.left(3).as_slice(), &[5]);
        assert_eq!(Media::default().left(2).as_slice(), &[] as &[u32]);
    }
}
