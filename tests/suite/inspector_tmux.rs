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

    let screen = wait_for(&session, |s| s.contains("ray tree") && s.contains("pixel "));
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

/// The learner at 80×24 in a plain tmux (no COLORTERM): one key to a
/// total internal reflection, step through it watching the tree grow, read
/// the full color sum, ask what if the glass had index 1.0, quit.
#[test]
fn a_learner_at_80x24_finds_steps_through_and_edits_a_total_internal_reflection() {
    if Command::new("tmux").arg("-V").output().is_err() {
        println!("skipped: tmux is not installed (.ci/run installs it)");
        return;
    }
    let root = env!("CARGO_MANIFEST_DIR");
    let session = format!("raytree-test-80x24-{}", std::process::id());
    let exit_file: PathBuf = std::env::temp_dir().join(format!("{session}.exit"));
    let _ = std::fs::remove_file(&exit_file);
    let command = format!(
        "cd {root} && env -u COLORTERM {} inspect scenes/whitted.json; echo $? > {}; sleep 60",
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
            "80",
            "-y",
            "24",
            &command,
        ])
        .status()
        .unwrap();
    assert!(started.success(), "tmux could not start a session");
    let send = |keys: &[&str]| {
        let mut args = vec!["send-keys", "-t", session.as_str()];
        args.extend_from_slice(keys);
        tmux(&args);
    };
    let capture = || tmux(&["capture-pane", "-t", &session, "-p"]);
    let kill = || {
        let _ = Command::new("tmux")
            .args(["kill-session", "-t", &session])
            .status();
    };
    let fail = |what: &str, screen: &str| -> ! {
        kill();
        panic!("{what}:\n{screen}");
    };

    let screen = wait_for(&session, |s| s.contains("ray tree") && s.contains("pixel "));
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
    // One key to a total internal reflection.
    send(&["f"]);
    let screen = wait_for(&session, |s| s.contains("found: total internal reflection"));
    if !screen.contains("found: total internal reflection") {
        fail("f finds a total internal reflection", &screen);
    }
    // Step to it: the tree grows one ray at a time.
    let mut rays_seen = Vec::new();
    let mut screen = String::new();
    for _ in 0..400 {
        send(&["n"]);
        std::thread::sleep(Duration::from_millis(15));
        screen = capture();
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
    // On to the last step, where the primary ray's color is summed.
    for _ in 0..400 {
        send(&["n"]);
        std::thread::sleep(Duration::from_millis(15));
        screen = capture();
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
    // What if the glass had index 1.0?
    send(&["x", "m"]);
    send(&["-l", "ior=1.0"]);
    send(&["Enter"]);
    let screen = wait_for(&session, |s| s.contains("what if"));
    if !(screen.contains("what if") && screen.contains("ior=1.0") && screen.contains(" → ")) {
        fail("the edit shows before → after", &screen);
    }
    send(&["q"]);
    let started = Instant::now();
    while !exit_file.exists() && started.elapsed() < Duration::from_secs(10) {
        std::thread::sleep(Duration::from_millis(100));
    }
    let status = std::fs::read_to_string(&exit_file).unwrap_or_default();
    let after = capture();
    kill();
    let _ = std::fs::remove_file(&exit_file);
    assert_eq!(status.trim(), "0", "raytree inspect exit status");
    assert!(
        !after.contains("ray tree"),
        "the main screen is back after quitting:\n{after}"
    );
}
