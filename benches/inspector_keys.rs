//! The inspector on a big scene, driven as its event loop drives it (the
//! preview worker live, each frame drawn into ratatui's test backend of
//! 160 × 48 cells, so no terminal is needed), timed from inside: how long the
//! scene takes to load, the first frame after it, and each key's frame.
//! `docs/performance.md` quotes it at a million objects.
//!
//! ```text
//! inspector_keys SCENE.json [KEYS]
//! ```
//!
//! KEYS is one character per key: `R`, `L`, `U`, `D` the arrows, `T` Tab, `E`
//! Enter, anything else that character (default `RDLTDE+-`: three pixels, the
//! tree pane, a line down and open, zoom in and out). It prints one line:
//! `load <s> first <s> key_median <s> key_max <s> | <key>=<s> …`.

use std::time::Instant;

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use raytree::inspector::{App, Frames};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: inspector_keys SCENE.json [KEYS]");
        std::process::exit(2);
    };
    let keys = args.get(2).map_or("RDLTDE+-", String::as_str);
    let started = Instant::now();
    let (scene, source) = match raytree::scene::source::load(Some(path.as_ref())) {
        Ok(loaded) => loaded,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let load = started.elapsed().as_secs_f64();
    let started = Instant::now();
    let mut app = App::new(scene, source, None, true);
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).expect("a test backend");
    let mut frames = Frames::default();
    frames
        .frame(&mut terminal, &mut app)
        .expect("a test backend");
    let first = started.elapsed().as_secs_f64();
    let mut times = Vec::new();
    for c in keys.chars() {
        let code = match c {
            'R' => KeyCode::Right,
            'L' => KeyCode::Left,
            'U' => KeyCode::Up,
            'D' => KeyCode::Down,
            'T' => KeyCode::Tab,
            'E' => KeyCode::Enter,
            c => KeyCode::Char(c),
        };
        let started = Instant::now();
        app.on_key(KeyEvent::new(code, KeyModifiers::NONE));
        frames.input();
        frames
            .frame(&mut terminal, &mut app)
            .expect("a test backend");
        times.push((c, started.elapsed().as_secs_f64()));
    }
    let mut sorted: Vec<f64> = times.iter().map(|&(_, t)| t).collect();
    sorted.sort_by(f64::total_cmp);
    let (median, max) = match sorted.as_slice() {
        [] => (0.0, 0.0),
        s => (s[s.len() / 2], s[s.len() - 1]),
    };
    let each: Vec<String> = times.iter().map(|(c, t)| format!("{c}={t:.3}")).collect();
    println!(
        "load {load:.3} first {first:.3} key_median {median:.3} key_max {max:.3} | {}",
        each.join(" ")
    );
}
