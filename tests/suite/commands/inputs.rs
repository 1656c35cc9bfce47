//! Every file raytree reads is held to the scene loader's standard (issue 12):
//! only regular files, each OBJ read once however many objects use it, the
//! strict format without holes (objects only, every name once, no control
//! characters), numbers within limits that keep every computed number finite,
//! and a right-handed camera frame.

use std::sync::Arc;

use raytree::geometry::object::Shape;
use raytree::scene::loader;

use crate::common::refused;

/// `render bad.json` refused; the error line without `error: bad.json: `.
fn scene_refused(name: &str, text: &str) -> String {
    let files: [(&str, &[u8]); 1] = [("bad.json", text.as_bytes())];
    let e = refused(name, &files, &["render", "bad.json", "-o", "out.png"]);
    e.strip_prefix("error: bad.json").unwrap_or(&e).to_owned()
}

#[test]
fn devices_and_pipes_are_refused_before_reading() {
    let e = refused("scene-dev-zero", &[], &["render", "/dev/zero"]);
    assert!(
        e.starts_with("error: cannot read /dev/zero: not a regular file"),
        "{e}"
    );
    let mesh = br#"{"objects": [{"mesh": {"file": "/dev/zero"}}]}"#;
    let e = refused("mesh-dev-zero", &[("m.json", mesh)], &["render", "m.json"]);
    assert!(
        e.starts_with("error: m.json: objects[0].mesh.file: '/dev/zero' leaves the scene's folder"),
        "{e}"
    );
    // diff's trouble is exit 2 (1 says the images differ).
    let e =
        crate::common::refused_with(2, "diff-dev-zero", &[], &["diff", "/dev/zero", "/dev/zero"]);
    assert!(
        e.starts_with("error: cannot read /dev/zero: not a regular file"),
        "{e}"
    );
    // A named pipe would block the reader until someone writes to it.
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe.json");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let e = loader::load(&fifo).unwrap_err().to_string();
        assert!(
            e.ends_with(
                "pipe.json: not a regular file (a device, pipe or socket cannot be read as one)"
            ),
            "{e}"
        );
    }
}

