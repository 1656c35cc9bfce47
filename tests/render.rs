//! The renderer: deterministic whatever the thread count, and never a NaN.

mod common;

use indicatif::ProgressBar;
use raytree::render::render;

#[test]
fn same_image_bit_for_bit_on_one_two_and_three_threads() {
    let mut scene = raytree::scene_file::whitted();
    scene.settings.width = 200;
    scene.settings.height = 150;
    scene.settings.spp = 4;
    let on = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| render(&scene, &ProgressBar::hidden()).unwrap())
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
        let image = render(&scene, &ProgressBar::hidden()).unwrap();
        let bad = image.pixels.iter().filter(|c| !c.is_finite()).count();
        assert_eq!(bad, 0, "{name}: {bad} non-finite pixels");
    }
}
