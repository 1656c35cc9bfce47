//! Small scenes whose colors are worked out by hand, independently of the code.
//! Each test shows its working; tolerances are a few ULPs of values near 1
//! (1e-12), far below any error a wrong formula would make.

use crate::common::{Log, close, scene};
use glam::DVec3;
use raytree::math::ray::Ray;
use raytree::trace::recorder::{Branch, NoRecorder, RayKind, ShadowOutcome};
use raytree::trace::tracer::Tracer;

const TOL: f64 = 1e-12;

#[test]
fn lit_sphere_head_on_is_ambient_plus_diffuse() {
    // Unit sphere at the origin, eye and light both at (0, 0, 5). The center pixel
    // of a 101×101 image looks straight down -z and hits (0, 0, 1), normal +z,
    // direction to the light +z: N·L = 1. With k_a = 0.1, k_d = 0.6, no specular,
    // ambient light 1: color = 0.1·c + 0.6·1·c = 0.7·c.
    let s = scene(
        r#"{ "camera": {"eye": [0,0,5], "fov": 40}, "render": {"width": 101, "height": 101},
             "materials": {"m": {"color": [1, 0.5, 0.25], "ambient": 0.1, "diffuse": 0.6}},
             "lights": [{"position": [0, 0, 5]}],
             "objects": [{"sphere": {}, "material": "m"}] }"#,
    );
    let tracer = Tracer::new(&s);
    let color = raytree::trace::pixel::pixel_color(&tracer, &s.camera(), 50, 50, &mut NoRecorder);
    assert!(
        close(color, 0.7 * DVec3::new(1.0, 0.5, 0.25), TOL),
        "{color}"
    );
}

#[test]
fn floor_point_in_shadow_gets_ambient_only_and_a_lit_one_gets_lamberts_cosine() {
    // Floor y = 0, light at (0, 4, 0), opaque ball of radius 0.5 at (0, 2, 0).
    // From (0, 0, 0) the light is straight up, through the ball: ambient only,
    // 0.1·c. From (3, 0, 0) the direction to the light is (-3, 4, 0)/5, N·L = 0.8;
    // the segment passes the ball's center at distance 1.2 (closest at s = 0.68:
    // (0.96, 0.72)), missing it: 0.1·c + 0.6·0.8·c = 0.58·c.
    let s = scene(
        r#"{ "materials": {"floor": {"color": [0.5, 1, 0.2], "ambient": 0.1, "diffuse": 0.6}},
             "lights": [{"position": [0, 4, 0]}],
             "objects": [{"name": "floor", "plane": {}, "material": "floor"},
                         {"name": "ball", "sphere": {"center": [0, 2, 0], "radius": 0.5}}] }"#,
    );
    let tracer = Tracer::new(&s);
    let c = DVec3::new(0.5, 1.0, 0.2);
    let mut log = Log::default();
    // Both rays come down at 45° from y = 1 onto the points worked out above.
    let shadowed = tracer.trace_primary(
        Ray::new(DVec3::new(-1.0, 1.0, 0.0), DVec3::new(1.0, -1.0, 0.0)),
        &mut log,
    );
    assert!(close(shadowed, 0.1 * c, TOL), "{shadowed}");
    assert!(
        matches!(log.shadows[0].outcome, ShadowOutcome::Blocked { object: 1, t } if t > 0.0 && t < 1.0)
    );
    let lit = tracer.trace_primary(
        Ray::new(DVec3::new(2.0, 1.0, 0.0), DVec3::new(1.0, -1.0, 0.0)),
        &mut NoRecorder,
    );
    assert!(close(lit, 0.58 * c, TOL), "{lit}");
}

