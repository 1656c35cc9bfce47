//! The `raytree` command line.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Mutex;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use clap::{ArgGroup, Args, Parser, Subcommand};
use glam::DVec3;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use raytree::io::image_file;
use raytree::io::output::PendingFile;
use raytree::math::ray::Ray;
use raytree::scene::Scene;
use raytree::scene::loader;
use raytree::trace::render;
use raytree::tree::document::{SceneRef, Trace};

/// A Whitted-style ray tracer that shows its work.
#[derive(Parser)]
#[command(name = "raytree", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene to a PNG or PPM image on all cores.
    Render(RenderArgs),
    /// Trace one pixel (or one ray) and print every ray it spawns, with every number.
    Trace(TraceArgs),
    /// Draw one pixel's (or one ray's) ray tree over the scene as a 2D figure (PNG).
    Diagram(DiagramArgs),
    /// Explore a scene in the terminal: pick a pixel, walk its ray tree step by step.
    Inspect(InspectArgs),
    /// Chart speed against accuracy over a sweep of settings and methods (PNG, and CSV figures).
    Chart(ChartArgs),
    /// Compare two images (PNG or PPM): mean and largest difference in 8-bit levels.
    Diff(DiffArgs),
    /// Write a generated scene file: random spheres, a grid of spheres, or an icosphere mesh.
    Generate(GenerateArgs),
}

#[derive(Args)]
struct DiffArgs {
    /// First image.
    a: PathBuf,
    /// Second image, the same size.
    b: PathBuf,
}

fn run_diff(args: &DiffArgs) -> Result<()> {
    let a = raytree::io::image_file::read_rgb8(&args.a)?;
    let b = raytree::io::image_file::read_rgb8(&args.b)?;
    let d = raytree::io::image_diff::difference(&a, &b)?;
    println!(
        "mean absolute difference {:.3}/255, largest {}/255, {:.2}% of pixels off by more than 3/255",
        d.mean,
        d.max,
        100.0 * d.share_over_3
    );
    Ok(())
}

#[derive(Args)]
struct GenerateArgs {
    #[command(subcommand)]
    what: Generated,
}

#[derive(Subcommand)]
enum Generated {
    /// N random spheres over a floor, at a density that stays the same as N grows.
    Spheres {
        /// How many spheres.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
        count: u64,
        /// Seed of the random placement and materials.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Scene file to write.
        #[arg(short, long, value_name = "OUT.json")]
        output: PathBuf,
    },
    /// A grid of spheres with random materials (scenes/spheres.json is the default).
    Grid {
        /// Spheres across, up and deep.
        #[arg(long, value_name = "XxYxZ", default_value = "20x5x20", value_parser = parse_grid)]
        size: [u32; 3],
        /// Seed of the materials.
        #[arg(long, default_value_t = 2026)]
        seed: u64,
        /// Scene file to write.
        #[arg(short, long, value_name = "OUT.json")]
        output: PathBuf,
    },
    /// A subdivided icosahedron of about N triangles (20·4^k), as an OBJ file beside a scene that uses it.
    Icosphere {
        /// Triangles wanted; the nearest 20·4^k is made.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
        triangles: u64,
        /// Scene file to write; the mesh goes beside it, with .obj.
        #[arg(short, long, value_name = "OUT.json")]
        output: PathBuf,
    },
}

fn parse_grid(s: &str) -> Result<[u32; 3], String> {
    let parts: Vec<Option<u32>> = s.split('x').map(|p| p.parse().ok()).collect();
    match parts[..] {
        [Some(x), Some(y), Some(z)]
            if x > 0
                && y > 0
                && z > 0
                && u64::from(x) * u64::from(y) * u64::from(z) <= 10_000_000 =>
        {
            Ok([x, y, z])
        }
        _ => Err(format!(
            "'{s}' is not a grid size like 20x5x20 (each at least 1, at most 10 million spheres)"
        )),
    }
}

