//! The inspector as a teacher: stepping reveals only what the algorithm has
//! computed, `f` finds the pixel it names, what-if edits re-trace and undo
//! exactly, a guided step-through quotes the trace, and the screen fits the
//! common terminal sizes (snapshots at 80×24 and 160×48).

use crate::inspector::drive::{key, keys, screen, whitted_at};
use std::path::Path;

use ratatui::crossterm::event::KeyCode;
use raytree::inspector::{App, Item};
use raytree::scene::source::SceneSource;
use raytree::tree::ray_tree::Branch;
use raytree::tree::record;
use raytree::tree::steps::StepKind;

/// True when the tree at `416,209` (the README's total internal reflection)
/// has a TIR branch: an independent check on the recorded tree.
fn has_tir(x: u32, y: u32) -> bool {
    let scene = raytree::scene::loader::whitted();
    let t = record::pixel(&scene, SceneSource::new("", ""), x, y, None).unwrap();
    t.samples[0].tree.nodes.iter().any(|n| {
        n.refracted
            .as_ref()
            .is_some_and(|b| b.outcome == Branch::TotalInternalReflection)
    })
}

#[test]
fn stepping_shows_exactly_the_rays_and_colors_computed_so_far() {
    let mut app = whitted_at((416, 209));
    let steps = app.steps().to_vec();
    let tree = app.trace().unwrap().samples[0].tree.clone();
    // Independently of the inspector: the step at which each ray is spawned
    // and the step at which its color is returned.
    let spawned_at = |n: usize| {
        steps
            .iter()
            .position(|s| s.node == n && s.kind == StepKind::Spawn)
            .unwrap()
    };
    // A hit's color exists once combined; a miss's (the background) once returned.
    let returned_at = |n: usize| {
        steps
            .iter()
            .position(|s| s.node == n && matches!(s.kind, StepKind::Combine | StepKind::Return))
            .unwrap()
    };
    key(&mut app, KeyCode::Char('e')); // every ray open, so every spawned ray is listed
    for s in 0..steps.len() {
        app.go_to_step(s);
        app.expand_all();
        let listed: Vec<usize> = app
            .items()
            .iter()
            .filter_map(|&(i, _)| match i {
                Item::Ray(n) => Some(n),
                Item::Shadow(..) => None,
            })
            .collect();
        let expected: Vec<usize> = {
            let mut v: Vec<usize> = (0..tree.nodes.len())
                .filter(|&n| spawned_at(n) <= s)
                .collect();
            // The tree pane lists depth first, which is the order of spawning.
            v.sort_by_key(|&n| spawned_at(n));
            v
        };
        assert_eq!(listed, expected, "rays listed at step {}", s + 1);
        let shown = app.revealed();
        for n in 0..tree.nodes.len() {
            assert_eq!(
                shown.node(n).color,
                returned_at(n) <= s,
                "ray {n}'s color at step {}",
                s + 1
            );
        }
    }
}

#[test]
fn the_numbers_pane_never_gives_the_color_away_before_it_is_computed() {
    let mut app = whitted_at((416, 209));
    let color = raytree::views::numbers::color(app.trace().unwrap().color);
    let combine = app
        .steps()
        .iter()
        .position(|s| s.node == 0 && s.kind == StepKind::Combine)
        .unwrap();
    // Step 8 is the first shadow ray: the selection moves to its line.
    app.go_to_step(7);
    assert_eq!(app.selected_item(), Some(Item::Shadow(0, 0)));
    app.go_to_step(combine - 1);
    app.select_node(0);
    let before = screen(&mut app, 160, 48);
    assert!(
        !before.contains(&format!("= {color}")),
        "the primary ray's color {color} shows before its step:\n{before}"
    );
    app.go_to_step(combine);
    let at = screen(&mut app, 160, 48);
    assert!(
        at.contains(&format!("= {color}")),
        "the primary ray's color {color} shows at its step:\n{at}"
    );
    assert!(at.contains("step") && at.contains("in primary"), "{at}");
}

#[test]
fn find_goes_to_the_first_total_internal_reflection_in_reading_order() {
    let mut app = whitted_at((0, 0));
    assert!(!has_tir(0, 0));
    key(&mut app, KeyCode::Char('f'));
    let found = app.cursor();
    assert!(
        has_tir(found.0, found.1),
        "{found:?} has a total internal reflection"
    );
    // No pixel before it (in reading order) has one: checked on the recorded trees.
    let (w, _) = app.image_size();
    let before = (found.1 * w + found.0) as usize;
    let first = (1..before)
        .map(|i| ((i as u32) % w, (i as u32) / w))
        .find(|&(x, y)| has_tir(x, y));
    assert_eq!(first, None, "a total internal reflection before {found:?}");
    // F moves on to the next kind of feature; each find says what it found.
    key(&mut app, KeyCode::Char('F'));
    assert!(
        app.message().contains("blocked shadow ray"),
        "{}",
        app.message()
    );
}

