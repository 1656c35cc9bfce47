//! Ray diagrams: probes of generated figures at pixels worked out from the
//! projection, byte-for-byte determinism, and two golden figures.
//!
//! Regenerate the goldens after an intended change with
//! `RAYTREE_BLESS=1 cargo test --release diagram`, and look at them.

use glam::DVec2;
use raytree::figure::canvas::Figure;
use raytree::figure::labels::Target;
use raytree::figure::pen::palette;
use raytree::geometry::object::Shape;
use raytree::scene::source::SceneSource;
use raytree::tree::document::TraceDocument;
use raytree::views::diagram::arrange::layout;
use raytree::views::diagram::draw::{draw, draw_with_labels};
use raytree::views::diagram::options::{Fit, Labels, Options};
use raytree::views::diagram::projection::{Outline, Projection, View};
use raytree::views::diagram::style::Stroke;
use raytree::views::numbers::degrees;

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
fn the_primary_ray_is_drawn_in_its_color_where_it_is_solid() {
    let options = Options {
        labels: Labels::None,
        shadows: false,
        fit: Fit::Tree,
        ..Options::default()
    };
    for (x, y) in [(264, 200), (416, 209), (168, 296), (300, 290)] {
        let (scene, trace, fig) = whitted_figure(x, y, &options);
        let lay = layout(&trace, &scene, &options).unwrap();
        let primary = lay
            .segments
            .iter()
            .find(|s| s.stroke == Stroke::Ray(raytree::tree::ray_tree::RayKind::Primary))
            .unwrap();
        // The middle of the longest solid piece (not passing an object).
        let mut cuts = vec![0.0];
        cuts.extend(primary.passing.iter().flatten());
        cuts.push(1.0);
        let (a, b) = cuts
            .chunks(2)
            .map(|w| (w[0], w[1]))
            .max_by(|p, q| (p.1 - p.0).total_cmp(&(q.1 - q.0)))
            .unwrap();
        let mid = primary.from + (primary.to - primary.from) * ((a + b) / 2.0);
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

/// Draws one golden figure.
type Drawer = Box<dyn Fn() -> Figure>;

#[test]
fn golden_figures() {
    let plain = |x, y, options: Options| move || whitted_figure(x, y, &options).2;
    let small = Options {
        width: 900,
        height: 600,
        ..Options::default()
    };
    let three_levels = Options {
        depth: Some(3),
        ..Options::default()
    };
    let camera = || {
        let (_, trace) = traced("whitted.json", 416, 209);
        raytree::views::diagram::camera_view::draw(&trace, 1200, 800).unwrap()
    };
    let boxes = || {
        let (scene, trace) = traced("spheres.json", 300, 200);
        let options = Options {
            view: View::Top,
            depth: Some(1),
            shadows: false,
            boxes: true,
            ..Options::default()
        };
        raytree::views::diagram::draw::draw(&trace, &scene, &options).unwrap()
    };
    let cases: [(&str, Drawer); 5] = [
        ("whitted-mirror", Box::new(plain(264, 200, small))),
        ("whitted-glass", Box::new(plain(416, 209, three_levels))),
        (
            "whitted-floor",
            Box::new(plain(168, 296, Options::default())),
        ),
        ("whitted-camera", Box::new(camera)),
        ("spheres-boxes", Box::new(boxes)),
    ];
    for (name, figure) in cases {
        let path = format!("{}/tests/diagrams/{name}.png", env!("CARGO_MANIFEST_DIR"));
        crate::common::matches_golden(&figure(), path.as_ref(), "diagram");
    }
}

/// Scenes, pixels and views that between them show every kind of figure.
fn cases() -> Vec<(&'static str, u32, u32, View)> {
    let mut out = Vec::new();
    for (x, y) in [
        (416, 209),
        (264, 200),
        (168, 296),
        (300, 40),
        (440, 376),
        (300, 290),
    ] {
        out.push(("whitted.json", x, y, View::Auto));
    }
    for view in [View::Auto, View::Top, View::Side, View::Front] {
        out.push(("ellipsoids.json", 320, 240, view));
    }
    out.push(("whitted.json", 300, 290, View::Front));
    out.push(("nested.json", 320, 240, View::Auto));
    out.push(("spheres.json", 320, 240, View::Auto));
    out.push(("gaspra.json", 320, 240, View::Auto));
    out
}

fn traced(scene: &str, x: u32, y: u32) -> (raytree::scene::Scene, TraceDocument) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(scene);
    let s = raytree::scene::loader::load(&path).unwrap();
    let t = raytree::tree::record::pixel(&s, SceneSource::new(scene, ""), x, y, None).unwrap();
    (s, t)
}

/// Whether `p` lies inside a bounded outline by more than a hair (the test's own
/// point-in-ellipse and point-in-convex-polygon).
fn strictly_inside(outline: &Outline, p: DVec2) -> bool {
    match outline {
        Outline::Ellipse { center, axes } => {
            let d = p - *center;
            let (l0, l1) = (axes[0].length_squared(), axes[1].length_squared());
            l0 > 0.0 && l1 > 0.0 && {
                let (u, v) = (d.dot(axes[0]) / l0, d.dot(axes[1]) / l1);
                u * u + v * v < 1.0 - 1e-6
            }
        }
        Outline::Polygon { points } if points.len() >= 3 => (0..points.len()).all(|k| {
            let (a, b) = (points[k], points[(k + 1) % points.len()]);
            (b - a).perp_dot(p - a) > 1e-9 * (b - a).length()
        }),
        _ => false,
    }
}

#[test]
fn a_ray_over_an_object_it_does_not_enter_is_never_drawn_solid() {
    let mut checked = 0;
    for (name, x, y, view) in cases() {
        let (scene, trace) = traced(name, x, y);
        let options = Options {
            view,
            ..Options::default()
        };
        let lay = layout(&trace, &scene, &options).unwrap();
        for seg in &lay.segments {
            let (a, b) = seg.ends;
            for k in 1..60 {
                let s = f64::from(k) / 60.0;
                let p3 = a + (b - a) * s;
                let p2 = lay.proj.point(p3);
                for (i, object) in scene.objects.iter().enumerate() {
                    if !strictly_inside(&lay.objects[i].silhouette, p2) || object.contains(p3) {
                        continue;
                    }
                    checked += 1;
                    let dotted = seg
                        .passing
                        .iter()
                        .any(|&[s0, s1]| s >= s0 - 1e-6 && s <= s1 + 1e-6);
                    assert!(
                        dotted,
                        "{name} {x},{y} {view:?}: {:?} drawn solid over '{}' at s = {s} though it passes it",
                        seg.stroke, object.name
                    );
                }
            }
        }
    }
    assert!(
        checked > 100,
        "only {checked} points over a silhouette checked"
    );
}

#[test]
fn the_auto_view_puts_world_up_on_top_and_runs_the_ray_left_to_right() {
    for (name, x, y, view) in cases().into_iter().filter(|c| c.3 == View::Auto) {
        let (scene, trace) = traced(name, x, y);
        let proj = Projection::new(view, &trace, 0, &scene.camera());
        let up = trace
            .camera
            .look_at
            .as_ref()
            .map_or(trace.camera.v, |l| l.up.normalize());
        let at = format!("{name} {x},{y}");
        // Tolerances: an orthonormal frame to a few ULPs.
        assert!(proj.up.dot(up) > 0.0, "{at}: world up points down the page");
        assert!(proj.right.dot(proj.up).abs() < 1e-12, "{at}");
        assert!(
            (proj.right.length() - 1.0).abs() < 1e-12 && (proj.up.length() - 1.0).abs() < 1e-12,
            "{at}"
        );
        let root = &trace.samples[0].tree.nodes[0];
        assert!(
            proj.vector(root.direction).x > 0.0,
            "{at}: the primary ray runs right to left"
        );
        // The drawing plane holds the primary ray: the plane of incidence (or, for a miss, the ray and up).
        assert!(
            root.direction.normalize().dot(proj.toward_viewer()).abs() < 1e-12,
            "{at}"
        );
        if let Some(h) = &root.hit {
            assert!(
                h.shading_normal.dot(proj.toward_viewer()).abs() < 1e-12,
                "{at}"
            );
        }
    }
}

#[test]
fn labels_never_collide_and_each_touches_what_it_names() {
    let mut placed = 0;
    for (name, x, y, view) in cases() {
        let (scene, trace) = traced(name, x, y);
        for (w, h) in [(1200, 800), (600, 400)] {
            let options = Options {
                width: w,
                height: h,
                view,
                ..Options::default()
            };
            let drawn = draw_with_labels(&trace, &scene, &options).unwrap();
            let at = format!("{name} {x},{y} {view:?} {w}×{h}");
            placed += labels_keep_apart(&drawn, &at);
            // At the default size every label that must be there finds room.
            let lost = lost(&drawn);
            assert!(w < 1200 || lost.is_empty(), "{at}: no room for {lost:?}");
        }
    }
    assert!(placed > 200, "only {placed} labels placed");
}

/// The whole tree framed with its ticks, roots and step numbers, the most
/// labels a diagram writes, on pixels with deep trees and on plain ones: the
/// same promise holds.
#[test]
fn labels_keep_apart_with_the_whole_tree_its_ticks_roots_and_steps() {
    let mut placed = 0;
    let pixels = [
        ("whitted.json", 160, 120),
        ("whitted.json", 416, 209),
        ("whitted.json", 386, 242),
        ("whitted.json", 264, 200),
        ("whitted.json", 300, 290),
        ("nested.json", 320, 240),
        ("nested.json", 300, 200),
        ("spheres.json", 320, 240),
        ("ellipsoids.json", 320, 240),
        ("cones.json", 320, 240),
        ("polygons.json", 320, 240),
        ("gaspra.json", 320, 240),
    ];
    for (name, x, y) in pixels {
        let (scene, trace) = traced(name, x, y);
        for (w, h) in [(1200, 800), (600, 400)] {
            for fit in [Fit::Tree, Fit::Hits] {
                let options = Options {
                    width: w,
                    height: h,
                    fit,
                    ticks: true,
                    roots: true,
                    steps: true,
                    ..Options::default()
                };
                let drawn = draw_with_labels(&trace, &scene, &options).unwrap();
                let at = format!("{name} {x},{y} {fit:?} {w}×{h} ticks roots steps");
                placed += labels_keep_apart(&drawn, &at);
            }
        }
    }
    assert!(placed > 300, "only {placed} labels placed");
}

/// A small object in a crowd of labels still gets its name, with a leader
/// through a gap between them: lesson 10's glass ball, in the whole tree of
/// its deepest pixel with every optional label, had its name left out.
#[test]
fn a_small_object_in_a_crowd_finds_a_gap_for_its_name() {
    let (scene, trace) = traced("whitted.json", 416, 209);
    let options = Options {
        width: 1200,
        height: 800,
        fit: Fit::Tree,
        ticks: true,
        roots: true,
        steps: true,
        ..Options::default()
    };
    let drawn = draw_with_labels(&trace, &scene, &options).unwrap();
    labels_keep_apart(&drawn, "whitted.json 416,209 Tree 1200×800");
    let glass = drawn.labels.iter().find(|p| p.label.text == "glass");
    assert!(
        glass.is_some_and(|p| p.leader.is_some()),
        "'glass' is placed with a leader; left out: {:?}",
        lost(&drawn)
    );
}

/// Checks the diagram's promise for one figure: no label leaves the frame,
/// covers the legend or another label, and each touches what it names or has
/// a leader line to it. Returns how many labels were placed.
fn labels_keep_apart(drawn: &raytree::views::diagram::draw::Drawn, at: &str) -> usize {
    for (i, a) in drawn.labels.iter().enumerate() {
        let text = &a.label.text;
        assert!(
            drawn.frame.holds(&a.rect),
            "{at}: '{text}' leaves the frame"
        );
        assert!(
            !a.rect.overlaps(&drawn.legend),
            "{at}: '{text}' covers the legend"
        );
        for b in &drawn.labels[i + 1..] {
            assert!(
                !a.rect.overlaps(&b.rect),
                "{at}: '{text}' and '{}' overlap",
                b.label.text
            );
        }
        // A leader through another label's text collides with it as surely.
        for b in &drawn.labels {
            let through = |p: &raytree::figure::labels::Placed,
                           q: &raytree::figure::labels::Placed| {
                p.leader
                    .is_some_and(|[from, to]| q.rect.crossed_by(from, to))
            };
            assert!(
                std::ptr::eq(a, b) || !(through(a, b) || through(b, a)),
                "{at}: a leader runs through '{text}' or '{}'",
                b.label.text
            );
        }
        let clearance = match a.label.target {
            Target::Point { clearance, .. } => clearance,
            Target::Outline { .. } => 0.0,
        };
        // Touching: within its mark's clearance and the gap the placer leaves (a few
        // pixels) along each axis; a label at a corner position is that far in x and in y.
        let gap = (a.rect.min - a.anchor)
            .max(a.anchor - a.rect.max)
            .max(DVec2::ZERO)
            .max_element();
        let touches = gap <= clearance + 5.0;
        let led = a
            .leader
            .is_some_and(|[from, to]| to == a.anchor && a.rect.distance(from) <= 1.5);
        assert!(
            touches || led,
            "{at}: '{text}' floats free of what it names ({gap:.1} px away)"
        );
    }
    drawn.labels.len()
}

/// The labels other than the optional ones (ticks, roots, step numbers, a
/// boundary's indices) that found no room.
fn lost(drawn: &raytree::views::diagram::draw::Drawn) -> Vec<&str> {
    (drawn.left_out.iter())
        .filter(|l| !l.optional)
        .map(|l| l.text.as_str())
        .collect()
}

#[test]
fn slide_marks_carry_the_traces_numbers() {
    // Total internal reflection: the badge quotes θ₁ and the critical angle of the trace.
    let (scene, trace) = traced("whitted.json", 416, 209);
    let drawn = draw_with_labels(&trace, &scene, &Options::default()).unwrap();
    let tir = trace.samples[0]
        .tree
        .nodes
        .iter()
        .find(|n| {
            n.refracted.as_ref().is_some_and(|b| {
                b.outcome == raytree::tree::ray_tree::Branch::TotalInternalReflection
            })
        })
        .and_then(|n| n.hit.as_ref()?.refraction)
        .unwrap();
    let badge = format!(
        "total internal reflection: θ₁ = {} > critical angle {}",
        degrees(tir.theta1),
        degrees(tir.critical.unwrap())
    );
    let placed = drawn
        .labels
        .iter()
        .find(|p| p.label.text == badge)
        .expect("the badge");
    assert!(placed.label.boxed);
    // The README's caption of this figure quotes the same two angles.
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let quoted = format!(
        "at {}, beyond the critical angle of {}",
        degrees(tir.theta1),
        degrees(tir.critical.unwrap())
    );
    assert!(
        readme.replace('\n', " ").contains(&quoted),
        "README.md should say '{quoted}'"
    );
    let texts: Vec<&str> = drawn.labels.iter().map(|p| p.label.text.as_str()).collect();
    let first = trace.samples[0].tree.nodes[0].hit.as_ref().unwrap();
    let r = first.refraction.unwrap();
    for expected in [
        format!("θ₁ = θᵢ = {}", degrees(r.theta1)),
        format!("θ₂ = {}", degrees(r.theta2.unwrap())),
        "n₁ = 1".to_owned(),
        "n₂ = 1.5".to_owned(),
        "P1".to_owned(),
        "glass".to_owned(),
    ] {
        assert!(
            texts.contains(&expected.as_str()),
            "no label {expected:?} in {texts:?}"
        );
    }
    // A shadow's blocker gets a cross: dark ink where the shadow ray meets it.
    let (scene, trace) = traced("whitted.json", 168, 296);
    let options = Options::default();
    let lay = layout(&trace, &scene, &options).unwrap();
    let drawn = draw_with_labels(&trace, &scene, &options).unwrap();
    assert!(!lay.marks.blocked.is_empty());
    for b in &lay.marks.blocked {
        let at = drawn.figure.to_px(b.at);
        assert!(
            around(&drawn.figure, at, 1)
                .iter()
                .any(|&c| near(c, palette::INK, 40)),
            "no cross at the blocker {at}"
        );
    }
    assert!(drawn.legend_entries.iter().any(|e| e.contains("blocker")));
    // The legend names only what is drawn: the mirror pixel has no refracted ray.
    let (scene, trace) = traced("whitted.json", 264, 200);
    let drawn = draw_with_labels(&trace, &scene, &Options::default()).unwrap();
    assert!(drawn.legend_entries.contains(&"reflected ray".to_owned()));
    assert!(
        !drawn.legend_entries.iter().any(|e| e.contains("refracted")),
        "{:?}",
        drawn.legend_entries
    );
}

#[test]
fn ticks_and_step_numbers_follow_the_trace() {
    let (scene, trace) = traced("whitted.json", 416, 209);
    let options = Options {
        ticks: true,
        steps: true,
        ..Options::default()
    };
    let lay = layout(&trace, &scene, &options).unwrap();
    // The primary ray's t = 1 tick lies on the image plane.
    let root = &trace.samples[0].tree.nodes[0];
    let one = lay.proj.point(root.origin + root.direction);
    assert!(
        lay.marks
            .ticks
            .iter()
            .any(|t| t.label == "t = 1" && t.at.abs_diff_eq(one, 1e-9))
    );
    // Step numbers are those of `raytree trace --steps`: the primary ray's spawn is step 2.
    assert!(lay.marks.steps.iter().any(|s| s.number == 2));
    let steps = trace.steps(0);
    for s in &lay.marks.steps {
        assert!(s.number >= 1 && s.number <= steps.len());
    }
}

/// Seen from the side, a corner pixel's ray ends inside its panel: the
/// panel's bottom rows (the side view is the page's lower left) hold none of
/// the ray's blue, which ran out of the panel before.
#[test]
fn the_side_view_keeps_a_corner_pixels_ray_in_its_panel() {
    let (_, trace) = traced("whitted.json", 0, 479);
    let cam = raytree::views::diagram::camera_view::draw(&trace, 1200, 800).unwrap();
    let blue = raytree::figure::pen::palette::PRIMARY;
    let at = |x: u32, y: u32| pixel(&cam, DVec2::new(f64::from(x), f64::from(y)));
    // The panel's bottom border: the lowest row darker than the paper in
    // column 300, which no label or ray reaches that low.
    let border = (600..800)
        .rev()
        .find(|&y| at(300, y).iter().all(|&v| v < 230))
        .expect("the side panel's border");
    for y in border - 6..border {
        for x in 0..600 {
            // 60 levels: the ray's antialiased edge on the light panel.
            assert!(
                !near(at(x, y), blue, 60),
                "the ray's blue at {x},{y}, by the border at row {border}"
            );
        }
    }
}

#[test]
fn the_camera_and_object_space_views() {
    let (scene, trace) = traced("whitted.json", 416, 209);
    let cam = raytree::views::diagram::camera_view::draw(&trace, 1200, 800).unwrap();
    assert_eq!(cam.size(), (1200, 800));
    assert!(
        cam.png()
            == raytree::views::diagram::camera_view::draw(&trace, 1200, 800)
                .unwrap()
                .png()
    );
    let ray = raytree::tree::record::ray(
        &scene,
        SceneSource::new("whitted.json", ""),
        raytree::math::ray::Ray::new(glam::DVec3::new(0.0, 1.0, 5.0), glam::DVec3::NEG_Z),
    )
    .unwrap();
    assert!(raytree::views::diagram::camera_view::draw(&ray, 1200, 800).is_err());
    // The object view needs a transformed sphere: the Whitted scene has none.
    let Err(err) = raytree::views::diagram::object_view::draw(&trace, &scene, &Options::default())
    else {
        panic!("the Whitted scene has no transformed sphere to draw in its own space");
    };
    assert!(err.contains("transformed sphere"), "{err}");
    let (scene, trace) = traced("ellipsoids.json", 320, 240);
    let fig =
        raytree::views::diagram::object_view::draw(&trace, &scene, &Options::default()).unwrap();
    assert_eq!(fig.size(), (1200, 800));
}
