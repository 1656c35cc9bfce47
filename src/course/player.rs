//! A lesson's step-through as a player for the book's page: the pixel's ray
//! diagram as SVG, drawn once, each part tagged with the step at which it
//! appears ([`crate::views::diagram::reveal`]), the stops with their
//! sentences and trace lines, and every ray with its numbers. The page's
//! script (`book/player/player.js`) only shows and hides what this made,
//! so the book's player and `raytree lesson N` cannot tell different stories.

use serde::Serialize;

use crate::course::lesson::{Lesson, StepThrough};
use crate::methods::Accel;
use crate::tree::ray_tree::ShadowOutcomeRecord;
use crate::tree::steps::StepKind;
use crate::views::diagram::draw;
use crate::views::diagram::options::{Fit, Options};
use crate::views::diagram::reveal::Reveal;
use crate::views::text;

/// Everything a player shows.
#[derive(Serialize)]
pub struct Player {
    /// The lesson's number.
    pub lesson: u32,
    /// The step-through's title.
    pub title: String,
    /// The pixel followed.
    pub pixel: [u32; 2],
    /// The scene, as the lesson names it.
    pub scene: String,
    /// How many steps the pixel takes in all.
    pub steps: usize,
    /// The diagram, tagged.
    pub svg: String,
    /// The stops, in order.
    pub stops: Vec<PlayerStop>,
    /// Every ray of the pixel, by tree node.
    pub rays: Vec<PlayerRay>,
}

/// One stop.
#[derive(Serialize)]
pub struct PlayerStop {
    /// The step, 1-based, as `raytree trace --steps` numbers it.
    pub step: usize,
    /// The ray the step belongs to (its tree node).
    pub ray: usize,
    /// The sentence.
    pub say: String,
    /// The step's lines in the trace: the headline, then its arithmetic.
    pub lines: Vec<String>,
}

/// One ray.
#[derive(Serialize)]
pub struct PlayerRay {
    /// Its parent's node, `None` for the primary ray.
    pub parent: Option<usize>,
    /// primary, reflected, refracted.
    pub kind: &'static str,
    /// Its depth, 1 for the primary ray.
    pub depth: u32,
    /// The step that spawns it.
    pub spawn: usize,
    /// Its lines in the trace: the spawn, then the closest hit or the miss.
    pub lines: Vec<String>,
    /// How many of `lines` are the spawn's: the rest are not shown before
    /// the step `found`, so the player never tells what a ray meets early.
    pub spawn_lines: usize,
    /// The step that finds its closest hit (or its miss).
    pub found: Option<usize>,
    /// What it hit, if anything.
    pub hit: Option<String>,
    /// Whether the diagram draws it (the script's `[player] depth`): the
    /// list names only what the reader can find in the drawing.
    pub drawn: bool,
    /// Its shadow rays, in the order cast, when the diagram draws them.
    pub shadows: Vec<PlayerShadow>,
}

/// One shadow ray, listed under the ray whose hit casts it.
#[derive(Serialize)]
pub struct PlayerShadow {
    /// The light it goes to.
    pub light: String,
    /// The step that casts it.
    pub step: usize,
    /// What it found, in a word for the list: reaches, dimmed or blocked.
    pub outcome: &'static str,
    /// Its lines in the trace.
    pub lines: Vec<String>,
}

/// The diagram's size: wide enough for its labels in a page's column.
pub const DIAGRAM_SIZE: (u32, u32) = (960, 640);

