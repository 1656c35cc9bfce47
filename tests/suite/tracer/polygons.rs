//! Polygons leave no crack: rays aimed exactly at the shared edges and
//! vertices of surfaces made of polygons (a hexagon split into a fan of
//! triangles, a bent strip of quads, a closed polyhedron of triangles and a
//! closed box of quads, all turned so no axis is special) meet at least one of
//! them, every one. A textbook inside test, which classifies each polygon's
//! own hit point `S + t·c` in the plane of the two axes its normal is least
//! along (Haines 1994, as most ray tracers did), lets some through: the test
//! has teeth.

use glam::{DMat3, DVec2, DVec3};
use raytree::geometry::polygon::Polygon;
use raytree::math::ray::Ray;

/// The surfaces: each a list of polygons, and the pairs of points (an edge's
/// two ends) the rays are aimed along.
fn surfaces() -> Vec<(&'static str, Vec<Vec<DVec3>>)> {
    let turn = DMat3::from_euler(glam::EulerRot::XYZ, 0.37, -1.1, 0.23);
    let place = |p: DVec3| turn * p + DVec3::new(0.31, -0.17, 0.05);
    let mut out = Vec::new();
    // A hexagon around its center, as six triangles.
    let center = DVec3::new(0.01, 0.02, 0.0);
    let ring: Vec<DVec3> = (0..6)
        .map(|k| {
            let a = f64::from(k) * std::f64::consts::FRAC_PI_3 + 0.1;
            DVec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    let fan = (0..6)
        .map(|k| {
            vec![center, ring[k], ring[(k + 1) % 6]]
                .into_iter()
                .map(place)
                .collect()
        })
        .collect();
    out.push(("hexagon fan", fan));
    // A strip of quads bent along its length: each quad planar (a trapezoid
    // of a cylinder), its neighbours at an angle.
    let strip = (0..8)
        .map(|k| {
            let (a, b) = (f64::from(k) * 0.3, f64::from(k + 1) * 0.3);
            let on = |angle: f64, y: f64| DVec3::new(angle.cos(), y, angle.sin());
            vec![on(a, -0.7), on(a, 0.6), on(b, 0.6), on(b, -0.7)]
                .into_iter()
                .map(place)
                .collect()
        })
        .collect();
    out.push(("bent strip of quads", strip));
    // A closed icosphere of triangles.
    let (positions, faces) = raytree::scene::generate::icosphere(2);
    let ico = faces
        .iter()
        .map(|f| f.iter().map(|&i| place(positions[i as usize])).collect())
        .collect();
    out.push(("icosphere of triangles", ico));
    // A closed box of quads, each counter-clockwise seen from outside.
    let corner = |i: usize| {
        DVec3::new(
            if i & 1 == 0 { -0.8 } else { 0.9 },
            if i & 2 == 0 { -0.6 } else { 0.7 },
            if i & 4 == 0 { -0.5 } else { 1.1 },
        )
    };
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let cube = quads
        .iter()
        .map(|q| q.iter().map(|&i| place(corner(i))).collect())
        .collect();
    out.push(("box of quads", cube));
    out
}

/// The textbook test: `t` from the plane, the point `S + t·c` projected on
/// the two axes the normal is least along, and the crossing number there with
/// the half-open rule.
fn textbook_hit(vertices: &[DVec3], ray: &Ray) -> bool {
    let n = (vertices[1] - vertices[0])
        .cross(vertices[2] - vertices[0])
        .normalize();
    let t = n.dot(vertices[0] - ray.origin) / n.dot(ray.dir);
    if t.is_nan() || t <= 0.0 {
        return false;
    }
    let p = ray.at(t);
    let a = n.abs();
    let drop = if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    };
    let flat = |v: DVec3| {
        let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
        DVec2::new(v[i] - p[i], v[j] - p[j])
    };
    let mut inside = false;
    let mut prev = flat(vertices[vertices.len() - 1]);
    for &v in vertices {
        let cur = flat(v);
        if (prev.y > 0.0) != (cur.y > 0.0)
            && (prev.x * cur.y - prev.y * cur.x > 0.0) == (cur.y > 0.0)
        {
            inside = !inside;
        }
        prev = cur;
    }
    inside
}

/// The points the rays are aimed at: on each edge two faces share, its ends
/// where every edge there is shared (an interior vertex) and 12 points
/// between, each with the mean normal of the faces it lies on.
fn targets(faces: &[Vec<DVec3>], rng: &mut fastrand::Rng) -> Vec<(DVec3, DVec3)> {
    let key = |v: DVec3| v.to_array().map(f64::to_bits);
    let normal = |f: &[DVec3]| (f[1] - f[0]).cross(f[2] - f[0]).normalize();
    let edges = |f: &[DVec3]| {
        (0..f.len())
            .map(|k| (f[k], f[(k + 1) % f.len()]))
            .collect::<Vec<_>>()
    };
    let mut owner = std::collections::HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for (a, b) in edges(f) {
            owner.insert((key(a), key(b)), i);
        }
    }
    let mut open_vertices = std::collections::HashSet::new();
    for f in faces {
        for (a, b) in edges(f) {
            if !owner.contains_key(&(key(b), key(a))) {
                open_vertices.insert(key(a));
                open_vertices.insert(key(b));
            }
        }
    }
    let mut out = Vec::new();
    for (i, f) in faces.iter().enumerate() {
        for (a, b) in edges(f) {
            let Some(&j) = owner.get(&(key(b), key(a))) else {
                continue;
            };
            let n = (normal(f) + normal(&faces[j])).normalize();
            if !open_vertices.contains(&key(a)) {
                // At a vertex, the mean of every face around it: a ray along the
                // mean of two could pass outside a corner, missing rightly.
                let around = faces.iter().filter(|g| g.iter().any(|&v| key(v) == key(a)));
                out.push((a, around.map(|g| normal(g)).sum::<DVec3>().normalize()));
            }
            if i < j {
                for _ in 0..12 {
                    out.push((a + rng.f64() * (b - a), n));
                }
            }
        }
    }
    out
}

#[test]
fn rays_at_shared_edges_and_vertices_never_miss() {
    let mut rng = fastrand::Rng::with_seed(27);
    let mut report = Vec::new();
    for (name, faces) in surfaces() {
        let polygons: Vec<Polygon> = faces
            .iter()
            .map(|f| Polygon::new(f.clone(), None, false).unwrap())
            .collect();
        let (mut rays, mut misses, mut textbook_misses) = (0, 0, 0);
        for (target, n) in targets(&faces, &mut rng) {
            // From both sides, along the normal there and off it at random, so
            // no direction is special and none grazes a fold.
            for side in [2.0, -2.0] {
                let jitter = DVec3::new(rng.f64(), rng.f64(), rng.f64()) - 0.5;
                let origin = target + side * n + jitter;
                let ray = Ray::new(origin, target - origin);
                rays += 1;
                let hit = polygons
                    .iter()
                    .any(|p| !p.roots(&ray, f64::INFINITY).as_slice().is_empty());
                misses += usize::from(!hit);
                textbook_misses += usize::from(!faces.iter().any(|f| textbook_hit(f, &ray)));
            }
        }
        println!("{name}: {rays} rays, {misses} misses; the textbook test {textbook_misses}");
        report.push((name, rays, misses, textbook_misses));
    }
    assert!(
        report.iter().all(|&(_, _, misses, _)| misses == 0),
        "rays slipped between polygons: {report:?}"
    );
    assert!(
        report.iter().map(|r| r.3).sum::<usize>() > 0,
        "the textbook test showed no crack: the test proves nothing ({report:?})"
    );
}
