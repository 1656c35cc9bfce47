//! A bad scene file, each fault one line naming the file and where, exit 1:
//! a file that is not there, JSON that does not parse (its line and
//! column), an unknown field, a value that makes no sense (the field's
//! path), an OBJ mesh that cannot be read (the OBJ file and its line).

use crate::commands::cli::fails;

const GOOD_OBJECTS: &str = r#""objects": [{"sphere": {"radius": 1}}]"#;

#[test]
fn missing_scene_file() {
    let e = fails("missing", None, &["nowhere.json"]);
    assert_eq!(e, "error: cannot read nowhere.json: no such file");
}

#[test]
fn malformed_json_names_line_and_column() {
    let e = fails(
        "malformed",
        Some("{\n  \"objects\": [\n    {\"sphere\": {\"radius\": 1}\n  ]\n}"),
        &[],
    );
    assert!(e.starts_with("error: bad.json:4:3: "), "{e}");
}

#[test]
fn unknown_field_names_its_path_and_the_expected_fields() {
    let e = fails(
        "unknown",
        Some("{\"objects\": [\n  {\"sphere\": {\"radus\": 1}}\n]}"),
        &[],
    );
    assert!(e.starts_with("error: bad.json:2:21: objects[0].sphere.radus: unknown field `radus`, expected `center` or `radius`"), "{e}");
}

#[test]
fn trailing_text_after_the_scene() {
    let e = fails("trailing", Some(&format!("{{{GOOD_OBJECTS}}} x")), &[]);
    assert!(e.contains("trailing characters"), "{e}");
}

#[test]
fn out_of_range_number() {
    let e = fails(
        "huge",
        Some(r#"{"objects": [{"sphere": {"radius": 1e999}}]}"#),
        &[],
    );
    assert!(
        e.contains("objects[0].sphere.radius") && e.contains("out of range"),
        "{e}"
    );
}

/// Scene files that parse but ask for what cannot be: each case's name, the
/// file's text, and the start of the message, which names the field at fault.
const FIELD_ERRORS: &[(&str, &str, &str)] = &[
    (
        "negative-radius",
        r#"{"objects": [{"sphere": {"radius": -1}}]}"#,
        "objects[0].sphere.radius: must be from 1e-9 to 1e9, got -1",
    ),
    (
        "zero-radius",
        r#"{"objects": [{"sphere": {"radius": 0}}]}"#,
        "objects[0].sphere.radius: must be from 1e-9 to 1e9, got 0",
    ),
    (
        "zero-normal",
        r#"{"objects": [{"plane": {"normal": [0, 0, 0]}}]}"#,
        "objects[0].plane.normal: must not be zero",
    ),
    (
        "singular",
        r#"{"objects": [{"sphere": {}, "transform": [{"scale": [1, 0, 1]}]}]}"#,
        "objects[0].transform[0].scale: each factor's size must be from 1e-9 to 1e9, got [1, 0, 1]",
    ),
    (
        "zero-axis",
        r#"{"objects": [{"sphere": {}, "transform": [{"rotate": {"axis": [0, 0, 0], "degrees": 5}}]}]}"#,
        "objects[0].transform[0].rotate.axis: must not be zero",
    ),
    (
        "ior",
        r#"{"materials": {"m": {"ior": 0}}, "objects": [{"sphere": {}, "material": "m"}]}"#,
        "materials.m.ior: a refractive index must be from 0.01 to 100, got 0",
    ),
    (
        "negative-ior",
        r#"{"materials": {"m": {"ior": -1.5}}, "objects": [{"sphere": {}, "material": "m"}]}"#,
        "materials.m.ior: a refractive index must be from 0.01 to 100, got -1.5",
    ),
    (
        "zero-width",
        r#"{"render": {"width": 0}}"#,
        "render.width: must be 1 to 32768, got 0",
    ),
    (
        "too-large",
        r#"{"render": {"width": 30000, "height": 30000}}"#,
        "render.width: 30000×30000 is 900000000 pixels",
    ),
    (
        "spp",
        r#"{"render": {"spp": 3}}"#,
        "render.spp: must be a square number",
    ),
    (
        "no-shape",
        r#"{"objects": [{"name": "x"}]}"#,
        "objects[0]: give exactly one shape",
    ),
    (
        "two-shapes",
        r#"{"objects": [{"sphere": {}, "plane": {}}]}"#,
        "objects[0]: give exactly one shape",
    ),
    (
        "flat-box",
        r#"{"objects": [{"box": {"min": [0, 0, 0], "max": [1, 0, 1]}}]}"#,
        "objects[0].box: min must be below max on every axis",
    ),
    (
        "line-triangle",
        r#"{"objects": [{"triangle": {"vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]}}]}"#,
        "objects[0].triangle.vertices: must be three points not on one line",
    ),
    (
        "two-vertex-polygon",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 0, 0]]}}]}"#,
        "objects[0].polygon.vertices: give at least 3 vertices, got 2",
    ),
    (
        "far-polygon-vertex",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 0, 0], [2e9, 1, 0]]}}]}"#,
        "objects[0].polygon.vertices[2]: every coordinate must be within ±1e9",
    ),
    (
        "line-polygon",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2], [0, 1, 0]]}}]}"#,
        "objects[0].polygon: vertices[0], vertices[1] and vertices[2] lie on one line",
    ),
    (
        "bent-polygon",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]]}}]}"#,
        "objects[0].polygon: vertices[3] lies 5e-1 off the plane of the first three",
    ),
    (
        "reflex-polygon",
        r#"{"objects": [{"polygon": {"vertices": [[2, -1, 0], [1, 0, 0], [2, 1, 0], [0, 0, 0]], "one_sided": true}}]}"#,
        "objects[0].polygon: vertices[1] is a reflex corner",
    ),
    (
        "patch-normals-count",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "normals": [[0, 0, 1]]}}]}"#,
        "objects[0].polygon.normals: give one normal per vertex: 3 vertices, 1 normals",
    ),
    (
        "patch-zero-normal",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "normals": [[0, 0, 1], [0, 0, 0], [0, 0, 1]]}}]}"#,
        "objects[0].polygon.normals[1]: must not be zero",
    ),
    (
        "polygon-and-triangle",
        r#"{"objects": [{"polygon": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}, "triangle": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]}"#,
        "objects[0]: give exactly one shape",
    ),
    (
        "unknown-material",
        r#"{"materials": {"glass": {}}, "objects": [{"sphere": {}, "material": "glas"}]}"#,
        "objects[0].material: no material named 'glas' (defined: glass)",
    ),
    (
        "color-and-checker",
        r#"{"materials": {"m": {"color": [1, 1, 1], "checker": {"colors": [[0,0,0],[1,1,1]]}}}}"#,
        "materials.m: give color or checker, not both",
    ),
    (
        "negative-color",
        r#"{"background": [0, -1, 0]}"#,
        "background: a color's components must be from 0 to 1e6, got [0, -1, 0]",
    ),
    (
        "reflective",
        r#"{"materials": {"m": {"reflective": 1.5}}}"#,
        "materials.m.reflective: must be from 0 to 1, got 1.5",
    ),
    (
        "checker-size",
        r#"{"materials": {"m": {"checker": {"colors": [[0,0,0],[1,1,1]], "size": 0}}}}"#,
        "materials.m.checker.size: must be from 1e-9 to 1e9, got 0",
    ),
    (
        "checker-sides",
        r#"{"materials": {"m": {"checker": {"colors": [[0,0,0],[1,1,1]], "size": [7, 0, 9]}}}}"#,
        "materials.m.checker.size: must be from 1e-9 to 1e9, got 0",
    ),
    (
        "eye-is-target",
        r#"{"camera": {"eye": [1, 2, 3], "look_at": [1, 2, 3]}}"#,
        "camera.look_at: must differ from camera.eye",
    ),
    (
        "fov",
        r#"{"camera": {"fov": 180}}"#,
        "camera.fov: must be from 0.001 to 179.999 degrees, got 180",
    ),
    (
        "mixed-camera",
        r#"{"camera": {"fov": 40, "u": [1, 0, 0]}}"#,
        "camera: give either look_at/up/fov or u/v/n",
    ),
    (
        "skewed-frame",
        r#"{"camera": {"u": [1, 0, 0], "v": [1, 1, 0], "n": [0, 0, 1], "half_width": 1, "half_height": 1}}"#,
        "camera: u, v and n must be mutually perpendicular",
    ),
];