#[test]
fn mirror_floor_shows_the_ball_it_reflects() {
    // A mirror floor (k_rfl = 0.8, no local light) under a ball that glows with its
    // ambient color only (k_a = 1, ambient light 1, no lights). The ray from (0, 1, 0)
    // along (1, -1, 0) meets the floor at (1, 0, 0); the reflected direction
    // v = c - 2(n·c)n = (1, 1, 0) heads for (2, 1, 0), the ball's center.
    // color = 0 + 0.8·red. The ray behind it, one step further, misses: 0.8·background.
    let s = scene(
        r#"{ "background": [0.2, 0.3, 0.4],
             "materials": {"mirror": {"ambient": 0, "diffuse": 0, "reflective": 0.8},
                           "glow": {"color": [1, 0, 0], "ambient": 1, "diffuse": 0}},
             "objects": [{"plane": {}, "material": "mirror"},
                         {"sphere": {"center": [2, 1, 0], "radius": 0.5}, "material": "glow"}] }"#,
    );
    let tracer = Tracer::new(&s);
    let mut log = Log::default();
    let color = tracer.trace_primary(Ray::new(DVec3::Y, DVec3::new(1.0, -1.0, 0.0)), &mut log);
    assert!(close(color, DVec3::new(0.8, 0.0, 0.0), TOL), "{color}");
    let reflected = log.of_kind(RayKind::Reflected);
    assert_eq!(reflected.len(), 1);
    assert!(close(
        reflected[0].ray.dir.normalize(),
        DVec3::new(1.0, 1.0, 0.0).normalize(),
        TOL
    ));
    let far = tracer.trace_primary(
        Ray::new(DVec3::new(0.0, 1.0, 5.0), DVec3::new(1.0, -1.0, 0.0)),
        &mut NoRecorder,
    );
    assert!(close(far, 0.8 * DVec3::new(0.2, 0.3, 0.4), TOL), "{far}");
}

#[test]
fn ray_through_a_glass_ball_is_bent_by_snells_law_twice() {
    // A ray parallel to the axis at height h = 0.5 meets a unit glass ball (n = 1.5)
    // at incidence θ₁ = asin 0.5 = 30°, refracts to θ₂ = asin(0.5/1.5) = 19.47°,
    // crosses, and leaves at θ₁ again. By symmetry the total deviation is
    // 2(θ₁ - θ₂) = 21.06°, toward the axis. Media: air → glass, then glass → air.
    let s = scene(
        r#"{ "materials": {"glass": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5}},
             "objects": [{"sphere": {}, "material": "glass"}] }"#,
    );
    let tracer = Tracer::new(&s);
    let mut log = Log::default();
    tracer.trace_primary(Ray::new(DVec3::new(-5.0, 0.5, 0.0), DVec3::X), &mut log);
    let refracted = log.of_kind(RayKind::Refracted);
    assert_eq!(refracted.len(), 2, "one ray inside, one leaving");
    let out = refracted[1].ray.dir.normalize();
    let (t1, t2) = (0.5f64.asin(), (0.5f64 / 1.5).asin());
    let deviation = 2.0 * (t1 - t2);
    assert!(
        close(out, DVec3::new(deviation.cos(), -deviation.sin(), 0.0), TOL),
        "{out}"
    );
    assert_eq!(
        (log.hits[0].n1, log.hits[0].n2, log.hits[0].entering),
        (1.0, 1.5, true)
    );
    assert_eq!(
        (log.hits[1].n1, log.hits[1].n2, log.hits[1].entering),
        (1.5, 1.0, false)
    );
}

