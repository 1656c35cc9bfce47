//! Orthographic projection of the scene onto a plane, for diagrams: the PNG
//! figures and the inspector's diagram pane both draw through this.
//!
//! The default view is the **plane of incidence** at the first hit, spanned by the
//! primary ray and the surface normal there. The reflected ray (`c - 2(n·c)n`) and
//! the refracted ray (a combination of `c` and `n`, by Snell's law) lie in that
//! plane too, so the first bounce is drawn without foreshortening.

use glam::{DMat3, DVec2, DVec3};

use crate::geometry::object::{Object, Shape};
use crate::geometry::sphere::Sphere;
use crate::scene::camera::Camera;
use crate::tree::document::TraceDocument;

/// How many points around each of a cone's rims it is drawn with: its
/// outline and cut are off by at most a chord's sag, `1 − cos(π/96)` ≈ 0.05%
/// of the radius.
pub const RIM_POINTS: usize = 96;

/// Which plane to project onto.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum View {
    /// The plane of incidence at the first hit (primary ray and normal).
    Auto,
    /// Looking down the world's -y axis: x to the right, -z up the page.
    Top,
    /// Looking along the world's -x axis: -z to the right, y up.
    Side,
    /// Looking along the world's -z axis: x to the right, y up.
    Front,
}

/// An orthographic projection: 3D points to 2D diagram coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// Which view this is.
    pub view: View,
    /// The 3D point drawn at the 2D origin (the first hit, or the eye).
    pub origin: DVec3,
    /// The unit direction drawn to the right.
    pub right: DVec3,
    /// The unit direction drawn up.
    pub up: DVec3,
}

impl Projection {
    /// The projection for sample `sample` of `trace`, seen from `view`.
    pub fn new(view: View, trace: &TraceDocument, sample: usize, camera: &Camera) -> Self {
        let root = &trace.samples[sample].tree.nodes[0];
        let origin = root.hit.as_ref().map_or(root.origin, |h| h.point);
        let world_up = trace
            .camera
            .look_at
            .as_ref()
            .map_or(camera.v, |l| l.up.normalize_or(camera.v));
        let (right, up) = match view {
            View::Top => (DVec3::X, DVec3::NEG_Z),
            View::Side => (DVec3::NEG_Z, DVec3::Y),
            View::Front => (DVec3::X, DVec3::Y),
            View::Auto => {
                let d = root.direction.normalize();
                // The plane of incidence: the ray and the normal. Head-on it is any
                // plane through the normal: take the one through the camera's u.
                // A miss: the plane of the ray and world up.
                let w = match &root.hit {
                    Some(hit) => d
                        .cross(hit.shading_normal)
                        .try_normalize()
                        .unwrap_or_else(|| camera.u.cross(hit.shading_normal).normalize()),
                    None => d.cross(world_up).try_normalize().unwrap_or(camera.v),
                };
                upright(w, d, world_up, camera.v)
            }
        };
        Self {
            view,
            origin,
            right,
            up,
        }
    }

    /// The 2D position of `p`.
    pub fn point(&self, p: DVec3) -> DVec2 {
        let d = p - self.origin;
        DVec2::new(d.dot(self.right), d.dot(self.up))
    }

    /// The 2D image of direction `v`.
    pub fn vector(&self, v: DVec3) -> DVec2 {
        DVec2::new(v.dot(self.right), v.dot(self.up))
    }

    /// The unit normal of the projection plane, toward the viewer.
    pub fn toward_viewer(&self) -> DVec3 {
        self.right.cross(self.up)
    }

