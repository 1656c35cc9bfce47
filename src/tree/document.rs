//! The trace document: a pixel's (or one ray's) ray trees with the scene and
//! settings that made them, as written by `raytree trace --json` and documented
//! field by field in `book/src/trace-format.md`.

use std::sync::Arc;

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::io::image::rgb8;
use crate::methods::Accel;
use crate::scene::Scene;
use crate::scene::settings::RenderSettings;
use crate::scene::source::SceneSource;
use crate::tree::arithmetic::{CameraRecord, CameraStage, camera_record};
use crate::tree::ray_tree::RayTree;
use crate::tree::steps::{Step, StepKind, steps};

/// The value of the `format` field.
pub const FORMAT: &str = "raytree-trace";
/// The value of the `version` field: raised whenever a field changes meaning or goes.
pub const VERSION: u32 = 10;

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
    /// The structure the rays went through: `settings.accel` with `auto`
    /// resolved for this scene. It names what a node's `boxes` are.
    pub structure: Accel,
    /// The camera, as the lecture names it.
    pub camera: CameraRecord,
    /// The scene's objects, by index. Shared: the inspector's traces of one
    /// scene hold the same list, made once (a million objects' entries took
    /// a tenth of a second to make at every key).
    pub objects: Arc<[ObjectEntry]>,
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

/// `scene`'s objects as traces name them, by index.
pub fn object_entries(scene: &Scene) -> Arc<[ObjectEntry]> {
    scene
        .objects
        .iter()
        .map(|o| ObjectEntry {
            name: o.name.clone(),
            kind: o.shape.kind().to_owned(),
            material: scene.materials[o.material].name.clone(),
            transformed: o.transform.is_some(),
        })
        .collect()
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
    /// A document of `samples` traced in `scene` through `structure`, with
    /// the scene's objects and lights named; the caller sets `pixel` or `ray`.
    pub fn new(
        scene: &Scene,
        structure: Accel,
        source: SceneSource,
        color: DVec3,
        samples: Vec<Sample>,
    ) -> Self {
        Self::sharing(
            object_entries(scene),
            scene,
            structure,
            source,
            color,
            samples,
        )
    }

    /// [`TraceDocument::new`] with `objects`, the scene's entries made
    /// beforehand by [`object_entries`].
    pub fn sharing(
        objects: Arc<[ObjectEntry]>,
        scene: &Scene,
        structure: Accel,
        source: SceneSource,
        color: DVec3,
        samples: Vec<Sample>,
    ) -> Self {
        debug_assert_eq!(objects.len(), scene.objects.len());
        let s = scene.settings;
        TraceDocument {
            format: FORMAT.to_owned(),
            version: VERSION,
            scene: source,
            settings: s,
            structure,
            camera: camera_record(&scene.camera(), &scene.camera),
            objects,
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
        numbers_on_one_line(&pretty)
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

/// Pretty JSON with every array of numbers (vectors, colors, roots) put on
/// one line, so a tree reads top to bottom: the trace document's layout, and
/// the learner trace's.
pub fn numbers_on_one_line(pretty: &str) -> String {
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
