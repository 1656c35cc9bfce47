//! The `raytree` command line.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use clap::{Args, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use raytree::image_file::{self, PendingFile};
use raytree::render;
use raytree::scene::Scene;
use raytree::scene_file;

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
}

impl SceneArgs {
    /// The scene with the command line's settings applied and checked.
    fn load(&self) -> Result<Scene> {
        let mut scene = match &self.scene {
            Some(path) => scene_file::load(path)?,
            None => scene_file::whitted(),
        };
        let s = &mut scene.settings;
        s.width = self.width.unwrap_or(s.width);
        s.height = self.height.unwrap_or(s.height);
        s.spp = self.spp.unwrap_or(s.spp);
        s.max_depth = self.max_depth.unwrap_or(s.max_depth);
        s.cutoff = self.cutoff.unwrap_or(s.cutoff);
        if let Err((field, message)) = s.validate() {
            bail!("--{}: {message}", field.replace('_', "-"));
        }
        Ok(scene)
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
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => run_render(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run_render(args: &RenderArgs) -> Result<()> {
    let scene = args.scene.load()?;
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{}.png", args.scene.stem())));
    let format = image_file::format_of(&output)?;
    let pending = PendingFile::create(&output)?;
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
    let (image, rays) = pool
        .install(|| render::render_counting(&scene, &progress))
        .map_err(|_| {
            anyhow::anyhow!(
                "not enough memory for a {}×{} image",
                scene.settings.width,
                scene.settings.height
            )
        })?;
    let seconds = started.elapsed().as_secs_f64();
    progress.finish_and_clear();
    pending.commit(&image_file::encode(&image, format)?)?;
    if !args.quiet {
        let s = &scene.settings;
        eprintln!(
            "wrote {} ({}×{}, {} spp, max depth {}) in {seconds:.2} s on {threads} threads: {:.2} M rays, {:.1} M rays/s",
            output.display(),
            s.width,
            s.height,
            s.spp,
            s.max_depth,
            rays.total() as f64 / 1e6,
            rays.total() as f64 / seconds / 1e6
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
