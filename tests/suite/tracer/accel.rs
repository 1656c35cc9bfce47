//! The bounding volume hierarchy finds exactly what testing every object finds,
//! and the watertight triangle test closes the cracks Möller–Trumbore leaves.

use std::fmt::Write;

use glam::DVec3;
use raytree::geometry::hit::{Search, TestCounts};
use raytree::math::ray::Ray;
use raytree::methods::{Accel, TriangleMethod};
use raytree::trace::recorder::NoRecorder;
use raytree::trace::tracer::Tracer;

/// A random scene of every kind of object: spheres, boxes, triangles and
/// polygons, some transformed, two icosphere meshes (one stretched), and a
/// plane. (Under the hierarchy, spheres without a transform are tested as
/// copies kept in its leaf order, the others as themselves: a copy off by a
/// part in 10⁴ of its radius fails here.)
fn random_scene(seed: u64, objects: usize, dir: &std::path::Path) -> String {
    let obj = dir.join(format!("ico{seed}.obj"));
    std::fs::write(&obj, raytree::scene::generate::icosphere_obj(2)).unwrap();
    let mut rng = fastrand::Rng::with_seed(seed);
    let mut p = |scale: f64| {
        DVec3::new(
            (rng.f64() - 0.5) * scale,
            (rng.f64() - 0.5) * scale,
            (rng.f64() - 0.5) * scale,
        )
    };
    let mut list = vec![
        r#"{ "plane": { "point": [0, -6, 0], "normal": [0.1, 1, 0] }, "material": "matte" }"#
            .to_owned(),
        format!(
            r#"{{ "mesh": {{ "file": "{}" }}, "material": "glass", "transform": [{{ "translate": {} }}] }}"#,
            obj.display(),
            json(p(8.0))
        ),
        format!(
            r#"{{ "mesh": {{ "file": "{}", "smooth": false }}, "material": "matte", "transform": [{{ "scale": [2, 0.5, 1] }}, {{ "rotate_z": 30 }}, {{ "translate": {} }}] }}"#,
            obj.display(),
            json(p(8.0))
        ),
    ];
    for i in 0..objects {
        let c = p(10.0);
        let material = ["matte", "mirror", "glass"][i % 3];
        let shape = shape(i, c, &mut p);
        list.push(format!("{{ {shape}, \"material\": \"{material}\" }}"));
    }
    let mut s = String::new();
    let _ = write!(
        s,
        r#"{{
  "camera": {{ "eye": [0, 0, 14], "look_at": [0, 0, 0] }},
  "render": {{ "width": 48, "height": 36 }},
  "materials": {{
    "matte": {{ "color": [0.8, 0.5, 0.3] }},
    "mirror": {{ "color": [0.5, 0.5, 0.5], "reflective": 0.7 }},
    "glass": {{ "color": [1, 1, 1], "transparent": 0.8, "reflective": 0.1, "ior": 1.4 }}
  }},
  "lights": [{{ "position": [5, 9, 9] }}, {{ "position": [-7, 3, 8], "color": [0.4, 0.4, 0.4] }}],
  "objects": [{}]
}}"#,
        list.join(",\n")
    );
    s
}

