//! Tests of the k-d tree's walk (`src/geometry/kdtree.rs`): closest hits, early
//! exits, the steps a walk takes, and the bounds on its size.

use super::tests::{cube, visited};
use super::*;
use crate::geometry::walk_tests::sphere_hit;
use glam::DVec3;

/// A closest-hit search through the tree finds what the lecture's loop over
/// every sphere finds. It fails if the walk stops too early once `t_max`
/// shrinks (a cell still to visit holding a nearer hit was skipped, e.g.
/// a far child pushed with the wrong interval), if cells are visited out of
/// order so that the stop is taken before a nearer cell, or if a sphere is
/// missing from a leaf its box reaches.
#[test]
fn closest_hit_matches_testing_every_sphere() {
    let mut rng = fastrand::Rng::with_seed(5);
    let spheres: Vec<(DVec3, f64)> = (0..2000)
        .map(|i| {
            let c = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 200.0 - 100.0;
            let r = if i % 50 == 0 {
                20.0
            } else {
                0.2 + 2.0 * rng.f64()
            };
            (c, r)
        })
        .collect();
    let bounds: Vec<Bounds> = spheres.iter().map(|&(c, r)| cube(c, r)).collect();
    let tree = KdTree::build(&bounds);
    let mut hits = 0;
    for case in 0..4000 {
        let o = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 300.0 - 150.0;
        let mut d = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 2.0 - 1.0;
        if case % 7 == 0 {
            d.y = 0.0;
        }
        let t_min = if case % 2 == 0 { 0.0 } else { 1e-9 };
        let ray = Ray::new(o, d);
        let mut expected = None;
        for (i, &(c, r)) in spheres.iter().enumerate() {
            if let Some(t) = sphere_hit(c, r, &ray, t_min)
                && expected.is_none_or(|(_, best)| t < best)
            {
                expected = Some((i, t));
            }
        }
        let mut found = None;
        let mut t_max = f64::INFINITY;
        let _ = tree.traverse_seeing(
            &ray,
            t_min,
            &mut t_max,
            &mut TestCounts::default(),
            |_, _| {},
            |p, t_max| {
                if let Some(t) = sphere_hit(spheres[p].0, spheres[p].1, &ray, t_min)
                    && t < *t_max
                {
                    *t_max = t;
                    found = Some((p, t));
                }
                ControlFlow::Continue(())
            },
        );
        assert_eq!(found, expected, "ray {o} + t·{d}");
        hits += usize::from(found.is_some());
    }
    assert!(hits > 500, "only {hits} rays hit anything");
}

/// A row of 100 cubes along x.
fn row() -> Vec<Bounds> {
    (0..100)
        .map(|i| cube(DVec3::new(i as f64, 0.0, 0.0), 0.25))
        .collect()
}

/// After a break nothing more is visited, and the break is returned. Fails
/// if the leaf loop or the walk goes on after `visit` breaks.
#[test]
fn breaking_stops_the_traversal() {
    let tree = KdTree::build(&row());
    let ray = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
    let mut calls = Vec::new();
    let flow = tree.traverse_seeing(
        &ray,
        0.0,
        &mut { f64::INFINITY },
        &mut TestCounts::default(),
        |_, _| {},
        |p, _| {
            calls.push(p);
            ControlFlow::Break(())
        },
    );
    assert_eq!((flow, calls), (ControlFlow::Break(()), vec![0]));
}

