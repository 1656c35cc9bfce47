//! Per-pixel quantities (`raytree render --aov`): each checked against what
//! it claims to show, worked out another way (the rendered image, the ray
//! tree `raytree trace` records, the lecture's quadratic), deterministic on
//! any number of threads, a few golden figures, and the command's errors.
//!
//! Regenerate the goldens after an intended change with
//! `RAYTREE_BLESS=1 cargo test --release aov`, and look at them.

use glam::DVec3;
use raytree::geometry::object::Shape;
use raytree::scene::Scene;
use raytree::scene::source::SceneSource;
use raytree::trace::aov::{Aov, AovImage, Value};
use raytree::trace::aov_render::render_aov;
use raytree::tree::ray_tree::{RayTree, ShadowOutcomeRecord};
use raytree::views::aov_figure;

use crate::common;

fn small(mut scene: Scene, width: u32, height: u32, spp: u32) -> Scene {
    scene.settings.width = width;
    scene.settings.height = height;
    scene.settings.spp = spp;
    scene
}

fn aov(scene: &Scene, spec: &str) -> AovImage {
    let aov = Aov::parse(spec, scene).unwrap();
    render_aov(scene, aov, &raytree::trace::progress::Progress::QUIET).unwrap()
}

fn color(v: Value) -> DVec3 {
    match v {
        Value::Color(c) => c,
        other => panic!("not a color: {other:?}"),
    }
}

fn number(v: Value) -> f64 {
    match v {
        Value::Number(x) => x,
        other => panic!("not a number: {other:?}"),
    }
}

/// Every `step`-th pixel, in both directions, of a `width × height` image.
fn sampled(width: u32, height: u32, step: u32) -> impl Iterator<Item = (u32, u32)> {
    (0..height)
        .step_by(step as usize)
        .flat_map(move |y| (0..width).step_by(step as usize).map(move |x| (x, y)))
}

fn trees(scene: &Scene, x: u32, y: u32) -> Vec<RayTree> {
    let doc =
        raytree::tree::record::pixel(scene, SceneSource::new("t.json", ""), x, y, None).unwrap();
    doc.samples.into_iter().map(|s| s.tree).collect()
}

#[test]
fn the_three_terms_sum_to_the_rendered_image() {
    // Four samples per pixel too: the terms are averaged as the image is.
    for (name, scene) in common::shipped() {
        for spp in [1, 4] {
            let scene = small(scene.clone(), 64, 48, spp);
            let image =
                raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET)
                    .unwrap();
            let terms = ["local", "reflected", "refracted"].map(|t| aov(&scene, t));
            for (i, rendered) in image.pixels.iter().enumerate() {
                let sum: DVec3 = terms.iter().map(|t| color(t.values[i])).sum();
                // 1e-12 per channel: the tracer adds the same three products in
                // the same order; only the mean over samples may round differently.
                assert!(
                    (sum - *rendered).abs().max_element() <= 1e-12,
                    "{name}, {spp} spp, pixel {i}: {sum} against {rendered}"
                );
            }
        }
    }
}

#[test]
fn depth_tests_and_shadows_agree_with_the_recorded_trees() {
    for (name, scene) in common::shipped() {
        let scene = small(scene, 48, 36, 1);
        let depth = aov(&scene, "depth");
        let tests = aov(&scene, "tests");
        let shadows: Vec<AovImage> = (0..scene.lights.len())
            .map(|l| aov(&scene, &format!("shadow={}", scene.lights[l].name)))
            .collect();
        for (x, y) in sampled(48, 36, 5) {
            let tree = &trees(&scene, x, y)[0];
            let deepest = tree.nodes.iter().map(|n| n.depth).max().unwrap();
            assert_eq!(
                number(depth.get(x, y)),
                f64::from(deepest),
                "{name} {x},{y}"
            );
            let counted: u32 = tree
                .nodes
                .iter()
                .flat_map(|n| {
                    std::iter::once(n.tested).chain(n.shadow_rays.iter().map(|s| s.tested))
                })
                .map(|t| t.boxes + t.primitives)
                .sum();
            assert_eq!(
                number(tests.get(x, y)),
                f64::from(counted),
                "{name} {x},{y}"
            );
            let root = &tree.nodes[0];
            for (l, image) in shadows.iter().enumerate() {
                let expected = match root.shadow_rays.get(l).map(|s| &s.outcome) {
                    None => Value::Undefined,
                    Some(ShadowOutcomeRecord::Reaches { transmitted }) if *transmitted >= 1.0 => {
                        Value::Category(0)
                    }
                    Some(ShadowOutcomeRecord::Reaches { .. }) => Value::Category(1),
                    Some(ShadowOutcomeRecord::Blocked { .. }) => Value::Category(2),
                    Some(ShadowOutcomeRecord::FacesAway) => Value::Category(3),
                };
                assert_eq!(image.get(x, y), expected, "{name} {x},{y} light {l}");
            }
        }
    }
}

