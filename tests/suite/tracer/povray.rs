//! The POV-Ray twins in benches/povray/ describe the same scenes as scenes/:
//! the generated sphere list agrees with scenes/spheres.json, and the hand-written
//! files name the same camera and lights as the JSON scenes.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// `spheres.inc`: one POV-Ray sphere per raytree sphere, with the texture of the
/// same name (and the glass interior for glass).
fn spheres_inc(scene: &serde_json::Value) -> String {
    let mut out = String::from(
        "// The spheres of scenes/spheres.json, one per line, for spheres.pov.\n// Written by tests/suite/tracer/povray.rs (RAYTREE_BLESS=1 cargo test --release povray).\n",
    );
    for o in scene["objects"].as_array().unwrap() {
        let Some(s) = o.get("sphere") else { continue };
        let c = &s["center"];
        let m = o["material"].as_str().unwrap();
        let interior = if m == "glass" {
            " interior { I_glass }"
        } else {
            ""
        };
        out.push_str(&format!(
            "sphere {{ <{}, {}, {}>, {} texture {{ T_{m} }}{interior} }}\n",
            c[0], c[1], c[2], s["radius"]
        ));
    }
    out
}

#[test]
fn the_sphere_list_matches_scenes_spheres_json() {
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("scenes/spheres.json")).unwrap())
            .unwrap();
    let expected = spheres_inc(&json);
    let path = root().join("benches/povray/spheres.inc");
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::write(&path, &expected).unwrap();
    }
    let committed = std::fs::read_to_string(&path).unwrap();
    assert!(
        committed == expected,
        "benches/povray/spheres.inc is stale: RAYTREE_BLESS=1 cargo test --release povray"
    );
    assert_eq!(
        committed
            .lines()
            .filter(|l| l.starts_with("sphere"))
            .count(),
        2000
    );
}

/// The hand-written parts: each twin's camera and lights are the JSON scene's.
#[test]
fn the_twins_name_the_same_camera_and_lights() {
    for name in ["whitted", "spheres"] {
        let json: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(root().join(format!("scenes/{name}.json"))).unwrap(),
        )
        .unwrap();
        let pov =
            std::fs::read_to_string(root().join(format!("benches/povray/{name}.pov"))).unwrap();
        let vec = |v: &serde_json::Value| {
            let n: Vec<String> = v
                .as_array()
                .unwrap()
                .iter()
                .map(|x| format!("{}", x.as_f64().unwrap()))
                .collect();
            format!("<{}>", n.join(", "))
        };
        let cam = &json["camera"];
        for (what, needle) in [
            ("eye", format!("#declare Eye = {};", vec(&cam["eye"]))),
            (
                "look_at",
                format!("#declare LookAt = {};", vec(&cam["look_at"])),
            ),
            (
                "fov",
                format!("tan(radians({}) / 2)", cam["fov"].as_f64().unwrap()),
            ),
        ] {
            assert!(pov.contains(&needle), "{name}.pov: {what}: no `{needle}`");
        }
        for light in json["lights"].as_array().unwrap() {
            let needle = format!(
                "light_source {{ {} color rgb {} }}",
                vec(&light["position"]),
                vec(&light["color"])
            );
            assert!(pov.contains(&needle), "{name}.pov: no `{needle}`");
        }
        let depth = json["render"]["max_depth"].as_u64().unwrap_or(8);
        assert!(
            pov.contains(&format!("max_trace_level {depth}")),
            "{name}.pov: max_trace_level"
        );
    }
}
