//! Ray–sphere intersection.
//!
//! The lecture substitutes the ray into `|P - C|² = r²` and solves the quadratic
//! `A t² + 2B t + C = 0` with `t = (-B ± √(B² - AC)) / A`. Written that way, the
//! discriminant cancels catastrophically for a far or grazing ray, and the `-B + √…`
//! root cancels when `|B| ≫ √(B² - AC)`. [`Sphere::roots`] uses the stable form of
//! Ray Tracing Gems (Haines et al., ch. 7, "Precision Improvements for Ray/Sphere
//! Intersection"); [`Sphere::lecture_roots`] keeps the lecture's form for teaching.

use glam::DVec3;

use crate::geometry::hit::{Roots, Surface};
use crate::math::float::gamma;
use crate::math::ray::Ray;
use crate::methods::SphereMethod;

/// A sphere with a center and a radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Center `C`.
    pub center: DVec3,
    /// Radius `r > 0`.
    pub radius: f64,
}

/// The lecture's quadratic for a ray against the unit sphere at the origin
/// (see [`Sphere::unit_quadratic`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitQuadratic {
    /// `S₁`, the ray's origin in the unit sphere's frame.
    pub origin: DVec3,
    /// `c₁`, its direction there.
    pub direction: DVec3,
    /// `A = |c₁|²`.
    pub a: f64,
    /// `B = S₁·c₁`.
    pub b: f64,
    /// `C = |S₁|² - 1`.
    pub c: f64,
    /// `B² - AC`: below 0 no root, 0 one, above 0 two.
    pub discriminant: f64,
}

impl Sphere {
    /// The roots by the scene's chosen method: [`Sphere::roots`] or
    /// [`Sphere::lecture_roots`].
    #[inline]
    pub fn roots_by(&self, ray: &Ray, method: SphereMethod) -> Roots {
        if method == SphereMethod::Lecture {
            self.lecture_roots(ray)
        } else {
            self.roots(ray)
        }
    }

