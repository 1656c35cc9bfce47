//! `cargo bench -p raytree-benches --bench render`: intersection tests and a whole render of the Whitted scene.
//!
//! Throughput is in rays (or tests) per second: divan prints it next to the time.
//! A render's ray count (primary, shadow, reflected, refracted) is deterministic,
//! so it is counted once with the counting recorder and given to divan.

use divan::Bencher;
use divan::counter::ItemsCount;
use glam::DVec3;
use raytree::geometry::plane::Plane;
use raytree::geometry::sphere::Sphere;
use raytree::math::ray::Ray;
use raytree::scene::source::SceneSource;
use raytree::trace::render;

fn main() {
    divan::main();
}

/// Rays from a grid of origins toward the origin: about half hit a unit sphere.
fn rays() -> Vec<Ray> {
    (0..1024)
        .map(|i| {
            let (x, y) = (
                f64::from(i % 32) / 16.0 - 1.0,
                f64::from(i / 32) / 16.0 - 1.0,
            );
            Ray::new(
                DVec3::new(0.0, 0.0, 5.0),
                DVec3::new(1.5 * x, 1.5 * y, -5.0),
            )
        })
        .collect()
}

#[divan::bench]
fn ray_sphere(bencher: Bencher) {
    let sphere = Sphere {
        center: DVec3::ZERO,
        radius: 1.0,
    };
    let rays = rays();
    bencher.counter(ItemsCount::new(rays.len())).bench(|| {
        for ray in &rays {
            divan::black_box(sphere.roots(divan::black_box(ray)));
        }
    });
}

#[divan::bench]
fn ray_plane(bencher: Bencher) {
    let plane = Plane {
        point: DVec3::new(0.0, -0.5, 0.0),
        normal: DVec3::Y,
    };
    let rays = rays();
    bencher.counter(ItemsCount::new(rays.len())).bench(|| {
        for ray in &rays {
            divan::black_box(plane.roots(divan::black_box(ray)));
        }
    });
}

/// The Whitted scene at 640×480, 1 sample per pixel, max depth 8, on all cores.
#[divan::bench(sample_count = 30, sample_size = 1)]
fn whitted_640x480(bencher: Bencher) {
    let mut scene = raytree::scene::loader::whitted();
    scene.settings.width = 640;
    scene.settings.height = 480;
    scene.settings.spp = 1;
    scene.settings.max_depth = 8;
    let quiet = raytree::Progress::QUIET;
    let (_, rays) = render::render_counting(&scene, &quiet).unwrap();
    bencher
        .counter(ItemsCount::new(rays.total()))
        .bench(|| render::render(&scene, &quiet).unwrap());
}

/// Recording a whole pixel's ray tree (`raytree trace`, the inspector): the mean
/// over a 16 × 12 grid of pixels of the Whitted scene, glass and mirror included.
#[divan::bench(sample_count = 30)]
fn record_pixel(bencher: Bencher) {
    let scene = raytree::scene::loader::whitted();
    let pixels: Vec<(u32, u32)> = (0..12)
        .flat_map(|j| (0..16).map(move |i| (20 + 40 * i, 20 + 40 * j)))
        .collect();
    let source = SceneSource::new("whitted.json", "");
    bencher.counter(ItemsCount::new(pixels.len())).bench(|| {
        for &(x, y) in &pixels {
            divan::black_box(
                raytree::tree::record::pixel(&scene, source.clone(), x, y, None).unwrap(),
            );
        }
    });
}

/// The inspector: selecting a pixel (trace it, build its tree, steps and panes)
/// and drawing the whole screen, 160 × 48 cells. Target: under 50 ms.
/// An inspector on the Whitted scene laid out as on a 160 × 48 terminal, no worker thread.
fn inspector_on_whitted() -> raytree::inspector::App {
    use ratatui::layout::Rect;
    let scene = raytree::scene::loader::whitted();
    let mut app =
        raytree::inspector::App::new(scene, SceneSource::new("whitted.json", ""), None, false);
    app.set_areas(raytree::inspector::Areas {
        image: Rect::new(1, 1, 78, 27),
        tree: Rect::new(81, 1, 78, 19),
        details: Rect::new(80, 21, 80, 25),
    });
    app
}

#[divan::bench(sample_count = 50)]
fn inspector_select_pixel(bencher: Bencher) {
    use ratatui::{Terminal, backend::TestBackend};
    let mut app = inspector_on_whitted();
    app.render_picture_now();
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    bencher.bench_local(|| {
        app.select((416, 209));
        raytree::inspector::tick(&mut app, ratatui::layout::Rect::new(0, 0, 160, 48));
        terminal
            .draw(|f| raytree::inspector::draw(f, &app))
            .unwrap();
    });
}

/// The inspector's first frame with a picture: start on the Whitted scene, trace
/// the coarse pass of a 78 × 54-dot image pane, draw 160 × 48 cells. Target: under 200 ms.
#[divan::bench(sample_count = 30)]
fn inspector_first_frame(bencher: Bencher) {
    use ratatui::{Terminal, backend::TestBackend};
    bencher.bench_local(|| {
        let mut app = inspector_on_whitted();
        let window = app.window();
        let picture = raytree::inspector::render_picture(
            &raytree::trace::tracer::Tracer::new(app.scene().unwrap()),
            window,
            0,
            &|| false,
        );
        app.set_picture(picture);
        let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
        raytree::inspector::tick(&mut app, ratatui::layout::Rect::new(0, 0, 160, 48));
        terminal
            .draw(|f| raytree::inspector::draw(f, &app))
            .unwrap();
    });
}
