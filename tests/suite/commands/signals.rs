//! SIGINT, SIGTERM, SIGHUP and SIGQUIT (issue 29) end raytree cleanly (issue 12): a writing command
//! leaves no pending file and exits 128 + the signal's number; the inspector
//! gives the terminal back (main screen, cooked mode) before it exits;
//! `raytree postscript` ends Ghostscript and removes its folder (issue 29).

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::inspector::tmux::{Session, has_tmux};

const SIGNALS: [(&str, i32); 4] = [("INT", 2), ("TERM", 15), ("HUP", 1), ("QUIT", 3)];

fn kill(signal: &str, pid: u32) {
    let sent = Command::new("kill")
        .args([format!("-{signal}"), pid.to_string()])
        .status()
        .unwrap();
    assert!(sent.success(), "kill -{signal} {pid}");
}

fn names_in(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect()
}

#[test]
fn each_signal_during_a_render_leaves_no_file() {
    for (signal, number) in SIGNALS {
        let dir = tempfile::tempdir().unwrap();
        let child = Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args([
                "render", "--width", "4000", "--height", "3000", "--spp", "64", "-o", "big.png",
            ])
            .current_dir(dir.path())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // The temporary file exists once the render has started.
        let started = Instant::now();
        while names_in(dir.path()).is_empty() && started.elapsed() < Duration::from_secs(10) {
            std::thread::sleep(Duration::from_millis(10));
        }
        assert!(
            !names_in(dir.path()).is_empty(),
            "SIG{signal}: the render never started"
        );
        kill(signal, child.id());
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(
            out.status.code(),
            Some(128 + number),
            "SIG{signal}: {stderr}"
        );
        assert!(
            stderr.trim_end().ends_with(": no output written"),
            "SIG{signal}: {stderr}"
        );
        assert!(
            names_in(dir.path()).is_empty(),
            "SIG{signal}: left behind {:?}",
            names_in(dir.path())
        );
    }
}

/// A signal's word is the one line on standard error: no empty line before
/// it (which ends a progress bar's line) when no bar was drawn, with `-q` or
/// with standard error not a terminal.
#[test]
fn a_signal_s_word_is_one_line_without_a_bar() {
    for quiet in [true, false] {
        let dir = tempfile::tempdir().unwrap();
        let mut args = vec![
            "render", "--width", "4000", "--height", "3000", "--spp", "64", "-o", "big.png",
        ];
        if quiet {
            args.push("-q");
        }
        let child = Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(&args)
            .current_dir(dir.path())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let started = Instant::now();
        while names_in(dir.path()).is_empty() && started.elapsed() < Duration::from_secs(10) {
            std::thread::sleep(Duration::from_millis(10));
        }
        kill("TERM", child.id());
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(128 + 15), "quiet {quiet}");
        assert_eq!(
            String::from_utf8_lossy(&out.stderr),
            "terminated (SIGTERM): no output written\n",
            "quiet {quiet}"
        );
    }
}

/// Runs the inspector in a tmux pane, sends it `signal` once it has drawn, and
/// returns its exit status and the terminal's settings after it ended.
fn inspector_after(signal: &str) -> (String, String, String) {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().display();
    // `exec` makes the shell's pid raytree's; the pane's shell then reports.
    let command = format!(
        "sh -c 'echo $$ > {d}/pid; exec {} inspect --width 64 --height 48'; echo $? > {d}/exit; stty -a > {d}/stty; sleep 30",
        env!("CARGO_BIN_EXE_raytree")
    );
    let session = Session::start(&format!("signal-{signal}"), 100, 30, &command);
    let wait = |ok: &dyn Fn() -> bool| {
        let started = Instant::now();
        while !ok() && started.elapsed() < Duration::from_secs(20) {
            std::thread::sleep(Duration::from_millis(50));
        }
    };
    wait(&|| session.capture().contains("ray tree"));
    let pid: u32 = std::fs::read_to_string(dir.path().join("pid"))
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    kill(signal, pid);
    wait(&|| dir.path().join("stty").exists());
    std::thread::sleep(Duration::from_millis(100));
    let screen = session.capture();
    drop(session);
    let read = |f: &str| std::fs::read_to_string(dir.path().join(f)).unwrap_or_default();
    (read("exit"), read("stty"), screen)
}

