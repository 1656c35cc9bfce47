//! The open cylinder or cone between two points, as an object: the unit cone
//! of [`crate::geometry::unit_cone`] and the transform placing it, the
//! lecture's transformed primitive. Its constructor is what the scene loader
//! and the NFF reader call.

use glam::{DAffine3, DMat3, DVec3};

use crate::geometry::object::{Object, Shape};
use crate::geometry::transform::Transform;
pub use crate::geometry::unit_cone::Cone;

/// What is wrong with a cone's numbers, and which of them.
#[derive(Clone, Debug, PartialEq)]
pub struct ConeError {
    /// The field at fault: `base`, `apex`, `base_radius`, `apex_radius`, or
    /// empty for the cone as a whole.
    pub field: &'static str,
    /// Why, in one line.
    pub message: String,
}

impl std::fmt::Display for ConeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

/// The unit cone and the map `M` placing it from `base` (radius `base_radius`)
/// to `apex` (radius `apex_radius`): `M = T(base)·R·S(r₀, r₀, length)`, `R`
/// turning `z` onto the axis. The wider end becomes the unit cone's `z = 0`,
/// so `s = r_narrow/r_wide`. The directions across the axis are made by Duff
/// et al.'s orthonormal basis ("Building an Orthonormal Basis, Revisited",
/// JCGT 2017), and `M`'s third column is `apex − base` itself.
pub fn cone_placement(
    base: DVec3,
    base_radius: f64,
    apex: DVec3,
    apex_radius: f64,
) -> Result<(Cone, DAffine3), ConeError> {
    let fail = |field, message: String| Err(ConeError { field, message });
    for (field, p) in [("base", base), ("apex", apex)] {
        if !p.is_finite() {
            return fail(field, format!("must be finite numbers, got {p}"));
        }
    }
    for (field, r) in [("base_radius", base_radius), ("apex_radius", apex_radius)] {
        if !r.is_finite() || r < 0.0 {
            return fail(
                field,
                format!("must be a finite number ≥ 0, got {}", short(r)),
            );
        }
    }
    if base_radius == 0.0 && apex_radius == 0.0 {
        return fail(
            "",
            "base_radius and apex_radius are both 0: the cone would be a line".to_owned(),
        );
    }
    if base == apex {
        return fail(
            "",
            "base and apex are the same point: the cone would have no length".to_owned(),
        );
    }
    let (wide, wide_radius, narrow, narrow_radius) = if base_radius >= apex_radius {
        (base, base_radius, apex, apex_radius)
    } else {
        (apex, apex_radius, base, base_radius)
    };
    let axis = narrow - wide;
    let (across, up) = axis.normalize().any_orthonormal_pair();
    let m = DAffine3 {
        matrix3: DMat3::from_cols(across * wide_radius, up * wide_radius, axis),
        translation: wide,
    };
    if !m.is_finite() || Transform::new(m).is_none() {
        return fail(
            "",
            format!(
                "radius {} over a length of {} is too extreme: its transform cannot be inverted",
                short(wide_radius),
                short(axis.length())
            ),
        );
    }
    Ok((
        Cone {
            ratio: narrow_radius / wide_radius,
        },
        m,
    ))
}

/// `x` as short as it reads (`1e-320`, not 320 digits), for a message.
fn short(x: f64) -> String {
    let (plain, sci) = (format!("{x}"), format!("{x:e}"));
    if plain.len() > sci.len() + 2 {
        sci
    } else {
        plain
    }
}

