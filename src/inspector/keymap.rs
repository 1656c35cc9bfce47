//! Every key of the inspector in one table: the keys as the help names them,
//! what they do in words, and the presses with the action each asks for. The
//! dispatch (`keys.rs`) looks a press up here, and the help and the README list
//! the rows, so the help cannot disagree with the keys (as gitui's key list).

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// What a key press asks for. Some depend on where the inspector is: the
/// arrows and Enter drive the focused pane; `n` and `p` move between a guided
/// step-through's stops while one is followed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Image: the cursor left. Tree: collapse the ray, or go to its parent.
    Left,
    /// Image: the cursor right. Tree: expand the ray.
    Right,
    /// Image: the cursor up. Tree: the line above.
    Up,
    /// Image: the cursor down. Tree: the line below.
    Down,
    /// Image: go to the tree. Tree: expand the ray.
    Enter,
    /// The other pane.
    SwitchFocus,
    /// The image pane.
    FocusImage,
    /// The tree pane.
    FocusTree,
    /// Every ray open.
    ExpandAll,
    /// Zoom in.
    ZoomIn,
    /// Zoom out.
    ZoomOut,
    /// Ask for a pixel to go to.
    GoTo,
    /// The next pixel with what is sought.
    Find,
    /// Seek the next kind of feature, and find it.
    FindOther,
    /// The next overlay.
    Overlay,
    /// The next step (or stop, when guided).
    Next,
    /// The previous step (or stop, when guided).
    Previous,
    /// The next step, guided or not.
    StepForward,
    /// The previous step, guided or not.
    StepBack,
    /// Leave stepping.
    LeaveStepping,
    /// The pixel's next sample.
    NextSample,
    /// Scroll the numbers up a page.
    ScrollUp,
    /// Scroll the numbers down a page.
    ScrollDown,
    /// Small terminals: the numbers or the diagram.
    SwitchPane,
    /// Ask for a what-if edit.
    Edit,
    /// Undo every edit.
    Undo,
    /// Ask where to write the edited scene.
    Write,
    /// Open the help.
    Help,
    /// Quit.
    Quit,
}

/// A key press: a key, with Ctrl held where `ctrl` says. Other modifiers are
/// not looked at (terminals differ in what they send with Shift or Alt).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Key {
    /// The key.
    pub code: KeyCode,
    /// Ctrl must be held.
    pub ctrl: bool,
}

impl Key {
    /// A character key.
    const fn ch(c: char) -> Self {
        Self::code(KeyCode::Char(c))
    }

    /// Any key.
    const fn code(code: KeyCode) -> Self {
        Self { code, ctrl: false }
    }

    /// A character key with Ctrl.
    const fn ctrl(c: char) -> Self {
        Self {
            code: KeyCode::Char(c),
            ctrl: true,
        }
    }

    /// Whether `key` is this press.
    pub fn matches(&self, key: &KeyEvent) -> bool {
        key.code == self.code && (!self.ctrl || key.modifiers.contains(KeyModifiers::CONTROL))
    }

    /// The press as a terminal sends it.
    pub fn event(&self) -> KeyEvent {
        let modifiers = if self.ctrl {
            KeyModifiers::CONTROL
        } else {
            KeyModifiers::NONE
        };
        KeyEvent::new(self.code, modifiers)
    }
}

/// One row of the help: the keys, what they do, and what is bound.
#[derive(Debug)]
pub struct Binding {
    /// The keys, as the help's first column names them.
    pub keys: &'static str,
    /// What they do, as the help says.
    pub what: &'static str,
    /// The presses `keys` names, each with its action (a key named by two
    /// rows, as → by the arrows and by Enter, is bound in the first).
    pub presses: &'static [(Key, Action)],
    /// Presses bound as well that `keys` does not name: another spelling of
    /// a named one (`=` for `+`, Shift-Tab, Ctrl-C) or one `what` names.
    pub also: &'static [(Key, Action)],
}

impl Binding {
    /// Every press the row binds.
    pub fn bound(&self) -> impl Iterator<Item = &(Key, Action)> {
        self.presses.iter().chain(self.also)
    }
}

/// A row that names its presses and binds no others.
const fn row(keys: &'static str, what: &'static str, presses: &'static [(Key, Action)]) -> Binding {
    Binding {
        keys,
        what,
        presses,
        also: &[],
    }
}

