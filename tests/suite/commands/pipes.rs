//! A closed pipe ends quietly (issue 24), as `raytree … | head` expects: every
//! command that prints, its standard output a pipe whose reader is gone
//! before it starts (and, in a second run, its standard error too), exits 0
//! (`diff` with its answer, 1 for images that differ) without a panic, and a
//! file it was asked for is whole (the same bytes as a run with nobody
//! closing anything) or not there at all.

use std::path::Path;
use std::process::{Command, Output, Stdio};

/// How a run's streams end.
#[derive(Clone, Copy, Debug)]
enum Closed {
    /// Standard output is a pipe nobody reads; standard error is kept.
    Stdout,
    /// Both are pipes nobody reads.
    Both,
}

/// Runs raytree in `dir` with its standard input empty and the streams of
/// `closed` pipes whose reading end is closed before the process starts, so
/// its first write to them fails (EPIPE), whatever the timing.
fn run_closed(args: &[&str], dir: &Path, closed: Closed) -> Output {
    let gone = || {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        writer
    };
    let mut command = Command::new(env!("CARGO_BIN_EXE_raytree"));
    command
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(gone());
    match closed {
        Closed::Stdout => command.stderr(Stdio::piped()),
        Closed::Both => command.stderr(gone()),
    };
    command.output().expect("the binary runs")
}

/// The files in `dir`, sorted, with their bytes.
fn files_in(dir: &Path) -> Files {
    let mut files: Files = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (
                e.file_name().into_string().unwrap(),
                std::fs::read(e.path()).unwrap(),
            )
        })
        .collect();
    files.sort();
    files
}

/// The commands that print, each with small sizes; the files each writes.
fn commands() -> Vec<(Vec<&'static str>, Vec<&'static str>)> {
    let small = ["--width", "64", "--height", "48"];
    let with = |args: &[&'static str], files: &[&'static str]| (args.to_vec(), files.to_vec());
    let sized = |args: &[&'static str], files: &[&'static str]| {
        ([args, &small[..]].concat(), files.to_vec())
    };
    vec![
        sized(&["render", "-o", "r.png"], &["r.png"]),
        sized(&["render", "--stats", "-o", "r.png"], &["r.png"]),
        sized(&["render", "--aov", "depth", "-o", "a.png"], &["a.png"]),
        sized(&["trace", "--pixel", "30,20"], &[]),
        sized(&["trace", "--pixel", "30,20", "--json"], &[]),
        sized(&["trace", "--pixel", "30,20", "--steps"], &[]),
        sized(&["trace", "--pixel", "30,20", "-o", "t.json"], &["t.json"]),
        sized(
            &[
                "diagram", "--pixel", "30,20", "--size", "320x240", "-o", "d.png",
            ],
            &["d.png"],
        ),
        sized(
            &["strip", "--vary", "max_depth=1..3", "-o", "s.png"],
            &["s.png"],
        ),
        sized(&["forward", "--photons", "1000", "-o", "f.png"], &["f.png"]),
        sized(
            &[
                "chart", "--cost", "tests", "--runs", "1", "--size", "320x240", "-o", "c.png",
            ],
            &["c.png"],
        ),
        sized(
            &[
                "structures",
                "--runs",
                "1",
                "--size",
                "480x320",
                "-o",
                "st.png",
                concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/whitted.json"),
            ],
            &["st.png"],
        ),
        with(&["diff", "one.png", "two.png"], &[]),
        with(&["diff", "one.png", "two.png", "-o", "d.png"], &["d.png"]),
        with(&["postscript", "--slips"], &[]),
        with(&["lesson", "--lessons", "LESSONS"], &[]),
        with(&["lesson", "1", "--text", "--lessons", "LESSONS"], &[]),
        with(
            &["generate", "spheres", "--count", "3", "-o", "g.json"],
            &["g.json"],
        ),
        with(
            &["generate", "icosphere", "--triangles", "20", "-o", "i.json"],
            &["i.json", "i.obj"],
        ),
        with(&["--help"], &[]),
        with(&["--version"], &[]),
        with(&["help", "strip"], &[]),
        with(&["strip", "--help"], &[]),
    ]
}

/// A file's name and bytes.
type Files = Vec<(String, Vec<u8>)>;