#[test]
fn each_validation_error_names_its_field() {
    for (name, text, expected) in FIELD_ERRORS {
        let e = fails(name, Some(text), &[]);
        assert!(
            e.starts_with(&format!("error: bad.json: {expected}")),
            "{name}: {e}"
        );
    }
    // A checker size of the wrong shape fails while parsing: at its line and column.
    let e = fails(
        "checker-two-sides",
        Some(r#"{"materials": {"m": {"checker": {"colors": [[0,0,0],[1,1,1]], "size": [7, 9]}}}}"#),
        &[],
    );
    assert!(
        e.starts_with("error: bad.json:1:")
            && e.contains(
                ": materials.m.checker.size: expected a length, or three lengths [x, y, z]"
            ),
        "{e}"
    );
}

#[test]
fn bad_meshes_name_the_obj_file_and_line() {
    let cases = [
        ("missing.obj", None, "missing.obj: no such file"),
        (
            "bad-vertex.obj",
            Some("v 0 0 0\nv 1 0 0\nv 0 1 x\nf 1 2 3\n"),
            "bad-vertex.obj:3: position parse error",
        ),
        (
            "bad-index.obj",
            Some("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n"),
            "bad-index.obj:5: face vertex index out of bounds",
        ),
        (
            "nan.obj",
            Some("v 0 0 0\nv 1 0 0\nv 0 1 NaN\nf 1 2 3\n"),
            "nan.obj:3: a coordinate is not a finite number",
        ),
        ("empty.obj", Some("# nothing\n"), "empty.obj: has no faces"),
    ];
    for (file, text, expected) in cases {
        // The OBJ file beside the scene: a mesh is read from the scene's folder.
        let scene = format!(r#"{{"objects": [{{"mesh": {{"file": "{file}"}}}}]}}"#);
        let mut files: Vec<(&str, &[u8])> = vec![("bad.json", scene.as_bytes())];
        if let Some(text) = text {
            files.push((file, text.as_bytes()));
        }
        let e = crate::common::refused(file, &files, &["render", "bad.json"]);
        let expected = format!("error: {expected}");
        assert!(e.starts_with(&expected), "{file}: {e}");
        assert!(
            e.ends_with("(the mesh of bad.json: objects[0].mesh.file)"),
            "{file}: {e}"
        );
    }
    // An empty name is the scene's fault, named by its field (it read as
    // "error: : no such file").
    for name in ["", " "] {
        let scene = format!(r#"{{"objects": [{{"mesh": {{"file": "{name}"}}}}]}}"#);
        let e = crate::common::refused(
            "empty-mesh-name",
            &[("bad.json", scene.as_bytes())],
            &["render", "bad.json"],
        );
        assert_eq!(
            e,
            "error: bad.json: objects[0].mesh.file: must name an OBJ file, got an empty name"
        );
    }
}
