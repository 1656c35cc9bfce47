//! The built book's code blocks fit [`CODE_WIDTH`]: a trace excerpt, a
//! command's help or a scene file wider than that runs off a phone's screen
//! and a printed page. Counted in characters, not bytes: `θ₁` and `×` are one
//! column each.

use std::path::Path;

use super::make::CODE_WIDTH;
use super::run::root;

/// Every line wider than [`CODE_WIDTH`] in a fenced code block of `markdown`:
/// its line number (from 1) and width.
fn too_wide(markdown: &str) -> Vec<(usize, usize)> {
    let mut inside = false;
    let mut out = Vec::new();
    for (i, line) in markdown.lines().enumerate() {
        let fence = ["```", "~~~"]
            .iter()
            .any(|f| line.trim_start().starts_with(f));
        let width = line.chars().count();
        if inside && !fence && width > CODE_WIDTH {
            out.push((i + 1, width));
        }
        inside ^= fence;
    }
    out
}

pub(super) fn markdown_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let p = entry.path();
        if p.is_dir() {
            markdown_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "md") {
            out.push(p);
        }
    }
}

#[test]
fn every_code_block_of_the_built_book_fits_its_width() {
    let mut files = Vec::new();
    markdown_files(&root().join("book/src"), &mut files);
    files.sort();
    assert!(
        files.len() > 14,
        "the book has a chapter per lesson: {files:?}"
    );
    let mut wide = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let rel = path.strip_prefix(root()).unwrap().display();
        for (line, width) in too_wide(&text) {
            wide.push(format!("{rel}: line {line}: {width} characters"));
        }
    }
    assert!(
        wide.is_empty(),
        "code block lines wider than {CODE_WIDTH} characters (the book wraps them when made: \
         `RAYTREE_BLESS=1 cargo test --release book`):\n{}",
        wide.join("\n")
    );
}

#[test]
fn a_wide_line_is_found_only_inside_a_code_block_and_counted_in_characters() {
    let wide = "θ".repeat(CODE_WIDTH + 1);
    let fits = "θ".repeat(CODE_WIDTH);
    let md = format!("{wide}\n```text\n{fits}\n{wide}\n```\n{wide}\n  ~~~\n  {wide}\n  ~~~\n");
    assert_eq!(too_wide(&md), [(4, CODE_WIDTH + 1), (8, CODE_WIDTH + 3)]);
}
