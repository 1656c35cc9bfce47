//! Lesson figures that must show what their captions and text say (issue 26):
//! each test reads the figure's own command from the lesson's spec, draws it
//! as the book does, and checks the claim the caption makes.

use std::path::Path;

use glam::{DVec2, DVec3};
use raytree::course::spec;
use raytree::figure::canvas::Figure;
use raytree::figure::pen::palette;
use raytree::math::ray::Ray;
use raytree::methods::Accel;
use raytree::scene::source::SceneSource;
use raytree::trace::aov::Aov;
use raytree::trace::progress::Progress;
use raytree::tree::document::TraceDocument;
use raytree::views::diagram::arrange::layout;
use raytree::views::diagram::options::{Fit, Options};
use raytree::views::diagram::projection::View;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A figure's command line (after `raytree`) and caption, from its lesson.
fn figure(lesson: &str, name: &str) -> (Vec<String>, String) {
    let spec = spec::load(&root().join("lessons").join(lesson).join("lesson.toml")).unwrap();
    let f = &spec.figures[name];
    (f.command.args.clone(), f.caption.clone())
}

fn value<'a>(args: &'a [String], flag: &str) -> Option<&'a str> {
    let i = args.iter().position(|a| a == flag)?;
    args.get(i + 1).map(String::as_str)
}

fn triple(s: &str) -> DVec3 {
    let v: Vec<f64> = s.split(',').map(|x| x.parse().unwrap()).collect();
    DVec3::new(v[0], v[1], v[2])
}

/// The trace a diagram command draws (its scene, and `--pixel` or `--ray`),
/// with the diagram options the test needs from its flags.
fn traced(args: &[String]) -> (raytree::scene::Scene, TraceDocument, Options) {
    let path = &args[1];
    let scene = raytree::scene::loader::load(&root().join(path)).unwrap();
    let source = SceneSource::new(path, "");
    let trace = if let Some(p) = value(args, "--pixel") {
        let (x, y) = p.split_once(',').unwrap();
        raytree::tree::record::pixel(&scene, source, x.parse().unwrap(), y.parse().unwrap(), None)
            .unwrap()
    } else {
        let (s, c) = value(args, "--ray").unwrap().split_once(':').unwrap();
        raytree::tree::record::ray(&scene, source, Ray::new(triple(s), triple(c))).unwrap()
    };
    let has = |f: &str| args.iter().any(|a| a == f);
    let options = Options {
        view: match value(args, "--view") {
            Some("side") => View::Side,
            Some("front") => View::Front,
            _ => View::Auto,
        },
        fit: if value(args, "--fit") == Some("tree") {
            Fit::Tree
        } else {
            Fit::Hits
        },
        depth: value(args, "--depth").map(|d| d.parse().unwrap()),
        shadows: !has("--no-shadows"),
        ticks: has("--ticks"),
        roots: has("--roots"),
        ..Options::default()
    };
    (scene, trace, options)
}

#[test]
fn lesson_4_ticks_every_whole_t_as_its_caption_says() {
    let (args, caption) = figure("04-rays", "glass");
    assert!(
        caption.contains("a tick at every whole step of t"),
        "{caption}"
    );
    let (scene, trace, options) = traced(&args);
    let lay = layout(&trace, &scene, &options).unwrap();
    let ray = &trace.samples[0].tree.nodes[0];
    let t_hit = ray.hit.as_ref().unwrap().t;
    // Every whole t short of the hit, each where S + t·c projects (the same
    // arithmetic as the figure's, so to rounding).
    let whole: Vec<f64> = (1..).map(f64::from).take_while(|&t| t < t_hit).collect();
    assert!(whole.len() >= 5, "the glass ball is past t = 5: {t_hit}");
    let labels: Vec<&str> = lay.marks.ticks.iter().map(|t| t.label.as_str()).collect();
    let want: Vec<String> = whole.iter().map(|t| format!("t = {t}")).collect();
    assert_eq!(labels, want);
    for (tick, t) in lay.marks.ticks.iter().zip(&whole) {
        let at = lay.proj.point(ray.origin + t * ray.direction);
        assert!(tick.at.abs_diff_eq(at, 1e-9), "t = {t}");
    }
}

