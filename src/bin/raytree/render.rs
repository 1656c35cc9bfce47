//! `raytree render`: every pixel of a scene, on all cores, to a PNG or PPM file.

use std::collections::TryReserveError;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use raytree::Image;
use raytree::geometry::structures::Structure;
use raytree::io::image;
use raytree::methods::Accel;
use raytree::scene::Scene;
use raytree::trace::progress::Progress;
use raytree::trace::recorder::RayCounter;
use raytree::trace::render;
use raytree::trace::tracer::Tracer;
use raytree::views::numbers::{num, thousands};

use crate::args::{SceneArgs, parse_threads, thread_pool, threads_word};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Output image (.png or .ppm) [default: the scene's name with .png, in the current folder].
    #[arg(short, long, value_name = "OUT")]
    pub output: Option<PathBuf>,
    /// Worker threads, 1 to 256 [default: one per core].
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    pub threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(short, long)]
    pub quiet: bool,
    /// Also count the rays cast, by kind, and the intersection tests they made, and
    /// print them with rays per second on standard output (about 1% slower).
    #[arg(long, conflicts_with_all = ["quiet", "aov"])]
    stats: bool,
    /// Render a per-pixel quantity instead of the color, as a PNG with its color
    /// bar or key below: local, reflected, refracted, ambient, diffuse, specular,
    /// shadow[=LIGHT], depth, rays[=KIND], tests, normal, t, object,
    /// discriminant[=SPHERE], tir (docs/commands.md says what each shows).
    #[arg(long, value_name = "NAME")]
    pub aov: Option<String>,
    /// With --aov: write the image alone, without the key strip.
    #[arg(long, requires = "aov")]
    pub no_key: bool,
}

/// What a scene lacks that an image needs to show anything but the
/// background or the ambient light: not an error (a teacher may start from
/// an empty scene), but an image with no word would look like a bug.
pub fn missing(scene: &Scene) -> Option<&'static str> {
    match (scene.objects.is_empty(), scene.lights.is_empty()) {
        (true, true) => Some("has no objects and no lights: every pixel is the background"),
        (true, false) => Some("has no objects: every pixel is the background"),
        (false, true) => Some("has no lights: surfaces show the ambient light alone"),
        (false, false) => None,
    }
}

/// `raytree render` without `--aov` (which `main` sends to `aov.rs`): the
/// image, and with `--stats` the counts of its rays and tests.
pub fn run(args: &Args) -> Result<()> {
    // The SPD's preprocessing: reading the file, then building what the rays need.
    let reading = Instant::now();
    let (scene, _) = args.scene.load()?;
    let read_seconds = reading.elapsed().as_secs_f64();
    let path = output::name_or(&args.output, || output::stem_and(args.scene.stem(), ".png"));
    let format = output::image_format(&path)?;
    let pending = output::create(&path, &args.scene.inputs(&scene))?;
    // The clock starts before the threads do: their start-up is part of the time.
    let started = Instant::now();
    let (pool, threads) = thread_pool(args.threads)?;
    let progress = output::progress_bar(
        args.quiet,
        "{spinner} rendering [{bar:40}] {pos}/{len} rows, {elapsed} (eta {eta})",
    );
    let s = &scene.settings;
    let no_memory = |_| anyhow::anyhow!("not enough memory for a {}×{} image", s.width, s.height);
    let on_bar = output::on_bar(&progress);
    let report = Progress::reporting(&on_bar);
    let (image, counted) = if args.stats {
        let (image, counted) =
            render_counting(&pool, &scene, report, read_seconds).map_err(no_memory)?;
        (image, Some(counted))
    } else {
        let image = pool
            .install(|| render::render(&scene, &report))
            .map_err(no_memory)?;
        (image, None)
    };
    let rendering = started.elapsed().as_secs_f64();
    progress.finish_and_clear();
    pending.commit(&image::file::encode(&image, format)?)?;
    if !args.quiet {
        // Each time named by what it covers: the scene's reading, then the
        // rendering (starting the threads, building the hierarchy, tracing);
        // encoding and writing the image are not timed.
        output::note(&format!(
            "wrote {} ({}×{}, {}, max depth {}): {} s reading the scene, {} s building and tracing on {}",
            path.display(),
            s.width,
            s.height,
            s.sampling(),
            s.max_depth,
            seconds(read_seconds),
            seconds(rendering),
            threads_word(threads)
        ))?;
        // After the image is written: a note, not a reason to stop.
        note_missing(args, &scene)?;
    }
    if let Some(counted) = counted {
        // The counts are what --stats asked for: standard output, as strip and
        // forward print their figures; notes stay on standard error.
        output::print(counted.text())?;
    }
    Ok(())
}

