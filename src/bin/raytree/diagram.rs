//! `raytree diagram`: one pixel's (or one ray's) ray tree drawn over the scene.

use std::path::PathBuf;

use anyhow::Result;
use raytree::views::diagram;
use raytree::views::diagram_layout::{Labels, Options};
use raytree::views::projection::View;

use crate::args::{SceneArgs, TargetArgs, parse_size};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    #[command(flatten)]
    target: TargetArgs,
    /// Output PNG [default: the scene's name, "diagram" and the pixel, e.g. whitted-diagram-320-240.png].
    #[arg(short, long, value_name = "FIG.png")]
    output: Option<PathBuf>,
    /// The plane drawn: the plane of incidence at the first hit (auto), or the scene's axes.
    #[arg(long, value_enum, default_value = "auto")]
    view: View,
    /// Figure size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1200x800", value_parser = parse_size)]
    size: (u32, u32),
    /// Draw only the first D levels of rays (1: the primary ray).
    #[arg(long, value_name = "D")]
    depth: Option<u32>,
    /// Leave out the shadow rays.
    #[arg(long)]
    no_shadows: bool,
    /// Which labels to write.
    #[arg(long, value_enum, default_value = "all")]
    labels: Labels,
}

pub fn run(args: &Args) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let path = output::name_or(&args.output, || match args.target.pixel {
        Some((x, y)) => format!("{}-diagram-{x}-{y}.png", args.scene.stem()),
        None => format!("{}-diagram-ray.png", args.scene.stem()),
    });
    output::require_png(&path, "a diagram")?;
    let pending = output::create(&path)?;
    let trace = args.target.record(&scene, source)?;
    let options = Options {
        width: args.size.0,
        height: args.size.1,
        view: args.view,
        depth: args.depth,
        shadows: !args.no_shadows,
        labels: args.labels,
        sample: 0,
    };
    let figure = diagram::draw(&trace, &scene, &options).map_err(anyhow::Error::msg)?;
    pending.commit(&figure.png())
}