#[test]
fn a_closed_pipe_ends_every_command_quietly() {
    let lessons = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons");
    let lessons = lessons.to_str().unwrap();
    let inputs = images_to_diff();
    let mut failures = Vec::new();
    for (args, outputs) in commands() {
        let args: Vec<&str> = args
            .iter()
            .map(|&a| if a == "LESSONS" { lessons } else { a })
            .collect();
        let line = format!("raytree {}", args.join(" "));
        // diff's exit status is its answer: 1, these images differ.
        let answer = if args[0] == "diff" { Some(1) } else { Some(0) };
        let expected = run_open(&args, &inputs, &line, answer);
        for closed in [Closed::Stdout, Closed::Both] {
            failures.extend(closed_run_failures(
                &args, &inputs, closed, &line, answer, &expected,
            ));
            for name in &outputs {
                assert!(
                    expected.iter().any(|(n, _)| n == name),
                    "{line}: the open run wrote no {name}"
                );
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The two images `diff` compares, made once: their names and bytes.
fn images_to_diff() -> Files {
    let images = tempfile::tempdir().unwrap();
    for (name, depth) in [("one.png", "1"), ("two.png", "3")] {
        let made = Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args([
                "render",
                "-q",
                "--width",
                "64",
                "--height",
                "48",
                "--max-depth",
                depth,
                "-o",
                name,
            ])
            .current_dir(images.path())
            .output()
            .unwrap();
        assert!(made.status.success(), "{made:?}");
    }
    files_in(images.path())
}

/// A fresh folder holding `inputs`.
fn fresh(inputs: &Files) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in inputs {
        std::fs::write(dir.path().join(name), bytes).unwrap();
    }
    dir
}

/// What a run of `args` (the command `line`) with nobody closing anything
/// writes, in a fresh folder holding `inputs`: it exits with `answer` and
/// prints something (else it tests nothing here).
fn run_open(args: &[&str], inputs: &Files, line: &str, answer: Option<i32>) -> Files {
    let open = fresh(inputs);
    let whole = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(open.path())
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(
        whole.status.code(),
        answer,
        "{line}: {}",
        String::from_utf8_lossy(&whole.stderr)
    );
    assert!(
        !whole.stdout.is_empty() || !whole.stderr.is_empty(),
        "{line} prints nothing: it tests nothing here"
    );
    files_in(open.path())
}

/// What went wrong in a run of `args` with the streams of `closed` closed:
/// an exit other than `answer`, a panic, or a file that is not one the open
/// run wrote (`expected`), whole.
fn closed_run_failures(
    args: &[&str],
    inputs: &Files,
    closed: Closed,
    line: &str,
    answer: Option<i32>,
    expected: &Files,
) -> Vec<String> {
    let mut failures = Vec::new();
    let dir = fresh(inputs);
    let out = run_closed(args, dir.path(), closed);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if out.status.code() != answer || stderr.contains("panicked") {
        failures.push(format!(
            "{line} ({closed:?} closed): exit {:?}, stderr {stderr:?}",
            out.status.code()
        ));
    }
    // Whole or absent: each output is what the open run wrote, or missing;
    // nothing else is left behind (no temporary file).
    for (name, bytes) in files_in(dir.path()) {
        if !is_whole(&name, &bytes, expected) {
            failures.push(format!(
                "{line} ({closed:?} closed): {name} is not a whole output"
            ));
        }
    }
    failures
}

/// Whether file `name` holding `bytes` is one of the open run's outputs
/// (`expected`), whole.
fn is_whole(name: &str, bytes: &[u8], expected: &Files) -> bool {
    let same = expected.iter().find(|(n, _)| *n == name);
    match same {
        // The chart is drawn from test counts, which are exact;
        // still, any complete PNG of the right size will do. The
        // structures chart shows times, the date and the load,
        // which change from run to run.
        Some((_, want)) if name == "c.png" || name == "st.png" => image::load_from_memory(bytes)
            .is_ok_and(|i| image::load_from_memory(want).unwrap().width() == i.width()),
        Some((_, want)) => *want == bytes,
        None => false,
    }
}

#[test]
fn only_the_output_module_writes_to_the_streams() {
    // The lint in main.rs refuses print! and eprint!; this refuses the
    // streams' handles, which would let a write around the door.
    let bin = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/bin/raytree");
    let mut found = Vec::new();
    for entry in std::fs::read_dir(&bin).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if name == "output.rs" {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap();
            // `stdout()` called as a function (not `use_stderr()`, nor a
            // child's `.stdout(…)`), and clap's `.print()`.
            let names = |word: &str| {
                code.match_indices(word).any(|(i, _)| {
                    !code[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_' || c == '.')
                })
            };
            if names("stdout(") || names("stderr(") || code.contains(".print()") {
                found.push(format!("src/bin/raytree/{name}:{}: {}", n + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "write through output.rs, the one door out:\n{}",
        found.join("\n")
    );
}
