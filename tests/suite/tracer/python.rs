//! The course's Python tracer (`lessons/python/`) against raytree: the
//! teacher's solution passes every lesson's test vectors, reproduces raytree's
//! rays and image on the Whitted scene at 64×48 and on each lesson's featured
//! pixel, and refuses what it cannot read in one line; the starter runs and
//! fails its vectors until the learner writes the functions.
//!
//! The ray-by-ray comparison and its tolerances are in
//! `lessons/python/tools/compare.py` (a tool a teacher runs too); these tests
//! run it and read its verdict.

use std::path::Path;
use std::process::{Command, Output};

use raytree::course::lesson;

use crate::tools::{Need, available};

/// Runs `python3 ARGS…` from the repository, with raytree the binary under test.
fn python(args: &[&str]) -> Output {
    Command::new("python3")
        .args(args)
        .env("RAYTREE", env!("CARGO_BIN_EXE_raytree"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("python3 runs")
}

fn text(out: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn here() -> bool {
    available("", &[Need::Python3], "runs the course's Python tracer")
}

/// Whether this raytree has `raytree check` (issue 25's oracle, built beside
/// this tracer): the comparisons then hand every learner trace to it too.
fn has_check() -> bool {
    Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["check", "--help"])
        .output()
        .is_ok_and(|o| o.status.success())
}

const SOLUTION: &str = "lessons/python/teacher/solution.py";
const STARTER: &str = "lessons/python/starter/tracer.py";
const COMPARE: &str = "lessons/python/tools/compare.py";

#[test]
fn the_python_solution_passes_every_lessons_vectors() {
    if !here() {
        return;
    }
    let out = python(&[SOLUTION, "test"]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stdout}{stderr}");
    // One case at least per function of lessons 03–11, none failed.
    let last = stdout.lines().last().unwrap_or_default();
    let passed: usize = last.split(' ').next().unwrap_or("0").parse().unwrap_or(0);
    assert!(passed >= 15 && last.ends_with(" 0 failed"), "{stdout}");
}

/// `raytree vectors SCENE` writes cases of every function from a scene's
/// pixels; the solution runs that file as it runs a lesson's, and a path
/// that is no file is one line, exit 2.
#[test]
fn the_python_solution_runs_a_scenes_vectors_file() {
    if !here() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("whitted-vectors.json");
    let made = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["vectors", "scenes/whitted.json", "-o"])
        .arg(&file)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(made.status.success(), "{:?}", made);
    let out = python(&[SOLUTION, "test", file.to_str().unwrap()]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stdout}{stderr}");
    let last = stdout.lines().last().unwrap_or_default();
    let passed: usize = last.split(' ').next().unwrap_or("0").parse().unwrap_or(0);
    assert!(passed >= 50 && last.ends_with(" 0 failed"), "{stdout}");
    let gone = dir.path().join("gone.json");
    let out = python(&[SOLUTION, "test", gone.to_str().unwrap()]);
    let (_, stderr) = text(&out);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("gone.json: no such vectors file"),
        "{stderr}"
    );
}

#[test]
fn the_python_starter_runs_and_fails_its_vectors_until_written() {
    if !here() {
        return;
    }
    let out = python(&[STARTER, "test"]);
    let (stdout, stderr) = text(&out);
    assert_eq!(out.status.code(), Some(1), "{stdout}{stderr}");
    assert!(
        stdout
            .lines()
            .last()
            .unwrap_or_default()
            .starts_with("0 passed"),
        "{stdout}"
    );
    // Each failure points to the lesson to read, not a traceback.
    let fails: Vec<&str> = stdout.lines().filter(|l| l.starts_with("FAIL")).collect();
    assert!(!fails.is_empty());
    for l in &fails {
        assert!(
            l.contains("not written yet") && l.contains("lessons/"),
            "{l}"
        );
    }
    for lesson in ["03", "05", "08", "10", "11"] {
        assert!(
            fails
                .iter()
                .any(|l| l.starts_with(&format!("FAIL {lesson}-"))),
            "{lesson}: {stdout}"
        );
    }
    // Rendering stops at the first function not written, in one line.
    let out = python(&[
        STARTER,
        "scenes/whitted.json",
        "--pixel",
        "1,1",
        "--width",
        "64",
        "--height",
        "48",
    ]);
    let (_, stderr) = text(&out);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("not written yet: primary_ray")
            || stderr.starts_with("not written yet: image_plane_point"),
        "{stderr}"
    );
}

#[test]
fn the_python_solution_refuses_scenes_outside_its_subset_in_one_line() {
    if !here() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "box.json",
            r#"{"objects": [{"box": {}}]}"#,
            "objects[0]: unknown or unsupported field 'box'",
        ),
        (
            "methods.json",
            r#"{"render": {"weights": "fresnel"}}"#,
            "render.weights",
        ),
        ("broken.json", r#"{"objects": ["#, "not JSON"),
    ];
    for (name, json, said) in cases {
        let path = dir.path().join(name);
        std::fs::write(&path, json).unwrap();
        let out = python(&[SOLUTION, path.to_str().unwrap(), "--pixel", "0,0"]);
        let (_, stderr) = text(&out);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{name}: {stderr}");
        assert!(
            stderr.contains(name) && stderr.contains(said),
            "{name}: {stderr}"
        );
    }
}

#[test]
fn the_python_solution_agrees_with_raytree_on_every_pixel_of_the_whitted_scene() {
    if !here() {
        return;
    }
    let mut args = vec![
        COMPARE,
        "scenes/whitted.json",
        "--width",
        "64",
        "--height",
        "48",
        "--all",
        "--image",
    ];
    if has_check() {
        args.push("--check");
    }
    let out = python(&args);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stdout}{stderr}");
    // Every pixel traced on both sides, and the two images the same bytes.
    assert!(stdout.contains(": 3072 pixels,"), "{stdout}");
    assert!(stdout.contains("image: 3072 pixels, 0 differ"), "{stdout}");
    if has_check() {
        assert!(
            stdout.contains("raytree check: 3072 of 3072 pixels check clean"),
            "{stdout}"
        );
    }
}

#[test]
fn the_python_solution_agrees_with_raytree_on_the_lessons_featured_pixels() {
    if !here() {
        return;
    }
    let lessons = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons");
    let mut by_scene: Vec<(String, Vec<String>)> = Vec::new();
    for number in 3..=11 {
        let loaded = lesson::load(&lessons, number).unwrap();
        let scene = loaded.script.scene.display().to_string();
        let [x, y] = loaded.script.pixel;
        match by_scene.iter_mut().find(|(s, _)| *s == scene) {
            Some((_, pixels)) => pixels.push(format!("{x},{y}")),
            None => by_scene.push((scene, vec![format!("{x},{y}")])),
        }
    }
    assert!(by_scene.len() >= 3, "{by_scene:?}");
    for (scene, pixels) in &by_scene {
        let mut args = vec![COMPARE, scene.as_str()];
        if has_check() {
            args.push("--check");
        }
        for p in pixels {
            args.extend(["--pixel", p.as_str()]);
        }
        let out = python(&args);
        let (stdout, stderr) = text(&out);
        assert!(out.status.success(), "{scene}: {stdout}{stderr}");
    }
}
