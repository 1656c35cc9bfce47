//! `raytree forward`: rays shot from the lights, followed through the scene's
//! mirrors and glass, counted as they reach the eye or are lost; beside the
//! sparse image they form, the backward render of the same image and its rays.

use std::path::PathBuf;

use anyhow::{Context, Result, anyhow, bail};
use raytree::scene::limits;
use raytree::trace::forward;
use raytree::trace::progress::Progress;
use raytree::trace::render;
use raytree::views::forward_figure;

use crate::args::{SceneArgs, parse_threads, thread_pool};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Rays to shoot from the lights, shared equally between them.
    #[arg(long, value_name = "N", default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(1..=10_000_000_000))]
    photons: u64,
    /// Seed of the random directions: the same seed gives the same rays.
    #[arg(long, value_name = "S", default_value_t = 1)]
    seed: u64,
    /// Radius of the eye's pupil in scene units, 1e-9 to 1e9 as a scene's lengths (a point eye is never met)
    /// [default: 1/10 of the image plane's half-width, taken at the look-at distance].
    #[arg(long, value_name = "R", value_parser = parse_pupil)]
    pupil: Option<f64>,
    /// Output figure (.png) [default: the scene's name with -forward.png].
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// Write the sparse image alone, pixel for pixel, without the backward render and the figures.
    #[arg(long)]
    no_key: bool,
    /// Worker threads, 1 to 256 [default: one per core].
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
}

/// `--pupil R`: a length within a scene's limits.
fn parse_pupil(s: &str) -> Result<f64, String> {
    let r = s
        .trim()
        .parse::<f64>()
        .map_err(|_| format!("'{s}' is not a number"))?;
    limits::length(r)
}

pub fn run(args: &Args) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    if scene.lights.is_empty() {
        bail!(
            "{}: the scene has no lights to shoot rays from",
            source.file
        );
    }
    // The default is a length within the scene's limits, as the camera's are.
    let pupil = args.pupil.unwrap_or_else(|| forward::default_pupil(&scene));
    let path = output::name_or(&args.output, || {
        output::stem_and(args.scene.stem(), "-forward.png")
    });
    output::require_png(&path, "a forward trace")?;
    let pending = output::create(&path, &args.scene.inputs(&scene))?;
    let (pool, _) = thread_pool(args.threads)?;
    let progress = output::progress_bar(
        args.quiet,
        "{spinner} shooting [{bar:40}] {pos}/{len} rays, {elapsed} (eta {eta})",
    );
    let traced = pool.install(|| {
        forward::trace(
            &scene,
            args.photons,
            args.seed,
            pupil,
            &Progress::reporting(&output::on_bar(&progress)),
        )
    });
    progress.finish_and_clear();
    let s = &scene.settings;
    let (backward, rays) = pool
        .install(|| render::render_counting(&scene, &Progress::QUIET))
        .map_err(|_| anyhow!("not enough memory for a {}×{} image", s.width, s.height))?;
    let summary = forward_figure::report(&traced, &rays, args.seed, pupil, (s.width, s.height));
    if !args.quiet {
        output::print(summary)?;
    }
    let figure = if args.no_key {
        forward_figure::bare(&traced, s.width, s.height).context("image too large")?
    } else {
        let title = forward_figure::title(&source.file, (s.width, s.height), args.seed, pupil);
        forward_figure::draw(&traced, &backward, &rays, &title)
            .context("the figure is too large to draw")?
    };
    pending.commit(&figure.png())?;
    if !args.quiet {
        output::note(&format!("wrote {}", path.display()))?;
    }
    Ok(())
}