/// A hit shrinking `t_max` ends the walk: no cell beyond the hit is visited,
/// far fewer steps than the whole row, and the first cube is visited first.
/// Fails if the walk ignores the shrunk `t_max` when taking far children off
/// its stack, or visits cells back to front.
#[test]
fn a_near_hit_stops_the_walk() {
    let tree = KdTree::build(&row());
    let ray = Ray::new(DVec3::new(-1.0, 0.01, 0.02), DVec3::X);
    let (all, full_steps) = visited(&tree, &ray, 0.0);
    assert_eq!(all.len(), 100);
    assert!(
        all.windows(2).all(|w| w[0] < w[1]),
        "not front to back: {all:?}"
    );
    let mut tested = TestCounts::default();
    let mut calls = 0;
    let mut t_max = f64::INFINITY;
    let hit = std::cell::Cell::new(false);
    let _ = tree.traverse_seeing(
        &ray,
        0.0,
        &mut t_max,
        &mut tested,
        |cell, _| {
            // Once the hit at t = 0.75 (x = −0.25) is known, no cell the
            // ray enters beyond it is visited.
            assert!(
                !hit.get() || cell.min.x <= -0.25 + 1e-9,
                "{cell:?} visited beyond the hit"
            );
        },
        |p, t_max| {
            hit.set(true);
            calls += 1;
            // The cube at x = p is entered at t = p + 0.75.
            *t_max = t_max.min(p as f64 + 0.75);
            ControlFlow::Continue(())
        },
    );
    assert_eq!(t_max, 0.75);
    assert!(
        calls <= 2 && tested.boxes * 5 < full_steps,
        "{calls} visits, {} steps of {full_steps}",
        tested.boxes
    );
}

/// A grid of small cubes: a ray along one row visits few of them and takes
/// few steps, and every step shows its cell. Fails if the build makes no
/// useful splits (a leaf of everything passes the containment test).
#[test]
fn a_row_in_a_grid_takes_few_steps() {
    let boxes: Vec<Bounds> = (0..1000)
        .map(|i| {
            let at = DVec3::new((i % 10) as f64, (i / 10 % 10) as f64, (i / 100) as f64);
            cube(at, 0.25)
        })
        .collect();
    let tree = KdTree::build(&boxes);
    let ray = Ray::new(DVec3::new(-1.0, 4.1, 3.9), DVec3::new(1.0, 0.01, 0.02));
    let mut cells = 0;
    let mut tested = TestCounts::default();
    let mut seen = Vec::new();
    let _ = tree.traverse_seeing(
        &ray,
        0.0,
        &mut { f64::INFINITY },
        &mut tested,
        |_, met| {
            assert!(met);
            cells += 1;
        },
        |p, _| {
            seen.push(p);
            ControlFlow::Continue(())
        },
    );
    assert_eq!(cells, tested.boxes);
    assert!(seen.len() < 30 && tested.boxes < 200, "{seen:?} {tested:?}");
    assert!(tree.depth > 5, "{}", tree.describe());
}

/// No primitives: nothing is visited, no step taken. One primitive: it is
/// visited by a ray that meets its box and not by one that misses the
/// scene. Fails on an unguarded root, or a one-leaf tree clipped wrongly.
#[test]
fn empty_and_single() {
    let ray = Ray::new(DVec3::ZERO, DVec3::new(1.0, 0.5, 0.25));
    let empty = KdTree::build(&[]);
    assert_eq!(visited(&empty, &ray, 0.0), (Vec::new(), 0));
    assert!(empty.describe().contains("0 primitives"));
    let one = KdTree::build(&[cube(DVec3::new(4.0, 2.0, 1.0), 0.5)]);
    assert_eq!(visited(&one, &ray, 0.0), (vec![0], 1));
    assert_eq!(
        visited(&one, &Ray::new(DVec3::ZERO, -ray.dir), 0.0).0,
        Vec::<usize>::new()
    );
    // From inside the box, parallel to an axis.
    let inside = Ray::new(DVec3::new(4.0, 2.0, 1.0), DVec3::Z);
    assert_eq!(visited(&one, &inside, 0.0).0, vec![0]);
    // Lying in its face, parallel to two axes.
    let face = Ray::new(DVec3::new(0.0, 1.5, 1.5), DVec3::X);
    assert_eq!(visited(&one, &face, 0.0).0, vec![0]);
}

/// The entry cap bounds memory: boxes that all overlap would otherwise be
/// copied into every leaf.
#[test]
fn entries_are_capped() {
    let boxes: Vec<Bounds> = (0..500)
        .map(|i| {
            cube(
                DVec3::new(i as f64 * 0.01, 0.0, 0.0),
                10.0 + i as f64 * 0.001,
            )
        })
        .collect();
    let tree = KdTree::build(&boxes);
    assert!(
        tree.entries.len() <= ENTRY_CAP * boxes.len(),
        "{}",
        tree.describe()
    );
}
