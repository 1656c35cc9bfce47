//! `raytree strip`: one frame per value of a setting or a scene field, side by
//! side, each with the share of pixels that changed from the frame before.

use std::path::PathBuf;

use anyhow::{Context, Result, anyhow, bail};
use raytree::io::{image, image_diff};
use raytree::scene::loader;
use raytree::scene::vary::{self, Variation};
use raytree::trace::progress::Progress;
use raytree::trace::render;
use raytree::views::filmstrip::{self, Frame};
use raytree::views::numbers::num;

use crate::args::SceneArgs;
use crate::output;
use crate::render::thread_pool;

/// Frames are this wide unless --width or --height is given.
const FRAME_WIDTH: u32 = 320;

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
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
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
    let Variation { path, values } = &args.vary;
    if ["width", "height", "render.width", "render.height"].contains(&path.as_str()) {
        bail!(
            "--vary {path}: the frames of a strip share one size; give --width and --height instead"
        );
    }
    let text = match &args.scene.scene {
        Some(file) => loader::read(file)?,
        None => loader::WHITTED.to_owned(),
    };
    let mut overrides = args.scene.overrides;
    let setting = path.strip_prefix("render.").unwrap_or(path);
    let given = serde_json::to_value(overrides).context("the settings given")?;
    if given.get(setting).is_some() {
        bail!(
            "--vary {path} and --{} both set {setting}: give one",
            setting.replace('_', "-")
        );
    }
    // Frames keep the scene's shape: one side given, the other follows.
    let s = &base.settings;
    let aspect = f64::from(s.height) / f64::from(s.width);
    let side = |v: f64| v.round().max(1.0) as u32;
    match (overrides.width, overrides.height) {
        (None, None) => {
            overrides.width = Some(FRAME_WIDTH);
            overrides.height = Some(side(f64::from(FRAME_WIDTH) * aspect));
        }
        (Some(w), None) => overrides.height = Some(side(f64::from(w) * aspect)),
        (None, Some(h)) => overrides.width = Some(side(f64::from(h) / aspect)),
        (Some(_), Some(_)) => {}
    }
    let scenes = values
        .iter()
        .map(|&v| vary::scene_with(&text, &source.file, &overrides, path, v))
        .collect::<Result<Vec<_>, String>>()
        .map_err(|e| anyhow!(e))?;
    // lights[0].position[1] → lights-0-position-1
    let field = path
        .split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("-");
    let out = output::name_or(&args.output, || {
        format!("{}-strip-{field}.png", args.scene.stem())
    });
    output::require_png(&out, "a strip")?;
    let pending = output::create(&out, &args.scene.inputs(&base))?;
    let (pool, _) = thread_pool(args.threads)?;
    let progress = output::progress_bar(
        args.quiet,
        "{spinner} rendering frame {pos}/{len} [{bar:40}] {elapsed}",
    );
    progress.set_length(scenes.len() as u64);
    let mut frames: Vec<Frame> = Vec::new();
    let mut previous: Option<::image::RgbImage> = None;
    let (width, height) = (scenes[0].settings.width, scenes[0].settings.height);
    for (scene, &value) in scenes.iter().zip(values) {
        let rendered = pool
            .install(|| render::render(scene, &Progress::QUIET))
            .map_err(|_| anyhow!("not enough memory for a {width}×{height} image"))?;
        let rgb = image::to_rgb8(&rendered);
        let now = ::image::RgbImage::from_raw(width, height, rgb.clone()).context("frame size")?;
        let change = match &previous {
            None => "the first frame".to_owned(),
            Some(before) => {
                let d = image_diff::difference(before, &now)?;
                format!("{:.1}% of pixels changed", 100.0 * d.share_over_3)
            }
        };
        let label = format!("{path} = {}", num(value));
        if !args.quiet {
            let from = if previous.is_some() {
                " (from the frame before, by more than 3/255)"
            } else {
                ""
            };
            output::print(format!("{label}: {change}{from}\n"))?;
        }
        frames.push(Frame { rgb, label, change });
        previous = Some(now);
        progress.inc(1);
    }
    progress.finish_and_clear();
    let s = &scenes[0].settings;
    let title = format!(
        "{}: {path} from {} to {} · {width}×{height} · {}{} · under each frame: the share of pixels that changed from the frame before by more than 3/255 (as raytree diff counts)",
        source.file,
        num(values[0]),
        num(values[values.len() - 1]),
        s.sampling(),
        if path.ends_with("max_depth") {
            String::new()
        } else {
            format!(" · max depth {}", s.max_depth)
        }
    );
    let figure = filmstrip::draw(&frames, width, height, &title)
        .context("the strip is too large to draw")?;
    pending.commit(&figure.png())?;
    if !args.quiet {
        output::note(&format!(
            "wrote {} ({} frames of {width}×{height})",
            out.display(),
            frames.len()
        ))?;
    }
    Ok(())
}
