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
