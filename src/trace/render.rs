//! The one pixel loop: "for every pixel, on all cores" is written here and
//! nowhere else. The image, `--stats`, the AOVs, the inspector's picture and
//! its overlays each hand it only what happens at one pixel (as pbrt-v4's
//! `ImageTileIntegrator::Render` takes the per-pixel work of every integrator),
//! so a number shown in two places is counted by the same code.
//!
//! Each pixel depends on nothing but the scene, so the result is the same bit
//! for bit whatever the number of threads or the order the bands finish in.

use std::collections::TryReserveError;
use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use crate::io::image::Image;
use crate::methods::Antialiasing;
use crate::scene::Scene;
use crate::trace::pixel::{corner_mean, pixel_color};
use crate::trace::progress::Progress;
use crate::trace::recorder::{NoRecorder, RayCounter, Recorder};
use crate::trace::tracer::Tracer;

/// Cells are traced in bands of this many rows, and across a band in squares
/// of this side: neighbouring rays meet the same boxes and objects, which then
/// stay in the cache.
const TILE: u32 = 8;

/// Which pixels a pass traces: a grid of cells, each over one image pixel (or
/// off the image, where nothing is traced).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pixels {
    /// Every pixel of the image.
    All,
    /// Every `n`-th pixel across and down, from the top left.
    Every(u32),
    /// The `(W + 1) × (H + 1)` pixel corners: cell `(i, j)` is the top left
    /// corner of pixel `(i, j)`, the last row and column the bottom and right
    /// edges' ([`crate::methods::Antialiasing::Corners`]).
    Corners,
    /// A window onto the image: cell `(i, j)` is over the pixel under
    /// `(left + (i·step + ½)·scale, top + (j·step + ½)·scale)`; `cols × rows`
    /// is the window's size in `scale`-sized steps, so a `step` of 4 traces
    /// one of every 4 × 4 (a quick first pass).
    Window {
        /// Image x at the window's left edge.
        left: f64,
        /// Image y at the window's top edge.
        top: f64,
        /// Image pixels per step.
        scale: f64,
        /// Steps across.
        cols: u32,
        /// Steps down.
        rows: u32,
        /// Steps per cell.
        step: u32,
    },
}

impl Pixels {
    /// Cells across and down for an image of `width × height`.
    pub fn cells(&self, width: u32, height: u32) -> (u32, u32) {
        match *self {
            Pixels::All => (width, height),
            Pixels::Every(n) => (width.div_ceil(n.max(1)), height.div_ceil(n.max(1))),
            Pixels::Corners => (width + 1, height + 1),
            Pixels::Window {
                cols, rows, step, ..
            } => (cols.div_ceil(step.max(1)), rows.div_ceil(step.max(1))),
        }
    }

    /// The image pixel under cell `(i, j)`, if it is over the image (for
    /// [`Pixels::Corners`], the pixel whose top left corner the cell is, or
    /// the column and row past the last).
    pub fn pixel(&self, i: u32, j: u32, width: u32, height: u32) -> Option<(u32, u32)> {
        let (x, y) = match *self {
            Pixels::Corners => return (i <= width && j <= height).then_some((i, j)),
            Pixels::All => (i, j),
            Pixels::Every(n) => (i * n.max(1), j * n.max(1)),
            Pixels::Window {
                left,
                top,
                scale,
                step,
                ..
            } => {
                let x = left + (f64::from(i * step.max(1)) + 0.5) * scale;
                let y = top + (f64::from(j * step.max(1)) + 0.5) * scale;
                if !(x >= 0.0 && y >= 0.0 && x < f64::from(width) && y < f64::from(height)) {
                    return None;
                }
                (x as u32, y as u32)
            }
        };
        (x < width && y < height).then_some((x, y))
    }
}

/// What a pass made: a value per cell, row by row (the default where a cell
/// is off the image), and each band's own state (its recorder) to combine.
#[derive(Debug)]
pub struct Traced<S, T> {
    /// Cells across.
    pub cols: u32,
    /// Cells down.
    pub rows: u32,
    /// `cols × rows` values, row by row.
    pub cells: Vec<T>,
    /// Each band's state, top band first.
    pub bands: Vec<S>,
}

/// Why a pass stopped early.
#[derive(Debug)]
pub enum Stopped {
    /// [`Progress::cancelled`] said so.
    Cancelled,
    /// The cells' memory could not be had.
    NoMemory(TryReserveError),
}

