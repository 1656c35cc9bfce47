//! Driving an inspector without a terminal, for the tests that do: keys
//! pressed one by one, the Whitted scene at a pixel, and the screen drawn into
//! ratatui's test backend as text.

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use raytree::inspector::{App, draw};
use raytree::scene::source::SceneSource;

pub fn key(app: &mut App, code: KeyCode) {
    app.on_key(KeyEvent::new(code, KeyModifiers::NONE));
}

pub fn keys(app: &mut App, text: &str) {
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
}

pub fn whitted_at(pixel: (u32, u32)) -> App {
    App::new(
        raytree::scene::loader::whitted(),
        SceneSource::new("scenes/whitted.json", ""),
        Some(pixel),
        false,
    )
}

/// The screen drawn at `w`×`h`, one line per row (symbols only, colors lost).
pub fn screen(app: &mut App, w: u16, h: u16) -> String {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    // The time to trace differs from run to run: hold it still for snapshots.
    app.set_trace_time(std::time::Duration::ZERO);
    // Lay out once so the picture is rendered for the pane's real size.
    raytree::inspector::tick(app, Rect::new(0, 0, w, h));
    terminal.draw(|f| draw(f, app)).unwrap();
    app.render_picture_now();
    raytree::inspector::tick(app, Rect::new(0, 0, w, h));
    terminal.draw(|f| draw(f, app)).unwrap();
    let buffer = terminal.backend().buffer().clone();
    (0..buffer.area.height)
        .map(|y| {
            let row: String = (0..buffer.area.width)
                .map(|x| buffer[(x, y)].symbol().to_owned())
                .collect();
            row.trim_end().to_owned() + "\n"
        })
        .collect()
}
