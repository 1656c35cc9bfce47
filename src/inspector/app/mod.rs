//! The inspector's state, apart from any terminal so it can be tested
//! directly: [`App`] holds the scene and what the inspector says and is
//! asked, and composes the parts that own the rest (the selection, stepping,
//! finding, what-if edits, the image pane, the screen), all behind private
//! fields and the small API here that the binary, the tests and the drawing
//! read. `app/keys.rs` turns keys and clicks into changes; `app/changes.rs`
//! makes the changes that reach across parts.

mod changes;
mod keys;

use std::time::Duration;

use super::layout::{Areas, Screen};
use super::state::find::Finding;
use super::state::image_view::ImageView;
use super::state::preview::{Picture, Window, Worker};
use super::state::reveal::Revealed;
use super::state::selection::{Focus, Item, Selection};
use super::state::stepping::{Guided, Stepping};
use super::state::traced_scene::TracedScene;
use super::state::whatif::WhatIf;
use crate::scene::Scene;
use crate::scene::source::SceneSource;
use crate::tree::document::TraceDocument;
use crate::tree::steps::Step;
use crate::views::diagram::arrange::{Objects, layout_of};
use crate::views::diagram::layout::Layout;
use crate::views::diagram::options::Options;

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

/// The inspector's state: the scene and what the inspector says and is
/// asked, and the parts that own the rest.
pub struct App {
    /// The scene, when known (a saved trace may come without it); the edited
    /// one while what-if edits are in effect. With its hierarchy, built once.
    scene: Option<TracedScene>,
    /// Names the scene in traces.
    source: SceneSource,
    /// The pixel, its trace, the focus, the tree pane's cursor.
    selection: Selection,
    /// Where in the algorithm's steps the panes are.
    stepping: Stepping,
    /// A guided step-through, when following one.
    guide: Option<Guided>,
    /// What `f` seeks, the overlay, the image's features.
    finding: Finding,
    /// The what-if edits in effect.
    what_if: WhatIf,
    /// The image pane's zoom, picture and worker.
    image: ImageView,
    /// The pane areas, the small terminal's right-hand pane, the help.
    screen: Screen,
    /// A line being typed (go to, edit, write), while open.
    prompt: Option<Prompt>,
    /// A one-line message for the status bar, answering the last key.
    message: String,
    /// The user asked to quit.
    quit: bool,
    /// The last key asked to quit with unsaved edits: another quits.
    quit_asked: bool,
    /// Draw in 24-bit color (else the 256-color palette).
    truecolor: bool,
    /// Why the terminal is drawn in 256 colors, when it is.
    color_note: Option<String>,
    /// The saved trace's file, when the inspector opened one (no timing then).
    loaded_from: Option<String>,
}

impl App {
    /// An inspector on `scene`, the cursor at `start` (or at a pixel worth
    /// looking at: the deepest tree, nearest the center). `live` starts the
    /// preview worker; tests leave it off and call [`App::render_picture_now`].
    pub fn new(scene: Scene, source: SceneSource, start: Option<(u32, u32)>, live: bool) -> Self {
        let s = scene.settings;
        let scene = TracedScene::new(scene);
        let start = start.unwrap_or_else(|| {
            // A coarse scan (every 8th pixel) is quick even for large images.
            super::state::features::scan_with(&scene.tracer(), 8)
                .most_interesting(s.width, s.height)
        });
        let worker = live.then(|| Worker::start(scene.clone()));
        let mut app = Self::empty(Some(scene), source, worker);
        app.select(start);
        app
    }