    /// What the caption says the view is.
    pub fn caption(&self) -> &'static str {
        match self.view {
            View::Auto => {
                "view: plane of incidence at the first hit (primary ray and normal), world up on top"
            }
            View::Top => "view: top (looking down -y; x right, -z up)",
            View::Side => "view: side (looking along -x; -z right, y up)",
            View::Front => "view: front (looking along -z; x right, y up)",
        }
    }

    /// The exact outline of `object` in this projection.
    pub fn outline(&self, object: &Object) -> Outline {
        let (linear, translation) = match &object.transform {
            Some(t) => (t.to_world.matrix3, t.to_world.translation),
            None => (DMat3::IDENTITY, DVec3::ZERO),
        };
        let to_world = |p: DVec3| linear * p + translation;
        match &object.shape {
            Shape::Sphere(s) => self.ellipse(s, linear, translation),
            Shape::Plane(p) => {
                let normal = object
                    .transform
                    .as_ref()
                    .map_or(p.normal, |t| (t.normal_to_world * p.normal).normalize());
                self.plane_line(to_world(p.point), normal)
            }
            Shape::Triangle(t) => self.hull([t.a, t.b, t.c].map(to_world).to_vec()),
            Shape::Mesh(m) => self.hull(m.positions.iter().map(|&p| to_world(p)).collect()),
            Shape::Polygon(p) => self.hull(p.vertices().iter().map(|&v| to_world(v)).collect()),
            // The cone lies in the convex hull of its two end discs, and reaches
            // its every edge: the hull of the rims' points, within a chord's sag.
            Shape::Cone(c) => self.hull(c.rims(RIM_POINTS).into_iter().map(to_world).collect()),
            Shape::Box(_) => {
                let b = object.shape.bounds().expect("a box is bounded");
                let corners = (0..8).map(|i: u32| {
                    DVec3::select(
                        glam::BVec3::new(i & 1 != 0, i & 2 != 0, i & 4 != 0),
                        b.max,
                        b.min,
                    )
                });
                self.hull(corners.map(to_world).collect())
            }
        }
    }

    /// A box, triangle, polygon, mesh or cone: the convex hull of its projected
    /// world vertices (for a non-convex polygon, its silhouette's hull).
    fn hull(&self, world: Vec<DVec3>) -> Outline {
        Outline::Polygon {
            points: convex_hull(world.into_iter().map(|p| self.point(p)).collect()),
        }
    }

    /// A sphere under the linear map `linear` and `translation`: the ball is
    /// {C + L·r·p : |p| ≤ 1}; its shadow on the plane is the ellipse {A·p} with
    /// A = P·L·r (P the 2×3 projection), whose shape matrix A·Aᵀ gives the axes
    /// as eigenvectors scaled by √eigenvalue.
    fn ellipse(&self, s: &Sphere, linear: DMat3, translation: DVec3) -> Outline {
        let center = self.point(linear * s.center + translation);
        let rows = [
            linear.transpose() * self.right * s.radius,
            linear.transpose() * self.up * s.radius,
        ];
        let (a, b, c) = (
            rows[0].dot(rows[0]),
            rows[0].dot(rows[1]),
            rows[1].dot(rows[1]),
        );
        let mean = (a + c) / 2.0;
        let spread = (((a - c) / 2.0).powi(2) + b * b).sqrt();
        let (l1, l2) = (mean + spread, (mean - spread).max(0.0));
        let e1 = if b.abs() > 1e-12 * (a + c) {
            DVec2::new(b, l1 - a).normalize()
        } else if a >= c {
            DVec2::X
        } else {
            DVec2::Y
        };
        Outline::Ellipse {
            center,
            axes: [e1 * l1.sqrt(), e1.perp() * l2.sqrt()],
        }
    }

    /// Where the plane through world `point` with unit `normal` crosses the
    /// diagram plane: `a·(right·m) + b·(up·m) = (p₀ - O)·m`.
    fn plane_line(&self, point: DVec3, normal: DVec3) -> Outline {
        let n2 = self.vector(normal);
        if n2.length() < 1e-9 {
            return Outline::Parallel;
        }
        let k = (point - self.origin).dot(normal);
        Outline::Line {
            point: n2 * k / n2.length_squared(),
            dir: n2.perp().normalize(),
            outward: n2.normalize(),
        }
    }
}

