//! What happens in each pixel, in a few numbers: whether its tree holds a
//! total internal reflection, a blocked shadow ray, a refraction, a branch cut
//! by the weight cutoff, a missed primary ray, how deep it goes, how many rays
//! and tests it costs. Read from the per-pixel record that `render --aov`
//! reads too (no tree is built), so an overlay shows the AOV's numbers; the
//! inspector finds pixels and colors its overlays from it.

use crate::scene::Scene;
use crate::trace::pixel_record::{SampleRecord, record_pixel};
use crate::trace::progress::Progress;
use crate::trace::render::{Pixels, trace_pixels};
use crate::trace::tracer::Tracer;

/// One pixel's features.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Features {
    /// A ray was totally internally reflected.
    pub tir: bool,
    /// A shadow ray was blocked.
    pub blocked: bool,
    /// A refracted ray was traced.
    pub refraction: bool,
    /// A branch was skipped by the weight cutoff.
    pub cutoff: bool,
    /// A primary ray hit nothing.
    pub miss: bool,
    /// The deepest ray (1: only primary rays).
    pub depth: u32,
    /// Rays cast, shadow rays included.
    pub rays: u32,
    /// Boxes and primitives tested.
    pub tests: u32,
}

impl Features {
    /// A pixel's features from its record: what any of its samples met.
    pub fn of(samples: &[SampleRecord]) -> Features {
        let count = |n: u64| u32::try_from(n).unwrap_or(u32::MAX);
        Features {
            tir: samples.iter().any(|s| s.tir),
            blocked: samples.iter().any(|s| s.blocked),
            refraction: samples.iter().any(|s| s.refraction),
            cutoff: samples.iter().any(|s| s.cutoff),
            miss: samples.iter().any(|s| s.hit.is_none()),
            depth: samples.iter().map(|s| s.depth).max().unwrap_or(0),
            rays: count(samples.iter().map(|s| s.rays.total()).sum()),
            tests: count(samples.iter().map(|s| s.tests).sum()),
        }
    }
}

/// The features of pixel `(x, y)`, recorded on its own (as `raytree trace`
/// and `render --aov` record it).
pub fn of_pixel(tracer: &Tracer, scene: &Scene, x: u32, y: u32) -> Features {
    Features::of(&record_pixel(tracer, &scene.camera(), x, y, None).samples)
}

/// The features of every `stride`-th pixel across and down, row by row,
/// through the one pixel loop: `(columns, rows, features)`.
pub fn scan(scene: &Scene, stride: u32) -> FeatureMap {
    scan_with(&Tracer::new(scene), stride)
}

/// [`scan`] with `tracer`, made beforehand for its scene.
pub fn scan_with(tracer: &Tracer, stride: u32) -> FeatureMap {
    let stride = stride.max(1);
    let scene = tracer.scene();
    let traced = trace_pixels(
        scene,
        Pixels::Every(stride),
        || (),
        |_, x, y| of_pixel(tracer, scene, x, y),
        &Progress::QUIET,
    )
    .expect("the scene's size is capped on loading, so a cell per pixel fits in memory");
    FeatureMap {
        stride,
        cols: traced.cols,
        rows: traced.rows,
        cells: traced.cells,
    }
}

/// Features over the image, every `stride`-th pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct FeatureMap {
    /// Image pixels between two cells.
    pub stride: u32,
    /// Cells across.
    pub cols: u32,
    /// Cells down.
    pub rows: u32,
    /// Row by row.
    pub cells: Vec<Features>,
}

impl FeatureMap {
    /// The cell holding image pixel `(x, y)`.
    pub fn at(&self, x: u32, y: u32) -> Features {
        let (i, j) = (
            (x / self.stride).min(self.cols - 1),
            (y / self.stride).min(self.rows - 1),
        );
        self.cells[(j * self.cols + i) as usize]
    }

    /// The next pixel in reading order after `from` that has `want`, skipping
    /// the run of such pixels `from` is in (so repeated finds move on to the
    /// next place, not the next pixel); wraps around the image.
    pub fn next(&self, from: (u32, u32), want: impl Fn(&Features) -> bool) -> Option<(u32, u32)> {
        let n = self.cells.len();
        let start = ((from.1 / self.stride).min(self.rows - 1) * self.cols
            + (from.0 / self.stride).min(self.cols - 1)) as usize;
        let mut leaving = want(&self.cells[start]);
        for k in 1..=n {
            let c = (start + k) % n;
            let has = want(&self.cells[c]);
            if leaving {
                leaving = has;
                continue;
            }
            if has {
                let (i, j) = (c as u32 % self.cols, c as u32 / self.cols);
                return Some((i * self.stride, j * self.stride));
            }
        }
        None
    }

    /// The pixel worth starting on: the deepest tree, nearest the image's
    /// center among equals.
    pub fn most_interesting(&self, width: u32, height: u32) -> (u32, u32) {
        let center = (f64::from(width) / 2.0, f64::from(height) / 2.0);
        let score = |c: usize| {
            let f = &self.cells[c];
            let (x, y) = (
                c as u32 % self.cols * self.stride,
                c as u32 / self.cols * self.stride,
            );
            let d = (f64::from(x) - center.0).hypot(f64::from(y) - center.1);
            (f.depth + u32::from(f.tir), -d)
        };
        let best = (0..self.cells.len())
            .max_by(|&a, &b| {
                let (a, b) = (score(a), score(b));
                a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
            })
            .unwrap_or(0) as u32;
        (
            best % self.cols * self.stride,
            best / self.cols * self.stride,
        )
    }
}
