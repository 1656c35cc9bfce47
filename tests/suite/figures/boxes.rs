//! The hierarchy's boxes a ray was tested against, as the ray tree records
//! them and `raytree diagram --boxes` draws them: every box counted is
//! recorded, a box marked met is one the ray meets, a box marked missed is one
//! it meets nowhere before its hit, and the boxes entered lead down to the
//! object hit.

use glam::DVec3;
use raytree::scene::source::SceneSource;
use raytree::tree::document::TraceDocument;
use raytree::tree::ray_tree::{BoxRecord, RayNode};
use raytree::tree::steps::{Step, StepKind};
use raytree::views::diagram::draw::draw_with_labels;
use raytree::views::diagram::options::Options;
use raytree::views::diagram::projection::View;

fn spheres() -> raytree::scene::Scene {
    raytree::scene::loader::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/spheres.json"
    )))
    .unwrap()
}

fn traced(scene: &raytree::scene::Scene, x: u32, y: u32) -> TraceDocument {
    raytree::tree::record::pixel(
        scene,
        SceneSource::new("scenes/spheres.json", ""),
        x,
        y,
        None,
    )
    .unwrap()
}

/// Where the ray `o + t·d` enters and leaves the box, exactly as the slab
/// method says (f64, no widening), or `None` when it misses it for t > 0.
fn slabs(o: DVec3, d: DVec3, b: &BoxRecord) -> Option<(f64, f64)> {
    let (mut enter, mut leave) = (0.0f64, f64::INFINITY);
    for a in 0..3 {
        let (t0, t1) = ((b.min[a] - o[a]) / d[a], (b.max[a] - o[a]) / d[a]);
        enter = enter.max(t0.min(t1));
        leave = leave.min(t0.max(t1));
    }
    (enter <= leave).then_some((enter, leave))
}

