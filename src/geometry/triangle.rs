//! Ray–triangle intersection, two ways.
//!
//! [`Triangle::moller_trumbore`] is the textbook test (Möller & Trumbore, "Fast,
//! Minimum Storage Ray/Triangle Intersection", 1997): solve `S + t·c = A + u·e₁ + v·e₂`
//! by Cramer's rule and accept `u, v ≥ 0, u + v ≤ 1`. Two triangles sharing an edge
//! compute that edge's test from different numbers, so a ray through the edge can
//! round outside both: a crack the background shows through. Nor does it bound
//! the rounding error of its `t`: a ray leaving the triangle (or a neighbour in
//! its plane) can meet it again at a `t` of rounding size, on the wrong side of
//! 0. Kept as the textbook has it, to show both.
//!
//! [`Triangle::watertight`] is Woop, Benthin & Wald's ("Watertight Ray/Triangle
//! Intersection", JCGT 2(1), 2013): translate the vertices to the ray origin, shear
//! them so the ray runs along +z, and evaluate the three 2D edge functions. An edge
//! function of a shared edge is computed from the same two sheared vertices by both
//! triangles, with the operands swapped, and `a·b - c·d` swaps sign exactly: a ray
//! can never fall between them. (The paper re-evaluates an edge function that rounds
//! to exactly 0 in double precision; we already compute in double, and a zero counts
//! as inside for both neighbours, which keeps the test watertight.) Like pbrt-v4
//! (§6.5.3) it also bounds the rounding error of `t` and refuses a hit within it
//! of the origin, so a ray leaving the triangle never meets it again.

use glam::DVec3;

use crate::geometry::hit::Surface;
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// A triangle with vertices `a`, `b`, `c`; counter-clockwise seen from the side its
/// geometric normal `(b - a) × (c - a)` points to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    /// First vertex.
    pub a: DVec3,
    /// Second vertex.
    pub b: DVec3,
    /// Third vertex.
    pub c: DVec3,
}

/// Where a ray meets a triangle: `t` and the barycentric weights of `a`, `b`, `c`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    /// Ray parameter.
    pub t: f64,
    /// Weights of the vertices `a`, `b`, `c`; they sum to 1.
    pub bary: DVec3,
}

/// A watertight hit before its weights are divided out: `t`, the edge
/// functions and their sum.
#[derive(Clone, Copy)]
struct Edges {
    t: f64,
    u: f64,
    v: f64,
    w: f64,
    det: f64,
}

/// A ray prepared for the watertight test: the axis it runs most along becomes z,
/// and the shear that makes it run along +z (Woop et al., section 3).
#[derive(Clone, Copy, Debug)]
pub struct ShearedRay {
    origin: DVec3,
    /// Permutation: which world axes become x, y, z.
    k: [usize; 3],
    shear: DVec3,
}

impl ShearedRay {
    /// Prepares `ray` (once, for every triangle it is tested against).
    #[inline]
    pub fn new(ray: &Ray) -> Self {
        let d = ray.dir;
        let a = d.abs();
        let kz = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let mut kx = (kz + 1) % 3;
        let mut ky = (kx + 1) % 3;
        // Keep the winding: swap x and y when the ray runs along -z.
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        ShearedRay {
            origin: ray.origin,
            k: [kx, ky, kz],
            shear: DVec3::new(d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]),
        }
    }

    /// `p` moved to the ray's origin and sheared: its (x, y) across the ray,
    /// the same operations [`Triangle::watertight`] does on its vertices, so a
    /// polygon and a triangle sharing a vertex get the same numbers for it.
    #[inline]
    pub fn sheared_xy(&self, p: DVec3) -> (f64, f64) {
        by_axis_order!(self.k, |KX, KY, KZ| self.sheared_xy_in::<KX, KY, KZ>(p))
    }

    /// [`ShearedRay::sheared_xy`] for the ray's axis order `KX, KY, KZ` (its
    /// `k`), read at fixed places: a test of many vertices picks the order once
    /// with [`by_axis_order!`] instead of once a coordinate.
    #[inline(always)]
    pub(crate) fn sheared_xy_in<const KX: usize, const KY: usize, const KZ: usize>(
        &self,
        p: DVec3,
    ) -> (f64, f64) {
        debug_assert_eq!(self.k, [KX, KY, KZ]);
        let o = self.origin;
        let (x, y, z) = (p[KX] - o[KX], p[KY] - o[KY], p[KZ] - o[KZ]);
        (x - self.shear.x * z, y - self.shear.y * z)
    }

    /// Which world axes become x, y, z (see [`by_axis_order!`]).
    #[inline(always)]
    pub(crate) fn axis_order(&self) -> [usize; 3] {
        self.k
    }
}

