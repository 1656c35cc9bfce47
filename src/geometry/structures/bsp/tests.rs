//! Tests of the BSP tree: that it never misses a primitive the ray meets
//! (decided exactly, at every scale, for rays grazing faces, edges and
//! corners), visits each once, finds the closest hit and stops early. (That
//! the entry cap bounds its size is tested beside the build.)

use super::*;
use crate::geometry::structures::walk_tests::{cube, described, everything_visited, sphere_hit};
use glam::DVec3;

/// Every primitive the walk hands out from `t_min` on, in order, and its steps.
fn visited(tree: &BspTree, ray: &Ray, t_min: f64) -> (Vec<usize>, u32) {
    everything_visited(|t_max, tested, visit| {
        tree.walk(ray, t_min, t_max, tested, |_, _| {}, visit)
    })
}

/// A box on an integer grid ("ticks"): its coordinates times a power of two
/// are exact in f64, so the exact test below decides what the tree must find.
#[derive(Clone, Copy, Debug)]
struct IBox {
    min: [i64; 3],
    max: [i64; 3],
}

/// Whether `o + t·d` meets the closed box for some `t ≥ t_min` (a fraction
/// `num/den`, `den > 0`), in exact integer arithmetic: every entering
/// parameter is at most every leaving one, compared as fractions.
fn exact_meets(b: &IBox, o: [i64; 3], d: [i64; 3], t_min: (i128, i128)) -> bool {
    let mut enter = vec![t_min];
    let mut leave = Vec::new();
    for k in 0..3 {
        let (lo, hi, o, d) = (
            i128::from(b.min[k]),
            i128::from(b.max[k]),
            i128::from(o[k]),
            i128::from(d[k]),
        );
        match d.signum() {
            0 if o < lo || o > hi => return false,
            0 => {}
            1 => {
                enter.push((lo - o, d));
                leave.push((hi - o, d));
            }
            _ => {
                enter.push((o - hi, -d));
                leave.push((o - lo, -d));
            }
        }
    }
    enter
        .iter()
        .all(|&(n0, d0)| leave.iter().all(|&(n1, d1)| n0 * d1 <= n1 * d0))
}

/// Random boxes in ticks within ±`l`: mostly small, a few huge, some flat in
/// one axis, some coincident with earlier ones, many with faces on a coarse
/// grid so that they share planes with each other and with ray origins.
fn random_boxes(rng: &mut fastrand::Rng, count: usize, l: i64) -> Vec<IBox> {
    let mut boxes: Vec<IBox> = Vec::with_capacity(count);
    for i in 0..count {
        let kind = rng.u32(0..100);
        let b = if kind < 5 && i > 0 {
            boxes[rng.usize(0..i)]
        } else if kind < 8 {
            let mut b = IBox {
                min: [0; 3],
                max: [0; 3],
            };
            for k in 0..3 {
                b.min[k] = -l + rng.i64(0..l / 4);
                b.max[k] = l - rng.i64(0..l / 4);
            }
            b
        } else {
            let coarse = kind < 40;
            let mut b = IBox {
                min: [0; 3],
                max: [0; 3],
            };
            for k in 0..3 {
                let (mut c, mut h) = (rng.i64(-l..=l), rng.i64(0..=512));
                if coarse {
                    c = c / 1024 * 1024;
                    h = h / 256 * 256 + 512;
                }
                b.min[k] = (c - h).max(-l);
                b.max[k] = (c + h).min(l);
            }
            if kind.is_multiple_of(7) {
                let k = rng.usize(0..3);
                b.max[k] = b.min[k];
            }
            b
        };
        boxes.push(b);
    }
    boxes
}

/// Three random ticks within ±`r`.
fn pick(rng: &mut fastrand::Rng, r: i64) -> [i64; 3] {
    [rng.i64(-r..=r), rng.i64(-r..=r), rng.i64(-r..=r)]
}

/// The origin of ray `case`, in ticks: inside the boxes' span, outside it, or
/// on a face plane of one of `boxes`; every 13th on the coarse grid of 1024.
fn tick_origin(rng: &mut fastrand::Rng, case: usize, boxes: &[IBox], l: i64) -> [i64; 3] {
    let o = match case % 3 {
        0 => pick(rng, l),
        1 => pick(rng, 3 * l),
        _ => {
            let b = boxes[rng.usize(0..boxes.len())];
            let mut o = pick(rng, l);
            let k = rng.usize(0..3);
            o[k] = if rng.bool() { b.min[k] } else { b.max[k] };
            o
        }
    };
    if case.is_multiple_of(13) {
        o.map(|v| v / 1024 * 1024)
    } else {
        o
    }
}

