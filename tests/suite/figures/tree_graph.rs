//! The ray tree drawn as a graph (`raytree diagram --graph`): a box per ray
//! and an edge per parent and child, laid out without overlaps; and one hit's
//! vectors enlarged (`--vectors`).

use std::collections::BTreeSet;

use raytree::scene::source::SceneSource;
use raytree::views::tree_graph::{draw, layout};

#[test]
fn one_box_per_ray_and_one_edge_per_parent_and_child() {
    let scene = raytree::scene::loader::whitted();
    let source = SceneSource::new("scenes/whitted.json", "");
    // Lesson 11's pixel: 18 rays down to depth 8, with total internal
    // reflections, a weight cutoff and the maximum depth.
    let trace = raytree::tree::record::pixel(&scene, source, 386, 242, None).unwrap();
    let tree = &trace.samples[0].tree;
    assert!(tree.nodes.len() > 10, "the test needs a deep tree");
    let graph = layout(tree, 1400, 1000);
    assert_eq!(graph.nodes.len(), tree.nodes.len(), "one box per ray");
    let pairs: BTreeSet<(usize, usize)> = (tree.nodes.iter().enumerate())
        .filter_map(|(i, n)| Some((n.parent?, i)))
        .collect();
    let edges: BTreeSet<(usize, usize)> = graph.edges.iter().map(|e| (e.from, e.to)).collect();
    assert_eq!(
        graph.edges.len(),
        pairs.len(),
        "one edge per pair, none twice"
    );
    assert_eq!(edges, pairs);
    // Each box says its ray's kind, depth and hit, hits numbered in the
    // tree's order as the diagram numbers them (P1, P2, …).
    let mut hits = 0;
    for (node, ray) in graph.nodes.iter().zip(&tree.nodes) {
        assert_eq!(node.kind, ray.kind);
        assert!(node.lines[1].starts_with(&format!("depth {} ", ray.depth)));
        match &ray.hit {
            Some(h) => {
                hits += 1;
                assert_eq!(node.lines[2], format!("P{hits}: hits {}", h.name));
            }
            None => assert_eq!(node.lines[2], "misses: background"),
        }
    }
    // A row per depth, children below their parent, and no two boxes overlap.
    for e in &graph.edges {
        assert!(graph.nodes[e.to].center.y > graph.nodes[e.from].center.y);
    }
    for (i, a) in graph.nodes.iter().enumerate() {
        for b in &graph.nodes[i + 1..] {
            let d = (a.center - b.center).abs();
            assert!(
                d.x >= graph.size.x || d.y >= graph.size.y,
                "rays {} and {} overlap",
                a.ray + 1,
                b.ray + 1
            );
        }
    }
    assert!(draw(tree, "whitted", 1400, 1000).is_some());
    assert!(
        draw(tree, "whitted", 200, 200).is_none(),
        "too small to read"
    );
}

/// `raytree diagram --vectors`: lesson 9's hit split from the trace's own
/// vectors, c = along + across and v = across − along, and drawn.
#[test]
fn a_hits_vectors_split_into_along_and_across_the_normal() {
    use raytree::views::hit_vectors::{draw as draw_hit, parts};
    let scene = raytree::scene::loader::whitted();
    let source = SceneSource::new("scenes/whitted.json", "");
    let trace = raytree::tree::record::pixel(&scene, source, 200, 280, None).unwrap();
    let hit = trace.samples[0].tree.nodes[0].hit.as_ref().unwrap();
    let p = parts(hit);
    // Tolerance: the tracer's v and these parts round differently, a few ε
    // of unit vectors.
    assert!((p.along + p.across - hit.incoming).length() < 1e-14);
    assert!((p.across - p.along - hit.mirror).length() < 1e-14);
    assert!(p.across.dot(hit.shading_normal).abs() < 1e-14, "across n");
    assert!(
        p.along.cross(hit.shading_normal).length() < 1e-14,
        "along n"
    );
    assert!(draw_hit(hit, "P1", "whitted", 1400, 560).is_some());
}
