//! `raytree diff`: how far apart two images are, in 8-bit levels, and with
//! `-o` a figure of the two side by side with where they differ.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use raytree::io::{image_diff, image_file};
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
}

pub fn run(args: &Args) -> Result<()> {
    let a = image_file::read_rgb8(&args.a)?;
    let b = image_file::read_rgb8(&args.b)?;
    let d = image_diff::difference(&a, &b)?;
    let pending = match &args.output {
        Some(path) => {
            output::require_png(path, "a difference figure")?;
            Some(output::create(path, &[args.a.clone(), args.b.clone()])?)
        }
        None => None,
    };
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
        output::note(&format!("wrote {}", path.display()))?;
    }
    output::print(format!(
        "mean absolute difference {:.3}/255, largest {}/255, {:.2}% of pixels off by more than 3/255\n",
        d.mean,
        d.max,
        100.0 * d.share_over_3
    ))?;
    Ok(())
}
