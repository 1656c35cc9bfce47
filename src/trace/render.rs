//! The full renderer: every pixel, in parallel on all cores.
//!
//! Each pixel depends on nothing but the scene, so the image is the same bit for
//! bit whatever the number of threads or the order tiles finish in.

use glam::DVec3;
use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::io::image::Image;
use crate::scene::Scene;
use crate::trace::pixel::pixel_color;
use crate::trace::recorder::{NoRecorder, RayCounter, Recorder};
use crate::trace::tracer::Tracer;

/// Pixels are traced in square tiles of this side.
const TILE: usize = 8;

/// Renders the scene at its settings' size, reporting finished rows to `progress`.
/// Fails only if the image's memory cannot be had.
pub fn render(
    scene: &Scene,
    progress: &ProgressBar,
) -> Result<Image, std::collections::TryReserveError> {
    render_with::<NoRecorder>(scene, progress).map(|(image, _)| image)
}

/// Renders and counts every ray cast, by kind.
pub fn render_counting(
    scene: &Scene,
    progress: &ProgressBar,
) -> Result<(Image, RayCounter), std::collections::TryReserveError> {
    render_with::<RayCounter>(scene, progress)
}

/// Renders with a tracer already built (its hierarchy too): what a sweep over
/// settings that share one hierarchy needs.
pub fn render_with_tracer(
    tracer: &Tracer,
    progress: &ProgressBar,
) -> Result<Image, std::collections::TryReserveError> {
    render_traced::<NoRecorder>(tracer, progress).map(|(image, _)| image)
}

/// Renders with a tracer already built (its hierarchy too), counting every ray
/// cast: what a benchmark that times the tracing alone needs.
pub fn render_counting_with(
    tracer: &Tracer,
    progress: &ProgressBar,
) -> Result<(Image, RayCounter), std::collections::TryReserveError> {
    render_traced::<RayCounter>(tracer, progress)
}

/// Renders with a fresh recorder of type `R` per row; the rows' recorders are
/// merged by `RayCounter::add` when `R` counts.
fn render_with<R: Recorder + Default + Send + Tally>(
    scene: &Scene,
    progress: &ProgressBar,
) -> Result<(Image, R), std::collections::TryReserveError> {
    render_traced(&Tracer::new(scene), progress)
}

fn render_traced<R: Recorder + Default + Send + Tally>(
    tracer: &Tracer,
    progress: &ProgressBar,
) -> Result<(Image, R), std::collections::TryReserveError> {
    let scene = tracer.scene();
    let (width, height) = (scene.settings.width, scene.settings.height);
    let mut pixels = Vec::new();
    pixels.try_reserve_exact(width as usize * height as usize)?;
    pixels.resize(width as usize * height as usize, DVec3::ZERO);
    let camera = scene.camera();
    progress.set_length(u64::from(height));
    // Bands of TILE rows, traced TILE × TILE pixels at a time: neighbouring rays
    // meet the same boxes and objects, which then stay in the cache.
    let tally = pixels
        .par_chunks_mut(TILE * width as usize)
        .enumerate()
        .map(|(band, rows)| {
            let mut rec = R::default();
            let y0 = band * TILE;
            let band_height = rows.len() / width as usize;
            for x0 in (0..width as usize).step_by(TILE) {
                for dy in 0..band_height {
                    for x in x0..(x0 + TILE).min(width as usize) {
                        let (px, py) = (x as u32, (y0 + dy) as u32);
                        rows[dy * width as usize + x] =
                            pixel_color(tracer, &camera, px, py, &mut rec);
                    }
                }
            }
            progress.inc(band_height as u64);
            rec
        })
        .reduce(R::default, R::merge);
    Ok((
        Image {
            width,
            height,
            pixels,
        },
        tally,
    ))
}

/// Recorders whose per-row results can be combined.
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