#[test]
fn an_obj_many_objects_use_is_read_once() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("tri.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let objects: Vec<String> = (0..200)
        .map(|i| {
            format!(
                r#"{{"mesh": {{"file": "tri.obj"}}, "transform": [{{"translate": [{i}, 0, 0]}}]}}"#
            )
        })
        .collect();
    let scene = dir.path().join("many.json");
    std::fs::write(&scene, format!(r#"{{"objects": [{}]}}"#, objects.join(","))).unwrap();
    let scene = loader::load(&scene).unwrap();
    let meshes: Vec<_> = scene
        .objects
        .iter()
        .map(|o| match &o.shape {
            Shape::Mesh(m) => Arc::clone(m),
            _ => unreachable!(),
        })
        .collect();
    assert_eq!(meshes.len(), 200);
    assert!(
        meshes.iter().all(|m| Arc::ptr_eq(m, &meshes[0])),
        "one parse, shared"
    );
    assert_eq!(scene.mesh_files.len(), 1);
}

#[test]
fn the_strict_format_has_no_holes() {
    let cases = [
        (
            "array-scene",
            "[]",
            ":1:1: invalid type: sequence, expected a scene object",
        ),
        (
            "positional-object",
            r#"{"objects": [[null, {"center": [0, 0, 0], "radius": 1}]]}"#,
            ":1:13: objects[0]: invalid type: sequence, expected an object {…}",
        ),
        (
            "positional-sphere",
            r#"{"objects": [{"sphere": [[0, 0, 0], 1]}]}"#,
            ":1:24: objects[0].sphere: invalid type: sequence, expected an object {…}",
        ),
        (
            "positional-render",
            r#"{"render": [64, 48]}"#,
            ":1:11: render: invalid type: sequence, expected an object {…}",
        ),
        (
            "positional-rotate",
            r#"{"objects": [{"sphere": {}, "transform": [{"rotate": [[0, 1, 0], 45]}]}]}"#,
            "objects[0].transform[0].rotate: invalid type: sequence, expected an object {…}",
        ),
        (
            "duplicate-material",
            r#"{"materials": {"glass": {"ior": 1.5}, "glass": {"ior": 1.2}}}"#,
            "the name `glass` is given twice",
        ),
        (
            "duplicate-key",
            r#"{"objects": [{"sphere": {"radius": 1, "radius": 2}}]}"#,
            "objects[0].sphere: duplicate field `radius`",
        ),
        (
            "duplicate-object",
            r#"{"objects": [{"name": "ball", "sphere": {}}, {"name": "ball", "sphere": {}}]}"#,
            ": objects[1].name: 'ball' is already the name of objects[0]",
        ),
        (
            "default-name-collision",
            r#"{"objects": [{"name": "sphere1", "sphere": {}}, {"sphere": {}}]}"#,
            ": objects[1].name: 'sphere1' is already the name of objects[0]",
        ),
        (
            "duplicate-light",
            r#"{"lights": [{"name": "key", "position": [0, 1, 0]}, {"name": "key", "position": [0, 2, 0]}]}"#,
            ": lights[1].name: 'key' is already the name of lights[0]",
        ),
        (
            "escape-in-object-name",
            "{\"objects\": [{\"name\": \"x\\u001b[31mred\", \"sphere\": {}}]}",
            ": objects[0].name: 'x\\u{1b}[31mred' holds a control character (\\u{1b}); names must be printable",
        ),
        (
            "newline-in-material-name",
            "{\"materials\": {\"a\\nb\": {}}}",
            ": materials.a\\nb: 'a\\nb' holds a control character",
        ),
        (
            "escape-in-unknown-field",
            "{\"\\u001b[2J\": 1}",
            "unknown field `\\u{1b}[2J`",
        ),
    ];
    for (name, text, expected) in cases {
        let e = scene_refused(name, text);
        assert!(e.contains(expected), "{name}: {e}");
    }
}

/// Numbers outside the limits that keep every computed number finite, and a
/// left-handed frame: each case's name, the scene's text, and the message's
/// start after the file's name.
const OUT_OF_LIMITS: &[(&str, &str, &str)] = &[
    (
        "far",
        r#"{"objects": [{"sphere": {"center": [2e9, 0, 0]}}]}"#,
        ": objects[0].sphere.center: every coordinate must be within ±1e9, got [2e9, 0, 0]",
    ),
    (
        "bright",
        r#"{"lights": [{"position": [0, 5, 0], "color": [1e7, 1e7, 1e7]}]}"#,
        ": lights[0].color: a color's components must be from 0 to 1e6",
    ),
    (
        "more-than-all",
        r#"{"materials": {"m": {"reflective": 0.6, "transparent": 0.6}}}"#,
        ": materials.m: reflective + transparent must be at most 1",
    ),
    (
        "ior",
        r#"{"materials": {"m": {"ior": 1e-5}}}"#,
        ": materials.m.ior: a refractive index must be from 0.01 to 100, got 1e-5",
    ),
    (
        "tiny-sphere",
        r#"{"objects": [{"sphere": {"radius": 1e-12}}]}"#,
        ": objects[0].sphere.radius: must be from 1e-9 to 1e9, got 1e-12",
    ),
    (
        "far-transform",
        r#"{"objects": [{"sphere": {}, "transform": [{"scale": [1e-9, 1e-9, 1e-9]}, {"translate": [1e9, 0, 0]}]}]}"#,
        ": objects[0].transform: scales or moves too far",
    ),
    (
        "obj-far",
        r#"{"camera": {"fov": 0.0001}}"#,
        ": camera.fov: must be from 0.001 to 179.999 degrees, got 0.0001",
    ),
    // A number is echoed as short as it reads, not as 300 digits (issue 29).
    (
        "fov-tiny",
        r#"{"camera": {"fov": 1e-300}}"#,
        ": camera.fov: must be from 0.001 to 179.999 degrees, got 1e-300",
    ),
    (
        "fov-huge",
        r#"{"camera": {"fov": 1e300}}"#,
        ": camera.fov: must be from 0.001 to 179.999 degrees, got 1e300",
    ),
    (
        "reflective-tiny",
        r#"{"materials": {"m": {"reflective": -1e-300}}}"#,
        ": materials.m.reflective: must be from 0 to 1, got -1e-300",
    ),
    (
        "shininess-huge",
        r#"{"materials": {"m": {"shininess": 1e300}}}"#,
        ": materials.m.shininess: must be from 0 to 1e6, got 1e300",
    ),
    (
        "cutoff-tiny",
        r#"{"render": {"cutoff": -1e-300}}"#,
        ": render.cutoff: must be a number from 0 up to (not including) 1, got -1e-300",
    ),
    (
        "epsilon-tiny",
        r#"{"render": {"offset": {"epsilon": -1e-300}}}"#,
        ": render.offset: an epsilon must be a number > 0, got -1e-300",
    ),
    (
        "left-handed",
        r#"{"camera": {"u": [-1, 0, 0], "v": [0, 1, 0], "n": [0, 0, 1], "half_width": 1, "half_height": 1}}"#,
        ": camera.n: makes a left-handed frame (u × v = -n), which would mirror the image",
    ),
];

#[test]
fn numbers_outside_the_limits_and_left_handed_frames_are_refused() {
    for (name, text, expected) in OUT_OF_LIMITS {
        let e = scene_refused(name, text);
        assert!(e.starts_with(expected), "{name}: {e}");
    }
    // The right-handed twin of the last one renders.
    let scene = loader::parse(
        r#"{"camera": {"u": [1, 0, 0], "v": [0, 1, 0], "n": [0, 0, 1], "half_width": 1, "half_height": 1}}"#,
        "ok.json",
    );
    assert!(scene.is_ok());
}

/// A cone's fields, each refused in one line naming it, by `raytree render`
/// (exit 1): what the loader checks against the limits, then what
/// `cone_object` refuses, named as the cone's own.
#[test]
fn a_bad_cone_is_refused_naming_its_field() {
    let cone = |fields: &str| format!(r#"{{"objects": [{{"cone": {{{fields}}}}}]}}"#);
    let cases = [
        (
            "cone-missing-radius",
            cone(r#""base": [0, 0, 0], "base_radius": 1, "apex": [0, 1, 0]"#),
            "objects[0].cone: missing field `apex_radius`",
        ),
        (
            "cone-unknown-field",
            cone(r#""base": [0, 0, 0], "radius": 1, "apex": [0, 1, 0], "apex_radius": 1"#),
            "objects[0].cone.radius: unknown field `radius`",
        ),
        (
            "cone-negative-radius",
            cone(r#""base": [0, 0, 0], "base_radius": -1, "apex": [0, 1, 0], "apex_radius": 1"#),
            ": objects[0].cone.base_radius: must be from 0 to 1e9, got -1",
        ),
        (
            "cone-huge-radius",
            cone(r#""base": [0, 0, 0], "base_radius": 1, "apex": [0, 1, 0], "apex_radius": 1e10"#),
            ": objects[0].cone.apex_radius: must be from 0 to 1e9, got 1e10",
        ),
        (
            "cone-far-apex",
            cone(r#""base": [0, 0, 0], "base_radius": 1, "apex": [0, 2e9, 0], "apex_radius": 1"#),
            ": objects[0].cone.apex: every coordinate must be within ±1e9, got [0, 2e9, 0]",
        ),
        (
            "cone-both-radii-zero",
            cone(r#""base": [0, 0, 0], "base_radius": 0, "apex": [0, 1, 0], "apex_radius": 0"#),
            ": objects[0].cone: base_radius and apex_radius are both 0: the cone would be a line",
        ),
        (
            "cone-no-length",
            cone(r#""base": [1, 2, 3], "base_radius": 1, "apex": [1, 2, 3], "apex_radius": 0.5"#),
            ": objects[0].cone: base and apex are the same point: the cone would have no length",
        ),
        (
            "cone-too-thin-to-invert",
            cone(r#""base": [0, 0, 0], "base_radius": 1e-300, "apex": [0, 1, 0], "apex_radius": 0"#),
            ": objects[0].cone: radius 1e-300 over a length of 1 is too extreme: its transform cannot be inverted",
        ),
        (
            "cone-too-thin",
            cone(r#""base": [0, 0, 0], "base_radius": 1e-15, "apex": [0, 1, 0], "apex_radius": 0"#),
            ": objects[0].cone: scales or moves too far",
        ),
        (
            "cone-and-sphere",
            r#"{"objects": [{"sphere": {}, "cone": {"base": [0, 0, 0], "base_radius": 1, "apex": [0, 1, 0], "apex_radius": 1}}]}"#.to_owned(),
            ": objects[0]: give exactly one shape: \"sphere\", \"plane\", \"box\", \"triangle\", \"mesh\", \"polygon\" or \"cone\"",
        ),
        (
            "cone-moved-too-far-by-its-transform",
            r#"{"objects": [{"cone": {"base": [0, 0, 0], "base_radius": 1, "apex": [0, 1, 0], "apex_radius": 1}, "transform": [{"scale": [1e-9, 1e-9, 1e-9]}, {"translate": [1e9, 0, 0]}]}]}"#.to_owned(),
            ": objects[0].transform: scales or moves too far",
        ),
    ];
    for (name, text, expected) in cases {
        let e = scene_refused(name, &text);
        assert!(e.contains(expected), "{name}: {e}");
        assert!(!e.trim_end().contains('\n'), "{name}: one line: {e}");
    }
}

/// Every number at the edge of its range at once: the eye in a corner of a
/// mirror box 2e9 wide, lights of 1e6 and every coefficient at 1e6, a sphere
/// of radius 1e-9 beside one of 1e9, a cone as wide as the box and one as
/// thin as the thinnest sphere (near the origin: a cone's inverse transform
/// grows with its distance from the origin over its radius, and its entries
/// must stay within 1e12), indices 0.01 and 100, the deepest
/// recursion and the widest view. One sample a pixel: at depth 1000 under the
/// default cutoff a sample may trace 1,014,783 rays, and a trace holds at most
/// 1,048,576 (`trace_check::MAX_TRACE_RAYS`), so four would not be recorded.
const EXTREME: &str = r#"{
    "camera": {"eye": [9.99e8, 9.99e8, 9.99e8], "look_at": [-1e9, -1e9, -1e9], "up": [0, 1e9, 0], "fov": 179.999},
    "render": {"width": 12, "height": 9, "spp": 1, "max_depth": 1000, "weights": "fresnel"},
    "background": [1e6, 1e6, 1e6],
    "ambient_light": [1e6, 1e6, 1e6],
    "materials": {
        "mirror": {"color": [1e6, 1e6, 1e6], "ambient": 1e6, "diffuse": 1e6, "specular": 1e6, "shininess": 1e6, "reflective": 1},
        "dense": {"color": [1e6, 0, 1e6], "ambient": 1e6, "diffuse": 1e6, "specular": 1e6, "shininess": 1e-9, "reflective": 0.5, "transparent": 0.5, "ior": 100},
        "thin": {"checker": {"colors": [[1e6, 1e6, 1e6], [0, 0, 0]], "size": 1e-9}, "transparent": 1, "ior": 0.01}
    },
    "lights": [
        {"position": [1e9, 1e9, -1e9], "color": [1e6, 1e6, 1e6]},
        {"position": [-1e9, 1e9, 1e9], "color": [1e6, 1e6, 1e6]},
        {"position": [0, 0, 0], "color": [1e6, 1e6, 1e6]}
    ],
    "objects": [
        {"box": {"min": [-1e9, -1e9, -1e9], "max": [1e9, 1e9, 1e9]}, "material": "mirror"},
        {"sphere": {"center": [0, 0, 0], "radius": 1e9}, "material": "dense"},
        {"sphere": {"center": [9.99e8, 9.99e8, 9.98e8], "radius": 1e-9}, "material": "thin"},
        {"sphere": {}, "material": "thin", "transform": [{"scale": [1e6, 1e-6, 1]}, {"rotate": {"axis": [1, 1, 1], "degrees": 1e9}}, {"translate": [1e5, 1e5, 1e5]}]},
        {"plane": {"point": [1e9, 1e9, 1e9], "normal": [1e-9, 1, 1e9]}, "material": "dense"},
        {"triangle": {"vertices": [[1e9, -1e9, 0], [-1e9, 1e9, 0], [1e9, 1e9, 1e-9]]}, "material": "thin"},
        {"cone": {"base": [-1e9, -1e9, -1e9], "base_radius": 1e9, "apex": [1e9, 1e9, 1e9], "apex_radius": 0}, "material": "mirror"},
        {"cone": {"base": [1, 1, 1], "base_radius": 1e-9, "apex": [1, 1, 1.000000001], "apex_radius": 1e-9}, "material": "thin"},
        {"polygon": {"vertices": [[1e9, -1e9, 1e9], [1e9, 1e9, 1e9], [-1e9, 1e9, 1e9], [0, 0, 1e9], [-1e9, -1e9, 1e9]], "normals": [[1e-9, 1, 1e9], [1e9, 1e9, 1e9], [-1e9, 0, 1e-9], [0, 0, -1], [1, 1e9, 0]]}, "material": "dense"}
    ]
}"#;

#[test]
fn the_most_extreme_valid_scene_renders_and_traces_finite_numbers() {
    let scene = loader::parse(EXTREME, "extreme.json").unwrap();
    let image =
        raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
    assert!(
        image.pixels.iter().all(|p| p.is_finite()),
        "every pixel finite"
    );
    let source = raytree::scene::source::SceneSource::new("extreme.json", EXTREME);
    for (x, y) in [(0, 0), (6, 4), (11, 8), (3, 7)] {
        let trace = raytree::tree::record::pixel(&scene, source.clone(), x, y, None).unwrap();
        // Written only if it reads back exactly: no number became `null`.
        let json = trace
            .to_checked_json()
            .unwrap_or_else(|e| panic!("{x},{y}: {e}"));
        assert_eq!(
            trace.color,
            image.get(x, y),
            "{x},{y}: the trace is the render"
        );
        assert!(json.len() > 1000);
    }
}

/// Within the limits, yet below the precision of the ray: a sphere of radius
/// 1e-9 seen from 1e9 away, whose hit rounds onto its very center. It renders
/// finite and its trace reads back (it was NaN, and the JSON trace refused).
#[test]
fn a_sphere_below_the_rays_precision_renders_and_traces_finite_numbers() {
    let text = r#"{"camera": {"eye": [0, 0, 1e9]}, "render": {"width": 9, "height": 9},
        "lights": [{"position": [0, 5, 5]}],
        "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1e-9}}]}"#;
    let scene = loader::parse(text, "tiny.json").unwrap();
    let image =
        raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
    assert!(image.pixels.iter().all(|p| p.is_finite()));
    let source = raytree::scene::source::SceneSource::new("tiny.json", text);
    let trace = raytree::tree::record::pixel(&scene, source, 4, 4, None).unwrap();
    let hit = trace.samples[0].tree.nodes[0].hit.as_ref().expect("a hit");
    assert_eq!(hit.name, "sphere0");
    trace.to_checked_json().unwrap();
    assert_eq!(trace.color, image.get(4, 4));
}

/// Whether `message` names a Rust type (`struct SceneFile`, `f64`, `usize`)
/// where a user should read a word of the format.
pub fn names_a_rust_type(message: &str) -> bool {
    message.contains("struct ")
        || message.contains("enum ")
        || message
            .split(|c: char| !c.is_ascii_alphanumeric())
            .any(|w| {
                matches!(
                    w,
                    "f32"
                        | "f64"
                        | "u8"
                        | "u16"
                        | "u32"
                        | "u64"
                        | "usize"
                        | "i32"
                        | "i64"
                        | "isize"
                )
            })
}

/// A value of the wrong type is named in the format's words: a number, a
/// whole number, a scene object, never `f64` or `struct SceneFile` (issue 29).
#[test]
fn wrong_types_are_named_in_the_users_words() {
    let cases = [
        (
            "string-for-number",
            r#"{"camera": {"fov": "x"}}"#,
            ":1:22: camera.fov: invalid type: string \"x\", expected a number",
        ),
        (
            "float-for-count",
            r#"{"render": {"width": 1.5}}"#,
            ":1:24: render.width: invalid type: floating point `1.5`, expected a whole number",
        ),
        (
            "negative-count",
            r#"{"render": {"width": -1}}"#,
            ":1:23: render.width: invalid value: integer `-1`, expected a whole number",
        ),
        (
            "array-scene",
            "[]",
            ":1:1: invalid type: sequence, expected a scene object",
        ),
        (
            "string-for-point",
            r#"{"camera": {"eye": "x"}}"#,
            ":1:22: camera.eye: invalid type: string \"x\", expected",
        ),
        (
            "string-in-point",
            r#"{"camera": {"eye": [0, "x", 0]}}"#,
            "camera.eye",
        ),
        (
            "string-for-color",
            r#"{"lights": [{"position": [0, 1, 0], "color": [1, 1, "x"]}]}"#,
            "lights[0].color",
        ),
        (
            "string-for-depth",
            r#"{"render": {"max_depth": "x"}}"#,
            "render.max_depth: invalid type: string \"x\", expected a whole number",
        ),
        (
            "number-for-object",
            r#"{"objects": [5]}"#,
            "objects[0]: invalid type: integer `5`, expected",
        ),
        (
            "number-for-material",
            r#"{"materials": {"m": 5}}"#,
            "materials.m: invalid type: integer `5`, expected",
        ),
        (
            "string-for-offset",
            r#"{"render": {"offset": {"epsilon": "x"}}}"#,
            "render.offset",
        ),
        (
            "string-for-spp",
            r#"{"render": {"spp": "x"}}"#,
            "render.spp",
        ),
    ];
    for (name, text, expected) in cases {
        let e = scene_refused(name, text);
        assert!(
            e.starts_with(expected) || e.contains(expected),
            "{name}: {e}"
        );
        assert!(!names_a_rust_type(&e), "{name}: {e}");
    }
}

/// A mesh is read from the scene's folder or below it, never from elsewhere:
/// `../`, an absolute path or a symlink out of the folder is refused in one
/// line naming the field, whether or not the file it names exists (issue 29).
#[cfg(unix)]
#[test]
fn a_mesh_must_stay_in_the_scenes_folder() {
    let dir = tempfile::tempdir().unwrap();
    let scenes = dir.path().join("scenes");
    std::fs::create_dir_all(scenes.join("sub")).unwrap();
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::fs::write(dir.path().join("outside.obj"), tri).unwrap();
    std::fs::write(scenes.join("inside.obj"), tri).unwrap();
    std::os::unix::fs::symlink(dir.path(), scenes.join("up")).unwrap();
    std::os::unix::fs::symlink(dir.path().join("outside.obj"), scenes.join("out.obj")).unwrap();
    let run = |mesh: &str| {
        let scene = format!(
            r#"{{"render": {{"width": 4, "height": 3}}, "objects": [{{"mesh": {{"file": "{mesh}"}}}}]}}"#
        );
        std::fs::write(scenes.join("s.json"), scene).unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(["render", "s.json", "-o", "out.png"])
            .current_dir(&scenes)
            .output()
            .unwrap();
        (out.status.code(), String::from_utf8(out.stderr).unwrap())
    };
    let outside = dir.path().join("outside.obj").display().to_string();
    for mesh in [
        "../outside.obj",
        "sub/../../outside.obj",
        outside.as_str(),
        "up/outside.obj",
        "out.obj",
        "up/scenes/../outside.obj",
        "../../../../../../../../etc/shadow",
        "../../../../../../../../no/such/file.obj",
        "up/no-such-file.obj",
    ] {
        let (code, e) = run(mesh);
        assert_eq!(code, Some(1), "{mesh}: {e}");
        assert_eq!(e.lines().count(), 1, "{mesh}: {e}");
        assert!(
            e.starts_with("error: s.json: objects[0].mesh.file: ")
                && e.contains("leaves the scene's folder"),
            "{mesh}: {e}"
        );
        assert!(
            !e.contains("no such file") && !e.contains("permission"),
            "{mesh}: {e}"
        );
    }
    for mesh in [
        "inside.obj",
        "./inside.obj",
        "sub/../inside.obj",
        "up/scenes/inside.obj",
    ] {
        let (code, e) = run(mesh);
        assert_eq!(code, Some(0), "{mesh}: {e}");
    }
    let (code, e) = run("sub/none.obj");
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("no such file"), "{e}");
}

/// A file that ends early is said the same way by the scene reader and the
/// learner-trace reader: where (columns from 1), the field as far as it was
/// read (no `?` for a key not read yet), and that the file ends early.
#[test]
fn a_file_that_ends_early_is_said_alike_by_both_readers() {
    let cut = b"{\"camera\": {\n";
    let scene = crate::common::refused(
        "ends-early-scene",
        &[("bad.json", cut)],
        &["render", "bad.json"],
    );
    assert_eq!(
        scene.trim(),
        "error: bad.json:2:1: camera: the file ends early: EOF while parsing an object"
    );
    let whitted =
        std::fs::read(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json"))
            .unwrap();
    let learner = crate::common::refused_with(
        2,
        "ends-early-learner",
        &[
            ("w.json", &whitted),
            ("bad.json", b"{\"format\": \"raytree-learner-trace\",\n"),
        ],
        &["check", "w.json", "--pixel", "1,1", "bad.json"],
    );
    assert_eq!(
        learner.trim(),
        "error: bad.json:2:1: not JSON: the file ends early: EOF while parsing a value"
    );
}
