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

use crate::course::teacher_file;
use crate::scene::settings::RenderSettings;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::ShadowOutcomeRecord;
use crate::tree::record::TraceError;
use crate::tree::steps::{StepKind, visit_tests};
use crate::views::numbers::{color, degrees, num, vec3};
use crate::views::walk;

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
    for (i, pair) in file.stop.windows(2).enumerate() {
        if pair[1].step <= pair[0].step {
            return Err(format!(
                "{at}: stop {}: step {} does not come after step {}; stops go forward",
                i + 2,
                pair[1].step,
                pair[0].step
            ));
        }
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
/// A stop past the last step, or a placeholder the step has no number for, is
/// an error naming the stop and what the step does have.
pub fn narrate(script: &Script, trace: &TraceDocument) -> Result<Vec<Narration>, String> {
    let at = script.path.display();
    if script.sample >= trace.samples.len() {
        return Err(format!(
            "{at}: sample {} but the pixel has {} sample(s)",
            script.sample + 1,
            trace.samples.len()
        ));
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

/// The numbers a stop may quote: those of the step's ray (its kind, depth, hit,
/// angles, local color, sum, the boxes and primitives its search tested), the
/// pixel's camera stage, and the step's own (the object tested; the shadow
/// ray's light, its tests and the recent blocker it tried first).
pub fn values(trace: &TraceDocument, sample: usize, step: usize) -> BTreeMap<String, String> {
    let mut v = BTreeMap::new();
    let mut put = |k: &str, s: String| {
        v.insert(k.to_owned(), s);
    };
    let steps = trace.steps(sample);
    let Some(s) = steps.get(step) else {
        return BTreeMap::new();
    };
    let smp = &trace.samples[sample];
    put("step", (step + 1).to_string());
    put("steps", steps.len().to_string());
    if let Some(cam) = &smp.camera {
        put("x", num(cam.x));
        put("y", num(cam.y));
        put("c", num(cam.c));
        put("r", num(cam.r));
        put("u_c", num(cam.u_c));
        put("v_r", num(cam.v_r));
        put("P", vec3(cam.point));
    }
    if step + 1 == steps.len() {
        put("color", color(smp.color));
    }
    put("N", num(trace.camera.distance));
    put("W", num(trace.camera.half_width));
    put("H", num(trace.camera.half_height));
    let node = &smp.tree.nodes[s.node];
    let kind = node.kind.name();
    put("ray", kind.to_owned());
    put("depth", node.depth.to_string());
    put("origin", vec3(node.origin));
    put("direction", vec3(node.direction));
    put("weight", num(node.weight));
    // Only what the algorithm knows at this step: a stop must not give the
    // answer away before the step that computes it.
    let hit_known = !matches!(
        s.kind,
        StepKind::Camera
            | StepKind::Spawn
            | StepKind::Visit(_)
            | StepKind::Test(_)
            | StepKind::Miss
    );
    let local_known = matches!(
        s.kind,
        StepKind::Local
            | StepKind::Reflect
            | StepKind::Refract
            | StepKind::Combine
            | StepKind::Return
    );
    let angles_known = matches!(
        s.kind,
        StepKind::Refract | StepKind::Combine | StepKind::Return
    );
    if matches!(s.kind, StepKind::Combine | StepKind::Return) {
        put("ray_color", color(node.sum.color));
        put("k_rfl", num(node.sum.k_rfl));
        put("k_rfa", num(node.sum.k_rfa));
    }
    // The search for the closest hit is over once it is chosen (or missed):
    // what it cost is known from then on.
    if hit_known || s.kind == StepKind::Miss {
        put("boxes", node.tested.boxes.to_string());
        put("primitives", node.tested.primitives.to_string());
    }
    if let Some(h) = node.hit.as_ref().filter(|_| hit_known) {
        put("object", h.name.clone());
        put("material", h.material.clone());
        put("t", num(h.t));
        put("point", vec3(h.point));
        put("on_ray", vec3(h.on_ray));
        put("normal", vec3(h.shading_normal));
        put("n1", num(h.n1));
        put("n2", num(h.n2));
        put("n_dot_c", num(h.n_dot_c));
        put("mirror", vec3(h.mirror));
        if let Some(p) = h.object_point {
            put("object_point", vec3(p));
        }
        if let (Some(n), Some(wrong)) = (h.object_normal, h.normal_like_point) {
            put("geometric_normal", vec3(h.normal));
            put("object_normal", vec3(n));
            put("normal_like_point", vec3(wrong));
        }
        if let Some(off) = crate::views::explain::normal_like_point_error(h) {
            put("normal_error", degrees(off));
        }
        if let Some(r) = h.refraction.as_ref().filter(|_| angles_known) {
            put("theta1", degrees(r.theta1));
            put("sin_theta1", num(r.sin_theta1));
            put("sin_theta2", num(r.sin_theta2));
            put("eta", num(r.eta));
            if let Some(t2) = r.theta2 {
                put("theta2", degrees(t2));
            }
            if let Some(c) = r.critical {
                put("critical", degrees(c));
            }
        }
    }
    if let Some(l) = node.local.as_ref().filter(|_| local_known) {
        put("local", color(l.total));
        put("ambient", color(l.ambient));
        put("k_a", num(l.k_a));
        put("k_d", num(l.k_d));
        put("k_s", num(l.k_s));
        put("shininess", num(l.shininess));
        for light in &l.lights {
            if let Some(p) = &light.phong {
                put(&format!("n_dot_l.{}", light.name), num(p.n_dot_l));
                put(&format!("r_dot_v.{}", light.name), num(p.r_dot_v));
            }
            put(&format!("diffuse.{}", light.name), color(light.diffuse));
            put(&format!("specular.{}", light.name), color(light.specular));
        }
    }
    match s.kind {
        StepKind::Visit(k) => {
            let visit = node.boxes[k];
            put("visit", (k + 1).to_string());
            put("visit_min", vec3(visit.min));
            put("visit_max", vec3(visit.max));
            put("tests_before", visit.after_tests.to_string());
            put("visit_tests", visit_tests(node, k).to_string());
            if trace.structure == crate::methods::Accel::Grid
                && let Some(exit) = walk::cell_exit(node, k)
            {
                put("exit_axis", walk::axis_name(exit.axis).to_owned());
                put("exit_t", num(exit.t));
                for (a, wall) in exit.walls.iter().enumerate() {
                    if let Some((at, t)) = wall {
                        put(&format!("wall.{}", walk::axis_name(a)), num(*at));
                        put(&format!("wall_t.{}", walk::axis_name(a)), num(*t));
                    }
                }
            }
        }
        StepKind::Test(k) => {
            let test = &node.tests[k];
            put("tested", test.name.clone());
            if let Some(r) = &test.object_ray {
                put("object_origin", vec3(r.origin));
                put("object_direction", vec3(r.direction));
            }
            if let Some(
                crate::tree::arithmetic::Arithmetic::Quadratic {
                    a,
                    b,
                    c,
                    discriminant,
                    ..
                }
                | crate::tree::arithmetic::Arithmetic::ConeQuadratic {
                    a,
                    b,
                    c,
                    discriminant,
                    ..
                },
            ) = &test.arithmetic
            {
                put("A", num(*a));
                put("B", num(*b));
                put("C", num(*c));
                put("discriminant", num(*discriminant));
            }
            let roots: Vec<String> = test.roots.iter().map(|r| num(r.t)).collect();
            put(
                "roots",
                if roots.is_empty() {
                    "none".to_owned()
                } else {
                    roots.join(", ")
                },
            );
        }
        StepKind::Shadow(k) => {
            let shadow = &node.shadow_rays[k];
            put("light", shadow.name.clone());
            put("shadow_boxes", shadow.tested.boxes.to_string());
            put("shadow_primitives", shadow.tested.primitives.to_string());
            if let Some(r) = &shadow.recent {
                put("recent", r.name.clone());
                let blocks = if r.blocks { "blocks" } else { "does not block" };
                put("recent_blocks", blocks.to_owned());
            }
            let outcome = match &shadow.outcome {
                ShadowOutcomeRecord::Reaches { transmitted } if *transmitted == 1.0 => {
                    "reaches the light".to_owned()
                }
                ShadowOutcomeRecord::Reaches { transmitted } => {
                    put("transmitted", num(*transmitted));
                    format!(
                        "reaches the light through transparent objects, keeping {}",
                        num(*transmitted)
                    )
                }
                ShadowOutcomeRecord::Blocked { name, t, .. } => {
                    put("blocker_t", num(*t));
                    format!("blocked by {name}")
                }
                ShadowOutcomeRecord::FacesAway => {
                    "not cast: the light is behind the surface".to_owned()
                }
            };
            put("outcome", outcome);
        }
        _ => {}
    }
    v
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
                "scene = \"a\"\npixel = [1, 2]\n[[stop]]\nstep = 2\nsay = \"\"\n[[stop]]\nstep = 2\nsay = \"\"\n",
                "stop 2: step 2 does not come after step 2",
            ),
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
