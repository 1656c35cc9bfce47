//! `raytree trace`: one pixel's (or one ray's) ray tree as text or JSON.

use std::path::PathBuf;

use anyhow::Result;
use raytree::views::text;

use crate::args::{SceneArgs, TargetArgs};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    #[command(flatten)]
    target: TargetArgs,
    /// Print the JSON trace document (book/src/trace-format.md) instead of the text tree.
    #[arg(long)]
    json: bool,
    /// Print the pixel's learner trace instead (docs/learner-trace.md): raytree's own rays reduced to the fields a learner's tracer writes, for `raytree check`.
    #[arg(long, conflicts_with_all = ["json", "steps"])]
    learner: bool,
    /// Number the steps, in the order the algorithm runs them.
    #[arg(long, conflicts_with = "json")]
    steps: bool,
    /// Write to this file (atomically) instead of standard output; a .json name implies --json.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let json = args.json
        || !args.learner
            && args.output.as_ref().is_some_and(|p| {
                p.extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("json"))
            });
    let inputs = args.scene.inputs(&scene);
    let pending = (args.output.as_deref())
        .map(|p| output::create(p, &inputs))
        .transpose()?;
    let trace = args.target.record(&scene, source)?;
    let text = if args.learner {
        let reduced =
            raytree::course::learner::reduce::reduce(&trace).map_err(anyhow::Error::msg)?;
        reduced.to_json()
    } else if json {
        trace.to_checked_json().map_err(anyhow::Error::msg)?
    } else {
        text::format(&trace, args.steps)
    };
    match (pending, &args.output) {
        (Some(file), Some(path)) => {
            file.commit(text.as_bytes())?;
            output::note(&format!("wrote {}", path.display()))?;
            Ok(())
        }
        _ => {
            output::print(text)?;
            Ok(())
        }
    }
}