fn run_generate(args: &GenerateArgs) -> Result<()> {
    use raytree::scene::generate;
    let (output, text) = match &args.what {
        Generated::Spheres {
            count,
            seed,
            output,
        } => (output, generate::random_spheres(*count as usize, *seed)),
        Generated::Grid { size, seed, output } => (output, generate::sphere_grid(*size, *seed)),
        Generated::Icosphere { triangles, output } => {
            let levels = generate::icosphere_levels(*triangles);
            let obj = output.with_extension("obj");
            let name = obj
                .file_name()
                .context("the output needs a file name")?
                .to_string_lossy()
                .into_owned();
            let mesh = generate::icosphere_obj(levels);
            create_output(&obj)?.commit(mesh.as_bytes())?;
            eprintln!(
                "wrote {} ({} triangles)",
                obj.display(),
                20u64 << (2 * levels)
            );
            (output, generate::icosphere_scene(&name, 20 << (2 * levels)))
        }
    };
    create_output(output)?.commit(text.as_bytes())?;
    eprintln!("wrote {}", output.display());
    Ok(())
}

#[derive(Args)]
struct ChartArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// Output chart (.png) [default: the scene's name with -chart.png].
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// Also write every raw figure to this CSV file.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Renders per setting; the chart shows the median time.
    #[arg(long, value_name = "N", default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=100))]
    runs: u32,
    /// Chart size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1200x800", value_parser = parse_size)]
    size: (u32, u32),
}

#[derive(Args)]
struct InspectArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// Start at this pixel (image coordinates) [default: the image's center].
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pixel: Option<(u32, u32)>,
    /// Open a saved trace (raytree trace --json) instead, with its scene if that file is found.
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["scene", "pixel", "width", "height", "spp", "max_depth", "cutoff", "sphere", "offset", "weights", "aa", "triangle", "accel"])]
    trace: Option<PathBuf>,
}

/// A scene and the settings that override its `render` block.
#[derive(Args)]
struct SceneArgs {
    /// Scene file (JSON, see scenes/README.md); the built-in Whitted scene if omitted.
    scene: Option<PathBuf>,
    /// Image width in pixels.
    #[arg(long, value_name = "W")]
    width: Option<u32>,
    /// Image height in pixels.
    #[arg(long, value_name = "H")]
    height: Option<u32>,
    /// Samples per pixel, a square number (1, 4, 9, 16, …) for an n×n stratified grid.
    #[arg(long, value_name = "N")]
    spp: Option<u32>,
    /// Deepest ray traced: 1 traces only primary rays (default 8).
    #[arg(long, value_name = "D")]
    max_depth: Option<u32>,
    /// Skip reflected and refracted rays whose weight (product of coefficients) is below this; 0 turns it off.
    #[arg(long, value_name = "W")]
    cutoff: Option<f64>,
    /// Ray–sphere intersection: the lecture's quadratic as written, or the stable form [default: stable].
    #[arg(long, value_enum)]
    sphere: Option<raytree::methods::SphereMethod>,
    /// Where secondary rays start: none (at the hit: acne), epsilon=E (E along the normal), robust [default: robust].
    #[arg(long, value_name = "none|robust|epsilon=E", value_parser = parse_offset)]
    offset: Option<raytree::methods::Offset>,
    /// Reflection/refraction weights of transparent surfaces: constant k_rfl/k_rfa, Schlick, or Fresnel [default: constant].
    #[arg(long, value_enum)]
    weights: Option<raytree::methods::Weights>,
    /// Anti-aliasing: grid (the --spp grid) or adaptive corner subdivision (Whitted 1980), with an optional threshold [default: grid].
    #[arg(long, value_name = "grid|adaptive[=T]", value_parser = parse_aa)]
    aa: Option<raytree::methods::Antialiasing>,
    /// Ray–triangle intersection: Woop et al.'s watertight test, or the textbook Möller–Trumbore [default: watertight].
    #[arg(long, value_enum)]
    triangle: Option<raytree::methods::TriangleMethod>,
    /// Acceleration: none (test every object), bvh (a bounding volume hierarchy), auto (a hierarchy from 16 bounded objects up) [default: auto].
    #[arg(long, value_enum)]
    accel: Option<raytree::methods::Accel>,
}

