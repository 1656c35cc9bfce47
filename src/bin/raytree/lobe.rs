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
    /// Figure size in pixels, at least 800x520 (smaller, the legend covers the curves and the labels).
    #[arg(long, value_name = "WxH", default_value = "1000x640", value_parser = parse_lobe_size)]
    size: (u32, u32),
}

/// The smallest lobe figure whose title, legend and axis labels all fit: at
/// 700x450 the legend covered the vertical axis's label.
const SMALLEST: (u32, u32) = (800, 520);

fn parse_lobe_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = parse_size(s)?;
    if w < SMALLEST.0 || h < SMALLEST.1 {
        return Err(format!(
            "{w}x{h} is too small for the lobe's title, legend and labels: at least {}x{}",
            SMALLEST.0, SMALLEST.1
        ));
    }
    Ok((w, h))
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
