//! Ray diagrams: probes of generated figures at pixels worked out from the
//! projection, byte-for-byte determinism, and two golden figures.
//!
//! Regenerate the goldens after an intended change with
//! `RAYTREE_BLESS=1 cargo test --release diagram`, and look at them.

use glam::DVec2;
use raytree::geometry::object::Shape;
use raytree::scene::source::SceneSource;
use raytree::tree::document::TraceDocument;
use raytree::views::diagram::draw;
use raytree::views::diagram_layout::{Labels, Options};
use raytree::views::figure::{Figure, palette};
use raytree::views::projection::{Outline, Projection, View};

fn whitted_figure(
    x: u32,
    y: u32,
    options: &Options,
) -> (raytree::scene::Scene, TraceDocument, Figure) {
    let scene = raytree::scene::loader::whitted();
    let trace = raytree::tree::record::pixel(
        &scene,
        SceneSource::new("scenes/whitted.json", ""),
        x,
        y,
        None,
    )
    .unwrap();
    let figure = draw(&trace, &scene, options).unwrap();
    (scene, trace, figure)
}

fn pixel(fig: &Figure, p: DVec2) -> [u8; 3] {
    let (w, _) = fig.size();
    let rgb = fig.rgb();
    let i = (p.y as usize * w as usize + p.x as usize) * 3;
    [rgb[i], rgb[i + 1], rgb[i + 2]]
}

/// The pixels within `r` of `p` (a line is antialiased over a pixel or two).
fn around(fig: &Figure, p: DVec2, r: i32) -> Vec<[u8; 3]> {
    (-r..=r)
        .flat_map(|dy| (-r..=r).map(move |dx| (dx, dy)))
        .map(|(dx, dy)| pixel(fig, p.round() + DVec2::new(f64::from(dx), f64::from(dy))))
        .collect()
}

fn near(c: [u8; 3], want: [u8; 3], tol: u8) -> bool {
    c.iter().zip(want).all(|(&a, b)| a.abs_diff(b) <= tol)
}

#[test]
fn the_primary_ray_midpoint_has_the_primary_color() {
    let options = Options {
        labels: Labels::None,
        shadows: false,
        ..Options::default()
    };
    for (x, y) in [(264, 200), (416, 209), (168, 296)] {
        let (scene, trace, fig) = whitted_figure(x, y, &options);
        let proj = Projection::new(View::Auto, &trace, 0, &scene.camera());
        let root = &trace.samples[0].tree.nodes[0];
        let mid = (proj.point(root.origin) + proj.point(root.hit.as_ref().unwrap().point)) / 2.0;
        // Tolerance 12: the 2.5-pixel line covers its center pixel fully; antialiasing
        // at the nearest pixel center can mix in a little paper.
        let at = fig.to_px(mid);
        assert!(
            around(&fig, at, 1)
                .iter()
                .any(|&c| near(c, palette::PRIMARY, 12)),
            "pixel {x},{y}: no primary color near {at}: {:?}",
            around(&fig, at, 1)
        );
    }
}

#[test]
fn a_sphere_outline_passes_where_its_circle_must() {
    let options = Options {
        labels: Labels::None,
        shadows: false,
        ..Options::default()
    };
    let (scene, trace, fig) = whitted_figure(264, 200, &options);
    let proj = Projection::new(View::Auto, &trace, 0, &scene.camera());
    let mirror = &scene.objects[1];
    let Shape::Sphere(s) = mirror.shape else {
        panic!("the mirror is a sphere")
    };
    let Outline::Ellipse { center, .. } = proj.outline(mirror) else {
        panic!()
    };
    assert!(center.abs_diff_eq(proj.point(s.center), 1e-12));
    // The outline is 1.5 pixels of dark gray (60, 60, 60): its darkest pixel is well under 150.
    for theta in [180f64, 225.0, 270.0, 315.0, 0.0] {
        let t = theta.to_radians();
        let on = fig.to_px(center + s.radius * DVec2::new(t.cos(), t.sin()));
        let darkest = around(&fig, on, 1)
            .into_iter()
            .map(|c| c.into_iter().max().unwrap())
            .min()
            .unwrap();
        assert!(
            darkest < 150,
            "no outline at {theta}° ({on}): {:?}",
            around(&fig, on, 1)
        );
        // And just inside, the fill: not the outline.
        let inside = fig.to_px(center + 0.9 * s.radius * DVec2::new(t.cos(), t.sin()));
        assert!(
            pixel(&fig, inside).iter().all(|&v| v > 180),
            "fill expected inside at {theta}°"
        );
    }
}

#[test]
fn nothing_is_drawn_outside_the_frame() {
    for (x, y) in [(416, 209), (8, 8), (168, 296)] {
        let (_, _, fig) = whitted_figure(x, y, &Options::default());
        let (w, h) = fig.size();
        let f = fig.frame();
        let rgb = fig.rgb();
        for py in 0..h {
            for px in 0..w {
                let (fx, fy) = (px as f32, py as f32);
                // The frame's 1-pixel border may spill half a pixel each way; the caption lives above the frame.
                let outside = fx < f.left() - 1.0 || fx > f.right() + 1.0 || fy > f.bottom() + 1.0;
                if outside {
                    let i = (py * w + px) as usize * 3;
                    assert_eq!(
                        &rgb[i..i + 3],
                        &palette::PAPER,
                        "pixel {x},{y}: drawing at ({px}, {py}) outside the frame"
                    );
                }
            }
        }
    }
}

#[test]
fn figures_are_deterministic() {
    let (_, _, a) = whitted_figure(416, 209, &Options::default());
    let (_, _, b) = whitted_figure(416, 209, &Options::default());
    assert!(a.png() == b.png());
}

#[test]
fn golden_figures() {
    let cases = [
        (
            "whitted-mirror",
            264,
            200,
            Options {
                width: 900,
                height: 600,
                ..Options::default()
            },
        ),
        (
            "whitted-glass",
            416,
            209,
            Options {
                depth: Some(3),
                ..Options::default()
            },
        ),
    ];
    for (name, x, y, options) in cases {
        let path = format!("{}/tests/diagrams/{name}.png", env!("CARGO_MANIFEST_DIR"));
        let (_, _, fig) = whitted_figure(x, y, &options);
        if std::env::var_os("RAYTREE_BLESS").is_some() {
            std::fs::write(&path, fig.png()).unwrap();
            continue;
        }
        let golden = image::open(&path)
            .unwrap_or_else(|e| panic!("{path}: {e} (make it with RAYTREE_BLESS=1)"))
            .to_rgb8();
        assert_eq!(golden.dimensions(), fig.size(), "{name}");
        // Tolerance 8 of 255 per channel: the figure is drawn the same way on every
        // machine, but a different SIMD path in the rasterizer may round an edge
        // pixel's coverage differently; a moved line or label changes pixels by far more.
        let worst = golden
            .as_raw()
            .iter()
            .zip(fig.rgb())
            .map(|(&a, b)| a.abs_diff(b))
            .max()
            .unwrap();
        assert!(
            worst <= 8,
            "{name}: a pixel differs by {worst} from tests/diagrams/{name}.png"
        );
    }
}
