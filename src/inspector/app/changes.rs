//! The changes that reach across the inspector's parts: a pixel selected is
//! traced and its steps start over; a step or a guided stop selects its line
//! in the tree; an edit swaps the scene, which restarts the picture and the
//! features and keeps the tree's view.

use std::sync::Arc;
use std::time::Instant;

use super::App;
use crate::course::guide::Script;
use crate::inspector::state::selection::Item;
use crate::inspector::state::stepping::{Guided, Stepping};
use crate::inspector::state::whatif::Before;
use crate::scene::Scene;
use crate::tree::document::TraceDocument;
use crate::tree::steps::StepKind;

impl App {
    /// Traces pixel `(x, y)` and shows its tree; back at a guided
    /// step-through's pixel, at the stop it showed. Without the scene only
    /// the saved trace's pixel is known, so the cursor stays on it: panes
    /// must never describe another pixel than the one named.
    pub fn select(&mut self, (x, y): (u32, u32)) {
        let (w, h) = self.image_size();
        let (x, y) = (x.min(w - 1), y.min(h - 1));
        let Some(scene) = &self.scene else {
            if (x, y) != self.cursor() {
                self.message = self.no_scene_here();
            }
            return;
        };
        self.selection.set_pixel((x, y));
        let started = Instant::now();
        match scene.record(self.source.clone(), x, y) {
            Ok(trace) => {
                self.set_trace(trace);
                self.selection.set_traced_in(started.elapsed());
                if self.guided_here() {
                    self.stop_by(0);
                }
            }
            Err(e) => self.message = e.to_string(),
        }
    }

    /// Why the cursor cannot leave the saved trace's pixel.
    pub(in crate::inspector) fn no_scene_here(&self) -> String {
        let (x, y) = self.cursor();
        format!(
            "only pixel {x},{y} is here (the saved trace): scene {} not found, so no other pixel can be traced",
            self.source.file
        )
    }

    /// Whether a guided step-through is followed and its pixel is the one
    /// selected: elsewhere its stops would quote numbers of another pixel.
    pub(in crate::inspector) fn guided_here(&self) -> bool {
        self.guide
            .as_ref()
            .is_some_and(|g| g.pixel() == self.cursor())
    }

    /// Shows `trace`, not stepping.
    pub(super) fn set_trace(&mut self, trace: TraceDocument) {
        self.stepping = Stepping::new(self.selection.show(trace));
    }

    /// Follows a guided step-through: its pixel, its first stop.
    pub fn follow(&mut self, script: Script) -> Result<(), String> {
        self.selection.set_sample(script.sample);
        self.select((script.pixel[0], script.pixel[1]));
        let trace = self
            .trace()
            .ok_or("the script's pixel could not be traced")?;
        let told = crate::course::guide::narrate(&script, trace)?;
        self.guide = Some(Guided::new(script, told));
        self.stop_by(0);
        Ok(())
    }

    /// Moves `by` stops through the guided step-through.
    pub(super) fn stop_by(&mut self, by: i64) {
        let Some(guide) = self.guide.as_mut() else {
            return;
        };
        let was = guide.position();
        let step = guide.move_by(by);
        if guide.position() == was {
            // A key that does nothing would look like a key not read.
            self.message = match by.signum() {
                1 => format!(
                    "stop {} of {} is the guide's last: p goes back",
                    was.1, was.1
                ),
                _ => format!("stop 1 of {} is the guide's first: n goes on", was.1),
            };
        }
        if let Some(step) = step {
            self.go_to_step(step);
        }
    }

    /// Moves `by` steps through the algorithm and selects the step's line.
    pub(super) fn step_by(&mut self, by: i64) {
        let Some(s) = self.stepping.target(by) else {
            return;
        };
        if self.stepping.at() == Some(s) {
            let n = self.stepping.steps().len();
            self.message = match by.signum() {
                1 => format!("step {n} of {n} is the last: p steps back, x shows the whole tree"),
                _ => format!("step 1 of {n} is the first: n steps on, x shows the whole tree"),
            };
        }
        self.go_to_step(s);
    }

