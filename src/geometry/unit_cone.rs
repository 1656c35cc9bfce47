//! The open cylinder and cone, as the lecture does transformed primitives: one
//! unit primitive in its own space, met by the inverse-transformed ray.
//!
//! The unit cone runs along `z` from `z = 0` to `z = 1`; its radius goes
//! linearly from 1 at `z = 0` to the ratio `s` at `z = 1`, so its surface is
//! `x² + y² = (1 + (s − 1)z)²`, with no end caps. A cylinder is the cone with
//! `s = 1`; a pointed cone has `s = 0`. [`crate::geometry::cone::cone_object`] places it between two
//! points: scale by `(r₀, r₀, length)`, turn `z` onto the axis, move to the
//! base; the wider end is always the base, so `0 ≤ s ≤ 1` and the unit cone
//! fits in the unit cylinder, whatever the two radii.
//!
//! Substituting the ray `S + t·c` gives the lecture's `A t² + 2B t + C = 0`
//! (see [`Cone::quadratic`]). Written with the "lifted" vectors
//! `U = (S_x, S_y, 1 + (s − 1)S_z)` and `V = (c_x, c_y, (s − 1)c_z)` and the
//! product `⟨p, q⟩ = p_x q_x + p_y q_y − p_z q_z`, it is `A = ⟨V, V⟩`,
//! `B = ⟨U, V⟩`, `C = ⟨U, U⟩`: the sphere's quadratic with one sign changed.
//! So the sphere's stable form carries over (Ray Tracing Gems, Haines et al.,
//! ch. 7; pbrt-v4 §6.3.2 does the same for its cylinder): `B² − AC` is
//! computed as `−A·⟨P, P⟩` with `P = U − (B/A)V`, without subtracting two
//! large squares, and the roots are `q/A` and `C/q` with
//! `q = −(B + sign(B)·√(B² − AC))`. Only roots with `0 ≤ z ≤ 1` are on the
//! open surface: the rest cross the infinite cone beyond an open end, or its
//! other nappe (past the apex, `z > 1/(1 − s) ≥ 1`).

use glam::{DAffine3, DMat3, DVec3};

use crate::geometry::hit::{Roots, Surface};
use crate::math::bounds::Bounds;
use crate::math::float::gamma;
use crate::math::ray::Ray;

/// The unit open cone `x² + y² = (1 + (s − 1)z)²`, `0 ≤ z ≤ 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// `s`, the radius at `z = 1` over the radius at `z = 0`: from 0 (a
    /// pointed cone) to 1 (a cylinder).
    pub ratio: f64,
}

/// The lecture's quadratic for a ray against the unit cone (see [`Cone::quadratic`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConeQuadratic {
    /// `S`, the ray's origin in the unit cone's space.
    pub origin: DVec3,
    /// `c`, its direction there.
    pub direction: DVec3,
    /// `A = c_x² + c_y² − (s − 1)²c_z²`.
    pub a: f64,
    /// `B = S_x c_x + S_y c_y − (1 + (s − 1)S_z)(s − 1)c_z`.
    pub b: f64,
    /// `C = S_x² + S_y² − (1 + (s − 1)S_z)²`.
    pub c: f64,
    /// `B² − AC`: below 0 no root, 0 one, above 0 two (with `A = 0`, one
    /// root `−C/(2B)`, or none when `B = 0` too).
    pub discriminant: f64,
    /// Where the ray's line crosses the infinite cone, ascending, whatever
    /// the height: [`ConeQuadratic::height`] tells which are on the open cone.
    pub crossings: Roots,
}

impl ConeQuadratic {
    /// `z = S_z + t·c_z`, the height where the ray is at `t`.
    pub fn height(&self, t: f64) -> f64 {
        self.origin.z + t * self.direction.z
    }

    /// Whether the crossing at `t` lies on the open cone, `0 ≤ z ≤ 1`.
    pub fn on_cone(&self, t: f64) -> bool {
        (0.0..=1.0).contains(&self.height(t))
    }
}

/// `p_x q_x + p_y q_y − p_z q_z`: the product under which the cone's
/// quadratic has the sphere's form.
fn lifted(p: DVec3, q: DVec3) -> f64 {
    p.x * q.x + p.y * q.y - p.z * q.z
}

