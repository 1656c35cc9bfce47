//! The lessons' test vectors (`lessons/NN-topic/vectors.json`) are what
//! `raytree vectors N` makes now: a change to the tracer or to a lesson's
//! pixels that moves a number makes them stale, and this fails, naming the
//! file and the command that makes it again (or `RAYTREE_BLESS=1` writes them).

use std::path::Path;

use raytree::course::vectors;

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