fn parse_aa(s: &str) -> Result<raytree::methods::Antialiasing, String> {
    use raytree::methods::Antialiasing;
    match s.split_once('=') {
        None if s == "grid" => Ok(Antialiasing::Grid),
        None if s == "adaptive" => Ok(Antialiasing::Adaptive {
            threshold: 0.05,
            levels: 3,
        }),
        Some(("adaptive", t)) => match t.parse::<f64>() {
            Ok(threshold) if threshold.is_finite() && threshold >= 0.0 => {
                Ok(Antialiasing::Adaptive {
                    threshold,
                    levels: 3,
                })
            }
            _ => Err(format!("'{t}' is not a threshold (a number ≥ 0)")),
        },
        _ => Err("expected grid, adaptive or adaptive=T (e.g. adaptive=0.05)".to_owned()),
    }
}

fn parse_offset(s: &str) -> Result<raytree::methods::Offset, String> {
    use raytree::methods::Offset;
    match s {
        "none" => Ok(Offset::None),
        "robust" => Ok(Offset::Robust),
        _ => {
            let e = s
                .strip_prefix("epsilon=")
                .ok_or("expected none, robust or epsilon=E (e.g. epsilon=1e-4)")?;
            let e: f64 = e.parse().map_err(|_| format!("'{e}' is not a number"))?;
            if e.is_finite() && e > 0.0 {
                Ok(Offset::Epsilon(e))
            } else {
                Err(format!("the epsilon must be > 0, got {e}"))
            }
        }
    }
}

impl SceneArgs {
    /// The scene with the command line's settings applied and checked, and
    /// what names it in a trace.
    fn load(&self) -> Result<(Scene, SceneRef)> {
        let (mut scene, source) = match &self.scene {
            Some(path) => {
                let text = loader::read(path)?;
                let name = path.display().to_string();
                (loader::parse(&text, &name)?, SceneRef::new(&name, &text))
            }
            None => (
                loader::whitted(),
                SceneRef::new("whitted.json (built in)", loader::WHITTED),
            ),
        };
        let s = &mut scene.settings;
        s.width = self.width.unwrap_or(s.width);
        s.height = self.height.unwrap_or(s.height);
        s.spp = self.spp.unwrap_or(s.spp);
        s.max_depth = self.max_depth.unwrap_or(s.max_depth);
        s.cutoff = self.cutoff.unwrap_or(s.cutoff);
        s.sphere = self.sphere.unwrap_or(s.sphere);
        s.offset = self.offset.unwrap_or(s.offset);
        s.weights = self.weights.unwrap_or(s.weights);
        s.aa = self.aa.unwrap_or(s.aa);
        s.triangle = self.triangle.unwrap_or(s.triangle);
        s.accel = self.accel.unwrap_or(s.accel);
        if let Err((field, message)) = s.validate() {
            bail!("--{}: {message}", field.replace('_', "-"));
        }
        Ok((scene, source))
    }

    /// The scene's file stem, or "whitted" for the built-in scene.
    fn stem(&self) -> String {
        self.scene.as_ref().and_then(|p| p.file_stem()).map_or_else(
            || "whitted".to_owned(),
            |s| s.to_string_lossy().into_owned(),
        )
    }
}

#[derive(Args)]
struct RenderArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// Output image (.png or .ppm) [default: the scene's name with .png, in the current folder].
    #[arg(short, long, value_name = "OUT")]
    output: Option<PathBuf>,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
    /// Also count the rays cast, by kind, and report rays per second (about 1% slower).
    #[arg(long, conflicts_with = "quiet")]
    stats: bool,
}

/// What to trace: a pixel or a ray.
#[derive(Args)]
#[command(group(ArgGroup::new("target").required(true).args(["pixel", "ray"])))]
struct TargetArgs {
    /// The pixel to trace, in image coordinates: x to the right, y down from the top-left, as in the rendered image.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pixel: Option<(u32, u32)>,
    /// Trace one ray instead of a pixel: its origin and direction in world coordinates.
    #[arg(long, value_name = "OX,OY,OZ:DX,DY,DZ", value_parser = parse_ray, allow_hyphen_values = true)]
    ray: Option<Ray>,
    /// With several samples per pixel, keep only sample K (0-based, row by row from the top-left).
    #[arg(long, value_name = "K", conflicts_with = "ray")]
    sample: Option<u32>,
}