/// Every key, for the dispatch, the help and the README, in the help's order.
pub const KEYS: &[Binding] = &[
    row(
        "←↑↓→ / hjkl",
        "move the pixel cursor (image pane) or through the tree (tree pane)",
        &[
            (Key::code(KeyCode::Left), Action::Left),
            (Key::code(KeyCode::Up), Action::Up),
            (Key::code(KeyCode::Down), Action::Down),
            (Key::code(KeyCode::Right), Action::Right),
            (Key::ch('h'), Action::Left),
            (Key::ch('j'), Action::Down),
            (Key::ch('k'), Action::Up),
            (Key::ch('l'), Action::Right),
        ],
    ),
    // The mouse: keys.rs handles clicks and the wheel.
    row(
        "click",
        "select a pixel (image pane) or a line (tree pane)",
        &[],
    ),
    Binding {
        keys: "Tab",
        what: "switch between the image and the tree pane (also i: image, t: tree)",
        presses: &[(Key::code(KeyCode::Tab), Action::SwitchFocus)],
        also: &[
            (Key::code(KeyCode::BackTab), Action::SwitchFocus),
            (Key::ch('i'), Action::FocusImage),
            (Key::ch('t'), Action::FocusTree),
        ],
    },
    row(
        "Enter",
        "expand the selected ray (tree pane); from the image, go to the tree",
        &[(Key::code(KeyCode::Enter), Action::Enter)],
    ),
    // → and ← are bound with the arrows (in the image they move the cursor):
    // these rows say what they do in the tree.
    row("→", "tree pane: expand the selected ray", &[]),
    row(
        "←",
        "tree pane: collapse the selected ray, or go to its parent",
        &[],
    ),
    row(
        "e",
        "expand the whole tree",
        &[(Key::ch('e'), Action::ExpandAll)],
    ),
    Binding {
        keys: "+ / -",
        what: "zoom in / out around the cursor",
        presses: &[
            (Key::ch('+'), Action::ZoomIn),
            (Key::ch('-'), Action::ZoomOut),
        ],
        also: &[
            (Key::ch('='), Action::ZoomIn),
            (Key::ch('_'), Action::ZoomOut),
        ],
    },
    row(
        "g",
        "go to a pixel: type x,y and Enter",
        &[(Key::ch('g'), Action::GoTo)],
    ),
    row(
        "f",
        "find the next pixel with a total internal reflection (or what F chose)",
        &[(Key::ch('f'), Action::Find)],
    ),
    row(
        "F",
        "find something else: blocked shadow, refraction, depth ≥ 4, cutoff, miss",
        &[(Key::ch('F'), Action::FindOther)],
    ),
    row(
        "o",
        "overlay: marks of what f finds, depth, rays or tests per pixel, none",
        &[(Key::ch('o'), Action::Overlay)],
    ),
    row(
        "n / space",
        "next step of the algorithm (in a guided step-through: next stop)",
        &[(Key::ch('n'), Action::Next), (Key::ch(' '), Action::Next)],
    ),
    row(
        "p / Backspace",
        "previous step (guided: previous stop)",
        &[
            (Key::ch('p'), Action::Previous),
            (Key::code(KeyCode::Backspace), Action::Previous),
        ],
    ),
    row(
        "] / [",
        "next / previous step, also in a guided step-through",
        &[
            (Key::ch(']'), Action::StepForward),
            (Key::ch('['), Action::StepBack),
        ],
    ),
    row(
        "x",
        "leave stepping: show the whole tree",
        &[(Key::ch('x'), Action::LeaveStepping)],
    ),
    row(
        "s",
        "show the pixel's next sample (with several samples per pixel)",
        &[(Key::ch('s'), Action::NextSample)],
    ),
    row(
        "PgUp / PgDn",
        "scroll the numbers (or the mouse wheel over them)",
        &[
            (Key::code(KeyCode::PageUp), Action::ScrollUp),
            (Key::code(KeyCode::PageDown), Action::ScrollDown),
        ],
    ),
    row(
        "v",
        "small terminals: show the diagram or the numbers on the right",
        &[(Key::ch('v'), Action::SwitchPane)],
    ),
    row(
        "m",
        "what if: edit the selected hit's material or a method, e.g. ior=1.0",
        &[(Key::ch('m'), Action::Edit)],
    ),
    row(
        "u",
        "undo every edit: the scene as loaded",
        &[(Key::ch('u'), Action::Undo)],
    ),
    row(
        "w",
        "write the edited scene to a new file",
        &[(Key::ch('w'), Action::Write)],
    ),
    row(
        "?",
        "this help (↑↓ PgUp PgDn scroll it, any other key closes)",
        &[(Key::ch('?'), Action::Help)],
    ),
    Binding {
        keys: "q / Esc",
        what: "quit (with unsaved what-if edits, a second press quits)",
        presses: &[
            (Key::ch('q'), Action::Quit),
            (Key::code(KeyCode::Esc), Action::Quit),
        ],
        also: &[(Key::ctrl('c'), Action::Quit)],
    },
];

