//! raytree's closest-hit loop alone, for the side-by-sides with Embree
//! (`benches/embree/compare.sh` through Python, `benches/embree/native.sh`
//! natively; see there).
//!
//! ```text
//! closest_hit export DIR [--width W --height H --random N]
//! closest_hit time DIR [--set primary|random|inside] [--passes P] [--tracer]
//! closest_hit spheres export DIR N [--width W --height H]
//! closest_hit spheres time DIR N [--passes P]
//! ```
//!
//! `export` writes into DIR the Gaspra mesh's triangles in world space
//! (`triangles.f32`: 9 floats each) and three sets of rays (`primary.f64`,
//! `random.f64`, `inside.f64`: 6 doubles each, origin then direction): exactly
//! raytree's primary rays of `scenes/gaspra.json` at W×H (default 640×480, one
//! per pixel through its center); N rays (default 300,000, fixed seed) from
//! random points on a sphere around the mesh toward random points in its box;
//! and N rays from random points inside the mesh's box in random directions
//! (most start in empty space between the asteroid's box and its surface, some
//! inside the asteroid).
//!
//! `time` reads the mesh and a ray set back, builds raytree's hierarchy over the
//! world-space triangles, and times the closest hit of every ray on one thread
//! (the watertight test in f64 under the 4-wide single-precision hierarchy, as
//! the renderer runs it), P passes (default 3). It prints one line:
//! `seconds=<fastest pass> rays=<n> hits=<n> t_sum=<Σ t over hits>`.
//! With `--tracer` it times instead the tracer's own search, as the renderer
//! runs it for every ray: `Tracer::closest_hit` (through the scene's objects,
//! counting its tests, with the no-op recorder) on a scene of `gaspra.json`
//! whose one object is that same world-space mesh. The two lines' difference
//! is the tracer's own work around the loop.
//!
//! `spheres export` writes the spheres of `raytree generate spheres N` (seed 1,
//! the scene `benches/scenes.rs` times; its floor plane left out) as
//! `spheres-N.f64` (4 doubles each: center, radius) and that scene's primary
//! rays at W×H (default 320×240, as `benches/scenes.rs`) as `spheres-N-rays.f64`.
//! `spheres time` times what the renderer does for each of those rays:
//! `Tracer::closest_hit` on a tracer over a scene of those spheres alone, under
//! the hierarchy (`accel: bvh`), with the no-op recorder; it prints the same line.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use glam::DVec3;
use raytree::geometry::hit::{Search, TestCounts};
use raytree::geometry::mesh::Mesh;
use raytree::geometry::object::{Object, Shape};
use raytree::math::ray::Ray;
use raytree::methods::{Accel, TriangleMethod};
use raytree::trace::pixel::sample_points;
use raytree::trace::recorder::NoRecorder;
use raytree::trace::tracer::Tracer;

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let flag = |name: &str, default: usize| {
        args.iter()
            .position(|a| a == name)
            .and_then(|i| args.get(i + 1))
            .map_or(default, |v| {
                v.parse().unwrap_or_else(|_| fail(&format!("{name}: {v}")))
            })
    };
    let set = args
        .iter()
        .position(|a| a == "--set")
        .and_then(|i| args.get(i + 1))
        .map_or("primary", String::as_str);
    // The words that are not flags or their values.
    let words: Vec<&str> = args
        .iter()
        .enumerate()
        .filter(|&(i, a)| !a.starts_with("--") && (i == 0 || !args[i - 1].starts_with("--")))
        .map(|(_, a)| a.as_str())
        .collect();
    let count = |word: &str| {
        word.parse::<usize>()
            .ok()
            .filter(|&n| n > 0)
            .unwrap_or_else(|| fail(&format!("sphere count: {word}")))
    };
    match words.as_slice() {
        ["export", dir] => export(
            Path::new(dir),
            flag("--width", 640),
            flag("--height", 480),
            flag("--random", 300_000),
        ),
        ["time", dir] => time(
            Path::new(dir),
            set,
            flag("--passes", 3),
            args.iter().any(|a| a == "--tracer"),
        ),
        ["spheres", "export", dir, n] => export_spheres(
            Path::new(dir),
            count(n),
            flag("--width", 320),
            flag("--height", 240),
        ),
        ["spheres", "time", dir, n] => time_spheres(Path::new(dir), count(n), flag("--passes", 3)),
        // `cargo test --benches` runs every bench target once: nothing to do.
        _ if args.is_empty() || args.iter().any(|a| a == "--test") => {}
        _ => fail(
            "usage: closest_hit export DIR [--width W --height H --random N] | time DIR [--set primary|random|inside] [--passes P] [--tracer] | spheres export DIR N [--width W --height H] | spheres time DIR N [--passes P]",
        ),
    }
}

