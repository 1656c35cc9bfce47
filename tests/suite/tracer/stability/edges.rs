//! Where a single object's numbers are at their edge: a far sphere near its
//! silhouette, tangent and grazing rays, the critical angle, nested media, an
//! ellipsoid stretched 1e4 to 1, facing mirrors, and no NaN reaching an image.

use crate::common;

use crate::common::scene;
use glam::{DQuat, DVec3};
use raytree::methods::Offset;
use raytree::trace::tracer::Tracer;

/// For rays from (0, 0, -D) aimed at (x, 0, 0), the line passes the center at
/// distance D·|x|/√(x² + D²), so it meets the unit sphere iff |x| < D/√(D² - 1).
/// Aiming at that silhouette times (1 + u), u in ±1% (never 0), the right answer is
/// "hit" iff u < 0, with a margin far above f64's rounding.
fn far_sphere(d: f64, lecture: bool) -> (usize, usize, f64) {
    use raytree::geometry::sphere::Sphere;
    use raytree::math::ray::Ray;
    let sphere = Sphere {
        center: DVec3::ZERO,
        radius: 1.0,
    };
    let silhouette = d / (d * d - 1.0).sqrt();
    let n = 2000;
    let (mut wrong, mut hits, mut worst) = (0, 0, 0.0f64);
    for k in 0..n {
        let u = -0.01 + 0.02 * (f64::from(k) + 0.5) / f64::from(n);
        let ray = Ray::new(
            DVec3::new(0.0, 0.0, -d),
            DVec3::new(silhouette * (1.0 + u), 0.0, d),
        );
        let roots = if lecture {
            sphere.lecture_roots(&ray)
        } else {
            sphere.roots(&ray)
        };
        let t = roots.first_in(0.0, f64::INFINITY);
        wrong += usize::from(t.is_some() != (u < 0.0));
        if let Some(t) = t {
            hits += 1;
            worst = worst.max((ray.at(t).length() - 1.0).abs());
        }
    }
    (wrong, hits, worst)
}

#[test]
fn far_sphere_near_its_silhouette() {
    let mut lecture_failed = false;
    for e in 2..=7 {
        let d = 10f64.powi(e);
        let (sw, sh, sd) = far_sphere(d, false);
        let (lw, lh, ld) = far_sphere(d, true);
        println!(
            "D = 1e{e}: stable (default): {sw:>4} of 2000 wrong, {sh:>4} hits, worst |p| - 1 = {sd:.1e}   lecture: {lw:>4} wrong, {lh:>4} hits, worst |p| - 1 = {ld:.1e}"
        );
        // The default: never wrong, hit points on the surface to a few ULPs of D.
        assert_eq!(sw, 0, "D = 1e{e}");
        assert!(sd < 1e-14 * d, "D = 1e{e}: worst {sd}");
        lecture_failed |= lw > 0 || ld > 1e-3;
    }
    assert!(
        lecture_failed,
        "the lecture's quadratic should fail for a far sphere"
    );
}

// ---------------------------------------------------------------------------
// Tangent and grazing rays.

