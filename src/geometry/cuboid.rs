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

/// Where a ray is between the two planes of one axis of a box (one slab).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SlabSpan {
    /// The ray crosses the planes: it is between them for `t` in `[near, far]`.
    Crossing {
        /// Where it enters the slab.
        near: f64,
        /// Where it leaves.
        far: f64,
    },
    /// The ray runs parallel to the planes: between them (the closed slab, so a
    /// ray lying in one of the planes is inside) all along, or never.
    Parallel {
        /// Between them.
        inside: bool,
    },
}

impl Cuboid {
    /// Each axis's slab (Kay & Kajiya 1986): the ray `S + t·c` is between the
    /// planes `min` and `max` of an axis for `t` from `(min − S)/c` to
    /// `(max − S)/c` (ordered). A zero direction component is decided apart,
    /// never divided by: `0/0` and `0·∞` are NaN, and whichever side of a
    /// comparison a NaN fell on used to decide whether a ray lying in a face
    /// plane met the box (the x-max and y-max faces did, the other four did not).
    /// The same numbers serve the test, the face of a hit and the trace.
    #[inline]
    pub fn slabs(&self, ray: &Ray) -> [SlabSpan; 3] {
        std::array::from_fn(|k| {
            let (s, c) = (ray.origin[k], ray.dir[k]);
            if c == 0.0 {
                return SlabSpan::Parallel {
                    inside: self.min[k] <= s && s <= self.max[k],
                };
            }
            let (t0, t1) = ((self.min[k] - s) / c, (self.max[k] - s) / c);
            if c > 0.0 {
                SlabSpan::Crossing { near: t0, far: t1 }
            } else {
                SlabSpan::Crossing { near: t1, far: t0 }
            }
        })
    }

    /// The slab method: the ray is inside the box where the three slabs'
    /// intervals overlap, entering at the largest start and leaving at the
    /// smallest end. The test is closed (an overlap of a single `t` counts, and
    /// a ray in a face plane is inside that slab), so two boxes sharing a face
    /// leave no crack between them: the shared plane's `t` is computed from the
    /// same numbers for both, and each interval includes it.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        match overlap(&self.slabs(ray)) {
            Some((enter, leave)) if leave.is_finite() => Roots::two(enter, leave),
            _ => Roots::NONE,
        }
    }

    /// The surface at `ray.at(t)`: on the face whose plane the ray crosses at
    /// `t` (the nearest such plane, for a `t` that is not a root), with the point
    /// put exactly on it. A slab the ray runs along has no plane it crosses, so
    /// a ray lying in a face plane gets the face it enters or leaves through,
    /// never the one it lies in (at an edge the point alone cannot tell them apart).
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        let mut point = ray.at(t);
        let mut best: Option<(f64, usize, bool)> = None;
        for (k, slab) in self.slabs(ray).into_iter().enumerate() {
            if let SlabSpan::Crossing { near, far } = slab {
                for (gap, entering) in [((near - t).abs(), true), ((far - t).abs(), false)] {
                    if best.is_none_or(|(g, _, _)| gap < g) {
                        best = Some((gap, k, entering));
                    }
                }
            }
        }
        let mut normal = DVec3::ZERO;
        if let Some((_, k, entering)) = best {
            // Entering, the ray meets the plane facing it: `min` going up the axis.
            let up = ray.dir[k] > 0.0;
            let on_max = up != entering;
            normal[k] = if on_max { 1.0 } else { -1.0 };
            point[k] = if on_max { self.max[k] } else { self.min[k] };
        }
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

/// Where the slabs' intervals overlap: from the largest start to the smallest
/// end, both included; `None` when a parallel slab is never entered or the
/// intervals are disjoint. Every slab parallel leaves `(−∞, ∞)`. (With a finite
/// origin no quotient is NaN: `c` is never 0 in one.)
pub fn overlap(slabs: &[SlabSpan; 3]) -> Option<(f64, f64)> {
    let (mut enter, mut leave) = (f64::NEG_INFINITY, f64::INFINITY);
    for slab in slabs {
        match *slab {
            SlabSpan::Crossing { near, far } => {
                enter = enter.max(near);
                leave = leave.min(far);
            }
            SlabSpan::Parallel { inside: false } => return None,
            SlabSpan::Parallel { inside: true } => {}
        }
    }
    (enter <= leave).then_some((enter, leave))
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

    /// A ray lying in one of the six face planes, crossing the box along the
    /// face: the closed test counts it inside that face's slab, whatever the
    /// sign of the zero direction components (before, `0·∞ = NaN` fell to one
    /// side or the other of `min`/`max`, and only the x-max and y-max faces hit).
    /// It enters and leaves through the faces it crosses, not the one it lies in.
    #[test]
    fn a_ray_in_any_face_plane_is_inside_that_slab() {
        for axis in 0..3 {
            // The ray runs along the next axis; the third coordinate is inside.
            let along = (axis + 1) % 3;
            let third = (axis + 2) % 3;
            for side in [-1.0, 1.0] {
                for zero in [0.0, -0.0] {
                    let mut origin = DVec3::ZERO;
                    origin[axis] = side;
                    origin[along] = -5.0;
                    origin[third] = 0.25;
                    let mut dir = DVec3::splat(zero);
                    dir[along] = 1.0;
                    let ray = Ray::new(origin, dir);
                    let roots = unit().roots(&ray);
                    let what = format!("face {side} of axis {axis}, zeros {zero:?}");
                    assert_eq!(roots.as_slice(), &[4.0, 6.0], "{what}");
                    let mut entry_normal = DVec3::ZERO;
                    entry_normal[along] = -1.0;
                    assert_eq!(unit().surface(&ray, 4.0).normal, entry_normal, "{what}");
                    assert_eq!(unit().surface(&ray, 6.0).normal, -entry_normal, "{what}");
                }
            }
        }
    }
}