#[test]
fn every_box_counted_is_recorded_and_its_fate_is_what_the_slabs_say() {
    let scene = spheres();
    let mut checked = 0;
    for (x, y) in [(300, 200), (330, 210), (250, 300), (400, 260), (120, 380)] {
        let trace = traced(&scene, x, y);
        for node in &trace.samples[0].tree.nodes {
            // spheres.json has no meshes: every box tested is the scene's.
            assert_eq!(node.boxes.len(), node.tested.boxes as usize, "({x}, {y})");
            let t_hit = node.hit.as_ref().map_or(f64::INFINITY, |h| h.t);
            for b in &node.boxes {
                let met = slabs(node.origin, node.direction, b);
                if b.met {
                    // The stored box is rounded outward and the test widened by
                    // its rounding, so a met box may be missed by the exact ray
                    // only by a hair: grow it by 1e-5 of its size to check.
                    let grow = (b.max - b.min).max_element() * 1e-5;
                    let wider = BoxRecord {
                        min: b.min - grow,
                        max: b.max + grow,
                        ..*b
                    };
                    assert!(
                        slabs(node.origin, node.direction, &wider).is_some(),
                        "({x}, {y}): a box marked met that the ray misses: {b:?}"
                    );
                } else if let Some((enter, _)) = met {
                    // Missed: the ray meets it only beyond its hit (the search's
                    // interval had shrunk past it) or not within (t_min, ∞).
                    assert!(
                        enter >= t_hit * (1.0 - 1e-9) || enter < node.t_min,
                        "({x}, {y}): a box marked missed that the ray enters at t = {enter}, before its hit at {t_hit}"
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "only {checked} boxes checked");
}

#[test]
fn the_boxes_entered_lead_down_to_the_object_hit() {
    let scene = spheres();
    let trace = traced(&scene, 300, 200);
    let node = &trace.samples[0].tree.nodes[0];
    let hit = node.hit.as_ref().expect("pixel 300,200 hits a sphere");
    let bounds = scene.objects[hit.object].bounds().unwrap();
    let holding: Vec<&BoxRecord> = node
        .boxes
        .iter()
        .filter(|b| b.met && b.min.cmple(bounds.min).all() && b.max.cmpge(bounds.max).all())
        .collect();
    // From the root's child down to the leaf: several nested boxes hold it.
    assert!(
        holding.len() >= 3,
        "{} boxes hold the object hit",
        holding.len()
    );
    for pair in holding.windows(2) {
        assert!(
            pair[0].min.cmple(pair[1].min).all() && pair[0].max.cmpge(pair[1].max).all(),
            "each box entered holds the next one down"
        );
    }
}

#[test]
fn the_diagram_counts_the_boxes_in_its_legend_and_draws_them_only_when_asked() {
    let scene = spheres();
    let trace = traced(&scene, 300, 200);
    let node = &trace.samples[0].tree.nodes[0];
    let met = node.boxes.iter().filter(|b| b.met).count();
    let options = Options {
        view: View::Top,
        depth: Some(1),
        shadows: false,
        boxes: true,
        ..Options::default()
    };
    let drawn = draw_with_labels(&trace, &scene, &options).unwrap();
    let entries = &drawn.legend_entries;
    assert!(
        entries.contains(&format!("box the ray entered ({met})")),
        "{entries:?}"
    );
    assert!(
        entries.contains(&format!("box tested, missed ({})", node.boxes.len() - met)),
        "{entries:?}"
    );
    let plain = draw_with_labels(
        &trace,
        &scene,
        &Options {
            boxes: false,
            ..options
        },
    )
    .unwrap();
    assert!(!plain.legend_entries.iter().any(|e| e.contains("box")));
    // Without shadow rays, no mark of them either.
    assert!(
        !entries
            .iter()
            .any(|e| e.contains("shadow") || e.contains("light behind"))
    );
}

#[test]
fn scenes_without_a_hierarchy_record_no_boxes() {
    let scene = raytree::scene::loader::whitted();
    let trace =
        raytree::tree::record::pixel(&scene, SceneSource::new("", ""), 416, 209, None).unwrap();
    assert!(
        trace.samples[0]
            .tree
            .nodes
            .iter()
            .all(|n| n.boxes.is_empty())
    );
    let json = serde_json::to_string(&trace).unwrap();
    assert!(
        !json.contains("\"boxes\":["),
        "empty boxes are left out of the JSON"
    );
}

/// A grid walk's cells sit among the ray's tests where the search made them:
/// the objects tested after a cell and before the next are ones the cell
/// lists (their boxes overlap it), the unbounded floor comes before the walk,
/// and the steps (`raytree trace --steps`, the step-through) put each cell
/// just before the tests it led to. A stamp taken at the wrong moment would
/// put an object under a cell it does not touch.
#[test]
fn a_grid_walks_cells_sit_among_its_tests_where_the_search_made_them() {
    use raytree::methods::Accel;
    let file = "lessons/12-efficiency/scatter.json";
    let mut scene =
        raytree::scene::loader::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(file))
            .unwrap();
    scene.settings.accel = Accel::Grid;
    let mut placed = 0;
    for (x, y) in [(497, 160), (320, 240), (100, 300), (560, 400), (200, 120)] {
        let trace =
            raytree::tree::record::pixel(&scene, SceneSource::new(file, ""), x, y, None).unwrap();
        let tree = &trace.samples[0].tree;
        let order = raytree::tree::steps::steps(tree);
        for (i, node) in tree.nodes.iter().enumerate() {
            let at = format!("({x}, {y}) ray {i}");
            only_unbounded_objects_come_before_the_walk(&scene, node, &at);
            placed += tests_after_a_cell_touch_it(&scene, node, &at);
            every_cell_is_a_step_before_its_tests(&order, i, node, &at);
        }
    }
    assert!(
        placed >= 10,
        "only {placed} tests placed: pick pixels that walk the grid"
    );
}

/// The objects a ray tested before its first cell are unbounded (the floor):
/// a cell could hold any other.
fn only_unbounded_objects_come_before_the_walk(
    scene: &raytree::scene::Scene,
    node: &RayNode,
    at: &str,
) {
    let first = node
        .boxes
        .first()
        .map_or(node.tests.len(), |b| b.after_tests);
    for test in &node.tests[..first] {
        assert!(
            scene.objects[test.object].bounds().is_none(),
            "{at}: '{}' tested before the walk, but a cell could hold it",
            test.name
        );
    }
}

/// The objects tested after a cell and before the next have boxes that
/// overlap the cell; how many tests were so placed.
fn tests_after_a_cell_touch_it(scene: &raytree::scene::Scene, node: &RayNode, at: &str) -> usize {
    let mut placed = 0;
    for (k, cell) in node.boxes.iter().enumerate() {
        let end = node
            .boxes
            .get(k + 1)
            .map_or(node.tests.len(), |b| b.after_tests);
        assert!(cell.after_tests <= end, "{at}: stamps go backwards");
        for test in &node.tests[cell.after_tests..end] {
            let b = scene.objects[test.object]
                .bounds()
                .unwrap_or_else(|| panic!("{at}: unbounded '{}' tested in a cell", test.name));
            // The grid lists an object in every cell its box overlaps,
            // widened by a few roundings: a relative 1e-9 covers them
            // and is far below any cell's size here (about 1).
            let slack = 1e-9 * (1.0 + b.max.abs().max(b.min.abs()).max_element());
            let apart =
                (0..3).any(|a| b.max[a] < cell.min[a] - slack || b.min[a] > cell.max[a] + slack);
            assert!(
                !apart,
                "{at}: '{}' tested after cell {} it does not touch",
                test.name,
                k + 1
            );
            placed += 1;
        }
    }
    placed
}

/// In the steps of ray `i`, each test comes after exactly the cells stamped
/// at or before it, and the cells come in the order walked.
fn every_cell_is_a_step_before_its_tests(order: &[Step], i: usize, node: &RayNode, at: &str) {
    let mut walked = 0;
    for step in order.iter().filter(|s| s.node == i) {
        match step.kind {
            StepKind::Visit(k) => {
                assert_eq!(k, walked, "{at}: cells out of order");
                walked += 1;
            }
            StepKind::Test(t) => {
                let due = node.boxes.iter().filter(|b| b.after_tests <= t).count();
                assert_eq!(walked, due, "{at}: test {t} after {walked} cells");
            }
            _ => {}
        }
    }
    assert_eq!(walked, node.boxes.len(), "{at}: every cell is a step");
}