#[test]
fn tangent_and_grazing_rays_give_no_nan_and_no_far_side_hit() {
    use raytree::geometry::object::{Object, Shape};
    use raytree::geometry::plane::Plane;
    use raytree::geometry::sphere::Sphere;
    use raytree::math::ray::Ray;
    // Rays along +z passing the unit sphere at x = 1 + δ: tangent at (1, 0, 0).
    for method in [
        raytree::methods::SphereMethod::Stable,
        raytree::methods::SphereMethod::Lecture,
    ] {
        let ball = Object {
            name: "ball".into(),
            shape: Shape::Sphere(Sphere {
                center: DVec3::ZERO,
                radius: 1.0,
            }),
            transform: None,
            material: 0,
        };
        let mut hits = 0;
        for delta in [-1e-6, -1e-9, -1e-12, -1e-15, 0.0, 1e-15, 1e-12, 1e-9] {
            let ray = Ray::new(DVec3::new(1.0 + delta, 0.0, -5.0), DVec3::Z);
            let roots = ball.roots(&ray, method);
            assert!(
                roots.as_slice().iter().all(|t| t.is_finite()),
                "{method:?} δ {delta}: {roots:?}"
            );
            if let Some(t) = roots.first_in(0.0, f64::INFINITY) {
                hits += 1;
                // The chord of a near-tangent ray is short: every hit is near z = 0, none on the far side.
                assert!(
                    (ray.at(t).z).abs() < 2e-3,
                    "{method:?} δ {delta}: hit at {}",
                    ray.at(t)
                );
                let n = ball.surface(&ray, t, 0, method.into()).normal;
                assert!(
                    n.is_finite() && n.dot(DVec3::Z).abs() < 2e-3,
                    "{method:?} δ {delta}: normal {n}"
                );
            }
        }
        println!(
            "{method:?}: {hits} of 8 near-tangent rays hit, all within 2e-3 of the tangent point"
        );
    }
    // Rays grazing the floor y = 0 from height 1 with slope s: hit at x = 1/s, exactly on the plane.
    let floor = Plane {
        point: DVec3::ZERO,
        normal: DVec3::Y,
    };
    for s in [1e-3, 1e-6, 1e-9, 1e-12, 1e-15] {
        let ray = Ray::new(DVec3::Y, DVec3::new(1.0, -s, 0.0));
        let t = floor.roots(&ray).first_in(0.0, f64::INFINITY).unwrap();
        let p = floor.surface(&ray, t).point;
        // Tolerance: t ≈ 1/s is computed from two products, a few ULPs of it.
        assert!(
            p.y == 0.0 && ((p.x - 1.0 / s) * s).abs() < 1e-14,
            "slope {s}: {p}"
        );
    }
    // Parallel to it, in it, or leaving it: no hit and no NaN.
    for ray in [
        Ray::new(DVec3::Y, DVec3::X),
        Ray::new(DVec3::ZERO, DVec3::X),
        Ray::new(DVec3::ZERO, DVec3::new(1.0, 1e-300, 0.0)),
    ] {
        let roots = floor.roots(&ray);
        assert!(roots.as_slice().iter().all(|t| !t.is_nan()), "{ray:?}");
        assert_eq!(
            roots.first_in(0.0, f64::INFINITY).filter(|t| t.is_finite()),
            None,
            "{ray:?}"
        );
    }
    println!("grazing rays at slopes 1e-3 … 1e-15 meet the floor exactly on it, at x = 1/slope");
}

// ---------------------------------------------------------------------------
// Total internal reflection at and around the critical angle.

#[test]
fn reflected_and_transmitted_shares_sum_to_one_around_the_critical_angle() {
    use raytree::math::ray::Ray;
    use raytree::methods::Weights;
    // From inside a unit glass ball (n = 1.5), a ray along +x at height ρ meets the
    // wall at incidence asin ρ; the critical angle is asin(1/1.5).
    let critical = 1.0 / 1.5;
    for weights in [Weights::Constant, Weights::Schlick, Weights::Fresnel] {
        let mut s = scene(
            r#"{ "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1]},
            "materials": {"glass": {"ambient": 0, "diffuse": 0, "reflective": 0, "transparent": 1, "ior": 1.5}},
            "objects": [{"sphere": {}, "material": "glass"}] }"#,
        );
        s.settings.weights = weights;
        s.settings.max_depth = 2;
        let tracer = Tracer::new(&s);
        let mut figures = Vec::new();
        for offset in [-1e-3, -1e-6, -1e-9, -1e-12, 0.0, 1e-12, 1e-9, 1e-6, 1e-3] {
            let rho: f64 = critical + offset;
            let mut log = common::Log::default();
            let color =
                tracer.trace_primary(Ray::new(DVec3::new(0.0, rho, 0.0), DVec3::X), &mut log);
            let sum = log.colors.last().unwrap();
            assert!(
                color.is_finite() && sum.k_rfl.is_finite() && sum.k_rfa.is_finite(),
                "{weights:?} ρ {rho}"
            );
            // Tolerance: one rounding in k_rfa·R and one in k_rfa·(1 - R).
            assert!(
                (sum.k_rfl + sum.k_rfa - 1.0).abs() < 1e-15,
                "{weights:?} ρ {rho}: {} + {}",
                sum.k_rfl,
                sum.k_rfa
            );
            if offset > 1e-9 {
                assert_eq!(
                    sum.k_rfa, 0.0,
                    "{weights:?} ρ {rho}: beyond the critical angle, all is reflected"
                );
            }
            figures.push(format!("{:.3}", sum.k_rfl));
        }
        println!(
            "{weights:?}: reflected share from 1e-3 below to 1e-3 above the critical angle: {}",
            figures.join(" ")
        );
    }
}

