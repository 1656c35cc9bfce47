//! The recorded ray tree: its arithmetic adds up, it agrees with the renderer bit
//! for bit, its JSON reads back, every field is documented, and its steps follow
//! the algorithm's order.

use crate::common;

use std::collections::BTreeSet;

use glam::DVec3;
use raytree::math::ray::Ray;
use raytree::methods::Antialiasing;
use raytree::scene::Scene;
use raytree::scene::source::SceneSource;
use raytree::trace::recorder::Branch;
use raytree::trace::render::render;
use raytree::tree::document::TraceDocument;
use raytree::tree::ray_tree::RayTree;
use raytree::tree::steps::StepKind;

fn source(name: &str) -> SceneSource {
    SceneSource::new(&format!("scenes/{name}"), "")
}

/// Traces of a coarse grid of pixels of every shipped scene at 160×120.
fn grid_traces() -> Vec<(String, Scene, TraceDocument)> {
    let mut out = Vec::new();
    for (name, mut scene) in common::shipped() {
        scene.settings.width = 160;
        scene.settings.height = 120;
        for y in (3..120).step_by(9) {
            for x in (5..160).step_by(11) {
                let trace = raytree::tree::record::pixel(&scene, source(name), x, y, None).unwrap();
                out.push((format!("{name} pixel {x},{y}"), scene.clone(), trace));
            }
        }
    }
    out
}

/// Tolerance for the sum check: the recorded parts are the very values the
/// tracer added, so the sums agree to a few ULPs of colors near 1.
const SUM_TOL: f64 = 1e-12;

fn check_sums(label: &str, scene: &Scene, tree: &RayTree) {
    for (i, node) in tree.nodes.iter().enumerate() {
        let s = &node.sum;
        let at = format!("{label}, node {i}");
        assert!(
            common::close(
                s.color,
                s.local + s.k_rfl * s.reflected + s.k_rfa * s.refracted,
                SUM_TOL
            ),
            "{at}: color ≠ local + k_rfl·reflected + k_rfa·refracted"
        );
        match (&node.hit, &node.local) {
            (None, None) => assert!(
                s.color == scene.background && s.k_rfl == 0.0 && s.k_rfa == 0.0,
                "{at}: a miss returns the background"
            ),
            (Some(_), Some(local)) => {
                let lights: DVec3 = local.lights.iter().map(|l| l.diffuse + l.specular).sum();
                assert!(
                    common::close(local.total, local.ambient + lights, SUM_TOL),
                    "{at}: local ≠ ambient + Σ(diffuse + specular)"
                );
                assert_eq!(local.total, s.local, "{at}");
                assert_eq!(
                    (local.lights.len(), node.shadow_rays.len()),
                    (scene.lights.len(), scene.lights.len()),
                    "{at}: one term and one shadow ray per light"
                );
            }
            _ => panic!("{at}: a hit has local terms, a miss none"),
        }
        for (branch, k, color) in [
            (&node.reflected, s.k_rfl, s.reflected),
            (&node.refracted, s.k_rfa, s.refracted),
        ] {
            let Some(branch) = branch else { continue };
            match branch.node {
                Some(c) => {
                    let child = &tree.nodes[c];
                    assert_eq!(branch.outcome, Branch::Traced, "{at}");
                    assert_eq!(
                        child.color(),
                        color,
                        "{at}: the child's color is what the parent added"
                    );
                    assert_eq!(
                        (child.parent, child.depth),
                        (Some(i), node.depth + 1),
                        "{at}"
                    );
                    assert_eq!(
                        child.weight,
                        node.weight * k,
                        "{at}: weight is the product of coefficients"
                    );
                }
                None => assert_eq!(color, DVec3::ZERO, "{at}: an untraced branch adds nothing"),
            }
        }
    }
}

