//! The default weight cutoff (Hall & Greenberg's adaptive depth) against a fixed
//! depth of 32 on every shipped scene: no 8-bit pixel moves by more than one
//! level, and fewer rays are traced.

use crate::common;

use raytree::io::image::to_rgb8;
use raytree::scene::settings::RenderSettings;
use raytree::trace::render::render_counting;

#[test]
fn default_cutoff_changes_no_pixel_by_more_than_one_level() {
    let (mut all_fixed, mut all_adaptive) = (0, 0);
    for (name, mut scene) in common::shipped() {
        scene.settings.width = 320;
        scene.settings.height = 240;
        scene.settings.max_depth = 32;
        scene.settings.cutoff = 0.0;
        let (fixed, fixed_rays) =
            render_counting(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
        scene.settings.cutoff = RenderSettings::DEFAULT_CUTOFF;
        let (adaptive, adaptive_rays) =
            render_counting(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
        let worst = common::worst_difference(&to_rgb8(&fixed), &to_rgb8(&adaptive));
        println!(
            "{name}: fixed depth 32 traces {} rays, cutoff {} traces {} ({:.1}%); worst 8-bit difference {worst}",
            fixed_rays.total(),
            RenderSettings::DEFAULT_CUTOFF,
            adaptive_rays.total(),
            100.0 * adaptive_rays.total() as f64 / fixed_rays.total() as f64
        );
        assert!(worst <= 1, "{name}: a pixel moved by {worst} levels");
        assert!(
            adaptive_rays.total() <= fixed_rays.total(),
            "{name}: the cutoff traced more rays"
        );
        all_fixed += fixed_rays.total();
        all_adaptive += adaptive_rays.total();
    }
    // A scene without chains of reflections (the ellipsoids) has nothing to save.
    assert!(
        2 * all_adaptive < all_fixed,
        "the cutoff should at least halve the rays over the shipped scenes: {all_adaptive} vs {all_fixed}"
    );
}