// ---------------------------------------------------------------------------
// Nested dielectrics: n1 → n2 on every boundary.

#[test]
fn nested_media_give_the_right_indices_on_every_boundary() {
    use raytree::math::ray::Ray;
    // Water (1.33, radius 1) inside glass (1.5, radius 2), both centered on the origin.
    let json = r#"{ "camera": {"eye": [0, 0, 10], "look_at": [0, 0, 0]},
        "materials": {"glass": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5},
                      "water": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.33}},
        "objects": [{"name": "glass", "sphere": {"radius": 2}, "material": "glass"},
                    {"name": "water", "sphere": {"radius": 1}, "material": "water"}] }"#;
    let boundaries = |s: &raytree::scene::Scene, from: DVec3| {
        let mut log = common::Log::default();
        Tracer::new(s).trace_primary(Ray::new(from, DVec3::NEG_Z), &mut log);
        log.hits
            .iter()
            .map(|h| (h.n1, h.n2, h.entering))
            .collect::<Vec<_>>()
    };
    // From outside, straight through the center: air → glass → water → glass → air.
    let outside = scene(json);
    let seen = boundaries(&outside, DVec3::new(0.0, 0.0, 10.0));
    println!("from outside: {seen:?}");
    assert_eq!(
        seen,
        vec![
            (1.0, 1.5, true),
            (1.5, 1.33, true),
            (1.33, 1.5, false),
            (1.5, 1.0, false)
        ]
    );
    // The camera inside the glass, between the two surfaces.
    let mut inside = scene(&json.replace(r#""eye": [0, 0, 10]"#, r#""eye": [0, 0, 1.5]"#));
    inside.settings.max_depth = 8;
    let seen = boundaries(&inside, DVec3::new(0.0, 0.0, 1.5));
    println!("from inside the glass: {seen:?}");
    assert_eq!(
        seen,
        vec![(1.5, 1.33, true), (1.33, 1.5, false), (1.5, 1.0, false)]
    );
}

// ---------------------------------------------------------------------------
// A very flat ellipsoid's normals.

#[test]
fn ellipsoid_normals_follow_the_inverse_transpose_at_axis_ratio_1e4() {
    use raytree::math::ray::Ray;
    // A unit sphere scaled to 1 × 1e-4 × 1, then turned 30° about z. In its own
    // (unturned) frame the surface is x² + (y/1e-4)² + z² = 1 with gradient
    // (x, y/1e-8, z): the analytic normal, worked out from the world point alone.
    // The tracer's normal goes through the inverse transpose; transforming the
    // normal like a point (by M) is the classic mistake.
    let s = scene(
        r#"{ "objects": [{"sphere": {}, "transform": [{"scale": [1, 1e-4, 1]}, {"rotate_z": 30}]}] }"#,
    );
    let object = &s.objects[0];
    let tf = **object.transform.as_ref().unwrap();
    let angle = |a: DVec3, b: DVec3| a.cross(b).length().atan2(a.dot(b));
    let (mut worst, mut worst_naive) = (0.0f64, 0.0f64);
    for k in 0..200 {
        let a = f64::from(k) * 0.031;
        let target = DVec3::new(0.9 * a.cos(), 0.0, 0.9 * a.sin());
        let origin = tf.to_world.transform_point3(DVec3::new(0.0, 3.0, 0.0))
            + tf.to_world.transform_vector3(target);
        let ray = Ray::new(
            origin,
            tf.to_world.transform_vector3(DVec3::new(0.0, -1.0, 0.0))
                + DVec3::new(0.01 * a.sin(), 0.0, 0.0),
        );
        let Some(t) = object
            .roots(&ray, s.settings.sphere)
            .first_in(0.0, f64::INFINITY)
        else {
            continue;
        };
        let surface = object.surface(&ray, t, 0, s.settings.intersection_methods());
        let turn = DQuat::from_rotation_z(30f64.to_radians());
        let q = turn.inverse() * surface.point;
        let analytic = turn * DVec3::new(q.x, q.y / 1e-8, q.z);
        let local = tf.to_object.transform_point3(surface.point);
        worst = worst.max(angle(surface.normal, analytic.normalize()));
        let naive = tf.to_world.transform_vector3(local);
        worst_naive = worst_naive.max(angle(naive.normalize(), analytic.normalize()));
    }
    println!(
        "worst normal error: inverse transpose (default) {worst:.2e} rad, transformed like a point {worst_naive:.2e} rad"
    );
    assert!(worst < 1e-6, "{worst}");
    assert!(
        worst_naive > 0.1,
        "the naive normal should be far off: {worst_naive}"
    );
}

// ---------------------------------------------------------------------------
// Two facing mirrors.

#[test]
fn facing_mirrors_stop_at_the_maximum_depth_and_the_cutoff_saves_rays() {
    use raytree::io::image::to_rgb8;
    use raytree::trace::render::render_counting;
    let mut s = scene(
        r#"{ "camera": {"eye": [0, 1, 0.5], "look_at": [3, 1, -0.4]},
        "render": {"width": 64, "height": 48, "max_depth": 64},
        "background": [0.3, 0.5, 0.8],
        "materials": {"mirror": {"color": [0.9, 0.9, 0.9], "ambient": 0.2, "diffuse": 0.4, "reflective": 0.5}},
        "lights": [{"position": [0, 3, 0]}],
        "objects": [{"plane": {"point": [0, 0, -1], "normal": [0, 0, 1]}, "material": "mirror"},
                    {"plane": {"point": [0, 0, 1], "normal": [0, 0, -1]}, "material": "mirror"}] }"#,
    );
    s.settings.cutoff = 0.0;
    let (fixed, fixed_rays) =
        render_counting(&s, &raytree::trace::progress::Progress::QUIET).unwrap();
    let mut log = common::Log::default();
    Tracer::new(&s).trace_primary(s.camera().pixel_ray(32.0, 24.0), &mut log);
    let deepest = log.rays.iter().map(|r| r.depth).max().unwrap();
    assert_eq!(deepest, 64, "the recursion ends at the maximum depth");
    let fixed8 = to_rgb8(&fixed);
    // The default cutoff was chosen for "within one 8-bit level"; a smaller one
    // gives the very same 8-bit image here. Both trace far fewer rays.
    for (cutoff, identical) in [
        (
            raytree::scene::settings::RenderSettings::DEFAULT_CUTOFF,
            false,
        ),
        (1e-6, true),
    ] {
        s.settings.cutoff = cutoff;
        let (adaptive, rays) =
            render_counting(&s, &raytree::trace::progress::Progress::QUIET).unwrap();
        let adaptive8 = to_rgb8(&adaptive);
        let worst = common::worst_difference(&fixed8, &adaptive8);
        let differ = fixed8
            .chunks(3)
            .zip(adaptive8.chunks(3))
            .filter(|(a, b)| a != b)
            .count();
        println!(
            "facing mirrors: fixed depth 64 traces {} rays (deepest ray {deepest}); cutoff {cutoff:.2e} traces {} ({:.1}%), {differ} pixels differ in 8 bits, by at most {worst}",
            fixed_rays.total(),
            rays.total(),
            100.0 * rays.total() as f64 / fixed_rays.total() as f64
        );
        assert!(
            rays.total() * 2 < fixed_rays.total(),
            "the cutoff should trace far fewer rays"
        );
        if identical {
            assert_eq!(differ, 0, "cutoff {cutoff}: the same 8-bit image");
        } else {
            assert!(worst <= 1, "cutoff {cutoff}: within one 8-bit level");
        }
    }
}

// ---------------------------------------------------------------------------
// No NaN or infinity reaches an image, whatever the methods.

#[test]
fn no_nan_or_infinity_reaches_an_image() {
    use raytree::methods::{SphereMethod, Weights};
    let mut renders = 0;
    for (name, mut s) in common::shipped() {
        s.settings.width = 48;
        s.settings.height = 36;
        for sphere in [SphereMethod::Lecture, SphereMethod::Stable] {
            for offset in [Offset::None, Offset::Epsilon(1e-4), Offset::Robust] {
                for weights in [Weights::Constant, Weights::Schlick, Weights::Fresnel] {
                    s.settings.sphere = sphere;
                    s.settings.offset = offset;
                    s.settings.weights = weights;
                    let image = raytree::trace::render::render(
                        &s,
                        &raytree::trace::progress::Progress::QUIET,
                    )
                    .unwrap();
                    let bad = image.pixels.iter().filter(|c| !c.is_finite()).count();
                    assert_eq!(bad, 0, "{name} {sphere:?} {offset:?} {weights:?}");
                    renders += 1;
                }
            }
        }
    }
    println!("{renders} renders (every shipped scene × every method), no NaN or infinity");
}
