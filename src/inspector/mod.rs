//! `raytree inspect`: pick a pixel, walk its ray tree step by step, in the terminal.
//!
//! [`App`] holds the state in owned parts and handles keys without a terminal
//! (tested directly); [`tick`] makes the changes a frame needs and
//! [`draw`] draws it, only reading; this module owns the terminal: raw mode, the
//! alternate screen and mouse capture are switched on here and restored on every
//! way out (quit, error, panic, and SIGINT, SIGTERM, SIGHUP or SIGQUIT through
//! the binary's handler). A frame is drawn only when something changed
//! ([`Frames`]).
//!
//! `app/` is the state and what keys do to it, `state/` its owned parts,
//! `panes/` the four panes drawn from it (gitui's `components/` in spirit).

mod app;
mod colors;
mod fit;
mod keymap;
mod layout;
mod panes;
mod state;
mod tick;
mod ui;

use std::io::{IsTerminal, Stdout, stdout};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use ratatui::Terminal;
use ratatui::backend::{Backend, CrosstermBackend};
use ratatui::crossterm::event::{
    self, DisableMouseCapture, EnableMouseCapture, Event, KeyEventKind,
};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{
    EnterAlternateScreen, LeaveAlternateScreen, disable_raw_mode, enable_raw_mode,
};
use ratatui::layout::Rect;

pub use app::{App, Prompt};
pub use colors::detect as color_support;
pub use keymap::{Action, Binding, KEYS, Key};
pub use layout::{Areas, Pane};
pub use state::features::{
    FeatureMap, Features, scan as scan_features, scan_with as scan_features_with,
};
pub use state::find::{Overlay, Seek};
pub use state::preview::{Picture, Window, render_picture};
pub use state::reveal::{RayRevealed, Revealed, call_stack};
pub use state::selection::{Focus, Item};
pub use state::stepping::Guided;
pub use state::whatif::Before;
pub use tick::tick;
pub use ui::{GLYPHS, draw};

static ACTIVE: AtomicBool = AtomicBool::new(false);

/// Runs the inspector until the user quits.
pub fn run(mut app: App) -> std::io::Result<()> {
    if !stdout().is_terminal() {
        return Err(std::io::Error::other(
            "raytree inspect needs a terminal (standard output is not one)",
        ));
    }
    let mut terminal = setup()?;
    let result = event_loop(&mut terminal, &mut app);
    restore();
    result
}

fn setup() -> std::io::Result<Terminal<CrosstermBackend<Stdout>>> {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        restore();
        previous(info);
    }));
    enable_raw_mode()?;
    ACTIVE.store(true, Ordering::SeqCst);
    execute!(stdout(), EnterAlternateScreen, EnableMouseCapture)?;
    Terminal::new(CrosstermBackend::new(stdout()))
}

/// Gives the terminal back (mouse capture off, main screen, cooked mode, cursor
/// shown) if the inspector has it; safe to call more than once.
pub fn restore() {
    if ACTIVE.swap(false, Ordering::SeqCst) {
        let _ = execute!(
            stdout(),
            DisableMouseCapture,
            LeaveAlternateScreen,
            ratatui::crossterm::cursor::Show
        );
        let _ = disable_raw_mode();
    }
}

fn event_loop(
    terminal: &mut Terminal<CrosstermBackend<Stdout>>,
    app: &mut App,
) -> std::io::Result<()> {
    let mut frames = Frames::default();
    loop {
        frames.frame(terminal, app)?;
        if app.quitting() {
            return Ok(());
        }
        // Wake up often enough to show the picture as it refines; idle, a
        // wake-up draws nothing.
        if event::poll(Duration::from_millis(30))? {
            frames.input();
            match event::read()? {
                Event::Key(key) if key.kind == KeyEventKind::Press => app.on_key(key),
                Event::Mouse(m) => app.on_mouse(m),
                _ => {} // A resize: the next frame lays out again.
            }
        }
    }
}

/// The event loop's frames, drawn only when something changed since the last
/// one: an input event, the terminal's size, a picture from the worker or the
/// image's features from their scan.
/// Idle, the inspector draws nothing (it drew every 30 ms, for a fifth of a
/// core, issue 29).
#[derive(Debug)]
pub struct Frames {
    /// The size the last frame was drawn at.
    size: Option<Rect>,
    /// Whether an input event came since the last frame.
    input: bool,
    drawn: u64,
}

impl Default for Frames {
    /// None drawn yet: the first frame is due.
    fn default() -> Self {
        Self {
            size: None,
            input: true,
            drawn: 0,
        }
    }
}

impl Frames {
    /// An input event arrived (a key, a click, a resize): a frame is due.
    pub fn input(&mut self) {
        self.input = true;
    }

    /// Takes a picture the worker finished or the features scanned, if any
    /// came, and, if anything changed, makes the update step ([`tick`]) and
    /// draws a frame that only reads the state; returns whether it drew.
    pub fn frame<B: Backend>(
        &mut self,
        terminal: &mut Terminal<B>,
        app: &mut App,
    ) -> Result<bool, B::Error> {
        terminal.autoresize()?;
        let area = terminal.get_frame().area();
        let arrived = app.receive();
        if !(self.input || arrived || self.size != Some(area)) {
            return Ok(false);
        }
        (self.input, self.size) = (false, Some(area));
        tick(app, area);
        terminal.draw(|frame| draw(frame, app))?;
        self.drawn += 1;
        Ok(true)
    }

    /// How many frames were drawn.
    pub fn drawn(&self) -> u64 {
        self.drawn
    }
}
