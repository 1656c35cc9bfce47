//! The inspector's state and what keys and clicks do to it, apart from any
//! terminal, so it can be tested directly.

use std::collections::BTreeSet;
use std::sync::Arc;
use std::time::{Duration, Instant};

use ratatui::crossterm::event::{
    KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use ratatui::layout::Rect;

use super::preview::{Picture, Window, Worker};
use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::trace::recorder::Branch;
use crate::tree::document::TraceDocument;
use crate::tree::steps::Step;

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

/// Where the panes were last drawn, for mouse clicks and the picture's size.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Areas {
    /// The image pane's inside.
    pub image: Rect,
    /// The tree pane's inside.
    pub tree: Rect,
    /// The selected ray's pane, border included.
    pub details: Rect,
}

/// The inspector's state.
pub struct App {
    /// The scene, when known (a saved trace may come without it).
    pub scene: Option<Arc<Scene>>,
    /// Names the scene in traces.
    pub source: SceneSource,
    /// The selected pixel, in the full image's coordinates (as `raytree trace --pixel`).
    pub cursor: (u32, u32),
    /// Zoom level: 0 fits the whole image; each level doubles the magnification.
    pub zoom: u32,
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
    /// The algorithm's steps for the trace, and the current one.
    pub steps: Vec<Step>,
    /// Index into `steps`, once stepping has started.
    pub step: Option<usize>,
    /// Which pane the arrows drive.
    pub focus: Focus,
    /// The key help is shown.
    pub help: bool,
    /// The user asked to quit.
    pub quit: bool,
    /// Text typed after `g` (go to pixel), while the prompt is open.
    pub goto: Option<String>,
    /// A one-line message for the status bar.
    pub message: String,
    /// Where the panes are.
    pub areas: Areas,
    /// What the image pane shows.
    pub picture: Option<Picture>,
    /// How long the last pixel's trace took.
    pub trace_time: Duration,
    /// Draw in 24-bit color (else the 256-color palette).
    pub truecolor: bool,
    worker: Option<Worker>,
    requested: Option<Window>,
}

impl App {
    /// An inspector on `scene`, the cursor at `start` (or the center). `live`
    /// starts the preview worker; tests leave it off and call [`App::render_picture_now`].
    pub fn new(scene: Scene, source: SceneSource, start: Option<(u32, u32)>, live: bool) -> Self {
        let s = scene.settings;
        let scene = Arc::new(scene);
        let worker = live.then(|| Worker::start(Arc::clone(&scene)));
        let mut app = Self::empty(Some(scene), source, worker);
        app.select(start.unwrap_or((s.width / 2, s.height / 2)));
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
            zoom: 0,
            trace: None,
            sample: 0,
            detail_scroll: 0,
            expanded: BTreeSet::new(),
            selected: 0,
            steps: Vec::new(),
            step: None,
            focus: Focus::Image,
            help: false,
            quit: false,
            goto: None,
            message: String::new(),
            areas: Areas::default(),
            picture: None,
            trace_time: Duration::ZERO,
            truecolor: true,
            worker,
            requested: None,
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
        self.steps = trace.steps(self.sample);
        self.trace = Some(trace);
        self.expanded = BTreeSet::from([0]);
        self.selected = 0;
        self.step = None;
        self.detail_scroll = 0;
    }

    /// The tree pane's lines: the item and its indentation.
    pub fn items(&self) -> Vec<(Item, usize)> {
        let mut out = Vec::new();
        if let Some(t) = &self.trace {
            let nodes = &t.samples[self.sample].tree.nodes;
            if !nodes.is_empty() {
                self.push_items(nodes, 0, 0, &mut out);
            }
        }
        out
    }

