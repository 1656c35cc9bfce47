//! The image pane's picture: the scene traced at the pane's resolution on a
//! worker thread, a coarse pass first and then every dot, so the first frame is
//! quick and input is never blocked. A newer request cancels an older one.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};

use super::traced_scene::TracedScene;
use crate::io::image::rgb8;
use crate::trace::pixel::pixel_color;
use crate::trace::progress::Progress;
use crate::trace::recorder::NoRecorder;
use crate::trace::render::{Pixels, trace_pixels};
use crate::trace::tracer::Tracer;

/// Which image pixels the pane's dots show: dot `(i, j)` shows the image pixel
/// under `(left + (i + ½)·scale, top + (j + ½)·scale)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Image x at the pane's left edge.
    pub left: f64,
    /// Image y at the pane's top edge.
    pub top: f64,
    /// Image pixels per dot.
    pub scale: f64,
    /// Dots across.
    pub cols: u16,
    /// Dots down (two per terminal row).
    pub rows: u16,
}

impl Window {
    /// The image pixel under dot `(i, j)`, if the dot is over the image (as
    /// the pixel loop maps it).
    pub fn pixel_at(&self, i: u16, j: u16, width: u32, height: u32) -> Option<(u32, u32)> {
        self.cells(1)
            .pixel(u32::from(i), u32::from(j), width, height)
    }

    /// The window as the pixel loop's cells, one traced every `step` dots.
    fn cells(&self, step: u16) -> Pixels {
        Pixels::Window {
            left: self.left,
            top: self.top,
            scale: self.scale,
            cols: u32::from(self.cols),
            rows: u32::from(self.rows),
            step: u32::from(step),
        }
    }

    /// The dot over the center of image pixel `(x, y)`, if it is in the pane.
    pub fn dot_of(&self, x: u32, y: u32) -> Option<(u16, u16)> {
        let i = ((f64::from(x) + 0.5 - self.left) / self.scale).floor();
        let j = ((f64::from(y) + 0.5 - self.top) / self.scale).floor();
        (i >= 0.0 && j >= 0.0 && i < f64::from(self.cols) && j < f64::from(self.rows))
            .then_some((i as u16, j as u16))
    }
}

/// A picture of the pane: one color per dot, `None` where nothing is known yet.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    /// The window it shows.
    pub window: Window,
    /// `cols × rows` dots, row by row.
    pub dots: Vec<Option<[u8; 3]>>,
    /// Whether every dot has its own color (else a coarse pass filled blocks).
    pub complete: bool,
}

