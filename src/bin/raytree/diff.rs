//! `raytree diff`: how far apart two images are, in 8-bit levels.

use std::path::PathBuf;

use anyhow::Result;
use raytree::io::{image_diff, image_file};

use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// First image.
    a: PathBuf,
    /// Second image, the same size.
    b: PathBuf,
}

pub fn run(args: &Args) -> Result<()> {
    let a = image_file::read_rgb8(&args.a)?;
    let b = image_file::read_rgb8(&args.b)?;
    let d = image_diff::difference(&a, &b)?;
    output::write_stdout(
        format!(
            "mean absolute difference {:.3}/255, largest {}/255, {:.2}% of pixels off by more than 3/255\n",
            d.mean,
            d.max,
            100.0 * d.share_over_3
        )
        .as_bytes(),
    )
}