impl TargetArgs {
    fn trace(&self, scene: &Scene, source: SceneRef) -> Result<Trace> {
        Ok(match (self.pixel, self.ray) {
            (Some((x, y)), _) => raytree::tree::record::pixel(scene, source, x, y, self.sample)?,
            (_, Some(ray)) => raytree::tree::record::ray(scene, source, ray)?,
            _ => unreachable!("clap requires --pixel or --ray"),
        })
    }
}

#[derive(Args)]
struct TraceArgs {
    #[command(flatten)]
    scene: SceneArgs,
    #[command(flatten)]
    target: TargetArgs,
    /// Print the JSON trace document (book/src/trace-format.md) instead of the text tree.
    #[arg(long)]
    json: bool,
    /// Number the steps, in the order the algorithm runs them.
    #[arg(long, conflicts_with = "json")]
    steps: bool,
    /// Write to this file (atomically) instead of standard output; a .json name implies --json.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
}

#[derive(Args)]
struct DiagramArgs {
    #[command(flatten)]
    scene: SceneArgs,
    #[command(flatten)]
    target: TargetArgs,
    /// Output PNG [default: the scene's name, "diagram" and the pixel, e.g. whitted-diagram-320-240.png].
    #[arg(short, long, value_name = "FIG.png")]
    output: Option<PathBuf>,
    /// The plane drawn: the plane of incidence at the first hit (auto), or the scene's axes.
    #[arg(long, value_enum, default_value = "auto")]
    view: raytree::views::projection::View,
    /// Figure size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1200x800", value_parser = parse_size)]
    size: (u32, u32),
    /// Draw only the first D levels of rays (1: the primary ray).
    #[arg(long, value_name = "D")]
    depth: Option<u32>,
    /// Leave out the shadow rays.
    #[arg(long)]
    no_shadows: bool,
    /// Which labels to write.
    #[arg(long, value_enum, default_value = "all")]
    labels: raytree::views::diagram::Labels,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or("expected WxH, e.g. 1200x800")?;
    let side = |v: &str| {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (64..=8192).contains(&n))
            .ok_or_else(|| format!("'{v}' is not a size from 64 to 8192 pixels"))
    };
    Ok((side(w)?, side(h)?))
}

fn parse_numbers<const N: usize>(s: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != N {
        return Err(format!(
            "expected {N} comma-separated numbers, got {}",
            parts.len()
        ));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = p
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("'{p}' is not a finite number"))?;
    }
    Ok(out)
}

fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let (x, y) = s.split_once(',').ok_or("expected X,Y, e.g. 320,240")?;
    let coord = |v: &str| {
        v.trim()
            .parse::<u32>()
            .map_err(|_| format!("'{v}' is not a pixel coordinate (a whole number ≥ 0)"))
    };
    Ok((coord(x)?, coord(y)?))
}

fn parse_ray(s: &str) -> Result<Ray, String> {
    let (o, d) = s
        .split_once(':')
        .ok_or("expected OX,OY,OZ:DX,DY,DZ, e.g. 0,1,5:0,0,-1")?;
    let [ox, oy, oz] = parse_numbers::<3>(o)?;
    let [dx, dy, dz] = parse_numbers::<3>(d)?;
    if dx == 0.0 && dy == 0.0 && dz == 0.0 {
        return Err("the direction must not be zero".to_owned());
    }
    Ok(Ray::new(DVec3::new(ox, oy, oz), DVec3::new(dx, dy, dz)))
}

