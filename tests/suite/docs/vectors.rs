//! The lessons' test vectors (`lessons/NN-topic/vectors.json`) are what
//! `raytree vectors N` makes now: a change to the tracer or to a lesson's
//! pixels that moves a number makes them stale, and this fails, naming the
//! file and the command that makes it again (or `RAYTREE_BLESS=1` writes them).

use std::path::Path;

use raytree::course::learner::vectors;

#[test]
fn lesson_vectors_are_current() {
    // Relative, as a learner runs `raytree vectors` from the repository: the
    // cases name their scenes that way.
    let lessons = Path::new("lessons");
    let mut stale = Vec::new();
    for (number, functions) in vectors::LESSON_FUNCTIONS {
        let (name, targets) = vectors::lesson_targets(lessons, number).unwrap();
        let made_by = format!("raytree vectors {number}");
        let fresh = vectors::document(&name, &made_by, functions, &targets).unwrap();
        let path = lessons.join(&name).join("vectors.json");
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        if committed != fresh {
            if std::env::var_os("RAYTREE_BLESS").is_some() {
                std::fs::write(&path, &fresh).unwrap();
            } else {
                stale.push(format!(
                    "{} is stale: raytree vectors {number} -o {}",
                    path.display(),
                    path.display()
                ));
            }
        }
        // Every function the lesson teaches has cases, and each case states
        // its input and expected output.
        let doc: serde_json::Value = serde_json::from_str(&fresh).unwrap();
        for f in functions {
            let n = doc["cases"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|c| c["function"] == *f && c["input"].is_object())
                .count();
            assert!(n >= 4, "{name}: only {n} cases of {f}");
        }
        assert_eq!(doc["tolerance"], vectors::TOLERANCE);
    }
    assert!(stale.is_empty(), "{}", stale.join("\n"));
}

#[test]
fn vectors_of_a_scene_hold_every_function_and_bad_targets_are_one_line() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .unwrap()
    };
    let functions_of = |scene: &str| {
        let out = run(&["vectors", scene]);
        assert!(out.status.success(), "{scene}");
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let mut found: Vec<String> = (doc["cases"].as_array().unwrap().iter())
            .map(|c| c["function"].as_str().unwrap().to_owned())
            .collect();
        found.sort();
        found.dedup();
        found
    };
    // The Whitted scene has every function but the transforms' (it places
    // no object by a transform), which the egg of lesson 06 has.
    let whitted = functions_of("scenes/whitted.json");
    let egg = functions_of("lessons/06-transforms/ellipsoid.json");
    for (_, functions) in vectors::LESSON_FUNCTIONS {
        for f in functions {
            let transform = ["to_object_ray", "normal_to_world"].contains(f);
            let found = if transform { &egg } else { &whitted };
            assert!(found.iter().any(|g| g == f), "no case of {f}: {found:?}");
        }
    }
    // A lesson without vectors and a folder that holds no lessons are the
    // command line's fault (exit 2, ending with the help); a scene file that
    // cannot be read or used is the file's (exit 1), as for every command.
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.json");
    std::fs::write(&bad, r#"{"objects": [{"sphere": {"radius": -2}}]}"#).unwrap();
    let bad = bad.to_str().unwrap();
    for (args, code, said) in [
        (
            &["vectors", "2"][..],
            2,
            "lesson 2: vectors exist for lessons 3 to 11 (see raytree vectors --help)",
        ),
        (&["vectors", "12"][..], 2, "lesson 12"),
        (
            &["vectors", "5", "--lessons", "nosuch"][..],
            2,
            "nosuch: no such folder",
        ),
        (
            &["vectors", "nosuch.json"][..],
            1,
            "nosuch.json: no such file",
        ),
        (
            &["vectors", bad][..],
            1,
            "objects[0].sphere.radius: must be from 1e-9 to 1e9, got -2",
        ),
        (
            &["vectors", "/dev/zero"][..],
            1,
            "cannot read /dev/zero: not a regular file",
        ),
    ] {
        let out = run(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(code), "{args:?}: {stderr}");
        assert_eq!(stderr.contains("--help"), code == 2, "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("error: ") && stderr.contains(said),
            "{args:?}: {stderr}"
        );
        assert!(out.stdout.is_empty());
    }
}

/// `-o` never writes over what the command reads: the scene, its meshes, a
/// lesson's own files. The input is left as it was, and the legitimate
/// output beside them is still written.
#[test]
fn vectors_never_write_over_their_inputs() {
    let dir = tempfile::tempdir().unwrap();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let copy = |from: &str| {
        let to = dir.path().join(from);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(root.join(from), &to).unwrap();
    };
    for f in [
        "scenes/whitted.json",
        "scenes/gaspra.json",
        "scenes/meshes/gaspra.obj",
        "lessons/05-sphere/lesson.toml",
        "lessons/05-sphere/lesson.md",
        "lessons/05-sphere/steps.toml",
        "lessons/05-sphere/ball.json",
        "lessons/05-sphere/behind.json",
    ] {
        copy(f);
    }
    let run = |args: &[&str]| crate::commands::cli::raytree(args, dir.path());
    for (target, output) in [
        ("scenes/whitted.json", "scenes/whitted.json"),
        ("scenes/gaspra.json", "scenes/meshes/gaspra.obj"),
        ("5", "lessons/05-sphere/lesson.toml"),
        ("5", "lessons/05-sphere/steps.toml"),
        ("5", "lessons/05-sphere/ball.json"),
        ("5", "scenes/whitted.json"),
    ] {
        let before = std::fs::read(dir.path().join(output)).unwrap();
        let out = run(&["vectors", target, "-o", output]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{target} -o {output}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(
            stderr.contains(&format!("cannot write {output}")),
            "{stderr}"
        );
        assert_eq!(
            std::fs::read(dir.path().join(output)).unwrap(),
            before,
            "{output} changed"
        );
    }
    let out = run(&["vectors", "5", "-o", "lessons/05-sphere/vectors.json"]);
    assert!(out.status.success(), "{out:?}");
    assert!(dir.path().join("lessons/05-sphere/vectors.json").is_file());
}
