//! The real binary in a real terminal: tmux runs `raytree inspect`, keys are
//! typed, the screen is read back, and the exit status is checked.
//! Skipped, saying so, when tmux is not installed ([`crate::tools`]).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use crate::tools::{Need, available};

/// Whether tmux is here; if not, the test says it is skipped (and fails under CI=true).
pub fn has_tmux() -> bool {
    available(
        "",
        &[Need::Tmux],
        "it drives the inspector in a real terminal",
    )
}

/// A detached tmux session of `width` × `height` running `command` in a
/// shell, on a tmux server of its own (its own socket, no configuration
/// file), so tests share nothing with each other or with the user's own
/// sessions; the server is killed when the session is dropped, so a failing
/// test leaves nothing behind.
pub struct Session {
    /// The name of the server's socket (`tmux -L`), unique to the session.
    socket: String,
    /// Where tmux made it, removed with the server.
    socket_path: Option<PathBuf>,
}

/// The one session on each server.
const SESSION: &str = "raytree";

impl Session {
    /// Starts `command` in a new `width` × `height` session on its own server.
    pub fn start(name: &str, width: u16, height: u16, command: &str) -> Session {
        static STARTED: AtomicUsize = AtomicUsize::new(0);
        let mut session = Session {
            socket: format!(
                "raytree-{name}-{}-{}",
                std::process::id(),
                STARTED.fetch_add(1, Ordering::Relaxed)
            ),
            socket_path: None,
        };
        let (w, h) = (width.to_string(), height.to_string());
        let started = session
            .tmux()
            .args([
                "new-session",
                "-d",
                "-s",
                SESSION,
                "-x",
                &w,
                "-y",
                &h,
                command,
            ])
            .status()
            .unwrap();
        assert!(started.success(), "tmux could not start a session");
        let path = session.run(&["display-message", "-p", "#{socket_path}"]);
        session.socket_path = Some(PathBuf::from(path.trim_end()));
        session
    }

    /// `tmux` talking to this session's own server only.
    fn tmux(&self) -> Command {
        let mut tmux = Command::new("tmux");
        tmux.args(["-L", &self.socket, "-f", "/dev/null"])
            .env_remove("TMUX");
        tmux
    }

    fn run(&self, args: &[&str]) -> String {
        let out = self.tmux().args(args).output().expect("tmux runs");
        String::from_utf8_lossy(&out.stdout).into_owned()
    }

    /// Types `keys` (tmux key names, or `-l` and literal text).
    pub fn send(&self, keys: &[&str]) {
        self.run(&[&["send-keys", "-t", SESSION][..], keys].concat());
    }

    /// The screen as text.
    pub fn capture(&self) -> String {
        self.run(&["capture-pane", "-t", SESSION, "-p"])
    }