#[test]
fn lesson_5_marks_the_exit_root_and_the_rejected_negative_root() {
    for (name, t, words) in [("hit", 6.0, "not the first"), ("inside", -1.0, "rejected")] {
        let (args, _) = figure("05-sphere", name);
        assert!(args.iter().any(|a| a == "--roots"), "{name}: {args:?}");
        let (scene, trace, options) = traced(&args);
        let lay = layout(&trace, &scene, &options).unwrap();
        let ray = &trace.samples[0].tree.nodes[0];
        assert_eq!(lay.marks.roots.len(), 1, "{name}: {:?}", lay.marks.roots);
        let mark = &lay.marks.roots[0];
        assert!(
            mark.label.starts_with(&format!("t = {t}:")) && mark.label.contains(words),
            "{name}: {}",
            mark.label
        );
        // The unit sphere's roots are whole numbers here: exact to rounding.
        let at = lay.proj.point(ray.origin + t * ray.direction);
        assert!(mark.at.abs_diff_eq(at, 1e-9), "{name}");
        // The negative root lies behind the start, against the ray's direction.
        let along = lay.proj.vector(ray.direction);
        let start = lay.proj.point(ray.origin);
        assert_eq!((mark.at - start).dot(along) < 0.0, t < 0.0, "{name}");
    }
}

#[test]
fn lesson_5_the_grazing_normal_points_up_out_of_the_sphere() {
    let (args, caption) = figure("05-sphere", "graze");
    assert!(caption.contains("pointing up"), "{caption}");
    let (scene, trace, options) = traced(&args);
    let lay = layout(&trace, &scene, &options).unwrap();
    assert_eq!(lay.hits.len(), 1);
    // The side view draws world y up; the outward normal at the top is +y.
    let n = lay.hits[0].normal;
    assert!(n.y > 0.999 && n.x.abs() < 1e-9, "{n}");
}

#[test]
fn lesson_2_draws_the_lamp_mirror_floor_path_to_the_pixels_floor_point() {
    let (args, caption) = figure("02-sources", "room");
    assert!(caption.contains("lamp → mirror → floor"), "{caption}");
    let (scene, trace, options) = traced(&args);
    let nodes = &trace.samples[0].tree.nodes;
    let lamp = scene.lights[0].position;
    assert!(
        nodes[0].origin.abs_diff_eq(lamp, 1e-12),
        "the ray starts at the lamp"
    );
    let first = nodes[0].hit.as_ref().unwrap();
    assert_eq!(first.name, "ceiling");
    let down = nodes.iter().find(|n| n.depth == 2).unwrap();
    let floor = down.hit.as_ref().unwrap();
    assert_eq!(floor.name, "floor");
    // The point pixel 160,225 sees: the direction is typed to four digits, so
    // the two agree to a few thousandths over a path of length about 8.
    let pixel_args = ["diagram", &args[1], "--pixel", "160,225"].map(str::to_owned);
    let (_, pixel, _) = traced(&pixel_args);
    let seen = pixel.samples[0].tree.nodes[0].hit.as_ref().unwrap().point;
    assert!(
        floor.point.abs_diff_eq(seen, 2e-3),
        "{} vs {seen}",
        floor.point
    );
    // There the shadow ray to the lamp is blocked by the wall, and the figure
    // draws the reflected ray down and the blocker's ×.
    assert!(matches!(
        down.shadow_rays[0].outcome,
        raytree::tree::ray_tree::ShadowOutcomeRecord::Blocked { object, .. }
            if scene.objects[object].name == "wall"
    ));
    let lay = layout(&trace, &scene, &options).unwrap();
    assert_eq!(lay.marks.blocked.len(), 1);
    assert!(lay.segments.iter().any(|s| nodes[s.node].depth == 2));
}

