//! The image pane's state: how far it is zoomed, the picture it shows, and the
//! worker that traces that picture on its own thread. The update step asks for
//! the picture of the window the pane shows and takes it once traced, so a key
//! never waits for tracing.

use ratatui::layout::Rect;

use super::preview::{Picture, Window, Worker};
use super::traced_scene::TracedScene;

/// The zoom, the picture and the worker.
pub(in crate::inspector) struct ImageView {
    /// 0 fits the whole image; each level doubles the magnification.
    zoom: u32,
    /// What the pane shows, once traced.
    picture: Option<Picture>,
    /// Traces pictures, when live (tests trace them here and now instead).
    worker: Option<Worker>,
    /// The window last asked for.
    requested: Option<Window>,
}

impl ImageView {
    /// Fitting the whole image, nothing traced yet; `worker` traces the pictures.
    pub fn new(worker: Option<Worker>) -> Self {
        Self {
            zoom: 0,
            picture: None,
            worker,
            requested: None,
        }
    }

    /// The zoom level.
    pub fn zoom(&self) -> u32 {
        self.zoom
    }

    /// Zooms `by` levels, from fitting the image to four dots per pixel, for
    /// an image of `size` in a pane of `pane` cells.
    pub fn zoom_by(&mut self, by: i32, size: (u32, u32), pane: Rect) {
        let max = max_zoom(size, pane);
        self.zoom = self.zoom.saturating_add_signed(by).min(max);
    }

    /// The part of an image of `size` a pane of `pane` cells shows: the whole
    /// image at zoom 0, else a window centered on `cursor`, kept inside the image.
    pub fn window(&self, size: (u32, u32), cursor: (u32, u32), pane: Rect) -> Window {
        let (w, h) = size;
        let (cols, rows) = (pane.width.max(1), pane.height.max(1) * 2);
        let scale = fit_scale(size, pane) / f64::from(1u32 << self.zoom.min(15));
        let (span_x, span_y) = (f64::from(cols) * scale, f64::from(rows) * scale);
        let place = |cursor: u32, span: f64, size: u32| {
            if span >= f64::from(size) {
                (f64::from(size) - span) / 2.0
            } else {
                (f64::from(cursor) + 0.5 - span / 2.0).clamp(0.0, f64::from(size) - span)
            }
        };
        Window {
            left: place(cursor.0, span_x, w),
            top: place(cursor.1, span_y, h),
            scale,
            cols,
            rows,
        }
    }

    /// The picture traced last, if any.
    pub fn picture(&self) -> Option<&Picture> {
        self.picture.as_ref()
    }

    /// Shows `picture` (traced elsewhere: tests, benchmarks).
    pub fn set_picture(&mut self, picture: Option<Picture>) {
        self.picture = picture;
    }

    /// Asks the worker for the picture of `window`, if it changed.
    pub fn request(&mut self, window: Window) {
        if self.requested != Some(window) {
            self.requested = Some(window);
            if let Some(w) = &self.worker {
                w.request(window);
            }
        }
    }

    /// Takes the newest picture the worker finished, if one came; returns
    /// whether one did.
    pub fn receive(&mut self) -> bool {
        match self.worker.as_ref().and_then(Worker::receive) {
            Some(p) => {
                self.picture = Some(p);
                true
            }
            None => false,
        }
    }

    /// The scene changed: a worker for `scene` (when live), no picture, none asked for.
    pub fn restart(&mut self, scene: &TracedScene) {
        if self.worker.is_some() {
            self.worker = Some(Worker::start(scene.clone()));
        }
        self.picture = None;
        self.requested = None;
    }
}

/// The deepest zoom for an image of `size` in a pane of `pane` cells: four
/// dots per image pixel.
fn max_zoom(size: (u32, u32), pane: Rect) -> u32 {
    let fit = fit_scale(size, pane);
    (0..16)
        .take_while(|&z| fit / f64::from(1u32 << z) >= 0.25)
        .last()
        .unwrap_or(0)
}

/// Image pixels per dot when the whole image fits the pane.
fn fit_scale((w, h): (u32, u32), pane: Rect) -> f64 {
    let (cols, rows) = (
        f64::from(pane.width.max(1)),
        f64::from(pane.height.max(1)) * 2.0,
    );
    (f64::from(w) / cols).max(f64::from(h) / rows)
}