/// Traces the picture for `window`: pass 0 traces one dot in every 4 × 4 block
/// and fills the block; pass 1 traces every dot. Stops early (returns `None`)
/// when `cancelled` says a newer window is wanted.
pub fn render_picture(
    tracer: &Tracer,
    window: Window,
    pass: u8,
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Option<Picture> {
    let scene = tracer.scene();
    let (w, h) = (scene.settings.width, scene.settings.height);
    let camera = scene.camera();
    let step: u16 = if pass == 0 { 4 } else { 1 };
    let pixels = window.cells(step);
    let traced = trace_pixels(
        scene,
        pixels,
        || NoRecorder,
        |rec, x, y| Some(rgb8(pixel_color(tracer, &camera, x, y, rec))),
        &Progress::cancellable(cancelled),
    )
    .ok()?;
    let rows = traced
        .cells
        .chunks(traced.cols.max(1) as usize)
        .map(<[Option<[u8; 3]>]>::to_vec);
    let mut dots = vec![None; usize::from(window.cols) * usize::from(window.rows)];
    for (bj, row) in rows.enumerate() {
        for (bi, c) in row.into_iter().enumerate() {
            for j in (bj * usize::from(step))
                ..((bj + 1) * usize::from(step)).min(usize::from(window.rows))
            {
                for i in (bi * usize::from(step))
                    ..((bi + 1) * usize::from(step)).min(usize::from(window.cols))
                {
                    // In the coarse pass a block takes its traced dot's color where that dot is over the image.
                    if window.pixel_at(i as u16, j as u16, w, h).is_some() {
                        dots[j * usize::from(window.cols) + i] = c;
                    }
                }
            }
        }
    }
    Some(Picture {
        window,
        dots,
        complete: pass == 1,
    })
}

/// The worker: takes windows, sends back pictures (coarse, then complete).
pub struct Worker {
    requests: Sender<Window>,
    pictures: Receiver<Picture>,
    latest: Arc<AtomicU64>,
}

impl Worker {
    /// Starts the worker thread for `scene`, whose hierarchy it shares.
    pub(in crate::inspector) fn start(scene: TracedScene) -> Self {
        let (requests, inbox) = channel::<Window>();
        let (outbox, pictures) = channel();
        // Each request bumps `latest`; a pass in progress stops when it moves on.
        let latest = Arc::new(AtomicU64::new(0));
        let newest = Arc::clone(&latest);
        std::thread::spawn(move || {
            while let Ok(mut window) = inbox.recv() {
                // Only the newest request matters.
                while let Ok(newer) = inbox.try_recv() {
                    window = newer;
                }
                let mine = newest.load(Ordering::SeqCst);
                let stale = || newest.load(Ordering::SeqCst) != mine;
                for pass in 0..2 {
                    match render_picture(&scene.tracer(), window, pass, &stale) {
                        Some(p) => {
                            if outbox.send(p).is_err() {
                                return;
                            }
                        }
                        None => break,
                    }
                }
            }
        });
        Self {
            requests,
            pictures,
            latest,
        }
    }

    /// Asks for the picture of `window`.
    pub fn request(&self, window: Window) {
        self.latest.fetch_add(1, Ordering::SeqCst);
        let _ = self.requests.send(window);
    }

    /// The newest picture that arrived, if any.
    pub fn receive(&self) -> Option<Picture> {
        self.pictures.try_iter().last()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn window_maps_dots_to_pixels_and_back() {
        let w = Window {
            left: 0.0,
            top: 0.0,
            scale: 8.0,
            cols: 80,
            rows: 60,
        };
        // Dot (0, 0) shows the pixel under (4, 4); dot (79, 59) the one under (636, 476).
        assert_eq!(w.pixel_at(0, 0, 640, 480), Some((4, 4)));
        assert_eq!(w.pixel_at(79, 59, 640, 480), Some((636, 476)));
        assert_eq!(w.dot_of(636, 476), Some((79, 59)));
        // Zoomed in, 4 dots per pixel: pixel (10, 20) is under dot ((10.5 - 8)/0.25, (20.5 - 16)/0.25) = (10, 18).
        let z = Window {
            left: 8.0,
            top: 16.0,
            scale: 0.25,
            cols: 40,
            rows: 40,
        };
        assert_eq!(z.dot_of(10, 20), Some((10, 18)));
        assert_eq!(z.pixel_at(10, 18, 640, 480), Some((10, 20)));
        assert_eq!(z.dot_of(100, 20), None);
    }

    #[test]
    fn coarse_pass_fills_blocks_and_fine_pass_every_dot() {
        let scene = crate::scene::loader::whitted();
        let tracer = Tracer::new(&scene);
        let window = Window {
            left: 0.0,
            top: 0.0,
            scale: 16.0,
            cols: 40,
            rows: 30,
        };
        let coarse = render_picture(&tracer, window, 0, &|| false).unwrap();
        let fine = render_picture(&tracer, window, 1, &|| false).unwrap();
        assert!(coarse.dots.iter().all(Option::is_some) && fine.dots.iter().all(Option::is_some));
        assert!(!coarse.complete && fine.complete);
        // The coarse pass is exact on the dots it traced.
        assert_eq!(coarse.dots[4 * 40 + 8], fine.dots[4 * 40 + 8]);
        // A cancelled pass gives nothing.
        assert!(render_picture(&tracer, window, 1, &|| true).is_none());
    }
}
