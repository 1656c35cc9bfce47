//! The inspector's work for a key does not grow with the scene: what it makes
//! of all the objects (the hierarchy) is made once, and a key costs what its
//! pixel and its panes cost. With a million objects each key took 4–9 s
//! (issue 29). Counted, not timed: the counts are exact on any machine.

use std::path::Path;

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use raytree::inspector::{App, draw, tick};
use raytree::trace::accelerator::Accelerator;

/// An inspector on `scenes/spheres.json` (2,001 objects: it has a hierarchy),
/// no worker thread, and a way to press a key and draw the frame after it.
fn spheres(start: Option<(u32, u32)>) -> App {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/spheres.json");
    let (scene, source) = raytree::scene::source::load(Some(&path)).unwrap();
    assert!(scene.objects.len() > 2000);
    App::new(scene, source, start, false)
}

fn press(app: &mut App, terminal: &mut Terminal<TestBackend>, code: KeyCode) {
    app.on_key(KeyEvent::new(code, KeyModifiers::NONE));
    frame(app, terminal);
}

fn frame(app: &mut App, terminal: &mut Terminal<TestBackend>) {
    tick(app, Rect::new(0, 0, 160, 48));
    app.render_picture_now();
    terminal.draw(|f| draw(f, app)).unwrap();
}

/// Every kind of key that traces, scans or re-renders: the arrows (a new
/// pixel), stepping, the tree, zoom, find and overlays (a scan of the image),
/// the next sample, a what-if edit and its undo.
const KEYS: &[KeyCode] = &[
    KeyCode::Right,
    KeyCode::Down,
    KeyCode::Left,
    KeyCode::Char('n'),
    KeyCode::Char('n'),
    KeyCode::Char('p'),
    KeyCode::Char('x'),
    KeyCode::Tab,
    KeyCode::Down,
    KeyCode::Enter,
    KeyCode::Char('e'),
    KeyCode::Tab,
    KeyCode::Char('+'),
    KeyCode::Char('-'),
    KeyCode::Char('f'),
    KeyCode::Char('F'),
    KeyCode::Char('o'),
    KeyCode::Char('s'),
    KeyCode::Char('m'),
    KeyCode::Char('m'),
    KeyCode::Char('a'),
    KeyCode::Char('x'),
    KeyCode::Char('_'),
    KeyCode::Char('d'),
    KeyCode::Char('e'),
    KeyCode::Char('p'),
    KeyCode::Char('t'),
    KeyCode::Char('h'),
    KeyCode::Char('='),
    KeyCode::Char('3'),
    KeyCode::Enter,
    KeyCode::Right,
    KeyCode::Char('u'),
];

#[test]
fn the_hierarchy_is_built_once_and_no_key_builds_it_again() {
    let built = Accelerator::built_on_this_thread;
    let at_start = built();
    // Starting on the pixel worth a look scans the image and traces that pixel.
    let mut app = spheres(None);
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    frame(&mut app, &mut terminal);
    assert_eq!(
        built() - at_start,
        1,
        "the first frame builds the scene's hierarchy once"
    );
    let before = built();
    for &code in KEYS {
        press(&mut app, &mut terminal, code);
        assert_eq!(
            built(),
            before,
            "{code:?} built a hierarchy again (message: {})",
            app.message()
        );
    }
    // The keys did what they say (else the count above proves nothing).
    assert!(app.message().contains("as loaded"), "{}", app.message());
}