#[test]
fn every_color_is_the_sum_of_its_recorded_parts() {
    let traces = grid_traces();
    let mut nodes = 0;
    let mut outcomes = BTreeSet::new();
    for (label, scene, trace) in &traces {
        for sample in &trace.samples {
            check_sums(label, scene, &sample.tree);
            nodes += sample.tree.nodes.len();
            for n in &sample.tree.nodes {
                outcomes.extend(
                    [&n.reflected, &n.refracted]
                        .into_iter()
                        .flatten()
                        .map(|b| format!("{:?}", b.outcome)),
                );
            }
        }
    }
    println!(
        "checked {nodes} nodes in {} trees; branch outcomes seen: {outcomes:?}",
        traces.len()
    );
    for expected in [
        "Traced",
        "NoCoefficient",
        "WeightCutoff",
        "TotalInternalReflection",
    ] {
        assert!(
            outcomes.contains(expected),
            "the trees should include a {expected} branch"
        );
    }
}

#[test]
fn traced_color_equals_rendered_color_bit_for_bit() {
    for (name, mut scene) in common::shipped() {
        for (width, height, spp, aa) in [
            (64, 48, 1, Antialiasing::Grid),
            (24, 18, 4, Antialiasing::Grid),
            (
                24,
                18,
                1,
                Antialiasing::Adaptive {
                    threshold: 0.05,
                    levels: 3,
                },
            ),
        ] {
            scene.settings.width = width;
            scene.settings.height = height;
            scene.settings.spp = spp;
            scene.settings.aa = aa;
            let image = render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
            for y in 0..height {
                for x in 0..width {
                    let trace =
                        raytree::tree::record::pixel(&scene, source(name), x, y, None).unwrap();
                    assert_eq!(
                        trace.color,
                        image.get(x, y),
                        "{name} {width}×{height} spp {spp}: pixel {x},{y}"
                    );
                    if aa == Antialiasing::Grid {
                        assert_eq!(trace.samples.len(), spp as usize);
                    } else {
                        assert!(trace.samples.len() >= 4, "the four corners at least");
                    }
                }
            }
        }
    }
}

#[test]
fn json_reads_back_exactly() {
    let scene = raytree::scene::loader::whitted();
    let pixel =
        raytree::tree::record::pixel(&scene, source("whitted.json"), 416, 209, None).unwrap();
    let ray = raytree::tree::record::ray(
        &scene,
        source("whitted.json"),
        Ray::new(DVec3::new(0.0, 1.6, 7.0), DVec3::new(0.1, -0.1, -1.0)),
    )
    .unwrap();
    for trace in [pixel, ray] {
        // Compared as values so a failure names the field rather than printing two trees.
        let back: TraceDocument = serde_json::from_str(&trace.to_json()).unwrap();
        assert!(
            back == trace,
            "pretty JSON changed a value: {:?}",
            first_difference(&back, &trace)
        );
        let compact: TraceDocument =
            serde_json::from_str(&serde_json::to_string(&trace).unwrap()).unwrap();
        assert!(
            compact == trace,
            "compact JSON changed a value: {:?}",
            first_difference(&compact, &trace)
        );
    }
}

/// The path and values of the first field where two traces differ.
fn first_difference(a: &TraceDocument, b: &TraceDocument) -> Option<String> {
    fn walk(a: &serde_json::Value, b: &serde_json::Value, path: String) -> Option<String> {
        use serde_json::Value::{Array, Object};
        match (a, b) {
            (Object(x), Object(y)) => x
                .iter()
                .find_map(|(k, v)| walk(v, &y[k], format!("{path}.{k}"))),
            (Array(x), Array(y)) => x
                .iter()
                .zip(y)
                .enumerate()
                .find_map(|(i, (v, w))| walk(v, w, format!("{path}[{i}]"))),
            _ => (a != b).then(|| format!("{path}: {a} vs {b}")),
        }
    }
    walk(
        &serde_json::to_value(a).unwrap(),
        &serde_json::to_value(b).unwrap(),
        String::new(),
    )
}

#[test]
fn reading_rejects_unknown_fields() {
    let scene = raytree::scene::loader::whitted();
    let trace =
        raytree::tree::record::pixel(&scene, source("whitted.json"), 100, 100, None).unwrap();
    let text = trace.to_json().replacen(
        "\"format\": \"raytree-trace\",",
        "\"format\": \"raytree-trace\", \"extra\": 0,",
        1,
    );
    let err = serde_json::from_str::<TraceDocument>(&text)
        .unwrap_err()
        .to_string();
    assert!(err.contains("unknown field `extra`"), "{err}");
}

