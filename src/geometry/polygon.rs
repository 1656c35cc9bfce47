//! Planar polygons of any number of vertices, convex or not, and polygonal
//! patches (a normal per vertex, smoothly shaded): the `p` and `pp` of Eric
//! Haines's Neutral File Format, which his Standard Procedural Databases use.
//!
//! The test has two parts.
//!
//! - **The plane.** NFF takes the normal from the first three vertices,
//!   `n = (V₁ - V₀) × (V₂ - V₀)` normalized, counter-clockwise seen from the
//!   front. Substituting the ray `S + t·c` into `(P - V₀)·n = 0` gives
//!   `t = (V₀ - S)·n / (n·c)`, the plane equation of the lecture. A ray parallel
//!   to the plane (`n·c = 0`) never meets it; a one-sided polygon also refuses
//!   a ray meeting its back (`n·c ≥ 0`). `t` is checked against the ray's
//!   interval before anything else, so a polygon behind the ray or beyond the
//!   nearest hit so far costs two dot products and a division.
//! - **Inside or outside.** The crossing-number (even–odd) test of Haines,
//!   "Point in Polygon Strategies" (Graphics Gems IV, 1994): a half-line from
//!   the point crosses the outline an odd number of times exactly when the
//!   point is inside, convex or not. It is done in the ray-sheared frame of Woop,
//!   Benthin & Wald, "Watertight Ray/Triangle Intersection" (JCGT 2(1), 2013),
//!   the frame [`Triangle::watertight`](crate::geometry::triangle::Triangle::watertight)
//!   uses ([`ShearedRay`]): each vertex is moved to the ray's origin and sheared
//!   so the ray runs along +z from (0, 0), and the point to classify is (0, 0).
//!   The half-line runs along +x. An edge `a → b` counts when it straddles
//!   `y = 0` by the half-open rule (`a_y > 0` differs from `b_y > 0`, so a
//!   vertex on the line counts once, with the edge above it) and meets the
//!   half-line at `x > 0`: the edge function `e = a_x·b_y - a_y·b_x` has the sign
//!   of `b_y - a_y` there. An `e` of exactly 0 within the straddle puts (0, 0)
//!   on the edge (or on a vertex): the ray meets the boundary, and counts as
//!   inside. So does an edge lying along `y = 0` through (0, 0), which the
//!   half-open rule sees on neither side (a vertex at (0, 0) with both its
//!   edges below, or a horizontal edge).
//!
//! Why no ray slips between two polygons sharing an edge: each edge's decision
//! uses only its own two sheared vertices, and both polygons shear the same
//! vertices for the same ray with the same operations, so they get the same
//! numbers; with the ends swapped the straddle test is the same, `e` changes
//! sign exactly (`p - q` and `q - p` round alike), and the count decision comes
//! out the same. So the sum of the crossings over the polygons is the union's
//! own count plus twice each shared edge's: odd inside the union, and some
//! polygon's count is odd. A ray exactly on a shared edge finds `e = 0` in both
//! and hits both; the tracer keeps the nearer. The same argument needs nothing
//! of triangles: a fan or a strip of quads is as tight as one polygon.
//!
//! The hit's `t` comes from the plane, not from the sheared frame: the plane
//! gives it with one division, and the point is then projected onto the plane
//! as [`Plane::surface`](crate::geometry::plane::Plane::surface) does, so its
//! error bound is a few ULPs of its size however far the ray came (pbrt-v4
//! §6.8.4). Like pbrt-v4's triangle (§6.5.3, "Ensuring a positive t"), a ray
//! whose origin lies on the plane within the rounding error of the numerator
//! `(V₀ - S)·n` does not meet it: a ray leaving the polygon never meets it again.

use glam::DVec3;

