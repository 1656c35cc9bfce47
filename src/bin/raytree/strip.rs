//! `raytree strip`: one frame per value of a setting or a scene field, side by
//! side, each with the share of pixels that changed from the frame before.

use std::path::PathBuf;

use anyhow::{Context, Result};
use raytree::scene::vary::{self, Variation};
use raytree::scene::{loader, nff};
use raytree::trace::frames;
use raytree::views::filmstrip::{self, Frame};

use crate::args::{SceneArgs, parse_threads, thread_pool, usage};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// The field to vary and its values: PATH=A..B (whole numbers A to B) or PATH=V1,V2,… (at most 12).
    /// PATH is a render setting (max_depth, spp, cutoff) or any numeric field of the scene file,
    /// written as in the file: materials.glass.ior, lights[0].position[1], objects[2].sphere.radius.
    #[arg(long, value_name = "PATH=VALUES", value_parser = vary::parse)]
    vary: Variation,
    /// Output figure (.png) [default: the scene's name with -strip- and the field].
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// Worker threads, 1 to 256 [default: one per core].
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
}

pub fn run(args: &Args) -> Result<()> {
    // The scene's own settings, for its shape; the flags are checked here and
    // applied to each frame.
    let (base, source) = raytree::scene::source::load(args.scene.scene.as_deref())?;
    args.scene.settings(&base.settings)?;
    // The scene as JSON, whose fields --vary names: an NFF file read into it.
    let text = match &args.scene.scene {
        Some(file) if nff::is_nff(&source.file) => {
            nff::to_json(&loader::read(file)?, &source.file)?
        }
        Some(file) => loader::read(file)?,
        None => loader::WHITTED.to_owned(),
    };
    let Variation { path, values } = &args.vary;
    // The scene read as it is; what fails now is the variation --vary asks for.
    let scenes = vary::frames(
        &text,
        &source.file,
        &base.settings,
        &args.scene.overrides,
        &args.vary,
    )
    .map_err(usage)?;
    let out = output::name_or(&args.output, || {
        output::stem_and(
            args.scene.stem(),
            &format!("-strip-{}.png", args.vary.file_word()),
        )
    });
    output::require_png(&out, "a strip")?;
    let pending = output::create(&out, &args.scene.inputs(&base))?;
    let (pool, _) = thread_pool(args.threads)?;
    let progress = output::progress_bar(
        args.quiet,
        "{spinner} rendering frame {pos}/{len} [{bar:40}] {elapsed}",
    );
    progress.set_length(scenes.len() as u64);
    let mut strip: Vec<Frame> = Vec::new();
    // Each frame is rendered on the pool, and shown as soon as it is done.
    let mut rendered = frames::render_each(&scenes).zip(values);
    while let Some((frame, &value)) = pool.install(|| rendered.next()) {
        let frame = frame.map_err(anyhow::Error::msg)?;
        let first = frame.changed.is_none();
        let frame = Frame::varied(frame.rgb, path, value, frame.changed);
        if !args.quiet {
            output::print(frame.line(first))?;
        }
        strip.push(frame);
        progress.inc(1);
    }
    progress.finish_and_clear();
    let s = &scenes[0].settings;
    let title = filmstrip::title(&source.file, path, values, s);
    let figure = filmstrip::draw(&strip, s.width, s.height, &title)
        .context("the strip is too large to draw")?;
    pending.commit(&figure.png())?;
    if !args.quiet {
        output::note(&format!(
            "wrote {} ({} frame{} of {}×{})",
            out.display(),
            strip.len(),
            if strip.len() == 1 { "" } else { "s" },
            s.width,
            s.height
        ))?;
    }
    Ok(())
}
