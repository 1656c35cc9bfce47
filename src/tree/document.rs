//! The trace document: a pixel's (or one ray's) ray trees with the scene and
//! settings that made them, as written by `raytree trace --json` and documented
//! field by field in `book/src/trace-format.md`.

use std::path::{Path, PathBuf};

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::io::image::rgb8;
use crate::io::input::{self, MAX_INPUT_BYTES};
use crate::scene::Scene;
use crate::scene::settings::RenderSettings;
use crate::scene::source::{BUILT_IN, SceneSource};
use crate::scene::strict::printable;
use crate::tree::arithmetic::{CameraRecord, CameraStage, camera_record};
use crate::tree::ray_tree::RayTree;
use crate::tree::steps::{Step, StepKind, steps};
use crate::tree::trace_check;

/// The value of the `format` field.
pub const FORMAT: &str = "raytree-trace";
/// The value of the `version` field: raised whenever a field changes meaning or goes.
pub const VERSION: u32 = 6;

/// A trace document.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TraceDocument {
    /// Always `"raytree-trace"`.
    pub format: String,
    /// The format's version.
    pub version: u32,
    /// Which scene, by name and content hash.
    pub scene: SceneSource,
    /// The render settings in force.
    pub settings: RenderSettings,
    /// The camera, as the lecture names it.
    pub camera: CameraRecord,
    /// The scene's objects, by index.
    pub objects: Vec<ObjectEntry>,
    /// The scene's lights, by index.
    pub lights: Vec<LightEntry>,
    /// The pixel traced (image coordinates), if a pixel was traced.
    pub pixel: Option<Pixel>,
    /// The ray traced, if one ray was traced instead of a pixel.
    pub ray: Option<GivenRay>,
    /// The pixel's (or ray's) final color, linear RGB, unclamped.
    pub color: DVec3,
    /// The 8-bit sRGB triple the renderer writes for `color`.
    pub rgb8: [u8; 3],
    /// One tree per sample (only the chosen one with `--sample`).
    pub samples: Vec<Sample>,
}

/// An object, as traces name it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectEntry {
    /// Its name.
    pub name: String,
    /// `sphere` or `plane`.
    pub kind: String,
    /// Its material's name.
    pub material: String,
    /// Whether it is placed by a transform.
    pub transformed: bool,
}

/// A light, as traces name it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightEntry {
    /// Its name.
    pub name: String,
    /// Where it is.
    pub position: DVec3,
    /// Its color.
    pub color: DVec3,
}

/// A pixel in image coordinates: x to the right, y down from the top-left.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pixel {
    /// Column.
    pub x: u32,
    /// Row from the top.
    pub y: u32,
}

/// A ray given by hand.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GivenRay {
    /// Origin.
    pub origin: DVec3,
    /// Direction.
    pub direction: DVec3,
}

/// One sample's tree.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sample {
    /// Which sample of the pixel (0 for a single ray).
    pub index: u32,
    /// Where it went through the image, in continuous image coordinates
    /// (pixel centers are integers); `None` for a ray given by hand.
    pub position: Option<[f64; 2]>,
    /// How its primary ray was made from the pixel, in the lecture's terms;
    /// `None` for a ray given by hand.
    pub camera: Option<CameraStage>,
    /// Its color.
    pub color: DVec3,
    /// Its rays.
    pub tree: RayTree,
}

impl TraceDocument {
    /// A document of `samples` traced in `scene`, with the scene's objects and
    /// lights named; the caller sets `pixel` or `ray`.
    pub fn new(scene: &Scene, source: SceneSource, color: DVec3, samples: Vec<Sample>) -> Self {
        let s = scene.settings;
        TraceDocument {
            format: FORMAT.to_owned(),
            version: VERSION,
            scene: source,
            settings: s,
            camera: camera_record(&scene.camera(), &scene.camera),
            objects: scene
                .objects
                .iter()
                .map(|o| ObjectEntry {
                    name: o.name.clone(),
                    kind: o.shape.kind().to_owned(),
                    material: scene.materials[o.material].name.clone(),
                    transformed: o.transform.is_some(),
                })
                .collect(),
            lights: scene
                .lights
                .iter()
                .map(|l| LightEntry {
                    name: l.name.clone(),
                    position: l.position,
                    color: l.color,
                })
                .collect(),
            pixel: None,
            ray: None,
            color,
            rgb8: rgb8(color),
            samples,
        }
    }

    /// The document as pretty JSON, with arrays of numbers (vectors, colors,
    /// roots) kept on one line so a tree reads top to bottom.
    pub fn to_json(&self) -> String {
        let pretty = serde_json::to_string_pretty(self).expect("a trace always serializes");
        let mut out = String::with_capacity(pretty.len());
        let mut lines = pretty.lines().peekable();
        while let Some(line) = lines.next() {
            if line.ends_with('[') {
                // Gather the items up to the closing bracket if they are all numbers.
                let mut items = Vec::new();
                let mut look = lines.clone();
                let mut close = None;
                for next in look.by_ref() {
                    let t = next.trim();
                    if t.starts_with(']') {
                        close = Some(t);
                        break;
                    }
                    let item = t.trim_end_matches(',');
                    if item.parse::<f64>().is_err() {
                        break;
                    }
                    items.push(item);
                }
                if let Some(close) = close {
                    out.push_str(line);
                    out.push_str(&items.join(", "));
                    out.push_str(close);
                    out.push('\n');
                    lines = look;
                    continue;
                }
            }
            out.push_str(line);
            out.push('\n');
        }
        out
    }

