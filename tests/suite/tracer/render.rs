//! The renderer: deterministic whatever the thread count, and never a NaN.

use crate::common;

use raytree::trace::render::render;

#[test]
fn same_image_bit_for_bit_on_one_two_and_three_threads() {
    let mut scene = raytree::scene::loader::whitted();
    scene.settings.width = 200;
    scene.settings.height = 150;
    scene.settings.spp = 4;
    let on = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap())
    };
    let one = on(1);
    assert_eq!(one, on(2));
    assert_eq!(one, on(3));
}

#[test]
fn shipped_scenes_render_finite_colors() {
    for (name, mut scene) in common::shipped() {
        scene.settings.width = 160;
        scene.settings.height = 120;
        let image = render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
        let bad = image.pixels.iter().filter(|c| !c.is_finite()).count();
        assert_eq!(bad, 0, "{name}: {bad} non-finite pixels");
    }
}

#[test]
fn adaptive_antialiasing_splits_only_where_corners_differ() {
    use raytree::methods::Antialiasing;
    use raytree::trace::pixel::pixel_color;
    use raytree::trace::recorder::RayCounter;
    use raytree::trace::tracer::Tracer;
    // A white ball on a black background, 64 × 48: a pixel in the empty corner
    // traces its four corners and stops; a pixel on the ball's edge splits.
    let mut s = common::scene(
        r#"{ "render": {"width": 64, "height": 48}, "ambient_light": [1, 1, 1],
             "materials": {"white": {"color": [1, 1, 1], "ambient": 1, "diffuse": 0}},
             "objects": [{"sphere": {"radius": 1}, "material": "white"}] }"#,
    );
    s.settings.aa = Antialiasing::Adaptive {
        threshold: 0.05,
        levels: 3,
    };
    let tracer = Tracer::new(&s);
    let camera = s.camera();
    let mut flat = RayCounter::default();
    assert_eq!(
        pixel_color(&tracer, &camera, 2, 2, &mut flat),
        glam::DVec3::ZERO
    );
    assert_eq!(flat.primary, 4);
    // Find a pixel on the edge: its color is strictly between black and white.
    let edge = (0..64).map(|x| (x, 24)).find(|&(x, y)| {
        let c = pixel_color(&tracer, &camera, x, y, &mut RayCounter::default()).x;
        c > 0.05 && c < 0.95
    });
    let (x, y) = edge.expect("a pixel on the ball's edge");
    let mut split = RayCounter::default();
    pixel_color(&tracer, &camera, x, y, &mut split);
    // Each split adds at most 5 corners; 3 levels along an edge stay well under a full 9 × 9 grid.
    assert!(
        split.primary > 4 && split.primary < 81,
        "{} rays",
        split.primary
    );
}

/// `render --stats` counts the boxes and primitives every ray tested, shadow
/// rays too: pixel by pixel, starting each with no remembered blocker, the
/// counter's tests add up to the `tests` image's (another recorder of the same
/// hooks), on a scene with a hierarchy and one without.
#[test]
fn the_ray_counter_counts_the_tests_the_tests_image_shows() {
    use raytree::trace::aov::{Aov, Value};
    use raytree::trace::aov_render::render_aov;
    use raytree::trace::pixel::pixel_color;
    use raytree::trace::recorder::RayCounter;
    use raytree::trace::tracer::Tracer;
    let spheres = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/spheres.json");
    for mut scene in [
        raytree::scene::loader::whitted(),
        raytree::scene::loader::load(&spheres).unwrap(),
    ] {
        scene.settings.width = 40;
        scene.settings.height = 30;
        let tracer = Tracer::new(&scene);
        let camera = scene.camera();
        let mut counted = RayCounter::default();
        for y in 0..30 {
            for x in 0..40 {
                tracer.forget_recent();
                pixel_color(&tracer, &camera, x, y, &mut counted);
            }
        }
        let image = render_aov(
            &scene,
            Aov::Tests,
            &raytree::trace::progress::Progress::QUIET,
        )
        .unwrap();
        let shown: f64 = image
            .values
            .iter()
            .map(|v| match v {
                Value::Number(n) => *n,
                other => panic!("a tests pixel is a number, not {other:?}"),
            })
            .sum();
        assert_eq!(counted.tests() as f64, shown);
        assert_eq!(counted.tests(), counted.boxes + counted.primitives);
        // Every ray tests something; a hierarchy's box tests show.
        assert!(counted.primitives >= counted.primary);
        assert_eq!(
            counted.boxes > 0,
            tracer.accelerator().bvh().is_some(),
            "boxes are tested exactly when there is a hierarchy"
        );
    }
}

/// The SPD protocol's sampling (issue 27): the renderer traces each of the
/// (W + 1) × (H + 1) pixel corners once, so it casts (W + 1)(H + 1) primary
/// rays, not 4·W·H; and every pixel is the mean of its four corners, bit for
/// bit what recording that pixel alone gives.
#[test]
fn corners_are_traced_once_and_each_pixel_is_their_mean() {
    use raytree::methods::Antialiasing;
    use raytree::trace::pixel::pixel_color;
    use raytree::trace::progress::Progress;
    use raytree::trace::recorder::RayCounter;
    use raytree::trace::render::render_counting;
    use raytree::trace::tracer::Tracer;
    let mut s = common::shipped().remove(0).1;
    (s.settings.width, s.settings.height) = (24, 18);
    s.settings.aa = Antialiasing::Corners;
    let (image, counted) = render_counting(&s, &Progress::QUIET).unwrap();
    assert_eq!(counted.primary, 25 * 19);
    let tracer = Tracer::new(&s);
    let camera = s.camera();
    for y in 0..18 {
        for x in 0..24 {
            let mut one = RayCounter::default();
            let c = pixel_color(&tracer, &camera, x, y, &mut one);
            assert_eq!(one.primary, 4);
            assert_eq!(image.pixels[(y * 24 + x) as usize], c, "pixel {x},{y}");
        }
    }
}

/// The counter's "eye hit rays": the primary rays that hit an object, as the
/// SPD counts them. A sphere filling part of the view: the hits are the
/// pixels whose `t` is finite in a render of the same rays.
#[test]
fn the_counter_counts_the_primary_rays_that_hit() {
    use raytree::trace::progress::Progress;
    use raytree::trace::render::render_counting;
    let mut s = common::scene(
        r#"{ "render": {"width": 32, "height": 24},
             "materials": {"m": {"color": [1, 1, 1], "reflective": 0.5}},
             "objects": [{"sphere": {"radius": 1.5}, "material": "m"}] }"#,
    );
    let (_, counted) = render_counting(&s, &Progress::QUIET).unwrap();
    let camera = s.camera();
    let ball = &s.objects[0];
    let expected = (0..24)
        .flat_map(|y| (0..32).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let ray = camera.pixel_ray(f64::from(x), f64::from(y));
            ball.roots(&ray, s.settings.intersection_methods())
                .first_in(0.0, f64::INFINITY)
                .is_some()
        })
        .count() as u64;
    assert!(expected > 50 && expected < 32 * 24, "{expected}");
    assert_eq!(counted.primary_hits, expected);
    // Reflected rays start and hit nothing (a lone ball): they do not count.
    assert!(counted.reflected > 0);
    s.settings.max_depth = 1;
    assert_eq!(
        render_counting(&s, &Progress::QUIET)
            .unwrap()
            .1
            .primary_hits,
        expected
    );
}
