//! Mutants prove the diagnoses (issue 25, part 7): each mutant of
//! `lessons/python/tools/mutants.py` is the teacher's Python solution with one
//! classic mistake applied; `raytree check --json` must name its diagnosis
//! at its ray as the first divergence, and the unmutated solution must check
//! clean on the same pixel. Every diagnosis `raytree check` knows has a
//! mutant. The mutants the book shows (one for each of lessons 03–11, in
//! `lessons/NN-topic/mutant.json`) are made again and compared with the
//! committed files; `RAYTREE_BLESS=1` rewrites them. Every mutant's report,
//! JSON and text, is held to `tests/reports/mutants.json`: the JSON
//! report is a contract with autograders, so a change of its words or ids
//! shows there first.

use std::path::Path;
use std::process::{Command, Output};

use raytree::course::learner::mistakes::Mistake;
use serde_json::Value;

use crate::tools::{Need, available};

const MUTANTS: &str = "lessons/python/tools/mutants.py";

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn run(program: &str, args: &[&str]) -> Output {
    Command::new(program)
        .args(args)
        .current_dir(root())
        .output()
        .unwrap_or_else(|e| panic!("{program}: {e}"))
}

fn said(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// Checks mutant `m` (written to `dir` with its unmutated solution): its
/// report names its diagnosis at its ray as the first divergence, and the
/// solution checks clean. Returns its reports, JSON and text.
fn check_mutant(m: &Value, dir: &Path) -> Value {
    let raytree = env!("CARGO_BIN_EXE_raytree");
    let name = m["name"].as_str().unwrap();
    let scene = m["scene"].as_str().unwrap();
    let pixel = format!("{},{}", m["pixel"][0], m["pixel"][1]);
    let file = dir.join(format!("{name}.json"));
    let out = run(
        raytree,
        &[
            "check",
            scene,
            "--pixel",
            &pixel,
            file.to_str().unwrap(),
            "--json",
        ],
    );
    assert_eq!(out.status.code(), Some(1), "{name}: {}", said(&out));
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    let text = run(
        raytree,
        &["check", scene, "--pixel", &pixel, file.to_str().unwrap()],
    );
    let first = &report["first"];
    assert_eq!(first["ray"], m["ray"], "{name}: {first:#}");
    assert_eq!(
        first["diagnosis"]["id"], m["diagnosis"],
        "{name}: {first:#}"
    );
    let clean = dir.join(format!("{name}.clean.json"));
    let unmutated = run(
        raytree,
        &["check", scene, "--pixel", &pixel, clean.to_str().unwrap()],
    );
    assert_eq!(
        unmutated.status.code(),
        Some(0),
        "{name} unmutated: {}",
        said(&unmutated)
    );
    serde_json::json!({
        "json": String::from_utf8_lossy(&out.stdout),
        "text": String::from_utf8_lossy(&text.stdout),
    })
}

/// `made` is the committed file `committed` (`RAYTREE_BLESS=1` writes it).
fn is_current(committed: &Path, made: &[u8], what: &str) {
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::write(committed, made).unwrap();
    }
    let now = std::fs::read(committed).unwrap_or_default();
    assert!(
        now == made,
        "{} is stale{what}: RAYTREE_BLESS=1 cargo test --release every_mutant",
        committed.display()
    );
}