fn fail(message: &str) -> ! {
    eprintln!("error: {message}");
    std::process::exit(2)
}

fn gaspra_scene() -> raytree::scene::Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/gaspra.json");
    raytree::scene::loader::load(&path).unwrap_or_else(|e| fail(&format!("{e:#}")))
}

/// The Gaspra mesh's triangles in world space.
fn world_triangles(scene: &raytree::scene::Scene) -> Vec<[DVec3; 3]> {
    let object = scene
        .objects
        .iter()
        .find(|o| matches!(o.shape, Shape::Mesh(_)))
        .unwrap_or_else(|| fail("gaspra.json has no mesh"));
    let Shape::Mesh(mesh) = &object.shape else {
        unreachable!()
    };
    let to_world = |p: DVec3| {
        object
            .transform
            .as_ref()
            .map_or(p, |tf| tf.to_world.transform_point3(p))
    };
    (0..mesh.faces.len())
        .map(|f| {
            let t = mesh.triangle(f);
            [to_world(t.a), to_world(t.b), to_world(t.c)]
        })
        .collect()
}

fn export(dir: &Path, width: usize, height: usize, random: usize) {
    std::fs::create_dir_all(dir).unwrap_or_else(|e| fail(&format!("{}: {e}", dir.display())));
    let mut scene = gaspra_scene();
    scene.settings.width = width as u32;
    scene.settings.height = height as u32;
    let triangles = world_triangles(&scene);
    let floats: Vec<f32> = triangles
        .iter()
        .flat_map(|t| t.iter().flat_map(|p| [p.x as f32, p.y as f32, p.z as f32]))
        .collect();
    write(&dir.join("triangles.f32"), &floats, f32::to_le_bytes);
    let camera = scene.camera();
    let primary: Vec<Ray> = (0..height as u32)
        .flat_map(|y| (0..width as u32).map(move |x| (x, y)))
        .flat_map(|(x, y)| sample_points(x, y, 1))
        .map(|(sx, sy)| camera.pixel_ray(sx, sy))
        .collect();
    write_rays(&dir.join("primary.f64"), &primary);
    let bounds = raytree::math::bounds::Bounds::around(triangles.iter().flatten().copied());
    let (center, radius) = (bounds.center(), (bounds.max - bounds.min).length());
    let mut rng = fastrand::Rng::with_seed(18);
    let mut unit = || DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 2.0 - DVec3::ONE;
    let random_rays: Vec<Ray> = (0..random)
        .map(|_| {
            let origin = center + radius * unit().normalize_or(DVec3::X);
            let target = center + 0.5 * (bounds.max - bounds.min) * unit();
            Ray::new(origin, (target - origin).normalize())
        })
        .collect();
    write_rays(&dir.join("random.f64"), &random_rays);
    let mut rng = fastrand::Rng::with_seed(19);
    let inside: Vec<Ray> = (0..random)
        .map(|_| {
            let at = DVec3::new(rng.f64(), rng.f64(), rng.f64());
            let origin = bounds.min + at * (bounds.max - bounds.min);
            // Uniform over directions: a point drawn in the unit ball, away from its center.
            let dir = loop {
                let d = DVec3::new(rng.f64(), rng.f64(), rng.f64()) * 2.0 - DVec3::ONE;
                if (1e-6..=1.0).contains(&d.length_squared()) {
                    break d.normalize();
                }
            };
            Ray::new(origin, dir)
        })
        .collect();
    write_rays(&dir.join("inside.f64"), &inside);
    eprintln!(
        "wrote {} triangles, {} primary, {} random and {} inside rays to {}",
        triangles.len(),
        primary.len(),
        random_rays.len(),
        inside.len(),
        dir.display()
    );
}

