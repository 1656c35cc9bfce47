//! Stepping through the algorithm, freely or along a guided step-through's
//! stops: where in the steps the inspector is, and what the panes may show
//! there.

use super::reveal::Revealed;
use crate::course::guide::{Narration, Script};
use crate::tree::ray_tree::RayTree;
use crate::tree::steps::Step;

/// The algorithm's steps for the tree shown, and the current one once
/// stepping has started.
#[derive(Debug, Default)]
pub(super) struct Stepping {
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
/// the trace's numbers, and the stop shown.
#[derive(Clone, Debug, PartialEq)]
pub struct Guided {
    script: Script,
    told: Vec<Narration>,
    at: usize,
}

impl Guided {
    /// At the first of `told`, the stops of `script`.
    pub fn new(script: Script, told: Vec<Narration>) -> Self {
        Self {
            script,
            told,
            at: 0,
        }
    }

    /// Moves `by` stops, kept within them; the step of the stop reached.
    pub fn move_by(&mut self, by: i64) -> Option<usize> {
        let last = self.told.len().saturating_sub(1) as i64;
        self.at = (self.at as i64 + by).clamp(0, last) as usize;
        self.stop().map(|n| n.step)
    }

    /// The stop shown.
    pub fn stop(&self) -> Option<&Narration> {
        self.told.get(self.at)
    }

    /// Which stop is shown (0 is the first) and how many there are.
    pub fn position(&self) -> (usize, usize) {
        (self.at, self.told.len())
    }

    /// The script's title.
    pub fn title(&self) -> Option<&str> {
        self.script.title.as_deref()
    }
}
