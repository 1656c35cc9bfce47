//! A guided step-through: a teacher's script of stops along one pixel's steps,
//! each with a sentence that quotes the trace's own numbers by name
//! (`{theta1}`, `{critical}`), so the narrative can never disagree with the
//! code. A stop may quote only what the algorithm knows by its step. The inspector plays it (`raytree inspect --script FILE`, `raytree
//! lesson N`) and the book prints it.
//!
//! A script is a small TOML file:
//!
//! ```toml
//! title = "Total internal reflection"
//! scene = "../../scenes/whitted.json"   # relative to the script
//! pixel = [416, 209]
//!
//! [player]                              # optional: what the book's player draws
//! depth = 1                             # rays to this depth only
//! ticks = true                          # whole steps of t marked
//! no_shadows = true
//! whole_tree = true                     # frame the eye too, not just the hits
//!
//! [[stop]]
//! step = 1                              # as `raytree trace --steps` numbers them
//! say = "Pixel (x, y) is column c = {c}, row r = {r}."
//! ```

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;

pub use crate::course::step_values::values;
use crate::course::teacher_file;
use crate::scene::settings::RenderSettings;
use crate::tree::document::TraceDocument;
use crate::tree::record::TraceError;

/// A guided step-through, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Script {
    /// Where it was read from (for messages).
    pub path: PathBuf,
    /// What it shows, for the inspector's title.
    pub title: Option<String>,
    /// The scene, resolved relative to the script's folder.
    pub scene: PathBuf,
    /// The pixel it follows.
    pub pixel: [u32; 2],
    /// The line of the file that gives the pixel (for messages).
    pub pixel_line: usize,
    /// The sample it follows (0-based; written 1-based).
    pub sample: usize,
    /// Its stops, in step order.
    pub stops: Vec<Stop>,
    /// How the book's player draws the pixel's diagram.
    pub player: PlayerView,
}

/// What the book's player draws of the pixel (`[player]` in the script):
/// a lesson about the first hit leaves out the deeper rays and marks that
/// belong to later lessons.
#[derive(Clone, Copy, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlayerView {
    /// Draw rays only to this depth (1: the primary ray).
    pub depth: Option<u32>,
    /// Mark whole steps of t along the rays.
    #[serde(default)]
    pub ticks: bool,
    /// Leave the shadow rays out.
    #[serde(default)]
    pub no_shadows: bool,
    /// Frame the whole tree, the eye included, not just the hits.
    #[serde(default)]
    pub whole_tree: bool,
}

