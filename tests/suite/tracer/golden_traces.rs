//! Golden traces: JSON traces of chosen pixels (and one chosen ray) of the
//! shipped scenes, in `tests/traces/`, each exactly what its `raytree trace …
//! --json` command writes. Each command is run again and its output compared
//! byte for byte with the committed file; when they differ, the first field
//! that differs is named with its path.
//!
//! Regenerate them after an intended change with
//! `RAYTREE_BLESS=1 cargo test --release golden_traces`, and read the diff.
//!
//! Exact, not within a tolerance: the same code on the same platform
//! reproduces every bit, and a comparison that forgives anything (a rounding,
//! a field read back as its default) lets a golden fall behind the code
//! unnoticed. Another platform's libm may round `powf` in the Phong highlight
//! differently in the last place; that would show here as a field named with
//! its two values, to be judged, not hidden.

use std::path::{Path, PathBuf};
use std::process::Command;

use raytree::tree::document::TraceDocument;
use serde_json::Value;

struct Golden {
    name: &'static str,
    /// The arguments of `raytree`, run from the repository.
    args: &'static [&'static str],
}

/// Lesson 12's scene of 32 spheres, where cells and nodes are big enough to see.
const SCATTER: &str = "lessons/12-efficiency/scatter.json";

const GOLDEN: &[Golden] = &[
    Golden {
        name: "whitted-diffuse",
        args: &["trace", "scenes/whitted.json", "--pixel", "120,420"],
    },
    Golden {
        name: "whitted-glass-shadow",
        args: &["trace", "scenes/whitted.json", "--pixel", "440,376"],
    },
    Golden {
        name: "whitted-shadow",
        args: &["trace", "scenes/whitted.json", "--pixel", "168,296"],
    },
    Golden {
        name: "whitted-mirror",
        args: &["trace", "scenes/whitted.json", "--pixel", "264,200"],
    },
    Golden {
        name: "whitted-glass-tir",
        args: &["trace", "scenes/whitted.json", "--pixel", "416,209"],
    },
    Golden {
        name: "whitted-miss",
        args: &["trace", "scenes/whitted.json", "--pixel", "8,8"],
    },
    Golden {
        name: "whitted-glass-edge-4spp",
        args: &[
            "trace",
            "scenes/whitted.json",
            "--pixel",
            "330,240",
            "--spp",
            "4",
        ],
    },
    Golden {
        name: "polygons-star",
        args: &["trace", "scenes/polygons.json", "--pixel", "95,215"],
    },
    Golden {
        name: "polygons-vase",
        args: &["trace", "scenes/polygons.json", "--pixel", "360,200"],
    },
    Golden {
        name: "cones-horn-inside",
        args: &["trace", "scenes/cones.json", "--pixel", "540,280"],
    },
    // One ray through each structure of the efficiency slide (issue 28):
    // the same pixel of lesson 12's small scene, its steps in `boxes`.
    Golden {
        name: "scatter-bvh",
        args: &["trace", SCATTER, "--pixel", "497,160", "--accel", "bvh"],
    },
    Golden {
        name: "scatter-grid",
        args: &["trace", SCATTER, "--pixel", "497,160", "--accel", "grid"],
    },
    Golden {
        name: "scatter-octree",
        args: &["trace", SCATTER, "--pixel", "497,160", "--accel", "octree"],
    },
    Golden {
        name: "scatter-bsp",
        args: &["trace", SCATTER, "--pixel", "497,160", "--accel", "bsp"],
    },
    Golden {
        name: "nested-ray-to-core",
        args: &[
            "trace",
            "scenes/nested.json",
            "--ray",
            "0,2.2,6:0.05,-0.15,-1",
        ],
    },
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// What `raytree ARGS --json` writes today, run from the repository.
fn traced(g: &Golden) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(g.args)
        .arg("--json")
        .current_dir(root())
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "raytree {} --json: {}",
        g.args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("a trace is UTF-8")
}

/// Writes every golden into `dir`, as a bless does.
fn bless_into(dir: &Path) {
    for g in GOLDEN {
        let path = dir.join(format!("{}.json", g.name));
        // Written beside and renamed into place, so that a test reading the
        // committed goldens while a bless runs never sees half a file.
        let part = path.with_extension("json.part");
        std::fs::write(&part, traced(g)).unwrap();
        std::fs::rename(&part, &path).unwrap();
        println!("blessed {}", path.display());
    }
}

/// The first place where `got` differs from `want`, as `path: want vs got`.
/// Values are compared exactly, every field of both.
fn difference(want: &Value, got: &Value, path: &str) -> Option<String> {
    match (want, got) {
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
            if let Some(k) = a.keys().find(|k| !b.contains_key(*k)) {
                return Some(format!("{path}.{k}: in the golden, not in the new trace"));
            }
            if let Some(k) = b.keys().find(|k| !a.contains_key(*k)) {
                return Some(format!("{path}.{k}: in the new trace, not in the golden"));
            }
            a.iter()
                .find_map(|(k, v)| difference(v, &b[k], &format!("{path}.{k}")))
        }
        _ => (want != got).then(|| format!("{path}: {want} in the golden, {got} now")),
    }
}

