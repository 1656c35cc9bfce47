use super::node::*;
use super::traverse::*;
use super::*;
use crate::geometry::hit::TestCounts;
use crate::geometry::structures::Structure;
use crate::math::bounds::RayBox;
use crate::math::ray::Ray;
use glam::DVec3;
use std::ops::ControlFlow;
use wide::f32x4;

fn cube(at: DVec3) -> Bounds {
    Bounds {
        min: at - 0.25,
        max: at + 0.25,
    }
}

/// 1,000 small cubes on a 10 × 10 × 10 grid of spacing 1.
fn ten_by_ten_by_ten() -> Vec<Bounds> {
    (0..1000)
        .map(|i| {
            cube(DVec3::new(
                (i % 10) as f64,
                (i / 10 % 10) as f64,
                (i / 100) as f64,
            ))
        })
        .collect()
}

/// Every primitive a brute-force slab test says the ray meets.
fn met(boxes: &[Bounds], ray: &Ray) -> Vec<usize> {
    let rb = RayBox::new(ray);
    (0..boxes.len())
        .filter(|&i| rb.hits(&boxes[i], 0.0, f64::INFINITY))
        .collect()
}

#[test]
fn every_primitive_is_in_exactly_one_leaf() {
    let boxes = ten_by_ten_by_ten();
    let bvh = Bvh::build(&boxes);
    let mut seen = bvh.order.clone();
    seen.sort_unstable();
    assert_eq!(seen, (0..1000).collect::<Vec<u32>>());
    for node in &bvh.nodes {
        for c in &node.children[..usize::from(node.len)] {
            assert!(!c.is_leaf() || c.primitives().len() <= MAX_LEAF);
        }
    }
}

#[test]
fn traversal_visits_every_box_the_ray_meets_and_few_others() {
    let boxes = ten_by_ten_by_ten();
    let bvh = Bvh::build(&boxes);
    let ray = Ray::new(DVec3::new(-1.0, 4.1, 3.9), DVec3::new(1.0, 0.01, 0.02));
    let mut visited = Vec::new();
    let mut tested = TestCounts::default();
    let _ = bvh.walk(
        &ray,
        0.0,
        &mut { f64::INFINITY },
        &mut tested,
        |_, _| {},
        |p, _| {
            visited.push(p);
            ControlFlow::Continue(())
        },
    );
    let expected = met(&boxes, &ray);
    assert!(!expected.is_empty());
    for p in &expected {
        assert!(visited.contains(p), "primitive {p} was skipped");
    }
    // One row of ten cubes: the hierarchy should look at far fewer than 1000.
    assert!(
        visited.len() < 50 && tested.boxes < 200,
        "{visited:?} {tested:?}"
    );
}

/// The single-precision test keeps every box the double-precision one does
/// (which is exact but for a widening of a few ULPs of f64), at every scale,
/// for rays aimed right at corners and edges, starting on faces, or parallel
/// to an axis, and for boxes flat in one axis.
#[test]
fn single_precision_boxes_lose_no_hit() {
    let mut rng = fastrand::Rng::with_seed(7);
    let mut kept_more = 0;
    for scale in [1e-3, 1.0, 1e4, 1e7] {
        for case in 0..20_000 {
            let at =
                |r: &mut fastrand::Rng| DVec3::new(r.f64(), r.f64(), r.f64()) * 2.0 * scale - scale;
            let (a, b) = (at(&mut rng), at(&mut rng));
            let mut bounds = Bounds {
                min: a.min(b),
                max: a.max(b),
            };
            if case % 7 == 0 {
                bounds.max.y = bounds.min.y;
            }
            let corner = DVec3::new(
                [bounds.min.x, bounds.max.x][case % 2],
                [bounds.min.y, bounds.max.y][case / 2 % 2],
                [bounds.min.z, bounds.max.z][case / 4 % 2],
            );
            let mut origin = at(&mut rng) * 3.0;
            if case % 5 == 0 {
                origin.x = bounds.min.x;
            }
            let mut dir = match case % 3 {
                0 => corner - origin,
                1 => 0.5 * (corner + bounds.center()) - origin,
                _ => at(&mut rng),
            };
            if case % 11 == 0 {
                dir.z = 0.0;
            }
            let ray = RayBox::new(&Ray::new(origin, dir));
            let mut node = Node {
                bounds: [
                    [f32x4::splat(f32::INFINITY); 3],
                    [f32x4::splat(f32::NEG_INFINITY); 3],
                ],
                children: [Child(0); WIDTH],
                len: 1,
            };
            set_lane(&mut node, 0, &bounds);
            let t_max = if case % 4 == 0 {
                f64::INFINITY
            } else {
                rng.f64() * 4.0
            };
            let exact = ray.hits(&bounds, 0.0, t_max);
            let (mask, _) = RayBox4::new(&ray).hits(&node, 0.0, RayBox4::reach(t_max));
            assert!(
                !exact || mask == 1,
                "box {bounds:?} lost: ray {origin} + t·{dir}, t < {t_max}"
            );
            kept_more += usize::from(!exact && mask == 1);
        }
    }
    // Conservative, but not by much: the widening admits few extra boxes.
    assert!(kept_more < 800, "{kept_more} of 80,000 kept without need");
}