#[test]
fn the_shadow_categories_cover_the_lit_the_dimmed_the_blocked_and_the_turned_away() {
    let scene = small(raytree::scene::loader::whitted(), 96, 72, 1);
    let key = aov(&scene, "shadow=key");
    for k in 0..4 {
        assert!(
            key.values.contains(&Value::Category(k)),
            "category {k} never occurs"
        );
    }
    assert!(key.values.contains(&Value::Undefined), "the sky has no hit");
}

#[test]
fn the_discriminant_sign_is_hit_or_miss_of_the_lecture_quadratic() {
    let scene = small(common::shipped()[2].1.clone(), 64, 48, 1);
    let camera = scene.camera();
    let spheres: Vec<usize> = (0..scene.objects.len())
        .filter(|&i| matches!(scene.objects[i].shape, Shape::Sphere(_)))
        .collect();
    assert!(
        spheres.len() >= 2,
        "ellipsoids.json has transformed spheres"
    );
    let (mut hits, mut misses) = (0, 0);
    for &i in &spheres {
        let image = aov(&scene, &format!("discriminant={}", scene.objects[i].name));
        let object = &scene.objects[i];
        let Shape::Sphere(sphere) = &object.shape else {
            unreachable!()
        };
        for (x, y) in sampled(64, 48, 3) {
            let ray = camera.pixel_ray(f64::from(x), f64::from(y));
            let own = object
                .transform
                .as_ref()
                .map_or(ray, |t| t.ray_to_object(&ray));
            let d = number(image.get(x, y));
            let hit = !sphere.lecture_roots(&own).as_slice().is_empty();
            // Within rounding of zero the two forms (scaled by r⁴) may disagree.
            if d.abs() < 1e-9 {
                continue;
            }
            assert_eq!(d > 0.0, hit, "{} at {x},{y}: B² − AC = {d}", object.name);
            if hit { hits += 1 } else { misses += 1 }
        }
    }
    assert!(hits > 20 && misses > 20, "{hits} hits, {misses} misses");
}

#[test]
fn every_quantity_is_the_same_on_one_and_two_threads() {
    let scene = small(raytree::scene::loader::whitted(), 40, 30, 4);
    let names = raytree::trace::aov::NAMES
        .iter()
        .map(|(n, _)| n.split('[').next().unwrap())
        .chain(["shadow=fill", "rays=shadow", "discriminant=glass"]);
    for name in names {
        let on = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| aov(&scene, name))
        };
        let one = on(1);
        assert_eq!(one, on(2), "{name}");
        let figure = |image: &AovImage| aov_figure::draw(image, "caption").unwrap().png();
        assert_eq!(figure(&one), figure(&on(2)), "{name}: the figure");
    }
}

#[test]
fn golden_figures() {
    let scene = small(raytree::scene::loader::whitted(), 160, 120, 1);
    for name in ["depth", "tests", "shadow=key", "discriminant=glass"] {
        let image = aov(&scene, name);
        let fig = aov_figure::draw(&image, "scenes/whitted.json · 160×120").unwrap();
        let file = name.replace('=', "-");
        let path = format!("{}/tests/aovs/{file}.png", env!("CARGO_MANIFEST_DIR"));
        crate::common::matches_golden(&fig, path.as_ref(), "aov");
    }
}

#[test]
fn bad_names_are_one_line_errors() {
    // A name the scene does not have is the flag's fault: exit 2.
    use crate::commands::cli::usage_in;
    let e = usage_in("render", "aov-name", &["--aov", "colour"]);
    assert!(
        e.starts_with("error: --aov: unknown quantity 'colour' (known: local"),
        "{e}"
    );
    let e = usage_in("render", "aov-light", &["--aov", "shadow=sun"]);
    assert_eq!(
        e,
        "error: --aov: unknown light 'sun' (the scene's lights: key, fill)"
    );
    let e = usage_in("render", "aov-sphere", &["--aov", "discriminant=floor"]);
    assert!(e.contains("'floor' is not a sphere"), "{e}");
    let e = usage_in("render", "aov-ppm", &["--aov", "depth", "-o", "d.ppm"]);
    assert!(e.contains("is a .png"), "{e}");
}

