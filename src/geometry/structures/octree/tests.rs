//! Tests of the octree: that it never misses a primitive the ray meets, visits
//! each once, and stops early.

use super::*;
use crate::geometry::structures::walk_tests::{cube, described, everything_visited, sphere_hit};
use glam::DVec3;

/// Every primitive the walk hands out from `t_min` on, in order, and its steps.
fn walk(tree: &Octree, ray: &Ray, t_min: f64) -> (Vec<usize>, u32) {
    everything_visited(|t_max, tested, visit| {
        tree.walk(ray, t_min, t_max, tested, |_, _| {}, visit)
    })
}

fn point(rng: &mut fastrand::Rng, lo: f64, hi: f64) -> DVec3 {
    DVec3::new(rng.f64(), rng.f64(), rng.f64()) * (hi - lo) + lo
}

/// A scene in the cube [0, 64]³ (one box is that cube, so cell planes fall
/// on multiples of 64/2^k): many small boxes, a third of them on a grid of
/// 0.5 so their faces lie in cell planes; a few huge ones; flat ones (half of
/// them in the planes of the coarsest cells); single
/// points; and copies of earlier boxes.
fn mixed_scene(rng: &mut fastrand::Rng) -> Vec<Bounds> {
    let mut boxes = vec![Bounds {
        min: DVec3::ZERO,
        max: DVec3::splat(64.0),
    }];
    for i in 0..2600 {
        let mut min = point(rng, 0.0, 63.0);
        let mut size = point(rng, 0.01, 1.0);
        if i % 3 == 0 {
            min = (min * 2.0).floor() / 2.0;
            size = DVec3::splat(0.5);
        }
        boxes.push(Bounds {
            min,
            max: min + size,
        });
    }
    for _ in 0..10 {
        let min = point(rng, 0.0, 32.0);
        let max = (min + point(rng, 10.0, 60.0)).min(DVec3::splat(64.0));
        boxes.push(Bounds { min, max });
    }
    for i in 0..200 {
        let mut min = point(rng, 0.0, 60.0);
        let mut max = min + point(rng, 0.1, 4.0);
        if i % 2 == 0 {
            // In a plane of the coarse cells, as a floor or a wall may be.
            min[i % 3] = (min[i % 3] / 8.0).round() * 8.0;
        }
        max[i % 3] = min[i % 3];
        boxes.push(Bounds { min, max });
    }
    for _ in 0..20 {
        let p = point(rng, 0.0, 64.0);
        boxes.push(Bounds { min: p, max: p });
    }
    for _ in 0..150 {
        let b = boxes[rng.usize(..boxes.len())];
        boxes.push(b);
    }
    // Last, small cubes with a corner on a corner or an edge of the root,
    // which no cell outside the root shares.
    for i in 0..CORNERED {
        let mut c = DVec3::new(
            [0.0, 64.0][rng.usize(..2)],
            [0.0, 64.0][rng.usize(..2)],
            [0.0, 64.0][rng.usize(..2)],
        );
        if i % 2 == 0 {
            c[i % 3] = rng.f64() * 60.0 + 2.0;
        }
        let min = DVec3::select(c.cmpeq(DVec3::splat(64.0)), c - 0.5, c);
        boxes.push(Bounds {
            min,
            max: min + 0.5,
        });
    }
    boxes
}

/// How many boxes end [`mixed_scene`] with a corner on the root's surface.
const CORNERED: usize = 40;