/// The frame of a drawing plane with unit normal `w`: `up` is world up as
/// seen in the plane (the camera's `v` when world up is nearly along `w`), and
/// `right` makes the ray `d` run left to right, so a figure never comes out
/// upside down or on its side.
fn upright(w: DVec3, d: DVec3, world_up: DVec3, camera_v: DVec3) -> (DVec3, DVec3) {
    let in_plane = |v: DVec3| (v - v.dot(w) * w).try_normalize();
    let up = in_plane(world_up)
        .filter(|u| u.dot(world_up).abs() > 1e-3)
        .or_else(|| in_plane(camera_v))
        .unwrap_or_else(|| w.any_orthonormal_vector());
    let right = up.cross(w);
    if right.dot(d) < 0.0 {
        (-right, up)
    } else {
        (right, up)
    }
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain):
/// the exact outline of a projected box or triangle, and a mesh's silhouette
/// with its hollows filled.
fn convex_hull(mut points: Vec<DVec2>) -> Vec<DVec2> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let turn = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::with_capacity(2 * points.len());
    for pass in [points.clone(), points.into_iter().rev().collect()] {
        let base = hull.len();
        for p in pass {
            while hull.len() >= base + 2
                && turn(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// An object's outline in a projection.
#[derive(Clone, Debug, PartialEq)]
pub enum Outline {
    /// A sphere or ellipsoid: `center + cos θ·axes[0] + sin θ·axes[1]`.
    Ellipse {
        /// Center.
        center: DVec2,
        /// The two semi-axes (perpendicular; equal length for a sphere).
        axes: [DVec2; 2],
    },
    /// A plane crossing the diagram plane, with its outside (the normal's side).
    Line {
        /// A point of the line.
        point: DVec2,
        /// Its unit direction.
        dir: DVec2,
        /// The unit normal of the line on the outside of the solid.
        outward: DVec2,
    },
    /// A plane parallel to the diagram plane: it covers the whole view.
    Parallel,
    /// A box, triangle or mesh: the convex hull of its projected vertices.
    Polygon {
        /// The hull's corners, counter-clockwise.
        points: Vec<DVec2>,
    },
    /// Where the drawing plane cuts a triangle or a mesh's faces.
    Segments {
        /// Each cut, end to end.
        segments: Vec<[DVec2; 2]>,
    },
}

impl Outline {
    /// The bounding box of a bounded outline.
    pub fn bounds(&self) -> Option<(DVec2, DVec2)> {
        match self {
            Outline::Ellipse { center, axes } => {
                let half = DVec2::new(axes[0].x.hypot(axes[1].x), axes[0].y.hypot(axes[1].y));
                Some((center - half, center + half))
            }
            Outline::Polygon { points } if !points.is_empty() => {
                Some(points.iter().fold((points[0], points[0]), |(lo, hi), p| {
                    (lo.min(*p), hi.max(*p))
                }))
            }
            Outline::Segments { segments } if !segments.is_empty() => {
                let first = segments[0][0];
                Some(
                    segments
                        .iter()
                        .flatten()
                        .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))),
                )
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::source::SceneSource;

    fn glass_trace() -> (crate::scene::Scene, TraceDocument) {
        let scene = crate::scene::loader::whitted();
        let trace = crate::tree::record::pixel(
            &scene,
            SceneSource::new("whitted.json", ""),
            416,
            209,
            None,
        )
        .unwrap();
        (scene, trace)
    }

    #[test]
    fn auto_view_holds_the_primary_reflected_and_refracted_rays() {
        let (scene, trace) = glass_trace();
        let proj = Projection::new(View::Auto, &trace, 0, &scene.camera());
        let w = proj.toward_viewer();
        let nodes = &trace.samples[0].tree.nodes;
        // The primary ray's origin and direction lie in the plane (to rounding).
        assert!((nodes[0].origin - proj.origin).dot(w).abs() < 1e-12);
        assert!(nodes[0].direction.normalize().dot(w).abs() < 1e-12);
        // So do the first reflected and refracted rays.
        for child in nodes[0].children() {
            assert!(
                nodes[child].direction.normalize().dot(w).abs() < 1e-12,
                "child {child}"
            );
        }
        // The frame is orthonormal, and up the page is world up (the camera's
        // look-at's up, else its v) as seen in the plane. Tolerance: a few ULPs of unit vectors.
        assert!(proj.right.dot(proj.up).abs() < 1e-15 && (proj.right.length() - 1.0).abs() < 1e-15);
        let v = trace
            .camera
            .look_at
            .as_ref()
            .map_or(trace.camera.v, |l| l.up.normalize());
        let seen = (v - v.dot(w) * w).normalize();
        assert!(proj.up.abs_diff_eq(seen, 1e-12), "{} vs {seen}", proj.up);
    }

    #[test]
    fn points_on_the_plane_map_to_their_coordinates() {
        let (scene, trace) = glass_trace();
        let proj = Projection::new(View::Auto, &trace, 0, &scene.camera());
        // The hit is the origin; one unit along the normal is (0, 1); along the ray's
        // tangent, (1, 0); 2 along the tangent and -3 along the normal, (2, -3).
        assert_eq!(proj.point(proj.origin), DVec2::ZERO);
        assert!(
            proj.point(proj.origin + proj.up)
                .abs_diff_eq(DVec2::Y, 1e-15)
        );
        assert!(
            proj.point(proj.origin + 2.0 * proj.right - 3.0 * proj.up)
                .abs_diff_eq(DVec2::new(2.0, -3.0), 1e-14)
        );
        // The primary ray arrives from the upper left: its origin has x < 0, y > 0.
        let eye = proj.point(trace.samples[0].tree.nodes[0].origin);
        assert!(eye.x < 0.0 && eye.y > 0.0, "{eye}");
    }

    #[test]
    fn outlines_are_exact() {
        let proj = Projection {
            view: View::Front,
            origin: DVec3::ZERO,
            right: DVec3::X,
            up: DVec3::Y,
        };
        let sphere = |transform| Object {
            name: "s".into(),
            shape: Shape::Sphere(crate::geometry::sphere::Sphere {
                center: DVec3::new(1.0, 2.0, 3.0),
                radius: 2.0,
            }),
            transform,
            material: 0,
        };
        // An untransformed sphere: a circle of its radius around its projected center.
        match proj.outline(&sphere(None)) {
            Outline::Ellipse { center, axes } => {
                assert_eq!(center, DVec2::new(1.0, 2.0));
                assert!(
                    (axes[0].length() - 2.0).abs() < 1e-12
                        && (axes[1].length() - 2.0).abs() < 1e-12
                );
            }
            other => panic!("{other:?}"),
        }
        // Scaled by (3, 1, 1) then turned 90° about z: x becomes y, so the ellipse is
        // 2 wide and 6 tall. The center scales too: M·(1, 2, 3) = Rz(90°)·(3, 2, 3) = (-2, 3, 3),
        // so the bounds are x in -2 ± 2 and y in 3 ± 6.
        let m = glam::DAffine3::from_rotation_z(std::f64::consts::FRAC_PI_2)
            * glam::DAffine3::from_scale(DVec3::new(3.0, 1.0, 1.0));
        let t = crate::geometry::transform::Transform::new(m).map(Box::new);
        let (lo, hi) = proj.outline(&sphere(t)).bounds().unwrap();
        assert!(
            lo.abs_diff_eq(DVec2::new(-4.0, -3.0), 1e-12)
                && hi.abs_diff_eq(DVec2::new(0.0, 9.0), 1e-12),
            "{lo} {hi}"
        );
        // The floor y = 0 seen from the front is the line y = 0, outside upward.
        let floor = Object {
            name: "f".into(),
            shape: Shape::Plane(crate::geometry::plane::Plane {
                point: DVec3::ZERO,
                normal: DVec3::Y,
            }),
            transform: None,
            material: 0,
        };
        match proj.outline(&floor) {
            Outline::Line {
                point,
                dir,
                outward,
            } => {
                assert_eq!(point.y, 0.0);
                assert!(dir.abs_diff_eq(DVec2::NEG_X, 0.0) || dir.abs_diff_eq(DVec2::X, 0.0));
                assert_eq!(outward, DVec2::Y);
            }
            other => panic!("{other:?}"),
        }
    }
}
