//! The key table checked from the outside, on the screen a user sees: every
//! press the table binds changes something (in at least one of a few
//! situations, since some keys act only in a pane or while stepping), and
//! every key the inspector reacts to is in the table.

use std::time::Duration;

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use raytree::inspector::{App, KEYS, draw};
use raytree::scene::source::SceneSource;

/// A small terminal, where `v` has something to switch.
const SIZE: Rect = Rect::new(0, 0, 80, 24);

/// The situations a key is tried in, each set up by keys from a fresh start.
const SITUATIONS: &[(&str, &[KeyCode])] = &[
    ("the image pane focused", &[]),
    (
        "the tree pane focused, on its second line",
        &[KeyCode::Tab, KeyCode::Down],
    ),
    (
        "zoomed in, ten steps into the algorithm",
        &[
            KeyCode::Char('+'),
            KeyCode::Char('+'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
            KeyCode::Char('n'),
        ],
    ),
];

/// An inspector on a small Whitted image, at its most interesting pixel, in `setup`.
fn inspector(setup: &[KeyCode]) -> App {
    let mut scene = raytree::scene::loader::whitted();
    (scene.settings.width, scene.settings.height) = (160, 120);
    let mut app = App::new(
        scene,
        SceneSource::new("scenes/whitted.json", ""),
        None,
        false,
    );
    for &code in setup {
        app.on_key(KeyEvent::new(code, KeyModifiers::NONE));
    }
    app
}

/// What the user sees: the screen, colors included, and whether it quit.
fn seen(app: &mut App) -> (Buffer, bool) {
    app.set_trace_time(Duration::ZERO);
    raytree::inspector::tick(app, SIZE);
    let mut terminal = Terminal::new(TestBackend::new(SIZE.width, SIZE.height)).unwrap();
    terminal.draw(|f| draw(f, app)).unwrap();
    (terminal.backend().buffer().clone(), app.quitting())
}

/// Whether pressing `key` in `setup` changes what the user sees.
fn reacts(setup: &[KeyCode], key: KeyEvent) -> bool {
    let mut app = inspector(setup);
    let before = seen(&mut app);
    app.on_key(key);
    seen(&mut app) != before
}

/// Whether the table binds `key`.
fn bound(key: &KeyEvent) -> bool {
    KEYS.iter()
        .flat_map(|b| b.bound())
        .any(|(k, _)| k.matches(key))
}

#[test]
fn every_press_in_the_key_table_does_something() {
    for b in KEYS {
        for (k, action) in b.bound() {
            assert!(
                SITUATIONS.iter().any(|(_, setup)| reacts(setup, k.event())),
                "{k:?} ({action:?}, help row {:?}) changes nothing in any of: {}",
                b.keys,
                SITUATIONS
                    .iter()
                    .map(|(s, _)| *s)
                    .collect::<Vec<_>>()
                    .join("; ")
            );
        }
    }
}

#[test]
fn every_key_the_inspector_reacts_to_is_in_the_key_table() {
    let mut codes: Vec<KeyCode> = (' '..='~').map(KeyCode::Char).collect();
    codes.extend([
        KeyCode::Backspace,
        KeyCode::Enter,
        KeyCode::Left,
        KeyCode::Right,
        KeyCode::Up,
        KeyCode::Down,
        KeyCode::Home,
        KeyCode::End,
        KeyCode::PageUp,
        KeyCode::PageDown,
        KeyCode::Tab,
        KeyCode::BackTab,
        KeyCode::Delete,
        KeyCode::Insert,
        KeyCode::Esc,
    ]);
    codes.extend((1..=12).map(KeyCode::F));
    let mut presses: Vec<KeyEvent> = codes
        .into_iter()
        .map(|c| KeyEvent::new(c, KeyModifiers::NONE))
        .collect();
    presses.extend(('a'..='z').map(|c| KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)));
    let mut unlisted = Vec::new();
    for key in presses {
        let acts = SITUATIONS.iter().find(|(_, setup)| reacts(setup, key));
        if let (Some((situation, _)), false) = (acts, bound(&key)) {
            unlisted.push(format!("{key:?} ({situation})"));
        }
    }
    assert!(
        unlisted.is_empty(),
        "keys that act but are not in the key table: {unlisted:?}"
    );
    // And the check sees a difference: an unbound key changes nothing.
    assert!(!reacts(
        &[],
        KeyEvent::new(KeyCode::Char('c'), KeyModifiers::NONE)
    ));
    assert!(reacts(
        &[],
        KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL)
    ));
}