#[test]
fn what_if_ior_1_removes_the_bending_and_undo_restores_the_tree_exactly() {
    let mut app = whitted_at((416, 209));
    let original = app.trace().cloned().unwrap();
    let nodes = &original.samples[0].tree.nodes;
    let refracted = nodes[0].refracted.as_ref().unwrap().node.unwrap();
    let bent = nodes[refracted].direction;
    let incoming = nodes[0].direction.normalize();
    assert!(
        bent.angle_between(incoming) > 0.05,
        "the glass bends the ray"
    );

    key(&mut app, KeyCode::Char('m'));
    keys(&mut app, "ior=1.0");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.edits(), vec!["glass: ior=1.0".to_owned()]);
    let edited = app.trace().cloned().unwrap();
    let nodes = &edited.samples[0].tree.nodes;
    let refracted = nodes[0].refracted.as_ref().unwrap().node.unwrap();
    let straight = nodes[refracted].direction;
    // Snell's law with n₁ = n₂ keeps the direction; 1e-12 allows the rounding
    // of cos θ₂ = √(1 − sin²θ₁) against cos θ₁ in the vector form.
    assert!(
        straight.angle_between(incoming) < 1e-12,
        "ior 1.0 leaves the ray straight: {straight} vs {incoming}"
    );
    assert_ne!(edited.color, original.color);
    let text = screen(&mut app, 160, 48);
    assert!(text.contains("what if") && text.contains(" → "), "{text}");

    key(&mut app, KeyCode::Char('u'));
    assert_eq!(
        app.trace().unwrap(),
        &original,
        "undo gives the tree as loaded, bit for bit"
    );
    assert!(app.edits().is_empty());
}

#[test]
fn what_if_writes_the_edited_scene_and_it_reads_back_as_edited() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("whitted.json");
    std::fs::write(&file, raytree::scene::loader::WHITTED).unwrap();
    let (scene, source) = raytree::scene::source::load(Some(&file)).unwrap();
    let mut app = App::new(scene, source, Some((416, 209)), false);
    for typed in ["ior=1.0", "color=1,0,0", "max_depth=3"] {
        key(&mut app, KeyCode::Char('m'));
        keys(&mut app, typed);
        key(&mut app, KeyCode::Enter);
    }
    assert_eq!(app.edits().len(), 3, "{}", app.message());
    let out = dir.path().join("edited.json");
    key(&mut app, KeyCode::Char('w'));
    // The prompt offers a name beside the scene: type another.
    for _ in 0..200 {
        key(&mut app, KeyCode::Backspace);
    }
    keys(&mut app, out.to_str().unwrap());
    key(&mut app, KeyCode::Enter);
    assert!(app.message().starts_with("wrote "), "{}", app.message());
    let (written, _) = raytree::scene::source::load(Some(&out)).unwrap();
    let edited = app.scene().unwrap();
    assert_eq!(written.objects, edited.objects);
    assert_eq!(written.materials, edited.materials);
    assert_eq!(written.settings.max_depth, 3);
    let glass = written
        .materials
        .iter()
        .find(|m| m.name == "glass")
        .unwrap();
    assert_eq!(glass.ior, 1.0);
    assert_eq!(
        glass.pattern,
        raytree::shading::material::Pattern::Solid(glam::DVec3::X)
    );
}

#[test]
fn what_if_refuses_unknown_fields_and_bad_values_in_one_line() {
    let mut app = whitted_at((416, 209));
    let original = app.trace().cloned().unwrap();
    for typed in ["colour=1", "ior=-2", "ior"] {
        key(&mut app, KeyCode::Char('m'));
        keys(&mut app, typed);
        key(&mut app, KeyCode::Enter);
        assert!(
            !app.message().is_empty() && !app.message().contains('\n'),
            "{typed}: {:?}",
            app.message()
        );
        assert_eq!(app.trace().unwrap(), &original, "{typed} changed nothing");
    }
}

#[test]
fn a_guided_step_through_moves_between_its_stops_and_quotes_the_trace() {
    let steps = whitted_at((416, 209)).steps().to_vec();
    let app = whitted_at((416, 209));
    let nodes = &app.trace().unwrap().samples[0].tree.nodes;
    let tir = steps
        .iter()
        .position(|s| {
            s.kind == StepKind::Refract
                && nodes[s.node]
                    .refracted
                    .as_ref()
                    .is_some_and(|b| b.outcome == Branch::TotalInternalReflection)
        })
        .unwrap();
    let script = raytree::course::guide::parse(
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/tir.toml")),
        &format!(
            "title = \"TIR\"\nscene = \"../scenes/whitted.json\"\npixel = [416, 209]\n\
             [[stop]]\nstep = 1\nsay = \"c = {{c}}\"\n\
             [[stop]]\nstep = {}\nsay = \"θ₁ = {{theta1}} beyond {{critical}}\"\n",
            tir + 1
        ),
    )
    .unwrap();
    let mut app = whitted_at((0, 0));
    app.follow(script).unwrap();
    assert_eq!((app.cursor(), app.step()), ((416, 209), Some(0)));
    let first = screen(&mut app, 80, 24);
    assert!(first.contains("TIR · stop 1/2: c = 416"), "{first}");
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(app.step(), Some(tir));
    let second = screen(&mut app, 80, 24);
    assert!(second.contains("stop 2/2: θ₁ = "), "{second}");
    assert!(second.contains("total internal reflection"), "{second}");
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(app.step(), Some(tir), "the last stop stays");
    key(&mut app, KeyCode::Char('p'));
    assert_eq!(app.step(), Some(0));
    // ] and [ still step one algorithm step at a time between the stops.
    key(&mut app, KeyCode::Char(']'));
    assert_eq!(app.step(), Some(1));
}

