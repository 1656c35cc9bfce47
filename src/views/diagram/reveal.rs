//! When each part of a diagram appears as the algorithm runs, written into
//! its SVG: the book's players draw the whole diagram once and reveal it stop
//! by stop, so every part says which ray it belongs to (`data-ray`, the tree
//! node) and from which step of `raytree trace --steps` it is drawn
//! (`data-step`, 1-based): a ray from its spawn, its hit and the marks there
//! from the closest hit, a shadow ray from the step that casts it. Parts of
//! the scene (objects, lights, the eye) carry no tag: they are there from the
//! start.

use std::collections::{BTreeSet, HashMap};

use crate::tree::document::TraceDocument;
use crate::tree::steps::StepKind;

/// The step at which each part of one sample's tree appears.
#[derive(Clone, Debug, Default)]
pub struct Reveal {
    spawn: HashMap<usize, usize>,
    hit: HashMap<usize, usize>,
    shadow: HashMap<(usize, usize), usize>,
    visit: HashMap<(usize, usize), usize>,
}

/// What a tagged part is, for the player's styles and the browser test.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// A ray's line (primary, reflected, refracted).
    Ray,
    /// A shadow ray's line.
    Shadow,
    /// A hit point, its normal, and the marks at it.
    Hit,
    /// A label naming one of those.
    Label,
    /// A box or cell of the scene's structure, from the step that visits it.
    Box,
}

impl Reveal {
    /// The steps of `sample` of `trace`.
    pub fn of(trace: &TraceDocument, sample: usize) -> Self {
        let mut r = Reveal::default();
        for (k, s) in trace.steps(sample).iter().enumerate() {
            let step = k + 1;
            match s.kind {
                StepKind::Spawn => {
                    r.spawn.entry(s.node).or_insert(step);
                }
                StepKind::Hit => {
                    r.hit.entry(s.node).or_insert(step);
                }
                StepKind::Shadow(j) => {
                    r.shadow.entry((s.node, j)).or_insert(step);
                }
                StepKind::Visit(j) => {
                    r.visit.entry((s.node, j)).or_insert(step);
                }
                _ => {}
            }
        }
        r
    }

    /// The attributes of a ray's line: drawn to its hit from the step that
    /// finds the hit (before that, [`Reveal::pending`] stands in for it), or
    /// from its spawn when it meets nothing.
    pub fn ray(&self, node: usize) -> String {
        let found = self.hit.get(&node).or(self.spawn.get(&node));
        tag(Part::Ray, node, found)
    }

    /// The attributes of a ray's stand-in between its spawn and its hit: a
    /// short faint arrow from its start, so the figure neither tells where
    /// the ray stops before the algorithm has found it nor draws it through
    /// what it will miss. Hidden unless a
    /// player shows it; `None` when the ray's hit is found at its spawn.
    pub fn pending(&self, node: usize) -> Option<String> {
        let (&spawn, &hit) = (self.spawn.get(&node)?, self.hit.get(&node)?);
        (hit > spawn + 1).then(|| {
            format!(
                "class=\"ray pending\" data-ray=\"{node}\" data-step=\"{spawn}\" data-until=\"{}\" display=\"none\"",
                hit - 1
            )
        })
    }

    /// The attributes of shadow ray `k` of `node`.
    pub fn shadow(&self, node: usize, k: usize) -> String {
        let tag = tag(Part::Shadow, node, self.shadow.get(&(node, k)));
        format!("{tag} data-shadow=\"{k}\"")
    }

    /// The shadow rays a drawing holds, as `(node, k)`, from the tags its SVG
    /// carries ([`crate::figure::canvas::Figure::svg_tags`]): a light behind
    /// the surface casts no ray, and one wholly outside the frame is not drawn.
    pub fn shadows_drawn(&self, tags: &BTreeSet<String>) -> BTreeSet<(usize, usize)> {
        let drawn = |&&(node, k): &&(usize, usize)| tags.contains(&self.shadow(node, k));
        self.shadow.keys().filter(drawn).copied().collect()
    }

    /// The attributes of `node`'s hit and what is marked there.
    pub fn hit(&self, node: usize) -> String {
        tag(Part::Hit, node, self.hit.get(&node))
    }

    /// The attributes of box `k` that `node`'s search visited.
    pub fn visit(&self, node: usize, k: usize) -> String {
        tag(Part::Box, node, self.visit.get(&(node, k)))
    }

    /// The attributes of a label naming a part of `node` that appears with
    /// its hit (`at_hit`) or its spawn.
    pub fn label(&self, node: usize, at_hit: bool) -> String {
        let step = if at_hit {
            self.hit.get(&node)
        } else {
            self.spawn.get(&node)
        };
        tag(Part::Label, node, step)
    }
}

fn tag(part: Part, node: usize, step: Option<&usize>) -> String {
    let class = match part {
        Part::Ray => "ray",
        Part::Shadow => "shadow",
        Part::Hit => "hit",
        Part::Label => "label",
        Part::Box => "box",
    };
    // A part with no step of its own (a tree cut short) appears at the end.
    let step = step.map_or_else(|| "end".to_owned(), |s| s.to_string());
    format!("class=\"{class}\" data-ray=\"{node}\" data-step=\"{step}\"")
}
