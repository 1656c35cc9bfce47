//! The report of `raytree check SCENE --pixel X,Y LEARNER.json`
//! ([`crate::course::learner::check`]): the first divergence in the
//! lecture's words (which ray, which quantity, both values, the step of `raytree trace --steps` where it arises, and the
//! classic mistake when its numbers show one), then the rest briefly. The
//! `--json` report is for autograders; its fields are documented in
//! `docs/learner-trace.md` and stay stable within its version.

use std::fmt::Write as _;

use serde_json::{Value, json};

use crate::course::learner::difference::{Difference, Quantity};

/// The `format` of the JSON report.
pub const REPORT_FORMAT: &str = "raytree-check-report";
/// Its version.
pub const REPORT_VERSION: u32 = 1;

/// The check of one pixel.
#[derive(Debug)]
pub struct Report {
    /// The scene file, as traces name it.
    pub scene: String,
    /// The pixel.
    pub pixel: (u32, u32),
    /// The image's size it was traced at: the step numbers are those of a
    /// trace at this size, which the report's command says.
    pub size: (u32, u32),
    /// How many rays the learner's trace holds, and raytree's.
    pub rays: (usize, usize),
    /// Every difference, in raytree's step order (divergences and notes).
    pub differences: Vec<Difference>,
}

impl Report {
    /// The divergences (not the tolerated notes).
    pub fn divergences(&self) -> impl Iterator<Item = &Difference> {
        self.differences.iter().filter(|d| d.divergence)
    }

    /// Whether every field agreed: the command's exit status 0.
    pub fn agrees(&self) -> bool {
        self.divergences().next().is_none()
    }

    /// The report for a reader.
    pub fn text(&self) -> String {
        let (x, y) = self.pixel;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "raytree check: pixel {x},{y} of {}: your trace holds {} ray{}, raytree's {}",
            self.scene,
            self.rays.0,
            if self.rays.0 == 1 { "" } else { "s" },
            self.rays.1
        );
        let mut rest = self.divergences();
        match rest.next() {
            None => {
                let _ = writeln!(
                    out,
                    "agrees: every field you gave is raytree's within its tolerance (docs/learner-trace.md)"
                );
            }
            Some(first) => {
                self.first_divergence(&mut out, first);
                let rest: Vec<&Difference> = rest.collect();
                if !rest.is_empty() {
                    let _ = writeln!(
                        out,
                        "then {} more (often consequences of the first):",
                        rest.len()
                    );
                    for d in rest {
                        let _ = writeln!(out, "  {}", brief(d));
                    }
                }
            }
        }
        let notes: Vec<&Difference> = self.differences.iter().filter(|d| !d.divergence).collect();
        if !notes.is_empty() {
            let _ = writeln!(out, "tolerated:");
            for d in notes {
                let _ = writeln!(out, "  {}", brief(d));
            }
        }
        out
    }

    /// The first divergence in full: where, what, both values, and the
    /// diagnosis (or, for a primary direction none explains, a question
    /// about the image's size).
    fn first_divergence(&self, out: &mut String, first: &Difference) {
        let (x, y) = self.pixel;
        let _ = writeln!(
            out,
            "first divergence, at step {} of `raytree trace {} --pixel {x},{y} --width {} --height {} --steps`:",
            first.step, self.scene, self.size.0, self.size.1
        );
        let _ = writeln!(out, "  ray:        {}", first.ray);
        let _ = writeln!(out, "  quantity:   {}", first.quantity);
        let _ = writeln!(out, "  yours:      {}", first.learner);
        let _ = writeln!(out, "  raytree's:  {}", first.ours);
        match &first.diagnosis {
            Some(d) => {
                let _ = writeln!(out, "  diagnosis:  {} [{}]", d.words, d.id());
                let _ = writeln!(out, "  lesson:     {}", d.lesson());
            }
            None => {
                let _ = writeln!(
                    out,
                    "  diagnosis:  none of the classic mistakes matches these numbers"
                );
                if first.ray.is_primary() && first.quantity == Quantity::Direction {
                    let _ = writeln!(
                        out,
                        "  note:       raytree's image is {}×{}: was yours traced at that size (--width, --height)?",
                        self.size.0, self.size.1
                    );
                }
            }
        }
    }

    /// The report for an autograder (`--json`).
    pub fn json(&self) -> String {
        let all: Vec<Value> = self.differences.iter().map(difference).collect();
        let first = self.divergences().next().map_or(Value::Null, difference);
        let doc = json!({
            "format": REPORT_FORMAT,
            "version": REPORT_VERSION,
            "scene": self.scene,
            "pixel": [self.pixel.0, self.pixel.1],
            "agree": self.agrees(),
            "rays": { "learner": self.rays.0, "raytree": self.rays.1 },
            "first": first,
            "differences": all,
        });
        let mut text = serde_json::to_string_pretty(&doc).expect("JSON values print");
        text.push('\n');
        text
    }
}

fn brief(d: &Difference) -> String {
    let why = d
        .diagnosis
        .as_ref()
        .map_or(String::new(), |g| format!(" [{}]", g.id()));
    format!(
        "step {:>3}  {}: {}: yours {}, raytree's {}{why}",
        d.step, d.ray, d.quantity, d.learner, d.ours
    )
}

fn difference(d: &Difference) -> Value {
    json!({
        "step": d.step,
        "ray": d.ray,
        "quantity": d.quantity,
        "learner": d.learner,
        "raytree": d.ours,
        "divergence": d.divergence,
        "diagnosis": d.diagnosis.as_ref().map(|g| json!({
            "id": g.mistake, "lesson": g.lesson(), "words": g.words,
        })),
    })
}