/// Why the committed text `want` is not `got`, byte for byte: the first field
/// that differs, or else the first line (the same values written otherwise).
fn why_differs(want: &str, got: &str) -> String {
    let parse = |t: &str| serde_json::from_str::<Value>(t);
    if let (Ok(w), Ok(g)) = (parse(want), parse(got))
        && let Some(d) = difference(&w, &g, "")
    {
        return d;
    }
    let line = want
        .lines()
        .zip(got.lines())
        .position(|(a, b)| a != b)
        .unwrap_or(want.lines().count().min(got.lines().count()));
    format!(
        "the same values, written differently from line {}: {:?} in the golden, {:?} now",
        line + 1,
        want.lines().nth(line).unwrap_or(""),
        got.lines().nth(line).unwrap_or("")
    )
}

#[test]
fn golden_traces_still_hold() {
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        bless_into(&root().join("tests/traces"));
        return;
    }
    let mut failures = Vec::new();
    for g in GOLDEN {
        let path = root().join("tests/traces").join(format!("{}.json", g.name));
        let committed = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (make it with RAYTREE_BLESS=1)", path.display()));
        let fresh = traced(g);
        if committed != fresh {
            failures.push(format!(
                "{} (raytree {} --json): {}",
                g.name,
                g.args.join(" "),
                why_differs(&committed, &fresh)
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "golden traces differ (RAYTREE_BLESS=1 cargo test --release golden_traces, then read the diff):\n{}",
        failures.join("\n")
    );
}

/// A bless on a clean checkout rewrites nothing: blessed into an empty
/// folder, the goldens are the committed files byte for byte, and
/// `tests/traces/` holds no trace that no golden makes.
#[test]
fn blessing_a_clean_checkout_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    bless_into(dir.path());
    let jsons = |d: &Path| -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .filter(|n| n.ends_with(".json"))
            .collect();
        names.sort();
        names
    };
    let committed_dir = root().join("tests/traces");
    assert_eq!(
        jsons(dir.path()),
        jsons(&committed_dir),
        "tests/traces/ holds exactly the goldens"
    );
    let changed: Vec<String> = jsons(dir.path())
        .into_iter()
        .filter(|n| {
            std::fs::read(dir.path().join(n)).unwrap()
                != std::fs::read(committed_dir.join(n)).unwrap()
        })
        .collect();
    assert!(
        changed.is_empty(),
        "a bless would rewrite {} (RAYTREE_BLESS=1 cargo test --release golden_traces, then read the diff)",
        changed.join(", ")
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
    // Through the horn's wide open end onto its inner side: the crossing
    // before the open end is no root, the one inside is the hit, met from inside.
    let horn = root_node(&load("cones-horn-inside"));
    let hit = horn.hit.as_ref().unwrap();
    assert_eq!(hit.name, "horn");
    assert!(hit.normal.dot(horn.direction) > 0.0);
    let test = horn.tests.iter().find(|t| t.name == "horn").unwrap();
    let Some(raytree::tree::arithmetic::Arithmetic::ConeQuadratic { crossings, .. }) =
        &test.arithmetic
    else {
        panic!("the horn's test records its quadratic")
    };
    assert!(crossings.len() == 2 && crossings[0].z < 0.0 && test.roots.len() == 1);
    // The same ray through each structure: the same hit, found through that
    // structure's own steps (recorded, and named by the trace's `structure`).
    for (name, structure) in [
        ("scatter-bvh", raytree::methods::Accel::Bvh),
        ("scatter-grid", raytree::methods::Accel::Grid),
        ("scatter-octree", raytree::methods::Accel::Octree),
        ("scatter-bsp", raytree::methods::Accel::Bsp),
    ] {
        let trace = load(name);
        assert_eq!(trace.structure, structure, "{name}");
        let ray = root_node(&trace);
        assert_eq!(ray.hit.as_ref().unwrap().name, "ball5", "{name}");
        assert!(ray.tested.boxes > 0, "{name}: the walk took steps");
        assert_eq!(ray.boxes.len() as u32, ray.tested.boxes, "{name}");
        // Fewer objects than the 33 (32 spheres and the floor) a ray tests
        // without a structure; the floor, unbounded, is tested either way.
        assert!(
            (2..33).contains(&ray.tested.primitives),
            "{name}: {:?}",
            ray.tested
        );
    }
    assert!(
        load("nested-ray-to-core").samples[0]
            .tree
            .nodes
            .iter()
            .any(|n| n.hit.as_ref().is_some_and(|h| h.name == "inner"))
    );
}