/// The open cylinder or cone from `base` (radius `base_radius`) to `apex`
/// (radius `apex_radius`) as an object: the unit cone and the transform
/// placing it ([`cone_placement`]). A cylinder is the cone with equal radii.
/// `Err` with a one-line reason for non-finite numbers, a negative radius,
/// both radii 0, `base == apex`, or sizes so extreme the transform cannot be
/// inverted.
pub fn cone_object(
    name: String,
    base: DVec3,
    base_radius: f64,
    apex: DVec3,
    apex_radius: f64,
    material: usize,
) -> Result<Object, String> {
    let (cone, m) =
        cone_placement(base, base_radius, apex, apex_radius).map_err(|e| e.to_string())?;
    let transform = Transform::new(m).ok_or("the cone's transform cannot be inverted")?;
    Ok(Object {
        name,
        shape: Shape::Cone(cone),
        transform: Some(Box::new(transform)),
        material,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::ray::Ray;
    use crate::methods::IntersectionMethods;

    fn cone(base: DVec3, r0: f64, apex: DVec3, r1: f64) -> Object {
        cone_object("c".into(), base, r0, apex, r1, 0).unwrap()
    }

    #[test]
    fn a_cone_from_either_end_is_the_same_surface() {
        // Radius 2 at (1, 2, 3) to a point at (1, 2, 7), given either way round:
        // the wider end becomes the unit cone's base both times.
        let (wide, tip) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 2.0, 7.0));
        let a = cone(wide, 2.0, tip, 0.0);
        let b = cone(tip, 0.0, wide, 2.0);
        assert_eq!(a, b);
        assert_eq!(a.shape, Shape::Cone(Cone { ratio: 0.0 }));
        // From (−9, 2, 5) along +x: at z = 5, halfway up, the radius is 1, so
        // x = 0 and 2 at t = 9 and 11.
        let r = Ray::new(DVec3::new(-9.0, 2.0, 5.0), DVec3::X);
        let roots = a.roots(&r, IntersectionMethods::default());
        // Tolerance: the transform's inverse and the quadratic, a few ULPs of 10.
        assert_eq!(roots.as_slice().len(), 2);
        assert!((roots.as_slice()[0] - 9.0).abs() < 1e-13, "{roots:?}");
        assert!((roots.as_slice()[1] - 11.0).abs() < 1e-13, "{roots:?}");
    }

    #[test]
    fn a_tilted_cone_is_met_at_the_radius_of_its_height() {
        // Between two arbitrary points: every hit point's distance from the axis
        // is the radius interpolated at its projection onto the axis.
        let (base, apex) = (DVec3::new(1.0, -2.0, 0.5), DVec3::new(-1.5, 3.0, 2.25));
        let (r0, r1) = (0.7, 0.2);
        let object = cone(base, r0, apex, r1);
        let axis = apex - base;
        let mut hits = 0;
        for k in 0..300 {
            let a = f64::from(k) * 0.377;
            let from = base + 0.5 * axis + 6.0 * DVec3::new(a.cos(), a.sin(), (2.0 * a).cos());
            let toward = base + (f64::from(k % 11) / 10.0) * axis;
            let ray = Ray::new(from, toward - from);
            let Some(t) = object
                .roots(&ray, IntersectionMethods::default())
                .first_in(0.0, f64::INFINITY)
            else {
                continue;
            };
            hits += 1;
            let methods = IntersectionMethods::default();
            for p in [ray.at(t), object.surface(&ray, t, 0, methods).point] {
                let h = (p - base).dot(axis) / axis.length_squared();
                let off_axis = (p - base - h * axis).length();
                let radius = r0 + (r1 - r0) * h;
                // Tolerance: coordinates of order 5 through a transform and its
                // inverse and a quadratic, tens of ULPs: 1e-13.
                assert!(
                    (off_axis - radius).abs() < 1e-13,
                    "{k}: {off_axis} vs {radius}"
                );
                assert!((-1e-13..=1.0 + 1e-13).contains(&h), "{k}: h = {h}");
            }
            // The world normal is outward: away from the axis.
            let s = object.surface(&ray, t, 0, methods);
            let h = (s.point - base).dot(axis) / axis.length_squared();
            assert!(s.normal.dot(s.point - base - h * axis) > 0.0);
        }
        assert!(hits > 200, "{hits} of 300 rays aimed at the axis hit");
        // Its box is the one around both end discs: on each axis ±r·√(1 − aᵢ²).
        let a = axis.normalize();
        let half = |r: f64| DVec3::ONE.map(|_| 0.0) + (DVec3::ONE - a * a).map(f64::sqrt) * r;
        let want_min = (base - half(r0)).min(apex - half(r1));
        let want_max = (base + half(r0)).max(apex + half(r1));
        let b = object.bounds().unwrap();
        // Tolerance: a few ULPs of coordinates of order 3.
        assert!((b.min - want_min).abs().max_element() < 1e-14, "{b:?}");
        assert!((b.max - want_max).abs().max_element() < 1e-14, "{b:?}");
    }

    #[test]
    fn a_cylinder_has_ratio_one_and_its_center_on_the_axis_midpoint() {
        let c = cone(DVec3::ZERO, 0.5, DVec3::new(0.0, 4.0, 0.0), 0.5);
        assert_eq!(c.shape, Shape::Cone(Cone { ratio: 1.0 }));
        assert_eq!(c.shape.kind(), "cone");
        assert!(!c.shape.is_solid() && !c.contains(DVec3::new(0.0, 2.0, 0.0)));
        // Tolerance: a few ULPs of 2.
        assert!((c.center() - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-15);
    }

    #[test]
    fn bad_cones_are_refused_in_one_line() {
        let (o, z) = (DVec3::ZERO, DVec3::Z);
        let cases = [
            (
                o,
                f64::NAN,
                z,
                1.0,
                "base_radius: must be a finite number ≥ 0, got NaN",
            ),
            (
                o,
                1.0,
                z,
                f64::INFINITY,
                "apex_radius: must be a finite number ≥ 0, got inf",
            ),
            (
                DVec3::splat(f64::NAN),
                1.0,
                z,
                1.0,
                "base: must be finite numbers",
            ),
            (
                o,
                1.0,
                DVec3::new(0.0, f64::INFINITY, 0.0),
                1.0,
                "apex: must be finite numbers",
            ),
            (
                o,
                -1.0,
                z,
                1.0,
                "base_radius: must be a finite number ≥ 0, got -1",
            ),
            (o, 0.0, z, 0.0, "base_radius and apex_radius are both 0"),
            (z, 1.0, z, 0.5, "base and apex are the same point"),
            (
                o,
                1e-320,
                z,
                0.0,
                "too extreme: its transform cannot be inverted",
            ),
            (o, 1e300, DVec3::new(1e300, 0.0, 0.0), 1.0, "too extreme"),
        ];
        for (base, r0, apex, r1, want) in cases {
            let e = cone_object("c".into(), base, r0, apex, r1, 0).unwrap_err();
            assert!(e.contains(want), "{e}");
            assert!(!e.contains('\n'), "{e}");
        }
    }
}
