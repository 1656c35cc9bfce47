//! What happens in each pixel, in a few numbers: whether its tree holds a
//! total internal reflection, a blocked shadow ray, a refraction, a branch cut
//! by the weight cutoff, a missed primary ray, how deep it goes, how many rays
//! and tests it costs. A recorder that only counts (no tree is built), so the
//! whole image is scanned in about a second; the inspector finds pixels and
//! colors its overlays from it.

use rayon::prelude::*;

use crate::geometry::hit::TestCounts;
use crate::scene::Scene;
use crate::trace::pixel::pixel_color;
use crate::trace::recorder::{
    Branch, BranchEvent, RayKind, RayStart, Recorder, ShadowEvent, ShadowOutcome, SumEvent,
};
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

/// Counts into [`Features`] as the tracer runs.
#[derive(Default)]
struct Counter {
    features: Features,
    depths: Vec<u32>,
}

impl Recorder for Counter {
    // Test counts come only with the detailed events.
    const ENABLED: bool = true;

    fn ray_started(&mut self, start: &RayStart) {
        self.features.rays += 1;
        self.features.depth = self.features.depth.max(start.depth);
        self.depths.push(start.depth);
    }

    fn tested(&mut self, tested: &TestCounts) {
        self.features.tests += tested.boxes + tested.primitives;
    }

    fn missed(&mut self) {
        if self.depths.last() == Some(&1) {
            self.features.miss = true;
        }
    }

    fn shadow_ray(&mut self, shadow: &ShadowEvent) {
        if !matches!(shadow.outcome, ShadowOutcome::FacesAway) {
            self.features.rays += 1;
            self.features.tests += shadow.tested.boxes + shadow.tested.primitives;
        }
        if matches!(shadow.outcome, ShadowOutcome::Blocked { .. }) {
            self.features.blocked = true;
        }
    }

    fn branch(&mut self, branch: &BranchEvent) {
        match branch.branch {
            Branch::TotalInternalReflection => self.features.tir = true,
            Branch::WeightCutoff => self.features.cutoff = true,
            Branch::Traced if branch.kind == RayKind::Refracted => self.features.refraction = true,
            _ => {}
        }
    }

    fn ray_finished(&mut self, _sum: &SumEvent) {
        self.depths.pop();
    }
}

/// The features of pixel `(x, y)`.
pub fn of_pixel(tracer: &Tracer, scene: &Scene, x: u32, y: u32) -> Features {
    let mut counter = Counter::default();
    pixel_color(tracer, &scene.camera(), x, y, &mut counter);
    counter.features
}

/// The features of every `stride`-th pixel across and down, row by row, on all
/// cores: `(columns, rows, features)`.
pub fn scan(scene: &Scene, stride: u32) -> FeatureMap {
    let stride = stride.max(1);
    let tracer = Tracer::new(scene);
    let (w, h) = (scene.settings.width, scene.settings.height);
    let (cols, rows) = (w.div_ceil(stride), h.div_ceil(stride));
    let cells: Vec<Features> = (0..rows)
        .into_par_iter()
        .flat_map_iter(|j| {
            let tracer = &tracer;
            (0..cols).map(move |i| of_pixel(tracer, scene, i * stride, j * stride))
        })
        .collect();
    FeatureMap {
        stride,
        cols,
        rows,
        cells,
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
                score(a)
                    .partial_cmp(&score(b))
                    .expect("distances are finite")
            })
            .unwrap_or(0) as u32;
        (
            best % self.cols * self.stride,
            best / self.cols * self.stride,
        )
    }
}
