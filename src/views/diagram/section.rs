//! Honest projection: what the drawing plane really cuts of each object, and
//! where a drawn ray only passes in front of or behind an object.
//!
//! A diagram flattens 3D onto a plane. An object's silhouette covers every
//! point of the plane it would hide, but a ray drawn across the silhouette may
//! run above or below the object in 3D. So figures draw each object's true
//! cross-section with the drawing plane solid and its silhouette as a faint
//! ghost, and a ray piece that lies over a silhouette without being inside the
//! object in 3D dashed and faded: nothing seems hit that was not.

use glam::{DMat3, DVec2, DVec3};

use crate::geometry::object::{Object, Shape};
use crate::math::ray::Ray;
use crate::views::diagram::projection::{Outline, Projection, RIM_POINTS};

/// The cross-section of `object` with the drawing plane of `proj`: an ellipse
/// for a sphere or ellipsoid, a convex polygon for a box, the segments where
/// the plane cuts a triangle, a polygon, a mesh's faces or a cone, the line of a
/// plane; `None`
/// when the plane misses the object.
pub fn cross_section(proj: &Projection, object: &Object) -> Option<Outline> {
    let (linear, translation) = match &object.transform {
        Some(t) => (t.to_world.matrix3, t.to_world.translation),
        None => (DMat3::IDENTITY, DVec3::ZERO),
    };
    // A point (a, b) of the drawing plane in the object's own frame: q0 + a·qa + b·qb.
    let inverse = linear.inverse();
    let q0 = inverse * (proj.origin - translation);
    let (qa, qb) = (inverse * proj.right, inverse * proj.up);
    let to_world = |p: DVec3| linear * p + translation;
    match &object.shape {
        Shape::Sphere(s) => ellipse_section(q0 - s.center, qa, qb, s.radius),
        Shape::Plane(_) => Some(proj.outline(object)),
        Shape::Box(b) => {
            let (lo, hi) = proj.outline(object).bounds()?;
            let square = vec![lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
            let mut polygon = square;
            for axis in 0..3 {
                // min ≤ q ≤ max on this axis: two half-planes in (a, b).
                let (o, a, c) = (q0[axis], qa[axis], qb[axis]);
                polygon = clip_half_plane(&polygon, |p| o + a * p.x + c * p.y - b.min[axis]);
                polygon = clip_half_plane(&polygon, |p| b.max[axis] - (o + a * p.x + c * p.y));
            }
            (polygon.len() >= 3).then_some(Outline::Polygon { points: polygon })
        }
        Shape::Triangle(t) => {
            let segments = triangle_section(proj, [t.a, t.b, t.c].map(to_world));
            (!segments.is_empty()).then_some(Outline::Segments { segments })
        }
        Shape::Polygon(p) => {
            let vertices: Vec<DVec3> = p.vertices().iter().map(|&v| to_world(v)).collect();
            let segments = polygon_section(proj, &vertices);
            (!segments.is_empty()).then_some(Outline::Segments { segments })
        }
        Shape::Mesh(m) => {
            let segments: Vec<[DVec2; 2]> = (0..m.faces.len())
                .flat_map(|f| {
                    let t = m.triangle(f);
                    triangle_section(proj, [t.a, t.b, t.c].map(to_world))
                })
                .collect();
            (!segments.is_empty()).then_some(Outline::Segments { segments })
        }
        Shape::Cone(c) => {
            // The surface as thin triangles between the two rims: the cut is
            // the conic within a chord's sag (1 − cos(π/RIM_POINTS) of the radius).
            let rims: Vec<DVec3> = c.rims(RIM_POINTS).into_iter().map(to_world).collect();
            let (bottom, top) = rims.split_at(RIM_POINTS);
            let segments: Vec<[DVec2; 2]> = (0..RIM_POINTS)
                .flat_map(|k| {
                    let l = (k + 1) % RIM_POINTS;
                    let mut cut = triangle_section(proj, [bottom[k], bottom[l], top[k]]);
                    cut.extend(triangle_section(proj, [bottom[l], top[l], top[k]]));
                    cut
                })
                .collect();
            (!segments.is_empty()).then_some(Outline::Segments { segments })
        }
    }
}

/// Where the plane `q0 + a·qa + b·qb` cuts the sphere `|q| ≤ r`: the quadratic
/// form `|q0 + a·qa + b·qb|² ≤ r²` in `(a, b)` is an ellipse with center
/// `m = -G⁻¹g` and axes along `G`'s eigenvectors, `G` the Gram matrix of `qa`, `qb`.
fn ellipse_section(q0: DVec3, qa: DVec3, qb: DVec3, r: f64) -> Option<Outline> {
    let (gaa, gab, gbb) = (qa.dot(qa), qa.dot(qb), qb.dot(qb));
    let g = DVec2::new(q0.dot(qa), q0.dot(qb));
    let det = gaa * gbb - gab * gab;
    if det <= 0.0 {
        return None;
    }
    let center = -DVec2::new(gbb * g.x - gab * g.y, gaa * g.y - gab * g.x) / det;
    // What is left of r² at the center: the ellipse is (x - m)ᵀG(x - m) ≤ k.
    let k = r * r - (q0 + center.x * qa + center.y * qb).length_squared();
    if k <= 0.0 {
        return None;
    }
    let mean = (gaa + gbb) / 2.0;
    let spread = (((gaa - gbb) / 2.0).powi(2) + gab * gab).sqrt();
    let (l1, l2) = (mean + spread, mean - spread);
    let e1 = if gab.abs() > 1e-12 * (gaa + gbb) {
        DVec2::new(gab, l1 - gaa).normalize()
    } else if gaa >= gbb {
        DVec2::X
    } else {
        DVec2::Y
    };
    Some(Outline::Ellipse {
        center,
        axes: [e1 * (k / l1).sqrt(), e1.perp() * (k / l2).sqrt()],
    })
}

/// The segment where the drawing plane crosses a triangle (world vertices), if it does.
fn triangle_section(proj: &Projection, vertices: [DVec3; 3]) -> Vec<[DVec2; 2]> {
    let w = proj.toward_viewer();
    let side = vertices.map(|v| (v - proj.origin).dot(w));
    let mut ends = Vec::with_capacity(2);
    for k in 0..3 {
        let (i, j) = (k, (k + 1) % 3);
        if (side[i] < 0.0) != (side[j] < 0.0) {
            let s = side[i] / (side[i] - side[j]);
            ends.push(proj.point(vertices[i] + s * (vertices[j] - vertices[i])));
        }
    }
    match ends[..] {
        [a, b] => vec![[a, b]],
        _ => Vec::new(),
    }
}

/// The segments where the drawing plane cuts a planar polygon (world
/// vertices), convex or not: the points where its edges cross the plane, in
/// order along the line the two planes share, paired first with second, third
/// with fourth (between each pair the line is inside, by the even–odd rule).
/// A vertex on the plane counts with the side `≥ 0`, so every crossing is
/// counted once and they come in pairs.
fn polygon_section(proj: &Projection, vertices: &[DVec3]) -> Vec<[DVec2; 2]> {
    let w = proj.toward_viewer();
    let side: Vec<f64> = vertices.iter().map(|&v| (v - proj.origin).dot(w)).collect();
    let mut ends = Vec::new();
    for i in 0..vertices.len() {
        let j = (i + 1) % vertices.len();
        if (side[i] < 0.0) != (side[j] < 0.0) {
            let s = side[i] / (side[i] - side[j]);
            ends.push(proj.point(vertices[i] + s * (vertices[j] - vertices[i])));
        }
    }
    let Some(along) = ends
        .iter()
        .map(|&e| e - ends[0])
        .max_by(|a, b| a.length_squared().total_cmp(&b.length_squared()))
    else {
        return Vec::new();
    };
    ends.sort_by(|a, b| a.dot(along).total_cmp(&b.dot(along)));
    ends.chunks_exact(2)
        .map(|pair| [pair[0], pair[1]])
        .filter(|[a, b]| a != b)
        .collect()
}

/// The part of a convex polygon where `inside(p) ≥ 0`, for a linear `inside`
/// (Sutherland–Hodgman on one edge).
fn clip_half_plane(polygon: &[DVec2], inside: impl Fn(DVec2) -> f64) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(polygon.len() + 1);
    for (k, &a) in polygon.iter().enumerate() {
        let b = polygon[(k + 1) % polygon.len()];
        let (sa, sb) = (inside(a), inside(b));
        if sa >= 0.0 {
            out.push(a);
        }
        if (sa < 0.0) != (sb < 0.0) {
            out.push(a + (b - a) * (sa / (sa - sb)));
        }
    }
    out
}

