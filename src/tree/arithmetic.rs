//! The lecture's own arithmetic for each recorded step, worked out while
//! recording (never while rendering) with the same functions the tracer uses:
//! the camera stage `(x, y) → (c, r) → (u_c, v_r) → P(r, c)`, the ray–sphere
//! quadratic `A t² + 2B t + C = 0` in the unit sphere's frame, the
//! inverse-transformed ray `S' + t·c'`, what became of each root, `n·c` and the
//! mirror direction, and Snell's angles.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::scene::camera::{Camera, CameraSpec};
use crate::shading::optics::{reflect, refract};

/// The camera as the lecture names it: eye, u, v, n, W, H, N, N_c × N_r.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraRecord {
    /// The eye.
    pub eye: DVec3,
    /// `u`: right.
    pub u: DVec3,
    /// `v`: up.
    pub v: DVec3,
    /// `n`: backward (the camera looks along `-n`).
    pub n: DVec3,
    /// `W`: half the image plane's width.
    pub half_width: f64,
    /// `H`: half its height.
    pub half_height: f64,
    /// `N`: the image plane is at `n = -N`.
    pub distance: f64,
    /// `N_c`: pixels across.
    pub columns: u32,
    /// `N_r`: pixels down.
    pub rows: u32,
    /// The look-at form the frame was made from, if the scene gave one.
    pub look_at: Option<LookAtRecord>,
}

/// A camera given by eye, look-at point, up and field of view.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LookAtRecord {
    /// The point seen at the image's center.
    pub look_at: DVec3,
    /// Which way is up.
    pub up: DVec3,
    /// The horizontal field of view between the outermost pixel centers, degrees.
    pub fov_degrees: f64,
}

/// How one sample's primary ray was made, in the lecture's terms.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraStage {
    /// The pixel, in image coordinates (`x` right, `y` down from the top-left).
    pub pixel: [u32; 2],
    /// Where the sample lies, continuous image coordinates (pixel centers are whole).
    pub x: f64,
    /// See `x`.
    pub y: f64,
    /// The sample's offset from the pixel's center.
    pub offset: [f64; 2],
    /// The lecture's column: `c = x`.
    pub c: f64,
    /// The lecture's row, counted up from the bottom: `r = N_r - 1 - y`.
    pub r: f64,
    /// `u_c = -W + W·2c/(N_c - 1)`.
    pub u_c: f64,
    /// `v_r = -H + H·2r/(N_r - 1)`.
    pub v_r: f64,
    /// `P(r, c) = eye - N·n + u_c·u + v_r·v`, on the image plane; the primary ray
    /// is `eye + t·(P(r, c) - eye)`, so `t = 1` there.
    pub point: DVec3,
}

/// What `t` counts along a ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TUnit {
    /// A primary ray through a pixel, direction `P(r, c) - eye`: `t = 1` is on
    /// the image plane.
    ImagePlane,
    /// A ray given by hand: `t` counts lengths of its direction.
    Direction,
    /// A reflected or refracted ray, whose direction is a unit vector: `t` is
    /// the distance travelled.
    Distance,
}

/// How an object was tested.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TestMethod {
    /// The lecture's quadratic as written.
    LectureQuadratic,
    /// The numerically stable quadratic (Ray Tracing Gems ch. 7).
    StableQuadratic,
    /// `t = (P₀ - S)·n / (c·n)`.
    PlaneEquation,
    /// The slab test.
    Slabs,
    /// Woop, Benthin & Wald's watertight test.
    Watertight,
    /// The textbook Möller–Trumbore test.
    MollerTrumbore,
    /// A polygon: its plane, then Haines's crossing-number test in the
    /// watertight sheared frame.
    CrossingNumber,
}

