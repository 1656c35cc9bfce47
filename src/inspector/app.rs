//! The inspector's state and what keys and clicks do to it, apart from any
//! terminal, so it can be tested directly.

mod keys;

use std::sync::Arc;
use std::time::{Duration, Instant};

use ratatui::layout::Rect;

use super::find::Finding;
use super::image_view::ImageView;
use super::layout::{Areas, Screen};
use super::preview::{Picture, Window, Worker};
use super::reveal::Revealed;
use super::selection::{Focus, Item, Selection};
use super::stepping::{Guided, Stepping};
use super::whatif::{Before, WhatIf};
use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::tree::document::TraceDocument;
use crate::tree::steps::{Step, StepKind};
use crate::views::guide::Script;

/// A line being typed in the step line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Prompt {
    /// `g`: a pixel to go to.
    GoTo(String),
    /// `m`: an edit of the selected hit's material or a method (`ior=1.0`).
    Edit(String),
    /// `w`: a new file to write the edited scene to.
    Write(String),
}

/// The inspector's state.
pub struct App {
    /// The scene, when known (a saved trace may come without it).
    pub scene: Option<Arc<Scene>>,
    /// Names the scene in traces.
    pub source: SceneSource,
    selection: Selection,
    stepping: Stepping,
    /// The user asked to quit.
    pub quit: bool,
    /// A line being typed (go to, edit, write), while open.
    pub prompt: Option<Prompt>,
    /// A one-line message for the status bar.
    pub message: String,
    /// Draw in 24-bit color (else the 256-color palette).
    pub truecolor: bool,
    /// Why the terminal is drawn in 256 colors, when it is.
    pub color_note: Option<String>,
    /// The saved trace's file, when the inspector opened one (no timing then).
    pub loaded_from: Option<String>,
    finding: Finding,
    screen: Screen,
    /// A guided step-through, when following one.
    guide: Option<Guided>,
    what_if: WhatIf,
    image: ImageView,
}

impl App {
    /// An inspector on `scene`, the cursor at `start` (or at a pixel worth
    /// looking at: the deepest tree, nearest the center). `live` starts the
    /// preview worker; tests leave it off and call [`App::render_picture_now`].
    pub fn new(scene: Scene, source: SceneSource, start: Option<(u32, u32)>, live: bool) -> Self {
        let s = scene.settings;
        let start = start.unwrap_or_else(|| {
            // A coarse scan (every 8th pixel) is quick even for large images.
            super::features::scan(&scene, 8).most_interesting(s.width, s.height)
        });
        let scene = Arc::new(scene);
        let worker = live.then(|| Worker::start(Arc::clone(&scene)));
        let mut app = Self::empty(Some(scene), source, worker);
        app.select(start);
        app
    }

    /// An inspector on a saved trace; `scene` is the scene it names, when found.
    pub fn from_trace(trace: TraceDocument, scene: Option<Scene>, live: bool) -> Self {
        let scene = scene.map(Arc::new);
        let worker = if live {
            scene.as_ref().map(|s| Worker::start(Arc::clone(s)))
        } else {
            None
        };
        let source = trace.scene.clone();
        let mut app = Self::empty(scene, source, worker);
        app.selection
            .set_pixel(trace.pixel.map_or((0, 0), |p| (p.x, p.y)));
        app.set_trace(trace);
        if app.scene.is_none() {
            app.message = format!(
                "scene {} not found: showing the saved trace only",
                app.source.file
            );
        }
        app
    }

    fn empty(scene: Option<Arc<Scene>>, source: SceneSource, worker: Option<Worker>) -> Self {
        Self {
            scene,
            source,
            selection: Selection::default(),
            stepping: Stepping::default(),
            quit: false,
            prompt: None,
            message: String::new(),
            truecolor: true,
            color_note: None,
            loaded_from: None,
            finding: Finding::default(),
            screen: Screen::default(),
            guide: None,
            what_if: WhatIf::default(),
            image: ImageView::new(worker),
        }
    }

    /// The update step before each frame on a terminal of `area`: takes the
    /// newest picture the worker finished, lays the panes out (kept for
    /// clicks), asks the worker for the picture of the image pane's window and
    /// keeps the numbers' scroll in range. Drawing then only reads.
    pub fn tick(&mut self, area: Rect) {
        self.image.receive();
        let panes = super::ui::panes(self, area);
        self.screen.set_areas(panes.areas());
        self.image.request(self.window());
        if let Some(details) = panes.details {
            let top = super::ui::details_top(self, details) as u16;
            self.selection.set_scroll(top);
        }
    }

    /// Where the panes were last laid out (by [`App::tick`]).
    pub fn areas(&self) -> Areas {
        self.screen.areas()
    }

    /// Lays the panes out as given (tests that click without drawing).
    pub fn set_areas(&mut self, areas: Areas) {
        self.screen.set_areas(areas);
    }

    /// Whether the key help is shown.
    pub fn help_shown(&self) -> bool {
        self.screen.help_open()
    }

    /// The screen: the right-hand pane of a small terminal, the help.
    pub(super) fn screen(&self) -> &Screen {
        &self.screen
    }

    /// The full image's size.
    pub fn image_size(&self) -> (u32, u32) {
        match (&self.scene, self.selection.trace()) {
            (Some(s), _) => (s.settings.width, s.settings.height),
            (None, Some(t)) => (t.settings.width, t.settings.height),
            _ => (1, 1),
        }
    }

    /// The selected pixel, in the full image's coordinates (as `raytree trace --pixel`).
    pub fn cursor(&self) -> (u32, u32) {
        self.selection.pixel()
    }

    /// The selected pixel's trace.
    pub fn trace(&self) -> Option<&TraceDocument> {
        self.selection.trace()
    }

