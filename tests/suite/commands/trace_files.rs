//! Saved traces read back safely (issue 12): every way a trace file can be
//! broken is one line and exit 1 before the terminal is touched; a scene that
//! changed since tracing is left out with a note; the scene is found beside the
//! trace first, then from the working folder, or given after it.

use std::path::Path;

use raytree::scene::source::SceneSource;
use raytree::tree::document::TraceDocument;
use raytree::tree::reading;
use raytree::tree::record;
use serde_json::{Value, json};

use crate::common::refused;

fn whitted_text() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json"))
        .unwrap()
}

/// The glass pixel's trace of the Whitted scene saved as `s.json` (11 rays).
fn good_trace() -> TraceDocument {
    let text = whitted_text();
    let scene = raytree::scene::loader::parse(&text, "s.json").unwrap();
    record::pixel(&scene, SceneSource::new("s.json", &text), 416, 209, None).unwrap()
}

/// The trace with `change` made to its JSON.
fn broken(change: impl FnOnce(&mut Value)) -> Vec<u8> {
    let mut v = serde_json::to_value(good_trace()).unwrap();
    change(&mut v);
    serde_json::to_vec(&v).unwrap()
}

fn node(v: &mut Value, i: usize) -> &mut Value {
    &mut v["samples"][0]["tree"]["nodes"][i]
}

/// A broken trace: its name, its bytes, and what the refusal says.
type Broken = (&'static str, Vec<u8>, &'static str);