/// The direction of ray `case` from `o`, in ticks: random, through a corner or
/// an edge's midpoint of one of `boxes` (grazing it), or parallel to one or two
/// axes; never zero.
fn tick_direction(rng: &mut fastrand::Rng, case: usize, boxes: &[IBox], o: [i64; 3]) -> [i64; 3] {
    let b = boxes[rng.usize(0..boxes.len())];
    let mut d = match case % 4 {
        0 => pick(rng, 256),
        1 => {
            let c = [0, 1, 2].map(|k| if rng.bool() { b.min[k] } else { b.max[k] });
            [0, 1, 2].map(|k| c[k] - o[k])
        }
        2 => {
            let c = [0, 1, 2].map(|k| match rng.u32(0..3) {
                0 => b.min[k],
                1 => b.max[k],
                _ => (b.min[k] + b.max[k]) / 2,
            });
            [0, 1, 2].map(|k| c[k] - o[k])
        }
        _ => pick(rng, 256),
    };
    if case.is_multiple_of(5) {
        d[rng.usize(0..3)] = 0;
    }
    if case.is_multiple_of(17) {
        let k = rng.usize(0..3);
        d = [0; 3];
        d[k] = if rng.bool() { 1 } else { -1 };
    }
    if d == [0; 3] {
        d = [1, 0, 0];
    }
    d
}

/// The containment test: every primitive whose box the ray meets (decided
/// exactly) is visited, and none twice. It fails if rounding in the clip to
/// the scene box or in a plane crossing skips a cell the ray enters (most
/// likely for rays grazing a face or an edge, lying in a splitting plane,
/// parallel to an axis, or starting on a plane), if a primitive touching a
/// cell only on its boundary (flat, coincident, sharing a plane with the
/// split) was not stored on both sides, or if the mailbox lets a primitive
/// stored in several leaves through twice. Run at three scales (the same
/// configuration times 2⁻⁴⁸, 2⁻⁸, 2³²) since relative bounds must hold at all.
#[test]
fn every_box_met_is_visited_exactly_once() {
    let mut rng = fastrand::Rng::with_seed(28);
    let l: i64 = 1 << 14;
    let boxes = random_boxes(&mut rng, 3000, l);
    let mut extra = 0usize;
    let mut needed = 0usize;
    for scale in [(-48f64).exp2(), (-8f64).exp2(), 32f64.exp2()] {
        let f = |v: [i64; 3]| DVec3::new(v[0] as f64, v[1] as f64, v[2] as f64) * scale;
        let bounds: Vec<Bounds> = boxes
            .iter()
            .map(|b| Bounds {
                min: f(b.min),
                max: f(b.max),
            })
            .collect();
        let tree = BspTree::build(&bounds);
        let mut count = vec![0u32; boxes.len()];
        for case in 0..1500 {
            let o = tick_origin(&mut rng, case, &boxes, l);
            let d = tick_direction(&mut rng, case, &boxes, o);
            let t_min = if case % 6 == 0 { (1, 2) } else { (0, 1) };
            let ray = Ray::new(f(o), f(d));
            let (seen, _) = visited(&tree, &ray, t_min.0 as f64 / t_min.1 as f64);
            for &p in &seen {
                count[p] += 1;
            }
            for (p, b) in boxes.iter().enumerate() {
                let must = exact_meets(b, o, d, t_min);
                assert!(
                    !must || count[p] == 1,
                    "box {p} {b:?} visited {} times: ray {o:?} + t·{d:?}, t ≥ {t_min:?}, scale {scale}",
                    count[p]
                );
                assert!(count[p] <= 1, "box {p} visited {} times", count[p]);
                needed += usize::from(must);
                extra += usize::from(!must && count[p] == 1);
            }
            for &p in &seen {
                count[p] = 0;
            }
        }
    }
    // Not a requirement, but a tree visiting everything would pass the above:
    // the leaves the ray passes hold few boxes it misses.
    assert!(
        extra < 3 * needed,
        "{extra} extra visits for {needed} needed"
    );
}