/// The parts of the drawn segment `a → b` (3D, projected by `proj`) that lie
/// over `object`'s silhouette while the 3D segment is outside the object: where
/// the ray passes in front of or behind it. As parameter intervals in `[0, 1]`
/// along the segment; slivers at the ends (a ray starting or ending on the
/// surface) are dropped.
pub fn passing(proj: &Projection, object: &Object, (a, b): (DVec3, DVec3)) -> Vec<[f64; 2]> {
    let silhouette = proj.outline(object);
    let over = inside_2d(&silhouette, proj.point(a), proj.point(b));
    if over.is_empty() {
        return Vec::new();
    }
    let within = inside_3d(object, a, b);
    let mut out = Vec::new();
    for [s0, s1] in over {
        // Subtract every 3D interval from [s0, s1].
        let mut pieces = vec![[s0, s1]];
        for &[t0, t1] in &within {
            pieces = pieces
                .into_iter()
                .flat_map(|[p0, p1]| {
                    let mut keep = Vec::new();
                    if t0 > p0 {
                        keep.push([p0, t0.min(p1)]);
                    }
                    if t1 < p1 {
                        keep.push([t1.max(p0), p1]);
                    }
                    keep
                })
                .filter(|[p0, p1]| p1 > p0)
                .collect();
        }
        out.extend(pieces);
    }
    const SLIVER: f64 = 1e-6;
    out.retain(|[p0, p1]| p1 - p0 > SLIVER);
    out
}