/// An object test's own numbers.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Arithmetic {
    /// The lecture's `A t² + 2B t + C = 0` for the unit sphere at the origin:
    /// the ray moved into the sphere's frame and scaled by its radius,
    /// `S = (S' - center)/r`, `c = c'/r`.
    Quadratic {
        /// `S` in the unit sphere's frame.
        origin: DVec3,
        /// `c` in the unit sphere's frame.
        direction: DVec3,
        /// `A = |c|²`.
        a: f64,
        /// `B = S·c`.
        b: f64,
        /// `C = |S|² - 1`.
        c: f64,
        /// `B² - AC`: below 0 no root, 0 one, above 0 two.
        discriminant: f64,
    },
    /// The plane `(P - P₀)·n = 0`: `t = numerator / n_dot_c`.
    Plane {
        /// `c·n`: 0 for a ray parallel to the plane.
        n_dot_c: f64,
        /// `(P₀ - S)·n`.
        numerator: f64,
    },
    /// The slab test: on each axis, where the ray is between the box's two planes.
    Slabs {
        /// `x`, `y`, `z`, in the box's own frame.
        axes: [Slab; 3],
    },
    /// A triangle's barycentric weights of its vertices a, b, c at the root.
    Barycentric {
        /// They sum to 1.
        weights: [f64; 3],
    },
    /// A mesh's nearest face and the barycentric weights there.
    Face {
        /// Index of the face.
        face: u32,
        /// Weights of its three vertices.
        weights: [f64; 3],
    },
    /// A polygon: its plane gives `t = numerator / n_dot_c`, and the crossing
    /// number says whether the ray passes inside its outline.
    Polygon {
        /// `n·c`, `n` the front's normal: 0 for a ray parallel to the plane; at
        /// or above 0, a one-sided polygon is met from the back.
        n_dot_c: f64,
        /// `(V₀ - S)·n`.
        numerator: f64,
        /// Whether a ray meeting the back misses.
        one_sided: bool,
        /// Edges of the outline the half-line from the ray's point crosses, in
        /// the sheared frame: odd inside, even outside.
        crossings: u32,
        /// The ray passes exactly through an edge or a vertex: inside.
        on_edge: bool,
    },
    /// The lecture's `A t² + 2B t + C = 0` for the unit open cone
    /// `x² + y² = (1 + (s − 1)z)²`, `0 ≤ z ≤ 1`, met by the inverse-transformed
    /// ray `S + t·c` (a cylinder when `s = 1`).
    ConeQuadratic {
        /// `S` in the unit cone's space.
        origin: DVec3,
        /// `c` in the unit cone's space.
        direction: DVec3,
        /// `s`, the radius at `z = 1` over the radius at `z = 0`.
        ratio: f64,
        /// `A = c_x² + c_y² − (s − 1)²c_z²`.
        a: f64,
        /// `B = S_x c_x + S_y c_y − (1 + (s − 1)S_z)(s − 1)c_z`.
        b: f64,
        /// `C = S_x² + S_y² − (1 + (s − 1)S_z)²`.
        c: f64,
        /// `B² − AC`.
        discriminant: f64,
        /// Every root of the quadratic and the height `z` there; only those
        /// with `0 ≤ z ≤ 1` are on the open cone and become the test's roots.
        crossings: Vec<Crossing>,
    },
}

/// Where a ray's line crosses the infinite cone.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Crossing {
    /// The ray parameter.
    pub t: f64,
    /// The height in the unit cone's space, `S_z + t·c_z`.
    pub z: f64,
}

/// One axis of the slab test.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Slab {
    /// The ray crosses the two planes: it is between them for `t` in `[near, far]`.
    Crossing {
        /// Where it enters the slab.
        near: f64,
        /// Where it leaves.
        far: f64,
    },
    /// The ray runs parallel to the two planes, between them all along or never.
    Parallel {
        /// Between them.
        inside: bool,
    },
}

/// One root of an object test and what became of it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RootRecord {
    /// The ray parameter.
    pub t: f64,
    /// Kept, or why not.
    pub fate: Fate,
    /// The root lies on the surface the ray starts from, within its offset: the
    /// "first intersection?" a ray must not take (taken, it is shadow acne).
    pub at_start: bool,
}

/// What the tracer did with a root.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Fate {
    /// The closest root ahead of the origin: the hit.
    Chosen,
    /// Ahead of the origin, but not the closest.
    Farther,
    /// At or behind the origin (`t ≤ t_min`): ignored.
    Behind,
    /// Past the end of a bounded ray (`t ≥ t_max`): ignored.
    Beyond,
}

/// A ray as origin and direction.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RayRecord {
    /// `S`.
    pub origin: DVec3,
    /// `c`.
    pub direction: DVec3,
}