#[test]
fn empty_lanes_are_never_hit() {
    let node = Node {
        bounds: [
            [f32x4::splat(f32::INFINITY); 3],
            [f32x4::splat(f32::NEG_INFINITY); 3],
        ],
        children: [Child(0); WIDTH],
        len: 0,
    };
    for dir in [
        DVec3::X,
        DVec3::NEG_Y,
        DVec3::new(0.0, -0.0, 1.0),
        DVec3::ONE,
    ] {
        let ray = RayBox::new(&Ray::new(DVec3::ZERO, dir));
        let (mask, _) = RayBox4::new(&ray).hits(&node, 0.0, f32::INFINITY);
        assert_eq!(mask, 0, "{dir}");
    }
}

/// A shadow ray's walk, in the stored order, reaches the same leaves as the
/// nearest-first walk when neither stops early (so a blocker one finds,
/// the other finds), and on a row of boxes does not take them nearest
/// first (so the order really is another).
#[test]
fn any_order_reaches_the_leaves_the_nearest_first_walk_does() {
    let boxes = ten_by_ten_by_ten();
    let bvh = Bvh::build(&boxes);
    let mut orders_differ = false;
    for (origin, dir) in [
        (DVec3::new(-1.0, 4.1, 3.9), DVec3::new(1.0, 0.01, 0.02)),
        (DVec3::new(10.5, 4.2, 3.9), DVec3::new(-1.0, 0.02, -0.01)),
        (DVec3::new(4.1, -2.0, 4.1), DVec3::new(0.01, 1.0, 0.02)),
        (DVec3::new(-1.0, -1.0, -1.0), DVec3::ONE),
    ] {
        let ray = RayBox::new(&Ray::new(origin, dir));
        let walk = |any: bool| {
            let mut leaves = Vec::new();
            let visit = |leaf: std::ops::Range<usize>, _: &mut f64| {
                leaves.push(leaf.start);
                ControlFlow::Continue(())
            };
            let (t_max, tested) = (&mut { f64::INFINITY }, &mut TestCounts::default());
            let _ = if any {
                bvh.traverse_leaves_any(&ray, 0.0, t_max, tested, visit)
            } else {
                bvh.traverse_leaves(&ray, 0.0, t_max, tested, visit)
            };
            leaves
        };
        let (nearest, any) = (walk(false), walk(true));
        assert!(nearest.len() >= 2, "{origin}: {nearest:?}");
        orders_differ |= nearest != any;
        let sorted = |mut v: Vec<usize>| {
            v.sort_unstable();
            v
        };
        assert_eq!(sorted(nearest), sorted(any), "ray from {origin}");
    }
    assert!(
        orders_differ,
        "the stored order was the nearest-first one for every ray"
    );
}

#[test]
fn breaking_stops_the_traversal() {
    let boxes: Vec<Bounds> = (0..100)
        .map(|i| cube(DVec3::new(i as f64, 0.0, 0.0)))
        .collect();
    let bvh = Bvh::build(&boxes);
    let ray = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
    let mut visited = 0;
    let flow = bvh.walk(
        &ray,
        0.0,
        &mut { f64::INFINITY },
        &mut TestCounts::default(),
        |_, _| {},
        |_, _| {
            visited += 1;
            ControlFlow::Break(())
        },
    );
    assert_eq!((flow, visited), (ControlFlow::Break(()), 1));
}