/// A ray of one of several awkward kinds (`case` picks), over `boxes`.
fn awkward_ray(rng: &mut fastrand::Rng, boxes: &[Bounds], case: usize) -> Ray {
    let b = boxes[rng.usize(..boxes.len())];
    let corner = |rng: &mut fastrand::Rng| {
        DVec3::new(
            [b.min.x, b.max.x][rng.usize(..2)],
            [b.min.y, b.max.y][rng.usize(..2)],
            [b.min.z, b.max.z][rng.usize(..2)],
        )
    };
    let outside = |rng: &mut fastrand::Rng| {
        let d = point(rng, -1.0, 1.0).normalize_or(DVec3::X);
        DVec3::splat(32.0) + 150.0 * d
    };
    let axis = rng.usize(..3);
    let sign = if rng.bool() { 1.0 } else { -1.0 };
    let zero = if rng.bool() { 0.0 } else { -0.0 };
    match case % 8 {
        // From inside, anywhere.
        0 => Ray::new(point(rng, 0.0, 64.0), point(rng, -1.0, 1.0)),
        // From outside, aimed inside.
        1 => {
            let o = outside(rng);
            Ray::new(o, point(rng, 0.0, 64.0) - o)
        }
        // Along an axis, the other coordinates on the 0.5 grid (in cell
        // planes and grid boxes' faces), from inside or outside.
        2 => {
            let mut o = (point(rng, -8.0, 72.0) * 2.0).floor() / 2.0;
            o[axis] = rng.f64() * 200.0 - 68.0;
            let mut dir = DVec3::splat(zero);
            dir[axis] = sign;
            Ray::new(o, dir)
        }
        // In the plane of a box's face, grazing it.
        3 => {
            let mut o = point(rng, -10.0, 74.0);
            o[axis] = [b.min[axis], b.max[axis]][rng.usize(..2)];
            let mut dir = point(rng, -1.0, 1.0);
            dir[axis] = zero;
            Ray::new(o, dir)
        }
        // At a box's corner, from inside or outside.
        4 => {
            let o = if rng.bool() {
                outside(rng)
            } else {
                point(rng, 0.0, 64.0)
            };
            Ray::new(o, corner(rng) - o)
        }
        // Along a box's edge: from beside a corner, parallel to an axis.
        5 => {
            let mut o = corner(rng);
            o[axis] -= sign * rng.f64() * 100.0;
            let mut dir = DVec3::splat(zero);
            dir[axis] = sign;
            Ray::new(o, dir)
        }
        // Touching a box at one corner only, on the root's surface: along
        // one axis the ray leaves the box and the root beyond the corner,
        // along another before it, so the ray meets every cell holding the
        // box at that point only, rounding decides, and the widening must
        // keep the cells.
        6 => {
            let b = boxes[boxes.len() - 1 - rng.usize(..CORNERED)];
            let c = DVec3::select(b.max.cmpeq(DVec3::splat(64.0)), b.max, b.min);
            let away = |i: usize| if c[i] == b.max[i] { 1.0 } else { -1.0 };
            let (i, j) = (axis, (axis + 1) % 3);
            let mut dir = point(rng, -1.0, 1.0);
            dir[i] = away(i) * (0.1 + rng.f64());
            dir[j] = -away(j) * (0.1 + rng.f64());
            Ray::new(c - (1.0 + 99.0 * rng.f64()) * dir, dir)
        }
        // Through a box's corner and the scene's centre, not axis-parallel.
        _ => {
            let c = corner(rng);
            Ray::new(c, DVec3::splat(32.0) - c + point(rng, -1e-9, 1e-9))
        }
    }
}

/// The reference: whether the ray meets the closed box at some `t ≥ t_min`,
/// decided exactly for the axes the ray is parallel to, and by an `f64` slab
/// test widened by 8ε (above its own rounding, about γ(4) ≈ 2ε, and below the
/// octree's 32ε) for the others. (Not [`crate::math::bounds::RayBox::hits`]: a ray
/// parallel to one slab and outside it, lying in the plane of another, gives
/// it a NaN that its `min_element` lets through as a hit.)
fn meets(ray: &Ray, b: &Bounds, t_min: f64) -> bool {
    let (mut enter, mut leave) = (t_min, f64::INFINITY);
    for axis in 0..3 {
        let (o, d) = (ray.origin[axis], ray.dir[axis]);
        if d == 0.0 {
            if o < b.min[axis] || o > b.max[axis] {
                return false;
            }
            continue;
        }
        let t0 = (b.min[axis] - o) / d;
        let t1 = (b.max[axis] - o) / d;
        enter = enter.max(t0.min(t1));
        leave = leave.min(t0.max(t1));
    }
    enter <= leave + leave.abs() * 8.0 * f64::EPSILON
}