/// Where the 2D segment `p → q` lies inside a bounded outline, as parameter
/// intervals in `[0, 1]`. Planes are unbounded and give none.
fn inside_2d(outline: &Outline, p: DVec2, q: DVec2) -> Vec<[f64; 2]> {
    let d = q - p;
    let interval = match outline {
        Outline::Ellipse { center, axes } => {
            // In the ellipse's own axes the region is x² + y² ≤ 1.
            let (e0, e1) = (axes[0], axes[1]);
            let (l0, l1) = (e0.length_squared(), e1.length_squared());
            if l0 == 0.0 || l1 == 0.0 {
                return Vec::new();
            }
            let local = |v: DVec2| DVec2::new(v.dot(e0) / l0, v.dot(e1) / l1);
            let (o, v) = (local(p - *center), local(d));
            let (qa, qb, qc) = (v.dot(v), o.dot(v), o.dot(o) - 1.0);
            let disc = qb * qb - qa * qc;
            if qa == 0.0 || disc <= 0.0 {
                return Vec::new();
            }
            let root = disc.sqrt();
            [(-qb - root) / qa, (-qb + root) / qa]
        }
        Outline::Polygon { points } if points.len() >= 3 => {
            // Counter-clockwise hull: inside every edge's left side (Cyrus–Beck).
            let (mut s0, mut s1) = (f64::NEG_INFINITY, f64::INFINITY);
            for k in 0..points.len() {
                let (a, b) = (points[k], points[(k + 1) % points.len()]);
                let normal = (b - a).perp();
                let (num, den) = (normal.dot(p - a), normal.dot(d));
                if den == 0.0 {
                    if num < 0.0 {
                        return Vec::new();
                    }
                } else if den > 0.0 {
                    s0 = s0.max(-num / den);
                } else {
                    s1 = s1.min(-num / den);
                }
            }
            [s0, s1]
        }
        _ => return Vec::new(),
    };
    let [s0, s1] = [interval[0].max(0.0), interval[1].min(1.0)];
    if s1 > s0 { vec![[s0, s1]] } else { Vec::new() }
}

