//! Golden traces: JSON traces of chosen pixels (and one chosen ray) of the
//! shipped scenes, in `tests/traces/`. Each is traced again and compared field by
//! field; the first difference is reported with its path.
//!
//! Regenerate them after an intended change with
//! `RAYTREE_BLESS=1 cargo test --release golden_traces`, and read the diff.
//!
//! Tolerance: numbers agree to 1e-9 relative (1e-9 absolute near zero). The same
//! code on the same platform reproduces every bit; another platform's libm may
//! round `powf` in the Phong highlight differently in the last place (~1e-16), and
//! the recursion carries that through a handful of additions. 1e-9 is far above
//! that and far below what any change to a formula would move.

use std::path::PathBuf;

use glam::DVec3;
use raytree::math::ray::Ray;
use raytree::scene::source::SceneSource;
use raytree::tree::document::TraceDocument;
use serde_json::Value;

const REL_TOL: f64 = 1e-9;

enum Target {
    Pixel(u32, u32),
    Ray([f64; 3], [f64; 3]),
}

struct Golden {
    name: &'static str,
    scene: &'static str,
    target: Target,
    spp: Option<u32>,
}

const GOLDEN: &[Golden] = &[
    Golden {
        name: "whitted-diffuse",
        scene: "whitted.json",
        target: Target::Pixel(120, 420),
        spp: None,
    },
    Golden {
        name: "whitted-glass-shadow",
        scene: "whitted.json",
        target: Target::Pixel(440, 376),
        spp: None,
    },
    Golden {
        name: "whitted-shadow",
        scene: "whitted.json",
        target: Target::Pixel(168, 296),
        spp: None,
    },
    Golden {
        name: "whitted-mirror",
        scene: "whitted.json",
        target: Target::Pixel(264, 200),
        spp: None,
    },
    Golden {
        name: "whitted-glass-tir",
        scene: "whitted.json",
        target: Target::Pixel(416, 209),
        spp: None,
    },
    Golden {
        name: "whitted-miss",
        scene: "whitted.json",
        target: Target::Pixel(8, 8),
        spp: None,
    },
    Golden {
        name: "whitted-glass-edge-4spp",
        scene: "whitted.json",
        target: Target::Pixel(330, 240),
        spp: Some(4),
    },
    Golden {
        name: "nested-ray-to-core",
        scene: "nested.json",
        target: Target::Ray([0.0, 2.2, 6.0], [0.05, -0.15, -1.0]),
        spp: None,
    },
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn trace(g: &Golden) -> TraceDocument {
    let file = format!("scenes/{}", g.scene);
    let text = std::fs::read_to_string(root().join(&file)).unwrap();
    let mut scene = raytree::scene::loader::parse(&text, &file).unwrap();
    if let Some(spp) = g.spp {
        scene.settings.spp = spp;
    }
    let source = SceneSource::new(&file, &text);
    match g.target {
        Target::Pixel(x, y) => raytree::tree::record::pixel(&scene, source, x, y, None).unwrap(),
        Target::Ray(o, d) => {
            raytree::tree::record::ray(&scene, source, Ray::new(DVec3::from(o), DVec3::from(d)))
                .unwrap()
        }
    }
}

/// The first place where `got` differs from `want`, as `path: want vs got`.
fn difference(want: &Value, got: &Value, path: &str) -> Option<String> {
    match (want, got) {
        (Value::Number(a), Value::Number(b)) => {
            let (a, b) = (a.as_f64().unwrap(), b.as_f64().unwrap());
            let scale = a.abs().max(b.abs()).max(1.0);
            ((a - b).abs() > REL_TOL * scale).then(|| format!("{path}: {a} in the golden, {b} now"))
        }
        (Value::Array(a), Value::Array(b)) => {
            if a.len() != b.len() {
                return Some(format!(
                    "{path}: {} items in the golden, {} now",
                    a.len(),
                    b.len()
                ));
            }
            a.iter()
                .zip(b)
                .enumerate()
                .find_map(|(i, (x, y))| difference(x, y, &format!("{path}[{i}]")))
        }
        (Value::Object(a), Value::Object(b)) => {
            if let Some(k) = a
                .keys()
                .find(|k| !b.contains_key(*k))
                .or_else(|| b.keys().find(|k| !a.contains_key(*k)))
            {
                return Some(format!(
                    "{path}.{k}: present in only one of the golden and the new trace"
                ));
            }
            a.iter()
                .find_map(|(k, v)| difference(v, &b[k], &format!("{path}.{k}")))
        }
        _ => (want != got).then(|| format!("{path}: {want} in the golden, {got} now")),
    }
}

#[test]
fn golden_traces_still_hold() {
    let bless = std::env::var_os("RAYTREE_BLESS").is_some();
    let mut failures = Vec::new();
    for g in GOLDEN {
        let path = root().join("tests/traces").join(format!("{}.json", g.name));
        let fresh = trace(g);
        if bless {
            std::fs::write(&path, fresh.to_json()).unwrap();
            println!("blessed {}", path.display());
            continue;
        }
        let text = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (make it with RAYTREE_BLESS=1)", path.display()));
        let golden: TraceDocument = serde_json::from_str(&text)
            .unwrap_or_else(|e| panic!("{}: not a trace: {e}", path.display()));
        if golden.scene.hash != fresh.scene.hash {
            failures.push(format!("{}: scenes/{} changed since the golden was made (re-bless after checking the change)", g.name, g.scene));
            continue;
        }
        if let Some(d) = difference(
            &serde_json::to_value(&golden).unwrap(),
            &serde_json::to_value(&fresh).unwrap(),
            "",
        ) {
            failures.push(format!("{}: {d}", g.name));
        }
    }
    assert!(
        failures.is_empty(),
        "golden traces differ:\n{}",
        failures.join("\n")
    );
}

#[test]
fn golden_traces_show_what_they_are_named_for() {
    use raytree::trace::recorder::{Branch, RayKind};
    use raytree::tree::ray_tree::ShadowOutcomeRecord;
    let load = |name: &str| -> TraceDocument {
        serde_json::from_str(
            &std::fs::read_to_string(root().join("tests/traces").join(format!("{name}.json")))
                .unwrap(),
        )
        .unwrap()
    };
    let root_node = |t: &TraceDocument| t.samples[0].tree.nodes[0].clone();

    let diffuse = root_node(&load("whitted-diffuse"));
    assert_eq!(diffuse.hit.as_ref().unwrap().name, "floor");
    assert!(diffuse.shadow_rays.iter().all(
        |s| matches!(s.outcome, ShadowOutcomeRecord::Reaches { transmitted } if transmitted == 1.0)
    ));

    let through_glass = root_node(&load("whitted-glass-shadow"));
    assert!(through_glass.shadow_rays.iter().all(
        |s| matches!(s.outcome, ShadowOutcomeRecord::Reaches { transmitted } if transmitted == 0.88)
    ));

    let shadow = root_node(&load("whitted-shadow"));
    assert!(
        shadow
            .shadow_rays
            .iter()
            .all(|s| matches!(s.outcome, ShadowOutcomeRecord::Blocked { .. }))
    );

    let mirror = load("whitted-mirror");
    assert_eq!(root_node(&mirror).hit.unwrap().name, "mirror");
    assert_eq!(
        root_node(&mirror).reflected.unwrap().outcome,
        Branch::Traced
    );

    let glass = load("whitted-glass-tir");
    let nodes = &glass.samples[0].tree.nodes;
    assert_eq!(nodes[0].hit.as_ref().unwrap().name, "glass");
    assert!(nodes.iter().any(|n| n.kind == RayKind::Refracted));
    assert!(nodes.iter().any(|n| {
        n.refracted
            .as_ref()
            .is_some_and(|r| r.outcome == Branch::TotalInternalReflection)
    }));

    assert!(root_node(&load("whitted-miss")).hit.is_none());
    assert_eq!(load("whitted-glass-edge-4spp").samples.len(), 4);
    assert!(
        load("nested-ray-to-core").samples[0]
            .tree
            .nodes
            .iter()
            .any(|n| n.hit.as_ref().is_some_and(|h| h.name == "inner"))
    );
}
