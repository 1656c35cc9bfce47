//! Runs that end well (issue 29): a script's pixel off the image is refused.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs raytree with `args` in a fresh folder holding `files` and expects a
/// refusal within a few seconds (a run that would not finish is killed, and
/// fails the test): exit code `code`, one line on stderr, no file added.
/// Returns the line.
fn refused_at_once(code: i32, files: &[(&str, &[u8])], args: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    for (file, bytes) in files {
        std::fs::write(dir.path().join(file), bytes).unwrap();
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(dir.path())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // A refusal comes before any work: seconds are ample on a busy machine.
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(20) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("raytree {}: still running after 20 s", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let shown = args.join(" ");
    assert_eq!(out.status.code(), Some(code), "raytree {shown}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "raytree {shown}: {stderr:?}");
    assert!(stderr.starts_with("error: "), "raytree {shown}: {stderr}");
    let left = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(left, files.len(), "raytree {shown}: a file was left");
    stderr.trim_end().to_owned()
}

#[test]
fn a_scripts_pixel_off_the_image_is_refused_by_inspect_as_by_lesson() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lessons = tempfile::tempdir().unwrap();
    let folder = lessons.path().join("01-off");
    std::fs::create_dir(&folder).unwrap();
    std::fs::copy(
        root.join("lessons/01-forward/lesson.toml"),
        folder.join("lesson.toml"),
    )
    .unwrap();
    let scene = root.join("scenes/whitted.json");
    let script = folder.join("steps.toml");
    std::fs::write(
        &script,
        format!(
            "title = \"Off the image\"\nscene = {:?}\npixel = [640, 10]\n\n[[stop]]\nstep = 1\nsay = \"here\"\n",
            scene.to_str().unwrap()
        ),
    )
    .unwrap();
    let expected = format!(
        "error: {}: line 3: pixel 640,10 is outside the 640×480 image (x is 0 to 639, y is 0 to 479)",
        script.display()
    );
    let inspect = refused_at_once(1, &[], &["inspect", "--script", script.to_str().unwrap()]);
    assert_eq!(inspect, expected);
    let lesson = refused_at_once(
        1,
        &[],
        &[
            "lesson",
            "1",
            "--text",
            "--lessons",
            lessons.path().to_str().unwrap(),
        ],
    );
    assert_eq!(lesson, expected);
}