    /// An inspector on a saved trace; `scene` is the scene it names, when found.
    pub fn from_trace(trace: TraceDocument, scene: Option<Scene>, live: bool) -> Self {
        let scene = scene.map(TracedScene::new);
        let worker = if live {
            scene.as_ref().map(|s| Worker::start(s.clone()))
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

    fn empty(scene: Option<TracedScene>, source: SceneSource, worker: Option<Worker>) -> Self {
        Self {
            scene,
            source,
            selection: Selection::default(),
            stepping: Stepping::default(),
            guide: None,
            finding: Finding::new(worker.is_some()),
            what_if: WhatIf::default(),
            image: ImageView::new(worker),
            screen: Screen::default(),
            prompt: None,
            message: String::new(),
            quit: false,
            quit_asked: false,
            truecolor: true,
            color_note: None,
            loaded_from: None,
        }
    }

    /// Takes the newest picture the worker finished and the image's features
    /// if their scan finished (a pending `f` then goes to what it finds);
    /// returns whether anything came.
    pub(super) fn receive(&mut self) -> bool {
        let picture = self.image.receive();
        let Some(arrived) = self.finding.receive(self.cursor()) else {
            return picture;
        };
        self.message = arrived.said;
        if let Some(p) = arrived.found {
            self.select(p);
        }
        true
    }

    /// Asks the worker for the picture of the image pane's window.
    pub(super) fn request_picture(&mut self) {
        self.image.request(self.window());
    }

    /// Scrolls the selected ray's numbers to line `top`.
    pub(super) fn scroll_details_to(&mut self, top: u16) {
        self.selection.set_scroll(top);
    }

    /// Whether the user asked to quit.
    pub fn quitting(&self) -> bool {
        self.quit
    }

    /// The status bar's message.
    pub fn message(&self) -> &str {
        &self.message
    }

    /// Shows `message` in the status bar (until the next key).
    pub fn set_message(&mut self, message: String) {
        self.message = message;
    }

    /// Draws in 24-bit color, or in the 256-color palette with `note` saying why.
    pub fn set_colors(&mut self, truecolor: bool, note: Option<String>) {
        self.truecolor = truecolor;
        self.color_note = note;
    }

    /// Why the terminal is drawn in 256 colors, when it is.
    pub fn color_note(&self) -> Option<&str> {
        self.color_note.as_deref()
    }

    /// Says the trace shown was loaded from `file` (so there is no time to trace).
    pub fn set_loaded_from(&mut self, file: String) {
        self.loaded_from = Some(file);
    }

    /// The saved trace's file, when the inspector opened one.
    pub(super) fn loaded_from(&self) -> Option<&str> {
        self.loaded_from.as_deref()
    }

    /// Whether to draw in 24-bit color.
    pub(super) fn truecolor(&self) -> bool {
        self.truecolor
    }

    /// The scene, when known.
    pub fn scene(&self) -> Option<&Scene> {
        self.scene.as_ref().map(|s| &**s.scene())
    }

    /// Names the scene in traces.
    pub(super) fn source(&self) -> &SceneSource {
        &self.source
    }

    /// The line being typed, while open.
    pub(super) fn prompt(&self) -> Option<&Prompt> {
        self.prompt.as_ref()
    }

    /// Where the panes were last laid out (by [`tick`](crate::inspector::tick)).
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
        match (self.scene(), self.selection.trace()) {
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

    /// The tree pane's lines: the item and its indentation; while stepping,
    /// only the rays spawned and shadow rays cast so far.
    pub fn items(&self) -> Vec<(Item, usize)> {
        self.selection.items(&self.revealed())
    }

    /// The selected tree line's item.
    pub fn selected_item(&self) -> Option<Item> {
        self.selection.selected_item(&self.revealed())
    }

    /// The zoom level: 0 fits the whole image; each level doubles the magnification.
    pub fn zoom(&self) -> u32 {
        self.image.zoom()
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
    pub fn picture(&self) -> Option<&Picture> {
        self.image.picture()
    }

    /// Traces the picture of the current window here and now (tests, benchmarks).
    pub fn render_picture_now(&mut self) {
        if let Some(scene) = &self.scene {
            let picture =
                super::state::preview::render_picture(&scene.tracer(), self.window(), 1, &|| false);
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

    /// The diagram pane's layout: the pixel's rays (while stepping, those
    /// computed so far), with the same projection and honesty rules as
    /// `raytree diagram`, and the objects they met (every object, in a scene
    /// without a hierarchy): drawn again at every key, it must not cost a
    /// million objects' projections. `None` without a scene or a trace.
    pub fn diagram(&self) -> Option<Layout> {
        let options = Options {
            sample: self.selection.sample(),
            until_step: self.step(),
            ..Options::default()
        };
        layout_of(self.trace()?, self.scene()?, &options, Objects::Met).ok()
    }

    /// The what-if edits and the pixel before them.
    pub(super) fn what_if(&self) -> &WhatIf {
        &self.what_if
    }
}