/// Runs `$body` with the const generics `$kx, $ky, $kz` set to the axis order
/// `$k` of a [`ShearedRay`] (one of the six the ray's largest direction
/// component and its sign give), so the code inside reads each coordinate at a
/// fixed place with no branch.
macro_rules! by_axis_order {
    ($k:expr, |$kx:ident, $ky:ident, $kz:ident| $body:expr) => {{
        match $k {
            [1, 2, 0] => {
                const $kx: usize = 1;
                const $ky: usize = 2;
                const $kz: usize = 0;
                $body
            }
            [2, 1, 0] => {
                const $kx: usize = 2;
                const $ky: usize = 1;
                const $kz: usize = 0;
                $body
            }
            [2, 0, 1] => {
                const $kx: usize = 2;
                const $ky: usize = 0;
                const $kz: usize = 1;
                $body
            }
            [0, 2, 1] => {
                const $kx: usize = 0;
                const $ky: usize = 2;
                const $kz: usize = 1;
                $body
            }
            [0, 1, 2] => {
                const $kx: usize = 0;
                const $ky: usize = 1;
                const $kz: usize = 2;
                $body
            }
            _ => {
                const $kx: usize = 1;
                const $ky: usize = 0;
                const $kz: usize = 2;
                $body
            }
        }
    }};
}
pub(crate) use by_axis_order;

impl Triangle {
    /// The geometric normal `(b - a) × (c - a)`, unit length; zero if degenerate.
    pub fn normal(&self) -> DVec3 {
        (self.b - self.a).cross(self.c - self.a).normalize_or_zero()
    }

    /// The barycentric weights of a point in the triangle's plane: each vertex's
    /// weight is the area of the triangle the point makes with the opposite edge.
    pub fn barycentric(&self, p: DVec3) -> DVec3 {
        let n = (self.b - self.a).cross(self.c - self.a);
        let area = |u: DVec3, v: DVec3| (u - p).cross(v - p).dot(n);
        DVec3::new(
            area(self.b, self.c),
            area(self.c, self.a),
            area(self.a, self.b),
        ) / n.dot(n)
    }

    /// Woop, Benthin & Wald's watertight test, both sides, within `(t_min, t_max)`,
    /// and, as pbrt-v4 adds, never within its own rounding error of `t = 0`.
    #[inline]
    pub fn watertight(&self, ray: &ShearedRay, t_min: f64, t_max: f64) -> Option<TriangleHit> {
        self.watertight_edges(ray, t_min, t_max)
            .map(|Edges { t, u, v, w, det }| TriangleHit {
                t,
                bary: DVec3::new(u, v, w) / det,
            })
    }

    /// [`Triangle::watertight`]'s `t` alone, for a search that needs only the
    /// nearest hit: the weights wait for [`Triangle::surface`] of the one kept.
    #[inline(always)]
    pub fn watertight_t(&self, ray: &ShearedRay, t_min: f64, t_max: f64) -> Option<f64> {
        self.watertight_edges(ray, t_min, t_max).map(|e| e.t)
    }

    /// The test for the ray's axis permutation, chosen once here so that the
    /// test proper reads each coordinate at a fixed place, with no branch.
    #[inline(always)]
    fn watertight_edges(&self, ray: &ShearedRay, t_min: f64, t_max: f64) -> Option<Edges> {
        by_axis_order!(ray.k, |KX, KY, KZ| self
            .watertight_in::<KX, KY, KZ>(ray, t_min, t_max))
    }

