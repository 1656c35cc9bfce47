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
    /// Open a saved trace (raytree trace --json) instead. Its scene is the SCENE given after it, or else the file the trace names, found beside the trace or from the current folder; a scene that changed since is left out (the trace is shown without its drawing).
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["pixel", "Overrides"])]
    trace: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<()> {
    // Everything is read and checked before the terminal is touched, so a
    // rejection is one line on a terminal left as it was.
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
            let opened = document::open(path, args.scene.scene.as_deref())?;
            let mut app = App::from_trace(opened.trace, opened.scene, true);
            if let Some(note) = opened.note {
                app.message = note;
            }
            app
        }
    };
    if !std::io::stdout().is_terminal() {
        bail!("raytree inspect needs a terminal (standard output is not one)");
    }
    inspector::run(app).map_err(|e| anyhow::anyhow!("terminal error: {e}"))
}
