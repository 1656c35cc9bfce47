//! Tests of the grid: that it never misses a primitive the ray meets, visits
//! each once, and stops early.

use super::build::{capped, resolution};
use super::*;
use crate::geometry::structures::walk_tests::{cube, described, everything_visited};
use crate::math::float::gamma;

/// Whether the ray meets the box at some `t ≥ t_min`: the slab test in f64,
/// the leaving distances widened by `2γ(3)` for their rounding (pbrt-v4
/// §6.1.2), and an axis the ray is parallel to decided by whether the origin
/// lies in that slab. (The library's `RayBox` keeps every box whose slab
/// plane the ray lies in, whatever the other axes say: conservative for
/// culling, too generous to be the reference here.)
fn meets(b: &Bounds, ray: &Ray, t_min: f64) -> bool {
    let (mut enter, mut leave) = (t_min, f64::INFINITY);
    for axis in 0..3 {
        let (o, d) = (ray.origin[axis], ray.dir[axis]);
        if d == 0.0 {
            if o < b.min[axis] || o > b.max[axis] {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((b.min[axis] - o) / d, (b.max[axis] - o) / d);
        enter = enter.max(t0.min(t1));
        leave = leave.min(t0.max(t1) * (1.0 + 2.0 * gamma(3)));
    }
    enter <= leave
}

/// Every primitive the walk hands out from `t_min` on, and its steps.
fn walk(grid: &Grid, ray: &Ray, t_min: f64) -> (Vec<usize>, u32) {
    everything_visited(|t_max, tested, visit| {
        grid.walk(ray, t_min, t_max, tested, |_, _| {}, visit)
    })
}

/// A few thousand boxes of mixed kinds in [-10, 10]³: many small, a few
/// huge, some flat in one axis, some repeated exactly, some sharing a face
/// with the scene's box.
fn mixed_boxes(rng: &mut fastrand::Rng) -> Vec<Bounds> {
    let point = |r: &mut fastrand::Rng| DVec3::new(r.f64(), r.f64(), r.f64()) * 20.0 - 10.0;
    let mut boxes = Vec::new();
    for i in 0..3000usize {
        let c = point(rng);
        let b = match i % 10 {
            0 if i.is_multiple_of(300) => cube(c * 0.2, 4.0 + 4.0 * rng.f64()), // huge
            1 => {
                // flat in one axis, like a triangle in an axis plane
                let mut b = cube(c, 0.3 * rng.f64());
                let axis = rng.usize(0..3);
                b.max[axis] = b.min[axis];
                b
            }
            2 if i > 0 => boxes[rng.usize(0..boxes.len())], // coincident
            3 => {
                // a box with one face on the scene box's face
                let mut b = cube(c, 0.2);
                b.min.x = -10.0;
                b
            }
            4 => Bounds { min: c, max: c }, // a point
            _ => cube(c, 0.05 + 0.2 * rng.f64()),
        };
        boxes.push(Bounds {
            min: b.min.max(DVec3::splat(-10.0)),
            max: b.max.min(DVec3::splat(10.0)),
        });
    }
    boxes
}

/// Rays of every kind the walk must handle: from outside and inside,
/// parallel to one or two axes, lying in a box face's plane, aimed at a box
/// corner, starting on the scene box's face.
fn mixed_ray(rng: &mut fastrand::Rng, boxes: &[Bounds], case: usize) -> Ray {
    let point =
        |r: &mut fastrand::Rng, s: f64| (DVec3::new(r.f64(), r.f64(), r.f64()) * 2.0 - 1.0) * s;
    let b = boxes[rng.usize(0..boxes.len())];
    let corner = DVec3::new(
        [b.min.x, b.max.x][case % 2],
        [b.min.y, b.max.y][case / 2 % 2],
        [b.min.z, b.max.z][case / 4 % 2],
    );
    let mut origin = if case.is_multiple_of(3) {
        point(rng, 9.0)
    } else {
        point(rng, 30.0)
    };
    let mut dir = match case % 4 {
        0 => corner - origin,
        1 => b.center() - origin,
        _ => point(rng, 1.0),
    };
    match case % 7 {
        0 => dir.y = 0.0,
        1 => {
            dir.x = 0.0;
            dir.z = 0.0;
        }
        2 => {
            // in the plane of a box's face, parallel to it
            origin.z = b.max.z;
            dir.z = 0.0;
        }
        3 => origin.x = -10.0,
        _ => {}
    }
    if dir == DVec3::ZERO {
        dir = DVec3::X;
    }
    Ray::new(origin, dir)
}

/// The walk visits every primitive whose box the ray meets: it fails if a
/// rounded DDA boundary, a clamp, the clip to the grid, or an axis-parallel
/// ray's infinite reciprocal makes the walk skip a cell the ray passes
/// through, or if listing a box in its cells rounds one cell short. The
/// reference is the BVH's f64 slab test, exact but for a widening of a few
/// ULPs. It also fails if the mailbox lets a primitive through twice.
#[test]
fn the_walk_visits_every_box_the_ray_meets_once() {
    let mut rng = fastrand::Rng::with_seed(28);
    let boxes = mixed_boxes(&mut rng);
    for grid in [
        Grid::build(&boxes),
        Grid::build_with_resolution(&boxes, [1, 1, 1]),
        Grid::build_with_resolution(&boxes, [97, 3, 250]),
    ] {
        for case in 0..3000 {
            let ray = mixed_ray(&mut rng, &boxes, case);
            let t_min = if case.is_multiple_of(5) {
                rng.f64()
            } else {
                0.0
            };
            let (visited, _) = walk(&grid, &ray, t_min);
            let mut once = visited.clone();
            once.sort_unstable();
            once.dedup();
            assert_eq!(once.len(), visited.len(), "a primitive visited twice");
            for (p, b) in boxes.iter().enumerate() {
                if meets(b, &ray, t_min) {
                    assert!(
                        once.binary_search(&p).is_ok(),
                        "{} skipped box {p} {b:?}: ray {ray:?} from {t_min}",
                        described(&grid)
                    );
                }
            }
        }
    }
}

/// Boxes whose faces lie exactly on cell boundaries, at scales where the
/// cell coordinates round, and rays along those boundaries: where a
/// DDA that trusted its rounded `t` would step into the wrong neighbour.
#[test]
fn boxes_on_cell_boundaries_are_found_at_every_scale() {
    let mut rng = fastrand::Rng::with_seed(5);
    for (scale, offset) in [(1.0, 0.0), (1e-3, 1e3), (1e5, -3e7), (0.1, 0.1)] {
        let boxes: Vec<Bounds> = (0..512)
            .map(|i| {
                let at = DVec3::new((i % 8) as f64, (i / 8 % 8) as f64, (i / 64) as f64);
                Bounds {
                    min: at * scale + offset,
                    max: (at + 1.0) * scale + offset,
                }
            })
            .filter(|_| rng.f64() < 0.3)
            .collect();
        let grid = Grid::build_with_resolution(&boxes, [8, 8, 8]);
        for case in 0..4000usize {
            let on = |r: &mut fastrand::Rng| (r.usize(0..9) as f64) * scale + offset;
            let origin = DVec3::new(on(&mut rng), on(&mut rng), on(&mut rng))
                + DVec3::new(rng.f64(), rng.f64(), rng.f64())
                    * scale
                    * f64::from(u8::from(case.is_multiple_of(2)));
            let target = DVec3::new(on(&mut rng), on(&mut rng), on(&mut rng));
            let mut dir = target - origin;
            if case.is_multiple_of(3) {
                dir[case / 3 % 3] = 0.0;
            }
            if dir == DVec3::ZERO {
                continue;
            }
            let ray = Ray::new(origin, dir);
            let (visited, _) = walk(&grid, &ray, 0.0);
            for (p, b) in boxes.iter().enumerate() {
                if meets(b, &ray, 0.0) {
                    assert!(
                        visited.contains(&p),
                        "skipped {b:?}: {ray:?} at scale {scale}"
                    );
                }
            }
        }
    }
}

/// The widening costs (almost) no extra cells: over random rays through
/// 5,000 small boxes, the cells visited are within 1% of the cells the ray
/// pierces (1 + the boundaries it crosses on each axis, inside the grid).
/// Fails if each piece's two doubts (the cell before, the cell after) are
/// joined in one box, which adds a diagonal cell at nearly every step.
#[test]
fn the_walk_visits_about_the_cells_the_ray_pierces() {
    let mut rng = fastrand::Rng::with_seed(3);
    let boxes: Vec<Bounds> = (0..5000)
        .map(|_| cube(DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 20.0, 0.1))
        .collect();
    let grid = Grid::build(&boxes);
    let (mut steps, mut pierced) = (0, 0);
    for _ in 0..2000 {
        let origin = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 20.0;
        let dir = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 2.0 - 1.0;
        let ray = Ray::new(origin, dir);
        steps += walk(&grid, &ray, 0.0).1;
        // Where the ray leaves the grid's box, then the cells in between.
        let b = grid.bounds;
        let t_out = (0..3)
            .map(|a| ((if dir[a] > 0.0 { b.max[a] } else { b.min[a] }) - origin[a]) / dir[a])
            .fold(f64::INFINITY, f64::min);
        let (from, to) = (grid.cell_of(origin), grid.cell_of(ray.at(t_out)));
        pierced += 1 + (0..3).map(|a| from[a].abs_diff(to[a]) as u32).sum::<u32>();
    }
    assert!(
        steps >= pierced && steps * 100 <= pierced * 101,
        "{steps} cells visited, {pierced} pierced"
    );
}

/// The nearest root of `|o + t·d − c|² = r²` beyond `t_min`, in the stable form.
fn sphere_root(ray: &Ray, c: DVec3, r: f64, t_min: f64) -> Option<f64> {
    let oc = ray.origin - c;
    let a = ray.dir.length_squared();
    let h = oc.dot(ray.dir);
    let cc = oc.length_squared() - r * r;
    let disc = h * h - a * cc;
    if disc < 0.0 {
        return None;
    }
    let q = -(h + disc.sqrt().copysign(h));
    let (t0, t1) = (q / a, cc / q);
    let (near, far) = (t0.min(t1), t0.max(t1));
    [near, far].into_iter().find(|&t| t > t_min)
}

/// A closest-hit search through the grid finds the same sphere at the same
/// `t` as a loop over all of them: it fails if the walk stops too early
/// (a cell entered before `*t_max` judged beyond it), visits cells out of
/// order in a way the stop rule then cuts short, or skips a cell.
#[test]
fn closest_hit_matches_the_loop_over_everything() {
    let mut rng = fastrand::Rng::with_seed(11);
    let spheres: Vec<(DVec3, f64)> = (0..2000usize)
        .map(|i| {
            let c = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 20.0 - 10.0;
            let r = if i.is_multiple_of(100) {
                2.0
            } else {
                0.05 + 0.3 * rng.f64()
            };
            (c, r)
        })
        .collect();
    // Padded a little: the box of a sphere must hold every point a rounded
    // root can land on.
    let boxes: Vec<Bounds> = spheres
        .iter()
        .map(|&(c, r)| cube(c, r * (1.0 + 1e-9)))
        .collect();
    let grid = Grid::build(&boxes);
    let mut hits = 0;
    for case in 0..5000 {
        let ray = mixed_ray(&mut rng, &boxes, case);
        let t_min = if case.is_multiple_of(3) { 1e-9 } else { 0.0 };
        let mut best = None;
        let mut t_max = f64::INFINITY;
        for (i, &(c, r)) in spheres.iter().enumerate() {
            if let Some(t) = sphere_root(&ray, c, r, t_min).filter(|&t| t < t_max) {
                (best, t_max) = (Some(i), t);
            }
        }
        let mut found = None;
        let mut t = f64::INFINITY;
        let _ = grid.walk(
            &ray,
            t_min,
            &mut t,
            &mut TestCounts::default(),
            |_, _| {},
            |p, t_max| {
                let (c, r) = spheres[p];
                if let Some(t) = sphere_root(&ray, c, r, t_min).filter(|&t| t < *t_max) {
                    *t_max = t;
                    found = Some(p);
                }
                ControlFlow::Continue(())
            },
        );
        assert_eq!((found, t), (best, t_max), "{ray:?}");
        hits += usize::from(best.is_some());
    }
    assert!(hits > 1000, "only {hits} rays hit anything");
}

/// A row of 100 cubes along x, on a 100-cell grid.
fn row() -> (Vec<Bounds>, Grid, Ray) {
    let boxes: Vec<Bounds> = (0..100)
        .map(|i| cube(DVec3::new(i as f64, 0.0, 0.0), 0.25))
        .collect();
    let grid = Grid::build(&boxes);
    (boxes, grid, Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X))
}

/// After a break nothing more is visited: fails if the walk ignores `?`.
#[test]
fn breaking_stops_the_walk() {
    let (_, grid, ray) = row();
    let mut visited = 0;
    let flow = grid.walk(
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

/// A hit near the start shrinks `t_max` and ends the walk: fails if the walk
/// reads `t_max` only once, walking every cell to the grid's end.
#[test]
fn a_near_hit_ends_the_walk() {
    let (_, grid, ray) = row();
    let (all, full) = walk(&grid, &ray, 0.0);
    assert_eq!(all.len(), 100);
    let mut tested = TestCounts::default();
    let mut visited = Vec::new();
    let _ = grid.walk(
        &ray,
        0.0,
        &mut { f64::INFINITY },
        &mut tested,
        |_, _| {},
        |p, t_max| {
            visited.push(p);
            // The cube's near face along the ray: x = p − 0.25, from x = −5.
            *t_max = t_max.min(p as f64 - 0.25 + 5.0);
            ControlFlow::Continue(())
        },
    );
    assert!(visited.contains(&0) && visited.len() <= 3, "{visited:?}");
    assert!(tested.boxes * 10 < full, "{} steps of {full}", tested.boxes);
}

/// No primitives: nothing visited, nothing counted, a summary all the same.
#[test]
fn an_empty_grid_visits_nothing() {
    for grid in [
        Grid::build(&[]),
        Grid::build_with_resolution(&[], [4, 4, 4]),
    ] {
        let (visited, steps) = walk(&grid, &Ray::new(DVec3::ZERO, DVec3::ONE), 0.0);
        assert_eq!((visited.len(), steps), (0, 0));
        assert!(
            described(&grid).contains("0 primitives"),
            "{}",
            described(&grid)
        );
    }
}

/// One primitive, solid, flat or a point: found by a ray through it from any
/// side or along an axis, missed by a ray far away. Fails if a zero extent
/// makes the cell size infinite or NaN. (The rule gives λ·1 = 4 cells,
/// ⌈4^{1/3}⌉ = 2 per axis, one across a flat axis, one for a point.)
#[test]
fn a_single_primitive() {
    let one = DVec3::ONE;
    for b in [
        cube(one, 0.5),
        Bounds {
            min: DVec3::new(0.5, 1.0, 0.5),
            max: DVec3::new(1.5, 1.0, 1.5),
        },
        Bounds { min: one, max: one },
    ] {
        let grid = Grid::build(&[b]);
        let cells = if b.min == b.max {
            1
        } else if b.min.y == b.max.y {
            4
        } else {
            8
        };
        assert_eq!(grid.resolution().iter().product::<usize>(), cells);
        for dir in [DVec3::X, DVec3::NEG_Y, DVec3::new(-1.0, -1.0, -1.0)] {
            let through = Ray::new(one - 3.0 * dir, dir);
            assert_eq!(walk(&grid, &through, 0.0).0, vec![0], "{b:?} {dir}");
            let inside = Ray::new(one, dir);
            assert_eq!(walk(&grid, &inside, 0.0).0, vec![0], "{b:?} {dir}");
            let far = Ray::new(one + DVec3::new(0.0, 0.0, 50.0) - 3.0 * dir, dir);
            assert_eq!(walk(&grid, &far, 0.0).0, Vec::<usize>::new());
        }
    }
}

/// The resolution rule: about λN near-cubic cells, one cell across a flat
/// axis, and the clamps.
#[test]
fn resolution_follows_the_rule() {
    // 1000 primitives in a unit cube: ⌈(4000)^{1/3}⌉ = ⌈15.87⌉ = 16 per axis.
    assert_eq!(resolution(DVec3::ONE, 1000), [16, 16, 16]);
    // A box twice as long in x: V = 2, n_x = ⌈2·(2000)^{1/3}⌉ = ⌈25.2⌉.
    assert_eq!(resolution(DVec3::new(2.0, 1.0, 1.0), 1000), [26, 13, 13]);
    // Flat in z: the rule in two dimensions, ⌈(4000)^{1/2}⌉ = 64.
    assert_eq!(resolution(DVec3::new(1.0, 1.0, 0.0), 1000), [64, 64, 1]);
    // Nearly flat: the thin axis gets one cell, the others share λN.
    assert_eq!(resolution(DVec3::new(1.0, 1.0, 1e-6), 1000), [64, 64, 1]);
    assert_eq!(resolution(DVec3::ONE, 1 << 30), [MAX_AXIS; 3]);
    assert_eq!(resolution(DVec3::ZERO, 5), [1, 1, 1]);
    assert_eq!(capped([1024, 1024, 1024]), [256, 128, 128]);
    let grid = Grid::build_with_resolution(&[cube(DVec3::ZERO, 1.0)], [0, 5, 5000]);
    assert_eq!(grid.resolution(), [1, 5, MAX_AXIS_SWEEP]);
}