    /// Makes step `s` the current one and selects its line: the ray's, or the
    /// shadow ray's for a shadow step.
    pub fn go_to_step(&mut self, s: usize) {
        let Some(step) = self.stepping.go_to(s) else {
            return;
        };
        // Stepping, the newest numbers are the last lines: show the end.
        self.selection.set_scroll(u16::MAX);
        self.select_node(step.node);
        if let StepKind::Shadow(k) = step.kind {
            self.selection.expand(step.node);
            let shown = self.revealed();
            self.selection
                .select_item(Item::Shadow(step.node, k), &shown);
        }
    }

    /// Selects node `n`'s line, expanding its ancestors.
    pub fn select_node(&mut self, n: usize) {
        let shown = self.revealed();
        self.selection.select_node(n, &shown);
    }

    /// Opens every ray of the tree.
    pub fn expand_all(&mut self) {
        self.selection.expand_all();
    }

    /// Shows the pixel's next sample (after the last, the first again).
    pub(super) fn next_sample(&mut self) {
        if self.trace().is_some_and(|t| t.samples.len() == 1) {
            self.message =
                "this pixel has one sample: s shows the next one at --spp 4 and more".to_owned();
            return;
        }
        if let Some(steps) = self.selection.next_sample() {
            self.stepping = Stepping::new(steps);
        }
    }

    pub(super) fn zoom_by(&mut self, by: i32) {
        let pane = self.screen.areas().image;
        self.image.zoom_by(by, self.image_size(), pane);
    }

    /// Applies a typed edit (`ior=1.0`) to the selected hit's material (or a
    /// method), re-traces the pixel and keeps what it was before the first edit.
    pub(super) fn edit(&mut self, typed: &str) {
        let Some(scene) = self.scene.as_ref().map(|s| Arc::clone(s.scene())) else {
            self.message = "no scene to edit".to_owned();
            return;
        };
        let before = self.trace().map(|t| Before {
            pixel: self.cursor(),
            color: t.color,
            rays: t.samples[0].tree.nodes.len(),
        });
        let material = self.selected_material();
        let edited = self
            .what_if
            .edit(&scene, &self.source, material.as_deref(), typed, before);
        match edited {
            Ok(edited) => {
                self.swap_scene(edited);
                self.message = self.what_if.told();
            }
            Err(e) => self.message = e,
        }
    }

    /// The selected hit's material, if the selected ray hit something.
    fn selected_material(&self) -> Option<String> {
        let node = self.selected_item().map_or(0, Item::node);
        let hit = self.selection.tree()?.nodes.get(node)?.hit.as_ref()?;
        Some(hit.material.clone())
    }

    /// Back to the scene as loaded, the pixel's tree bit for bit as before.
    pub(super) fn undo_edits(&mut self) {
        match self.what_if.undo() {
            Some(loaded) => {
                self.swap_scene(loaded);
                self.message = "the scene is as loaded again".to_owned();
            }
            None => self.message = "nothing to undo: the scene is as loaded".to_owned(),
        }
    }

    /// Works with `scene` from now on (an edit, or undoing them), the pixel
    /// traced again with its tree opened as it was.
    fn swap_scene(&mut self, scene: Arc<Scene>) {
        let Some(now) = &self.scene else { return };
        let scene = now.edited(scene);
        self.image.restart(&scene);
        self.scene = Some(scene);
        self.finding.forget();
        let view = self.selection.view();
        self.select(self.cursor());
        let line = self.selection.set_view(view);
        let count = self.items().len();
        self.selection.set_line(line.min(count.saturating_sub(1)));
        self.retell();
    }

    /// Tells the guided step-through again from its pixel traced in the scene
    /// as it is now, and goes back to the stop shown when that pixel is the
    /// one selected: a stop never quotes the trace before a what-if.
    fn retell(&mut self) {
        let (Some(guide), Some(scene)) = (&self.guide, &self.scene) else {
            return;
        };
        let pixel = guide.pixel();
        let here = pixel == self.cursor();
        let traced = match self.trace().filter(|_| here) {
            Some(trace) => Ok(trace.clone()),
            None => scene.record(self.source.clone(), pixel.0, pixel.1),
        };
        match traced {
            Ok(trace) => {
                if let Some(g) = self.guide.as_mut() {
                    g.retell(&trace);
                }
                if here {
                    self.stop_by(0);
                }
            }
            Err(e) => self.message = format!("the guided pixel could not be traced: {e}"),
        }
    }
}
