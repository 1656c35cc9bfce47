//! A polygon's plane, as NFF defines it: the normal of the first three
//! vertices, every other vertex on their plane, the first corner convex. Apart from the polygon itself
//! so that a reader can name what is wrong in its own format's terms (NFF's
//! "vertices 1 to 3", the scene JSON's `vertices[0]`), by the one rule the
//! intersection uses.

use glam::DVec3;

use crate::math::bounds::Bounds;

/// How far a vertex may lie off the plane of the first three, relative to the
/// larger of the polygon's extent and its largest coordinate: numbers printed
/// with 6 significant digits (C's `%g`, as NFF files are) are off by at most
/// half a unit in the sixth digit, 5e-6 of their size. The SPD's polygons are
/// planar to 1e-16.
pub const PLANE_TOLERANCE: f64 = 1e-5;

/// The sine of the angle at the first vertex below which the first three
/// vertices count as one line: there their normal is mostly rounding.
pub const COLLINEAR_SINE: f64 = 1e-9;

/// Why vertices give a polygon no plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlaneError {
    /// The first three vertices lie on one line (within [`COLLINEAR_SINE`]).
    Collinear,
    /// A vertex lies off the plane of the first three by more than
    /// [`PLANE_TOLERANCE`] of the polygon's size.
    OffPlane {
        /// Which vertex, from 0.
        vertex: usize,
        /// How far off the plane it lies.
        off: f64,
        /// How far it might lie, at this polygon's size.
        allowed: f64,
    },
    /// The corner at the second vertex is reflex: the first three vertices
    /// turn against the whole outline's winding (their normal against its
    /// [`newell_normal`]), so the polygon would face away from the side its
    /// outline runs counter-clockwise on. Checked here, not by each reader, so
    /// the JSON and NFF readers cannot disagree on which polygons they take.
    ReflexFirstCorner,
}

/// The unit normal of the first three of `vertices` (at least three, finite),
/// counter-clockwise seen from the front, once every vertex is checked to lie
/// on their plane and the first corner to turn the outline's way.
pub fn plane_normal(vertices: &[DVec3]) -> Result<DVec3, PlaneError> {
    let (e1, e2) = (vertices[1] - vertices[0], vertices[2] - vertices[0]);
    let cross = e1.cross(e2);
    if cross.length() <= COLLINEAR_SINE * e1.length() * e2.length() || !cross.is_finite() {
        return Err(PlaneError::Collinear);
    }
    let normal = cross.normalize();
    let bounds = Bounds::around(vertices.iter().copied());
    let scale = (bounds.min.abs().max(bounds.max.abs())).max_element();
    let extent = (bounds.max - bounds.min).max_element();
    let allowed = PLANE_TOLERANCE * extent.max(scale);
    for (k, v) in vertices.iter().enumerate().skip(3) {
        let off = (*v - vertices[0]).dot(normal).abs();
        if off > allowed {
            return Err(PlaneError::OffPlane {
                vertex: k,
                off,
                allowed,
            });
        }
    }
    if newell_normal(vertices).dot(normal) < 0.0 {
        return Err(PlaneError::ReflexFirstCorner);
    }
    Ok(normal)
}

/// Newell's normal of the closed outline through `vertices`: twice the
/// outline's vector area, so it points where the whole outline runs
/// counter-clockwise, whichever corner comes first. Where it and the first
/// three vertices' normal disagree, the first corner is reflex and the
/// polygon faces away from its own winding.
pub fn newell_normal(vertices: &[DVec3]) -> DVec3 {
    // About the first vertex, so that far-off coordinates cancel before the
    // products, not after.
    let o = vertices[0];
    let next = vertices.iter().cycle().skip(1);
    vertices
        .iter()
        .zip(next)
        .map(|(&a, &b)| (a - o).cross(b - o))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec3> {
        [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .map(|(x, y)| DVec3::new(x, y, 0.0))
            .to_vec()
    }

    #[test]
    fn the_plane_of_the_first_three_and_its_refusals() {
        assert_eq!(plane_normal(&square()), Ok(DVec3::Z));
        let mut line = square();
        line[2] = DVec3::new(2.0, 0.0, 0.0);
        assert_eq!(plane_normal(&line), Err(PlaneError::Collinear));
        let mut bent = square();
        bent[3].z = 0.5;
        assert!(matches!(
            plane_normal(&bent),
            Err(PlaneError::OffPlane { vertex: 3, off, .. }) if off == 0.5
        ));
    }

    /// The reviewer's arrow: its first corner, at (1, 0), is reflex, so the
    /// first three vertices turn clockwise while the outline runs
    /// counter-clockwise.
    #[test]
    fn newell_sees_a_reflex_first_corner_that_the_first_three_hide() {
        let arrow =
            [(2.0, -1.0), (1.0, 0.0), (2.0, 1.0), (0.0, 0.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
        assert_eq!(plane_normal(&arrow), Err(PlaneError::ReflexFirstCorner));
        assert!(newell_normal(&arrow).z > 0.0);
        // The same outline begun at its convex corner (0, 0) faces +z.
        let mut begun = arrow.to_vec();
        begun.rotate_left(3);
        assert_eq!(plane_normal(&begun), Ok(DVec3::Z));
        // Convex first corner: both agree, with twice the area.
        assert_eq!(newell_normal(&square()), DVec3::new(0.0, 0.0, 2.0));
        let far: Vec<DVec3> = square().iter().map(|v| *v + DVec3::splat(1e8)).collect();
        assert_eq!(newell_normal(&far), DVec3::new(0.0, 0.0, 2.0));
    }
}
