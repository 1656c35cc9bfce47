//! A lesson's step-through as a player for the book's page: the pixel's ray
//! diagram as SVG, drawn once, each part tagged with the step at which it
//! appears ([`crate::views::diagram::reveal`]), the stops with their
//! sentences and trace lines, and every ray with its numbers. The page's
//! script (`book/player/player.js`) only shows and hides what this made,
//! so the book's player and `raytree lesson N` cannot tell different stories.

use std::collections::BTreeSet;

use serde::Serialize;

use crate::course::guide::PlayerView;
use crate::course::lesson::{Lesson, StepThrough};
use crate::methods::Accel;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayNode, ShadowOutcomeRecord};
use crate::tree::steps::{Step, StepKind};
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
    let figure =
        draw::draw(trace, &lesson.scene, &diagram_options(lesson, trace)).map_err(|e| {
            format!(
                "{}: the player's diagram: {e}",
                lesson.script.path.display()
            )
        })?;
    let svg = figure
        .svg()
        .ok_or("the diagram was drawn without its SVG")?;
    let shadows_drawn = figure
        .svg_tags()
        .map(|tags| Reveal::of(trace, sample).shadows_drawn(tags))
        .unwrap_or_default();
    let steps = Steps {
        trace,
        sample,
        all: trace.steps(sample),
    };
    let stops = walk
        .stops
        .iter()
        .map(|s| PlayerStop {
            step: s.step,
            ray: steps.all[s.step - 1].node,
            say: s.say.clone(),
            lines: steps.lines(s.step - 1),
        })
        .collect();
    let view = &lesson.script.player;
    let rays = trace.samples[sample]
        .tree
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| ray(&steps, view, i, n, &shadows_drawn))
        .collect();
    let [x, y] = lesson.script.pixel;
    Ok(Player {
        lesson: lesson.entry.number,
        title: lesson.script.title.clone().unwrap_or_default(),
        pixel: [x, y],
        scene: lesson.script.scene.display().to_string(),
        steps: steps.all.len(),
        svg,
        stops,
        rays,
    })
}

/// The diagram as the script's `[player]` asks for it, in SVG.
fn diagram_options(lesson: &Lesson, trace: &TraceDocument) -> Options {
    let view = &lesson.script.player;
    Options {
        width: DIAGRAM_SIZE.0,
        height: DIAGRAM_SIZE.1,
        sample: lesson.script.sample,
        svg: true,
        // The boxes or cells a structure's search visits appear step by step
        // with the rays (lesson 12 walks a grid).
        boxes: trace.structure != Accel::None,
        depth: view.depth,
        ticks: view.ticks,
        shadows: !view.no_shadows,
        fit: if view.whole_tree {
            Fit::Tree
        } else {
            Fit::Hits
        },
        ..Options::default()
    }
}

/// The followed sample's steps, and each one's lines in the trace.
struct Steps<'a> {
    trace: &'a TraceDocument,
    sample: usize,
    all: Vec<Step>,
}

impl Steps<'_> {
    /// Step `k`'s lines (0-based): the headline, then its arithmetic.
    fn lines(&self, k: usize) -> Vec<String> {
        let (head, rest) = text::describe(self.trace, self.sample, &self.all[k]);
        std::iter::once(head).chain(rest).collect()
    }

    /// The first step (0-based) of `node` of one of `kinds`.
    fn of(&self, node: usize, kinds: &[StepKind]) -> Option<usize> {
        self.all
            .iter()
            .position(|s| s.node == node && kinds.contains(&s.kind))
    }
}

/// Ray `i` (`n`) with its lines, what it meets, and the shadow rays its hit
/// casts that the diagram draws (`shadows_drawn`).
fn ray(
    steps: &Steps,
    view: &PlayerView,
    i: usize,
    n: &RayNode,
    shadows_drawn: &BTreeSet<(usize, usize)>,
) -> PlayerRay {
    let spawn_step = steps.of(i, &[StepKind::Spawn]);
    let spawn = spawn_step.map(|k| steps.lines(k));
    let end = steps.of(i, &[StepKind::Hit, StepKind::Miss]);
    let drawn = view.depth.is_none_or(|d| n.depth <= d);
    let shadows = if drawn && !view.no_shadows {
        shadows(steps, i, n, shadows_drawn)
    } else {
        Vec::new()
    };
    PlayerRay {
        parent: n.parent,
        kind: n.kind.name(),
        depth: n.depth,
        spawn: spawn_step.map_or(steps.all.len(), |k| k + 1),
        spawn_lines: spawn.as_ref().map_or(0, Vec::len),
        lines: spawn
            .into_iter()
            .flatten()
            .chain(end.into_iter().flat_map(|k| steps.lines(k)))
            .collect(),
        found: end.map(|k| k + 1),
        hit: n.hit.as_ref().map(|h| h.name.clone()),
        drawn,
        shadows,
    }
}

/// The shadow rays of ray `i` (`n`) that the diagram draws: a light behind
/// the surface casts no ray, and one wholly outside the frame is not seen.
fn shadows(
    steps: &Steps,
    i: usize,
    n: &RayNode,
    shadows_drawn: &BTreeSet<(usize, usize)>,
) -> Vec<PlayerShadow> {
    n.shadow_rays
        .iter()
        .enumerate()
        .filter(|&(k, _)| shadows_drawn.contains(&(i, k)))
        .filter_map(|(k, s)| {
            let step = steps.of(i, &[StepKind::Shadow(k)])?;
            Some(PlayerShadow {
                outcome: outcome(&s.outcome),
                light: s.name.clone(),
                step: step + 1,
                lines: steps.lines(step),
            })
        })
        .collect()
}

/// What a shadow ray found, in a word for the list.
fn outcome(outcome: &ShadowOutcomeRecord) -> &'static str {
    match *outcome {
        ShadowOutcomeRecord::Reaches { transmitted } if transmitted < 1.0 => "dimmed",
        ShadowOutcomeRecord::Reaches { .. } => "reaches",
        ShadowOutcomeRecord::Blocked { .. } => "blocked",
        ShadowOutcomeRecord::FacesAway => "not cast",
    }
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
