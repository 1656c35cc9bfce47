//! Speed against accuracy, measured: render one scene with a sweep of settings,
//! time each (median of several runs, alternating over the settings), and
//! measure its error against a converged reference of the same scene.
//! [`crate::views::chart`] draws the result.
//!
//! Only settings that keep the scene's model are swept: samples per pixel, depth,
//! cutoff, the ray–sphere method and the origin offset. The weights method
//! (constant, Schlick, Fresnel) changes what the image should be, so an "error"
//! against one reference would mean nothing for it.

use std::time::Instant;

use crate::io::image::{Image, to_rgb8};
use crate::methods::{Antialiasing, Offset, SphereMethod};
use crate::scene::Scene;
use crate::scene::settings::RenderSettings;
use crate::trace::progress::Progress;
use crate::trace::render::{render_counting_with, render_with_tracer};
use crate::trace::tracer::Tracer;

/// One point of the sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// What was changed from the defaults.
    pub label: String,
    /// The settings rendered.
    pub settings: RenderSettings,
    /// Median wall time of the renders, in seconds.
    pub seconds: f64,
    /// Intersection tests (bounding boxes and primitives) per pixel, when the
    /// sweep counted them ([`Cost::Tests`]).
    pub tests: Option<f64>,
    /// Root-mean-square error against the reference, linear RGB, per channel.
    pub rmse: f64,
    /// Share of pixels whose 8-bit value differs from the reference's by more than 1 in some channel.
    pub off: f64,
    /// Whether these are the default settings.
    pub default: bool,
}

/// What a sweep measures as the cost of a setting.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Cost {
    /// Wall time, the median of several runs: what a user waits for, but it
    /// moves from run to run on a busy machine.
    #[default]
    Time,
    /// Intersection tests per pixel (bounding boxes and primitives), counted
    /// on one thread: exact, the same on every run and machine; most of the
    /// time, though shading is not counted.
    // One thread: each thread remembers its own recent shadow blockers, so on
    // several the counts would depend on scheduling. Exact counts are what
    // figures that must not change from run to run (the book's) need.
    Tests,
}

/// The settings swept: the defaults, then one change at a time.
pub fn sweep(base: &RenderSettings) -> Vec<(String, RenderSettings, bool)> {
    let d = RenderSettings {
        spp: 1,
        max_depth: 8,
        cutoff: RenderSettings::DEFAULT_CUTOFF,
        sphere: SphereMethod::Stable,
        offset: Offset::Robust,
        aa: Antialiasing::Grid,
        ..*base
    };
    let mut out = vec![("default".to_owned(), d, true)];
    let mut add = |label: String, s: RenderSettings| out.push((label, s, false));
    for spp in [4, 16] {
        add(format!("{spp} spp"), RenderSettings { spp, ..d });
    }
    for max_depth in [2, 4, 16] {
        add(
            format!("depth {max_depth}"),
            RenderSettings { max_depth, ..d },
        );
    }
    add(
        "fixed depth (no cutoff)".to_owned(),
        RenderSettings { cutoff: 0.0, ..d },
    );
    add(
        "cutoff 1/64".to_owned(),
        RenderSettings {
            cutoff: 1.0 / 64.0,
            ..d
        },
    );
    add(
        "lecture sphere".to_owned(),
        RenderSettings {
            sphere: SphereMethod::Lecture,
            ..d
        },
    );
    add(
        "no offset".to_owned(),
        RenderSettings {
            offset: Offset::None,
            ..d
        },
    );
    add(
        "epsilon 1e-4".to_owned(),
        RenderSettings {
            offset: Offset::Epsilon(1e-4),
            ..d
        },
    );
    add(
        "4 spp, depth 16".to_owned(),
        RenderSettings {
            spp: 4,
            max_depth: 16,
            ..d
        },
    );
    for threshold in [0.05, 0.2] {
        add(
            format!("adaptive AA {threshold}"),
            RenderSettings {
                aa: Antialiasing::Adaptive {
                    threshold,
                    levels: 3,
                },
                ..d
            },
        );
    }
    out
}

/// The converged reference: 8 × 8 samples, depth 32, no cutoff, robust methods.
pub fn reference_settings(base: &RenderSettings) -> RenderSettings {
    RenderSettings {
        spp: 64,
        max_depth: 32,
        cutoff: 0.0,
        sphere: SphereMethod::Stable,
        offset: Offset::Robust,
        aa: Antialiasing::Grid,
        ..*base
    }
}