/// Can fail if rounding in the slab test or the cell split loses a cell the
/// ray touches (a grazing ray, one in a cell plane, an axis-parallel one with
/// its ±∞ and NaN parameters, a flat or point box), if a primitive is not
/// listed in every cell its box touches, or if the mailbox lets one through
/// twice. The reference is [`meets`].
#[test]
fn visits_every_primitive_the_ray_meets_exactly_once() {
    let mut rng = fastrand::Rng::with_seed(28);
    let boxes = mixed_scene(&mut rng);
    let tree = Octree::build(&boxes);
    assert!(tree.depth >= 3, "{}", described(&tree));
    let (mut met_total, mut visited_total) = (0, 0);
    for case in 0..8000 {
        let ray = awkward_ray(&mut rng, &boxes, case);
        let t_min = if case % 4 == 3 { rng.f64() * 0.5 } else { 0.0 };
        let (visited, _) = walk(&tree, &ray, t_min);
        let mut sorted = visited.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), visited.len(), "a primitive twice: {ray:?}");
        for (i, b) in boxes.iter().enumerate() {
            if meets(&ray, b, t_min) {
                met_total += 1;
                assert!(
                    sorted.binary_search(&i).is_ok(),
                    "case {case}: primitive {i} {b:?} missed by {ray:?} from {t_min}"
                );
            }
        }
        visited_total += visited.len();
    }
    // Not vacuous, and not everything every time.
    assert!(met_total > 10_000, "{met_total}");
    assert!(
        visited_total < 8000 * boxes.len() / 2,
        "{visited_total} of {}",
        8000 * boxes.len()
    );
}

/// Can fail if a closer sphere sits in a cell the walk skipped because a
/// farther hit had shrunk `t_max` (cells out of order, or `reach` not
/// widened enough), or if the walk stops early.
#[test]
fn closest_hit_matches_testing_every_sphere() {
    let mut rng = fastrand::Rng::with_seed(5);
    let spheres: Vec<(DVec3, f64)> = (0..2000)
        .map(|i| {
            let r = if i % 100 == 0 {
                5.0 + rng.f64() * 15.0
            } else {
                0.2 + rng.f64() * 2.0
            };
            (point(&mut rng, 0.0, 100.0), r)
        })
        .collect();
    // Padded by a hair: the rounded `c ± r` may fall just inside the sphere.
    let boxes: Vec<Bounds> = spheres
        .iter()
        .map(|&(c, r)| cube(c, r + 1e-9 * (c.abs().max_element() + r)))
        .collect();
    let tree = Octree::build(&boxes);
    let mut hits = 0;
    for case in 0..4000 {
        let origin = if case % 2 == 0 {
            point(&mut rng, 0.0, 100.0)
        } else {
            point(&mut rng, -200.0, 300.0)
        };
        let mut dir = point(&mut rng, 0.0, 100.0) - origin;
        if case % 10 == 0 {
            dir = DVec3::ZERO;
            dir[case / 10 % 3] = 1.0;
        }
        let ray = Ray::new(origin, dir);
        let t_min = 1e-9;
        let mut brute = (None, f64::INFINITY);
        for (i, &(c, r)) in spheres.iter().enumerate() {
            if let Some(t) = sphere_hit(c, r, &ray, t_min).filter(|&t| t < brute.1) {
                brute = (Some(i), t);
            }
        }
        let mut found = None;
        let mut t_max = f64::INFINITY;
        let _ = tree.walk(
            &ray,
            t_min,
            &mut t_max,
            &mut TestCounts::default(),
            |_, _| {},
            |p, t_max| {
                let (c, r) = spheres[p];
                if let Some(t) = sphere_hit(c, r, &ray, t_min).filter(|&t| t < *t_max) {
                    *t_max = t;
                    found = Some(p);
                }
                ControlFlow::Continue(())
            },
        );
        assert_eq!((found, t_max), brute, "case {case}: {ray:?}");
        hits += usize::from(found.is_some());
    }
    assert!(hits > 1000, "{hits}");
}

/// A row of 100 small cubes along x, and a ray down the row.
fn row() -> (Vec<Bounds>, Ray) {
    let boxes = (0..100)
        .map(|i| cube(DVec3::new(f64::from(i), 0.0, 0.0), 0.25))
        .collect();
    (boxes, Ray::new(DVec3::new(-1.0, 0.01, -0.02), DVec3::X))
}

