//! Every structure of the efficiency slide (issue 28) finds exactly what
//! testing every object finds: the same images, bit for bit, on every shipped
//! scene and the seven SPD scenes, and fewer tests per ray than the lecture's
//! loop once a scene has many objects.

use raytree::methods::Accel;
use raytree::scene::Scene;
use raytree::trace::progress::Progress;
use raytree::trace::render::{render, render_counting};

use crate::tools::{self, Need};

const STRUCTURES: [Accel; 4] = [Accel::Bvh, Accel::Grid, Accel::Octree, Accel::Bsp];

/// Renders `scene` small with no structure and with each, and checks the
/// images are the same to the bit.
fn same_images(name: &str, mut scene: Scene, size: (u32, u32)) {
    (scene.settings.width, scene.settings.height) = size;
    scene.settings.accel = Accel::None;
    let none = render(&scene, &Progress::QUIET).unwrap();
    for accel in STRUCTURES {
        scene.settings.accel = accel;
        let with = render(&scene, &Progress::QUIET).unwrap();
        let differ = none
            .pixels
            .iter()
            .zip(&with.pixels)
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(
            differ, 0,
            "{name} with {accel:?}: {differ} pixels differ from testing every object"
        );
    }
}

#[test]
fn every_structure_renders_the_shipped_scenes_as_testing_every_object_does() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    for name in [
        "whitted.json",
        "nested.json",
        "ellipsoids.json",
        "spheres.json",
        "gaspra.json",
        "cones.json",
        "polygons.json",
        "sampler.nff",
        "../lessons/12-efficiency/scatter.json",
    ] {
        let scene = raytree::scene::loader::load(&root.join(name)).unwrap();
        same_images(name, scene, (64, 48));
    }
}

#[test]
fn every_structure_renders_the_spd_scenes_as_testing_every_object_does() {
    if !tools::available("", &[Need::Spd], "the SPD scenes are read from it") {
        return;
    }
    let dir = tools::spd().unwrap();
    for name in [
        "balls", "gears", "mount", "rings", "teapot", "tetra", "tree",
    ] {
        let mut scene = raytree::scene::loader::load(&dir.join(format!("{name}.nff"))).unwrap();
        scene.settings = raytree::scene::overrides::Protocol::Spd
            .overrides()
            .apply(&scene.settings);
        same_images(name, scene, (48, 48));
    }
}

#[test]
fn every_structure_tests_far_fewer_objects_than_the_lectures_loop() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scene = raytree::scene::loader::load(&root.join("spheres.json")).unwrap();
    (scene.settings.width, scene.settings.height) = (64, 48);
    scene.settings.accel = Accel::None;
    let all = render_counting(&scene, &Progress::QUIET).unwrap().1;
    for accel in STRUCTURES {
        scene.settings.accel = accel;
        let with = render_counting(&scene, &Progress::QUIET).unwrap().1;
        // 2,000 spheres: each structure should leave a ray a handful of spheres, not thousands.
        assert!(
            with.primitives * 10 < all.primitives,
            "{accel:?}: {} primitive tests against {} testing every object",
            with.primitives,
            all.primitives
        );
        assert_eq!(with.total(), all.total(), "{accel:?}: the same rays");
    }
}

/// The sizes a user may ask for, at both ends (a grid of one cell or of 160
/// along the longest side, a tree of one leaf or 48 levels), still find what
/// testing every object finds; and each changes the work as it should: one
/// cell or one leaf tests every object, a finer grid walks more cells.
#[test]
fn every_size_a_user_may_ask_for_renders_the_same_images() {
    use raytree::methods::Level;
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scene = raytree::scene::loader::load(&root.join("spheres.json")).unwrap();
    (scene.settings.width, scene.settings.height) = (40, 30);
    scene.settings.accel = Accel::None;
    let none = render_counting(&scene, &Progress::QUIET).unwrap();
    let mut cells = Vec::new();
    for (accel, grid_res, tree_depth) in [
        (Accel::Grid, Level::Given(1), Level::Auto),
        (Accel::Grid, Level::Given(20), Level::Auto),
        (Accel::Grid, Level::Given(160), Level::Auto),
        (Accel::Octree, Level::Auto, Level::Given(0)),
        (Accel::Octree, Level::Auto, Level::Given(48)),
        (Accel::Bsp, Level::Auto, Level::Given(0)),
        (Accel::Bsp, Level::Auto, Level::Given(48)),
    ] {
        scene.settings.accel = accel;
        scene.settings.grid_res = grid_res;
        scene.settings.tree_depth = tree_depth;
        let (image, counts) = render_counting(&scene, &Progress::QUIET).unwrap();
        let what = format!("{accel:?} at grid_res {grid_res}, tree_depth {tree_depth}");
        assert!(image.pixels == none.0.pixels, "{what}: the image differs");
        if grid_res == Level::Given(1) || tree_depth == Level::Given(0) {
            // Everything in one cell or leaf: a primary ray tests the floor
            // plane, and if it reaches the cell, all 2,000 spheres. (Only primary
            // rays: a shadow ray stops at its first blocker.)
            let mut eyes_only = scene.clone();
            eyes_only.lights.clear();
            eyes_only.settings.max_depth = 1;
            let with = render_counting(&eyes_only, &Progress::QUIET).unwrap().1;
            eyes_only.settings.accel = Accel::None;
            let all = render_counting(&eyes_only, &Progress::QUIET).unwrap().1;
            assert_eq!(all.primitives, all.primary * 2001, "{what}");
            let spheres = with.primitives - with.primary;
            assert!(
                spheres > 0 && spheres.is_multiple_of(2000),
                "{what}: {with:?}"
            );
        }
        if accel == Accel::Grid {
            cells.push(counts.boxes);
        }
    }
    assert!(
        cells[0] < cells[1] && cells[1] < cells[2],
        "cells walked: {cells:?}"
    );
}