#[test]
fn lesson_12_the_heat_maps_title_names_the_method_used() {
    let path = root().join("scenes/spheres.json");
    for (accel, says, not) in [
        (Accel::None, "--accel none", "bvh"),
        (Accel::Auto, "--accel auto: bvh", "none"),
        (Accel::Bvh, "--accel bvh", "none"),
    ] {
        let mut scene = raytree::scene::loader::load(&path).unwrap();
        scene.settings.accel = accel;
        scene.settings.width = 8;
        scene.settings.height = 6;
        let map =
            raytree::trace::aov_render::render_aov(&scene, Aov::Tests, &Progress::QUIET).unwrap();
        assert!(
            map.title.contains(says) && !map.title.contains(not),
            "{accel:?}: {}",
            map.title
        );
    }
}

/// Whether some pixel within `r` of `p` is within `tol` of `want` in each
/// channel (thin lines are antialiased, so never quite their pen's color).
fn drawn_near(fig: &Figure, p: DVec2, r: i32, want: [u8; 3], tol: u8) -> bool {
    let (w, h) = fig.size();
    let rgb = fig.rgb();
    (-r..=r)
        .flat_map(|dy| (-r..=r).map(move |dx| (dx, dy)))
        .any(|(dx, dy)| {
            let (x, y) = (p.x as i32 + dx, p.y as i32 + dy);
            if x < 0 || y < 0 || x >= w as i32 || y >= h as i32 {
                return false;
            }
            let i = 3 * (y as usize * w as usize + x as usize);
            (0..3).all(|k| rgb[i + k].abs_diff(want[k]) <= tol)
        })
}

#[test]
fn lesson_6_object_space_has_axes_reads_the_usual_way_and_shows_both_normals() {
    let (args, _) = figure("06-transforms", "shoulder");
    let (scene, trace, options) = traced(&args);
    let drawn =
        raytree::views::diagram::object_view::draw_marked(&trace, &scene, &options).unwrap();
    // The ray lies in z' = 0: x' and y' are drawn, full length, as a front view.
    let names: Vec<&str> = drawn.axes.iter().map(|a| a.0.as_str()).collect();
    assert_eq!(names.len(), 2, "{names:?}");
    assert!(names.contains(&"x'") && names.contains(&"y'"), "{names:?}");
    let axis = |name: &str| {
        let (_, from, to) = drawn.axes.iter().find(|a| a.0 == name).unwrap();
        (*from, *to - *from)
    };
    let (center, x) = axis("x'");
    let (_, y) = axis("y'");
    // Pixels run right and down: +x' right, +y' up.
    assert!(x.x > 0.0 && x.y.abs() < 1e-6 * x.x, "{x}");
    assert!(y.y < 0.0 && y.x.abs() < 1e-6 * -y.y, "{y}");
    // Past the sphere's outline (the tips are at 1.4 radii), on white paper,
    // a thin dark line: its 1.2 pixels may straddle two rows at half
    // strength each (about 137 of 255), hence the wide tolerance.
    for (name, from, to) in &drawn.axes {
        let p = *from + (*to - *from) * 0.85;
        assert!(
            drawn_near(&drawn.figure, p, 2, palette::INK, 125),
            "{name} at {p}"
        );
    }
    // P' = (0.708, 0.706, 0): up and to the right of the center.
    let hit = trace.samples[0].tree.nodes[0].hit.as_ref().unwrap();
    let p = hit.object_point.unwrap();
    assert!(p.x > 0.5 && p.y > 0.5, "{p}");
    assert!(drawn.hit.x > center.x && drawn.hit.y < center.y);
    // Both normals: N = (M⁻¹)ᵀn' and the point rule's M·n', apart by the
    // angle the trace reports, each drawn in its color past the hit's dot.
    let [right, wrong] = drawn.normals.unwrap();
    let angle = (right.1 - right.0)
        .angle_to(wrong.1 - wrong.0)
        .abs()
        .to_degrees();
    let off = raytree::views::explain::normal_like_point_error(hit).unwrap();
    assert!(
        (angle - off).abs() < 0.5,
        "drawn {angle}° apart, the trace says {off}°"
    );
    let along = |(a, b): (DVec2, DVec2)| a + (b - a) * 0.6;
    assert!(drawn_near(
        &drawn.figure,
        along(right),
        2,
        palette::NORMAL,
        40
    ));
    assert!(drawn_near(
        &drawn.figure,
        along(wrong),
        2,
        palette::SHADOW_BLOCKED,
        40
    ));
}
