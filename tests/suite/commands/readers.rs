//! What every reader does the same way, beside each reader's own cases
//! (`nff.rs`, `trace_files.rs`, `learner.rs`): a long word of the input
//! quoted short.

use std::path::Path;

use crate::common::refused_with;

/// The error line of `raytree ARGS` run in a folder holding `file` (named
/// `name`, `text`) and the shipped Whitted scene as `s.json`, exit `code`.
fn refused_in_folder(code: i32, case: &str, name: &str, text: &[u8], args: &[&str]) -> String {
    let scene =
        std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json")).unwrap();
    let files: [(&str, &[u8]); 2] = [("s.json", &scene), (name, text)];
    refused_with(code, case, &files, args)
}

/// Each kind of file raytree reads as text, by name, with the command that
/// reads it and that command's exit code for a bad file.
const READERS: [(&str, &[&str], i32); 4] = [
    ("scene.json", &["render", "scene.json", "-o", "o.png"], 1),
    ("scene.nff", &["render", "scene.nff", "-o", "o.png"], 1),
    ("trace.json", &["inspect", "--trace", "trace.json"], 1),
    (
        "learner.json",
        &["check", "s.json", "--pixel", "1,1", "learner.json"],
        2,
    ),
];

#[test]
fn a_long_word_is_quoted_short_by_every_reader() {
    // A word of a million characters, where each reader quotes the input.
    const N: usize = 1_000_000;
    let long = "k".repeat(N);
    let cut = format!("{}…", "k".repeat(raytree::scene::quote::MAX_QUOTED));
    let length = |n: usize| format!("({n} characters)");
    let bytes = |s: String| s.into_bytes();
    let cases: Vec<(&str, &str, Vec<u8>)> = vec![
        ("nff-keyword", "scene.nff", format!("{long}\n").into_bytes()),
        (
            "nff-number",
            "scene.nff",
            bytes(format!(
                "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\n\
                 f 1 1 1 1 0 10 0 0\ns 0 0 {long} 1\n"
            )),
        ),
        (
            "unknown-key",
            "scene.json",
            bytes(format!(r#"{{"objects": [], "{long}": 1}}"#)),
        ),
        (
            "material-name",
            "scene.json",
            bytes(format!(
                r#"{{"objects": [{{"sphere": {{}}, "material": "{long}"}}]}}"#
            )),
        ),
        (
            "material-key",
            "scene.json",
            bytes(format!(
                r#"{{"materials": {{"{long}": {{"ambient": -1}}}}, "objects": []}}"#
            )),
        ),
        (
            "mesh-file",
            "scene.json",
            bytes(format!(
                r#"{{"objects": [{{"mesh": {{"file": "{long}.obj"}}}}]}}"#
            )),
        ),
        (
            "wrong-type",
            "scene.json",
            bytes(format!(
                r#"{{"objects": [{{"sphere": {{"radius": "{long}"}}}}]}}"#
            )),
        ),
        (
            "unknown-variant",
            "scene.json",
            bytes(format!(r#"{{"render": {{"accel": "{long}"}}}}"#)),
        ),
        (
            "trace-format",
            "trace.json",
            bytes(format!(r#"{{"format": "{long}", "version": 1}}"#)),
        ),
        (
            "trace-key",
            "trace.json",
            bytes(format!(r#"{{"{long}": 1}}"#)),
        ),
        (
            "learner-key",
            "learner.json",
            bytes(format!(
                r#"{{"format": "raytree-learner-trace", "version": 1, "{long}": 1}}"#
            )),
        ),
    ];
    for (case, name, text) in cases {
        let (_, args, code) = READERS.iter().find(|r| r.0 == name).unwrap();
        let e = refused_in_folder(*code, case, name, &text, args);
        let head: String = e.chars().take(400).collect();
        assert!(e.len() < 400, "{case}: {} bytes: {head}", e.len());
        let n = N + if case == "mesh-file" { 4 } else { 0 };
        assert!(e.contains(&cut) && e.contains(&length(n)), "{case}: {e}");
    }
}
