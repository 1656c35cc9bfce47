//! No sentence of the built book turns into a list by where its line breaks.
//! Markdown reads a line starting with a number and ". " or ") " as a list
//! item, so "close to\n1. Phong's term" became a one-item list cutting
//! lesson 7's sentence in two, and an answer starting "{{count}}. Each"
//! became `<ol start="18">`. The book's real lists start at 1 after a blank
//! line, and each later item follows an item or its indented lines.

use super::code_width::markdown_files;
use super::run::root;

/// A line that Markdown reads as an ordered item: its number, if it is one.
fn item_number(line: &str) -> Option<&str> {
    let t = line.trim_start();
    let digits = t.len() - t.trim_start_matches(|c: char| c.is_ascii_digit()).len();
    let rest = &t[digits..];
    (digits > 0 && (rest.starts_with(". ") || rest.starts_with(") "))).then(|| &t[..digits])
}

/// The lines (from 1) of `markdown` that start like a numbered item but are
/// no real list's: outside code blocks, not continuing a list, and not a
/// list's first item (one at 1, after a blank line).
fn stray_items(markdown: &str) -> Vec<usize> {
    let (mut code, mut in_list, mut blank_before) = (false, false, true);
    let mut out = Vec::new();
    for (i, line) in markdown.lines().enumerate() {
        let t = line.trim_start();
        if t.starts_with("```") || t.starts_with("~~~") {
            code = !code;
            continue;
        }
        if code {
            continue;
        }
        if let Some(n) = item_number(line) {
            // A stray item is no list for the lines after it.
            in_list = in_list || (blank_before && n == "1");
            if !in_list {
                out.push(i + 1);
            }
        } else if t.starts_with("- ") || t.starts_with("* ") || t.starts_with("+ ") {
            in_list = true;
        } else if !t.is_empty() && t.len() == line.len() {
            // A paragraph's line at the margin ends any list.
            in_list = false;
        }
        blank_before = t.is_empty();
    }
    out
}

#[test]
fn no_line_of_the_built_book_starts_a_list_by_accident() {
    let mut files = Vec::new();
    markdown_files(&root().join("book/src"), &mut files);
    files.sort();
    assert!(files.len() > 14, "a chapter per lesson: {files:?}");
    let mut stray = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let rel = path.strip_prefix(root()).unwrap().display();
        for line in stray_items(&text) {
            let shown = text.lines().nth(line - 1).unwrap_or("");
            stray.push(format!("{rel}: line {line}: {shown}"));
        }
    }
    assert!(
        stray.is_empty(),
        "lines that Markdown makes list items, inside sentences (rewrap the source \
         so no line starts with a number and \". \" or \") \"):\n{}",
        stray.join("\n")
    );
}

#[test]
fn a_stray_item_is_told_from_a_real_list() {
    let md = "A list:\n\n1. one,\n   more of one\n2. two\n\n3. loose\n\n\
              Close to\n1. Phong's term\n\nwith (depth 1, weight\n1) that\n\n\
              18. Each ray\n\n```\n  7. a trace step\n```\n- a bullet\n  2. nested\n";
    assert_eq!(stray_items(md), [10, 13, 15]);
}
