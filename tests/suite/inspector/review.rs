//! What a student's review of the inspector found, each kept fixed: no pane
//! describes another pixel than the one shown, no text is cut without its
//! marker, an error names the typed mistake, and no edit is lost unasked.

use crate::inspector::drive::{key, keys, screen, whitted_at};
use std::path::Path;

use ratatui::crossterm::event::KeyCode;
use raytree::inspector::App;
use raytree::scene::source::SceneSource;
use raytree::tree::record;

/// Types `typed` after the key `k` opens a prompt, and Enter.
fn prompt(app: &mut App, k: char, typed: &str) {
    key(app, KeyCode::Char(k));
    keys(app, typed);
    key(app, KeyCode::Enter);
}

/// The Whitted scene followed by a guided step-through of pixel 416,209 whose
/// stops are at steps 1 and 5 and say `first` and `second`.
fn guided(first: &str, second: &str) -> App {
    let script = raytree::course::guide::parse(
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/review.toml")),
        &format!(
            "title = \"Review\"\nscene = \"../scenes/whitted.json\"\npixel = [416, 209]\n\
             [[stop]]\nstep = 1\nsay = \"{first}\"\n[[stop]]\nstep = 5\nsay = \"{second}\"\n"
        ),
    )
    .unwrap();
    let mut app = whitted_at((0, 0));
    app.follow(script).unwrap();
    app
}

#[test]
fn away_from_the_guides_pixel_its_stops_are_hidden_and_n_steps_this_pixel() {
    let mut app = guided("at the camera, c = {c}", "the fifth step");
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(app.step(), Some(4), "n goes to the second stop");
    prompt(&mut app, 'g', "450,209");
    assert_eq!(app.cursor(), (450, 209));
    let away = screen(&mut app, 80, 24);
    assert!(
        !away.contains("the fifth step")
            && away.contains("guide paused: its stops tell pixel 416,209; g 416,209 goes back"),
        "the stop, of pixel 416,209, is not shown at 450,209:\n{away}"
    );
    key(&mut app, KeyCode::Char('p'));
    assert_eq!(
        app.step(),
        Some(app.steps().len() - 1),
        "p steps back through this pixel's algorithm, not to a stop of another pixel"
    );
    key(&mut app, KeyCode::Char('x'));
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(
        app.step(),
        Some(0),
        "n starts stepping this pixel, as its hint says"
    );
    prompt(&mut app, 'g', "416,209");
    assert_eq!(
        app.step(),
        Some(4),
        "back at the guide's pixel, at its stop"
    );
    let back = screen(&mut app, 80, 24);
    assert!(back.contains("Review · stop 2/2: the fifth step"), "{back}");
}

#[test]
fn a_long_stop_wraps_and_a_too_long_one_is_cut_with_the_marker() {
    // About four lines and a half at 80 columns, like lesson 10's stop 4.
    let long = format!("{} its reflected ray keeps all of it.", "word ".repeat(56));
    let mut app = guided(&long, "second");
    let shown = screen(&mut app, 80, 24);
    assert!(
        shown.contains("keeps all of it."),
        "the whole stop is shown:\n{shown}"
    );
    let mut app = guided(&"word ".repeat(400), "second");
    let shown = screen(&mut app, 80, 24);
    let last = shown
        .lines()
        .rev()
        .find(|l| l.contains("word"))
        .unwrap_or_else(|| panic!("{shown}"));
    assert!(last.ends_with('…'), "a cut stop says so: {last:?}\n{shown}");
}

/// A saved trace without its scene: only that pixel is known.
fn saved_trace_alone() -> App {
    let scene = raytree::scene::loader::whitted();
    let trace = record::pixel(
        &scene,
        SceneSource::new("scenes/whitted.json", ""),
        416,
        209,
        None,
    )
    .unwrap();
    App::from_trace(trace, None, false)
}

#[test]
fn without_the_scene_the_cursor_stays_on_the_saved_pixel_and_f_says_why() {
    let mut app = saved_trace_alone();
    for go in [
        |app: &mut App| prompt(app, 'g', "100,100"),
        |app: &mut App| {
            key(app, KeyCode::Char('i'));
            key(app, KeyCode::Right);
        },
    ] {
        go(&mut app);
        assert_eq!(app.cursor(), (416, 209), "the panes show 416,209");
        assert!(
            app.message().contains("only pixel 416,209"),
            "{}",
            app.message()
        );
    }
    key(&mut app, KeyCode::Char('f'));
    assert!(
        !app.message().contains("no pixel has") && app.message().contains("needs the scene"),
        "f does not claim the saved pixel has no total internal reflection: {}",
        app.message()
    );
}

/// Every key the help says goes from the image to the tree does so.
#[test]
fn the_keys_the_help_says_go_to_the_tree_do() {
    let said: Vec<&str> = raytree::inspector::KEYS
        .iter()
        .filter(|b| b.what.contains("go to the tree"))
        .flat_map(|b| b.keys.split(" / "))
        .collect();
    assert!(!said.is_empty(), "the help says how to go to the tree");
    for name in said {
        let code = match name {
            "Enter" => KeyCode::Enter,
            "→" | "l" => KeyCode::Right,
            other => panic!("a key this test does not know: {other}"),
        };
        let mut app = whitted_at((416, 209));
        key(&mut app, KeyCode::Char('i'));
        key(&mut app, code);
        assert_eq!(
            app.focus(),
            raytree::inspector::Focus::Tree,
            "{name} from the image goes to the tree, as the help says"
        );
    }
}

