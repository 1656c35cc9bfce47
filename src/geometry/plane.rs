//! Ray–plane intersection. A plane is the boundary of a half-space: its normal
//! points out of the solid, so a ray can enter and leave it like any other
//! object (as in POV-Ray), which keeps refraction and media tracking uniform.

use glam::DVec3;

use crate::geometry::hit::{Roots, Surface};
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// An infinite plane through `point` with unit `normal`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// Any point on the plane.
    pub point: DVec3,
    /// The unit normal, pointing out of the half-space.
    pub normal: DVec3,
}

impl Plane {
    /// Substituting the ray into `(P - P₀)·n = 0` gives `t = (P₀ - S)·n / (c·n)`.
    /// A ray parallel to the plane (`c·n = 0`) never meets it.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let denom = ray.dir.dot(self.normal);
        if denom == 0.0 {
            return Roots::NONE;
        }
        Roots::one((self.point - ray.origin).dot(self.normal) / denom)
    }

    /// The surface at `ray.at(t)`, projected back onto the plane so its error
    /// is a few ULPs of the point's own size, whatever the ray's origin.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        let p = ray.at(t);
        let point = p - (p - self.point).dot(self.normal) * self.normal;
        Surface {
            point,
            // Relative to the whole point, not per component: the projection mixes
            // components, and a zero bound would put the offset origin on a
            // subnormal number (5e-324), which every later operation pays for.
            point_error: DVec3::splat(
                gamma(8) * (point.abs().max_element() + self.point.abs().max_element()),
            ),
            normal: self.normal,
            shading_normal: self.normal,
            pattern_point: flatten(point, self.normal),
        }
    }

    /// Whether `p` is strictly inside the half-space.
    pub fn contains(&self, p: DVec3) -> bool {
        (p - self.point).dot(self.normal) < 0.0
    }
}

/// Drops the coordinate along the normal's largest axis, so a checkerboard on the
/// plane is a 2D pattern in the two other axes of the plane's own space (the
/// world's, unless the plane has a transform) and a point rounded a hair below
/// the plane can never fall into the next layer of 3D cells.
fn flatten(p: DVec3, n: DVec3) -> DVec3 {
    let a = n.abs();
    if a.x >= a.y && a.x >= a.z {
        DVec3::new(0.0, p.y, p.z)
    } else if a.y >= a.z {
        DVec3::new(p.x, 0.0, p.z)
    } else {
        DVec3::new(p.x, p.y, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ray_meets_floor_where_worked_out() {
        // Floor y = 0; from (0, 2, 0) along (1, -1, 0): reaches y = 0 at t = 2, x = 2.
        let floor = Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        };
        let ray = Ray::new(DVec3::new(0.0, 2.0, 0.0), DVec3::new(1.0, -1.0, 0.0));
        let t = floor.roots(&ray).first_in(0.0, f64::INFINITY).unwrap();
        assert_eq!(t, 2.0);
        let s = floor.surface(&ray, t);
        assert_eq!(s.point, DVec3::new(2.0, 0.0, 0.0));
        assert_eq!(s.pattern_point.y, 0.0);
    }

    #[test]
    fn parallel_ray_misses_and_ray_away_has_negative_root() {
        let floor = Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        };
        assert_eq!(floor.roots(&Ray::new(DVec3::Y, DVec3::X)), Roots::NONE);
        let away = floor.roots(&Ray::new(DVec3::Y, DVec3::Y));
        assert_eq!(away.first_in(0.0, f64::INFINITY), None);
    }
}