/// Makes the player of `lesson`, whose step-through is `walk`.
pub fn make(lesson: &Lesson, walk: &StepThrough) -> Result<Player, String> {
    let sample = lesson.script.sample;
    let trace = &walk.trace;
    let options = Options {
        width: DIAGRAM_SIZE.0,
        height: DIAGRAM_SIZE.1,
        sample,
        svg: true,
        // The boxes or cells a structure's search visits appear step by step
        // with the rays (lesson 12 walks a grid).
        boxes: trace.structure != Accel::None,
        depth: lesson.script.player.depth,
        ticks: lesson.script.player.ticks,
        shadows: !lesson.script.player.no_shadows,
        fit: if lesson.script.player.whole_tree {
            Fit::Tree
        } else {
            Fit::Hits
        },
        ..Options::default()
    };
    let figure = draw::draw(trace, &lesson.scene, &options).map_err(|e| {
        format!(
            "{}: the player's diagram: {e}",
            lesson.script.path.display()
        )
    })?;
    let svg = figure
        .svg()
        .ok_or("the diagram was drawn without its SVG")?;
    let steps = trace.steps(sample);
    let lines = |k: usize| {
        let (head, rest) = text::describe(trace, sample, &steps[k]);
        std::iter::once(head).chain(rest).collect::<Vec<_>>()
    };
    let stops = walk
        .stops
        .iter()
        .map(|s| PlayerStop {
            step: s.step,
            ray: steps[s.step - 1].node,
            say: s.say.clone(),
            lines: lines(s.step - 1),
        })
        .collect();
    let tree = &trace.samples[sample].tree;
    let reveal = Reveal::of(trace, sample);
    let step_of = |node: usize, kinds: &[StepKind]| {
        steps
            .iter()
            .position(|s| s.node == node && kinds.contains(&s.kind))
    };
    let rays = tree
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let spawn_step = step_of(i, &[StepKind::Spawn]);
            let spawn = spawn_step.map(lines);
            let end = step_of(i, &[StepKind::Hit, StepKind::Miss]);
            let drawn = lesson.script.player.depth.is_none_or(|d| n.depth <= d);
            let shadows = n
                .shadow_rays
                .iter()
                .enumerate()
                .filter(|_| drawn && !lesson.script.player.no_shadows)
                // Only what the diagram draws: a light behind the surface
                // casts no ray, and one wholly outside the frame is not seen.
                .filter(|&(k, _)| svg.contains(&reveal.shadow(i, k)))
                .filter_map(|(k, s)| {
                    let step = step_of(i, &[StepKind::Shadow(k)])?;
                    Some(PlayerShadow {
                        outcome: match s.outcome {
                            ShadowOutcomeRecord::Reaches { transmitted } if transmitted < 1.0 => {
                                "dimmed"
                            }
                            ShadowOutcomeRecord::Reaches { .. } => "reaches",
                            ShadowOutcomeRecord::Blocked { .. } => "blocked",
                            ShadowOutcomeRecord::FacesAway => "not cast",
                        },
                        light: s.name.clone(),
                        step: step + 1,
                        lines: lines(step),
                    })
                })
                .collect();
            PlayerRay {
                parent: n.parent,
                kind: n.kind.name(),
                depth: n.depth,
                spawn: spawn_step.map_or(steps.len(), |k| k + 1),
                spawn_lines: spawn.as_ref().map_or(0, Vec::len),
                lines: spawn
                    .into_iter()
                    .flatten()
                    .chain(end.into_iter().flat_map(lines))
                    .collect(),
                found: end.map(|k| k + 1),
                hit: n.hit.as_ref().map(|h| h.name.clone()),
                drawn,
                shadows,
            }
        })
        .collect();
    let [x, y] = lesson.script.pixel;
    Ok(Player {
        lesson: lesson.entry.number,
        title: lesson.script.title.clone().unwrap_or_default(),
        pixel: [x, y],
        scene: lesson.script.scene.display().to_string(),
        steps: steps.len(),
        svg,
        stops,
        rays,
    })
}

/// The player as the script file a chapter loads: it files the data under
/// the lesson's number for `player.js`, which runs after the page.
pub fn script(player: &Player) -> Result<String, String> {
    let json = serde_json::to_string(player).map_err(|e| e.to_string())?;
    Ok(format!(
        "// Made by raytree at book build (src/course/player.rs): the player of lesson {}.\n(window.raytreePlayers = window.raytreePlayers || {{}})[\"{}\"] = {json};\n",
        player.lesson, player.lesson
    ))
}