/// Where the 3D segment `a → b` is inside the solid, as parameter intervals in
/// `[0, 1]`: between the entering and the leaving root. Triangles, meshes,
/// polygons and open cones are surfaces and hold nothing.
fn inside_3d(object: &Object, a: DVec3, b: DVec3) -> Vec<[f64; 2]> {
    if !object.shape.is_solid() {
        return Vec::new();
    }
    let roots = object.roots(&Ray::new(a, b - a), crate::methods::SphereMethod::Stable);
    match roots.as_slice() {
        &[t0, t1] if t1 > 0.0 && t0 < 1.0 => vec![[t0.max(0.0), t1.min(1.0)]],
        &[_] | &[] if object.contains(a) => vec![[0.0, 1.0]],
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::sphere::Sphere;
    use crate::views::diagram::projection::View;

    fn front() -> Projection {
        Projection {
            view: View::Front,
            origin: DVec3::ZERO,
            right: DVec3::X,
            up: DVec3::Y,
        }
    }

    fn ball(center: DVec3, radius: f64) -> Object {
        Object {
            name: "ball".into(),
            shape: Shape::Sphere(Sphere { center, radius }),
            transform: None,
            material: 0,
        }
    }

    #[test]
    fn the_plane_cuts_a_sphere_in_a_smaller_circle_off_center() {
        // A sphere of radius 2 whose center is 1.2 behind the plane z = 0: the cut
        // is a circle of radius √(4 - 1.44) = 1.6 around (3, 1).
        let cut = cross_section(&front(), &ball(DVec3::new(3.0, 1.0, -1.2), 2.0)).unwrap();
        let Outline::Ellipse { center, axes } = cut else {
            panic!("{cut:?}")
        };
        // Tolerance: a few ULPs of numbers of order 1.
        assert!(center.abs_diff_eq(DVec2::new(3.0, 1.0), 1e-12));
        assert!((axes[0].length() - 1.6).abs() < 1e-12 && (axes[1].length() - 1.6).abs() < 1e-12);
        // 2.5 behind the plane, the sphere of radius 2 is not cut at all.
        assert!(cross_section(&front(), &ball(DVec3::new(3.0, 1.0, -2.5), 2.0)).is_none());
    }

    #[test]
    fn a_cone_is_cut_along_its_two_side_lines_and_outlined_by_its_hull() {
        // A pointed cone standing on the plane y = 0, radius 1, tip at (0, 2, 0):
        // the plane z = 0 cuts it along |x| = 1 − y/2, and seen from the front
        // its outline is the triangle (−1, 0), (1, 0), (0, 2).
        let cone = crate::geometry::cone::cone_object(
            "c".into(),
            DVec3::ZERO,
            1.0,
            DVec3::new(0.0, 2.0, 0.0),
            0.0,
            0,
        )
        .unwrap();
        let Some(Outline::Segments { segments }) = cross_section(&front(), &cone) else {
            panic!("a cone's cut is drawn");
        };
        let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in segments.iter().flatten() {
            // Tolerance: on the side lines up to rounding (the cut runs through
            // rim points), a few ULPs of 2.
            assert!((p.x.abs() - (1.0 - p.y / 2.0)).abs() < 1e-12, "{p}");
            (low, high) = (low.min(p.y), high.max(p.y));
        }
        assert!(
            low.abs() < 1e-12 && (high - 2.0).abs() < 1e-12,
            "{low} {high}"
        );
        let Outline::Polygon { points } = front().outline(&cone) else {
            panic!("a cone's outline is its hull");
        };
        let (lo, hi) = Outline::Polygon { points }.bounds().unwrap();
        // Tolerance: a few ULPs; the rims' points include φ = 0 and π.
        assert!(lo.abs_diff_eq(DVec2::new(-1.0, 0.0), 1e-12), "{lo}");
        assert!(hi.abs_diff_eq(DVec2::new(1.0, 2.0), 1e-12), "{hi}");
    }

    #[test]
    fn a_ray_over_a_sphere_it_does_not_enter_passes_it() {
        // The ball of radius 1 at (0, 0, -5); a ray along x at z = 0 crosses its
        // silhouette (x in [-1, 1]) but never enters it.
        let b = ball(DVec3::new(0.0, 0.0, -5.0), 1.0);
        let pass = passing(
            &front(),
            &b,
            (DVec3::new(-4.0, 0.0, 0.0), DVec3::new(4.0, 0.0, 0.0)),
        );
        assert_eq!(pass.len(), 1);
        let [s0, s1] = pass[0];
        assert!(
            (s0 - 3.0 / 8.0).abs() < 1e-12 && (s1 - 5.0 / 8.0).abs() < 1e-12,
            "{pass:?}"
        );
        // Through the ball at z = -5 it enters it: nothing is passed.
        let through = (DVec3::new(-4.0, 0.0, -5.0), DVec3::new(4.0, 0.0, -5.0));
        assert!(passing(&front(), &b, through).is_empty());
        // Ending on its surface: also nothing.
        let to_surface = (DVec3::new(-4.0, 0.0, -5.0), DVec3::new(-1.0, 0.0, -5.0));
        assert!(passing(&front(), &b, to_surface).is_empty());
    }

    #[test]
    fn the_plane_cuts_a_non_convex_polygon_in_two_pieces() {
        // A U lying on y = 0 (its arms along z from x in [0, 1] and [2, 3],
        // joined by z in [-3, -2]), its arms' ends at z = 1: the front plane
        // z = 0 cuts the arms only, x from 0 to 1 and from 2 to 3 at y = 0.
        let at = |x: f64, z: f64| DVec3::new(x, 0.0, z);
        let u = [
            at(0., 1.),
            at(0., -3.),
            at(3., -3.),
            at(3., 1.),
            at(2., 1.),
            at(2., -2.),
            at(1., -2.),
            at(1., 1.),
        ];
        let polygon = crate::geometry::polygon::Polygon::new(u.to_vec(), None, false).unwrap();
        let object = Object {
            name: "u".into(),
            shape: Shape::Polygon(std::sync::Arc::new(polygon)),
            transform: None,
            material: 0,
        };
        let Some(Outline::Segments { mut segments }) = cross_section(&front(), &object) else {
            panic!("no cut")
        };
        for s in &mut segments {
            s.sort_by(|a, b| a.x.total_cmp(&b.x));
        }
        segments.sort_by(|a, b| a[0].x.total_cmp(&b[0].x));
        // Each end is a vertex's x (the edges cross z = 0 at their middles, exactly).
        let [x0, x1] = [DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0)];
        let [x2, x3] = [DVec2::new(2.0, 0.0), DVec2::new(3.0, 0.0)];
        assert_eq!(segments, vec![[x0, x1], [x2, x3]]);
        // Moved behind the plane, it is not cut.
        let behind = Object {
            transform: Some(Box::new(
                crate::geometry::transform::Transform::new(glam::DAffine3::from_translation(
                    DVec3::new(0.0, 0.0, -5.0),
                ))
                .unwrap(),
            )),
            ..object
        };
        assert!(cross_section(&front(), &behind).is_none());
    }
}
