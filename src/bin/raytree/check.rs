//! `raytree check`: a learner's own tracer checked against raytree, ray by
//! ray for one pixel (`--pixel X,Y TRACE.json`), or pixel by pixel for a
//! whole image (`--image YOURS.png`). Its exit status is its answer, as
//! `raytree diff`'s: 0 all agree, 1 a divergence, 2 bad input (the learner's
//! file, the scene, the command line).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;
use raytree::course::learner::{check, image};
use raytree::io::image::{diff, file};
use raytree::scene::overrides::Overrides;
use raytree::trace::progress::Progress;
use raytree::trace::render;
use raytree::views::difference::{self, Side};

use crate::args::{SceneArgs, parse_pixel, usage};
use crate::output;

// A check traces what a learner's tracer traces, one ray through each pixel's
// center: --spp and --aa (of the shared settings) would change nothing, so
// the help leaves them out and `run` refuses them.
#[derive(clap::Args)]
#[command(mut_arg("spp", |a| a.hide(true)), mut_arg("aa", |a| a.hide(true)))]
pub struct Args {
    /// The scene the learner's tracer rendered (JSON, see scenes/README.md, or NFF). The settings flags below change it as render's do; with --image, the image sets the width and height.
    scene: PathBuf,
    /// The pixel the learner traced, in image coordinates: x to the right, y down from the top-left.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel, allow_hyphen_values = true, requires = "learner")]
    pixel: Option<(u32, u32)>,
    /// The learner's trace of that pixel (docs/learner-trace.md): JSON, at most 8.4 MB.
    learner: Option<PathBuf>,
    /// Instead of one pixel's rays: the learner's whole image (PNG or PPM), compared with raytree's render at its size, one ray through each pixel's center.
    #[arg(long, value_name = "YOURS.png", conflicts_with_all = ["pixel", "learner"])]
    image: Option<PathBuf>,
    /// With --image: also draw yours, raytree's and where they differ side by side (.png).
    // clap does not enforce `requires` on an argument that conflicts with one
    // given (clap-rs/clap#4520): `run` refuses these three without --image.
    #[arg(short, long, value_name = "WHERE.png")]
    output: Option<PathBuf>,
    /// With --image: a pixel is off when a channel differs by more than this many 8-bit levels (1 forgives a color that agrees to many digits but rounds the other way) [default: 1].
    #[arg(long, value_name = "LEVELS")]
    tolerance: Option<u8>,
    /// With --image: how many of the worst pixels to list [default: 10].
    #[arg(long, value_name = "N")]
    worst: Option<usize>,
    /// Print a machine-readable report (format raytree-check-report, or raytree-image-check with --image; docs/learner-trace.md) instead of the text.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    overrides: Overrides,
}

/// Exit status 1: the learner's trace diverges from raytree's.
const DIVERGES: u8 = 1;

/// Checks and prints; the answer is the exit status. An error is bad input:
/// `main` reports it with exit status 2.
pub fn run(args: &Args) -> Result<ExitCode> {
    refuse_bad_flags(args)?;
    let scene_args = SceneArgs {
        scene: Some(args.scene.clone()),
        protocol: None,
        overrides: args.overrides,
    };
    // Neither mode given: name both (clap would name only --pixel).
    if args.pixel.is_none() && args.image.is_none() {
        return Err(usage(
            "give --pixel X,Y and your trace of that pixel (TRACE.json), or --image YOURS.png for a whole image",
        ));
    }
    let (scene, source) = scene_args.load()?;
    if let Some(yours) = &args.image {
        return run_image(args, &scene, yours);
    }
    let (Some(pixel), Some(learner)) = (args.pixel, &args.learner) else {
        return Err(usage(
            "give --pixel X,Y and your trace of that pixel (TRACE.json)",
        ));
    };
    let (x, y) = pixel;
    let (width, height) = (scene.settings.width, scene.settings.height);
    if x >= width || y >= height {
        return Err(usage(format_args!(
            "--pixel {x},{y} is outside the {width}×{height} image (x is 0 to {}, y is 0 to {})",
            width - 1,
            height - 1
        )));
    }
    let report = check::pixel(&scene, source, pixel, learner).map_err(anyhow::Error::msg)?;
    let text = if args.json {
        report.json()
    } else {
        report.text()
    };
    output::print(text)?;
    Ok(ExitCode::from(if report.agrees() { 0 } else { DIVERGES }))
}

/// Refuses the flags that would change nothing (a usage error): the
/// sampling (a check traces one ray through each pixel's center), the size
/// with --image (the image's own), and --image's own flags without it; and a
/// figure's name that is not a .png.
fn refuse_bad_flags(args: &Args) -> Result<()> {
    let o = &args.overrides;
    if o.spp.is_some() || o.aa.is_some() {
        return Err(usage(format_args!(
            "--{}: a check traces one ray through each pixel's center, as a learner's tracer does; leave it out",
            if o.spp.is_some() { "spp" } else { "aa" }
        )));
    }
    if args.image.is_some() {
        if o.width.is_some() || o.height.is_some() {
            return Err(usage(
                "--width and --height: with --image the size is your image's; leave them out",
            ));
        }
        if let Some(path) = &args.output {
            output::require_png(path, "a difference figure")?;
        }
        return Ok(());
    }
    let given = [
        ("-o", args.output.is_some()),
        ("--tolerance", args.tolerance.is_some()),
        ("--worst", args.worst.is_some()),
    ];
    if let Some((flag, _)) = given.iter().find(|(_, given)| *given) {
        return Err(usage(format_args!(
            "{flag} goes with --image only (a check of one pixel's rays draws and lists no pixels)"
        )));
    }
    Ok(())
}

/// `--image`: the whole image, its pixels off and the worst of them, and with
/// `-o` the figure of where.
fn run_image(args: &Args, scene: &raytree::scene::Scene, yours: &Path) -> Result<ExitCode> {
    let pending = match &args.output {
        Some(path) => Some(output::create(
            path,
            &[args.scene.clone(), yours.to_owned()],
        )?),
        None => None,
    };
    let theirs = file::read_rgb8(yours)?;
    let names = (
        args.scene.display().to_string(),
        yours.display().to_string(),
    );
    let mut at_size = scene.clone();
    at_size.settings = image::settings_for(&scene.settings, &names.1, theirs.dimensions())
        .map_err(anyhow::Error::msg)?;
    let ours = render::render(&at_size, &Progress::QUIET)
        .map_err(|_| anyhow::anyhow!("not enough memory to render {}", names.1))?;
    let check = image::check_image(
        (&names.0, &names.1),
        &theirs,
        &ours,
        args.tolerance.unwrap_or(1),
        args.worst.unwrap_or(10),
    );
    if let (Some(pending), Some(path)) = (pending, &args.output) {
        let ours = ::image::RgbImage::from_raw(check.width, check.height, check.ours.clone())
            .expect("a render of the image's size");
        let d = diff::difference(&theirs, &ours)?;
        let figure = difference::draw(
            &Side {
                rgb: theirs.as_raw(),
                name: "yours",
            },
            &Side {
                rgb: &check.ours,
                name: "raytree's",
            },
            check.width,
            check.height,
            &d,
        )
        .ok_or_else(|| anyhow::anyhow!("the images are too large for a figure"))?;
        pending.commit(&figure.png())?;
        output::note(&format!("wrote {}", path.display()))?;
    }
    output::print(if args.json {
        check.json()
    } else {
        check.text()
    })?;
    Ok(ExitCode::from(if check.agrees() { 0 } else { DIVERGES }))
}