/// Snell's law at a transparent surface, `n₁ sin θ₁ = n₂ sin θ₂`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RefractionRecord {
    /// `η = n₁/n₂`.
    pub eta: f64,
    /// `cos θ₁ = -n·c`.
    pub cos_theta1: f64,
    /// θ₁ in degrees: between the incoming ray (reversed) and the normal,
    /// `atan2(|n × c|, -n·c)` ([`crate::math::angle::angle_between`]), right at every angle.
    pub theta1: f64,
    /// `sin θ₁`, of that angle (`√(1 - cos² θ₁)` is 0 below about 1.5e-8 rad).
    pub sin_theta1: f64,
    /// `sin θ₂ = η·sin θ₁`; above 1 there is no refracted ray.
    pub sin_theta2: f64,
    /// `cos θ₂ = √(1 - η²(1 - cos² θ₁))`, as the refracted direction uses it;
    /// `None` under total internal reflection.
    pub cos_theta2: Option<f64>,
    /// θ₂ in degrees; `None` under total internal reflection.
    pub theta2: Option<f64>,
    /// The critical angle `asin(n₂/n₁)` in degrees, when `n₁ > n₂`.
    pub critical: Option<f64>,
    /// `t = η·c + (η cos θ₁ - cos θ₂)·n`; `None` under total internal reflection.
    pub direction: Option<DVec3>,
}

/// The camera of a trace, as the lecture names it.
pub fn camera_record(camera: &Camera, spec: &CameraSpec) -> CameraRecord {
    let look_at = match *spec {
        CameraSpec::LookAt {
            look_at,
            up,
            fov_degrees,
            ..
        } => Some(LookAtRecord {
            look_at,
            up,
            fov_degrees,
        }),
        CameraSpec::Frame { .. } => None,
    };
    CameraRecord {
        eye: camera.eye,
        u: camera.u,
        v: camera.v,
        n: camera.n,
        half_width: camera.half_width,
        half_height: camera.half_height,
        distance: camera.distance,
        columns: camera.columns,
        rows: camera.rows,
        look_at,
    }
}

/// The camera stage of the sample at image point `(x, y)` of `pixel`, computed
/// as [`Camera::pixel_ray`] does, so `point - eye` is the primary ray's
/// direction bit for bit.
pub fn camera_stage(camera: &Camera, pixel: (u32, u32), (x, y): (f64, f64)) -> CameraStage {
    let (c, r) = (x, f64::from(camera.rows) - 1.0 - y);
    let (u_c, v_r) = camera.plane_coords(c, r);
    CameraStage {
        pixel: [pixel.0, pixel.1],
        x,
        y,
        offset: [x - f64::from(pixel.0), y - f64::from(pixel.1)],
        c,
        r,
        u_c,
        v_r,
        point: camera.plane_point(c, r),
    }
}

/// What became of each root of a ray's tests: the hit's root is chosen, those
/// at or behind the origin and past a bounded ray's end are ignored, the rest
/// are farther. `start` is the object the ray leaves (none for a primary ray);
/// its root nearest 0 within `tolerance` (a distance) is the starting surface.
pub fn fates(
    roots: &[f64],
    object: usize,
    hit: Option<(usize, f64)>,
    (t_min, t_max): (f64, Option<f64>),
    start: Option<usize>,
    (dir_length, tolerance): (f64, f64),
) -> Vec<RootRecord> {
    let nearest_zero = roots
        .iter()
        .copied()
        .min_by(|a, b| a.abs().total_cmp(&b.abs()));
    roots
        .iter()
        .map(|&t| {
            let fate = if hit == Some((object, t)) {
                Fate::Chosen
            } else if t <= t_min {
                Fate::Behind
            } else if t_max.is_some_and(|m| t >= m) {
                Fate::Beyond
            } else {
                Fate::Farther
            };
            let at_start = start == Some(object)
                && nearest_zero == Some(t)
                && t.abs() * dir_length <= tolerance;
            RootRecord { t, fate, at_start }
        })
        .collect()
}