/// The screens at the two sizes the issue names, compared with committed
/// snapshots (`RAYTREE_BLESS=1` rewrites them after a deliberate change).
#[test]
fn screens_at_80x24_and_160x48_match_their_snapshots() {
    for (w, h) in [(80u16, 24u16), (160, 48)] {
        let mut app = whitted_at((416, 209));
        // Step to the total internal reflection's color sum, the deepest point of the story.
        let combine = app
            .steps()
            .iter()
            .position(|s| s.node == 0 && s.kind == StepKind::Combine)
            .unwrap();
        app.go_to_step(combine);
        let text = screen(&mut app, w, h);
        for line in text.lines() {
            assert!(line.chars().count() <= usize::from(w), "{line}");
        }
        assert!(
            text.contains("color = local"),
            "{w}×{h}: the color sum is in view:\n{text}"
        );
        let path = format!(
            "{}/tests/inspector/whitted-416-209-{w}x{h}.txt",
            env!("CARGO_MANIFEST_DIR")
        );
        if std::env::var_os("RAYTREE_BLESS").is_some() {
            std::fs::create_dir_all(Path::new(&path).parent().unwrap()).unwrap();
            std::fs::write(&path, &text).unwrap();
            continue;
        }
        let expected = std::fs::read_to_string(&path).unwrap_or_else(|_| {
            panic!("{path} is missing: RAYTREE_BLESS=1 cargo test --release inspector_teaching")
        });
        assert!(
            text == expected,
            "{w}×{h} screen differs from {path} (RAYTREE_BLESS=1 after a deliberate change):\n{text}"
        );
    }
}

/// A what-if while guided tells the stops again from the changed trace: the
/// stop shows the new numbers, and a stop the new trace cannot tell says so
/// instead of quoting the old trace.
#[test]
fn a_what_if_while_guided_retells_the_stops_from_the_new_trace() {
    let app = whitted_at((416, 209));
    let steps = app.steps().to_vec();
    let entering = steps
        .iter()
        .position(|s| s.node == 0 && s.kind == StepKind::Refract)
        .unwrap();
    let theta1 = app.trace().unwrap().samples[0].tree.nodes[0]
        .hit
        .as_ref()
        .and_then(|h| h.refraction.as_ref())
        .unwrap()
        .theta1;
    let script = raytree::course::guide::parse(
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/glass.toml")),
        &format!(
            "title = \"Glass\"\nscene = \"../scenes/whitted.json\"\npixel = [416, 209]\n\
             [[stop]]\nstep = {}\nsay = \"n2 = {{n2}}, theta2 = {{theta2}}\"\n\
             [[stop]]\nstep = {}\nsay = \"the pixel is {{color}}\"\n",
            entering + 1,
            steps.len()
        ),
    )
    .unwrap();
    let mut app = whitted_at((0, 0));
    app.follow(script).unwrap();
    let before = screen(&mut app, 160, 48);
    assert!(
        before.contains("Glass · stop 1/2: n2 = 1.5, theta2 = "),
        "{before}"
    );

    key(&mut app, KeyCode::Char('m'));
    keys(&mut app, "ior=1.33");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.edits(), vec!["glass: ior=1.33".to_owned()]);
    assert_eq!(app.step(), Some(entering), "the stop's step is shown again");
    let after = screen(&mut app, 160, 48);
    let said = after
        .lines()
        .find_map(|l| l.split("Glass · stop 1/2: ").nth(1))
        .unwrap_or_else(|| panic!("{after}"));
    assert!(said.starts_with("n2 = 1.33, theta2 = "), "{said}");
    // Snell's law from the unchanged incoming angle, independently of the
    // tracer: sin θ₂ = sin θ₁ / 1.33 (θ₁ recorded in degrees). The stop
    // prints 4 significant digits, so 0.01° is a few units of its last digit.
    let expected = (theta1.to_radians().sin() / 1.33).asin().to_degrees();
    let shown: f64 = said["n2 = 1.33, theta2 = ".len()..]
        .trim_end_matches('°')
        .parse()
        .unwrap_or_else(|_| panic!("{said}"));
    assert!((shown - expected).abs() < 0.01, "{shown} vs {expected}");

    // One bounce fewer than the last stop's step: the stop says it is gone.
    key(&mut app, KeyCode::Char('m'));
    keys(&mut app, "max_depth=1");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.edits().len(), 2, "{}", app.message());
    assert!(app.steps().len() < steps.len());
    key(&mut app, KeyCode::Char('n'));
    let gone = screen(&mut app, 160, 48);
    assert!(
        gone.contains(&format!("this stop's step {} is gone", steps.len()))
            && !gone.contains("the pixel is"),
        "{gone}"
    );
}