use crate::geometry::hit::{Roots, Surface};
use crate::geometry::polygon_plane::{PlaneError, plane_normal};
use crate::geometry::triangle::{ShearedRay, by_axis_order};
use crate::math::bounds::Bounds;
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// A planar polygon, or a polygonal patch with a normal per vertex.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    vertices: Vec<DVec3>,
    /// One unit normal per vertex, for a patch.
    normals: Option<Vec<DVec3>>,
    /// The unit normal of the first three vertices: the front.
    normal: DVec3,
    one_sided: bool,
    bounds: Bounds,
    /// The largest magnitude of a vertex coordinate: the scale the tests round at.
    scale: f64,
}

/// What the inside test found: how many edges the half-line from the point
/// crosses, and whether the point lies on an edge or a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crossings {
    /// Edges crossed by the half-line along +x in the sheared frame.
    pub count: u32,
    /// The point is on an edge or a vertex (an edge function of exactly 0).
    pub on_edge: bool,
}

impl Crossings {
    /// Odd, or on the boundary.
    pub fn inside(&self) -> bool {
        self.on_edge || self.count % 2 == 1
    }
}

impl Polygon {
    /// `vertices` counter-clockwise seen from the front (the normal follows from
    /// the first three, as NFF says); `normals` one per vertex (a patch) or
    /// `None`; `one_sided`: a ray meeting the back is not a hit.
    ///
    /// Refused, with a one-line reason: fewer than 3 vertices, a number that is
    /// not finite, the first three vertices on one line (within
    /// [`COLLINEAR_SINE`](crate::geometry::polygon_plane::COLLINEAR_SINE)), a
    /// vertex off their plane by more than
    /// [`PLANE_TOLERANCE`](crate::geometry::polygon_plane::PLANE_TOLERANCE), a reflex
    /// corner at the second vertex, a count of normals other than the vertices', a zero
    /// normal.
    pub fn new(
        vertices: Vec<DVec3>,
        normals: Option<Vec<DVec3>>,
        one_sided: bool,
    ) -> Result<Polygon, String> {
        if vertices.len() < 3 {
            return Err(format!(
                "a polygon needs at least 3 vertices, got {}",
                vertices.len()
            ));
        }
        if let Some(k) = vertices.iter().position(|v| !v.is_finite()) {
            return Err(format!("vertices[{k}] must be finite, got {}", vertices[k]));
        }
        let bounds = Bounds::around(vertices.iter().copied());
        let scale = (bounds.min.abs().max(bounds.max.abs())).max_element();
        let normal = plane_normal(&vertices).map_err(|e| match e {
            PlaneError::Collinear => {
                "vertices[0], vertices[1] and vertices[2] lie on one line: they give the polygon no plane"
                    .to_owned()
            }
            PlaneError::OffPlane { vertex, off, allowed } => format!(
                "vertices[{vertex}] lies {off:e} off the plane of the first three (allowed: {allowed:e})"
            ),
            PlaneError::ReflexFirstCorner => "vertices[1] is a reflex corner: the polygon's front and normal come from vertices[0], vertices[1] and vertices[2], which here turn against the outline's own winding, so it would face away (start the outline at a convex corner)".to_owned(),
        })?;
        let normals = match normals {
            None => None,
            Some(ns) if ns.len() != vertices.len() => {
                return Err(format!(
                    "a patch needs one normal per vertex: {} vertices, {} normals",
                    vertices.len(),
                    ns.len()
                ));
            }
            Some(ns) => Some(
                ns.iter()
                    .enumerate()
                    .map(|(k, n)| {
                        if !n.is_finite() {
                            Err(format!("normals[{k}] must be finite, got {n}"))
                        } else {
                            n.try_normalize()
                                .ok_or_else(|| format!("normals[{k}] must not be zero"))
                        }
                    })
                    .collect::<Result<Vec<_>, _>>()?,
            ),
        };
        Ok(Polygon {
            vertices,
            normals,
            normal,
            one_sided,
            bounds,
            scale,
        })
    }

    /// The vertices, in order.
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The per-vertex unit normals of a patch.
    pub fn normals(&self) -> Option<&[DVec3]> {
        self.normals.as_deref()
    }

