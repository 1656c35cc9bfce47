//! A guided step-through's script, as a teacher writes it: a scene, a pixel
//! and stops along the pixel's steps, each with a sentence that quotes the
//! trace's own numbers by name (`{theta1}`, `{critical}`). Read and checked
//! here, before anything is traced; told against a trace in
//! [`crate::course::guide::narrate`].
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

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::course::teacher_file;
use crate::scene::settings::RenderSettings;
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
    pub stops: Vec<ScriptStop>,
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

/// One stop as the script writes it (`[[stop]]`): a step and what to say
/// there, its numbers still placeholders.
#[derive(Clone, Debug, PartialEq)]
pub struct ScriptStop {
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
            .map(|s| ScriptStop {
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
}