#[test]
fn the_diagram_lays_out_the_objects_the_rays_met_not_every_object() {
    let mut app = spheres(None);
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    frame(&mut app, &mut terminal);
    for code in [KeyCode::Null, KeyCode::Char('n'), KeyCode::Right] {
        press(&mut app, &mut terminal, code);
        let trace = app.trace().unwrap();
        let tree = &trace.samples[0].tree;
        // What the rays name: the objects tested (planes by every ray,
        // spheres where the hierarchy led, the hit among them), and for each
        // shadow ray its blocker and the object it tried first.
        let mut named: Vec<usize> = tree
            .nodes
            .iter()
            .flat_map(|n| n.tests.iter().map(|t| t.object))
            .collect();
        named.sort_unstable();
        named.dedup();
        let shadow_rays: usize = tree.nodes.iter().map(|n| n.shadow_rays.len()).sum();
        let lay = app.diagram().unwrap();
        assert!(
            !named.is_empty() && lay.objects.len() <= named.len() + 2 * shadow_rays,
            "{code:?}: {} of the scene's {} objects laid out, for rays that named {}",
            lay.objects.len(),
            app.scene().unwrap().objects.len(),
            named.len()
        );
        // Every object hit is drawn.
        for n in tree.nodes.iter().filter_map(|n| n.hit.as_ref()) {
            assert!(lay.object(n.object).is_some(), "{code:?}: '{}'", n.name);
        }
    }
}

#[test]
fn every_trace_shares_the_object_list_made_when_the_scene_was_loaded() {
    let mut app = spheres(Some((320, 240)));
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    frame(&mut app, &mut terminal);
    // Kept alive, so a list made again could not take the same memory.
    let first = app.trace().unwrap().clone();
    for code in [KeyCode::Right, KeyCode::Down, KeyCode::Left] {
        press(&mut app, &mut terminal, code);
        let now = app.trace().unwrap();
        assert_ne!(now.pixel, first.pixel, "{code:?} traced another pixel");
        assert_eq!(now.objects.len(), 2001);
        assert!(
            std::ptr::eq(now.objects.as_ptr(), first.objects.as_ptr()),
            "{code:?}: the trace made its {} objects' entries again",
            now.objects.len()
        );
    }
}

#[test]
fn a_what_if_edit_reads_the_materials_again_not_the_objects() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("spheres.json");
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/spheres.json"))
            .unwrap();
    std::fs::write(&file, &text).unwrap();
    let (scene, source) = raytree::scene::source::load(Some(&file)).unwrap();
    let mut app = App::new(scene, source, Some((320, 240)), false);
    // Were the objects read again, this one would refuse the edit.
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    json["objects"] = serde_json::json!([{ "sphere": { "center": [0, 0, 0], "radius": -1 } }]);
    std::fs::write(&file, json.to_string()).unwrap();
    for c in "mmax_depth=2".chars() {
        app.on_key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE));
    }
    app.on_key(KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE));
    assert_eq!(
        app.message(),
        "what if max_depth=2  (u: undo all, w: write)"
    );
    let scene = app.scene().unwrap();
    assert_eq!((scene.objects.len(), scene.settings.max_depth), (2001, 2));
}

#[test]
fn finding_scans_the_image_beside_the_keys_and_jumps_when_the_scan_arrives() {
    // Without a worker the scan is made here and now: where `F` (a blocked
    // shadow ray) goes.
    let mut here = spheres(Some((0, 0)));
    here.on_key(KeyEvent::new(KeyCode::Char('F'), KeyModifiers::NONE));
    let (want, told) = (here.cursor(), here.message().to_owned());
    assert!(
        told.starts_with("found: blocked") && want != (0, 0),
        "{told}"
    );

    // The live inspector: the key returns before a single pixel is scanned.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/spheres.json");
    let (scene, source) = raytree::scene::source::load(Some(&path)).unwrap();
    let mut live = App::new(scene, source, Some((0, 0)), true);
    live.on_key(KeyEvent::new(KeyCode::Char('F'), KeyModifiers::NONE));
    assert_eq!(live.cursor(), (0, 0));
    let scanning = live.message().to_owned();
    assert!(scanning.starts_with("scanning the image"), "{scanning}");
    // Frames, as the event loop draws them, until the scan arrives (a bound
    // against hanging, not a measure of speed).
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    let mut frames = raytree::inspector::Frames::default();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(600);
    while live.message() == scanning {
        assert!(std::time::Instant::now() < deadline, "the scan never came");
        frames.frame(&mut terminal, &mut live).unwrap();
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    assert_eq!((live.cursor(), live.message()), (want, told.as_str()));
}