    /// The unit normal of the first three vertices, toward the front.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// Whether a ray meeting the back misses.
    pub fn one_sided(&self) -> bool {
        self.one_sided
    }

    /// The box around the vertices.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }

    /// The plane's two numbers for `ray`: `n·c` and `(V₀ - S)·n`, so
    /// `t = numerator / n_dot_c`.
    #[inline]
    pub fn plane(&self, ray: &Ray) -> (f64, f64) {
        (
            self.normal.dot(ray.dir),
            self.normal.dot(self.vertices[0] - ray.origin),
        )
    }

    /// The root in `(0, t_max)`, if the ray meets the polygon there (see the
    /// module's documentation).
    #[inline]
    pub fn roots(&self, ray: &Ray, t_max: f64) -> Roots {
        let n_dot_c = self.normal.dot(ray.dir);
        if n_dot_c == 0.0 || (self.one_sided && n_dot_c >= 0.0) {
            return Roots::NONE;
        }
        let to_plane = self.vertices[0] - ray.origin;
        let numerator = self.normal.dot(to_plane);
        let t = numerator / n_dot_c;
        if !(t > 0.0 && t < t_max) || numerator.abs() <= numerator_error(self.normal, to_plane) {
            return Roots::NONE;
        }
        if self.crossings(&ShearedRay::new(ray)).inside() {
            Roots::one(t)
        } else {
            Roots::NONE
        }
    }

    /// Haines's crossing-number test of the ray's own point (0, 0) in the
    /// sheared frame of `ray`, edge by edge (see the module's documentation).
    #[inline]
    pub fn crossings(&self, ray: &ShearedRay) -> Crossings {
        by_axis_order!(ray.axis_order(), |KX, KY, KZ| self
            .crossings_in::<KX, KY, KZ>(ray))
    }

    /// [`Polygon::crossings`] for the ray's axis order `KX, KY, KZ`, chosen once
    /// for all the vertices (reading a coordinate by a run-time axis is a branch).
    #[inline(always)]
    fn crossings_in<const KX: usize, const KY: usize, const KZ: usize>(
        &self,
        ray: &ShearedRay,
    ) -> Crossings {
        let mut found = Crossings {
            count: 0,
            on_edge: false,
        };
        let xy = |p: DVec3| ray.sheared_xy_in::<KX, KY, KZ>(p);
        let (mut ax, mut ay) = xy(self.vertices[self.vertices.len() - 1]);
        for &v in &self.vertices {
            let (bx, by) = xy(v);
            if (ay > 0.0) != (by > 0.0) {
                let e = ax * by - ay * bx;
                if e == 0.0 {
                    found.on_edge = true;
                } else if (e > 0.0) == (by > 0.0) {
                    found.count += 1;
                }
            } else if by == 0.0 && ay == 0.0 && ax.min(bx) <= 0.0 && ax.max(bx) >= 0.0 {
                // An edge along the half-line's own line, through (0, 0) or
                // ending there: the half-open rule counts it on neither side.
                found.on_edge = true;
            }
            (ax, ay) = (bx, by);
        }
        found
    }