#[test]
fn total_internal_reflection_sends_the_refracted_share_to_the_reflection() {
    // The eye inside a glass ball (n = 1.5): a ray from the center along
    // (sin 60°, cos 60°, 0) hits the wall head-on (0° incidence) and refracts,
    // but a ray from (0, 0.8, 0) along +x meets the wall at incidence
    // asin(0.8) = 53.1°, beyond the critical angle asin(1/1.5) = 41.8°: total internal
    // reflection, so the reflected ray gets k_rfl + k_rfa = 0.1 + 0.9 = 1.
    let s = scene(
        r#"{ "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1]},
             "materials": {"glass": {"ambient": 0, "diffuse": 0, "reflective": 0.1, "transparent": 0.9, "ior": 1.5}},
             "objects": [{"sphere": {}, "material": "glass"}] }"#,
    );
    let tracer = Tracer::new(&s);
    let mut log = Log::default();
    tracer.trace_primary(
        Ray::new(DVec3::ZERO, DVec3::new(60f64.to_radians().sin(), 0.5, 0.0)),
        &mut log,
    );
    assert_eq!(
        (log.hits[0].n1, log.hits[0].n2, log.hits[0].entering),
        (1.5, 1.0, false),
        "the eye is inside the glass"
    );
    assert_eq!(
        log.branches[1].branch,
        Branch::Traced,
        "head-on: refracts out"
    );

    let mut log = Log::default();
    tracer.trace_primary(Ray::new(DVec3::new(0.0, 0.8, 0.0), DVec3::X), &mut log);
    // The primary's reflected branch comes first; its child's subtree is traced
    // before the primary's refracted branch is decided, so look at the primary's sum.
    assert_eq!(
        (log.branches[0].kind, log.branches[0].coefficient),
        (RayKind::Reflected, 1.0)
    );
    assert!(
        log.branches
            .iter()
            .any(|b| b.branch == Branch::TotalInternalReflection)
    );
    let primary = log.colors.last().unwrap();
    assert_eq!((primary.k_rfl, primary.k_rfa), (1.0, 0.0));
    let incidence = log.hits[0].shading_normal.dot(-DVec3::X).acos();
    assert!(
        (incidence - 0.8f64.asin()).abs() < TOL,
        "incidence {incidence}"
    );
}

#[test]
fn a_turned_plane_turns_its_checker_cells() {
    // A floor y = 0 turned 45° about y, cells of side 1 colored 1 and 0.2, lit
    // only by ambient light (k_a = 1), so a pixel's color is its cell's. The cells
    // are laid out in the plane's own space (scenes/README.md, `checker`): the
    // world point (0.9, 0, 0.5) is (0.283, 0, 0.990) there (rotating back by
    // -45°), cell (0, 0); in world axes it would be cell (0, 0) too, so the test
    // probes (0.9, 0, -0.5): own space (0.990, 0, 0.283), cell (0, 0), but world
    // cell (0, -1), the other color.
    let s = scene(
        r#"{ "camera": {"eye": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1]},
             "ambient_light": [1, 1, 1],
             "materials": {"m": {"checker": {"colors": [[1, 1, 1], [0.2, 0.2, 0.2]], "size": 1},
                                 "ambient": 1, "diffuse": 0, "specular": 0}},
             "lights": [],
             "objects": [{"plane": {"point": [0, 0, 0], "normal": [0, 1, 0]},
                          "transform": [{"rotate_y": 45}], "material": "m"}] }"#,
    );
    let tracer = Tracer::new(&s);
    let color_at = |x: f64, z: f64| {
        let ray = Ray::new(DVec3::new(x, 5.0, z), DVec3::NEG_Y);
        tracer.trace_primary(ray, &mut NoRecorder)
    };
    let cell = |p: DVec3| {
        let own = glam::DQuat::from_rotation_y(-45f64.to_radians()) * p;
        (own.x.floor() + own.z.floor()).rem_euclid(2.0)
    };
    for (x, z) in [
        (0.9, -0.5),
        (0.9, 0.5),
        (-0.3, -1.2),
        (1.7, 0.4),
        (2.5, -2.2),
    ] {
        let expected = if cell(DVec3::new(x, 0.0, z)) == 0.0 {
            1.0
        } else {
            0.2
        };
        let got = color_at(x, z);
        // Ambient only: the color is the cell's times k_a = 1, exact but for the
        // product's rounding.
        assert!(close(got, DVec3::splat(expected), TOL), "({x}, {z}): {got}");
    }
}