/// The one pixel loop: for every cell of `pixels` over `scene`'s image, on all
/// cores of the current thread pool, `pixel(&mut state, x, y)` with the state
/// `start()` made for the cell's band. Reports rows of cells done to
/// `progress`, and stops between bands when it is cancelled.
pub fn trace_pixels<S, T>(
    scene: &Scene,
    pixels: Pixels,
    start: impl Fn() -> S + Sync,
    pixel: impl Fn(&mut S, u32, u32) -> T + Sync,
    progress: &Progress,
) -> Result<Traced<S, T>, Stopped>
where
    S: Send,
    T: Send + Default + Clone,
{
    let (width, height) = (scene.settings.width, scene.settings.height);
    let (cols, rows) = pixels.cells(width, height);
    let mut cells = Vec::new();
    let n = cols as usize * rows as usize;
    cells.try_reserve_exact(n).map_err(Stopped::NoMemory)?;
    cells.resize(n, T::default());
    let done = AtomicU64::new(0);
    let bands: Vec<Option<S>> = cells
        .par_chunks_mut((TILE * cols.max(1)) as usize)
        .enumerate()
        .map(|(band, band_cells)| {
            if progress.cancelled() {
                return None;
            }
            let mut state = start();
            let j0 = band as u32 * TILE;
            let band_rows = (band_cells.len() / cols.max(1) as usize) as u32;
            for i0 in (0..cols).step_by(TILE as usize) {
                for dj in 0..band_rows {
                    for i in i0..(i0 + TILE).min(cols) {
                        if let Some((x, y)) = pixels.pixel(i, j0 + dj, width, height) {
                            band_cells[(dj * cols + i) as usize] = pixel(&mut state, x, y);
                        }
                    }
                }
            }
            let finished = done.fetch_add(u64::from(band_rows), Ordering::Relaxed);
            progress.report(finished + u64::from(band_rows), u64::from(rows));
            Some(state)
        })
        .collect();
    let bands = bands
        .into_iter()
        .collect::<Option<Vec<S>>>()
        .ok_or(Stopped::Cancelled)?;
    Ok(Traced {
        cols,
        rows,
        cells,
        bands,
    })
}

/// Renders the scene at its settings' size, reporting rows done to `progress`.
/// Fails only if the image's memory cannot be had.
pub fn render(scene: &Scene, progress: &Progress) -> Result<Image, TryReserveError> {
    render_traced::<NoRecorder>(&Tracer::new(scene), progress).map(|(image, _)| image)
}

/// Renders and counts every ray cast, by kind, and every test (with each
/// thread remembering its recent shadow blockers from pixel to pixel, as a
/// render does).
pub fn render_counting(
    scene: &Scene,
    progress: &Progress,
) -> Result<(Image, RayCounter), TryReserveError> {
    render_traced(&Tracer::new(scene), progress)
}

/// Renders with a tracer already built (its hierarchy too): what a sweep over
/// settings that share one hierarchy needs.
pub fn render_with_tracer(tracer: &Tracer, progress: &Progress) -> Result<Image, TryReserveError> {
    render_traced::<NoRecorder>(tracer, progress).map(|(image, _)| image)
}

/// Renders with a tracer already built (its hierarchy too), counting every ray
/// cast: what a benchmark that times the tracing alone needs.
pub fn render_counting_with(
    tracer: &Tracer,
    progress: &Progress,
) -> Result<(Image, RayCounter), TryReserveError> {
    render_traced(tracer, progress)
}

/// The image, with a recorder of type `R` per band, the bands' recorders
/// combined by [`Tally::merge`]. Under the SPD protocol's sampling the pass
/// traces every pixel corner once, and each pixel is then the mean of its
/// four ([`corner_mean`], as a recorded pixel takes it).
fn render_traced<R: Recorder + Default + Send + Tally>(
    tracer: &Tracer,
    progress: &Progress,
) -> Result<(Image, R), TryReserveError> {
    let scene = tracer.scene();
    let camera = scene.camera();
    let corners = scene.settings.aa == Antialiasing::Corners;
    let traced = trace_pixels(
        scene,
        if corners {
            Pixels::Corners
        } else {
            Pixels::All
        },
        R::default,
        |rec, x, y| {
            if corners {
                let (sx, sy) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
                tracer.trace_primary(camera.pixel_ray(sx, sy), rec)
            } else {
                pixel_color(tracer, &camera, x, y, rec)
            }
        },
        // A render is never cancelled: only the reports pass through.
        &Progress::reporting(&|done, total| progress.report(done, total)),
    )
    .map_err(|stopped| match stopped {
        Stopped::NoMemory(e) => e,
        Stopped::Cancelled => unreachable!("a render reports but is never cancelled"),
    })?;
    let tally = traced.bands.into_iter().fold(R::default(), R::merge);
    let (width, height) = (scene.settings.width, scene.settings.height);
    let pixels = if corners {
        let corner = |x: u32, y: u32| traced.cells[(y * traced.cols + x) as usize];
        let mut pixels = Vec::new();
        pixels.try_reserve_exact(width as usize * height as usize)?;
        for y in 0..height {
            for x in 0..width {
                pixels.push(corner_mean([
                    corner(x, y),
                    corner(x + 1, y),
                    corner(x, y + 1),
                    corner(x + 1, y + 1),
                ]));
            }
        }
        pixels
    } else {
        traced.cells
    };
    Ok((
        Image {
            width,
            height,
            pixels,
        },
        tally,
    ))
}

/// Recorders whose per-band results can be combined.
trait Tally {
    fn merge(self, other: Self) -> Self;
}

impl Tally for NoRecorder {
    fn merge(self, _: Self) -> Self {
        self
    }
}

impl Tally for RayCounter {
    fn merge(mut self, other: Self) -> Self {
        self.add(&other);
        self
    }
}