    /// The surface at `ray.at(t)`: the point projected onto the plane (so its
    /// error is a few ULPs of its own size, as for [`crate::geometry::plane`]),
    /// the front's normal, and for a patch the shading normal interpolated from
    /// the vertices' (see [`Polygon::patch_normal`]), on the geometric normal's
    /// side.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        let n = self.normal;
        let v0 = self.vertices[0];
        let p = ray.at(t);
        let point = p - (p - v0).dot(n) * n;
        // The projection's own rounding (as for a plane), and never below the
        // scale the next test rounds at: it shears every vertex to the next
        // ray's origin, so closer than `γ(7)·max|vᵢ|` an origin is on the
        // polygon as far as it can tell (as for a triangle, see
        // `Triangle::surface`).
        let error = (gamma(8) * (point.abs().max_element() + v0.abs().max_element()))
            .max(gamma(7) * self.scale);
        let shading = self
            .normals
            .as_deref()
            .map(|normals| self.patch_normal(normals, point))
            .filter(|s| *s != DVec3::ZERO)
            .map_or(n, |s| if s.dot(n) < 0.0 { -s } else { s });
        Surface {
            point,
            point_error: DVec3::splat(error),
            normal: n,
            shading_normal: shading,
            pattern_point: point,
        }
    }

    /// The vertex normals mixed at `p` (on the plane): by the barycentric
    /// weights of `p` in the fan triangle `(V₀, Vᵢ, Vᵢ₊₁)` that holds it (for a
    /// triangle, its own weights). A convex polygon's fan covers it once; in a
    /// non-convex one's, fan triangles overlap or stick out, and the first that
    /// holds `p` is taken, or, when none does, the one `p` is least outside of
    /// (its smallest weight the largest). Normalized; zero if the mix is.
    pub fn patch_normal(&self, normals: &[DVec3], p: DVec3) -> DVec3 {
        let (v, n) = (&self.vertices, self.normal);
        let mut best = (f64::NEG_INFINITY, DVec3::ZERO);
        for i in 1..v.len() - 1 {
            let (a, b, c) = (v[0], v[i], v[i + 1]);
            // Twice the signed areas along n: each vertex's weight is the area
            // of the triangle p makes with the opposite edge, over the whole's.
            let whole = (b - a).cross(c - a).dot(n);
            if whole == 0.0 {
                continue;
            }
            let area = |u: DVec3, w: DVec3| (u - p).cross(w - p).dot(n);
            let weights = DVec3::new(area(b, c), area(c, a), area(a, b)) / whole;
            let least = weights.min_element();
            if least > best.0 {
                let mix =
                    weights.x * normals[0] + weights.y * normals[i] + weights.z * normals[i + 1];
                best = (least, mix);
            }
            if least >= 0.0 {
                break;
            }
        }
        best.1.normalize_or_zero()
    }
}

