//! Every file of the repository that a lesson or a doc names (`format:
//! src/course/guide/script.rs`, `see docs/commands.md`) exists: thirteen scripts
//! once pointed their readers to a guide.rs that had moved.

use std::path::{Path, PathBuf};

use super::book::run::root;

/// The folders a named path starts with, and the files it may be.
const FOLDERS: &[&str] = &["src/", "tests/", "lessons/", "docs/", "scenes/", "book/"];
const KINDS: &[&str] = &[".rs", ".md", ".toml", ".json", ".py"];

/// The lessons' files and the docs a reader opens.
fn read_by_people() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap().flatten() {
            let p = entry.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "md" || e == "toml") {
                out.push(p);
            }
        }
    }
    let root = root();
    let mut out = Vec::new();
    for dir in ["lessons", "docs", "book/pages", "scenes"] {
        walk(&root.join(dir), &mut out);
    }
    out.extend(["README.md", "ARCHITECTURE.md"].map(|f| root.join(f)));
    out
}

/// The repository paths `line` names: words of path characters starting
/// with one of [`FOLDERS`] and ending in one of [`KINDS`]. A placeholder
/// (`lessons/NN-topic/…`, `scenes/mine.json`) names no file.
fn named_paths(line: &str) -> Vec<&str> {
    line.split(|c: char| !(c.is_ascii_alphanumeric() || "_./-".contains(c)))
        .map(|w| w.trim_end_matches('.'))
        .filter(|w| FOLDERS.iter().any(|f| w.starts_with(f)))
        .filter(|w| KINDS.iter().any(|k| w.ends_with(k)))
        .filter(|w| !w.contains("NN") && !w.contains("mine"))
        .collect()
}

#[test]
fn every_path_a_lesson_or_doc_names_exists() {
    let mut missing = Vec::new();
    for file in read_by_people() {
        let text = std::fs::read_to_string(&file).unwrap();
        for (i, line) in text.lines().enumerate() {
            for path in named_paths(line) {
                if !root().join(path).exists() {
                    let at = file.strip_prefix(root()).unwrap_or(&file).display();
                    missing.push(format!("{at}:{}: {path}", i + 1));
                }
            }
        }
    }
    assert!(missing.is_empty(), "no such file:\n{}", missing.join("\n"));
}

#[test]
fn named_paths_are_found_in_comments_and_prose() {
    assert_eq!(
        named_paths("# The step-through (format: src/views/guide.rs)."),
        ["src/views/guide.rs"]
    );
    assert_eq!(
        named_paths("see `docs/commands.md`, lessons/NN-topic/vectors.json"),
        ["docs/commands.md"]
    );
}