/// At a hit with unit normal `n` facing the incoming direction `dir`: the unit
/// incoming `c`, `n·c`, the mirror direction `v = c - 2(n·c)n`, and for a
/// transparent surface Snell's law from index `n1` into `n2`.
pub fn hit_optics(
    dir: DVec3,
    n: DVec3,
    (n1, n2): (f64, f64),
    transparent: bool,
) -> (DVec3, f64, DVec3, Option<RefractionRecord>) {
    let c = dir.normalize();
    let n_dot_c = n.dot(c);
    let refraction = transparent.then(|| {
        let eta = n1 / n2;
        let cos_theta1 = -n_dot_c;
        let theta1 = crate::math::angle::angle_between(-c, n);
        let sin_theta1 = theta1.sin();
        let sin_theta2 = eta * sin_theta1;
        let direction = refract(c, n, eta);
        let sin2_t = eta * eta * (1.0 - cos_theta1 * cos_theta1).max(0.0);
        RefractionRecord {
            eta,
            cos_theta1,
            theta1: theta1.to_degrees(),
            sin_theta1,
            sin_theta2,
            cos_theta2: direction.map(|_| (1.0 - sin2_t).sqrt()),
            theta2: direction.map(|_| sin_theta2.min(1.0).asin().to_degrees()),
            critical: (n1 > n2).then(|| (n2 / n1).asin().to_degrees()),
            direction,
        }
    });
    (c, n_dot_c, reflect(c, n), refraction)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::sphere::Sphere;
    use crate::math::ray::Ray;
    use crate::tree::shape_arithmetic::quadratic;

    #[test]
    fn quadratic_of_a_ray_through_the_center() {
        // From (0, 0, -5) along +z at a sphere of radius 2 at the origin: in the
        // unit frame S = (0, 0, -2.5), c = (0, 0, 0.5), A = 0.25, B = -1.25,
        // C = 5.25, B² - AC = 1.5625 - 1.3125 = 0.25; t = (1.25 ± 0.5)/0.25 = 3, 7.
        let s = Sphere {
            center: DVec3::ZERO,
            radius: 2.0,
        };
        let q = quadratic(&s, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z));
        assert_eq!(
            q,
            Arithmetic::Quadratic {
                origin: DVec3::new(0.0, 0.0, -2.5),
                direction: DVec3::new(0.0, 0.0, 0.5),
                a: 0.25,
                b: -1.25,
                c: 5.25,
                discriminant: 0.25,
            }
        );
    }

    #[test]
    fn fates_follow_the_tracers_choice() {
        // Roots -1e-16 (the surface left), 2 (chosen), 5 (farther) of object 3.
        let f = fates(
            &[-1e-16, 2.0, 5.0],
            3,
            Some((3, 2.0)),
            (0.0, None),
            Some(3),
            (1.0, 1e-9),
        );
        let got: Vec<(Fate, bool)> = f.iter().map(|r| (r.fate, r.at_start)).collect();
        assert_eq!(
            got,
            [
                (Fate::Behind, true),
                (Fate::Chosen, false),
                (Fate::Farther, false)
            ]
        );
        // A shadow-like bounded ray: past t_max is beyond.
        let f = fates(&[1.5], 0, None, (0.0, Some(1.0)), None, (1.0, 1e-9));
        assert_eq!(f[0].fate, Fate::Beyond);
    }

    #[test]
    fn snell_angles_at_30_degrees_into_glass() {
        // 30° from air into glass: sin θ₂ = sin 30°/1.5 = 1/3, θ₂ = 19.47°.
        let a = 30f64.to_radians();
        let (c, n_dot_c, v, r) = hit_optics(
            DVec3::new(a.sin(), -a.cos(), 0.0),
            DVec3::Y,
            (1.0, 1.5),
            true,
        );
        let r = r.unwrap();
        // Tolerances: a few ULPs of the trigonometry (1e-12 degrees, 1e-15 in sines).
        assert!((r.theta1 - 30.0).abs() < 1e-12 && (r.sin_theta2 - 1.0 / 3.0).abs() < 1e-15);
        assert!((r.theta2.unwrap() - (1f64 / 3.0).asin().to_degrees()).abs() < 1e-12);
        assert_eq!(r.critical, None);
        assert!((n_dot_c + a.cos()).abs() < 1e-15);
        assert_eq!(v, DVec3::new(c.x, -c.y, 0.0));
    }
}
