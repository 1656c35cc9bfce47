//! Stepping through the algorithm, freely or along a guided step-through's
//! stops: where in the steps the inspector is, and what the panes may show
//! there.

use super::reveal::Revealed;
use crate::course::guide::{self, Narration, Script, Untold};
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::RayTree;
use crate::tree::steps::Step;

/// The algorithm's steps for the tree shown, and the current one once
/// stepping has started.
#[derive(Debug, Default)]
pub(in crate::inspector) struct Stepping {
    steps: Vec<Step>,
    at: Option<usize>,
}

impl Stepping {
    /// Not stepping yet through `steps`.
    pub fn new(steps: Vec<Step>) -> Self {
        Self { steps, at: None }
    }

    /// Every step, in execution order.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// The current step's index, while stepping.
    pub fn at(&self) -> Option<usize> {
        self.at
    }

    /// The current step, while stepping.
    pub fn current(&self) -> Option<&Step> {
        self.steps.get(self.at?)
    }

    /// Stops stepping: the whole tree again.
    pub fn leave(&mut self) {
        self.at = None;
    }

    /// The step `by` steps from the current one, kept within the steps; not
    /// yet stepping, forward starts at the first and back at the last. `None`
    /// without steps.
    pub fn target(&self, by: i64) -> Option<usize> {
        if self.steps.is_empty() {
            return None;
        }
        let last = self.steps.len() as i64 - 1;
        let next = match self.at {
            None if by >= 0 => 0,
            None => last,
            Some(s) => (s as i64 + by).clamp(0, last),
        };
        Some(next as usize)
    }

    /// Makes step `s` the current one, if there is one; returns it.
    pub fn go_to(&mut self, s: usize) -> Option<Step> {
        let step = *self.steps.get(s)?;
        self.at = Some(s);
        Some(step)
    }

    /// What the algorithm has computed in `tree` at the current step
    /// (everything when not stepping).
    pub fn revealed(&self, tree: Option<&RayTree>) -> Revealed {
        let Some(tree) = tree else {
            return Revealed::default();
        };
        match self.at {
            Some(s) => Revealed::until(tree, &self.steps, s),
            None => Revealed::all(tree),
        }
    }
}

/// A guided step-through being followed: its script, its stops filled with
/// the trace's numbers (told again after a what-if; a stop the changed trace
/// cannot tell says why), and the stop shown.
#[derive(Clone, Debug, PartialEq)]
pub struct Guided {
    script: Script,
    told: Vec<Result<Narration, Untold>>,
    at: usize,
}

impl Guided {
    /// At the first of `told`, the stops of `script`.
    pub fn new(script: Script, told: Vec<Narration>) -> Self {
        Self {
            script,
            told: told.into_iter().map(Ok).collect(),
            at: 0,
        }
    }

    /// Tells every stop again against `trace`, the script's pixel traced in
    /// the scene as it is now, so no stop quotes a number of the old trace.
    pub fn retell(&mut self, trace: &TraceDocument) {
        self.told = (0..self.script.stops.len())
            .map(|i| guide::tell(&self.script, trace, i))
            .collect();
    }

    /// Moves `by` stops, kept within them; the step of the stop reached.
    pub fn move_by(&mut self, by: i64) -> Option<usize> {
        let last = self.told.len().saturating_sub(1) as i64;
        self.at = (self.at as i64 + by).clamp(0, last) as usize;
        self.script.stops.get(self.at).map(|s| s.step - 1)
    }

    /// The stop shown: its sentence, or why the trace as it is now cannot
    /// tell it.
    pub fn stop(&self) -> Option<String> {
        let step = self.script.stops.get(self.at)?.step;
        Some(match self.told.get(self.at)? {
            Ok(n) => n.text.clone(),
            Err(Untold::PastEnd { steps }) => format!(
                "after the what-if, the pixel has {steps} steps, so this stop's step {step} is gone \
                 and it has nothing to tell (u undoes the edits)"
            ),
            Err(Untold::NoNumber { name, .. }) => format!(
                "after the what-if, step {step} has no {{{name}}} to quote, so this stop cannot be \
                 told of the changed trace (u undoes the edits)"
            ),
        })
    }

    /// Which stop is shown (0 is the first) and how many there are.
    pub fn position(&self) -> (usize, usize) {
        (self.at, self.told.len())
    }

    /// The script's title.
    pub fn title(&self) -> Option<&str> {
        self.script.title.as_deref()
    }

    /// The pixel the script follows.
    pub fn pixel(&self) -> (u32, u32) {
        (self.script.pixel[0], self.script.pixel[1])
    }
}
