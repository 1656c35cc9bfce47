//! The fuzzer's seeds: a valid input of each reader (shipped and generated
//! scenes, small OBJ files, real traces, NFF scenes holding every entity,
//! the structures CSVs, the learner trace examples), which the mutations
//! start from.

use std::path::Path;

use raytree::scene::source::SceneSource;
use raytree::scene::{generate, loader};
use serde_json::{Value, json};

/// `raytree structures` CSVs (issue 28): a comparison of two scenes, and a
/// grid sweep, written by the command's own writer from figures made up here
/// (the reader checks the ratios and medians against them, so a seed is
/// made, not typed).
pub(super) fn structures_seeds() -> Vec<String> {
    use raytree::methods::{Accel, Level};
    use raytree::trace::structure_sweep::{Comparison, Mode, Row, STRUCTURES, csv};
    let row = |scene: &str, structure: Accel, grid_res: Option<Level>, k: u64| Row {
        scene: scene.to_owned(),
        structure,
        grid_res,
        grid_cells: grid_res.map(|_| [8, 2, 8]),
        objects: 2001,
        rays: 6398 + k,
        steps: 1000 * k,
        primitives: 50_000 / (k + 1),
        build_seconds: 0.001 * k as f64,
        run_seconds: vec![0.01 * (k + 1) as f64, 0.02, 0.005],
    };
    let structures = Comparison {
        mode: Mode::Structures,
        about: "2026-11-25 21:09 UTC, 40×30, no protocol, 3 runs, threads = 1, load 0.5 0.4 0.3"
            .to_owned(),
        rows: ["a.json", "b, \"c\".nff"]
            .iter()
            .flat_map(|s| {
                STRUCTURES.iter().enumerate().map(move |(k, &a)| {
                    row(s, a, (a == Accel::Grid).then_some(Level::Auto), k as u64)
                })
            })
            .collect(),
    };
    let sweep = Comparison {
        mode: Mode::GridSweep,
        about: "x".to_owned(),
        rows: [Level::Given(2), Level::Given(160), Level::Auto]
            .iter()
            .enumerate()
            .map(|(k, &l)| row("a.json", Accel::Grid, Some(l), k as u64))
            .collect(),
    };
    vec![csv(&structures), csv(&sweep)]
}

/// Small NFF scenes holding every entity: the view, background, lights with
/// and without a color, materials opaque and transmitting, and each primitive.
pub(super) const NFF_SEEDS: [&str; 2] = [
    "# every entity\nv\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\nb 0.1 0.2 0.3\nl 2 -3 4\nl -2 -3 4 1 1 1\nf 1 0.5 0.2 0.7 0.3 20 0 0\np 4\n-2 -2 0\n2 -2 0\n2 2 0\n-2 2 0\ns 0 0 1 0.5\nf 0.9 0.9 1 0.1 0.1 100 0.8 1.5\nc\n1 0 0 0.3\n1 0 1 0.1\npp 3\n-1 0 0.5 0 -1 0\n-0.5 0 0.5 0 -1 0\n-0.75 0 1 0 -1 0.2\n",
    "v\nfrom 3 3 3\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.01\nresolution 5 5\nl 1 1 5\nf 1 0 0 1 0 100000 0 0\np 6\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\nc\n0 0 0 0.5\n0 0 1 0.5\n",
];

/// A folder holding what scenes refer to: `m.obj` and `n.obj`.
pub(super) fn folder() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("m.obj"), OBJ_SEEDS[0]).unwrap();
    std::fs::write(dir.path().join("n.obj"), generate::icosphere_obj(1)).unwrap();
    dir
}

pub(super) const OBJ_SEEDS: [&str; 3] = [
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n",
    "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nf 1/1 3/1 2/1\nf 1 2 4\nf -1 -2 -3\nf 2 3 4\n",
    "o a\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\no b\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf 4 5 6\n",
];

pub(super) fn scene_seeds() -> Vec<Value> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut seeds: Vec<Value> = [
        "whitted.json",
        "nested.json",
        "ellipsoids.json",
        "cones.json",
        "polygons.json",
    ]
    .iter()
    .map(|f| serde_json::from_str(&std::fs::read_to_string(root.join(f)).unwrap()).unwrap())
    .collect();
    seeds.push(serde_json::from_str(&generate::random_spheres(12, 1)).unwrap());
    seeds.push(serde_json::from_str(&generate::icosphere_scene("n.obj", 80)).unwrap());
    seeds.push(json!({
        "camera": {"eye": [0, 0, 5], "u": [1, 0, 0], "v": [0, 1, 0], "n": [0, 0, 1], "half_width": 1, "half_height": 0.75},
        "render": {"width": 8, "height": 6, "spp": 4, "weights": "fresnel", "offset": "epsilon=0.001"},
        "materials": {"m": {"checker": {"colors": [[1, 0, 0], [0, 0, 1]], "size": 0.5}}},
        "lights": [{"name": "l", "position": [1, 2, 3]}],
        "objects": [
            {"mesh": {"file": "m.obj", "smooth": false}, "material": "m"},
            {"box": {"min": [-1, -1, -1], "max": [0, 0, 0]}, "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 30}}, {"rotate_x": 10}, {"scale": [1, 2, 3]}]},
            {"triangle": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}},
            {"polygon": {"vertices": [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0.5, 0.2, 1], [0, 1, 1]], "one_sided": true}},
            {"polygon": {"vertices": [[0, 0, -1], [1, 0, -1], [0, 1, -1]], "normals": [[0, 0, 1], [0, 1, 1], [1, 0, 1]]}, "transform": [{"scale": [1, 2, 3]}]}
        ]
    }));
    seeds
}

pub(super) fn trace_seeds() -> Vec<Value> {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json"))
            .unwrap();
    let mut scene = loader::parse(&text, "s.json").unwrap();
    scene.settings.width = 64;
    scene.settings.height = 48;
    let source = SceneSource::new("s.json", &text);
    let pixel = raytree::tree::record::pixel(&scene, source.clone(), 42, 20, None).unwrap();
    scene.settings.spp = 4;
    let four = raytree::tree::record::pixel(&scene, source.clone(), 40, 30, None).unwrap();
    let ray = raytree::math::ray::Ray::new(glam::DVec3::new(0.9, 1.0, 1.2), glam::DVec3::X);
    let given = raytree::tree::record::ray(&scene, source, ray).unwrap();
    [pixel, four, given]
        .iter()
        .map(|t| serde_json::to_value(t).unwrap())
        .collect()
}

/// The learner trace examples of `docs/learner-trace/`, every one of them.
pub(super) fn learner_seeds() -> Vec<Value> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/learner-trace");
    let mut seeds: Vec<Value> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap())
        .collect();
    seeds.sort_by_key(Value::to_string);
    assert!(seeds.len() >= 2, "{}: the examples", dir.display());
    seeds
}

/// The scene the learner trace examples are of.
pub(super) const LEARNER_SCENE: &str = "scenes/whitted.json";