fn write<T: Copy, const N: usize>(path: &PathBuf, values: &[T], bytes: fn(T) -> [u8; N]) {
    let data: Vec<u8> = values.iter().flat_map(|&v| bytes(v)).collect();
    std::fs::write(path, data).unwrap_or_else(|e| fail(&format!("{}: {e}", path.display())));
}

fn write_rays(path: &PathBuf, rays: &[Ray]) {
    let values: Vec<f64> = rays
        .iter()
        .flat_map(|r| {
            [
                r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z,
            ]
        })
        .collect();
    write(path, &values, f64::to_le_bytes);
}

fn read<const N: usize>(path: &Path) -> Vec<[u8; N]> {
    let data = std::fs::read(path).unwrap_or_else(|e| fail(&format!("{}: {e}", path.display())));
    data.chunks_exact(N)
        .map(|c| c.try_into().expect("N bytes"))
        .collect()
}

fn read_doubles(path: &Path) -> Vec<f64> {
    read::<8>(path)
        .into_iter()
        .map(f64::from_le_bytes)
        .collect()
}

fn read_rays(path: &Path) -> Vec<Ray> {
    read_doubles(path)
        .chunks_exact(6)
        .map(|v| Ray::new(DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5])))
        .collect()
}

fn time(dir: &Path, set: &str, passes: usize, through_tracer: bool) {
    let floats: Vec<f64> = read::<4>(&dir.join("triangles.f32"))
        .into_iter()
        .map(|b| f64::from(f32::from_le_bytes(b)))
        .collect();
    // The same single-precision vertices Embree is given, one vertex per corner.
    let positions: Vec<DVec3> = floats.chunks_exact(3).map(DVec3::from_slice).collect();
    let faces: Vec<[u32; 3]> = (0..positions.len() as u32 / 3)
        .map(|f| [3 * f, 3 * f + 1, 3 * f + 2])
        .collect();
    let mesh = Mesh::new(positions, vec![], faces, vec![]);
    let rays = read_rays(&dir.join(format!("{set}.f64")));
    if through_tracer {
        return time_tracer(mesh, &rays, passes);
    }
    let mut best = f64::INFINITY;
    let (mut hits, mut t_sum) = (0, 0.0);
    let mut tested = TestCounts::default();
    for _ in 0..passes.max(1) {
        let start = Instant::now();
        (hits, t_sum) = (0, 0.0);
        tested = TestCounts::default();
        for ray in &rays {
            let roots = mesh.roots(
                ray,
                TriangleMethod::Watertight,
                f64::INFINITY,
                Search::Closest,
                &mut tested,
            );
            if let Some(&t) = roots.as_slice().first() {
                hits += 1;
                t_sum += t;
            }
        }
        best = best.min(start.elapsed().as_secs_f64());
        std::hint::black_box(&mut tested);
    }
    let per_ray = |n: u32| f64::from(n) / rays.len() as f64;
    println!(
        "seconds={best:.6} rays={} hits={hits} t_sum={t_sum:.6} boxes_per_ray={:.2} triangles_per_ray={:.2}",
        rays.len(),
        per_ray(tested.boxes),
        per_ray(tested.primitives),
    );
}