    fn push_items(
        &self,
        nodes: &[crate::tree::ray_tree::RayNode],
        i: usize,
        indent: usize,
        out: &mut Vec<(Item, usize)>,
    ) {
        out.push((Item::Ray(i), indent));
        if !self.expanded.contains(&i) {
            return;
        }
        for k in 0..nodes[i].shadow_rays.len() {
            out.push((Item::Shadow(i, k), indent + 1));
        }
        for c in nodes[i].children() {
            self.push_items(nodes, c, indent + 1, out);
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

    /// Handles one key press.
    pub fn on_key(&mut self, key: KeyEvent) {
        if let Some(text) = &mut self.goto {
            match key.code {
                KeyCode::Char(c) if c.is_ascii_digit() || c == ',' || c == ' ' => text.push(c),
                KeyCode::Backspace => {
                    text.pop();
                }
                KeyCode::Enter => {
                    let typed = self.goto.take().unwrap_or_default();
                    self.go_to(&typed);
                }
                KeyCode::Esc => self.goto = None,
                _ => {}
            }
            return;
        }
        if self.help {
            self.help = false;
            if matches!(key.code, KeyCode::Char('q')) {
                self.quit = true;
            }
            return;
        }
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        match key.code {
            KeyCode::Char('q') | KeyCode::Esc => self.quit = true,
            KeyCode::Char('c') if ctrl => self.quit = true,
            KeyCode::Char('?') => self.help = true,
            KeyCode::Tab | KeyCode::BackTab => {
                self.focus = if self.focus == Focus::Image {
                    Focus::Tree
                } else {
                    Focus::Image
                }
            }
            KeyCode::Char('n') | KeyCode::Char(' ') => self.step_by(1),
            KeyCode::Char('p') | KeyCode::Backspace => self.step_by(-1),
            KeyCode::Char('+') | KeyCode::Char('=') => self.zoom_by(1),
            KeyCode::Char('-') | KeyCode::Char('_') => self.zoom_by(-1),
            KeyCode::Char('g') => self.goto = Some(String::new()),
            KeyCode::Char('e') => self.expand_all(),
            KeyCode::Char('s') => self.next_sample(),
            KeyCode::PageDown => self.scroll_details(10),
            KeyCode::PageUp => self.scroll_details(-10),
            KeyCode::Char('t') => self.focus = Focus::Tree,
            KeyCode::Char('i') => self.focus = Focus::Image,
            code => match self.focus {
                Focus::Image => self.image_key(code),
                Focus::Tree => self.tree_key(code),
            },
        }
    }

    fn image_key(&mut self, code: KeyCode) {
        let step = self.cursor_step();
        let (x, y) = (i64::from(self.cursor.0), i64::from(self.cursor.1));
        let to = match code {
            KeyCode::Left | KeyCode::Char('h') => (x - step, y),
            KeyCode::Right | KeyCode::Char('l') => (x + step, y),
            KeyCode::Up | KeyCode::Char('k') => (x, y - step),
            KeyCode::Down | KeyCode::Char('j') => (x, y + step),
            KeyCode::Enter => {
                self.focus = Focus::Tree;
                return;
            }
            _ => return,
        };
        let (w, h) = self.image_size();
        self.select((
            to.0.clamp(0, i64::from(w) - 1) as u32,
            to.1.clamp(0, i64::from(h) - 1) as u32,
        ));
    }

    fn tree_key(&mut self, code: KeyCode) {
        let items = self.items();
        let Some(&(item, _)) = items.get(self.selected) else {
            return;
        };
        match code {
            KeyCode::Up | KeyCode::Char('k') => {
                self.selected = self.selected.saturating_sub(1);
                self.detail_scroll = 0;
            }
            KeyCode::Down | KeyCode::Char('j') => {
                self.selected = (self.selected + 1).min(items.len().saturating_sub(1));
                self.detail_scroll = 0;
            }
            KeyCode::Enter | KeyCode::Right | KeyCode::Char('l') => {
                if let Item::Ray(n) = item {
                    self.expanded.insert(n);
                }
            }
            KeyCode::Left | KeyCode::Char('h') => match item {
                Item::Ray(n) if self.expanded.contains(&n) => {
                    self.expanded.remove(&n);
                }
                _ => {
                    // Go to the parent line.
                    let parent = match item {
                        Item::Shadow(n, _) => Some(n),
                        Item::Ray(n) => self
                            .trace
                            .as_ref()
                            .and_then(|t| t.samples[self.sample].tree.nodes[n].parent),
                    };
                    if let Some(p) = parent {
                        self.select_node(p);
                    }
                }
            },
            _ => {}
        }
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

    fn expand_all(&mut self) {
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

    /// Moves `by` steps through the algorithm and selects the step's ray.
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
        self.step = Some(next as usize);
        self.select_node(self.steps[next as usize].node);
    }

    fn zoom_by(&mut self, by: i32) {
        let max = self.max_zoom();
        self.zoom = self.zoom.saturating_add_signed(by).min(max);
    }

    /// The deepest zoom: four dots per image pixel.
    pub fn max_zoom(&self) -> u32 {
        let fit = self.fit_scale();
        (0..16)
            .take_while(|&z| fit / f64::from(1u32 << z) >= 0.25)
            .last()
            .unwrap_or(0)
    }

    fn fit_scale(&self) -> f64 {
        let (w, h) = self.image_size();
        let (cols, rows) = (
            f64::from(self.areas.image.width.max(1)),
            f64::from(self.areas.image.height.max(1)) * 2.0,
        );
        (f64::from(w) / cols).max(f64::from(h) / rows)
    }

    /// How far one arrow press moves the cursor: one dot, but at least one pixel.
    fn cursor_step(&self) -> i64 {
        (self.window().scale.round() as i64).max(1)
    }

    /// The part of the image the pane shows: the whole image at zoom 0, else a
    /// window centered on the cursor, kept inside the image.
    pub fn window(&self) -> Window {
        let (w, h) = self.image_size();
        let (cols, rows) = (
            self.areas.image.width.max(1),
            self.areas.image.height.max(1) * 2,
        );
        let scale = self.fit_scale() / f64::from(1u32 << self.zoom.min(15));
        let (span_x, span_y) = (f64::from(cols) * scale, f64::from(rows) * scale);
        let place = |cursor: u32, span: f64, size: u32| {
            if span >= f64::from(size) {
                (f64::from(size) - span) / 2.0
            } else {
                (f64::from(cursor) + 0.5 - span / 2.0).clamp(0.0, f64::from(size) - span)
            }
        };
        Window {
            left: place(self.cursor.0, span_x, w),
            top: place(self.cursor.1, span_y, h),
            scale,
            cols,
            rows,
        }
    }

    /// Handles a mouse event: a left click on the image selects that pixel; on the
    /// tree, that line.
    pub fn on_mouse(&mut self, m: MouseEvent) {
        if self.areas.details.contains((m.column, m.row).into()) {
            match m.kind {
                MouseEventKind::ScrollDown => self.scroll_details(3),
                MouseEventKind::ScrollUp => self.scroll_details(-3),
                _ => {}
            }
            return;
        }
        if m.kind != MouseEventKind::Down(MouseButton::Left) {
            return;
        }
        let (img, tree) = (self.areas.image, self.areas.tree);
        if img.contains((m.column, m.row).into()) {
            let (i, j) = (m.column - img.x, (m.row - img.y) * 2);
            let (w, h) = self.image_size();
            if let Some(p) = self.window().pixel_at(i, j, w, h) {
                self.focus = Focus::Image;
                self.select(p);
            }
        } else if tree.contains((m.column, m.row).into()) {
            self.focus = Focus::Tree;
            let line = usize::from(m.row - tree.y) + self.tree_scroll(tree.height);
            if line < self.items().len() {
                self.selected = line;
            }
        }
    }

    /// The first tree line shown, so the selection stays in view.
    pub fn tree_scroll(&self, height: u16) -> usize {
        self.selected.saturating_sub(usize::from(height.max(1)) - 1)
    }

    fn go_to(&mut self, typed: &str) {
        let parsed = typed.split_once(',').and_then(|(x, y)| {
            Some((x.trim().parse::<u32>().ok()?, y.trim().parse::<u32>().ok()?))
        });
        let (w, h) = self.image_size();
        match parsed {
            Some((x, y)) if x < w && y < h => {
                self.message.clear();
                self.select((x, y));
            }
            Some((x, y)) => self.message = format!("pixel {x},{y} is outside the {w}×{h} image"),
            None => self.message = format!("'{typed}' is not a pixel: type x,y (e.g. 320,240)"),
        }
    }

    /// Asks the worker for the picture of the current window, if it changed.
    pub fn request_picture(&mut self) {
        let window = self.window();
        if self.requested != Some(window) {
            self.requested = Some(window);
            if let Some(w) = &self.worker {
                w.request(window);
            }
        }
    }

    /// Takes the newest picture the worker finished.
    pub fn receive_picture(&mut self) -> bool {
        match self.worker.as_ref().and_then(Worker::receive) {
            Some(p) => {
                self.picture = Some(p);
                true
            }
            None => false,
        }
    }

    /// Traces the picture of the current window here and now (tests, benchmarks).
    pub fn render_picture_now(&mut self) {
        if let Some(scene) = &self.scene {
            self.picture = super::preview::render_picture(scene, self.window(), 1, &|| false);
        }
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