    /// The selected pixel, its trace and the tree pane's cursor.
    pub(super) fn selection(&self) -> &Selection {
        &self.selection
    }

    /// Which pane the arrows drive.
    pub fn focus(&self) -> Focus {
        self.selection.focus()
    }

    /// Holds the time to trace still (snapshots).
    pub fn set_trace_time(&mut self, took: Duration) {
        self.selection.set_traced_in(took);
    }

    /// Traces pixel `(x, y)` and shows its tree.
    pub fn select(&mut self, (x, y): (u32, u32)) {
        let (w, h) = self.image_size();
        let (x, y) = (x.min(w - 1), y.min(h - 1));
        self.selection.set_pixel((x, y));
        let Some(scene) = &self.scene else { return };
        let started = Instant::now();
        match crate::tree::record::pixel(scene, self.source.clone(), x, y, None) {
            Ok(trace) => {
                self.set_trace(trace);
                self.selection.set_traced_in(started.elapsed());
            }
            Err(e) => self.message = e.to_string(),
        }
    }

    /// Shows `trace`, not stepping.
    fn set_trace(&mut self, trace: TraceDocument) {
        self.stepping = Stepping::new(self.selection.show(trace));
    }

    /// The algorithm's steps for the pixel's tree, in execution order.
    pub fn steps(&self) -> &[Step] {
        self.stepping.steps()
    }

    /// The current step's index into [`App::steps`], once stepping has started.
    pub fn step(&self) -> Option<usize> {
        self.stepping.at()
    }

    /// The current step, while stepping.
    pub(super) fn current_step(&self) -> Option<&Step> {
        self.stepping.current()
    }

    /// The guided step-through followed, if any.
    pub(super) fn guide(&self) -> Option<&Guided> {
        self.guide.as_ref()
    }

    /// What the algorithm has computed at the current step (everything when
    /// not stepping).
    pub fn revealed(&self) -> Revealed {
        self.stepping.revealed(self.selection.tree())
    }

    /// Follows a guided step-through: its pixel, its first stop.
    pub fn follow(&mut self, script: Script) -> Result<(), String> {
        self.selection.set_sample(script.sample);
        self.select((script.pixel[0], script.pixel[1]));
        let trace = self
            .trace()
            .ok_or("the script's pixel could not be traced")?;
        let told = crate::views::guide::narrate(&script, trace)?;
        self.guide = Some(Guided::new(script, told));
        self.stop_by(0);
        Ok(())
    }

    /// Moves `by` stops through the guided step-through.
    fn stop_by(&mut self, by: i64) {
        if let Some(step) = self.guide.as_mut().and_then(|g| g.move_by(by)) {
            self.go_to_step(step);
        }
    }

    /// Moves `by` steps through the algorithm and selects the step's line.
    fn step_by(&mut self, by: i64) {
        if let Some(s) = self.stepping.target(by) {
            self.go_to_step(s);
        }
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

    /// The tree pane's lines: the item and its indentation; while stepping,
    /// only the rays spawned and shadow rays cast so far.
    pub fn items(&self) -> Vec<(Item, usize)> {
        self.selection.items(&self.revealed())
    }

    /// The selected tree line's item.
    pub fn selected_item(&self) -> Option<Item> {
        self.selection.selected_item(&self.revealed())
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
    fn next_sample(&mut self) {
        if let Some(steps) = self.selection.next_sample() {
            self.stepping = Stepping::new(steps);
        }
    }

    /// The zoom level: 0 fits the whole image; each level doubles the magnification.
    pub fn zoom(&self) -> u32 {
        self.image.zoom()
    }

    pub(super) fn zoom_by(&mut self, by: i32) {
        let pane = self.screen.areas().image;
        self.image.zoom_by(by, self.image_size(), pane);
    }

    /// The part of the image the pane shows: the whole image at zoom 0, else a
    /// window centered on the cursor, kept inside the image.
    pub fn window(&self) -> Window {
        self.image
            .window(self.image_size(), self.cursor(), self.screen.areas().image)
    }

    /// What `f` seeks and the image pane overlays.
    pub(super) fn finding(&self) -> &Finding {
        &self.finding
    }

    /// The image pane's picture, once traced.
    pub(super) fn picture(&self) -> Option<&Picture> {
        self.image.picture()
    }

    /// Traces the picture of the current window here and now (tests, benchmarks).
    pub fn render_picture_now(&mut self) {
        if let Some(scene) = &self.scene {
            let picture = super::preview::render_picture(scene, self.window(), 1, &|| false);
            self.image.set_picture(picture);
        }
    }

    /// Shows `picture`, traced elsewhere (benchmarks).
    pub fn set_picture(&mut self, picture: Option<Picture>) {
        self.image.set_picture(picture);
    }

    /// The what-if edits in effect, as typed (a material's with its name).
    pub fn edits(&self) -> &[String] {
        self.what_if.edits()
    }

    /// The what-if edits and the pixel before them.
    pub(super) fn what_if(&self) -> &WhatIf {
        &self.what_if
    }

    /// Applies a typed edit (`ior=1.0`) to the selected hit's material (or a
    /// method), re-traces the pixel and keeps what it was before the first edit.
    fn edit(&mut self, typed: &str) {
        let Some(scene) = self.scene.clone() else {
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
    fn undo_edits(&mut self) {
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
    pub(super) fn swap_scene(&mut self, scene: Arc<Scene>) {
        self.image.restart(&scene);
        self.scene = Some(scene);
        self.finding.forget();
        let view = self.selection.view();
        self.select(self.cursor());
        let line = self.selection.set_view(view);
        let count = self.items().len();
        self.selection.set_line(line.min(count.saturating_sub(1)));
    }
}
