//! `raytree inspect`: the terminal inspector, on a scene or a saved trace.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use raytree::course::guide;
use raytree::inspector::{self, App};
use raytree::scene::source;
use raytree::tree::reading;

use crate::args::{SceneArgs, parse_pixel, usage};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Start at this pixel (image coordinates) [default: a pixel worth a look: the deepest ray tree nearest the center].
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel, allow_hyphen_values = true)]
    pixel: Option<(u32, u32)>,
    /// Open a saved trace (raytree trace --json) instead. Its scene is the SCENE given after it, or else the file the trace names, found beside the trace or from the current folder; a scene that changed since is left out (the trace is shown without its drawing).
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["pixel", "Overrides"])]
    trace: Option<PathBuf>,
    /// Follow a guided step-through (a lesson's TOML script: its scene, its pixel and its stops; n and p move between stops).
    #[arg(long, value_name = "FILE.toml", conflicts_with_all = ["scene", "pixel", "trace", "Overrides"])]
    script: Option<PathBuf>,
    /// Colors: auto detects 24-bit color (COLORTERM, TERM, known terminals, tmux) and says so when it falls back to 256.
    #[arg(long, value_enum, default_value_t = ColorMode::Auto)]
    color: ColorMode,
}

/// How many colors the terminal draws.
#[derive(Clone, Copy, clap::ValueEnum)]
enum ColorMode {
    /// Ask the environment.
    Auto,
    /// 24-bit color.
    Truecolor,
    /// The 256-color palette.
    #[value(name = "256")]
    Palette,
}

pub fn run(args: &Args) -> Result<()> {
    // Everything is read and checked before the terminal is touched, so a
    // rejection is one line on a terminal left as it was.
    let mut app = match (&args.trace, &args.script) {
        (None, Some(path)) => {
            let script = guide::load(path).map_err(anyhow::Error::msg)?;
            let (scene, source) = source::load(Some(&script.scene))?;
            script.fits(&scene.settings).map_err(anyhow::Error::msg)?;
            let mut app = App::new(
                scene,
                source,
                Some((script.pixel[0], script.pixel[1])),
                true,
            );
            app.follow(script).map_err(anyhow::Error::msg)?;
            app
        }
        (None, None) => {
            let (scene, source) = args
                .scene
                .load()
                .map_err(|e| a_trace_given(args.scene.scene.as_deref(), e))?;
            if let Some((x, y)) = args.pixel {
                let s = &scene.settings;
                if x >= s.width || y >= s.height {
                    return Err(usage(format_args!(
                        "--pixel {x},{y} is outside the {}×{} image",
                        s.width, s.height
                    )));
                }
            }
            App::new(scene, source, args.pixel, true)
        }
        (Some(path), _) => {
            let opened = reading::open(path, args.scene.scene.as_deref())?;
            let mut app = App::from_trace(opened.trace, opened.scene, true);
            if let Some(note) = opened.note {
                app.set_message(note);
            }
            app.set_loaded_from(path.display().to_string());
            app
        }
    };
    let (truecolor, note) = match args.color {
        ColorMode::Auto => inspector::color_support(),
        ColorMode::Truecolor => (true, None),
        ColorMode::Palette => (false, None),
    };
    if let (Some(note), true) = (&note, app.message().is_empty()) {
        app.set_message(note.clone());
    }
    app.set_colors(truecolor, note);
    if !output::stdout_is_terminal() {
        // A script prints as text only as a lesson's: the lesson command
        // has the frame that heads the text.
        let as_text = match &args.script {
            Some(_) => {
                "; to print a script as text, name it steps.toml in a folder NN-topic beside a lesson.toml (title, summary, objectives, minutes: lessons/README.md) and run raytree lesson --lessons DIR N --text"
            }
            None => "",
        };
        bail!("raytree inspect needs a terminal (standard output is not one){as_text}");
    }
    inspector::run(app).map_err(|e| anyhow::anyhow!("terminal error: {e}"))
}

/// `e`, the scene's refusal, unless the file given is a saved trace: then
/// how to open it, which its fields would not tell.
fn a_trace_given(path: Option<&Path>, e: anyhow::Error) -> anyhow::Error {
    // Only the start of a regular file: a device or a fifo may never end.
    let start = |p: &Path| -> Option<String> {
        use std::io::Read;
        let file = std::fs::File::open(p).ok()?;
        if !file.metadata().ok()?.is_file() {
            return None;
        }
        let mut bytes = Vec::new();
        file.take(4096).read_to_end(&mut bytes).ok()?;
        Some(String::from_utf8_lossy(&bytes).into_owned())
    };
    match path {
        Some(p) if start(p).is_some_and(|t| reading::starts_a_trace(&t)) => {
            let p = p.display();
            usage(format_args!(
                "{p} is a trace: open it with raytree inspect --trace {p}"
            ))
        }
        _ => e,
    }
}
