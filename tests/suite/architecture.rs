//! The shape of the house, checked from the source (see `../shared/DESIGN.md`):
//! folders by role, dependencies pointing one way, views that never run the
//! tracer, a scene model that knows nothing of the command line.
//!
//! Each library file's `crate::…` paths (outside comments) are read and checked
//! against the layers below, lowest first. A file may use its own folder and
//! any folder in a lower layer; `methods.rs` (the catalogue of method choices)
//! and `io/` (images and files) sit outside the layers: anyone may use them, and
//! they use nothing else of the crate.

use std::path::{Path, PathBuf};

/// The folders in layer order: each may use the ones before it.
const LAYERS: &[&str] = &[
    "math",
    "geometry",
    "shading",
    "scene",
    "trace",
    "tree",
    "views",
    "inspector",
];

/// Used by anyone, using nothing of the crate.
const FREE: &[&str] = &["methods", "io"];

/// What runs the tracer: views read the recorded tree instead.
const TRACING: &[&str] = &[
    "crate::trace::tracer",
    "crate::trace::accelerator",
    "crate::trace::render",
    "crate::trace::pixel",
    "crate::geometry::bvh",
];

/// The deliberate exceptions, each with its reason.
const EXCEPTIONS: &[(&str, &str, &str)] = &[
    (
        "src/inspector/",
        "crate::trace::",
        "the inspector traces the pixel you pick, and the preview, on demand",
    ),
    (
        "src/scene/overrides.rs",
        "clap",
        "one struct for the scene file's render block and the command-line flags",
    ),
];

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every library source file, relative to the crate root (`src/…`).
fn library_files() -> Vec<String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let mut files = Vec::new();
    walk(&src(), &mut files);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<String> = files
        .iter()
        .map(|p| p.strip_prefix(root).unwrap().display().to_string())
        .filter(|p| !p.starts_with("src/bin/"))
        .collect();
    names.sort();
    names
}

/// The file's code lines (comments dropped), numbered from 1.
fn code_lines(file: &str) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(file)).unwrap();
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim_start().starts_with("//"))
        .map(|(i, l)| (i + 1, l.to_owned()))
        .collect()
}

/// The top folder (or file stem) a path of the crate names: `crate::views::text` → `views`.
fn top(path: &str) -> &str {
    path.trim_start_matches("crate::")
        .split("::")
        .next()
        .unwrap_or("")
}

/// Where a library file sits: its folder, or its stem for a top-level file.
fn folder_of(file: &str) -> &str {
    let rest = file.trim_start_matches("src/");
    match rest.split_once('/') {
        Some((folder, _)) => folder,
        None => rest.trim_end_matches(".rs"),
    }
}

/// Every `crate::a::b…` path on a line.
fn crate_paths(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("crate::") {
        let tail = &rest[i..];
        let end = tail
            .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
            .unwrap_or(tail.len());
        out.push(tail[..end].trim_end_matches(':').to_owned());
        rest = &tail[end..];
    }
    out
}

fn excepted(file: &str, what: &str) -> bool {
    EXCEPTIONS
        .iter()
        .any(|(f, w, _)| file.starts_with(f) && what.starts_with(w))
}

/// Every breach of the rules, one line each.
fn breaches() -> Vec<String> {
    let rank = |folder: &str| LAYERS.iter().position(|l| *l == folder);
    let mut out = Vec::new();
    for file in library_files() {
        let here = folder_of(&file);
        for (n, line) in code_lines(&file) {
            if line.contains("crate::{") {
                out.push(format!(
                    "{file}:{n}: write one path per `use` so this test can read it"
                ));
            }
            for path in crate_paths(&line) {
                let there = top(&path);
                if there == here || excepted(&file, &path) {
                    continue;
                }
                if FREE.contains(&here) {
                    out.push(format!(
                        "{file}:{n}: {here} uses nothing of the crate, but names {path}"
                    ));
                } else if FREE.contains(&there) || there.is_empty() || there == "record" {
                    // `crate::record!` is the recorder's hook macro, exported at the root.
                } else if here == "views" && TRACING.iter().any(|t| path.starts_with(t)) {
                    out.push(format!(
                        "{file}:{n}: a view runs the tracer ({path}); views read the recorded tree"
                    ));
                } else if rank(there).is_none() || rank(there) > rank(here) {
                    out.push(format!(
                        "{file}:{n}: {here} uses {path}, a layer above it ({})",
                        LAYERS.join(" < ")
                    ));
                }
            }
            for tool in ["clap", "indicatif"] {
                let named =
                    line.contains(&format!("{tool}::")) || line.contains(&format!("use {tool}"));
                if here == "scene" && named && !excepted(&file, tool) {
                    out.push(format!(
                        "{file}:{n}: the scene model names {tool}; it knows nothing of the command line"
                    ));
                }
            }
        }
    }
    out
}

#[test]
fn dependencies_point_one_way() {
    let found = breaches();
    assert!(
        found.is_empty(),
        "the layers are broken:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_checker_sees_a_breach() {
    // The rules themselves, on made-up lines, so a checker that reads nothing fails here.
    assert_eq!(
        crate_paths("use crate::trace::tracer::Tracer; let x = crate::views::text::format(a);"),
        ["crate::trace::tracer::Tracer", "crate::views::text::format"]
    );
    assert_eq!(folder_of("src/views/text.rs"), "views");
    assert_eq!(folder_of("src/methods.rs"), "methods");
    assert!(excepted(
        "src/inspector/preview.rs",
        "crate::trace::tracer::Tracer"
    ));
    assert!(!excepted(
        "src/views/text.rs",
        "crate::trace::tracer::Tracer"
    ));
    assert!(library_files().len() > 40, "{:?}", library_files());
}

#[test]
fn src_shows_the_architecture() {
    // `ls src`: the folders by role, the catalogue of methods, the crate root, the binary.
    let mut top: Vec<String> = std::fs::read_dir(src())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    top.sort();
    let mut expected: Vec<String> = LAYERS
        .iter()
        .chain(FREE.iter().filter(|f| **f != "methods"))
        .map(|s| s.to_string())
        .chain(["bin", "lib.rs", "methods.rs"].map(String::from))
        .collect();
    expected.sort();
    assert_eq!(top, expected);
    // Small files: none over 600 lines.
    for file in library_files() {
        let lines = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(&file))
            .unwrap()
            .lines()
            .count();
        assert!(lines <= 600, "{file} has {lines} lines; split it by job");
    }
}
