//! What an intersection test returns: the roots along the ray, and, for the one
//! root the tracer keeps, the surface there.

use glam::DVec3;

use crate::math::float::offset_ray_origin;
use crate::methods::Offset;

/// The parameters `t` where a ray meets a surface, ascending; at most two
/// (a quadric has two, a plane one). Kept whole, not just the nearest, so the
/// ray tree can show every value the lecture's quadratic produced.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Roots {
    len: u8,
    /// Which face of a mesh the root belongs to (0 for other shapes).
    face: u32,
    t: [f64; 2],
}

impl Roots {
    /// No intersection.
    pub const NONE: Roots = Roots {
        len: 0,
        face: 0,
        t: [0.0; 2],
    };

    /// One root (a plane, or a tangent ray).
    pub fn one(t: f64) -> Self {
        Roots {
            len: 1,
            face: 0,
            t: [t, 0.0],
        }
    }

    /// One root on face `face` of a mesh (its nearest face).
    pub fn on_face(t: f64, face: u32) -> Self {
        Roots {
            len: 1,
            face,
            t: [t, 0.0],
        }
    }

    /// The mesh face the roots belong to (0 for other shapes).
    pub fn face(&self) -> u32 {
        self.face
    }

    /// Two roots, in any order.
    pub fn two(a: f64, b: f64) -> Self {
        Roots {
            len: 2,
            face: 0,
            t: [a.min(b), a.max(b)],
        }
    }

    /// The roots, ascending.
    pub fn as_slice(&self) -> &[f64] {
        &self.t[..usize::from(self.len)]
    }

    /// The smallest root strictly inside `(t_min, t_max)`: the lecture's
    /// "closest intersection" restricted to the ray's interval.
    #[inline]
    pub fn first_in(&self, t_min: f64, t_max: f64) -> Option<f64> {
        self.as_slice()
            .iter()
            .copied()
            .find(|&t| t > t_min && t < t_max)
    }
}

/// What an intersection search wants: the closest hit (a camera, reflected or
/// refracted ray), or any hit at all (a shadow ray asks only whether something
/// is in the way, so a mesh may stop at its first face).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// The nearest root.
    Closest,
    /// The first root found.
    Any,
}

/// The surface at a kept hit, in whichever space it was computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    /// The hit point.
    pub point: DVec3,
    /// A per-component bound on how far `point` may lie from the true surface
    /// (see [`crate::math::float`]).
    pub point_error: DVec3,
    /// The outward unit normal (for a plane, the side it was defined to face).
    pub normal: DVec3,
    /// The unit normal lighting uses: the geometric normal, except on a mesh with
    /// per-vertex normals, where it is interpolated (on the same side).
    pub shading_normal: DVec3,
    /// Where a pattern (the checkerboard) is evaluated: the object-space point,
    /// flattened onto the plane for planes so squares never flicker.
    pub pattern_point: DVec3,
}

/// How much work a ray cost: what the hierarchy saved shows in these counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TestCounts {
    /// Bounding boxes tested.
    pub boxes: u32,
    /// Primitives tested: objects, and the triangles of meshes.
    pub primitives: u32,
}

impl TestCounts {
    /// Adds another count.
    pub fn add(&mut self, other: TestCounts) {
        self.boxes += other.boxes;
        self.primitives += other.primitives;
    }
}

impl Surface {
    /// The origin of a ray leaving the surface in direction `dir`, placed as
    /// `offset` says: at the point (acne), a fixed epsilon along the normal, or
    /// just past the point's own error bound ([`offset_ray_origin`]).
    #[inline]
    pub fn ray_origin(&self, offset: Offset, dir: DVec3) -> DVec3 {
        match offset {
            Offset::None => self.point,
            Offset::Epsilon(e) => {
                self.point + if dir.dot(self.normal) < 0.0 { -e } else { e } * self.normal
            }
            Offset::Robust => offset_ray_origin(self.point, self.point_error, self.normal, dir),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn epsilon_offset_moves_along_the_normal_toward_the_ray() {
        let s = Surface {
            point: DVec3::ZERO,
            point_error: DVec3::ZERO,
            normal: DVec3::Y,
            shading_normal: DVec3::Y,
            pattern_point: DVec3::ZERO,
        };
        assert_eq!(
            s.ray_origin(Offset::Epsilon(0.1), DVec3::new(1.0, 1.0, 0.0)),
            DVec3::new(0.0, 0.1, 0.0)
        );
        assert_eq!(
            s.ray_origin(Offset::Epsilon(0.1), DVec3::new(1.0, -1.0, 0.0)),
            DVec3::new(0.0, -0.1, 0.0)
        );
        assert_eq!(s.ray_origin(Offset::None, DVec3::Y), DVec3::ZERO);
    }
}
