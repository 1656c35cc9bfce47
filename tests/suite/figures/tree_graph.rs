//! The ray tree drawn as a graph (`raytree diagram --graph`): a box per ray
//! and an edge per parent and child, laid out without overlaps; and one hit's
//! vectors enlarged (`--vectors`).

use std::collections::BTreeSet;

use glam::DVec2;
use raytree::figure::canvas::Figure;
use raytree::figure::labels::{Placed, PxRect, text_box};
use raytree::scene::source::SceneSource;
use raytree::views::tree_graph::{box_lines, draw, draw_with_labels, layout};

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

/// Every placed label of a figure inside `frame`, apart from the others and
/// from `blocked`, and no leader through another label.
fn apart(labels: &[Placed], blocked: &[PxRect], frame: &PxRect, at: &str) {
    for (i, a) in labels.iter().enumerate() {
        let text = &a.label.text;
        assert!(frame.holds(&a.rect), "{at}: '{text}' leaves the frame");
        for b in blocked {
            assert!(!a.rect.overlaps(b), "{at}: '{text}' covers {b:?}");
        }
        for (j, b) in labels.iter().enumerate() {
            if i == j {
                continue;
            }
            assert!(
                !a.rect.overlaps(&b.rect),
                "{at}: '{text}' and '{}' overlap",
                b.label.text
            );
            assert!(
                !a.leader.is_some_and(|[p, q]| b.rect.crossed_by(p, q)),
                "{at}: the leader of '{text}' runs through '{}'",
                b.label.text
            );
        }
    }
}

/// Pixels with deep trees (total internal reflections, the weight cutoff,
/// the maximum depth) and shallow ones.
const PIXELS: [(&str, u32, u32); 6] = [
    ("whitted.json", 386, 242),
    ("whitted.json", 416, 209),
    ("whitted.json", 160, 120),
    ("whitted.json", 200, 280),
    ("nested.json", 320, 240),
    ("nested.json", 300, 200),
];

fn traced(scene: &str, x: u32, y: u32) -> raytree::tree::document::TraceDocument {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(scene);
    let s = raytree::scene::loader::load(&path).unwrap();
    raytree::tree::record::pixel(&s, SceneSource::new(scene, ""), x, y, None).unwrap()
}

/// `--graph`: every line of a box inside its box, and the coefficients on
/// the edges clear of the boxes, of each other and of the frame; none left
/// out.
#[test]
fn the_graphs_text_stays_in_its_boxes_and_the_coefficients_off_them() {
    let mut checked = 0;
    for (name, x, y) in PIXELS {
        let trace = traced(name, x, y);
        let tree = &trace.samples[0].tree;
        for (w, h) in [(1200, 800), (1400, 1000), (800, 600)] {
            let at = format!("{name} {x},{y} {w}×{h}");
            let Some(drawn) = draw_with_labels(tree, name, w, h) else {
                assert!(w < 1200, "{at}: no figure");
                continue;
            };
            let g = &drawn.graph;
            let boxes: Vec<PxRect> = (g.nodes.iter())
                .map(|n| PxRect {
                    min: n.center - g.size / 2.0,
                    max: n.center + g.size / 2.0,
                })
                .collect();
            for (n, b) in g.nodes.iter().zip(&boxes) {
                for (line, (center, size)) in n.lines.iter().zip(box_lines(g, n)) {
                    let half = f64::from(Figure::text_width(line, size)) / 2.0;
                    let r = text_box(line, size, center - DVec2::new(half, 0.0), false);
                    assert!(b.holds(&r), "{at}: '{line}' leaves ray {}'s box", n.ray + 1);
                }
            }
            apart(&drawn.labels, &boxes, &drawn.frame, &at);
            let lost: Vec<&str> = drawn.left_out.iter().map(|l| l.text.as_str()).collect();
            assert!(lost.is_empty(), "{at}: no room for {lost:?}");
            checked += drawn.labels.len();
        }
    }
    assert!(checked > 40, "only {checked} coefficients checked");
}

/// `--vectors`: each hit's labels clear of each other, the arrowheads and
/// the frame, at the default size and at lesson 9's; none left out.
#[test]
fn the_vectors_labels_keep_apart() {
    use raytree::views::hit_vectors::draw_with_labels as draw_hit;
    let mut checked = 0;
    for (name, x, y) in PIXELS {
        let trace = traced(name, x, y);
        let hits = trace.samples[0]
            .tree
            .nodes
            .iter()
            .filter_map(|n| n.hit.as_ref());
        for (k, hit) in hits.enumerate().take(4) {
            for (w, h) in [(1200, 800), (1400, 560), (800, 520)] {
                let at = format!("{name} {x},{y} P{} {w}×{h}", k + 1);
                let Some(drawn) = draw_hit(hit, "P1 on 'glass'", name, w, h) else {
                    continue;
                };
                apart(&drawn.labels, &[], &drawn.frame, &at);
                let lost: Vec<&str> = drawn.left_out.iter().map(|l| l.text.as_str()).collect();
                assert!(lost.is_empty(), "{at}: no room for {lost:?}");
                checked += drawn.labels.len();
            }
        }
    }
    assert!(checked > 200, "only {checked} labels checked");
}