/// Temporary output files not yet renamed into place: removed if the user
/// interrupts, since a signal skips the destructors that would remove them.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn create_output(path: &std::path::Path) -> Result<PendingFile> {
    let file = PendingFile::create(path)?;
    PENDING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(file.temp_path().to_owned());
    Ok(file)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let _ = ctrlc::set_handler(|| {
        raytree::inspector::restore();
        for path in PENDING.lock().unwrap_or_else(|e| e.into_inner()).drain(..) {
            let _ = std::fs::remove_file(path);
        }
        eprintln!("\ninterrupted: no output written");
        std::process::exit(130);
    });
    let result = match cli.command {
        Command::Render(args) => run_render(&args),
        Command::Trace(args) => run_trace(&args),
        Command::Diagram(args) => run_diagram(&args),
        Command::Inspect(args) => run_inspect(&args),
        Command::Chart(args) => run_chart(&args),
        Command::Generate(args) => run_generate(&args),
        Command::Diff(args) => run_diff(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run_trace(args: &TraceArgs) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let json = args.json
        || args.output.as_ref().is_some_and(|p| {
            p.extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("json"))
        });
    let pending = args
        .output
        .as_deref()
        .map(PendingFile::create)
        .transpose()?;
    let trace = args.target.trace(&scene, source)?;
    let text = if json {
        trace.to_json()
    } else {
        raytree::views::text::render(&trace, args.steps)
    };
    match pending {
        Some(file) => file.commit(text.as_bytes()),
        None => write_stdout(text.as_bytes()),
    }
}

fn run_diagram(args: &DiagramArgs) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| match args.target.pixel {
            Some((x, y)) => PathBuf::from(format!("{}-diagram-{x}-{y}.png", args.scene.stem())),
            None => PathBuf::from(format!("{}-diagram-ray.png", args.scene.stem())),
        });
    if image_file::format_of(&output)? != image_file::Format::Png {
        bail!("cannot write {}: a diagram is a .png", output.display());
    }
    let pending = create_output(&output)?;
    let trace = args.target.trace(&scene, source)?;
    let options = raytree::views::diagram::Options {
        width: args.size.0,
        height: args.size.1,
        view: args.view,
        depth: args.depth,
        shadows: !args.no_shadows,
        labels: args.labels,
        sample: 0,
    };
    let figure =
        raytree::views::diagram::draw(&trace, &scene, &options).map_err(anyhow::Error::msg)?;
    pending.commit(&figure.png())
}

fn run_chart(args: &ChartArgs) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{}-chart.png", args.scene.stem())));
    if image_file::format_of(&output)? != image_file::Format::Png {
        bail!("cannot write {}: a chart is a .png", output.display());
    }
    let png = create_output(&output)?;
    let csv = args.csv.as_deref().map(create_output).transpose()?;
    let progress = progress_bar(false);
    progress.set_style(
        ProgressStyle::with_template(
            "{spinner} charting [{bar:40}] {pos}/{len} settings, {elapsed}",
        )
        .expect("valid template")
        .progress_chars("=> "),
    );
    let points = raytree::trace::sweep::measure(&scene, args.runs as usize, &progress);
    progress.finish_and_clear();
    let s = &scene.settings;
    let title = format!(
        "{} at {}×{}, {} runs each",
        source.file, s.width, s.height, args.runs
    );
    let figure = raytree::views::chart::draw(&points, &title, args.size.0, args.size.1)
        .context("the chart size is too small")?;
    png.commit(&figure.png())?;
    if let Some(file) = csv {
        file.commit(raytree::views::chart::csv(&points).as_bytes())?;
    }
    eprintln!(
        "wrote {}{}",
        output.display(),
        args.csv
            .as_ref()
            .map_or(String::new(), |c| format!(" and {}", c.display()))
    );
    Ok(())
}