impl Cone {
    /// `s − 1`, how fast the radius shrinks along `z`.
    fn slope(&self) -> f64 {
        self.ratio - 1.0
    }

    /// The radius at height `z`, `1 + (s − 1)z`.
    pub fn radius_at(&self, z: f64) -> f64 {
        1.0 + self.slope() * z
    }

    /// The quadratic `A t² + 2B t + C = 0` of the ray (in the unit cone's
    /// space) with the infinite cone, and its roots in the stable form (see
    /// the module's doc). `A = 0` when the ray runs parallel to a line of the
    /// surface (along a cylinder's axis, or along a cone's side): then the
    /// equation is linear, `2B t + C = 0`.
    #[inline]
    pub fn quadratic(&self, ray: &Ray) -> ConeQuadratic {
        let k = self.slope();
        let (s, c) = (ray.origin, ray.dir);
        let u = DVec3::new(s.x, s.y, 1.0 + k * s.z);
        let v = DVec3::new(c.x, c.y, k * c.z);
        let a = lifted(v, v);
        let b = lifted(u, v);
        let cc = lifted(u, u);
        let (discriminant, crossings) = if a == 0.0 {
            let roots = if b == 0.0 {
                // On the surface all along, or never on it: no crossing.
                Roots::NONE
            } else {
                Roots::one(-cc / (2.0 * b))
            };
            (b * b, roots)
        } else {
            let p = u - (b / a) * v;
            let disc = -a * lifted(p, p);
            let roots = if disc < 0.0 {
                Roots::NONE
            } else if disc == 0.0 {
                Roots::one(-b / a)
            } else {
                let q = -(b + b.signum() * disc.sqrt());
                Roots::two(cc / q, q / a)
            };
            (disc, roots)
        };
        ConeQuadratic {
            origin: s,
            direction: c,
            a,
            b,
            c: cc,
            discriminant,
            crossings,
        }
    }

