//! Transformed primitives, the lecture's way: to intersect `S + t·c` with `M·F`,
//! intersect the inverse-transformed ray `M⁻¹S + t·M⁻¹c` with `F`; the same `t`
//! then names the hit on the original ray. Normals go through the inverse
//! transpose of `M`'s linear part, because they must stay perpendicular to the
//! transformed surface.

use glam::{DAffine3, DMat3};

use crate::geometry::hit::Surface;
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// An invertible affine map from object space to world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// `M`: object space to world space.
    pub to_world: DAffine3,
    /// `M⁻¹`: world space to object space.
    pub to_object: DAffine3,
    /// `(M⁻¹)ᵀ` of the linear part: object normals to world normals.
    pub normal_to_world: DMat3,
}

impl Transform {
    /// The transform `m`, or `None` when it cannot be inverted: its determinant is
    /// zero or negligible next to the size of its columns, or its inverse is not finite.
    pub fn new(m: DAffine3) -> Option<Self> {
        let l = m.matrix3;
        let scale = l.x_axis.length() * l.y_axis.length() * l.z_axis.length();
        let det = l.determinant();
        if !(scale.is_finite() && det.is_finite()) || det.abs() <= 1e-12 * scale || scale == 0.0 {
            return None;
        }
        let inv = m.inverse();
        if !inv.is_finite() {
            return None;
        }
        Some(Self {
            to_world: m,
            to_object: inv,
            normal_to_world: inv.matrix3.transpose(),
        })
    }

    /// The inverse-transformed ray `S' + t·c'` (lecture, "Final Intersection"):
    /// the point `S` transforms with translation, the direction `c` without.
    #[inline]
    pub fn ray_to_object(&self, ray: &Ray) -> Ray {
        Ray::new(
            self.to_object.transform_point3(ray.origin),
            self.to_object.transform_vector3(ray.dir),
        )
    }

    /// A surface computed in object space, carried to world space. The point is
    /// the transformed object-space point, which is the lecture's `S + t·c` on the
    /// world ray up to rounding; its error bound is pbrt-v4's for a transformed
    /// point with error (§6.8.3).
    pub fn surface_to_world(&self, s: Surface) -> Surface {
        let abs_m = DMat3::from_cols(
            self.to_world.matrix3.x_axis.abs(),
            self.to_world.matrix3.y_axis.abs(),
            self.to_world.matrix3.z_axis.abs(),
        );
        let point = self.to_world.transform_point3(s.point);
        let point_error = (gamma(3) + 1.0) * (abs_m * s.point_error)
            + gamma(3) * (abs_m * s.point.abs() + self.to_world.translation.abs());
        Surface {
            point,
            point_error,
            normal: (self.normal_to_world * s.normal).normalize(),
            shading_normal: (self.normal_to_world * s.shading_normal).normalize(),
            pattern_point: s.pattern_point,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::sphere::Sphere;
    use glam::DVec3;

    #[test]
    fn inverse_transformed_ray_hits_an_ellipsoid_at_the_right_t() {
        // Unit sphere scaled by (2, 1, 1) then moved to (5, 0, 0): an ellipsoid
        // spanning x = 3..7. A ray from the origin along +x enters at x = 3, t = 3.
        let m = DAffine3::from_translation(DVec3::new(5.0, 0.0, 0.0))
            * DAffine3::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let tf = Transform::new(m).unwrap();
        let ray = Ray::new(DVec3::ZERO, DVec3::X);
        let local = tf.ray_to_object(&ray);
        // Worked out: M⁻¹ takes (0,0,0) to ((0-5)/2, 0, 0) = (-2.5, 0, 0), and +x to (0.5, 0, 0).
        assert_eq!(local.origin, DVec3::new(-2.5, 0.0, 0.0));
        assert_eq!(local.dir, DVec3::new(0.5, 0.0, 0.0));
        let unit = Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        };
        let roots = unit.roots(&local);
        assert_eq!(roots.as_slice(), &[3.0, 7.0]);
        let s = tf.surface_to_world(unit.surface(&local, 3.0));
        assert!((s.point - ray.at(3.0)).length() < 1e-14);
    }

    #[test]
    fn normals_go_through_the_inverse_transpose() {
        // Ellipsoid x²/4 + y² = 1 (scale x by 2). At the world point (√2, √2/2, 0) the
        // gradient of the implicit function is (x/2, 2y, 0) = (√2/2, √2, 0) ∝ (1, 2, 0);
        // transforming the object normal by M itself would give (2, 1, 0) instead.
        let tf = Transform::new(DAffine3::from_scale(DVec3::new(2.0, 1.0, 1.0))).unwrap();
        let local_n = DVec3::new(1.0, 1.0, 0.0).normalize();
        let s = Surface {
            point: local_n,
            point_error: DVec3::ZERO,
            normal: local_n,
            shading_normal: local_n,
            pattern_point: local_n,
        };
        let world = tf.surface_to_world(s);
        let expected = DVec3::new(1.0, 2.0, 0.0).normalize();
        assert!(
            (world.normal - expected).length() < 1e-15,
            "{}",
            world.normal
        );
    }

    #[test]
    fn singular_transforms_are_refused() {
        assert!(Transform::new(DAffine3::from_scale(DVec3::new(1.0, 0.0, 1.0))).is_none());
        assert!(Transform::new(DAffine3::from_scale(DVec3::new(1.0, f64::NAN, 1.0))).is_none());
        assert!(Transform::new(DAffine3::from_scale(DVec3::new(1e-4, 1.0, 1.0))).is_some());
    }
}
