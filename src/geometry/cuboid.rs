//! Ray–box intersection: an axis-aligned box in its own space, which a transform
//! can turn, stretch and move like any other object.

use glam::DVec3;

use crate::geometry::hit::{Roots, Surface};
use crate::math::bounds::Bounds;
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// The solid box `min ≤ p ≤ max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cuboid {
    /// The smallest corner.
    pub min: DVec3,
    /// The largest corner, greater than `min` on every axis.
    pub max: DVec3,
}

impl Cuboid {
    /// The slab method (Kay & Kajiya 1986): on each axis the ray is between the two
    /// planes for `t` in `[(min - S)/c, (max - S)/c]` (ordered); it is inside the box
    /// where all three intervals overlap, entering at the largest start and leaving
    /// at the smallest end. A ray parallel to a pair of planes and outside them
    /// gets an empty interval from the infinite quotients.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let inv = ray.dir.recip();
        let t0 = (self.min - ray.origin) * inv;
        let t1 = (self.max - ray.origin) * inv;
        let enter = t0.min(t1).max_element();
        let leave = t0.max(t1).min_element();
        if enter.is_nan() || leave.is_nan() || enter > leave || leave.is_infinite() {
            return Roots::NONE;
        }
        Roots::two(enter, leave)
    }

    /// The surface at `ray.at(t)`: the face is the one the point is nearest, in
    /// units of the box's half-size, and the point is put exactly on it.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        let mut point = ray.at(t);
        let center = 0.5 * (self.min + self.max);
        let half = 0.5 * (self.max - self.min);
        let rel = (point - center) / half;
        let a = rel.abs();
        let axis = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let mut normal = DVec3::ZERO;
        normal[axis] = rel[axis].signum();
        point[axis] = if rel[axis] > 0.0 {
            self.max[axis]
        } else {
            self.min[axis]
        };
        Surface {
            point,
            // As for a plane: `t` came from a division, the point from `S + t·c`.
            point_error: DVec3::splat(
                gamma(8) * (point.abs().max_element() + ray.origin.abs().max_element()),
            ),
            normal,
            shading_normal: normal,
            pattern_point: point,
        }
    }

    /// Whether `p` is strictly inside.
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpgt(self.min).all() && p.cmplt(self.max).all()
    }

    /// Its own bounds.
    pub fn bounds(&self) -> Bounds {
        Bounds {
            min: self.min,
            max: self.max,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Cuboid {
        Cuboid {
            min: DVec3::splat(-1.0),
            max: DVec3::ONE,
        }
    }

    #[test]
    fn enters_and_leaves_through_opposite_faces() {
        let ray = Ray::new(DVec3::new(0.2, 0.3, -5.0), DVec3::Z);
        assert_eq!(unit().roots(&ray).as_slice(), &[4.0, 6.0]);
        let s = unit().surface(&ray, 4.0);
        assert_eq!(s.normal, DVec3::NEG_Z);
        assert_eq!(s.point, DVec3::new(0.2, 0.3, -1.0));
        assert_eq!(unit().surface(&ray, 6.0).normal, DVec3::Z);
    }

    #[test]
    fn misses_beside_and_parallel() {
        let beside = Ray::new(DVec3::new(1.5, 0.0, -5.0), DVec3::Z);
        assert!(unit().roots(&beside).as_slice().is_empty());
        let diagonal = Ray::new(DVec3::new(-5.0, 3.5, 0.0), DVec3::new(1.0, -0.4, 0.0));
        // Reaches y = 1.5 at x = -1: above the box when it gets there.
        assert!(unit().roots(&diagonal).as_slice().is_empty());
    }

    #[test]
    fn from_inside_the_entry_is_behind() {
        let ray = Ray::new(DVec3::ZERO, DVec3::X);
        assert_eq!(unit().roots(&ray).as_slice(), &[-1.0, 1.0]);
        assert!(unit().contains(DVec3::ZERO) && !unit().contains(DVec3::new(1.0, 0.0, 0.0)));
    }
}
