//! Stepping through the algorithm, freely or along a guided step-through's
//! stops, and what the panes may show at the current step.

use super::app::{App, Guided, Item};
use super::reveal::Revealed;
use crate::course::guide::Script;
use crate::tree::steps::StepKind;

impl App {
    /// What the algorithm has computed at the current step (everything when
    /// not stepping).
    pub fn revealed(&self) -> Revealed {
        let Some(t) = &self.trace else {
            return Revealed::default();
        };
        let tree = &t.samples[self.sample].tree;
        match self.step {
            Some(s) => Revealed::until(tree, &self.steps, s),
            None => Revealed::all(tree),
        }
    }

    /// Follows a guided step-through: its pixel, its first stop.
    pub fn follow(&mut self, script: Script) -> Result<(), String> {
        self.sample = script.sample;
        self.select((script.pixel[0], script.pixel[1]));
        let trace = self
            .trace
            .as_ref()
            .ok_or("the script's pixel could not be traced")?;
        let told = crate::course::guide::narrate(&script, trace)?;
        self.guide = Some(Guided {
            script,
            told,
            at: 0,
        });
        self.stop_by(0);
        Ok(())
    }

    /// Moves `by` stops through the guided step-through.
    pub fn stop_by(&mut self, by: i64) {
        let Some(g) = &mut self.guide else { return };
        let last = g.told.len().saturating_sub(1) as i64;
        g.at = (g.at as i64 + by).clamp(0, last) as usize;
        let step = g.told.get(g.at).map(|n| n.step);
        if let Some(step) = step {
            self.go_to_step(step);
        }
    }

    /// Moves `by` steps through the algorithm and selects the step's line.
    pub fn step_by(&mut self, by: i64) {
        if self.steps.is_empty() {
            return;
        }
        let last = self.steps.len() as i64 - 1;
        let next = match self.step {
            None if by >= 0 => 0,
            None => last,
            Some(s) => (s as i64 + by).clamp(0, last),
        };
        self.go_to_step(next as usize);
    }

    /// Makes step `s` the current one and selects its line: the ray's, or the
    /// shadow ray's for a shadow step.
    pub fn go_to_step(&mut self, s: usize) {
        let Some(&step) = self.steps.get(s) else {
            return;
        };
        self.step = Some(s);
        // Stepping, the newest numbers are the last lines: show the end.
        self.detail_scroll = u16::MAX;
        self.select_node(step.node);
        if let StepKind::Shadow(k) = step.kind {
            self.expanded.insert(step.node);
            if let Some(pos) = self
                .items()
                .iter()
                .position(|&(item, _)| item == Item::Shadow(step.node, k))
            {
                self.selected = pos;
            }
        }
    }
}