/// A note naming what the scene lacks for an image to show anything
/// ([`missing`]), if it lacks it.
fn note_missing(args: &Args, scene: &Scene) -> Result<()> {
    if let Some(what) = missing(scene) {
        output::note(&format!(
            "note: {} {what}",
            args.scene
                .scene
                .as_deref()
                .unwrap_or("the scene".as_ref())
                .display()
        ))?;
    }
    Ok(())
}

/// What `--stats` counted: the rays and their tests, where the time went,
/// and the structure the rays went through, in its own numbers.
struct Counted {
    rays: RayCounter,
    times: Times,
    structure: Accel,
    /// What was built, in the structure's own numbers (a grid's cells per
    /// side, a tree's nodes and leaves); the BVH's are in `raytree memory`.
    built: Option<String>,
}

impl Counted {
    /// What `--stats` prints: [`stats`], and what was built.
    fn text(&self) -> String {
        let mut text = stats(&self.rays, &self.times, self.structure);
        if let Some(built) = &self.built {
            text.push_str(&format!("built: {built}\n"));
        }
        text
    }
}

/// The render with its rays counted on `pool`, the structure built first
/// and timed apart from the tracing; the scene took `read_seconds` to read.
fn render_counting(
    pool: &rayon::ThreadPool,
    scene: &Scene,
    report: Progress,
    read_seconds: f64,
) -> Result<(Image, Counted), TryReserveError> {
    let building = Instant::now();
    let tracer = pool.install(|| Tracer::new(scene));
    let build_seconds = building.elapsed().as_secs_f64();
    let structure = tracer.accelerator().kind();
    // What was built, in the structure's own numbers (a grid's cells per
    // side, a tree's nodes and leaves); the BVH has none to show.
    let built = tracer
        .accelerator()
        .structure()
        .and_then(Structure::describe);
    let tracing = Instant::now();
    let (image, rays) = pool.install(|| render::render_counting_with(&tracer, &report))?;
    let times = Times {
        reading: read_seconds,
        building: build_seconds,
        tracing: tracing.elapsed().as_secs_f64(),
    };
    let counted = Counted {
        rays,
        times,
        structure,
        built,
    };
    Ok((image, counted))
}

/// Where a counted render's time went, in seconds, split as the SPD asks:
/// preprocessing (reading the scene, building the hierarchy) and tracing.
struct Times {
    reading: f64,
    building: f64,
    tracing: f64,
}

/// What `--stats` prints on standard output: the rays by kind (with the
/// primary rays that hit something, the SPD's "eye hit rays"), the
/// intersection tests they made (the cost a hierarchy saves), the speed of
/// the tracing, and the time split into preprocessing and tracing.
fn stats(r: &RayCounter, t: &Times, structure: Accel) -> String {
    let rays = r.total().max(1);
    let per_ray = |n: u64| num(n as f64 / rays as f64);
    format!(
        "{} rays: {} primary ({} hit), {} shadow, {} reflected, {} refracted; {} M rays/s\n\
         {} tests: {} {}, {} primitives; {} per ray{}, {}\n\
         time: {} s preprocessing ({} s reading, {} s building), {} s tracing\n",
        thousands(r.total()),
        thousands(r.primary),
        thousands(r.primary_hits),
        thousands(r.shadow),
        thousands(r.reflected),
        thousands(r.refracted),
        num(r.total() as f64 / t.tracing / 1e6),
        thousands(r.tests()),
        thousands(r.boxes),
        structure.step_word(r.boxes != 1),
        thousands(r.primitives),
        per_ray(r.tests()),
        if r.boxes == 0 {
            String::new()
        } else {
            format!(
                " ({} {} and {} primitives)",
                per_ray(r.boxes),
                structure.step_word(true),
                per_ray(r.primitives)
            )
        },
        match structure {
            Accel::None if r.boxes > 0 => {
                "testing every object (--accel none), the boxes those of the meshes' own hierarchies"
            }
            Accel::None => "testing every object (--accel none)",
            Accel::Bvh => "through a bounding volume hierarchy (--accel bvh)",
            Accel::Grid => "through a uniform grid (--accel grid)",
            Accel::Octree => "through an octree (--accel octree)",
            Accel::Bsp => "through a k-d tree (--accel bsp)",
            Accel::Auto => unreachable!("a built structure is never auto"),
        },
        seconds(t.reading + t.building),
        seconds(t.reading),
        seconds(t.building),
        seconds(t.tracing),
    )
}

/// Seconds to the millisecond.
fn seconds(s: f64) -> String {
    format!("{s:.3}")
}