/// The same containment with rays from far away aimed (in f64) at corners
/// and edges of small boxes with full-precision coordinates: here `p − o`
/// rounds, so computed crossings of different planes can fall out of their
/// exact order, which only the widening in `traverse::crossing` makes up for (on the
/// tick grid above every subtraction is exact and a rounded quotient keeps
/// the order). Every value is a multiple of 2⁻³⁰ below 2³¹, so the exact
/// test runs on integers.
#[test]
fn far_rays_grazing_fine_boxes_lose_nothing() {
    let mut rng = fastrand::Rng::with_seed(1);
    let bounds = fine_boxes(&mut rng);
    let boxes: Vec<IBox> = bounds
        .iter()
        .map(|b| IBox {
            min: ticks(b.min),
            max: ticks(b.max),
        })
        .collect();
    let tree = BspTree::build(&bounds);
    let mut count = vec![0u32; boxes.len()];
    for case in 0..3000 {
        let o = if case % 4 == 0 {
            fine(&mut rng, 4.0)
        } else {
            DVec3::new(far(&mut rng), far(&mut rng), far(&mut rng))
        };
        let b = bounds[rng.usize(0..bounds.len())];
        let pick = |rng: &mut fastrand::Rng, k: usize| match rng.u32(0..3) {
            0 => b.min[k],
            1 => b.max[k],
            _ => (b.center()[k] * GRID).floor() / GRID,
        };
        let target = DVec3::new(pick(&mut rng, 0), pick(&mut rng, 1), pick(&mut rng, 2));
        let mut d = target - o;
        if case % 7 == 0 {
            d[rng.usize(0..3)] = 0.0;
        }
        if d == DVec3::ZERO {
            continue;
        }
        let ray = Ray::new(o, d);
        let (seen, _) = visited(&tree, &ray, 0.0);
        for &p in &seen {
            count[p] += 1;
        }
        let (oi, di) = (ticks(o), ticks(d));
        for (p, b) in boxes.iter().enumerate() {
            assert!(
                count[p] == 1 || (count[p] == 0 && !exact_meets(b, oi, di, (0, 1))),
                "box {p} {:?} visited {} times: ray {o:?} + t·{d:?}",
                bounds[p],
                count[p]
            );
        }
        for &p in &seen {
            count[p] = 0;
        }
    }
}

/// Fine ticks per unit: 2³⁰.
const GRID: f64 = 1073741824.0;

/// A point's coordinates in fine ticks (each must be a whole number of them).
fn ticks(v: DVec3) -> [i64; 3] {
    v.to_array().map(|c| {
        let s = c * GRID;
        assert!(s.fract() == 0.0 && s.abs() < 2f64.powi(62), "{c}");
        s as i64
    })
}

/// A random point within ±`r` on the fine ticks.
fn fine(rng: &mut fastrand::Rng, r: f64) -> DVec3 {
    let mut c = || ((rng.f64() * 2.0 - 1.0) * r * GRID).round() / GRID;
    DVec3::new(c(), c(), c())
}

/// A coordinate far off, either side: far enough that a difference with a
/// fine coordinate is a multiple of 2⁻³⁰ (its ULP is at least that), and
/// mostly rounds.
fn far(rng: &mut fastrand::Rng) -> f64 {
    let e = rng.i32(22..30);
    let m = 1.0 + f64::from(rng.u32(0..1024)) / 1024.0;
    if rng.bool() {
        m * 2f64.powi(e)
    } else {
        -m * 2f64.powi(e)
    }
}

/// 2,000 small boxes on the fine ticks within ±4, every ninth flat in z,
/// every fifth sharing an x plane with an earlier one.
fn fine_boxes(rng: &mut fastrand::Rng) -> Vec<Bounds> {
    let mut bounds = Vec::new();
    for i in 0..2000 {
        let (a, h) = (fine(rng, 4.0), fine(rng, 0.25).abs());
        let mut b = Bounds {
            min: a - h,
            max: a + h,
        };
        if i % 9 == 0 {
            b.max.z = b.min.z;
        }
        if i % 5 == 0 && i > 0 {
            // Share a plane with an earlier box.
            let other: Bounds = bounds[rng.usize(0..i)];
            b.min.x = other.max.x;
            b.max.x = b.max.x.max(b.min.x);
        }
        bounds.push(b);
    }
    bounds
}