    /// The stable roots (Ray Tracing Gems, ch. 7, eq. 7.11–7.13): with `f = S - C`,
    /// `a = c·c` and `b = f·c`, the discriminant is `Δ = r² - |f - (b/a)c|²`, the
    /// squared distance from the center to the line subtracted from `r²` (no
    /// cancellation between two large squares), and the roots are `q/a` and `C/q`
    /// with `q = -(b + sign(b)·√(aΔ))`, so neither is a difference of near-equal
    /// numbers. The direction need not be unit length: a miss costs one division
    /// and no square root.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let d = ray.dir;
        let a = d.length_squared();
        let f = ray.origin - self.center;
        let b = f.dot(d);
        let perp = f - (b / a) * d;
        let r2 = self.radius * self.radius;
        let disc = r2 - perp.length_squared();
        if disc < 0.0 {
            return Roots::NONE;
        }
        if disc == 0.0 {
            return Roots::one(-b / a);
        }
        let c = f.length_squared() - r2;
        let q = -(b + b.signum() * (a * disc).sqrt());
        Roots::two(c / q, q / a)
    }

    /// The lecture's roots as written: `A = |c|²`, `B = f·c`, `C = |f|² - r²`,
    /// `t = (-B ± √(B² - AC)) / A`. Fails for far and grazing rays; kept to show why.
    pub fn lecture_roots(&self, ray: &Ray) -> Roots {
        let f = ray.origin - self.center;
        let a = ray.dir.length_squared();
        let b = f.dot(ray.dir);
        let c = f.length_squared() - self.radius * self.radius;
        let disc = b * b - a * c;
        if disc < 0.0 {
            Roots::NONE
        } else if disc == 0.0 {
            Roots::one(-b / a)
        } else {
            let s = disc.sqrt();
            Roots::two((-b - s) / a, (-b + s) / a)
        }
    }

    /// The lecture's quadratic `A t² + 2B t + C = 0` for the unit sphere at the
    /// origin: the ray moved into this sphere's frame and scaled by its radius
    /// (`S₁ = (S - center)/r`, `c₁ = c/r`), so `A = |c₁|²`, `B = S₁·c₁`,
    /// `C = |S₁|² - 1`. Its `B² - AC` is what a trace prints and what
    /// `raytree render --aov discriminant` maps; its sign is the sign of
    /// [`Sphere::lecture_roots`]'s discriminant (they differ by the factor `r⁴`).
    pub fn unit_quadratic(&self, ray: &Ray) -> UnitQuadratic {
        let origin = (ray.origin - self.center) / self.radius;
        let direction = ray.dir / self.radius;
        let a = direction.length_squared();
        let b = origin.dot(direction);
        let c = origin.length_squared() - 1.0;
        UnitQuadratic {
            origin,
            direction,
            a,
            b,
            c,
            discriminant: b * b - a * c,
        }
    }

    /// The surface at `ray.at(t)`. The point is projected back onto the sphere,
    /// which leaves an error of a few ULPs of its own size whatever the ray's
    /// origin (pbrt-v4 §6.8.5), and that bound goes with it.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        let mut local = ray.at(t) - self.center;
        let mut length = local.length();
        // A sphere far below the precision of the ray (radius 1e-9 seen from
        // 1e9 away) can have its hit rounded onto its center, which gives no
        // direction to project along: take the side that faces the ray.
        if !(length > 0.0 && length.is_finite()) {
            local = -ray.dir;
            length = local.length();
        }
        local *= self.radius / length;
        let point = self.center + local;
        Surface {
            point,
            // Relative to the whole point (see `Plane::surface`): never zero, never subnormal.
            point_error: DVec3::splat(
                gamma(5) * self.radius + gamma(2) * point.abs().max_element(),
            ),
            normal: local / self.radius,
            shading_normal: local / self.radius,
            pattern_point: point,
        }
    }

    /// Whether `p` is strictly inside.
    pub fn contains(&self, p: DVec3) -> bool {
        (p - self.center).length_squared() < self.radius * self.radius
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Sphere {
        Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        }
    }

    /// Seen from 1e9 away, a sphere of radius 1e-9 is met at its center to
    /// the last bit: the surface is still a point on it, facing the ray.
    #[test]
    fn a_hit_rounded_onto_the_center_faces_the_ray() {
        let s = Sphere {
            center: DVec3::ZERO,
            radius: 1e-9,
        };
        let ray = Ray::new(DVec3::new(0.0, 0.0, 1e9), DVec3::NEG_Z);
        assert_eq!(ray.at(1e9), DVec3::ZERO);
        let surface = s.surface(&ray, 1e9);
        assert!(surface.point.is_finite() && surface.point_error.is_finite());
        assert_eq!(surface.normal, DVec3::Z);
        assert_eq!(surface.point, DVec3::new(0.0, 0.0, 1e-9));
    }

    #[test]
    fn quadratic_has_two_one_or_no_solutions() {
        let s = unit();
        for roots in [
            s.roots(&Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z)),
            s.lecture_roots(&Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z)),
        ] {
            // From z = -5 along +z the unit sphere is met at z = -1 and z = +1: t = 4, 6.
            assert_eq!(roots.as_slice(), &[4.0, 6.0]);
        }
        // Tangent: the line x = 1 touches the sphere at (1, 0, 0), t = 5.
        let tangent = Ray::new(DVec3::new(1.0, 0.0, -5.0), DVec3::Z);
        assert_eq!(s.lecture_roots(&tangent).as_slice(), &[5.0]);
        assert_eq!(s.roots(&tangent).as_slice(), &[5.0]);
        // Miss: x = 1.5 never reaches the sphere.
        let miss = Ray::new(DVec3::new(1.5, 0.0, -5.0), DVec3::Z);
        assert!(
            s.roots(&miss).as_slice().is_empty() && s.lecture_roots(&miss).as_slice().is_empty()
        );
    }

    #[test]
    fn closest_positive_root_from_inside_is_the_far_one() {
        // From the center, the roots are -1 and +1; only +1 is ahead of the ray.
        let roots = unit().roots(&Ray::new(DVec3::ZERO, DVec3::X));
        assert_eq!(roots.as_slice(), &[-1.0, 1.0]);
        assert_eq!(roots.first_in(0.0, f64::INFINITY), Some(1.0));
        // Sphere behind the ray: both roots negative, no hit.
        let behind = unit().roots(&Ray::new(DVec3::new(0.0, 0.0, 5.0), DVec3::Z));
        assert_eq!(behind.first_in(0.0, f64::INFINITY), None);
    }

    #[test]
    fn t_is_measured_in_units_of_the_direction() {
        // A direction of length 2 halves t: the same points, t = 2 and 3.
        let roots = unit().roots(&Ray::new(
            DVec3::new(0.0, 0.0, -5.0),
            DVec3::new(0.0, 0.0, 2.0),
        ));
        assert_eq!(roots.as_slice(), &[2.0, 3.0]);
    }

    #[test]
    fn stable_form_holds_far_away_where_the_lecture_form_does_not() {
        // From 1e9 away, a ray aimed at the center must hit at distance 1e9 - 1.
        // B² and AC are ~1e36 and differ by ~1e18, below what f64 resolves there.
        let s = unit();
        let ray = Ray::new(DVec3::new(0.0, 0.0, -1e9), DVec3::Z);
        let t = s.roots(&ray).first_in(0.0, f64::INFINITY).unwrap();
        // Tolerance: the result can be no better than one ULP of 1e9 (≈1.2e-7).
        assert!((t - (1e9 - 1.0)).abs() < 1e-6, "{t}");
        let p = s.surface(&ray, t).point;
        assert!((p.length() - 1.0).abs() < 1e-15);
        let lecture = s.lecture_roots(&ray);
        let wrong = match lecture.first_in(0.0, f64::INFINITY) {
            Some(t) => (t - (1e9 - 1.0)).abs() > 1e-3,
            None => true,
        };
        assert!(
            wrong,
            "expected the lecture form to fail at 1e9: {lecture:?}"
        );
    }

    #[test]
    fn surface_normal_is_outward_and_unit() {
        let s = Sphere {
            center: DVec3::new(1.0, 2.0, 3.0),
            radius: 2.0,
        };
        let ray = Ray::new(DVec3::new(1.0, 2.0, -10.0), DVec3::Z);
        let t = s.roots(&ray).first_in(0.0, f64::INFINITY).unwrap();
        let surf = s.surface(&ray, t);
        // Worked out: the ray along x=1,y=2 enters at z = 3 - 2 = 1, t = 11, normal -z.
        assert!((t - 11.0).abs() < 1e-12);
        assert!((surf.normal - DVec3::NEG_Z).length() < 1e-15);
    }
}