/// One stop: a step and what to say there.
#[derive(Clone, Debug, PartialEq)]
pub struct Stop {
    /// The step's number as `raytree trace --steps` prints it (1-based).
    pub step: usize,
    /// The sentence, with `{name}` placeholders.
    pub say: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ScriptFile {
    title: Option<String>,
    scene: String,
    pixel: toml::Spanned<[u32; 2]>,
    sample: Option<usize>,
    stop: Vec<StopFile>,
    #[serde(default)]
    player: PlayerView,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StopFile {
    step: usize,
    say: String,
}

/// Reads a script. Errors are one line naming the file (and the line, for a
/// syntax error or a bad field).
pub fn load(path: &Path) -> Result<Script, String> {
    let text = teacher_file::read(path, "a script")?;
    parse(path, &text)
}

/// Parses a script's text (`path` names it in messages and anchors the scene).
pub fn parse(path: &Path, text: &str) -> Result<Script, String> {
    let at = path.display();
    let file: ScriptFile = teacher_file::parse(path, text)?;
    if file.stop.is_empty() {
        return Err(format!(
            "{at}: no [[stop]]: a step-through needs at least one"
        ));
    }
    if let Some(s) = file.stop.iter().position(|s| s.step == 0) {
        return Err(format!("{at}: stop {}: steps count from 1", s + 1));
    }
    if file.sample == Some(0) {
        return Err(format!("{at}: sample: samples count from 1"));
    }
    for (i, s) in file.stop.iter().enumerate() {
        if let Some(c) = s.say.chars().find(|c| c.is_control() && *c != '\n') {
            return Err(format!(
                "{at}: stop {}: control character {c:?} in say",
                i + 1
            ));
        }
    }
    let folder = path.parent().unwrap_or(Path::new(""));
    Ok(Script {
        path: path.to_owned(),
        title: file.title,
        scene: folder.join(&file.scene),
        pixel: *file.pixel.get_ref(),
        pixel_line: teacher_file::line_of(text, file.pixel.span().start),
        sample: file.sample.map_or(0, |s| s - 1),
        player: file.player,
        stops: file
            .stop
            .into_iter()
            .map(|s| Stop {
                step: s.step,
                say: s.say,
            })
            .collect(),
    })
}

impl Script {
    /// Checks that the script's pixel is in its scene's image (`settings`'),
    /// before anything is traced: `raytree lesson` and `raytree inspect
    /// --script` refuse it alike, naming the file and the line.
    pub fn fits(&self, settings: &RenderSettings) -> Result<(), String> {
        let [x, y] = self.pixel;
        if x < settings.width && y < settings.height {
            return Ok(());
        }
        let outside = TraceError::PixelOutside {
            x,
            y,
            width: settings.width,
            height: settings.height,
        };
        Err(format!(
            "{}: line {}: {outside}",
            self.path.display(),
            self.pixel_line
        ))
    }
}

/// One stop made concrete against a trace: the step's index into
/// [`TraceDocument::steps`] and the sentence with its numbers filled in.
#[derive(Clone, Debug, PartialEq)]
pub struct Narration {
    /// 0-based index of the step.
    pub step: usize,
    /// The sentence.
    pub text: String,
}

/// Fills every stop's placeholders from `trace` (traced at the script's pixel).
/// A stop past the last step (named before any order), stops that do not go
/// forward, or a placeholder the step has no number for, is an error naming
/// the stop and what the step does have.
pub fn narrate(script: &Script, trace: &TraceDocument) -> Result<Vec<Narration>, String> {
    let at = script.path.display();
    if script.sample >= trace.samples.len() {
        return Err(format!(
            "{at}: sample {} but the pixel has {} sample(s)",
            script.sample + 1,
            trace.samples.len()
        ));
    }
    // Each step's range first: a step past the end, written before the
    // others, is the problem, not their order.
    let steps = trace.steps(script.sample).len();
    if let Some(i) = script.stops.iter().position(|s| s.step > steps) {
        return Err(format!(
            "{at}: stop {}: step {} is past the pixel's {steps} steps",
            i + 1,
            script.stops[i].step
        ));
    }
    for (i, pair) in script.stops.windows(2).enumerate() {
        if pair[1].step <= pair[0].step {
            return Err(format!(
                "{at}: stop {}: step {} does not come after step {}; stops go forward",
                i + 2,
                pair[1].step,
                pair[0].step
            ));
        }
    }
    (0..script.stops.len())
        .map(|i| {
            let stop = &script.stops[i];
            tell(script, trace, i).map_err(|untold| match untold {
                Untold::PastEnd { steps } => format!(
                    "{at}: stop {}: step {} is past the pixel's {steps} steps",
                    i + 1,
                    stop.step
                ),
                Untold::NoNumber { name, have } => format!(
                    "{at}: stop {} (step {}): no number {{{name}}} here; this step has {}",
                    i + 1,
                    stop.step,
                    have.join(", ")
                ),
            })
        })
        .collect()
}

/// Why a stop cannot be told against a trace: after a what-if in the
/// inspector, the trace may no longer be the one the teacher wrote it for.
#[derive(Clone, Debug, PartialEq)]
pub enum Untold {
    /// The stop's step is past the last of the pixel's `steps`.
    PastEnd {
        /// How many steps the pixel has.
        steps: usize,
    },
    /// The step has no number called `name`; it has `have`.
    NoNumber {
        /// The placeholder the sentence quotes.
        name: String,
        /// The names the step does have.
        have: Vec<String>,
    },
}

/// Stop `i` of `script` told against `trace`, on its own, so one stop that
/// no longer fits a changed trace leaves the others told.
pub fn tell(script: &Script, trace: &TraceDocument, i: usize) -> Result<Narration, Untold> {
    let stop = &script.stops[i];
    let steps = if script.sample < trace.samples.len() {
        trace.steps(script.sample).len()
    } else {
        0
    };
    if stop.step > steps {
        return Err(Untold::PastEnd { steps });
    }
    let names = values(trace, script.sample, stop.step - 1);
    let text = fill(&stop.say, &names).map_err(|name| Untold::NoNumber {
        name,
        have: names.keys().cloned().collect(),
    })?;
    Ok(Narration {
        step: stop.step - 1,
        text,
    })
}

/// Replaces `{name}` with its value (`{{` and `}}` stand for braces); the
/// error is the first unknown name.
fn fill(say: &str, names: &BTreeMap<String, String>) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = say;
    while let Some(i) = rest.find(['{', '}']) {
        out.push_str(&rest[..i]);
        let tail = &rest[i..];
        if tail.starts_with("{{") || tail.starts_with("}}") {
            out.push_str(&tail[..1]);
            rest = &tail[2..];
            continue;
        }
        if tail.starts_with('}') {
            return Err("}".to_owned());
        }
        let end = tail.find('}').ok_or_else(|| tail.to_owned())?;
        let name = &tail[1..end];
        out.push_str(names.get(name).ok_or_else(|| name.to_owned())?);
        rest = &tail[end + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn script(text: &str) -> Result<Script, String> {
        parse(Path::new("lessons/x/steps.toml"), text)
    }

    #[test]
    fn the_scene_is_found_beside_the_script() {
        let s = script("scene = \"../../scenes/whitted.json\"\npixel = [1, 2]\n[[stop]]\nstep = 1\nsay = \"hi\"\n")
            .unwrap();
        assert_eq!(s.scene, Path::new("lessons/x/../../scenes/whitted.json"));
        assert_eq!((s.pixel, s.sample, s.stops.len()), ([1, 2], 0, 1));
    }

    #[test]
    fn bad_scripts_are_one_line_naming_the_problem() {
        let cases = [
            ("scene = 1\n", "lessons/x/steps.toml: line 1:"),
            ("scene = \"a\"\npixel = [1, 2]\nstop = []\n", "no [[stop]]"),
            (
                "scene = \"a\"\npixel = [1, 2]\nzoom = 3\n[[stop]]\nstep = 1\nsay = \"\"\n",
                "line 3: unknown field `zoom`",
            ),
            (
                "scene = \"a\"\npixel = [1, 2]\n[[stop]]\nstep = 0\nsay = \"\"\n",
                "stop 1: steps count from 1",
            ),
        ];
        for (text, want) in cases {
            let e = script(text).unwrap_err();
            assert!(e.contains(want), "{e:?} should contain {want:?}");
            assert!(!e.contains('\n'), "{e:?} is more than one line");
        }
    }

    #[test]
    fn placeholders_fill_and_unknown_ones_are_named() {
        let names: BTreeMap<String, String> = [("t".to_owned(), "2.5".to_owned())].into();
        assert_eq!(fill("t = {t}, {{t}}", &names).unwrap(), "t = 2.5, {t}");
        assert_eq!(fill("{theta}", &names).unwrap_err(), "theta");
        assert_eq!(fill("open {t", &names).unwrap_err(), "{t");
    }
}
