//! `raytree inspect`: the terminal inspector, on a scene or a saved trace.

use std::io::IsTerminal;
use std::path::PathBuf;

use anyhow::{Result, bail};
use raytree::inspector::{self, App};
use raytree::tree::document;

use crate::args::{SceneArgs, parse_pixel};

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Start at this pixel (image coordinates) [default: the image's center].
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pixel: Option<(u32, u32)>,
    /// Open a saved trace (raytree trace --json) instead, with its scene if that file is found.
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["scene", "pixel", "Overrides"])]
    trace: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<()> {
    if !std::io::stdout().is_terminal() {
        bail!("raytree inspect needs a terminal (standard output is not one)");
    }
    let app = match &args.trace {
        None => {
            let (scene, source) = args.scene.load()?;
            if let Some((x, y)) = args.pixel {
                let s = &scene.settings;
                if x >= s.width || y >= s.height {
                    bail!(
                        "--pixel {x},{y} is outside the {}×{} image",
                        s.width,
                        s.height
                    );
                }
            }
            App::new(scene, source, args.pixel, true)
        }
        Some(path) => {
            let trace = document::read(path)?;
            let found = document::find_scene(&trace);
            let changed = matches!(found, Some((_, false)));
            let mut app = App::from_trace(trace, found.map(|(scene, _)| scene), true);
            if changed {
                app.message = format!("{} changed since the trace was saved", app.source.file);
            }
            app
        }
    };
    inspector::run(app).map_err(|e| anyhow::anyhow!("terminal error: {e}"))
}
