//! `cargo bench -p raytree-benches --bench scenes`: what the bounding volume hierarchy buys, in
//! figures printed as tables (the README quotes them).
//!
//! 1. Rays per second on the shipped scenes (Whitted, 2,000 spheres, the Gaspra
//!    mesh) at 640×480, 1 sample per pixel.
//! 2. Time per ray as the number of objects grows from 10 to 1,000,000 (random
//!    spheres at constant density, `raytree generate spheres`), with the
//!    hierarchy and without it (up to 10,000 objects: beyond, testing every
//!    object per ray takes too long to wait for).
//! 3. The hierarchy's build time and memory.
//!
//! Times are medians of several runs; only tracing is timed (the scene is parsed
//! and the hierarchy built before). The machines are shared: compare figures from
//! one run, not across runs.

use std::path::Path;
use std::time::Instant;

use raytree::geometry::structures::Structure;
use raytree::methods::Accel;
use raytree::scene::Scene;
use raytree::trace::render::render_counting_with;
use raytree::trace::tracer::Tracer;

/// Median seconds of `runs` renders, and the rays one render casts.
fn time_render(scene: &Scene, runs: usize) -> (f64, u64) {
    let tracer = Tracer::new(scene);
    let mut times = Vec::new();
    let mut rays = 0;
    for _ in 0..runs {
        let start = Instant::now();
        let (_, counted) =
            render_counting_with(&tracer, &raytree::trace::progress::Progress::QUIET)
                .expect("memory");
        times.push(start.elapsed().as_secs_f64());
        rays = counted.total();
    }
    times.sort_by(f64::total_cmp);
    (times[runs / 2], rays)
}

fn main() {
    // `cargo test -p raytree-benches --benches` runs benches once as tests: keep that quick.
    let quick = std::env::args().any(|a| a == "--test" || a == "--quick");
    let threads = rayon::current_num_threads();
    println!("raytree benchmarks on {threads} threads (medians; tracing only)\n");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    shipped_scenes(&root, quick);
    let per_ray = time_per_ray(quick);
    let at = |n: usize| per_ray.iter().find(|p| p.0 == n).map(|p| p.1);
    if let (Some(small), Some(large)) = (at(1_000), at(1_000_000)) {
        println!(
            "time per ray, 1,000,000 ÷ 1,000 objects: {:.2}× (target ≤ 2×)",
            large / small
        );
    }
    gaspra_hierarchy(&root);
}

/// Table 1: rays per second on the shipped scenes.
fn shipped_scenes(root: &Path, quick: bool) {
    println!("Shipped scenes, 640×480, 1 sample per pixel, max depth 8");
    println!(
        "{:<14} {:>8} {:>10} {:>10} {:>12} {:>10}",
        "scene", "objects", "accel", "rays", "median ms", "M rays/s"
    );
    for name in ["whitted.json", "spheres.json", "gaspra.json"] {
        let scene = raytree::scene::loader::load(&root.join(name)).expect("shipped scene");
        let accel = if Tracer::new(&scene).accelerator().bvh().is_some() {
            "bvh"
        } else {
            "none"
        };
        let (seconds, rays) = time_render(&scene, if quick { 1 } else { 7 });
        println!(
            "{:<14} {:>8} {:>10} {:>10} {:>12.1} {:>10.2}",
            name,
            scene.objects.len(),
            accel,
            rays,
            1e3 * seconds,
            rays as f64 / seconds / 1e6
        );
    }
}

/// Table 2: time per ray as random spheres grow in number, with the
/// hierarchy and without; returns (objects, seconds per ray with it).
fn time_per_ray(quick: bool) -> Vec<(usize, f64)> {
    println!("\nTime per ray against object count (random spheres, 320×240, 1 spp)");
    println!(
        "{:>9} {:>10} {:>10} {:>14} {:>14} {:>12} {:>12}",
        "objects", "parse ms", "build ms", "BVH memory", "rays", "ns/ray BVH", "ns/ray none"
    );
    let mut per_ray = Vec::new();
    let counts: &[usize] = if quick {
        &[10, 1000]
    } else {
        &[10, 100, 1_000, 10_000, 100_000, 1_000_000]
    };
    for &n in counts {
        let text = raytree::scene::generate::random_spheres(n, 1);
        let start = Instant::now();
        let mut scene =
            raytree::scene::loader::parse(&text, "random.json").expect("generated scene");
        let parse = start.elapsed().as_secs_f64();
        scene.settings.width = 320;
        scene.settings.height = 240;
        scene.settings.accel = Accel::Bvh;
        let start = Instant::now();
        let tracer = Tracer::new(&scene);
        let build = start.elapsed().as_secs_f64();
        let memory = tracer.accelerator().bvh().map_or(0, |b| b.memory());
        drop(tracer);
        let runs = if quick { 1 } else { 7 };
        let (with, rays) = time_render(&scene, runs);
        let none = if n <= 10_000 {
            scene.settings.accel = Accel::None;
            let (t, _) = time_render(&scene, if n >= 10_000 { 1 } else { runs });
            format!("{:.0}", 1e9 * t / rays as f64)
        } else {
            "(too slow)".to_owned()
        };
        per_ray.push((n, with / rays as f64));
        println!(
            "{:>9} {:>10.1} {:>10.2} {:>11.1} KB {:>14} {:>12.0} {:>12}",
            n,
            1e3 * parse,
            1e3 * build,
            memory as f64 / 1024.0,
            rays,
            1e9 * with / rays as f64,
            none
        );
    }
    per_ray
}

/// Table 3: the Gaspra mesh's own hierarchy, built again and timed.
fn gaspra_hierarchy(root: &Path) {
    let gaspra = raytree::scene::loader::load(&root.join("gaspra.json")).expect("shipped scene");
    for o in &gaspra.objects {
        if let raytree::geometry::object::Shape::Mesh(m) = &o.shape {
            let start = Instant::now();
            let rebuilt = raytree::geometry::mesh::Mesh::new(
                m.positions.clone(),
                m.normals.clone(),
                m.faces.clone(),
                m.face_normals.clone(),
            );
            println!(
                "\nGaspra mesh: {} triangles, hierarchy of {} nodes, {:.1} KB, built in {:.1} ms",
                rebuilt.faces.len(),
                rebuilt.bvh().node_count(),
                rebuilt.bvh().memory() as f64 / 1024.0,
                1e3 * start.elapsed().as_secs_f64()
            );
            break;
        }
    }
}