/// `time --tracer`: the tracer's closest-hit search in a scene whose one
/// object is `mesh`, as the renderer runs it for each ray.
fn time_tracer(mesh: Mesh, rays: &[Ray], passes: usize) {
    let mut scene = gaspra_scene();
    let rock = (scene.objects.iter())
        .find(|o| matches!(o.shape, Shape::Mesh(_)))
        .map_or(0, |o| o.material);
    scene.objects = vec![Object {
        name: "gaspra".to_owned(),
        shape: Shape::Mesh(Arc::new(mesh)),
        transform: None,
        material: rock,
    }];
    let tracer = Tracer::new(&scene);
    time_closest_hits(&tracer, rays, passes);
}

/// Times `Tracer::closest_hit` on every ray, `passes` times, and prints the
/// fastest pass's line.
fn time_closest_hits(tracer: &Tracer, rays: &[Ray], passes: usize) {
    let mut best = f64::INFINITY;
    let (mut hits, mut t_sum) = (0, 0.0);
    for _ in 0..passes.max(1) {
        let start = Instant::now();
        (hits, t_sum) = (0, 0.0);
        for ray in rays {
            if let Some((_, t, _)) = tracer.closest_hit(ray, 0.0, f64::INFINITY, &mut NoRecorder) {
                hits += 1;
                t_sum += t;
            }
        }
        best = best.min(start.elapsed().as_secs_f64());
    }
    println!(
        "seconds={best:.6} rays={} hits={hits} t_sum={t_sum:.6}",
        rays.len()
    );
}

/// The scene of `raytree generate spheres n` (seed 1) with its spheres alone,
/// under the hierarchy.
fn spheres_scene(n: usize) -> raytree::scene::Scene {
    let text = raytree::scene::generate::random_spheres(n, 1);
    let mut scene = raytree::scene::loader::parse(&text, "random.json")
        .unwrap_or_else(|e| fail(&format!("{e:#}")));
    scene
        .objects
        .retain(|o| matches!(o.shape, Shape::Sphere(_)));
    if scene.objects.len() != n || scene.objects.iter().any(|o| o.transform.is_some()) {
        fail("the generated scene's spheres are not n untransformed spheres");
    }
    scene.settings.accel = Accel::Bvh;
    scene
}

fn export_spheres(dir: &Path, n: usize, width: usize, height: usize) {
    std::fs::create_dir_all(dir).unwrap_or_else(|e| fail(&format!("{}: {e}", dir.display())));
    let mut scene = spheres_scene(n);
    scene.settings.width = width as u32;
    scene.settings.height = height as u32;
    let spheres: Vec<f64> = scene
        .objects
        .iter()
        .flat_map(|o| match &o.shape {
            Shape::Sphere(s) => [s.center.x, s.center.y, s.center.z, s.radius],
            _ => unreachable!("spheres only"),
        })
        .collect();
    write(
        &dir.join(format!("spheres-{n}.f64")),
        &spheres,
        f64::to_le_bytes,
    );
    let camera = scene.camera();
    let rays: Vec<Ray> = (0..height as u32)
        .flat_map(|y| (0..width as u32).map(move |x| (x, y)))
        .flat_map(|(x, y)| sample_points(x, y, 1))
        .map(|(sx, sy)| camera.pixel_ray(sx, sy))
        .collect();
    write_rays(&dir.join(format!("spheres-{n}-rays.f64")), &rays);
    eprintln!(
        "wrote {n} spheres and {} primary rays to {}",
        rays.len(),
        dir.display()
    );
}

fn time_spheres(dir: &Path, n: usize, passes: usize) {
    let scene = spheres_scene(n);
    let tracer = Tracer::new(&scene);
    let rays = read_rays(&dir.join(format!("spheres-{n}-rays.f64")));
    time_closest_hits(&tracer, &rays, passes);
}