/// The action `key` asks for, if it is bound.
pub fn action(key: &KeyEvent) -> Option<Action> {
    KEYS.iter()
        .flat_map(Binding::bound)
        .find(|(k, _)| k.matches(key))
        .map(|&(_, action)| action)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The keys a help row's first column names (`click` names none: it is the mouse).
    fn named(keys: &str) -> Vec<KeyCode> {
        keys.split(" / ")
            .flat_map(|part| match part {
                "click" => vec![],
                "Tab" => vec![KeyCode::Tab],
                "Enter" => vec![KeyCode::Enter],
                "Backspace" => vec![KeyCode::Backspace],
                "Esc" => vec![KeyCode::Esc],
                "PgUp" => vec![KeyCode::PageUp],
                "PgDn" => vec![KeyCode::PageDown],
                "space" => vec![KeyCode::Char(' ')],
                _ => part
                    .chars()
                    .map(|c| match c {
                        '←' => KeyCode::Left,
                        '↑' => KeyCode::Up,
                        '↓' => KeyCode::Down,
                        '→' => KeyCode::Right,
                        c => KeyCode::Char(c),
                    })
                    .collect(),
            })
            .collect()
    }

    #[test]
    fn every_key_the_help_names_is_bound_and_every_bound_key_is_in_the_help() {
        let all_named: Vec<KeyCode> = KEYS.iter().flat_map(|b| named(b.keys)).collect();
        let bound = |code: KeyCode| {
            KEYS.iter()
                .flat_map(|b| b.presses)
                .any(|(k, _)| k.code == code)
        };
        for code in &all_named {
            assert!(bound(*code), "the help names {code:?}, which nothing binds");
        }
        for b in KEYS {
            for (k, _) in b.presses {
                assert!(
                    named(b.keys).contains(&k.code) && !k.ctrl,
                    "row {:?} binds {k:?} without naming it",
                    b.keys
                );
            }
            // A press the column does not name is another spelling of one it
            // names (same action), or the row's text names it ("i: image").
            for (k, a) in b.also {
                let spelling = b.presses.iter().any(|(_, named)| named == a);
                let told = matches!(k.code, KeyCode::Char(c) if b.what.contains(&format!("{c}: ")));
                assert!(
                    spelling || told,
                    "row {:?} binds {k:?} and does not say so",
                    b.keys
                );
                assert!(!all_named.contains(&k.code), "{k:?} is bound twice");
            }
        }
    }

    #[test]
    fn no_press_is_bound_twice_and_each_finds_its_action() {
        let presses: Vec<&(Key, Action)> = KEYS.iter().flat_map(Binding::bound).collect();
        for (i, (k, a)) in presses.iter().enumerate() {
            assert!(
                presses[..i].iter().all(|(other, _)| other != k),
                "{k:?} is bound twice"
            );
            assert_eq!(action(&k.event()), Some(*a), "{k:?}");
        }
        // Modifiers other than Ctrl do not matter; Ctrl-C is not c.
        let shift_n = KeyEvent::new(KeyCode::Char('n'), KeyModifiers::SHIFT);
        assert_eq!(action(&shift_n), Some(Action::Next));
        assert_eq!(action(&Key::ch('c').event()), None);
        assert_eq!(action(&Key::ctrl('c').event()), Some(Action::Quit));
    }
}
