//! Axis-aligned bounding boxes: the bounding volumes of the lecture's last part,
//! and the slab test that decides whether a ray can reach anything inside one.

use glam::{DAffine3, DVec3};

use crate::math::float::gamma;
use crate::math::ray::Ray;

/// The box `min ≤ p ≤ max`. The empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// The smallest corner.
    pub min: DVec3,
    /// The largest corner.
    pub max: DVec3,
}

impl Bounds {
    /// Contains nothing; the identity of [`Bounds::union`].
    pub const EMPTY: Bounds = Bounds {
        min: DVec3::INFINITY,
        max: DVec3::NEG_INFINITY,
    };

    /// The smallest box holding every point.
    pub fn around(points: impl IntoIterator<Item = DVec3>) -> Bounds {
        points.into_iter().fold(Bounds::EMPTY, Bounds::grown)
    }

    /// This box grown to hold `p`.
    pub fn grown(self, p: DVec3) -> Bounds {
        Bounds {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The smallest box holding both.
    pub fn union(self, other: Bounds) -> Bounds {
        Bounds {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Whether it holds no point.
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// The center.
    pub fn center(&self) -> DVec3 {
        0.5 * (self.min + self.max)
    }

    /// Surface area: the surface area heuristic's measure of how likely a random
    /// ray is to hit the box (MacDonald & Booth 1990). Zero when empty.
    pub fn area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.max - self.min;
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// The box around this one carried by `m`: the eight transformed corners.
    pub fn transformed(&self, m: &DAffine3) -> Bounds {
        if self.is_empty() {
            return *self;
        }
        Bounds::around((0..8).map(|i| {
            let pick = |bit: usize, lo: f64, hi: f64| if i & bit == 0 { lo } else { hi };
            m.transform_point3(DVec3::new(
                pick(1, self.min.x, self.max.x),
                pick(2, self.min.y, self.max.y),
                pick(4, self.min.z, self.max.z),
            ))
        }))
    }
}

/// A ray prepared for many slab tests: the reciprocal direction is computed once.
#[derive(Clone, Copy, Debug)]
pub struct RayBox {
    origin: DVec3,
    inv_dir: DVec3,
    /// Which direction components are negative: which plane of each slab the
    /// ray enters first, and which child of a split it meets first.
    neg: glam::BVec3,
}

impl RayBox {
    /// Prepares `ray`.
    pub fn new(ray: &Ray) -> Self {
        let inv_dir = ray.dir.recip();
        RayBox {
            origin: ray.origin,
            inv_dir,
            neg: inv_dir.cmplt(DVec3::ZERO),
        }
    }

    /// The ray's origin.
    #[inline]
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The reciprocal of the ray's direction, per component.
    #[inline]
    pub fn inv_dir(&self) -> DVec3 {
        self.inv_dir
    }

    /// Whether the direction's component along `axis` is negative: the child of a
    /// split on that axis with the larger coordinates is the nearer one.
    #[inline]
    pub fn dir_is_neg(&self, axis: usize) -> bool {
        self.neg.test(axis)
    }

    /// The slab test (Kay & Kajiya 1986): the ray is inside the box between the
    /// largest entering and the smallest leaving slab parameter. Which plane of a
    /// slab is entered first follows from the direction's sign, known per ray, so
    /// no per-box ordering is needed (Williams et al., "An Efficient and Robust
    /// Ray–Box Intersection Algorithm", JGT 2005). The leaving values are widened
    /// by `1 + 2γ(3)` so rounding never culls a box the ray touches (pbrt-v4
    /// §6.1.2). Plain comparisons, not `min`/`max`: a NaN (a ray lying in a slab's
    /// plane) then leaves the interval as it was, and the box is kept.
    #[inline]
    pub fn hits(&self, b: &Bounds, t_min: f64, t_max: f64) -> bool {
        let near = DVec3::select(self.neg, b.max, b.min);
        let far = DVec3::select(self.neg, b.min, b.max);
        let t0 = (near - self.origin) * self.inv_dir;
        let t1 = (far - self.origin) * self.inv_dir * (1.0 + 2.0 * gamma(3));
        let enter = t0.max_element();
        let leave = t1.min_element();
        let enter = if enter > t_min { enter } else { t_min };
        let leave = if leave < t_max { leave } else { t_max };
        enter <= leave
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Bounds {
        Bounds {
            min: DVec3::ZERO,
            max: DVec3::ONE,
        }
    }

    #[test]
    fn slab_test_hits_and_misses() {
        let b = unit();
        let hit = RayBox::new(&Ray::new(DVec3::new(0.5, 0.5, -2.0), DVec3::Z));
        assert!(hit.hits(&b, 0.0, f64::INFINITY));
        // The box spans t = 2..3 along this ray: an interval ending before it misses.
        assert!(!hit.hits(&b, 0.0, 1.5));
        assert!(!hit.hits(&b, 3.5, f64::INFINITY));
        let beside = RayBox::new(&Ray::new(DVec3::new(1.5, 0.5, -2.0), DVec3::Z));
        assert!(!beside.hits(&b, 0.0, f64::INFINITY));
        // Axis-parallel from inside: the zero components give infinite slabs.
        let inside = RayBox::new(&Ray::new(DVec3::splat(0.5), DVec3::X));
        assert!(inside.hits(&b, 0.0, f64::INFINITY));
    }

    #[test]
    fn a_flat_box_is_still_hit() {
        // A triangle in the plane y = 0 has a box of zero height.
        let flat = Bounds {
            min: DVec3::new(0.0, 0.0, 0.0),
            max: DVec3::new(1.0, 0.0, 1.0),
        };
        let r = RayBox::new(&Ray::new(DVec3::new(0.3, 1.0, 0.3), DVec3::NEG_Y));
        assert!(r.hits(&flat, 0.0, f64::INFINITY));
    }

    #[test]
    fn area_and_transform() {
        assert_eq!(unit().area(), 6.0);
        assert_eq!(Bounds::EMPTY.area(), 0.0);
        let m = DAffine3::from_rotation_z(std::f64::consts::FRAC_PI_4);
        let r = unit().transformed(&m);
        // The unit square turned 45° spans x = -√2/2..√2/2 and y = 0..√2.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!((r.min.x + s).abs() < 1e-15 && (r.max.x - s).abs() < 1e-15);
        assert!((r.max.y - 2.0 * s).abs() < 1e-15 && r.min.y.abs() < 1e-15);
    }
}