/// Can fail if the walk goes on after a break, or ignores a shrunk `t_max`
/// (popping cells entered beyond it), or visits cells out of order.
#[test]
fn breaking_and_shrinking_stop_the_walk() {
    let (boxes, ray) = row();
    let tree = Octree::build(&boxes);
    let mut visited = 0;
    let flow = tree.walk(
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

    // Every cube, front to back.
    let (all, full_steps) = walk(&tree, &ray, 0.0);
    assert_eq!(all, (0..100).collect::<Vec<_>>());

    // A closest-hit search: the first cube is hit at t = 0.75.
    let mut t_max = f64::INFINITY;
    let mut tested = TestCounts::default();
    let mut visited = Vec::new();
    let _ = tree.walk(
        &ray,
        0.0,
        &mut t_max,
        &mut tested,
        |_, _| {},
        |p, t_max| {
            visited.push(p);
            let t = boxes[p].min.x - ray.origin.x;
            if t < *t_max {
                *t_max = t;
            }
            ControlFlow::Continue(())
        },
    );
    assert_eq!(t_max, 0.75);
    assert!(visited.len() <= LEAF_SIZE, "{visited:?}");
    assert!(
        tested.boxes * 5 < full_steps,
        "{} steps against {full_steps}",
        tested.boxes
    );
}

/// Can fail if an empty tree is walked (index 0 of no nodes) or a single
/// primitive's degenerate cube (here flat) loses it.
#[test]
fn empty_and_single() {
    let empty = Octree::build(&[]);
    let ray = Ray::new(DVec3::ZERO, DVec3::ONE);
    assert_eq!(walk(&empty, &ray, 0.0), (vec![], 0));
    assert_eq!(described(&empty), "octree: empty");

    let flat = Bounds {
        min: DVec3::new(1.0, 2.0, 3.0),
        max: DVec3::new(2.0, 2.0, 4.0),
    };
    let one = Octree::build(&[flat]);
    let down = Ray::new(DVec3::new(1.5, 5.0, 3.5), DVec3::NEG_Y);
    assert_eq!(walk(&one, &down, 0.0), (vec![0], 1));
    let beside = Ray::new(DVec3::new(2.5, 5.0, 3.5), DVec3::NEG_Y);
    assert_eq!(walk(&one, &beside, 0.0).0, vec![] as Vec<usize>);
    let behind = Ray::new(DVec3::new(1.5, 5.0, 3.5), DVec3::Y);
    assert_eq!(walk(&one, &behind, 0.0).0, vec![] as Vec<usize>);
    assert!(
        described(&one).contains("1 primitives"),
        "{}",
        described(&one)
    );
}

/// Can fail if splitting goes on when it cannot separate the primitives (a
/// pile of copies would be listed 8¹⁰ times), or the entry cap is ignored.
#[test]
fn memory_stays_bounded() {
    let pile = vec![cube(DVec3::ONE, 1.0); 500];
    let tree = Octree::build(&pile);
    assert_eq!((tree.nodes.len(), tree.entries.len()), (1, 500));

    // Long thin boxes crossing one another: each split separates them a
    // little, so only the cap and the depth stop it.
    let mut rng = fastrand::Rng::with_seed(3);
    let sticks: Vec<Bounds> = (0..3000)
        .map(|i| {
            let mut min = point(&mut rng, 0.0, 100.0);
            let mut max = min + 0.01;
            min[i % 3] = 0.0;
            max[i % 3] = 100.0;
            Bounds { min, max }
        })
        .collect();
    let tree = Octree::build(&sticks);
    assert!(tree.entries.len() <= Octree::entry_cap(3000));
    assert!(tree.depth <= DEPTH_LIMIT);
    let mut listed: Vec<u32> = tree.entries.clone();
    listed.sort_unstable();
    listed.dedup();
    assert_eq!(listed, (0..3000).collect::<Vec<u32>>());
}

/// A cluster in one corner of a big scene (the sphereflake over its floor):
/// the octree must keep splitting into the corner until the leaves are small,
/// not stop because one child holds everything; and a depth asked for is kept.
#[test]
fn a_cluster_in_one_corner_is_split_down_to_small_leaves() {
    let mut rng = fastrand::Rng::with_seed(5);
    let mut boxes: Vec<Bounds> = (0..2000)
        .map(|_| cube(point(&mut rng, 1.0, 3.0), 0.01))
        .collect();
    boxes.push(cube(DVec3::splat(50.0), 50.0)); // the "floor": the whole scene
    let tree = Octree::build(&boxes);
    let fullest = tree
        .nodes
        .iter()
        .filter_map(|n| match n.kind {
            Kind::Leaf { len, .. } => Some(len as usize),
            Kind::Inner { .. } => None,
        })
        .max()
        .unwrap();
    // Eight spheres and the floor in a leaf at most, or a leaf at the depth limit.
    assert!(
        fullest <= LEAF_SIZE + 1 || tree.depth == DEPTH_LIMIT,
        "{}",
        described(&tree)
    );
    assert!(tree.depth >= 7, "{}", described(&tree));
    for asked in [0, 3] {
        let shallow = Octree::build_to_depth(&boxes, asked);
        assert_eq!(shallow.depth, asked, "{}", described(&shallow));
    }
    assert_eq!(
        Octree::build_to_depth(&boxes, 1_000_000).depth_limit,
        DEEPEST
    );
}
