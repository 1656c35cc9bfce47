//! `raytree render --aov NAME`: a per-pixel quantity instead of the color, as
//! a PNG with its key below (or alone with `--no-key`).

use std::time::Instant;

use anyhow::{Result, anyhow};
use raytree::trace::aov::Aov;
use raytree::trace::aov_render;
use raytree::trace::progress::Progress;
use raytree::views::aov_figure;

use crate::args::{thread_pool, threads_word, usage};
use crate::output;
use crate::render::Args;

/// `raytree render --aov NAME`: what `main` runs for `render` with `--aov`.
pub fn run(args: &Args, name: &str) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let aov = Aov::parse(name, &scene).map_err(|e| usage(format_args!("--aov: {e}")))?;
    let label = aov.name(&scene).replace(['=', '/', ' '], "-");
    let path = output::name_or(&args.output, || {
        output::stem_and(args.scene.stem(), &format!("-{label}.png"))
    });
    output::require_png(&path, "a per-pixel quantity")?;
    let pending = output::create(&path, &args.scene.inputs(&scene))?;
    let (pool, threads) = thread_pool(args.threads)?;
    let progress = output::progress_bar(
        args.quiet,
        "{spinner} rendering [{bar:40}] {pos}/{len} rows, {elapsed} (eta {eta})",
    );
    let s = &scene.settings;
    let started = Instant::now();
    let image = pool
        .install(|| {
            aov_render::render_aov(
                &scene,
                aov,
                &Progress::reporting(&output::on_bar(&progress)),
            )
        })
        .map_err(|_| anyhow!("not enough memory for a {}×{} image", s.width, s.height))?;
    progress.finish_and_clear();
    let caption = format!(
        "{} · {}×{} · {} · max depth {}",
        source.file,
        s.width,
        s.height,
        s.sampling(),
        s.max_depth
    );
    let figure = if args.no_key {
        aov_figure::bare(&image)
    } else {
        aov_figure::draw(&image, &caption)
    }
    .ok_or_else(|| anyhow!("cannot draw a {}×{} figure", s.width, s.height))?;
    pending.commit(&figure.png())?;
    if !args.quiet {
        output::note(&format!(
            "wrote {} ({}, {}×{}) in {:.2} s on {}",
            path.display(),
            image.name,
            s.width,
            s.height,
            started.elapsed().as_secs_f64(),
            threads_word(threads)
        ))?;
    }
    Ok(())
}