/// Renders every setting of the sweep and measures it: `runs` times each for
/// [`Cost::Time`], once, counting its tests, for [`Cost::Tests`]. The scene's
/// hierarchy is built once and shared by every setting (none of them changes
/// the objects), so only tracing is timed.
pub fn measure(scene: &Scene, runs: usize, cost: Cost, progress: &Progress) -> Vec<Point> {
    let points = sweep(&scene.settings);
    let total = points.len() as u64 + 1;
    let base = Tracer::new(scene);
    let pixels = f64::from(scene.settings.width) * f64::from(scene.settings.height);
    let one_thread = (cost == Cost::Tests).then(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .expect("one worker thread can be started")
    });
    let render = |settings: RenderSettings| {
        let mut s = scene.clone();
        s.settings = settings;
        let tracer = base.with_settings(&s);
        let started = Instant::now();
        let (image, tests) = match cost {
            Cost::Time => (render_with_tracer(&tracer, &Progress::QUIET), None),
            Cost::Tests => match one_thread
                .as_ref()
                .map(|pool| pool.install(|| render_counting_with(&tracer, &Progress::QUIET)))
                .expect("built for counting")
            {
                Ok((image, counts)) => (Ok(image), Some(counts.tests() as f64 / pixels)),
                Err(e) => (Err(e), None),
            },
        };
        let image = image.expect("the size was validated");
        (image, started.elapsed().as_secs_f64(), tests)
    };
    let (reference, _, _) = render(reference_settings(&scene.settings));
    progress.report(1, total);
    let reference8 = to_rgb8(&reference);
    let runs = if cost == Cost::Tests { 1 } else { runs.max(1) };
    // Runs alternate over the settings, so a machine that slows down or speeds up
    // during the sweep shifts every setting alike.
    let mut times = vec![Vec::with_capacity(runs); points.len()];
    let mut images = vec![None; points.len()];
    let mut tests = vec![None; points.len()];
    for run in 0..runs {
        for (k, (_, settings, _)) in points.iter().enumerate() {
            let (image, seconds, counted) = render(*settings);
            times[k].push(seconds);
            images[k] = Some(image);
            tests[k] = counted;
        }
        progress.report(1 + (points.len() * (run + 1) / runs) as u64, total);
    }
    points
        .into_iter()
        .zip(times)
        .zip(images.into_iter().zip(tests))
        .map(
            |(((label, settings, default), mut times), (image, tests))| {
                times.sort_by(f64::total_cmp);
                let image = image.expect("at least one run");
                Point {
                    label,
                    settings,
                    seconds: times[times.len() / 2],
                    tests,
                    rmse: rmse(&image, &reference),
                    off: share_off(&to_rgb8(&image), &reference8),
                    default,
                }
            },
        )
        .collect()
}

/// Root-mean-square difference per channel, linear RGB.
pub fn rmse(a: &Image, b: &Image) -> f64 {
    let sum: f64 = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| (*p - *q).length_squared())
        .sum();
    (sum / (3.0 * a.pixels.len() as f64)).sqrt()
}

/// The share of pixels off by more than one 8-bit level in some channel.
pub fn share_off(a: &[u8], b: &[u8]) -> f64 {
    let off = a
        .chunks(3)
        .zip(b.chunks(3))
        .filter(|(p, q)| p.iter().zip(q.iter()).any(|(x, y)| x.abs_diff(*y) > 1))
        .count();
    off as f64 / (a.len() / 3) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_count_what_they_say() {
        use glam::DVec3;
        let a = Image {
            width: 2,
            height: 1,
            pixels: vec![DVec3::ZERO, DVec3::ONE],
        };
        let b = Image {
            width: 2,
            height: 1,
            pixels: vec![DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0)],
        };
        // One channel of six differs by 1: RMSE √(1/6).
        assert!((rmse(&a, &b) - (1.0f64 / 6.0).sqrt()).abs() < 1e-15);
        assert_eq!(
            share_off(&[0, 0, 0, 10, 10, 10], &[1, 0, 0, 10, 10, 12]),
            0.5
        );
    }
}