    /// The test proper, with the world axes `KX, KY, KZ` becoming x, y, z.
    #[inline(always)]
    fn watertight_in<const KX: usize, const KY: usize, const KZ: usize>(
        &self,
        ray: &ShearedRay,
        t_min: f64,
        t_max: f64,
    ) -> Option<Edges> {
        let s = ray.shear;
        let o = ray.origin;
        // Each vertex moved to the ray's origin, only on the axes read.
        let to_origin = |p: DVec3| (p[KX] - o[KX], p[KY] - o[KY], p[KZ] - o[KZ]);
        let (a, b, c) = (to_origin(self.a), to_origin(self.b), to_origin(self.c));
        let (ax, ay) = (a.0 - s.x * a.2, a.1 - s.y * a.2);
        let (bx, by) = (b.0 - s.x * b.2, b.1 - s.y * b.2);
        let (cx, cy) = (c.0 - s.x * c.2, c.1 - s.y * c.2);
        // Edge functions: the signed areas of the sheared 2D triangles the origin
        // makes with each edge.
        let u = cx * by - cy * bx;
        let v = ax * cy - ay * cx;
        let w = bx * ay - by * ax;
        if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
            return None;
        }
        let det = u + v + w;
        if det == 0.0 {
            return None;
        }
        // Scaled distance, compared before dividing (the paper's sign trick, here
        // written as a plain division since we keep both sides).
        let (az, bz, cz) = (s.z * a.2, s.z * b.2, s.z * c.2);
        let t = (u * az + v * bz + w * cz) / det;
        if !(t > t_min && t < t_max) {
            return None;
        }
        // pbrt-v4 §6.5.3 ("Ensuring a positive t"): a conservative bound on the
        // rounding error of `t`, from those of the sheared coordinates and of the
        // edge functions. A `t` within it of 0 may as well lie on the other side
        // of the origin: a ray leaving this triangle would meet it again.
        let max3 = |p: f64, q: f64, r: f64| p.abs().max(q.abs()).max(r.abs());
        let (max_xt, max_yt, max_zt) = (max3(ax, bx, cx), max3(ay, by, cy), max3(az, bz, cz));
        let delta_x = gamma(5) * (max_xt + max_zt);
        let delta_y = gamma(5) * (max_yt + max_zt);
        let delta_z = gamma(3) * max_zt;
        let delta_e = 2.0 * (gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
        let max_e = max3(u, v, w);
        let delta_t =
            3.0 * (gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) / det.abs();
        if t.abs() <= delta_t {
            return None;
        }
        Some(Edges { t, u, v, w, det })
    }

