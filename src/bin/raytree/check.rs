//! `raytree check`: a learner's own tracer checked against raytree, ray by
//! ray, for one pixel. Its exit status is its answer, as `raytree diff`'s:
//! 0 every field agrees, 1 a divergence, 2 bad input (the learner's file,
//! the scene, the command line).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use raytree::course::learner::{read, report};
use raytree::scene::overrides::Overrides;

use crate::args::{SceneArgs, parse_pixel};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// The scene the learner's tracer rendered (JSON, see scenes/README.md, or NFF).
    scene: PathBuf,
    /// The pixel the learner traced, in image coordinates: x to the right, y down from the top-left.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pixel: (u32, u32),
    /// The learner's trace of that pixel (docs/learner-trace.md): JSON, at most 8 MiB.
    learner: PathBuf,
    /// Print a machine-readable report (format raytree-check-report, version 1; docs/learner-trace.md) instead of the text.
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
    let scene_args = SceneArgs {
        scene: Some(args.scene.clone()),
        protocol: None,
        overrides: args.overrides,
    };
    let (scene, source) = scene_args.load()?;
    let learner = read::read(&args.learner).map_err(anyhow::Error::msg)?;
    let report = report::check(&scene, source, args.pixel, &learner).map_err(anyhow::Error::msg)?;
    let text = if args.json {
        report.json()
    } else {
        report.text()
    };
    output::print(text)?;
    Ok(ExitCode::from(if report.agrees() { 0 } else { DIVERGES }))
}
