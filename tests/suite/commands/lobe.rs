//! `raytree lobe` and the diagram's two drawings that leave the scene out
//! (`--graph`, `--vectors`): what they refuse, in one line, writing nothing.

use crate::common::refused_with;

#[test]
fn lobe_refuses_a_bad_shininess_and_too_many_curves() {
    for (name, value) in [
        ("lobe-zero", "40,0"),
        ("lobe-word", "forty"),
        ("lobe-inf", "inf"),
    ] {
        let e = refused_with(2, name, &[], &["lobe", "--shininess", value]);
        assert!(e.contains("not a shininess"), "{e}");
    }
    let e = refused_with(2, "lobe-four", &[], &["lobe", "--shininess", "1,2,3,4"]);
    assert!(e.contains("at most three"), "{e}");
    let e = refused_with(2, "lobe-svg", &[], &["lobe", "-o", "lobe.svg"]);
    assert!(e.contains("lobe.svg"), "{e}");
    // Smaller than this, the legend covered the axis's label (a review, 2026-11-26).
    let e = refused_with(2, "lobe-small", &[], &["lobe", "--size", "700x450"]);
    assert!(
        e.contains(
            "700x450 is too small for the lobe's title, legend and labels: at least 800x520"
        ),
        "{e}"
    );
}

#[test]
fn the_graph_and_a_hits_vectors_refuse_what_they_cannot_draw() {
    let scene = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/whitted.json")).unwrap();
    let files: &[(&str, &[u8])] = &[("w.json", &scene)];
    // Pixel 200,280 has two hits (the mirror ball, the floor): no P5.
    let e = refused_with(
        2,
        "vectors-p5",
        files,
        &[
            "diagram",
            "w.json",
            "--pixel",
            "200,280",
            "--vectors",
            "5",
            "-o",
            "v.png",
        ],
    );
    assert!(e.contains("no hit P5"), "{e}");
    let e = refused_with(
        2,
        "graph-svg",
        files,
        &[
            "diagram", "w.json", "--pixel", "200,280", "--graph", "-o", "g.svg",
        ],
    );
    assert!(e.contains("PNG only"), "{e}");
    let e = refused_with(
        2,
        "graph-and-view",
        files,
        &[
            "diagram", "w.json", "--pixel", "200,280", "--graph", "--view", "top",
        ],
    );
    assert!(e.contains("--view"), "{e}");
}