fn run_inspect(args: &InspectArgs) -> Result<()> {
    use std::io::IsTerminal;
    if !std::io::stdout().is_terminal() {
        bail!("raytree inspect needs a terminal (standard output is not one)");
    }
    let app = match &args.trace {
        None => {
            let (scene, source) = args.scene.load()?;
            if let Some((x, y)) = args.pixel {
                let s = &scene.settings;
                if x >= s.width || y >= s.height {
                    bail!(
                        "--pixel {x},{y} is outside the {}×{} image",
                        s.width,
                        s.height
                    );
                }
            }
            raytree::inspector::App::new(scene, source, args.pixel, true)
        }
        Some(path) => {
            let text = loader::read(path)?;
            let trace: Trace = serde_json::from_str(&text).map_err(|e| {
                anyhow::anyhow!(
                    "{}:{}:{}: not a raytree trace: {}",
                    path.display(),
                    e.line(),
                    e.column(),
                    strip_position(&e.to_string())
                )
            })?;
            if trace.format != raytree::tree::document::FORMAT
                || trace.version != raytree::tree::document::VERSION
            {
                bail!(
                    "{}: a {} version {} document; this raytree reads {} version {}",
                    path.display(),
                    trace.format,
                    trace.version,
                    raytree::tree::document::FORMAT,
                    raytree::tree::document::VERSION
                );
            }
            let scene = scene_of(&trace);
            let mut app = raytree::inspector::App::from_trace(trace, scene.map(|(s, _)| s), true);
            if let Some((_, false)) = scene_of(app.trace.as_ref().expect("just set")) {
                app.message = format!("{} changed since the trace was saved", app.source.file);
            }
            app
        }
    };
    raytree::inspector::run(app).map_err(|e| anyhow::anyhow!("terminal error: {e}"))
}

/// The scene a saved trace names, with its settings, if the file is found; and
/// whether its contents still hash the same.
fn scene_of(trace: &Trace) -> Option<(Scene, bool)> {
    let (mut scene, text) = if trace.scene.file == "whitted.json (built in)" {
        (loader::whitted(), loader::WHITTED.to_owned())
    } else {
        let text = std::fs::read_to_string(&trace.scene.file).ok()?;
        (loader::parse(&text, &trace.scene.file).ok()?, text)
    };
    scene.settings = trace.settings;
    scene.settings.validate().ok()?;
    let same = SceneRef::new(&trace.scene.file, &text).hash == trace.scene.hash;
    Some((scene, same))
}

/// serde_json's message without its " at line L column C".
fn strip_position(message: &str) -> &str {
    message
        .rfind(" at line ")
        .map_or(message, |i| &message[..i])
}

/// Writes to standard output; a closed pipe (`| head`) is not an error.
fn write_stdout(bytes: &[u8]) -> Result<()> {
    match std::io::stdout().lock().write_all(bytes) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(e).context("cannot write to standard output")
        }
        _ => Ok(()),
    }
}

fn run_render(args: &RenderArgs) -> Result<()> {
    let (scene, _) = args.scene.load()?;
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{}.png", args.scene.stem())));
    let format = image_file::format_of(&output)?;
    let pending = create_output(&output)?;
    let threads = match args.threads {
        Some(0) => bail!("--threads: must be at least 1"),
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("cannot start worker threads")?;
    let progress = progress_bar(args.quiet);
    let started = Instant::now();
    let no_memory = |_| {
        anyhow::anyhow!(
            "not enough memory for a {}×{} image",
            scene.settings.width,
            scene.settings.height
        )
    };
    let (image, rays) = if args.stats {
        pool.install(|| render::render_counting(&scene, &progress))
            .map(|(image, rays)| (image, Some(rays)))
            .map_err(no_memory)?
    } else {
        (
            pool.install(|| render::render(&scene, &progress))
                .map_err(no_memory)?,
            None,
        )
    };
    let seconds = started.elapsed().as_secs_f64();
    progress.finish_and_clear();
    pending.commit(&image_file::encode(&image, format)?)?;
    if !args.quiet {
        let s = &scene.settings;
        eprintln!(
            "wrote {} ({}×{}, {} spp, max depth {}) in {seconds:.2} s on {threads} threads",
            output.display(),
            s.width,
            s.height,
            s.spp,
            s.max_depth
        );
    }
    if let Some(r) = rays {
        eprintln!(
            "{} rays: {} primary, {} shadow, {} reflected, {} refracted; {:.1} M rays/s",
            r.total(),
            r.primary,
            r.shadow,
            r.reflected,
            r.refracted,
            r.total() as f64 / seconds / 1e6
        );
    }
    Ok(())
}

/// A bar on stderr, drawn only when stderr is a terminal.
fn progress_bar(quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} rendering [{bar:40}] {pos}/{len} rows, {elapsed} (eta {eta})",
        )
        .expect("valid template")
        .progress_chars("=> "),
    );
    bar
}
