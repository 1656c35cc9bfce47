//! What every reader refuses the same way, beside each reader's own cases
//! (`scene_files.rs` for OBJ meshes, `nff.rs`, `trace_files.rs`,
//! `learner.rs`): a face OBJ's parser would drop or leave unchecked, a file
//! that is not text (a byte-order mark, a NUL byte: refused from its first
//! bytes, within a small memory), and a long word of the input quoted short.

use std::path::Path;

use raytree::scene::obj;

use crate::common::{refused, refused_with};

/// `render s.json` where `s.json` is a mesh of `m.obj` holding `text`: the
/// error line.
fn mesh_refused(name: &str, text: &[u8]) -> String {
    let scene = br#"{"objects": [{"mesh": {"file": "m.obj"}}]}"#;
    let files: [(&str, &[u8]); 2] = [("s.json", scene), ("m.obj", text)];
    let e = refused(name, &files, &["render", "s.json", "-o", "o.png"]);
    assert!(
        e.ends_with(" (the mesh of s.json: objects[0].mesh.file)"),
        "{name}: {e}"
    );
    e
}

const TRIANGLE: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

#[test]
fn every_obj_face_is_checked_even_where_tobj_does_not() {
    let cases = [
        (
            "texcoord-without-vt",
            "f 1/5 2/5 3/5\n",
            "m.obj:4: face texcoord index out of bounds: 5 (no `vt` lines in the file)",
        ),
        (
            "normal-without-vn",
            "f 1//7 2//7 3//7\n",
            "m.obj:4: face normal index out of bounds: 7 (no `vn` lines in the file)",
        ),
        (
            "relative-before-the-start",
            "f -1 -2 -4\n",
            "m.obj:4: face vertex index out of bounds: -4 (3 `v` lines before this face)",
        ),
        (
            "two-vertices-only",
            "f 1 2\n",
            "m.obj:4: a face needs at least 3 vertices, got 2",
        ),
        (
            "two-vertices-among-good-faces",
            "f 1 2 3\nf 1 2\nf 3 2 1\n",
            "m.obj:5: a face needs at least 3 vertices, got 2",
        ),
        (
            "no-vertices",
            "f\nf 1 2 3\n",
            "m.obj:4: a face needs at least 3 vertices, got 0",
        ),
        // The first problem in the file is the one named, tobj's or ours.
        (
            "parse-error-first",
            "vn x 0 1\nf 1 2\n",
            "m.obj:4: normal parse error",
        ),
    ];
    for (name, faces, expected) in cases {
        let e = mesh_refused(name, format!("{TRIANGLE}{faces}").as_bytes());
        assert!(e.starts_with(&format!("error: {expected}")), "{name}: {e}");
    }
    // What the checks allow: relative indices, and indices of vt and vn lines
    // that exist, before or after the face.
    for good in [
        "f -3 -2 -1\n",
        "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n",
        "f 1//1 2//1 3//1\nvn 0 0 1\n",
    ] {
        let mesh = obj::parse(format!("{TRIANGLE}{good}").as_bytes(), "m.obj", true);
        assert!(mesh.is_ok_and(|m| m.faces.len() == 1), "{good:?}");
    }
}

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
const READERS: [(&str, &[&str], i32); 5] = [
    ("scene.json", &["render", "scene.json", "-o", "o.png"], 1),
    ("scene.nff", &["render", "scene.nff", "-o", "o.png"], 1),
    ("trace.json", &["inspect", "--trace", "trace.json"], 1),
    (
        "learner.json",
        &["check", "s.json", "--pixel", "1,1", "learner.json"],
        2,
    ),
    ("m.obj", &[], 1),
];

/// `text` given to each reader: the error line of each.
fn every_reader_refuses(case: &str, text: &[u8]) -> Vec<String> {
    READERS
        .iter()
        .map(|(name, args, code)| {
            let case = format!("{case}-{}", name.replace('.', "-"));
            if name.ends_with(".obj") {
                mesh_refused(&case, text)
            } else {
                refused_in_folder(*code, &case, name, text, args)
            }
        })
        .collect()
}

#[test]
fn a_byte_order_mark_is_named_by_every_reader() {
    // Some Windows editors save UTF-8 with the mark U+FEFF first: no reader
    // takes it for the first word (a JSON value, an NFF keyword, an OBJ `v`).
    let mut text = "\u{feff}".as_bytes().to_vec();
    text.extend_from_slice(TRIANGLE.as_bytes());
    text.extend_from_slice(b"f 1 2 3\n");
    for (e, (name, ..)) in every_reader_refuses("bom", &text).iter().zip(READERS) {
        assert!(e.contains(name), "{e}");
        assert!(
            e.contains(": starts with a byte-order mark (U+FEFF); save it as UTF-8 without one"),
            "{name}: {e}"
        );
    }
}

#[test]
fn a_nul_byte_says_binary_and_where() {
    let text = b"{\n  \"objects\": []\n}\0\n";
    for (e, (name, ..)) in every_reader_refuses("nul", text).iter().zip(READERS) {
        assert!(
            e.contains(name) && e.contains("a binary file, not text: a NUL byte (line 3)"),
            "{name}: {e}"
        );
    }
}

#[test]
#[cfg(target_os = "linux")]
fn a_binary_file_is_refused_from_its_first_bytes() {
    // 1000 MB of NUL bytes (a sparse file: nothing is written), which a reader
    // of the whole file would hold once or twice: refused in 256 MiB.
    let dir = tempfile::tempdir().unwrap();
    let scene = br#"{"objects": [{"mesh": {"file": "m.obj"}}]}"#;
    std::fs::write(dir.path().join("s.json"), scene).unwrap();
    for name in ["m.obj", "z.nff", "z.json"] {
        std::fs::File::create(dir.path().join(name))
            .unwrap()
            .set_len(1_000_000_000)
            .unwrap();
    }
    for (file, args) in [
        ("m.obj", ["render", "s.json", "-o", "o.png"]),
        ("z.nff", ["render", "z.nff", "-o", "o.png"]),
        ("z.json", ["render", "z.json", "-o", "o.png"]),
    ] {
        let (code, err, seconds) = crate::common::within_memory(dir.path(), 256, &args);
        assert_eq!(code, Some(1), "{file}: {err}");
        assert_eq!(err.lines().count(), 1, "{file}: {err}");
        assert!(
            err.contains(&format!(
                "{file}: a binary file, not text: a NUL byte (line 1)"
            )),
            "{file}: {err}"
        );
        assert!(seconds < 2.0, "{file}: {seconds} s");
    }
}

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

/// An empty scene file, or one that is not JSON at all (a text file passed by
/// mistake), is named as such, where it is, not with the parser's words.
#[test]
fn an_empty_or_non_json_scene_file_is_said_in_plain_words() {
    let kinds = "a scene file is JSON (see scenes/README.md), or NFF by the extension .nff";
    for (name, file, text, said) in [
        (
            "empty",
            "e.json",
            &b""[..],
            format!("e.json:1:1: empty file: {kinds}"),
        ),
        (
            "blank",
            "b.json",
            b"\n\n  ",
            format!("b.json:1:1: empty file: {kinds}"),
        ),
        (
            "text",
            "x.txt",
            b"x",
            format!("x.txt:1:1: not JSON: {kinds}"),
        ),
        (
            "indented",
            "i.json",
            b"\n  hello {}",
            format!("i.json:2:3: not JSON: {kinds}"),
        ),
    ] {
        let e = refused(name, &[(file, text)], &["render", file, "-o", "o.png"]);
        assert_eq!(e, format!("error: {said}"), "{name}");
    }
}
