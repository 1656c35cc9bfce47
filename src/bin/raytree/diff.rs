//! `raytree diff`: how far apart two images are, in 8-bit levels, and with
//! `-o` a figure of the two side by side with where they differ. Its exit
//! status answers "do they differ?" as cmp(1) and diff(1) do, so a script
//! can ask it: 0 the same (within `--tolerance`), 1 different, 2 trouble.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use raytree::io::image;
use raytree::views::difference::{self, Side};

use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// First image.
    a: PathBuf,
    /// Second image, the same size.
    b: PathBuf,
    /// Also draw A, B and their difference side by side, with a color bar (.png).
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// The largest difference, in 8-bit levels, that still counts as the same: exit status 0 when no channel of any pixel differs by more, 1 when one does, 2 on trouble (an image that cannot be read, images of different sizes, a bad command line, an output that cannot be written).
    #[arg(long, value_name = "LEVELS", default_value_t = 0, value_parser = parse_levels, allow_negative_numbers = true)]
    tolerance: u8,
}

/// Exit status 0: no channel differs by more than the tolerance.
const SAME: u8 = 0;
/// Exit status 1: some channel does.
const DIFFERENT: u8 = 1;
/// Exit status 2: the comparison could not be made or reported.
pub const TROUBLE: u8 = 2;

/// Compares, prints and answers with the exit status: [`SAME`] or
/// [`DIFFERENT`]; an error is [`TROUBLE`] (`main` reports it). A reader
/// that goes away leaves the answer as it is: it is known before printing.
pub fn run(args: &Args) -> Result<ExitCode> {
    if let Some(path) = &args.output {
        output::require_png(path, "a difference figure")?;
    }
    let a = image::file::read_rgb8(&args.a)?;
    let b = image::file::read_rgb8(&args.b)?;
    let d = image::diff::difference(&a, &b)?;
    let pending = (args.output.as_deref())
        .map(|path| output::create(path, &[args.a.clone(), args.b.clone()]))
        .transpose()?;
    if let (Some(pending), Some(path)) = (pending, &args.output) {
        let name = |p: &Path| {
            p.file_name().map_or_else(
                || p.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            )
        };
        let (an, bn) = (name(&args.a), name(&args.b));
        let figure = difference::draw(
            &Side {
                rgb: a.as_raw(),
                name: &an,
            },
            &Side {
                rgb: b.as_raw(),
                name: &bn,
            },
            a.width(),
            a.height(),
            &d,
        )
        .context("the images are too large for a figure")?;
        pending.commit(&figure.png())?;
        unless_gone(output::note(&format!("wrote {}", path.display())))?;
    }
    let answer = if d.max > args.tolerance {
        DIFFERENT
    } else {
        SAME
    };
    // The verdict first, with what it was judged by: "0.00% off" beside
    // exit status 1 must not read as a contradiction.
    let verdict = if answer == SAME {
        format!(
            "same within tolerance {}: largest {}/255",
            args.tolerance, d.max
        )
    } else {
        format!(
            "different: largest {}/255 > tolerance {}",
            d.max, args.tolerance
        )
    };
    unless_gone(output::print(format!(
        "{verdict}; mean absolute difference {:.3}/255, {:.2}% of pixels off by more than 3/255\n",
        d.mean,
        100.0 * d.share_over_3
    )))?;
    Ok(ExitCode::from(answer))
}

/// A tolerance: 0 to 255 8-bit levels.
fn parse_levels(s: &str) -> Result<u8, String> {
    let n: i128 = (s.trim().parse())
        .map_err(|_| format!("'{s}' is not a whole number of 8-bit levels (0 to 255)"))?;
    u8::try_from(n).map_err(|_| format!("must be 0 to 255 8-bit levels, got {n}"))
}

/// A write, where a reader that went away is no failure: the answer stands.
fn unless_gone(written: std::io::Result<()>) -> std::io::Result<()> {
    match written {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}
