//! `raytree trace`: one pixel's (or one ray's) ray tree as text or JSON.

use std::path::PathBuf;

use anyhow::Result;
use raytree::views::text;

use crate::args::{SceneArgs, TargetArgs, usage};
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
    /// Write to this file (atomically) instead of standard output: a .json name writes the JSON trace (implies --json; with --learner, the learner trace), a .txt name the text.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<()> {
    let json = json_by_name(args)?;
    let (scene, source) = args.scene.load()?;
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

/// The trace a spec's run (`raytree trace ARGS…`, read by the binary's
/// grammar into `args`) prints, recorded here as the command would record it
/// typed in `root`, the repository its paths are relative to.
pub fn document(
    mut args: Args,
    root: &std::path::Path,
) -> Result<raytree::tree::document::TraceDocument> {
    args.scene.scene = args.scene.scene.map(|p| root.join(p));
    let (scene, source) = args.scene.load()?;
    args.target.record(&scene, source)
}

/// Whether the JSON trace is written: asked by --json, or by an output name
/// ending in .json (unless --learner asks for the learner trace). An output
/// name that is neither .json nor .txt (the text), or one at odds with
/// --json, --learner or --steps, is a usage error.
fn json_by_name(args: &Args) -> Result<bool> {
    let Some(path) = &args.output else {
        return Ok(args.json);
    };
    let (json, text) = (
        output::has_extension(path, "json"),
        output::has_extension(path, "txt"),
    );
    let refuse = |why: &str| {
        Err(usage(format_args!(
            "cannot write {}: {why}",
            path.display()
        )))
    };
    if !json && !text {
        return refuse(
            "a trace is written as .json (the JSON trace, or the learner trace with --learner) or .txt (the text)",
        );
    }
    if text && args.learner {
        return refuse("the learner trace is JSON, a .json");
    }
    if text && args.json {
        return refuse("--json writes the JSON trace, a .json");
    }
    if json && args.steps {
        return refuse(
            "--steps numbers the text trace, a .txt; a .json name writes the JSON trace",
        );
    }
    Ok(args.json || json && !args.learner)
}
