//! The real binary in a real terminal: tmux runs `raytree inspect`, keys are
//! typed, the screen is read back, and the exit status is checked.
//! Skipped, saying so, when tmux is not installed (`.ci/run` installs it).

use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

pub fn tmux(args: &[&str]) -> String {
    let out = Command::new("tmux").args(args).output().expect("tmux runs");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Waits until the captured screen satisfies `ok`, up to 20 s; returns the last capture.
fn wait_for(session: &str, ok: impl Fn(&str) -> bool) -> String {
    let started = Instant::now();
    loop {
        let screen = tmux(&["capture-pane", "-t", session, "-p"]);
        if ok(&screen) || started.elapsed() > Duration::from_secs(20) {
            return screen;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
}

#[test]
fn inspect_in_a_real_terminal() {
    if Command::new("tmux").arg("-V").output().is_err() {
        println!(
            "skipped: tmux is not installed, so the inspector cannot be driven in a real terminal here (.ci/run installs it)"
        );
        return;
    }
    let root = env!("CARGO_MANIFEST_DIR");
    let session = format!("raytree-test-{}", std::process::id());
    let exit_file: PathBuf = std::env::temp_dir().join(format!("{session}.exit"));
    let _ = std::fs::remove_file(&exit_file);
    let command = format!(
        "cd {root} && {} inspect scenes/whitted.json; echo $? > {}; sleep 60",
        env!("CARGO_BIN_EXE_raytree"),
        exit_file.display()
    );
    let started = Command::new("tmux")
        .args([
            "new-session",
            "-d",
            "-s",
            &session,
            "-x",
            "160",
            "-y",
            "48",
            &command,
        ])
        .status()
        .unwrap();
    assert!(started.success(), "tmux could not start a session");
    let kill = || {
        let _ = Command::new("tmux")
            .args(["kill-session", "-t", &session])
            .status();
    };

    let screen = wait_for(&session, |s| {
        s.contains("ray tree") && s.contains("pixel 320,240")
    });
    if !screen.contains("ray tree") {
        kill();
        panic!("the inspector did not start:\n{screen}");
    }
    // Go to a pixel on the glass sphere, as a user would: g, the coordinates, Enter.
    tmux(&[
        "send-keys",
        "-t",
        &session,
        "g",
        "4",
        "1",
        "6",
        ",",
        "2",
        "0",
        "9",
        "Enter",
    ]);
    let screen = wait_for(&session, |s| {
        s.contains("pixel 416,209") && s.contains("primary d1 'glass'")
    });
    assert!(
        screen.contains("refracted d2"),
        "the glass pixel's tree shows its refracted ray:\n{screen}"
    );
    assert!(
        !screen.contains("reflected d3"),
        "deeper rays stay folded until expanded:\n{screen}"
    );
    // Into the tree, down to the refracted ray, and open it.
    tmux(&[
        "send-keys",
        "-t",
        &session,
        "Tab",
        "Down",
        "Down",
        "Down",
        "Down",
        "Enter",
    ]);
    let screen = wait_for(&session, |s| s.contains("reflected d3"));
    assert!(
        screen.contains("reflected d3") && screen.contains("total internal reflection"),
        "the refracted ray opens:\n{screen}"
    );
    tmux(&["send-keys", "-t", &session, "q"]);
    let started = Instant::now();
    while !exit_file.exists() && started.elapsed() < Duration::from_secs(10) {
        std::thread::sleep(Duration::from_millis(100));
    }
    let status = std::fs::read_to_string(&exit_file).unwrap_or_default();
    let after = tmux(&["capture-pane", "-t", &session, "-p"]);
    kill();
    let _ = std::fs::remove_file(&exit_file);
    assert_eq!(status.trim(), "0", "raytree inspect exit status");
    assert!(
        !after.contains("ray tree"),
        "the main screen is back after quitting:\n{after}"
    );
}