/// A bound on the rounding error of the numerator `n·(V₀ - S)`: one rounding
/// in each difference, three in the dot product (pbrt-v4's γ(n), §6.8.1).
#[inline]
fn numerator_error(n: DVec3, to_plane: DVec3) -> f64 {
    gamma(4) * n.abs().dot(to_plane.abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z)
    }

    /// The square 0 ≤ x, y ≤ 2 in z = 0, counter-clockwise seen from +z.
    fn square(one_sided: bool) -> Polygon {
        let corners = vec![v(0., 0., 0.), v(2., 0., 0.), v(2., 2., 0.), v(0., 2., 0.)];
        Polygon::new(corners, None, one_sided).unwrap()
    }

    /// An L: the square 0 ≤ x, y ≤ 2 without its corner 1 < x, y ≤ 2 (the notch).
    fn ell() -> Polygon {
        let corners = vec![
            v(0., 0., 0.),
            v(2., 0., 0.),
            v(2., 1., 0.),
            v(1., 1., 0.),
            v(1., 2., 0.),
            v(0., 2., 0.),
        ];
        Polygon::new(corners, None, false).unwrap()
    }

    fn hit(p: &Polygon, origin: DVec3, dir: DVec3) -> Option<f64> {
        p.roots(&Ray::new(origin, dir), f64::INFINITY)
            .first_in(0.0, f64::INFINITY)
    }

    #[test]
    fn a_square_is_met_where_worked_out() {
        // From (0.5, 0.5, 3) along -z: n = +z, n·c = -1, (V₀ - S)·n = -3, t = 3.
        // Along (0, 0, -2): n·c = -2, t = 1.5, the same point.
        let sq = square(false);
        assert_eq!(sq.normal(), DVec3::Z);
        assert_eq!(hit(&sq, v(0.5, 0.5, 3.), DVec3::NEG_Z), Some(3.0));
        assert_eq!(hit(&sq, v(0.5, 0.5, 3.), v(0., 0., -2.)), Some(1.5));
        // Slanted, from (-1, 1, 2) along (1, 0.25, -1): z = 0 at t = 2, at
        // (1, 1.5, 0), inside. Exact in binary, so compared exactly.
        let ray = Ray::new(v(-1., 1., 2.), v(1., 0.25, -1.));
        assert_eq!(sq.roots(&ray, f64::INFINITY).as_slice(), [2.0]);
        let s = sq.surface(&ray, 2.0);
        assert_eq!(s.point, v(1., 1.5, 0.));
        assert_eq!((s.normal, s.shading_normal), (DVec3::Z, DVec3::Z));
        // Beside it: (3, 1, 0) and (1, -0.5, 0) are outside.
        assert_eq!(hit(&sq, v(3., 1., 3.), DVec3::NEG_Z), None);
        assert_eq!(hit(&sq, v(1., -0.5, 3.), DVec3::NEG_Z), None);
    }

    #[test]
    fn a_non_convex_polygon_misses_in_its_notch_and_hits_in_its_arms() {
        let l = ell();
        // The notch (1.5, 1.5) is inside the hull, outside the L: the half-line
        // along +x from it crosses nothing... in the sheared frame of a ray
        // along -z, which swaps x and y; either way an even count.
        let notch = Ray::new(v(1.5, 1.5, 1.), DVec3::NEG_Z);
        let c = l.crossings(&ShearedRay::new(&notch));
        assert!(!c.inside(), "{c:?}");
        assert_eq!(hit(&l, v(1.5, 1.5, 1.), DVec3::NEG_Z), None);
        for (x, y) in [(1.5, 0.5), (0.5, 1.5), (0.5, 0.5), (0.25, 1.9), (1.9, 0.1)] {
            assert_eq!(hit(&l, v(x, y, 1.), DVec3::NEG_Z), Some(1.0), "({x}, {y})");
        }
        for (x, y) in [(2.5, 0.5), (1.5, 2.5), (-0.1, 1.0), (1.01, 1.01)] {
            assert_eq!(hit(&l, v(x, y, 1.), DVec3::NEG_Z), None, "({x}, {y})");
        }
        // Seen slanted, from above the notch toward the arm below it: the
        // plane is met at (1.5, 0.5, 0), t = 1.
        assert_eq!(hit(&l, v(1.5, 1.5, 1.), v(0., -1., -1.)), Some(1.0));
    }

    #[test]
    fn the_boundary_counts_as_inside() {
        let l = ell();
        // On an edge, on the reflex vertex (1, 1), on a convex corner.
        for (x, y) in [(1.0, 0.0), (1.5, 1.0), (1.0, 1.0), (2.0, 0.0), (0.0, 2.0)] {
            let ray = Ray::new(v(x, y, 1.), DVec3::NEG_Z);
            let c = l.crossings(&ShearedRay::new(&ray));
            assert!(c.inside(), "({x}, {y}): {c:?}");
            assert_eq!(hit(&l, v(x, y, 1.), DVec3::NEG_Z), Some(1.0), "({x}, {y})");
        }
    }

    #[test]
    fn a_one_sided_polygon_is_not_met_from_the_back() {
        // From below, along +z: n·c = 1 ≥ 0, the back.
        assert_eq!(hit(&square(true), v(0.5, 0.5, -3.), DVec3::Z), None);
        assert_eq!(hit(&square(false), v(0.5, 0.5, -3.), DVec3::Z), Some(3.0));
        assert_eq!(hit(&square(true), v(0.5, 0.5, 3.), DVec3::NEG_Z), Some(3.0));
    }

    #[test]
    fn parallel_behind_and_beyond_rays_miss() {
        let sq = square(false);
        // In the plane, across the square; above it, parallel.
        assert_eq!(hit(&sq, v(-1., 1., 0.), DVec3::X), None);
        assert_eq!(hit(&sq, v(-1., 1., 1.), DVec3::X), None);
        // Away from it: t = -3.
        assert_eq!(hit(&sq, v(0.5, 0.5, 3.), DVec3::Z), None);
        // Past the end of the interval: t = 3 is not below t_max = 3.
        let ray = Ray::new(v(0.5, 0.5, 3.), DVec3::NEG_Z);
        assert_eq!(sq.roots(&ray, 3.0).as_slice(), [] as [f64; 0]);
    }

    #[test]
    fn a_grazing_ray_hits_where_the_plane_says() {
        // From (-1, 1, 1e-6) along (1.5, 0, -1e-6): z = 0 at t = 1, x = 0.5.
        let sq = square(false);
        let t = hit(&sq, v(-1., 1., 1e-6), v(1.5, 0., -1e-6)).expect("a hit");
        // t = 1e-6/1e-6, each a rounded decimal: a few ULPs.
        assert!((t - 1.0).abs() < 1e-15, "{t}");
        // The same ray aimed at x = 2.5, past the square's far edge, misses.
        assert_eq!(hit(&sq, v(-1., 1., 1e-6), v(3.5, 0., -1e-6)), None);
    }

    #[test]
    fn a_ray_leaving_the_polygon_does_not_meet_it_again() {
        // From on the plane (inside it, as a secondary ray with no offset
        // would start), upward or along it: the numerator is 0.
        let sq = square(false);
        for dir in [v(0.3, 0.2, 1.), v(0.3, 0.2, -1.), DVec3::X] {
            assert_eq!(hit(&sq, v(0.5, 0.5, 0.), dir), None, "{dir}");
        }
        // From the robust offset origin of a tilted, far polygon's hit, toward
        // lights on both sides: never again.
        let tilt = |x: f64, y: f64| v(1e4 + x, 3e3 + 0.3 * x + 0.7 * y, -2e4 + y);
        let p = Polygon::new(
            vec![
                tilt(0., 0.),
                tilt(7., 0.),
                tilt(9., 5.),
                tilt(3., 8.),
                tilt(-2., 4.),
            ],
            None,
            false,
        )
        .unwrap();
        let eye = tilt(2., 2.) + v(-3., 40., 5.);
        for i in 0..20 {
            for j in 0..20 {
                let target = tilt(f64::from(i) * 0.3 + 0.1, f64::from(j) * 0.3 + 0.2);
                let ray = Ray::new(eye, target - eye);
                let Some(t) = hit(&p, eye, target - eye) else {
                    continue;
                };
                let s = p.surface(&ray, t);
                for light in [eye, eye + v(30., -80., 2.), s.point + v(1e3, 1., -1e3)] {
                    let o = s.ray_origin(crate::methods::Offset::Robust, light - s.point);
                    let again = hit(&p, o, light - o);
                    assert_eq!(again, None, "from {o} toward {light}");
                }
            }
        }
    }

    #[test]
    fn a_patch_interpolates_its_normals() {
        let (a, b, c) = (v(0., 0., 0.), v(3., 0., 0.), v(0., 3., 0.));
        let normals = vec![v(0., 0., 2.), v(1., 0., 1.), v(0., -1., 1.)];
        let tri = Polygon::new(vec![a, b, c], Some(normals.clone()), false).unwrap();
        // Straight down onto each vertex: that vertex's own normal (normalized):
        // the weights there are exactly (1, 0, 0) and its permutations.
        for (k, &corner) in [a, b, c].iter().enumerate() {
            let ray = Ray::new(corner + DVec3::Z, DVec3::NEG_Z);
            let s = tri.surface(&ray, 1.0);
            // Normalizing rounds: an ULP or two.
            assert!(
                (s.shading_normal - normals[k].normalize()).length() < 1e-15,
                "vertex {k}: {}",
                s.shading_normal
            );
            assert_eq!(s.normal, DVec3::Z);
        }
        // At the centroid (1, 1, 0) the weights are ⅓ each: the mean, normalized.
        let ray = Ray::new(v(1., 1., 1.), DVec3::NEG_Z);
        let mean = (normals[0].normalize() + normals[1].normalize() + normals[2].normalize()) / 3.0;
        let s = tri.surface(&ray, 1.0);
        // Weights of ⅓ are rounded, and so is every step after: a few ULPs.
        assert!(
            (s.shading_normal - mean.normalize()).length() < 1e-15,
            "{}",
            s.shading_normal
        );
        // A square's fan: (1.5, 0.5) lies in the first triangle (V₀, V₁, V₂)
        // with weights (0.25, 0.5, 0.25); (0.5, 1.5) in the second (V₀, V₂, V₃)
        // with (0.25, 0.25, 0.5).
        let ns = vec![DVec3::Z, DVec3::X, DVec3::Y, DVec3::NEG_X];
        let sq = Polygon::new(square(false).vertices().to_vec(), Some(ns.clone()), false).unwrap();
        let at = |x: f64, y: f64| {
            sq.surface(&Ray::new(v(x, y, 1.), DVec3::NEG_Z), 1.0)
                .shading_normal
        };
        let first = (0.25 * ns[0] + 0.5 * ns[1] + 0.25 * ns[2]).normalize();
        let second = (0.25 * ns[0] + 0.25 * ns[2] + 0.5 * ns[3]).normalize();
        // Products and sums of quarters and halves are exact; normalizing rounds.
        assert!((at(1.5, 0.5) - first).length() < 1e-15, "{}", at(1.5, 0.5));
        assert!((at(0.5, 1.5) - second).length() < 1e-15, "{}", at(0.5, 1.5));
    }

    #[test]
    fn a_patch_normal_against_the_front_is_turned_to_it() {
        let down = vec![DVec3::NEG_Z; 4];
        let sq = Polygon::new(square(false).vertices().to_vec(), Some(down), false).unwrap();
        let s = sq.surface(&Ray::new(v(1., 1., 1.), DVec3::NEG_Z), 1.0);
        assert_eq!((s.normal, s.shading_normal), (DVec3::Z, DVec3::Z));
    }

    #[test]
    fn bad_polygons_are_refused_with_one_line() {
        let sq = square(false).vertices().to_vec();
        let refused = |vs: Vec<DVec3>, ns: Option<Vec<DVec3>>| {
            let why = Polygon::new(vs, ns, false).unwrap_err();
            assert!(!why.contains('\n'), "{why}");
            why
        };
        assert!(refused(sq[..2].to_vec(), None).contains("at least 3"));
        let mut nan = sq.clone();
        nan[3].y = f64::NAN;
        assert!(refused(nan, None).contains("vertices[3] must be finite"));
        let mut inf = sq.clone();
        inf[0].x = f64::INFINITY;
        assert!(refused(inf, None).contains("vertices[0] must be finite"));
        let line = vec![v(0., 0., 0.), v(1., 1., 1.), v(2., 2., 2.), v(0., 1., 0.)];
        assert!(refused(line, None).contains("one line"));
        let repeated = vec![v(0., 0., 0.), v(0., 0., 0.), v(2., 2., 0.)];
        assert!(refused(repeated, None).contains("one line"));
        let mut bent = sq.clone();
        bent[3].z = 0.01;
        assert!(refused(bent, None).contains("vertices[3] lies 1e-2 off"));
        let arrow = vec![v(2., -1., 0.), v(1., 0., 0.), v(2., 1., 0.), v(0., 0., 0.)];
        assert!(refused(arrow, None).contains("vertices[1] is a reflex corner"));
        // Within the tolerance (1e-5 of the size 2): accepted.
        let mut nearly = sq.clone();
        nearly[3].z = 1e-5;
        assert!(Polygon::new(nearly, None, false).is_ok());
        assert!(refused(sq.clone(), Some(vec![DVec3::Z; 3])).contains("4 vertices, 3 normals"));
        let mut zero = vec![DVec3::Z; 4];
        zero[2] = DVec3::ZERO;
        assert!(refused(sq.clone(), Some(zero)).contains("normals[2] must not be zero"));
        let mut nan = vec![DVec3::Z; 4];
        nan[1].x = f64::NAN;
        assert!(refused(sq, Some(nan)).contains("normals[1] must be finite"));
    }
}