/// Four boxes in a 2 × 2 square, so the cells' corners are the boxes'
/// corners, and rays from far off aimed (in f64) near the corner `c`
/// of the box at the origin, `c` just above (1, 1) with low bits set so
/// that `c − o` rounds: each ray passes within a rounding of the corner,
/// clipping the box or not, and whether the walk enters the box's cell turns
/// on the order of two crossings `t_x`, `t_y` equal but for rounding. (With
/// exact subtractions a correctly rounded quotient keeps that order, and no
/// widening would be needed.) It fails if the crossings are taken as exact.
#[test]
fn rays_through_a_cell_corner_keep_the_box() {
    let mut rng = fastrand::Rng::with_seed(3);
    let (mut met, mut missed) = (0, 0);
    for case in 0..400 {
        let fine = |rng: &mut fastrand::Rng| 1.0 + f64::from(rng.u32(1..1 << 20) | 1) / GRID;
        let c = DVec3::new(fine(&mut rng), fine(&mut rng), 1.0);
        // Four boxes tiling [0, 2]² meeting at `c`: the only planes to split
        // on inside the scene pass through `c`.
        let quad = |x: [f64; 2], y: [f64; 2]| Bounds {
            min: DVec3::new(x[0], y[0], 0.0),
            max: DVec3::new(x[1], y[1], 1.0),
        };
        let (lo_x, hi_x, lo_y, hi_y) = ([0.0, c.x], [c.x, 2.0], [0.0, c.y], [c.y, 2.0]);
        let bounds = [
            quad(lo_x, lo_y),
            quad(hi_x, lo_y),
            quad(lo_x, hi_y),
            quad(hi_x, hi_y),
        ];
        let tree = BspTree::build(&bounds);
        let a = IBox {
            min: ticks(bounds[0].min),
            max: ticks(bounds[0].max),
        };
        for _ in 0..50 {
            // Up and to the left of the corner, at 2²²…2³⁰ so that a
            // difference with `c` is a multiple of 2⁻³⁰ and mostly rounds.
            let e = rng.i32(22..30);
            let far = |rng: &mut fastrand::Rng| (1.0 + rng.f64()) * 2f64.powi(e);
            let o = DVec3::new(-far(&mut rng), far(&mut rng), 0.5);
            // Aimed a few 2⁻³⁰ off the corner: aimed right at it, the
            // computed crossings would both be `(c − o) / (c − o)` = 1.
            let off = |rng: &mut fastrand::Rng| f64::from(rng.i32(-4..=4)) / GRID;
            let d = DVec3::new(c.x + off(&mut rng), c.y + off(&mut rng), 0.5) - o;
            let must = exact_meets(&a, ticks(o), ticks(d), (0, 1));
            let got = visited(&tree, &Ray::new(o, d), 0.0).0.contains(&0);
            assert!(
                got || !must,
                "box lost: ray {o:?} + t·{d:?}, corner {c:?} ({case})"
            );
            met += usize::from(must);
            missed += usize::from(!must);
        }
    }
    // The rays fall on both sides of the corner.
    assert!(met > 100 && missed > 100, "{met} met, {missed} missed");
}

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
    let tree = BspTree::build(&bounds);
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
        let _ = tree.walk(
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
    let tree = BspTree::build(&row());
    let ray = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
    let mut calls = Vec::new();
    let flow = tree.walk(
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
    let tree = BspTree::build(&row());
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
    let _ = tree.walk(
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
    let tree = BspTree::build(&boxes);
    let ray = Ray::new(DVec3::new(-1.0, 4.1, 3.9), DVec3::new(1.0, 0.01, 0.02));
    let mut cells = 0;
    let mut tested = TestCounts::default();
    let mut seen = Vec::new();
    let _ = tree.walk(
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
    assert!(tree.depth > 5, "{}", described(&tree));
}

/// No primitives: nothing is visited, no step taken. One primitive: it is
/// visited by a ray that meets its box and not by one that misses the
/// scene. Fails on an unguarded root, or a one-leaf tree clipped wrongly.
#[test]
fn empty_and_single() {
    let ray = Ray::new(DVec3::ZERO, DVec3::new(1.0, 0.5, 0.25));
    let empty = BspTree::build(&[]);
    assert_eq!(visited(&empty, &ray, 0.0), (Vec::new(), 0));
    assert!(described(&empty).contains("0 primitives"));
    let one = BspTree::build(&[cube(DVec3::new(4.0, 2.0, 1.0), 0.5)]);
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
