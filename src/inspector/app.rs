//! The inspector's state and what keys and clicks do to it, apart from any
//! terminal, so it can be tested directly.

mod keys;

use std::collections::BTreeSet;
use std::sync::Arc;
use std::time::{Duration, Instant};

use ratatui::layout::Rect;

use super::find::Finding;
use super::image_view::ImageView;
use super::layout::{Areas, Pane};
use super::preview::{Picture, Window, Worker};
use super::reveal::Revealed;
use super::stepping::{Guided, Stepping};
use super::whatif::{Before, WhatIf};
use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::trace::recorder::Branch;
use crate::tree::document::TraceDocument;
use crate::tree::steps::{Step, StepKind};
use crate::views::guide::Script;

/// Which pane the arrow keys drive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Focus {
    /// Arrows move the pixel cursor.
    Image,
    /// Arrows move through the ray tree.
    Tree,
}

/// A line of the tree pane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    /// A ray: node index.
    Ray(usize),
    /// A shadow ray: node index and light index.
    Shadow(usize, usize),
}

impl Item {
    /// The node the line belongs to.
    pub fn node(self) -> usize {
        match self {
            Item::Ray(n) | Item::Shadow(n, _) => n,
        }
    }
}

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
    /// The selected pixel, in the full image's coordinates (as `raytree trace --pixel`).
    pub cursor: (u32, u32),
    /// The selected pixel's trace.
    pub trace: Option<TraceDocument>,
    /// Which of the pixel's samples the panes show (0 is the first).
    pub sample: usize,
    /// How many lines of the selected ray's details are scrolled past.
    pub detail_scroll: u16,
    /// Nodes whose children are shown.
    pub expanded: BTreeSet<usize>,
    /// The selected line of the tree pane.
    pub selected: usize,
    stepping: Stepping,
    /// Which pane the arrows drive.
    pub focus: Focus,
    /// The key help is shown.
    pub help: bool,
    /// The user asked to quit.
    pub quit: bool,
    /// A line being typed (go to, edit, write), while open.
    pub prompt: Option<Prompt>,
    /// A one-line message for the status bar.
    pub message: String,
    /// Where the panes are.
    pub areas: Areas,
    /// How long the last pixel's trace took.
    pub trace_time: Duration,
    /// Draw in 24-bit color (else the 256-color palette).
    pub truecolor: bool,
    /// Why the terminal is drawn in 256 colors, when it is.
    pub color_note: Option<String>,
    /// The saved trace's file, when the inspector opened one (no timing then).
    pub loaded_from: Option<String>,
    /// How far the help is scrolled.
    pub help_scroll: u16,
    finding: Finding,
    /// The right-hand pane on small terminals.
    pub pane: Pane,
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
        app.cursor = trace.pixel.map_or((0, 0), |p| (p.x, p.y));
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
            cursor: (0, 0),
            trace: None,
            sample: 0,
            detail_scroll: 0,
            expanded: BTreeSet::new(),
            selected: 0,
            stepping: Stepping::default(),
            focus: Focus::Image,
            help: false,
            quit: false,
            prompt: None,
            message: String::new(),
            areas: Areas::default(),
            trace_time: Duration::ZERO,
            truecolor: true,
            color_note: None,
            loaded_from: None,
            help_scroll: 0,
            finding: Finding::default(),
            pane: Pane::Details,
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
        self.areas = panes.areas();
        self.image.request(self.window());
        if let Some(details) = panes.details {
            self.detail_scroll = super::ui::details_top(self, details) as u16;
        }
    }

    /// The full image's size.
    pub fn image_size(&self) -> (u32, u32) {
        match (&self.scene, &self.trace) {
            (Some(s), _) => (s.settings.width, s.settings.height),
            (None, Some(t)) => (t.settings.width, t.settings.height),
            _ => (1, 1),
        }
    }

    /// Traces pixel `(x, y)` and shows its tree.
    pub fn select(&mut self, (x, y): (u32, u32)) {
        let (w, h) = self.image_size();
        self.cursor = (x.min(w - 1), y.min(h - 1));
        let Some(scene) = &self.scene else { return };
        let started = Instant::now();
        match crate::tree::record::pixel(
            scene,
            self.source.clone(),
            self.cursor.0,
            self.cursor.1,
            None,
        ) {
            Ok(trace) => {
                self.set_trace(trace);
                self.trace_time = started.elapsed();
            }
            Err(e) => self.message = e.to_string(),
        }
    }

    fn set_trace(&mut self, trace: TraceDocument) {
        self.sample = self.sample.min(trace.samples.len().saturating_sub(1));
        self.stepping = Stepping::new(trace.steps(self.sample));
        self.trace = Some(trace);
        self.expanded = BTreeSet::from([0]);
        self.selected = 0;
        self.detail_scroll = 0;
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
        let tree = self.trace.as_ref().map(|t| &t.samples[self.sample].tree);
        self.stepping.revealed(tree)
    }

    /// Follows a guided step-through: its pixel, its first stop.
    pub fn follow(&mut self, script: Script) -> Result<(), String> {
        self.sample = script.sample;
        self.select((script.pixel[0], script.pixel[1]));
        let trace = self
            .trace
            .as_ref()
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

    /// The tree pane's lines: the item and its indentation; while stepping,
    /// only the rays spawned and shadow rays cast so far.
    pub fn items(&self) -> Vec<(Item, usize)> {
        let mut out = Vec::new();
        if let Some(t) = &self.trace {
            let nodes = &t.samples[self.sample].tree.nodes;
            let shown = self.revealed();
            if !nodes.is_empty() && shown.node(0).spawned {
                self.push_items(nodes, &shown, 0, 0, &mut out);
            }
        }
        out
    }

    fn push_items(
        &self,
        nodes: &[crate::tree::ray_tree::RayNode],
        shown: &Revealed,
        i: usize,
        indent: usize,
        out: &mut Vec<(Item, usize)>,
    ) {
        out.push((Item::Ray(i), indent));
        if !self.expanded.contains(&i) || out.len() > nodes.len() * 64 {
            return;
        }
        for k in 0..shown.node(i).shadows.min(nodes[i].shadow_rays.len()) {
            out.push((Item::Shadow(i, k), indent + 1));
        }
        for c in nodes[i].children() {
            if shown.node(c).spawned {
                self.push_items(nodes, shown, c, indent + 1, out);
            }
        }
    }

    /// The selected tree line's item.
    pub fn selected_item(&self) -> Option<Item> {
        self.items().get(self.selected).map(|&(item, _)| item)
    }

    /// Whether node `i` has anything to expand.
    pub fn expandable(&self, i: usize) -> bool {
        self.trace.as_ref().is_some_and(|t| {
            let n = &t.samples[self.sample].tree.nodes[i];
            !n.shadow_rays.is_empty() || n.children().next().is_some()
        })
    }

    /// Selects node `n`'s line, expanding its ancestors.
    pub fn select_node(&mut self, n: usize) {
        let Some(t) = &self.trace else { return };
        let nodes = &t.samples[self.sample].tree.nodes;
        let mut p = nodes[n].parent;
        while let Some(i) = p {
            self.expanded.insert(i);
            p = nodes[i].parent;
        }
        if let Some(pos) = self
            .items()
            .iter()
            .position(|&(item, _)| item == Item::Ray(n))
        {
            self.selected = pos;
        }
    }

    pub(super) fn expand_all(&mut self) {
        if let Some(t) = &self.trace {
            self.expanded = (0..t.samples[self.sample].tree.nodes.len()).collect();
        }
    }

    /// Scrolls the selected ray's details by `by` lines.
    pub fn scroll_details(&mut self, by: i32) {
        self.detail_scroll = self.detail_scroll.saturating_add_signed(by as i16);
    }

    /// Shows the pixel's next sample (after the last, the first again).
    pub fn next_sample(&mut self) {
        let Some(trace) = self.trace.take() else {
            return;
        };
        self.sample = (self.sample + 1) % trace.samples.len().max(1);
        self.set_trace(trace);
    }

    /// The zoom level: 0 fits the whole image; each level doubles the magnification.
    pub fn zoom(&self) -> u32 {
        self.image.zoom()
    }

    pub(super) fn zoom_by(&mut self, by: i32) {
        self.image.zoom_by(by, self.image_size(), self.areas.image);
    }

    /// The part of the image the pane shows: the whole image at zoom 0, else a
    /// window centered on the cursor, kept inside the image.
    pub fn window(&self) -> Window {
        self.image
            .window(self.image_size(), self.cursor, self.areas.image)
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
        let before = self.trace.as_ref().map(|t| Before {
            pixel: self.cursor,
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
        let t = self.trace.as_ref()?;
        let node = self.selected_item().map_or(0, Item::node);
        let hit = t.samples[self.sample].tree.nodes.get(node)?.hit.as_ref()?;
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
        let (sample, selected, expanded) = (self.sample, self.selected, self.expanded.clone());
        self.select(self.cursor);
        self.sample = sample.min(self.trace.as_ref().map_or(1, |t| t.samples.len()) - 1);
        self.expanded = expanded;
        self.selected = selected.min(self.items().len().saturating_sub(1));
    }

    /// Why a node's branches stopped, in words ("" when both were traced or it continues).
    pub fn stop_reason(&self, n: usize) -> String {
        let Some(t) = &self.trace else {
            return String::new();
        };
        let node = &t.samples[self.sample].tree.nodes[n];
        if node.hit.is_none() {
            return "miss → background".to_owned();
        }
        let mut why: Vec<&str> = Vec::new();
        for (branch, none) in [
            (&node.reflected, "not reflective"),
            (&node.refracted, "opaque"),
        ] {
            match branch.as_ref().map(|b| b.outcome) {
                Some(Branch::NoCoefficient) => why.push(none),
                Some(Branch::MaxDepth) => why.push("max depth"),
                Some(Branch::WeightCutoff) => why.push("weight cutoff"),
                Some(Branch::TotalInternalReflection) => why.push("total internal reflection"),
                _ => {}
            }
        }
        why.dedup();
        why.join(", ")
    }
}