/// A point as a scene file writes it.
fn json(v: DVec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

/// The shape of the random scene's object `i`, at `c`, in turn a sphere, a
/// box, a triangle, a polygon (a twelfth of them one-sided), a transformed
/// sphere and a transformed box; `p(scale)` gives random offsets.
fn shape(i: usize, c: DVec3, p: &mut impl FnMut(f64) -> DVec3) -> String {
    let v = json;
    match i % 6 {
        0 => format!(
            r#""sphere": {{ "center": {}, "radius": {} }}"#,
            v(c),
            0.2 + 0.3 * (c.x.abs() % 1.0)
        ),
        1 => format!(
            r#""box": {{ "min": {}, "max": {} }}"#,
            v(c),
            v(c + DVec3::new(0.4, 0.7, 0.3))
        ),
        2 => format!(
            r#""triangle": {{ "vertices": [{}, {}, {}] }}"#,
            v(c),
            v(c + p(1.5)),
            v(c + p(1.5))
        ),
        3 => {
            let (u, w) = (p(1.5), p(1.5));
            format!(
                r#""polygon": {{ "vertices": [{}, {}, {}, {}], "one_sided": {} }}"#,
                v(c),
                v(c + u),
                v(c + u + w),
                v(c + w),
                i % 12 == 3
            )
        }
        4 => format!(
            r#""sphere": {{ "center": [0, 0, 0], "radius": 0.4 }}, "transform": [{{ "scale": [1, 0.5, 1.5] }}, {{ "translate": {} }}]"#,
            v(c)
        ),
        _ => format!(
            r#""box": {{ "min": [-0.3, -0.3, -0.3], "max": [0.3, 0.3, 0.3] }}, "transform": [{{ "rotate": {{ "axis": {}, "degrees": 40 }} }}, {{ "translate": {} }}]"#,
            v(p(1.0) + DVec3::X),
            v(c)
        ),
    }
}

#[test]
fn the_hierarchy_finds_the_same_hits_as_testing_every_object() {
    let dir = tempfile::tempdir().unwrap();
    let mut compared = 0;
    let (mut saved, mut all) = (0u64, 0u64);
    for seed in 1..=6 {
        let text = random_scene(seed, 60 * seed as usize, dir.path());
        // Named in its mesh's folder: a mesh is read from the scene's folder.
        let file = dir.path().join("random.json").display().to_string();
        let mut brute = raytree::scene::loader::parse(&text, &file).unwrap();
        brute.settings.accel = Accel::None;
        let mut bvh = brute.clone();
        bvh.settings.accel = Accel::Bvh;
        let (tb, th) = (Tracer::new(&brute), Tracer::new(&bvh));
        assert!(th.accelerator().bvh().is_some() && tb.accelerator().bvh().is_none());
        let mut rng = fastrand::Rng::with_seed(seed);
        for _ in 0..4000 {
            let mut r = || (rng.f64() - 0.5) * 24.0;
            let ray = Ray::new(DVec3::new(r(), r(), r()), DVec3::new(r(), r(), r()));
            let a = tb.closest_hit(&ray, 0.0, f64::INFINITY, &mut NoRecorder);
            let b = th.closest_hit(&ray, 0.0, f64::INFINITY, &mut NoRecorder);
            // Same object, same t to the bit: the hierarchy only skips tests.
            assert_eq!(a, b, "seed {seed}, {ray:?}");
            compared += usize::from(a.is_some());
            let count = |t: &Tracer| {
                let mut log = Counts::default();
                t.closest_hit(&ray, 0.0, f64::INFINITY, &mut log);
                log.0.primitives as u64
            };
            saved += count(&th);
            all += count(&tb);
        }
        // Whole images, shadows and recursion included, agree bit for bit.
        let none =
            raytree::trace::render::render(&brute, &raytree::trace::progress::Progress::QUIET)
                .unwrap();
        let with = raytree::trace::render::render(&bvh, &raytree::trace::progress::Progress::QUIET)
            .unwrap();
        assert!(none == with, "seed {seed}: the images differ");
    }
    println!(
        "{compared} hits compared; primitives tested: {saved} with the hierarchy, {all} without"
    );
    assert!(
        compared > 2000,
        "too few rays hit anything to compare: {compared}"
    );
    assert!(
        saved * 3 < all,
        "the hierarchy should test far fewer primitives: {saved} vs {all}"
    );
}

/// Keeps the counts the tracer reports.
#[derive(Default)]
struct Counts(TestCounts);

impl raytree::trace::recorder::Recorder for Counts {
    const ENABLED: bool = true;
    fn tested(&mut self, t: &TestCounts) {
        self.0 = *t;
    }
}

/// Rays aimed exactly at points on the shared edges of a closed mesh, from inside
/// and from outside: every one must hit. Möller–Trumbore lets some through;
/// the watertight test none (Woop, Benthin & Wald 2013, figure 1).
#[test]
fn watertight_triangles_have_no_cracks_where_moller_trumbore_does() {
    let (positions, faces) = raytree::scene::generate::icosphere(4);
    let mesh = raytree::geometry::mesh::Mesh::new(positions.clone(), vec![], faces.clone(), vec![]);
    let mut rng = fastrand::Rng::with_seed(7);
    let mut misses = [0usize; 2];
    let mut rays = 0;
    // Off-center inner origin and outer origins, so no ray direction is special.
    let inner = DVec3::new(0.013, -0.021, 0.007);
    for &[a, b, _] in &faces {
        let (a, b) = (positions[a as usize], positions[b as usize]);
        for _ in 0..4 {
            let on_edge = a + rng.f64() * (b - a);
            let outer = on_edge * 3.0 + DVec3::new(rng.f64(), rng.f64(), rng.f64());
            for ray in [
                Ray::new(inner, on_edge - inner),
                Ray::new(outer, on_edge - outer),
            ] {
                rays += 1;
                for (k, method) in [TriangleMethod::Watertight, TriangleMethod::MollerTrumbore]
                    .into_iter()
                    .enumerate()
                {
                    let roots = mesh.roots(
                        &ray,
                        method,
                        f64::INFINITY,
                        Search::Closest,
                        &mut TestCounts::default(),
                    );
                    misses[k] += usize::from(roots.as_slice().is_empty());
                }
            }
        }
    }
    println!(
        "{rays} rays at shared edges: watertight {} misses, Möller–Trumbore {}",
        misses[0], misses[1]
    );
    assert_eq!(misses[0], 0, "the watertight test let rays through");
    assert!(
        misses[1] > 0,
        "Möller–Trumbore showed no crack: the test proves nothing"
    );
}