#[test]
fn the_command_writes_the_figure_or_the_bare_image() {
    let dir = std::env::temp_dir().join(format!("raytree-aov-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let run = |extra: &[&str]| {
        let args = [
            &[
                "render", "--width", "80", "--height", "60", "--aov", "depth", "-q",
            ][..],
            extra,
        ]
        .concat();
        crate::commands::cli::succeeds(&args, &dir);
    };
    run(&[]);
    let figure = image::open(dir.join("whitted-depth.png")).unwrap();
    assert!(
        figure.width() >= 640 && figure.height() > 60,
        "a key strip below"
    );
    run(&["--no-key", "-o", "bare.png"]);
    let bare = image::open(dir.join("bare.png")).unwrap();
    assert_eq!((bare.width(), bare.height()), (80, 60));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["render", "--no-key"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "--no-key needs --aov");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The inspector's overlays read the same per-pixel record through the same
/// pixel loop as `render --aov`: tests, rays, depth and total internal
/// reflection agree on every pixel (on `spheres.json` the inspector once
/// differed on 15,605 of 19,200 pixels, remembering each thread's recent
/// shadow blocker from pixel to pixel where the AOV forgot it).
#[test]
fn the_inspectors_overlays_are_the_aovs_on_every_pixel() {
    for name in ["whitted.json", "spheres.json"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name);
        let scene = small(raytree::scene::loader::load(&path).unwrap(), 160, 120, 1);
        let overlay = raytree::inspector::scan_features(&scene, 1);
        assert_eq!((overlay.cols, overlay.rows), (160, 120));
        let cells = |f: fn(&raytree::inspector::Features) -> f64| -> Vec<f64> {
            overlay.cells.iter().map(f).collect()
        };
        let numbers =
            |spec: &str| -> Vec<f64> { aov(&scene, spec).values.into_iter().map(number).collect() };
        for (what, shown, rendered) in [
            ("tests", cells(|f| f64::from(f.tests)), numbers("tests")),
            ("rays", cells(|f| f64::from(f.rays)), numbers("rays")),
            ("depth", cells(|f| f64::from(f.depth)), numbers("depth")),
        ] {
            let differ = shown.iter().zip(&rendered).filter(|(a, b)| a != b).count();
            assert_eq!(
                differ, 0,
                "{name}: {what} differs on {differ} of 19,200 pixels"
            );
        }
        let tir = aov(&scene, "tir").values;
        for (f, v) in overlay.cells.iter().zip(tir) {
            assert_eq!(Value::Category(u32::from(f.tir)), v, "{name}: tir");
        }
    }
}

/// The object view of a scene of many objects names only those seen most,
/// and says how many it leaves out: a key of every object seen ran to 1,570
/// pixels high under a 120-pixel image of 400 spheres (colors repeating).
#[test]
fn the_object_key_of_a_big_scene_names_those_seen_most() {
    let mut text = String::from(
        r#"{"camera": {"eye": [0, 0, 30], "fov": 60}, "lights": [{"position": [0, 10, 30]}], "objects": ["#,
    );
    for i in 0..400 {
        let (x, y) = (f64::from(i % 20) - 9.5, f64::from(i / 20) - 9.5);
        text.push_str(&format!(
            r#"{}{{"name": "ball{i}", "sphere": {{"center": [{x}, {y}, 0], "radius": 0.45}}}}"#,
            if i == 0 { "" } else { ", " }
        ));
    }
    text.push_str("]}");
    let scene = small(
        raytree::scene::loader::parse(&text, "many.json").unwrap(),
        160,
        120,
        1,
    );
    let image = aov(&scene, "object");
    let seen: std::collections::BTreeSet<u32> = image
        .values
        .iter()
        .filter_map(|v| match v {
            Value::Category(k) => Some(*k),
            _ => None,
        })
        .collect();
    assert!(seen.len() > 100, "{} objects seen", seen.len());
    let fig = aov_figure::draw(&image, "many.json · 160×120").unwrap();
    let (_, height) = fig.size();
    assert!(
        height < 120 + 300,
        "the key is {} pixels high",
        height - 120
    );
}