#[test]
fn each_signal_gives_the_inspector_s_terminal_back() {
    if !has_tmux() {
        return;
    }
    for (signal, number) in SIGNALS {
        let (exit, stty, screen) = inspector_after(signal);
        assert_eq!(
            exit.trim(),
            (128 + number).to_string(),
            "SIG{signal}:\n{screen}"
        );
        // Cooked mode again: line editing and echo on.
        let words: Vec<&str> = stty.split_whitespace().collect();
        assert!(
            words.contains(&"icanon") && words.contains(&"echo"),
            "SIG{signal}: {stty}"
        );
        assert!(
            !screen.contains("ray tree"),
            "SIG{signal}: still on the inspector's screen:\n{screen}"
        );
    }
}

/// The pids of `pid`'s children, from /proc (every thread's list).
fn children_of(pid: u32) -> Vec<u32> {
    let Ok(tasks) = std::fs::read_dir(format!("/proc/{pid}/task")) else {
        return Vec::new();
    };
    tasks
        .filter_map(|t| std::fs::read_to_string(t.ok()?.path().join("children")).ok())
        .flat_map(|s| {
            s.split_whitespace()
                .filter_map(|p| p.parse().ok())
                .collect::<Vec<u32>>()
        })
        .collect()
}

/// Whether process `pid` exists and is not a zombie.
fn alive(pid: u32) -> bool {
    std::fs::read_to_string(format!("/proc/{pid}/stat")).is_ok_and(|stat| {
        // The state follows the command's closing parenthesis.
        stat.rsplit_once(')')
            .is_some_and(|(_, rest)| !rest.trim_start().starts_with('Z'))
    })
}

/// Issue 29: SIGTERM or SIGHUP while Ghostscript runs a program that never
/// ends used to leave Ghostscript looping on as an orphan, and its
/// temporary folder behind.
#[test]
fn a_signal_during_postscript_ends_ghostscript_and_leaves_no_folder() {
    use crate::tools::{Need, available};
    if !available("", &[Need::Ghostscript], "raytree postscript runs it") {
        return;
    }
    for (signal, number) in [("TERM", 15), ("HUP", 1)] {
        let dir = tempfile::tempdir().unwrap();
        let temp = dir.path().join("tmp");
        std::fs::create_dir(&temp).unwrap();
        std::fs::write(dir.path().join("loop.ps"), "%!PS\n{} loop\n").unwrap();
        let child = Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(["postscript", "loop.ps", "--timeout", "60"])
            .current_dir(dir.path())
            .env("TMPDIR", &temp)
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let started = Instant::now();
        let mut gs = children_of(child.id());
        while gs.is_empty() && started.elapsed() < Duration::from_secs(10) {
            std::thread::sleep(Duration::from_millis(20));
            gs = children_of(child.id());
        }
        assert_eq!(gs.len(), 1, "SIG{signal}: Ghostscript never started");
        let gs = gs[0];
        // Let Ghostscript read the program and start looping.
        std::thread::sleep(Duration::from_millis(300));
        assert!(alive(gs), "SIG{signal}: Ghostscript ended by itself");
        kill(signal, child.id());
        let sent = Instant::now();
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            sent.elapsed() < Duration::from_secs(5),
            "SIG{signal}: raytree took {:?} to end",
            sent.elapsed()
        );
        assert_eq!(
            out.status.code(),
            Some(128 + number),
            "SIG{signal}: {stderr}"
        );
        while alive(gs) && sent.elapsed() < Duration::from_secs(3) {
            std::thread::sleep(Duration::from_millis(20));
        }
        let orphan = alive(gs);
        if orphan {
            kill("KILL", gs);
        }
        assert!(!orphan, "SIG{signal}: Ghostscript ({gs}) still runs");
        assert!(
            names_in(&temp).is_empty(),
            "SIG{signal}: left behind in the temporary folder {:?}",
            names_in(&temp)
        );
        let mut left = names_in(dir.path());
        left.sort();
        assert_eq!(
            left,
            ["loop.ps", "tmp"],
            "SIG{signal}: no pending output left"
        );
    }
}
