//! `raytree forward`: rays shot from the lights, followed through the scene's
//! mirrors and glass, counted as they reach the eye or are lost; beside the
//! sparse image they form, the backward render of the same image and its rays.

use std::path::PathBuf;

use anyhow::{Context, Result, anyhow, bail};
use glam::DVec3;
use raytree::figure::canvas::Figure;
use raytree::io::image::{rgb8, to_rgb8};
use raytree::trace::forward::{self, Forward};
use raytree::trace::progress::Progress;
use raytree::trace::recorder::RayCounter;
use raytree::trace::render;
use raytree::views::filmstrip::{self, Frame};
use raytree::views::numbers::{num, thousands};

use crate::args::SceneArgs;
use crate::output;
use crate::render::thread_pool;

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
    /// Radius of the eye's pupil in scene units (a point eye is never met)
    /// [default: 1/10 of the image plane's half-width, taken at the look-at distance].
    #[arg(long, value_name = "R")]
    pupil: Option<f64>,
    /// Output figure (.png) [default: the scene's name with -forward.png].
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// Write the sparse image alone, pixel for pixel, without the backward render and the figures.
    #[arg(long)]
    no_key: bool,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
}

pub fn run(args: &Args) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    if scene.lights.is_empty() {
        bail!(
            "{}: the scene has no lights to shoot rays from",
            source.file
        );
    }
    let pupil = args.pupil.unwrap_or_else(|| forward::default_pupil(&scene));
    if !(pupil.is_finite() && pupil > 0.0) {
        bail!("--pupil: must be a number > 0, got {pupil}");
    }
    let path = output::name_or(&args.output, || {
        format!("{}-forward.png", args.scene.stem())
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
    let summary = report(&traced, &rays, args.seed, pupil, (s.width, s.height));
    if !args.quiet {
        output::print(summary)?;
    }
    let sparse = sparse_image(&traced, s.width, s.height, 0);
    let figure = if args.no_key {
        let mut fig = Figure::page(s.width, s.height).context("image too large")?;
        fig.image(0, 0, s.width, &sparse);
        fig
    } else {
        let c = &traced.counts;
        let frames = [
            Frame {
                rgb: sparse_image(&traced, s.width, s.height, 2),
                label: format!("forward: {} rays from the lights", thousands(c.shot)),
                change: format!(
                    "{} of {} reached a pixel ({}%), each shown 5 pixels wide",
                    thousands(c.reached),
                    thousands(c.shot),
                    num(100.0 * c.reached as f64 / c.shot as f64)
                ),
            },
            Frame {
                rgb: to_rgb8(&backward),
                label: format!("backward: {} rays from the eye", thousands(rays.total())),
                change: format!(
                    "every pixel: {} primary, {} shadow, {} reflected, {} refracted",
                    thousands(rays.primary),
                    thousands(rays.shadow),
                    thousands(rays.reflected),
                    thousands(rays.refracted)
                ),
            },
        ];
        let title = format!(
            "{}, {}×{}: light rays in uniform directions, followed through mirrors and glass (seed {}); the eye is a pupil of radius {}",
            source.file,
            s.width,
            s.height,
            args.seed,
            num(pupil)
        );
        filmstrip::draw(&frames, s.width, s.height, &title)
            .context("the figure is too large to draw")?
    };
    pending.commit(&figure.png())?;
    if !args.quiet {
        output::note(&format!("wrote {}", path.display()))?;
    }
    Ok(())
}

/// The figures, a line each; they add up to the rays shot.
fn report(f: &Forward, rays: &RayCounter, seed: u64, pupil: f64, (w, h): (u32, u32)) -> String {
    let c = &f.counts;
    let share = |n: u64| format!("{}%", num(100.0 * n as f64 / c.shot.max(1) as f64));
    let row = |n: u64, what: &str| format!("{:>13}  {what}\n", thousands(n));
    let mut out = format!(
        "forward: {} rays shot from the lights (seed {seed}, pupil radius {})\n",
        thousands(c.shot),
        num(pupil)
    );
    out += &row(
        c.reached,
        &format!("reached a pixel ({})", share(c.reached)),
    );
    out += &row(c.outside_image, "entered the eye from outside the image");
    out += &row(c.left_scene, "left the scene");
    out += &row(c.absorbed, "were absorbed by a surface");
    out += &row(c.max_depth, "were still bouncing at the maximum depth");
    out += &row(c.ended(), "in all");
    out += &format!("{:>13}  segments traced\n", thousands(c.segments));
    out += &format!(
        "backward: {} rays for every pixel of the same {w}×{h} image ({} primary, {} shadow, {} reflected, {} refracted)\n",
        thousands(rays.total()),
        thousands(rays.primary),
        thousands(rays.shadow),
        thousands(rays.reflected),
        thousands(rays.refracted)
    );
    out
}

/// The image the arrivals form: each pixel the sum of the colors that reached
/// it, as 8-bit sRGB on black; with `grow`, each arrival covers the pixels up
/// to `grow` away as well, so a single one shows in a figure.
fn sparse_image(f: &Forward, width: u32, height: u32, grow: i64) -> Vec<u8> {
    let mut sum = vec![DVec3::ZERO; width as usize * height as usize];
    for &(x, y, color) in &f.arrivals {
        for dy in -grow..=grow {
            for dx in -grow..=grow {
                let (px, py) = (i64::from(x) + dx, i64::from(y) + dy);
                if (0..i64::from(width)).contains(&px) && (0..i64::from(height)).contains(&py) {
                    sum[py as usize * width as usize + px as usize] += color;
                }
            }
        }
    }
    sum.iter().flat_map(|&c| rgb8(c)).collect()
}
