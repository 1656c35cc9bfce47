//! `raytree lobe`: Phong's highlight, (R·V)^shininess against the angle
//! between the mirror direction and the eye, for a few exponents.

use std::path::PathBuf;

use anyhow::{Context, Result};
use raytree::views::lobe;

use crate::args::{parse_size, usage};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// The exponents drawn, the first emphasized (a lesson's own, then others to compare).
    #[arg(long, value_name = "N,N,…", value_delimiter = ',', default_value = "40,5,320", value_parser = parse_shininess)]
    shininess: Vec<f64>,
    /// Output figure (.png).
    #[arg(short, long, value_name = "OUT.png", default_value = "lobe.png")]
    output: PathBuf,
    /// Figure size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1000x640", value_parser = parse_size)]
    size: (u32, u32),
}

/// A shininess: a positive, finite number.
fn parse_shininess(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(n) if n.is_finite() && n > 0.0 => Ok(n),
        _ => Err(format!("'{s}' is not a shininess (a number above 0)")),
    }
}

pub fn run(args: &Args) -> Result<()> {
    if args.shininess.len() > 3 {
        return Err(usage(
            "--shininess: at most three exponents: more curves than that cannot be told apart",
        ));
    }
    output::require_png(&args.output, "a lobe figure")?;
    let pending = output::create(&args.output, &[])?;
    let figure = lobe::draw(&args.shininess, args.size.0, args.size.1)
        .context("the figure size is too small")?;
    pending.commit(&figure.png())?;
    output::print(lobe::text(&args.shininess))?;
    output::note(&format!("wrote {}", args.output.display()))?;
    Ok(())
}
