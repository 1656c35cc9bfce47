//! Tests of the kdtree (`src/geometry/kdtree.rs`): that it never misses a
//! primitive the ray meets, visits each once, and stops early.

use super::*;
pub(super) use crate::geometry::walk_tests::cube;
use crate::geometry::walk_tests::everything_visited;
use glam::DVec3;

/// Every primitive the walk hands out from `t_min` on, in order, and its steps.
pub(super) fn visited(tree: &KdTree, ray: &Ray, t_min: f64) -> (Vec<usize>, u32) {
    everything_visited(|t_max, tested, visit| {
        tree.traverse_seeing(ray, t_min, t_max, tested, |_, _| {}, visit)
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
        let tree = KdTree::build(&bounds);
        let mut count = vec![0u32; boxes.len()];
        for case in 0..1500 {
            let pick = |rng: &mut fastrand::Rng, r: i64| {
                [rng.i64(-r..=r), rng.i64(-r..=r), rng.i64(-r..=r)]
            };
            // Inside, outside, or on a box's face plane.
            let mut o = match case % 3 {
                0 => pick(&mut rng, l),
                1 => pick(&mut rng, 3 * l),
                _ => {
                    let b = boxes[rng.usize(0..boxes.len())];
                    let mut o = pick(&mut rng, l);
                    let k = rng.usize(0..3);
                    o[k] = if rng.bool() { b.min[k] } else { b.max[k] };
                    o
                }
            };
            if case % 13 == 0 {
                o = o.map(|v| v / 1024 * 1024);
            }
            // Random, through a box's corner or edge midpoint (grazing), or
            // axis-parallel (one or two components zero).
            let b = boxes[rng.usize(0..boxes.len())];
            let mut d = match case % 4 {
                0 => pick(&mut rng, 256),
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
                _ => pick(&mut rng, 256),
            };
            if case % 5 == 0 {
                d[rng.usize(0..3)] = 0;
            }
            if case % 17 == 0 {
                let k = rng.usize(0..3);
                d = [0; 3];
                d[k] = if rng.bool() { 1 } else { -1 };
            }
            if d == [0; 3] {
                d = [1, 0, 0];
            }
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
/// exact order, which only the widening in [`crossing`] makes up for (on the
/// tick grid above every subtraction is exact and a rounded quotient keeps
/// the order). Every value is a multiple of 2⁻³⁰ below 2³¹, so the exact
/// test runs on integers.
#[test]
fn far_rays_grazing_fine_boxes_lose_nothing() {
    const GRID: f64 = 1073741824.0; // 2³⁰
    let ticks = |v: DVec3| {
        v.to_array().map(|c| {
            let s = c * GRID;
            assert!(s.fract() == 0.0 && s.abs() < 2f64.powi(62), "{c}");
            s as i64
        })
    };
    let fine = |rng: &mut fastrand::Rng, r: f64| {
        let mut c = || ((rng.f64() * 2.0 - 1.0) * r * GRID).round() / GRID;
        DVec3::new(c(), c(), c())
    };
    let mut rng = fastrand::Rng::with_seed(1);
    let mut bounds = Vec::new();
    for i in 0..2000 {
        let (a, h) = (fine(&mut rng, 4.0), fine(&mut rng, 0.25).abs());
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
    let boxes: Vec<IBox> = bounds
        .iter()
        .map(|b| IBox {
            min: ticks(b.min),
            max: ticks(b.max),
        })
        .collect();
    let tree = KdTree::build(&bounds);
    let mut count = vec![0u32; boxes.len()];
    for case in 0..3000 {
        let far = |rng: &mut fastrand::Rng| {
            // Far enough that a difference with a fine coordinate is a
            // multiple of 2⁻³⁰ (its ULP is at least that), and mostly rounds.
            let e = rng.i32(22..30);
            let m = 1.0 + f64::from(rng.u32(0..1024)) / 1024.0;
            if rng.bool() {
                m * 2f64.powi(e)
            } else {
                -m * 2f64.powi(e)
            }
        };
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
    const GRID: f64 = 1073741824.0; // 2³⁰
    let ticks = |v: DVec3| {
        v.to_array().map(|c| {
            let s = c * GRID;
            assert!(s.fract() == 0.0 && s.abs() < 2f64.powi(62), "{c}");
            s as i64
        })
    };
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
        let tree = KdTree::build(&bounds);
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