/// Traces whose tree is broken: no samples or nodes, a child or an index
/// that is not there, a test or a visit that cannot be, a loop, an orphan.
fn broken_trees() -> Vec<Broken> {
    vec![
        (
            "no-samples",
            broken(|v| v["samples"] = json!([])),
            "samples: empty",
        ),
        (
            "no-nodes",
            broken(|v| v["samples"][0]["tree"]["nodes"] = json!([])),
            "samples[0].tree.nodes: empty",
        ),
        (
            "child-past-the-end",
            broken(|v| node(v, 0)["reflected"]["node"] = json!(999)),
            "samples[0].tree.nodes[0].reflected.node: 999 is not a node (the tree has 11)",
        ),
        (
            "visit-after-too-many-tests",
            broken(
                |v| node(v, 0)["boxes"] = json!([{"min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 1.0], "met": true, "after_tests": 9}]),
            ),
            "samples[0].tree.nodes[0].boxes[0].after_tests: 9 is not between 0 (the visit before) and 4 (the ray's tests)",
        ),
        (
            "an-object-tested-twice",
            broken(|v| {
                let first = node(v, 0)["tests"][0].clone();
                node(v, 0)["tests"].as_array_mut().unwrap()[1] = first;
            }),
            "samples[0].tree.nodes[0].tests[1].object: 'floor' is tested a second time (a ray tests each object at most once)",
        ),
        (
            "more-tests-than-objects",
            broken(|v| {
                let tests = node(v, 0)["tests"].as_array().unwrap().clone();
                let many: Vec<Value> = tests.iter().cycle().take(40).cloned().collect();
                node(v, 0)["tests"] = json!(many);
            }),
            "samples[0].tree.nodes[0].tests: 40 tests of a scene of 4 objects",
        ),
        (
            "object-index",
            broken(|v| node(v, 0)["hit"]["object"] = json!(99)),
            "samples[0].tree.nodes[0].hit.object: object 99 does not exist (the trace lists 4)",
        ),
        (
            "light-index",
            broken(|v| node(v, 0)["shadow_rays"][1]["light"] = json!(7)),
            "samples[0].tree.nodes[0].shadow_rays[1].light: light 7 does not exist",
        ),
        (
            "parent-loop",
            broken(|v| {
                node(v, 1)["parent"] = json!(2);
                node(v, 2)["parent"] = json!(1);
            }),
            "must come after node 0, name it as its parent",
        ),
        (
            "child-loop",
            broken(|v| node(v, 3)["reflected"]["node"] = json!(2)),
            "samples[0].tree.nodes[3].reflected.node: node 2 must come after node 3",
        ),
        (
            "orphan",
            broken(|v| node(v, 0)["reflected"]["node"] = Value::Null),
            "samples[0].tree.nodes[1]: no node spawns it",
        ),
    ]
}

/// Traces whose document is wrong around a sound tree: a name, a pixel or a
/// setting the scene does not have, JSON of the wrong shape, an old version.
fn broken_documents() -> Vec<Broken> {
    vec![
        (
            "renamed-object",
            broken(|v| v["objects"][2]["name"] = json!("bowl")),
            "is 'bowl', not 'glass'",
        ),
        (
            "escape-in-a-name",
            broken(|v| v["lights"][0]["name"] = json!("key\u{1b}[2J")),
            "lights[0].name: 'key\\u{1b}[2J' holds a control character",
        ),
        (
            "pixel-outside",
            broken(|v| v["pixel"] = json!({"x": 640, "y": 0})),
            "pixel: 640,0 is outside the 640×480 image",
        ),
        (
            "bad-settings",
            broken(|v| v["settings"]["max_depth"] = json!(0)),
            "settings.max_depth: must be 1 to 1000",
        ),
        (
            "null-number",
            broken(|v| v["color"][0] = Value::Null),
            "not a raytree trace: invalid type: null, expected a number",
        ),
        ("array", b"[]".to_vec(), "not a raytree trace"),
        (
            "array-is-no-trace-object",
            b"[]".to_vec(),
            "not a raytree trace: invalid length 0, expected a trace object",
        ),
        (
            "string-for-a-pixel",
            broken(|v| v["pixel"]["x"] = json!("a")),
            "not a raytree trace: invalid type: string \"a\", expected a whole number",
        ),
        (
            "fraction-for-a-depth",
            broken(|v| v["settings"]["max_depth"] = json!(2.5)),
            "not a raytree trace: invalid type: floating point `2.5`, expected a whole number",
        ),
        (
            "number-for-a-root",
            broken(|v| v["samples"][0]["tree"] = json!(1)),
            "not a raytree trace: invalid type: integer `1`, expected",
        ),
        (
            "old-version",
            broken(|v| v["version"] = json!(1)),
            "a raytree-trace version 1 document; this raytree reads raytree-trace version",
        ),
        (
            // An older raytree's trace has other fields too: the version is
            // named before any field is (it once said "expected struct RootRecord").
            "old-version-other-fields",
            broken(|v| {
                v["version"] = json!(3);
                v["samples"][0]["tree"]["nodes"][0]["hit"]
                    .as_object_mut()
                    .unwrap()
                    .remove("object_normal");
                v["retired_field"] = json!(true);
            }),
            "a raytree-trace version 3 document; this raytree reads raytree-trace version",
        ),
    ]
}

#[test]
fn every_broken_trace_is_one_line_and_exit_1() {
    let cases = [broken_trees(), broken_documents()].concat();
    let scene = whitted_text();
    for (name, text, expected) in &cases {
        let files: [(&str, &[u8]); 2] = [("t.json", text), ("s.json", scene.as_bytes())];
        let e = refused(name, &files, &["inspect", "--trace", "t.json"]);
        assert!(
            e.starts_with("error: t.json") && e.contains(expected),
            "{name}: {e}"
        );
        assert!(!super::inputs::names_a_rust_type(&e), "{name}: {e}");
    }
}

#[test]
fn unreadable_trace_files_are_refused_at_once() {
    let e = refused("trace-dev-zero", &[], &["inspect", "--trace", "/dev/zero"]);
    assert!(e.contains("/dev/zero: not a regular file"), "{e}");
    let e = refused("trace-missing", &[], &["inspect", "--trace", "none.json"]);
    assert_eq!(e, "error: cannot read none.json: no such file");
}

#[test]
fn the_scene_is_found_beside_the_trace_then_from_the_working_folder() {
    let dir = tempfile::tempdir().unwrap();
    let text = good_trace().to_json();
    std::fs::create_dir(dir.path().join("saved")).unwrap();
    let trace = dir.path().join("saved/t.json");
    std::fs::write(&trace, &text).unwrap();
    // Not found anywhere: the trace alone, saying so.
    let opened = reading::open(&trace, None).unwrap();
    assert!(opened.scene.is_none());
    assert_eq!(
        opened.note.as_deref(),
        Some("scene s.json not found: showing the saved trace only")
    );
    // Beside the trace.
    std::fs::write(dir.path().join("saved/s.json"), whitted_text()).unwrap();
    let opened = reading::open(&trace, None).unwrap();
    assert!(
        opened.scene.is_some() && opened.note.is_none(),
        "{:?}",
        opened.note
    );
    // Changed since (objects deleted): the trace alone, never indexing past the end.
    let edited = whitted_text().replacen("\"name\": \"cavity\"", "\"name\": \"hole\"", 1);
    std::fs::write(dir.path().join("saved/s.json"), &edited).unwrap();
    let opened = reading::open(&trace, None).unwrap();
    assert!(opened.scene.is_none());
    assert!(
        opened
            .note
            .unwrap()
            .contains("changed since the trace was saved")
    );
    // Given explicitly: used when its objects and lights fit, refused when not.
    let fits = dir.path().join("fits.json");
    std::fs::write(&fits, whitted_text().replace("\"fov\"", " \"fov\"")).unwrap();
    let opened = reading::open(&trace, Some(&fits)).unwrap();
    assert!(opened.scene.is_some());
    assert!(
        opened
            .note
            .unwrap()
            .contains("is not the scene the trace was made from")
    );
    let e = reading::open(&trace, Some(&dir.path().join("saved/s.json"))).unwrap_err();
    assert!(
        e.to_string()
            .contains("object 3 is 'cavity' (sphere of 'air') in the trace, 'hole'"),
        "{e}"
    );
    // Given on the command line: one line when it does not fit.
    let files: [(&str, &[u8]); 2] = [("t.json", text.as_bytes()), ("s.json", b"{}")];
    let e = refused(
        "explicit-misfit",
        &files,
        &["inspect", "--trace", "t.json", "s.json"],
    );
    assert!(
        e.starts_with("error: t.json does not fit the scene s.json: the trace names 4 objects and 2 lights, the scene has 0 and 0"),
        "{e}"
    );
}

/// Adaptive sampling traces each pixel's corners, shared ones once: up to
/// (2^levels + 1)² primary rays, not `spp`. Its trace is written and read back
/// (it was refused on every pixel: "68 samples, but a pixel has 1").
#[test]
fn an_adaptive_trace_is_written_and_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("adaptive.json");
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args([
            "trace",
            "scenes/whitted.json",
            "--pixel",
            "416,209",
            "--aa",
            "adaptive",
            "--json",
            "-o",
        ])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let trace = reading::read(&out).unwrap_or_else(|e| panic!("{e}"));
    // 3 levels: at most a 9 × 9 grid of corners; the glass edge subdivides, so more than 4.
    assert!(
        (5..=81).contains(&trace.samples.len()),
        "{}",
        trace.samples.len()
    );
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let extra = v["samples"][0].clone();
    for _ in 0..82 {
        v["samples"].as_array_mut().unwrap().push(extra.clone());
    }
    let e = reading::parse(&v.to_string()).unwrap_err();
    assert!(e.contains("but a pixel has at most 81"), "{e}");
}

/// A scene the trace names that exists but is no scene file (a device, a
/// folder) is said to be so, not "not found" (issue 29); the same for a scene
/// given to `inspect` itself, refused before the terminal is touched.
#[test]
fn a_named_scene_that_is_no_file_is_said_to_be_so() {
    let dir = tempfile::tempdir().unwrap();
    for (named, why) in [
        ("/dev/zero", "/dev/zero: not a regular file"),
        ("folder", "folder: it is a directory"),
    ] {
        let mut v = serde_json::to_value(good_trace()).unwrap();
        v["scene"]["file"] = json!(named);
        let trace = dir.path().join("t.json");
        std::fs::write(&trace, serde_json::to_vec(&v).unwrap()).unwrap();
        std::fs::create_dir_all(dir.path().join("folder")).unwrap();
        let opened = reading::open(&trace, None).unwrap();
        assert!(opened.scene.is_none());
        let note = opened.note.unwrap();
        assert!(!note.contains("not found"), "{named}: {note}");
        assert!(note.contains(why), "{named}: {note}");
    }
    for (name, arg, why) in [
        (
            "inspect-dev-zero",
            "/dev/zero",
            "/dev/zero: not a regular file",
        ),
        ("inspect-folder", ".", ".: it is a directory"),
    ] {
        let e = refused(name, &[], &["inspect", arg]);
        assert!(!e.contains("not found"), "{name}: {e}");
        assert!(e.contains(why), "{name}: {e}");
    }
}

/// A trace given where the scene goes is named for what it is, with the
/// command that opens it, not refused for a scene's fields.
#[test]
fn a_trace_given_as_the_scene_says_how_to_open_it() {
    let text = good_trace().to_json();
    let files: [(&str, &[u8]); 1] = [("t.json", text.as_bytes())];
    let e = crate::common::refused_with(2, "trace-as-scene", &files, &["inspect", "t.json"]);
    assert!(
        e.starts_with("error: t.json is a trace: open it with raytree inspect --trace t.json"),
        "{e}"
    );
}