/// Every key and every tag value a trace can hold is documented in the book.
#[test]
fn every_field_is_documented() {
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/book/src/trace-format.md"
    ))
    .unwrap();
    let (mut keys, mut tags) = (BTreeSet::new(), BTreeSet::new());
    for t in &sample_traces() {
        collect(&serde_json::to_value(t).unwrap(), &mut keys, &mut tags);
    }
    let missing: Vec<_> = keys
        .iter()
        .filter(|k| !doc.contains(&format!("`{k}`")))
        .collect();
    assert!(
        missing.is_empty(),
        "fields missing from book/src/trace-format.md: {missing:?}"
    );
    let missing: Vec<_> = tags
        .iter()
        .filter(|v| !doc.contains(&format!("`\"{v}\"`")))
        .collect();
    assert!(
        missing.is_empty(),
        "values missing from book/src/trace-format.md: {missing:?}"
    );
    for tag in TAGS_SHOWN {
        assert!(tags.contains(tag), "the sample traces should show {tag}");
    }
}

/// The tag values the sample traces must show between them: the tests'
/// methods, what became of each root, what t counts, and why a ray stops.
const TAGS_SHOWN: [&str; 23] = [
    "quadratic",
    "plane",
    "slabs",
    "crossing",
    "parallel",
    "barycentric",
    "face",
    "cone_quadratic",
    "onto_cone",
    "chosen",
    "farther",
    "behind",
    "image_plane",
    "direction",
    "distance",
    "stable_quadratic",
    "plane_equation",
    "watertight",
    "crossing_number",
    "faces_away",
    "max_depth",
    "total_internal_reflection",
    "weight_cutoff",
];

/// Traces that between them hold every field and tag: pixels and a ray of
/// the Whitted scene (one at max depth 2), and every kind of test.
fn sample_traces() -> Vec<TraceDocument> {
    let scene = raytree::scene::loader::whitted();
    let src = source("whitted.json");
    let mut traces: Vec<TraceDocument> = [(8, 8), (440, 376), (168, 296), (264, 200), (416, 209)]
        .iter()
        .map(|&(x, y)| raytree::tree::record::pixel(&scene, src.clone(), x, y, None).unwrap())
        .collect();
    traces.push(
        raytree::tree::record::ray(
            &scene,
            src.clone(),
            Ray::new(DVec3::new(0.0, 1.6, 7.0), DVec3::new(0.1, -0.1, -1.0)),
        )
        .unwrap(),
    );
    let mut shallow = scene.clone();
    shallow.settings.max_depth = 2;
    traces.push(raytree::tree::record::pixel(&shallow, src.clone(), 416, 209, None).unwrap());
    traces.extend(shape_traces(&src));
    traces
}

/// Transformed spheres, a mesh, a cone, a box, a triangle and a polygon:
/// every kind of test.
fn shape_traces(src: &SceneSource) -> Vec<TraceDocument> {
    let mut traces = Vec::new();
    for (name, x, y) in [
        ("ellipsoids.json", 320, 240),
        ("gaspra.json", 320, 240),
        ("cones.json", 540, 280),
    ] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name);
        let s = raytree::scene::loader::load(&path).unwrap();
        traces.push(raytree::tree::record::pixel(&s, src.clone(), x, y, None).unwrap());
    }
    let shapes = common::scene(
        r#"{ "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]}, "render": {"width": 9, "height": 9},
             "objects": [{"box": {"min": [-1, -1, -1], "max": [0.5, 0.5, 0]}},
                         {"triangle": {"vertices": [[0, 0, 1], [2, 0, 1], [0, 2, 1]]}},
                         {"polygon": {"vertices": [[-2, 0, 2], [-2, -1, 2], [-1, -1, 2], [-1, 0, 2]], "one_sided": true}}] }"#,
    );
    for (x, y) in [(4, 4), (5, 3), (2, 6), (1, 5)] {
        traces.push(raytree::tree::record::pixel(&shapes, src.clone(), x, y, None).unwrap());
    }
    traces
}