    /// The roots on the open cone: the quadratic's crossings with `0 ≤ z ≤ 1`.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let q = self.quadratic(ray);
        match *q.crossings.as_slice() {
            [t0, t1] => match (q.on_cone(t0), q.on_cone(t1)) {
                (true, true) => q.crossings,
                (true, false) => Roots::one(t0),
                (false, true) => Roots::one(t1),
                (false, false) => Roots::NONE,
            },
            [t] if q.on_cone(t) => Roots::one(t),
            _ => Roots::NONE,
        }
    }

    /// The surface at `ray.at(t)`: the point keeps its height and is put at
    /// the radius there, `(x, y)` scaled to `1 + (s − 1)z`, so its error is a
    /// few ULPs whatever the ray's origin (pbrt-v4 §6.8.5 reprojects its
    /// cylinder's hits the same way). With `|x|, |y|, r ≤ 1`, the radius's
    /// two roundings and the five of the scaling bound it by `γ₈`. The normal
    /// is the implicit function's gradient `(x, y, −(s − 1)(1 + (s − 1)z))`,
    /// which points away from the axis; at the tip of a pointed cone, where it
    /// vanishes, the axis `+z`.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        let p = ray.at(t);
        let z = p.z.clamp(0.0, 1.0);
        let r = self.radius_at(z);
        let across = (p.x * p.x + p.y * p.y).sqrt();
        let (x, y) = if across > 0.0 {
            (p.x * (r / across), p.y * (r / across))
        } else {
            (0.0, 0.0)
        };
        let point = DVec3::new(x, y, z);
        let normal = DVec3::new(x, y, -self.slope() * r)
            .try_normalize()
            .unwrap_or(DVec3::Z);
        Surface {
            point,
            point_error: DVec3::splat(gamma(8)),
            normal,
            shading_normal: normal,
            pattern_point: point,
        }
    }

    /// `n` points evenly around each end circle, the `z = 0` circle's first:
    /// what a drawing joins into the cone's outline and cut.
    pub fn rims(&self, n: usize) -> Vec<DVec3> {
        [0.0, 1.0]
            .into_iter()
            .flat_map(|z| {
                let r = self.radius_at(z);
                (0..n).map(move |k| {
                    let phi = std::f64::consts::TAU * k as f64 / n as f64;
                    DVec3::new(r * phi.cos(), r * phi.sin(), z)
                })
            })
            .collect()
    }

    /// The box around the cone placed by `m`: around its two end discs, each
    /// exactly. The unit circle at height `z` goes to
    /// `m(0, 0, z) + r(M₀ cos φ + M₁ sin φ)` (`M₀`, `M₁` the first two columns
    /// of `m`'s linear part), whose extent on axis `i` is
    /// `r·√(M₀ᵢ² + M₁ᵢ²)`; for a disc of radius `r` with unit normal `a` this
    /// is the `r·√(1 − aᵢ²)` of a round disc.
    pub fn bounds_under(&self, m: &DAffine3) -> Bounds {
        let l: DMat3 = m.matrix3;
        let squares = l.x_axis * l.x_axis + l.y_axis * l.y_axis;
        let spread = DVec3::new(squares.x.sqrt(), squares.y.sqrt(), squares.z.sqrt());
        let disc = |z: f64| {
            let center = m.transform_point3(DVec3::new(0.0, 0.0, z));
            let half = spread * self.radius_at(z);
            Bounds {
                min: center - half,
                max: center + half,
            }
        };
        disc(0.0).union(disc(1.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CYLINDER: Cone = Cone { ratio: 1.0 };
    const POINTED: Cone = Cone { ratio: 0.0 };

    fn ray(origin: [f64; 3], dir: [f64; 3]) -> Ray {
        Ray::new(DVec3::from_array(origin), DVec3::from_array(dir))
    }

    #[test]
    fn a_cylinder_seen_from_the_side_is_met_where_x_squared_is_one() {
        // From (−5, 0, 0.5) along +x: A = 1, B = −5, C = 25 − 1 = 24,
        // B² − AC = 1, q = −(−5 − 1) = 6, t = C/q = 4 and q/A = 6: x = ∓1.
        let q = CYLINDER.quadratic(&ray([-5.0, 0.0, 0.5], [1.0, 0.0, 0.0]));
        assert_eq!((q.a, q.b, q.c, q.discriminant), (1.0, -5.0, 24.0, 1.0));
        assert_eq!(q.crossings.as_slice(), &[4.0, 6.0]);
        let r = ray([-5.0, 0.0, 0.5], [1.0, 0.0, 0.0]);
        assert_eq!(CYLINDER.roots(&r).as_slice(), &[4.0, 6.0]);
        let s = CYLINDER.surface(&r, 4.0);
        assert_eq!(s.point, DVec3::new(-1.0, 0.0, 0.5));
        assert_eq!(s.normal, DVec3::NEG_X);
        // Tilted up by 0.1 per unit: the far crossing is at z = 0.5 + 0.6 = 1.1,
        // past the open end, so only t = 4 (z = 0.9) is a root.
        let tilted = ray([-5.0, 0.0, 0.5], [1.0, 0.0, 0.1]);
        let q = CYLINDER.quadratic(&tilted);
        assert_eq!(q.crossings.as_slice(), &[4.0, 6.0]);
        // Tolerance: z = 0.5 + t·0.1 rounds once or twice (a few ULPs of 1).
        assert!((q.height(6.0) - 1.1).abs() < 1e-15 && !q.on_cone(6.0));
        assert_eq!(CYLINDER.roots(&tilted).as_slice(), &[4.0]);
    }

    #[test]
    fn a_cone_is_met_on_its_surface_line() {
        // The pointed cone (radius 1 − z) at z = 0.5 has radius 0.5: from
        // (−5, 0, 0.5) along +x, x = ∓0.5 at t = 4.5, 5.5. A = 1, B = −5,
        // C = 25 − 0.5² = 24.75, B² − AC = 0.25.
        let r = ray([-5.0, 0.0, 0.5], [1.0, 0.0, 0.0]);
        let q = POINTED.quadratic(&r);
        assert_eq!((q.a, q.b, q.c, q.discriminant), (1.0, -5.0, 24.75, 0.25));
        assert_eq!(POINTED.roots(&r).as_slice(), &[4.5, 5.5]);
        // The normal is the gradient (x, y, −(s − 1)(1 + (s − 1)z)) =
        // (−0.5, 0, 0.5): outward, tilted up as the side leans in.
        let s = POINTED.surface(&r, 4.5);
        assert_eq!(s.point, DVec3::new(-0.5, 0.0, 0.5));
        // Tolerance: one normalization, a few ULPs.
        assert!((s.normal - DVec3::new(-1.0, 0.0, 1.0).normalize()).length() < 1e-15);
    }

    #[test]
    fn a_ray_along_the_axis_misses_an_open_cylinder() {
        // Along z, c_x = c_y = 0 and s − 1 = 0: A = B = 0, the equation C = 0
        // holds for no t. From outside and from inside alike.
        for origin in [[0.0, 0.0, -5.0], [0.0, 0.0, 0.5], [0.3, -0.2, 0.5]] {
            let q = CYLINDER.quadratic(&ray(origin, [0.0, 0.0, 1.0]));
            assert_eq!((q.a, q.b), (0.0, 0.0));
            assert!(
                CYLINDER
                    .roots(&ray(origin, [0.0, 0.0, 1.0]))
                    .as_slice()
                    .is_empty()
            );
        }
        // A pointed cone along its axis meets its tip: one root, the double
        // root at z = 1, and the normal there is the axis.
        let r = ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]);
        assert_eq!(POINTED.roots(&r).as_slice(), &[6.0]);
        assert_eq!(POINTED.surface(&r, 6.0).normal, DVec3::Z);
    }

    #[test]
    fn a_ray_through_the_open_end_hits_the_inside() {
        // From (−0.5, 0, −1) along (1, 0, 1): through z = 0 at x = 0.5, inside
        // the opening; x = 1 at t = 1.5, z = 0.5. The other crossing, x = −1 at
        // t = −0.5, is at z = −1.5: below the open end. A = 1, B = −0.5,
        // C = −0.75, B² − AC = 1, q = 1.5: t = −0.75/1.5 = −0.5 and 1.5.
        let r = ray([-0.5, 0.0, -1.0], [1.0, 0.0, 1.0]);
        let q = CYLINDER.quadratic(&r);
        assert_eq!(q.crossings.as_slice(), &[-0.5, 1.5]);
        assert_eq!(CYLINDER.roots(&r).as_slice(), &[1.5]);
        // Met from inside: the outward normal faces along the ray (n·c > 0),
        // so the tracer shades the inner side, as for a triangle's back.
        let s = CYLINDER.surface(&r, 1.5);
        assert_eq!(s.normal, DVec3::X);
        assert!(s.normal.dot(r.dir) > 0.0);
    }

    #[test]
    fn rays_parallel_to_a_line_of_the_surface_have_one_root_or_none() {
        // On the cylinder's surface all along: A = B = C = 0, no root, no NaN.
        let on = ray([1.0, 0.0, -1.0], [0.0, 0.0, 1.0]);
        let q = CYLINDER.quadratic(&on);
        assert_eq!((q.a, q.b, q.c), (0.0, 0.0, 0.0));
        assert!(CYLINDER.roots(&on).as_slice().is_empty());
        // Along the pointed cone's side, the line from (1, 0, 0) to (0, 0, 1):
        // U = (2, 0, 2), V = (−1, 0, −1), A = 1 − 1 = 0, B = −2 + 2 = 0.
        let side = ray([2.0, 0.0, -1.0], [-1.0, 0.0, 1.0]);
        assert_eq!(POINTED.quadratic(&side).a, 0.0);
        assert!(POINTED.roots(&side).as_slice().is_empty());
        // The same direction half a unit further in: U = (1.5, 0, 2),
        // B = −1.5 + 2 = 0.5, C = 2.25 − 4 = −1.75, one root t = −C/(2B) = 1.75
        // at (−0.25, 0, 0.75), where the radius is 1 − 0.75 = 0.25.
        let inner = ray([1.5, 0.0, -1.0], [-1.0, 0.0, 1.0]);
        let q = POINTED.quadratic(&inner);
        assert_eq!((q.a, q.b, q.c), (0.0, 0.5, -1.75));
        assert_eq!(POINTED.roots(&inner).as_slice(), &[1.75]);
        // Half a unit further out it crosses the other nappe, past the tip
        // (z = 1.25): not on the cone.
        let outer = ray([2.5, 0.0, -1.0], [-1.0, 0.0, 1.0]);
        assert_eq!(POINTED.quadratic(&outer).crossings.as_slice(), &[2.25]);
        assert!(POINTED.roots(&outer).as_slice().is_empty());
    }

    #[test]
    fn a_grazing_ray_touches_once_and_a_cone_behind_the_origin_is_not_ahead() {
        // The line x = 1 touches the cylinder along y: P = (1, 0, 1),
        // ⟨P, P⟩ = 0, one root t = −B/A = 5.
        let r = ray([1.0, -5.0, 0.5], [0.0, 1.0, 0.0]);
        assert_eq!(CYLINDER.quadratic(&r).discriminant, 0.0);
        assert_eq!(CYLINDER.roots(&r).as_slice(), &[5.0]);
        // Just outside: no root.
        let past = ray([1.0 + 1e-12, -5.0, 0.5], [0.0, 1.0, 0.0]);
        assert!(CYLINDER.roots(&past).as_slice().is_empty());
        // Behind: both roots negative, nothing ahead.
        let behind = ray([5.0, 0.0, 0.5], [1.0, 0.0, 0.0]);
        assert_eq!(CYLINDER.roots(&behind).as_slice(), &[-6.0, -4.0]);
        assert_eq!(CYLINDER.roots(&behind).first_in(0.0, f64::INFINITY), None);
    }

    #[test]
    fn the_stable_form_holds_far_away() {
        // From 1e9 away the hit is at t = 1e9 − 1 (x = −1). B² and AC are 1e18
        // and differ by 1: the lecture's subtraction would lose it all.
        let r = ray([-1e9, 0.0, 0.5], [1.0, 0.0, 0.0]);
        let t = CYLINDER.roots(&r).first_in(0.0, f64::INFINITY).unwrap();
        // Tolerance: one ULP of 1e9 is 1.2e-7.
        assert!((t - (1e9 - 1.0)).abs() < 1e-6, "{t}");
        let q = CYLINDER.quadratic(&r);
        assert_eq!(q.discriminant, 1.0);
        assert!(
            q.b * q.b - q.a * q.c != 1.0,
            "the lecture's form would be right"
        );
    }

    #[test]
    fn hit_points_lie_on_the_surface_within_their_error_bound() {
        let cone = Cone { ratio: 0.3 };
        let mut hits = 0;
        for k in 0..200 {
            let a = k as f64 * 0.731;
            let origin = DVec3::new(4.0 * a.cos(), 4.0 * a.sin(), 2.0 * (a * 1.3).sin());
            let target = DVec3::new(0.1 * a.sin(), 0.0, (k % 10) as f64 / 10.0 + 0.05);
            let r = Ray::new(origin, target - origin);
            let Some(t) = cone.roots(&r).first_in(0.0, f64::INFINITY) else {
                continue;
            };
            hits += 1;
            let s = cone.surface(&r, t);
            let off = (s.point.x.hypot(s.point.y) - cone.radius_at(s.point.z)).abs();
            assert!(off <= s.point_error.x, "{k}: {off:e}");
            assert!((0.0..=1.0).contains(&s.point.z));
            // Outward: away from the axis.
            assert!(s.normal.truncate().dot(s.point.truncate()) > 0.0);
        }
        assert!(hits > 150, "{hits} of 200 rays aimed at the axis hit");
    }

    #[test]
    fn bounds_hold_every_point_of_the_surface_and_touch_it() {
        let cone = Cone { ratio: 0.4 };
        let m = DAffine3::from_cols_array(&[
            0.3, -1.2, 0.5, 2.0, 0.7, -0.1, -0.4, 0.2, 1.5, 3.0, -1.0, 0.25,
        ]);
        let b = cone.bounds_under(&m);
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for i in 0..=40 {
            let z = i as f64 / 40.0;
            for j in 0..720 {
                let phi = std::f64::consts::TAU * j as f64 / 720.0;
                let r = cone.radius_at(z);
                let p = m.transform_point3(DVec3::new(r * phi.cos(), r * phi.sin(), z));
                // Tolerance: a few ULPs of coordinates of order 4.
                assert!(
                    (p.cmpge(b.min - 1e-14) & p.cmple(b.max + 1e-14)).all(),
                    "{p} outside {b:?}"
                );
                (lo, hi) = (lo.min(p), hi.max(p));
            }
        }
        // Exact: every face is touched. Sampling 720 points round a circle of
        // radius below 4 misses its extreme by at most 4(1 − cos(π/720)) < 4e-5.
        assert!((lo - b.min).abs().max_element() < 4e-5, "{lo} {:?}", b.min);
        assert!((hi - b.max).abs().max_element() < 4e-5, "{hi} {:?}", b.max);
    }
}