    /// Waits until the captured screen satisfies `ok`, up to 20 s; returns the
    /// last capture.
    pub fn wait_for(&self, ok: impl Fn(&str) -> bool) -> String {
        let started = Instant::now();
        loop {
            let screen = self.capture();
            if ok(&screen) || started.elapsed() > Duration::from_secs(20) {
                return screen;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        let _ = self.tmux().arg("kill-server").status();
        // tmux leaves the socket file of a server it killed.
        if let Some(path) = &self.socket_path
            && path.ends_with(&self.socket)
        {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// `raytree inspect ARGS` run from the repository in a `width` × `height`
/// session, its exit status written to a file when it ends.
fn inspector(name: &str, width: u16, height: u16, env: &str, args: &str) -> (Session, PathBuf) {
    let exit_file =
        std::env::temp_dir().join(format!("raytree-{name}-{}.exit", std::process::id()));
    let _ = std::fs::remove_file(&exit_file);
    let command = format!(
        "cd {} && {env}{} inspect {args}; echo $? > {}; sleep 60",
        env!("CARGO_MANIFEST_DIR"),
        env!("CARGO_BIN_EXE_raytree"),
        exit_file.display()
    );
    (Session::start(name, width, height, &command), exit_file)
}

/// Quits with `q`; the inspector's exit status and the screen after it.
fn quit(session: &Session, exit_file: &Path) -> (String, String) {
    session.send(&["q"]);
    let started = Instant::now();
    while !exit_file.exists() && started.elapsed() < Duration::from_secs(10) {
        std::thread::sleep(Duration::from_millis(100));
    }
    let status = std::fs::read_to_string(exit_file).unwrap_or_default();
    let _ = std::fs::remove_file(exit_file);
    (status, session.capture())
}

#[test]
fn inspect_in_a_real_terminal() {
    if !has_tmux() {
        return;
    }
    let (session, exit_file) = inspector("test", 160, 48, "", "scenes/whitted.json");
    let screen = session.wait_for(|s| s.contains("ray tree") && s.contains("pixel "));
    assert!(
        screen.contains("ray tree"),
        "the inspector did not start:\n{screen}"
    );
    // Go to a pixel on the glass sphere, as a user would: g, the coordinates, Enter.
    session.send(&["g", "4", "1", "6", ",", "2", "0", "9", "Enter"]);
    let screen =
        session.wait_for(|s| s.contains("pixel 416,209") && s.contains("primary d1 'glass'"));
    assert!(
        screen.contains("refracted d2"),
        "the glass pixel's tree shows its refracted ray:\n{screen}"
    );
    assert!(
        !screen.contains("reflected d3"),
        "deeper rays stay folded until expanded:\n{screen}"
    );
    // Into the tree, down to the refracted ray, and open it.
    session.send(&["Tab", "Down", "Down", "Down", "Down", "Enter"]);
    let screen = session.wait_for(|s| s.contains("reflected d3"));
    assert!(
        screen.contains("reflected d3") && screen.contains("total internal reflection"),
        "the refracted ray opens:\n{screen}"
    );
    let (status, after) = quit(&session, &exit_file);
    assert_eq!(status.trim(), "0", "raytree inspect exit status");
    assert!(
        !after.contains("ray tree"),
        "the main screen is back after quitting:\n{after}"
    );
}

/// The learner at 80×24 in a plain tmux (no COLORTERM): one key to a
/// total internal reflection, step through it watching the tree grow, read
/// the full color sum, ask what if the glass had index 1.0, quit (asked
/// first, the edit being unsaved).
#[test]
fn a_learner_at_80x24_finds_steps_through_and_edits_a_total_internal_reflection() {
    if !has_tmux() {
        return;
    }
    let (session, exit_file) = inspector(
        "test-80x24",
        80,
        24,
        "env -u COLORTERM ",
        "scenes/whitted.json",
    );
    starts_in_256_colors_within_80_columns(&session);
    finds_a_total_internal_reflection(&session);
    steps_to_the_total_internal_reflection(&session);
    steps_on_to_the_full_color_sum(&session);
    asks_what_if_the_glass_had_index_1(&session);
    asks_before_quitting_with_an_unsaved_edit(&session, &exit_file);
}

/// Fails the test with `what` went wrong and the screen it went wrong on.
fn fail(what: &str, screen: &str) -> ! {
    panic!("{what}:\n{screen}")
}

/// The inspector starts, says it falls back to 256 colors without
/// COLORTERM, and no line is wider than the terminal.
fn starts_in_256_colors_within_80_columns(session: &Session) {
    let screen = session.wait_for(|s| s.contains("ray tree") && s.contains("pixel "));
    if !screen.contains("ray tree") {
        fail("the inspector did not start", &screen);
    }
    if !screen.contains("256 colors") {
        fail(
            "without COLORTERM it says it falls back to 256 colors",
            &screen,
        );
    }
    for line in screen.lines() {
        if line.chars().count() > 80 {
            fail("a line is wider than the terminal", &screen);
        }
    }
}

/// One key to a total internal reflection.
fn finds_a_total_internal_reflection(session: &Session) {
    session.send(&["f"]);
    let screen = session.wait_for(|s| s.contains("found: total internal reflection"));
    if !screen.contains("found: total internal reflection") {
        fail("f finds a total internal reflection", &screen);
    }
}

/// Steps to the total internal reflection: the tree grows one ray at a time.
fn steps_to_the_total_internal_reflection(session: &Session) {
    let mut rays_seen = Vec::new();
    let mut screen = String::new();
    for _ in 0..400 {
        session.send(&["n"]);
        std::thread::sleep(Duration::from_millis(15));
        screen = session.capture();
        rays_seen.push(screen.matches(" d").count());
        if screen.contains("no refracted ray: total internal reflection") {
            break;
        }
    }
    if !screen.contains("no refracted ray: total internal reflection") {
        fail("stepping reaches the total internal reflection", &screen);
    }
    if !rays_seen.windows(2).any(|w| w[1] > w[0]) || rays_seen[0] >= *rays_seen.last().unwrap() {
        fail("the tree grows while stepping", &screen);
    }
}

/// On to the last step, where the primary ray's color is summed in full.
fn steps_on_to_the_full_color_sum(session: &Session) {
    let mut screen = String::new();
    for _ in 0..400 {
        session.send(&["n"]);
        std::thread::sleep(Duration::from_millis(15));
        screen = session.capture();
        let at_end = screen
            .lines()
            .find(|l| l.starts_with("step "))
            .and_then(|l| l.split_whitespace().nth(1))
            .and_then(|f| f.split_once('/'))
            .is_some_and(|(a, b)| a == b);
        if at_end {
            break;
        }
    }
    if !(screen.contains("color = local")
        && screen.contains("reflected")
        && screen.contains("refracted")
        && screen.contains("      = ("))
    {
        fail("the full color sum is in view at the last step", &screen);
    }
}

/// What if the glass had index 1.0? The pane shows before → after.
fn asks_what_if_the_glass_had_index_1(session: &Session) {
    session.send(&["x", "m"]);
    session.send(&["-l", "ior=1.0"]);
    session.send(&["Enter"]);
    let screen = session.wait_for(|s| s.contains("what if"));
    if !(screen.contains("what if") && screen.contains("ior=1.0") && screen.contains(" → ")) {
        fail("the edit shows before → after", &screen);
    }
}

/// The edit is not saved: the first q asks, the second quits, and the main
/// screen is back.
fn asks_before_quitting_with_an_unsaved_edit(session: &Session, exit_file: &Path) {
    session.send(&["q"]);
    let screen = session.wait_for(|s| s.contains("not saved"));
    if !screen.contains("q again quits") {
        fail("q with an unsaved edit asks first", &screen);
    }
    let (status, after) = quit(session, exit_file);
    assert_eq!(status.trim(), "0", "raytree inspect exit status");
    assert!(
        !after.contains("ray tree"),
        "the main screen is back after quitting:\n{after}"
    );
}