/// Collects object keys, and the string values of the enum-like fields.
fn collect(v: &serde_json::Value, keys: &mut BTreeSet<String>, tags: &mut BTreeSet<String>) {
    match v {
        serde_json::Value::Object(map) => {
            for (k, v) in map {
                keys.insert(k.clone());
                let enum_like = ["kind", "outcome", "fate", "method", "t_unit", "placement"];
                if let (Some(s), true) = (v.as_str(), enum_like.contains(&k.as_str())) {
                    tags.insert(s.to_owned());
                }
                collect(v, keys, tags);
            }
        }
        serde_json::Value::Array(items) => items.iter().for_each(|i| collect(i, keys, tags)),
        _ => {}
    }
}

#[test]
fn steps_follow_the_algorithm() {
    for (label, _, trace) in grid_traces().iter().step_by(7) {
        let tree = &trace.samples[0].tree;
        let mut steps = trace.steps(0);
        // A pixel's first step is the camera stage that made its primary ray.
        assert_eq!(
            steps.remove(0).kind,
            StepKind::Camera,
            "{label}: a pixel starts at the camera"
        );
        // Rays are spawned in the order the nodes were recorded.
        let spawned: Vec<usize> = steps
            .iter()
            .filter(|s| s.kind == StepKind::Spawn)
            .map(|s| s.node)
            .collect();
        assert_eq!(
            spawned,
            (0..tree.nodes.len()).collect::<Vec<_>>(),
            "{label}"
        );
        // Each ray's steps run spawn → tests → hit or miss → shadows → local → … → return.
        for (i, node) in tree.nodes.iter().enumerate() {
            let own: Vec<StepKind> = steps
                .iter()
                .filter(|s| s.node == i)
                .map(|s| s.kind)
                .collect();
            let tests = node.tests.len();
            assert_eq!(own[0], StepKind::Spawn, "{label}");
            assert_eq!(
                own[1..=tests],
                (0..tests).map(StepKind::Test).collect::<Vec<_>>(),
                "{label}: node {i}: {own:?}"
            );
            assert_eq!(*own.last().unwrap(), StepKind::Return, "{label}");
            if node.hit.is_some() {
                let after = &own[tests + 1..];
                let shadows = node.shadow_rays.len();
                assert_eq!(after[0], StepKind::Hit, "{label}");
                assert_eq!(
                    after[1..=shadows],
                    (0..shadows).map(StepKind::Shadow).collect::<Vec<_>>(),
                    "{label}"
                );
                assert_eq!(
                    &after[shadows + 1..],
                    &[
                        StepKind::Local,
                        StepKind::Reflect,
                        StepKind::Refract,
                        StepKind::Combine,
                        StepKind::Return
                    ],
                    "{label}"
                );
            } else {
                assert_eq!(
                    &own[tests + 1..],
                    &[StepKind::Miss, StepKind::Return],
                    "{label}"
                );
            }
        }
        assert_eq!(
            steps.last().unwrap().node,
            0,
            "{label}: the last step returns the pixel's color"
        );
    }
}

#[test]
fn step_texts_carry_their_numbers() {
    let scene = raytree::scene::loader::whitted();
    let trace =
        raytree::tree::record::pixel(&scene, source("whitted.json"), 168, 296, None).unwrap();
    let steps = trace.steps(0);
    let texts: Vec<String> = steps
        .iter()
        .map(|s| raytree::views::text::describe(&trace, 0, s).0)
        .collect();
    let blocked = texts
        .iter()
        .find(|t| t.starts_with("shadow ray to light 'key': blocked by 'mirror' at t = "))
        .expect("the key light is blocked by the mirror");
    let blocked = blocked.trim_end_matches(" (t = 1 at the light)");
    let t = match &trace.samples[0].tree.nodes[0].shadow_rays[0].outcome {
        raytree::tree::ray_tree::ShadowOutcomeRecord::Blocked { t, .. } => *t,
        other => panic!("{other:?}"),
    };
    assert!(
        blocked.ends_with(&raytree::views::numbers::num(t)),
        "{blocked}"
    );
    assert!(
        texts
            .iter()
            .any(|t| t.starts_with("test plane 'floor': n·c = ")),
        "{texts:?}"
    );
}