    /// The textbook Möller–Trumbore test, both sides, within `(t_min, t_max)`: not
    /// watertight, and with no bound on the rounding error of `t` (see the module's
    /// documentation); only the offset of a secondary ray's origin keeps such a ray
    /// off the surface it leaves.
    #[inline]
    pub fn moller_trumbore(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<TriangleHit> {
        let e1 = self.b - self.a;
        let e2 = self.c - self.a;
        let p = ray.dir.cross(e2);
        let det = e1.dot(p);
        if det == 0.0 {
            return None;
        }
        let inv = 1.0 / det;
        let s = ray.origin - self.a;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(e1);
        let v = ray.dir.dot(q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return None;
        }
        let t = e2.dot(q) * inv;
        if !(t > t_min && t < t_max) {
            return None;
        }
        Some(TriangleHit {
            t,
            bary: DVec3::new(1.0 - u - v, u, v),
        })
    }

    /// The surface at a hit. The point is the barycentric mix of the vertices, not
    /// `S + t·c`: its error bound is then pbrt-v4's `γ(7)·Σ|bᵢ·pᵢ|` (§6.8.4), small
    /// and independent of how far the ray came from. `normals` are per-vertex
    /// normals to interpolate for shading.
    ///
    /// That bound counts each vertex by its weight: at a vertex, only that vertex's
    /// coordinates count, and at a vertex at the world origin nothing does. The
    /// bound was then 0 and the robust offset one subnormal step (5e-324), and a
    /// shadow ray met a neighbouring face again at t ≈ 1e-18 (lesson 13's sheet
    /// under Möller–Trumbore). Yet the test that meets the next ray with this
    /// triangle and its neighbours computes with all their vertices
    /// (Möller–Trumbore with `S − A` and the edges, the watertight test with the
    /// vertices moved to the ray's origin, an origin on this surface), so it
    /// rounds at their scale, not the point's: closer to the surface than
    /// `γ(7)·max|pᵢ|`, an origin is on it as far as either test can tell. That is
    /// the bound's floor, the same on every axis, as for the other shapes.
    pub fn surface(&self, hit: &TriangleHit, normals: Option<[DVec3; 3]>) -> Surface {
        let w = hit.bary;
        let point = w.x * self.a + w.y * self.b + w.z * self.c;
        let error = gamma(7) * ((w.x * self.a).abs() + (w.y * self.b).abs() + (w.z * self.c).abs());
        let normal = self.normal();
        let shading = normals
            .map(|n| (w.x * n[0] + w.y * n[1] + w.z * n[2]).normalize_or_zero())
            .filter(|n| *n != DVec3::ZERO)
            .map_or(normal, |n| if n.dot(normal) < 0.0 { -n } else { n });
        let vertices = self.a.abs().max(self.b.abs()).max(self.c.abs());
        Surface {
            point,
            // Never zero, nor subnormal (see `Plane::surface`).
            point_error: error.max(DVec3::splat(gamma(7) * vertices.max_element())),
            normal,
            shading_normal: shading,
            pattern_point: point,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri() -> Triangle {
        Triangle {
            a: DVec3::new(0.0, 0.0, 0.0),
            b: DVec3::new(1.0, 0.0, 0.0),
            c: DVec3::new(0.0, 1.0, 0.0),
        }
    }

    #[test]
    fn both_tests_agree_on_an_interior_hit() {
        // From (0.25, 0.25, 2) straight down: hits z = 0 at t = 2, weights (0.5, 0.25, 0.25).
        for dir in [DVec3::NEG_Z, DVec3::new(0.0, 0.0, -2.0)] {
            let ray = Ray::new(DVec3::new(0.25, 0.25, 2.0), dir);
            let w = tri()
                .watertight(&ShearedRay::new(&ray), 0.0, f64::INFINITY)
                .unwrap();
            let m = tri().moller_trumbore(&ray, 0.0, f64::INFINITY).unwrap();
            let t = 2.0 / dir.length();
            for h in [w, m] {
                assert!((h.t - t).abs() < 1e-15, "{h:?}");
                assert!(
                    (h.bary - DVec3::new(0.5, 0.25, 0.25)).length() < 1e-15,
                    "{h:?}"
                );
            }
        }
    }

    #[test]
    fn misses_outside_behind_and_parallel() {
        let s = |o: DVec3, d: DVec3| {
            let r = Ray::new(o, d);
            (
                tri().watertight(&ShearedRay::new(&r), 0.0, f64::INFINITY),
                tri().moller_trumbore(&r, 0.0, f64::INFINITY),
            )
        };
        assert_eq!(s(DVec3::new(0.8, 0.8, 1.0), DVec3::NEG_Z), (None, None));
        assert_eq!(s(DVec3::new(0.2, 0.2, 1.0), DVec3::Z), (None, None));
        assert_eq!(s(DVec3::new(0.2, 0.2, 1.0), DVec3::X), (None, None));
    }

    #[test]
    fn hits_from_the_back_too() {
        let ray = Ray::new(DVec3::new(0.2, 0.2, -1.0), DVec3::Z);
        assert!(tri().watertight(&ShearedRay::new(&ray), 0.0, 9.0).is_some());
        assert!(tri().moller_trumbore(&ray, 0.0, 9.0).is_some());
    }

    #[test]
    fn surface_interpolates_normals_on_the_geometric_side() {
        let ray = Ray::new(DVec3::new(0.25, 0.25, 2.0), DVec3::NEG_Z);
        let hit = tri().watertight(&ShearedRay::new(&ray), 0.0, 9.0).unwrap();
        let flat = tri().surface(&hit, None);
        assert_eq!(flat.normal, DVec3::Z);
        assert_eq!(flat.shading_normal, DVec3::Z);
        let tilted = DVec3::new(1.0, 0.0, 1.0).normalize();
        let s = tri().surface(&hit, Some([tilted; 3]));
        assert!((s.shading_normal - tilted).length() < 1e-15);
        assert!((s.point - DVec3::new(0.25, 0.25, 0.0)).length() < 1e-16);
    }

    /// How many of 40 × 40 points on `tri` around `focus` (within 3 along each
    /// leg), each seen from `eye` and lit by `light`, send a shadow ray (started
    /// with the robust offset) that `test` says meets `tri` itself on its way to
    /// the light, and how many were seen. The hit's weights are the test's own (a
    /// mesh's face) or, `from_point`, worked out afresh from the point `S + t·c`
    /// (a triangle object).
    fn self_shadowed(
        tri: &Triangle,
        (focus, eye, light): (DVec3, DVec3, DVec3),
        test: fn(&Triangle, &Ray) -> Option<TriangleHit>,
        from_point: bool,
    ) -> (usize, usize) {
        let (along_b, along_c) = ((tri.b - tri.a).normalize(), (tri.c - tri.a).normalize());
        let (mut seen, mut blocked) = (0, 0);
        for i in 0..40 {
            for j in 0..40 {
                let step = |k: i32| (f64::from(k) + 0.3) * 6.0 / 40.0 - 3.0;
                let target = focus + step(i) * along_b + step(j) * along_c;
                let primary = Ray::new(eye, target - eye);
                let Some(mut hit) = test(tri, &primary) else {
                    continue;
                };
                if from_point {
                    hit.bary = tri.barycentric(primary.at(hit.t));
                }
                let s = tri.surface(&hit, None);
                let origin = s.ray_origin(crate::methods::Offset::Robust, light - s.point);
                let shadow = Ray::new(origin, light - origin);
                seen += 1;
                blocked += usize::from(test(tri, &shadow).is_some_and(|h| h.t < 1.0));
            }
        }
        (seen, blocked)
    }

    fn watertight_test(tri: &Triangle, ray: &Ray) -> Option<TriangleHit> {
        tri.watertight(&ShearedRay::new(ray), 0.0, f64::INFINITY)
    }

    fn moller_trumbore_test(tri: &Triangle, ray: &Ray) -> Option<TriangleHit> {
        tri.moller_trumbore(ray, 0.0, f64::INFINITY)
    }

    /// The reviewers' shadow acne: a floor triangle whose corners lie 12 units
    /// and more from the origin blocked its own shadow rays near the origin
    /// (`t ≈ 3e-16`). The hit point there is exact in y and the offset a few
    /// ULPs of the point, but a light near and low sends the shadow rays more
    /// along x than y, and the watertight test's sheared z is then x, which
    /// differs by the triangle's whole size between its corners: its `t` is off by
    /// more than the offset. With pbrt-v4's conservative bound on `t` (§6.5.3) no
    /// shadow ray meets the triangle it leaves, near the origin or far from it.
    #[test]
    fn shadow_rays_leaving_a_large_far_triangle_never_meet_it() {
        let (mut total, mut acne) = (0, Vec::new());
        for (corner, tilt) in [
            (DVec3::new(-12.0, 0.0, -12.0), 0.0),
            (DVec3::new(-12.0, 0.0, -12.0), 0.013),
            (DVec3::new(-12.0, -0.1, -12.0), 0.25),
            (DVec3::new(88.0, 0.0, 88.0), 0.0),
        ] {
            let at = |x: f64, z: f64| corner + DVec3::new(x, tilt * (x + 2.0 * z), z);
            let tri = Triangle {
                a: at(0.0, 0.0),
                b: at(48.0, 0.0),
                c: at(0.0, 48.0),
            };
            // A light near and low beside the focus, the eye above it.
            let focus = at(12.0, 12.0);
            let eye = focus + DVec3::new(0.0, 6.0, -0.5);
            let light = focus + DVec3::new(-6.8, 5.0, -3.6);
            for from_point in [false, true] {
                let (seen, blocked) =
                    self_shadowed(&tri, (focus, eye, light), watertight_test, from_point);
                if blocked > 0 {
                    acne.push((corner, tilt, from_point, blocked));
                }
                total += seen;
            }
        }
        assert_eq!(total, 8 * 1600, "every point seen");
        assert_eq!(acne, [], "(corner, tilt, from the point, points blocked)");
    }

    /// Lesson 13's sheet has a vertex at the origin, and its center pixel's ray
    /// meets the sheet exactly there. The hit point's bound was `γ(7)·Σ|bᵢ·pᵢ|`,
    /// with the origin's weight near 1 and the others rounding errors near 0:
    /// about 1e-31, so the offset was one subnormal step, and under
    /// Möller–Trumbore the shadow ray met a neighbouring face at t ≈ 1e-18.
    /// Neither test may meet any of the six faces around the origin again,
    /// toward any light on the eye's side.
    #[test]
    fn a_hit_at_the_origin_is_offset_past_both_tests() {
        // The faces of lessons/13-numerics/sheet.obj around its vertex 265, the origin.
        let v = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        let v241 = v(
            -0.10999174470158836,
            0.10999174470158853,
            -0.021998348940317936,
        );
        let v242 = v(0.0, 0.10840196848259029, 0.021680393696517974);
        let v264 = v(-0.1108042482069638, 0.0, -0.04432169928278551);
        let v266 = v(0.1076241902109098, 0.0, 0.04304967608436394);
        let v288 = v(0.0, -0.10999174470158836, -0.021998348940317936);
        let v289 = v(
            0.10840196848259027,
            -0.10840196848259011,
            0.02168039369651842,
        );
        let o = DVec3::ZERO;
        let fan = [
            [v241, v242, o],
            [v241, o, v264],
            [v242, v266, o],
            [v264, o, v288],
            [o, v266, v289],
            [o, v289, v288],
        ]
        .map(|[a, b, c]| Triangle { a, b, c });
        let eye = DVec3::new(0.0, 0.0, 3.0);
        let n = fan[0].normal();
        let facing = if n.dot(eye) > 0.0 { n } else { -n };
        let (side, across) = (
            n.any_orthonormal_vector(),
            n.cross(n.any_orthonormal_vector()),
        );
        for test in [moller_trumbore_test, watertight_test] {
            // The nearest face, the first of equals, as a mesh keeps it.
            let primary = Ray::new(eye, -eye);
            let (tri, hit) = (fan.iter())
                .filter_map(|tri| test(tri, &primary).map(|h| (tri, h)))
                .fold(
                    None,
                    |best: Option<(&Triangle, TriangleHit)>, (tri, h)| match best {
                        Some((_, b)) if b.t <= h.t => best,
                        _ => Some((tri, h)),
                    },
                )
                .expect("the ray meets the sheet");
            // The origin: t = 1 up to a rounding or two.
            assert!((hit.t - 1.0).abs() < 1e-15, "{hit:?}");
            let s = tri.surface(&hit, None);
            for k in 0..200 {
                // Lights on a spiral over the side the eye is on.
                let angle = f64::from(k) * 2.399;
                let up = 0.05 + 0.9 * f64::from(k) / 200.0;
                let dir = up * facing
                    + (1.0 - up * up).sqrt() * (angle.cos() * side + angle.sin() * across);
                let light = 5.0 * dir;
                let origin = s.ray_origin(crate::methods::Offset::Robust, light - s.point);
                let shadow = Ray::new(origin, light - origin);
                for (f, face) in fan.iter().enumerate() {
                    let again = test(face, &shadow);
                    assert!(
                        again.is_none_or(|h| h.t >= 1.0),
                        "light {light}: face {f} met again at {again:?}, from {origin}"
                    );
                }
            }
        }
    }
}