/// A refused what-if names the edit and is read in full at 80×24 and 120×36,
/// stepping or not.
#[test]
fn a_refused_edit_names_the_edit_and_is_shown_in_full() {
    let squeeze = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    for (typed, starts) in [
        ("reflective=0.5", "reflective=0.5: materials.glass: "),
        ("ior=abc", "ior=abc: not a number"),
        ("foo=1", "'foo' cannot be edited"),
    ] {
        for (w, h) in [(80, 24), (120, 36)] {
            for stepping in [false, true] {
                let mut app = whitted_at((416, 209));
                if stepping {
                    key(&mut app, KeyCode::Char('n'));
                }
                prompt(&mut app, 'm', typed);
                let said = app.message().to_owned();
                assert!(said.starts_with(starts), "{typed}: {said}");
                let shown = squeeze(&screen(&mut app, w, h));
                assert!(
                    shown.contains(&squeeze(&said)),
                    "{typed} at {w}×{h} (stepping: {stepping}): {said:?} in full on\n{shown}"
                );
            }
        }
    }
}

/// Writing to a file that exists keeps the prompt open with the name, so
/// what is typed next edits the name instead of running as keys.
#[test]
fn writing_to_an_existing_file_keeps_the_name_to_edit() {
    let dir = std::env::temp_dir().join(format!("raytree-review-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let taken = dir.join("taken.json");
    std::fs::write(&taken, "{}").unwrap();
    let mut app = whitted_at((416, 209));
    prompt(&mut app, 'm', "shininess=10");
    key(&mut app, KeyCode::Char('w'));
    // Erase the proposed name, type the taken one.
    for _ in 0..300 {
        key(&mut app, KeyCode::Backspace);
    }
    keys(&mut app, &taken.display().to_string());
    key(&mut app, KeyCode::Enter);
    assert!(app.message().contains("exists"), "{}", app.message());
    let shown = screen(&mut app, 80, 24);
    assert!(
        shown.contains("exists") && shown.contains("write the edited scene to"),
        "the reason and the prompt, still open:\n{shown}"
    );
    for _ in 0.."taken.json".len() {
        key(&mut app, KeyCode::Backspace);
    }
    keys(&mut app, "new.json");
    key(&mut app, KeyCode::Enter);
    let written = dir.join("new.json");
    assert!(written.exists(), "{}", app.message());
    assert_eq!(app.edits().len(), 1, "the typed name ran no key");
    assert_eq!(std::fs::read_to_string(&taken).unwrap(), "{}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// q (or Esc) with what-if edits no file holds asks first; a second press
/// quits; once written, q quits at once.
#[test]
fn quitting_with_unsaved_edits_asks_first() {
    for quit in [KeyCode::Char('q'), KeyCode::Esc] {
        let mut app = whitted_at((416, 209));
        prompt(&mut app, 'm', "shininess=10");
        key(&mut app, quit);
        assert!(!app.quitting(), "the first press asks");
        assert!(app.message().contains("not saved"), "{}", app.message());
        key(&mut app, KeyCode::Char('e'));
        key(&mut app, quit);
        assert!(!app.quitting(), "another key between: it asks again");
        key(&mut app, quit);
        assert!(app.quitting(), "a second press right after quits");
    }
    let mut app = whitted_at((416, 209));
    key(&mut app, KeyCode::Char('q'));
    assert!(app.quitting(), "without edits q quits at once");
}

/// A key that can do nothing where it is pressed says why, instead of
/// looking unread: n at the last step, p at the first, s at one sample, w
/// without edits, n at a guide's last stop.
#[test]
fn a_key_with_nothing_to_do_says_why() {
    let mut app = whitted_at((416, 209));
    key(&mut app, KeyCode::Char('p'));
    let last = app.steps().len() - 1;
    assert_eq!(app.step(), Some(last), "p starts stepping at the last step");
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(app.step(), Some(last));
    let n = last + 1;
    assert_eq!(
        app.message(),
        format!("step {n} of {n} is the last: p steps back, x shows the whole tree")
    );
    key(&mut app, KeyCode::Char('p'));
    assert_eq!(app.step(), Some(last - 1));
    assert_eq!(app.message(), "", "a key that moved says nothing");
    key(&mut app, KeyCode::Char('x'));
    key(&mut app, KeyCode::Char('n'));
    key(&mut app, KeyCode::Char('p'));
    assert_eq!(app.step(), Some(0));
    assert!(app.message().starts_with("step 1 of "), "{}", app.message());

    key(&mut app, KeyCode::Char('s'));
    assert!(app.message().contains("one sample"), "{}", app.message());
    key(&mut app, KeyCode::Char('w'));
    assert!(
        app.message().starts_with("no what-if edits to write"),
        "{}",
        app.message()
    );
    let shown = screen(&mut app, 80, 24);
    assert!(
        !shown.contains("write the edited scene to"),
        "no prompt opens:\n{shown}"
    );

    let mut app = guided("one", "two");
    prompt(&mut app, 'g', "416,209");
    key(&mut app, KeyCode::Char('n'));
    key(&mut app, KeyCode::Char('n'));
    assert_eq!(
        app.message(),
        "stop 2 of 2 is the guide's last: p goes back"
    );
    key(&mut app, KeyCode::Char('p'));
    key(&mut app, KeyCode::Char('p'));
    assert_eq!(app.message(), "stop 1 of 2 is the guide's first: n goes on");
}