    /// [`Self::to_json`], read back and compared: JSON cannot hold an infinity
    /// or a NaN (serde_json writes `null`), so a trace that would not read back
    /// exactly is refused rather than written. The scene limits keep every
    /// number finite; this is the guarantee that the format never holds `null`
    /// for a number.
    pub fn to_checked_json(&self) -> Result<String, String> {
        let text = self.to_json();
        match parse(&text) {
            Ok(back) if back == *self => Ok(text),
            Ok(_) => Err("the trace holds a number JSON cannot write (infinite or NaN)".to_owned()),
            Err(e) => Err(format!("the trace would not read back:{e}")),
        }
    }

    /// The steps of sample `k` in execution order: for a pixel, the camera
    /// stage that made its primary ray, then its tree's.
    pub fn steps(&self, k: usize) -> Vec<Step> {
        let sample = &self.samples[k];
        let camera = sample.camera.is_some().then_some(Step {
            node: 0,
            kind: StepKind::Camera,
        });
        camera.into_iter().chain(steps(&sample.tree)).collect()
    }
}

/// Reads a saved trace document (`raytree trace --json -o FILE`): a regular
/// file of at most [`MAX_INPUT_BYTES`], a document this raytree writes, and
/// one that holds together ([`trace_check::structure`]). Errors are one line
/// naming the file.
pub fn read(path: &Path) -> anyhow::Result<TraceDocument> {
    let file = path.display();
    let text = input::read_text(path, MAX_INPUT_BYTES)
        .map_err(|reason| anyhow::anyhow!("cannot read {file}: {reason}"))?;
    parse(&text).map_err(|e| anyhow::anyhow!("{file}:{e}"))
}

/// Parses and checks a trace document's text. The error is one line: a
/// position (`L:C: …`) for a syntax error, else ` field: …`, to follow the
/// file's name.
pub fn parse(text: &str) -> Result<TraceDocument, String> {
    let trace: TraceDocument = serde_json::from_str(text).map_err(|e| {
        format!(
            "{}:{}: not a raytree trace: {}",
            e.line(),
            e.column(),
            printable(without_position(&e.to_string()))
        )
    })?;
    if trace.format != FORMAT || trace.version != VERSION {
        return Err(format!(
            " a {} version {} document; this raytree reads {FORMAT} version {VERSION}",
            trace.format.escape_debug(),
            trace.version,
        ));
    }
    trace_check::structure(&trace).map_err(|e| format!(" {e}"))?;
    Ok(trace)
}

/// A saved trace with the scene it was made from, when that is at hand.
#[derive(Debug)]
pub struct Opened {
    /// The trace, checked.
    pub trace: TraceDocument,
    /// Its scene with the trace's settings, when found and unchanged (or given).
    pub scene: Option<Scene>,
    /// What a user should know about the scene: not found, changed, or given
    /// in place of the one the trace names.
    pub note: Option<String>,
}

/// Opens a saved trace with its scene: `scene` when given (it must have the
/// objects and lights the trace names), else the file the trace names, looked
/// for beside the trace first, then from the working folder. A scene that
/// changed since the trace was made is left out, with a note: the trace is then
/// shown without the scene's drawing. Errors are one line naming the file.
pub fn open(path: &Path, scene: Option<&Path>) -> anyhow::Result<Opened> {
    let trace = read(path)?;
    let file = path.display();
    let Some(given) = scene else {
        let (scene, note) = find_scene(&trace, path);
        return Ok(Opened { trace, scene, note });
    };
    let (mut scene, source) = crate::scene::source::load(Some(given))?;
    scene.settings = trace.settings;
    trace_check::against_scene(&trace, &scene)
        .map_err(|e| anyhow::anyhow!("{file} does not fit the scene {}: {e}", given.display()))?;
    let note = (source.hash != trace.scene.hash).then(|| {
        format!(
            "{} is not the scene the trace was made from ({}), but has its objects and lights",
            given.display(),
            trace.scene.file
        )
    });
    Ok(Opened {
        trace,
        scene: Some(scene),
        note,
    })
}

/// The scene `trace` (read from `path`) names, if it is found and unchanged,
/// and a note when it is not.
fn find_scene(trace: &TraceDocument, path: &Path) -> (Option<Scene>, Option<String>) {
    let named = &trace.scene.file;
    let file = if named == BUILT_IN {
        None
    } else {
        let beside = path.parent().unwrap_or(Path::new("")).join(named);
        match [beside, PathBuf::from(named)]
            .into_iter()
            .find(|p| p.is_file())
        {
            Some(found) => Some(found),
            None => {
                return (
                    None,
                    Some(format!(
                        "scene {named} not found: showing the saved trace only"
                    )),
                );
            }
        }
    };
    let shown = file
        .as_deref()
        .map_or(named.clone(), |p| p.display().to_string());
    let (mut scene, now) = match crate::scene::source::load(file.as_deref()) {
        Ok(found) => found,
        Err(e) => return (None, Some(format!("{e}: showing the saved trace only"))),
    };
    scene.settings = trace.settings;
    if now.hash != trace.scene.hash {
        let note = format!(
            "{shown} changed since the trace was saved: showing the saved trace only (give the scene after the trace to use it anyway)"
        );
        return (None, Some(note));
    }
    match trace_check::against_scene(trace, &scene) {
        Ok(()) => (Some(scene), None),
        Err(e) => (
            None,
            Some(format!(
                "{shown} does not fit the trace ({e}): showing the saved trace only"
            )),
        ),
    }
}

/// serde_json's message without its " at line L column C".
fn without_position(message: &str) -> &str {
    message
        .rfind(" at line ")
        .map_or(message, |i| &message[..i])
}