#[test]
fn every_mutant_is_diagnosed_at_its_ray_and_the_solution_checks_clean() {
    if !available("", &[Need::Python3], "runs the course's Python mutants") {
        return;
    }
    let out = run("python3", &[MUTANTS, "table"]);
    assert!(out.status.success(), "{}", said(&out));
    let table: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().display().to_string();
    let out = run("python3", &[MUTANTS, "write", &folder]);
    assert!(out.status.success(), "{}", said(&out));
    let mut shown: Vec<String> = Vec::new();
    let mut reports = serde_json::Map::new();
    for m in &table {
        let name = m["name"].as_str().unwrap();
        reports.insert(name.to_owned(), check_mutant(m, dir.path()));
        // The book's mutant of this lesson, committed and current.
        if let Some(lesson) = m["lesson"].as_str() {
            let committed = root().join("lessons").join(lesson).join("mutant.json");
            let made = std::fs::read(dir.path().join(format!("{name}.json"))).unwrap();
            is_current(&committed, &made, "");
            shown.push(lesson[..2].to_owned());
        }
    }
    let made = serde_json::to_string_pretty(&Value::Object(reports)).unwrap() + "\n";
    is_current(
        &root().join("tests/reports/mutants.json"),
        made.as_bytes(),
        " (a mutant's report changed)",
    );
    // No diagnosis without its mutant.
    for mistake in Mistake::ALL {
        let id = mistake.id();
        assert!(
            table.iter().any(|m| m["diagnosis"] == id),
            "{id}: no mutant shows it"
        );
    }
    // One mutant for the book in each of lessons 03–11.
    shown.sort();
    let lessons: Vec<String> = (3..=11).map(|n| format!("{n:02}")).collect();
    assert_eq!(shown, lessons);
}

#[test]
fn a_mutant_whose_text_no_longer_applies_stops_in_one_line() {
    if !available("", &[Need::Python3], "runs the course's Python mutants") {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let solution = std::fs::read_to_string(root().join("lessons/python/teacher/solution.py"))
        .unwrap()
        .replace("eta = n1 / n2", "eta = n1/n2");
    let changed = dir.path().join("solution.py");
    std::fs::write(&changed, solution).unwrap();
    let folder = dir.path().display().to_string();
    for (args, word) in [
        (
            vec![MUTANTS, "write", &folder, "no-such-mutant"],
            "no-such-mutant",
        ),
        (
            vec![MUTANTS, "write", &folder, "eta-swapped"],
            "found 0 times",
        ),
    ] {
        let out = Command::new("python3")
            .args(&args)
            .env("MUTANTS_SOLUTION", &changed)
            .current_dir(root())
            .output()
            .unwrap();
        let text = said(&out);
        assert_eq!(out.status.code(), Some(2), "{text}");
        assert_eq!(text.lines().count(), 1, "{text}");
        assert!(text.contains(word), "{text}");
    }
}

/// Each lesson's own mutant (the one its chapter shows) fails that lesson's
/// test vectors: the unit tests a learner runs first catch the mistake the
/// lesson warns of, before a whole pixel is checked.
#[test]
fn each_lessons_mutant_fails_its_lessons_test_vectors() {
    if !available("", &[Need::Python3], "runs the course's Python mutants") {
        return;
    }
    let out = run("python3", &[MUTANTS, "table"]);
    assert!(out.status.success(), "{}", said(&out));
    let table: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
    let solution =
        std::fs::read_to_string(root().join("lessons/python/teacher/solution.py")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("teacher")).unwrap();
    let copy = dir.path().join("teacher/solution.py");
    let mut tried = 0;
    for m in &table {
        let Some(lesson) = m["lesson"].as_str() else {
            continue;
        };
        let (find, replace) = (m["find"].as_str().unwrap(), m["replace"].as_str().unwrap());
        assert_eq!(solution.matches(find).count(), 1, "{lesson}: {find}");
        std::fs::write(&copy, solution.replace(find, replace)).unwrap();
        // The copy finds the course's plumbing (learner_io) by the path.
        let out = Command::new("python3")
            .arg(&copy)
            .args(["test", &lesson[..2]])
            .env("PYTHONPATH", root().join("lessons/python"))
            .current_dir(root())
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(1), "{lesson}: {}", said(&out));
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            stdout
                .lines()
                .any(|l| l.starts_with(&format!("FAIL {lesson} "))),
            "{lesson}: {stdout}"
        );
        tried += 1;
    }
    assert_eq!(tried, 9, "one mutant a lesson, 03–11");
}
