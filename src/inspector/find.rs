//! Finding pixels worth a look (a total internal reflection, a blocked shadow
//! ray, …) and the image overlays that mark them or color the image by a
//! per-pixel count.

use std::time::Instant;

use super::app::App;
use super::features::{FeatureMap, Features};

/// What `f` looks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seek {
    /// A total internal reflection.
    Tir,
    /// A blocked shadow ray.
    Blocked,
    /// A traced refracted ray.
    Refraction,
    /// A tree at least this deep.
    Deep(u32),
    /// A branch cut by the weight cutoff.
    Cutoff,
    /// A primary ray that misses everything.
    Miss,
}

impl Seek {
    /// Every kind, in the order `F` cycles through them.
    pub const ALL: [Seek; 6] = [
        Seek::Tir,
        Seek::Blocked,
        Seek::Refraction,
        Seek::Deep(4),
        Seek::Cutoff,
        Seek::Miss,
    ];

    /// Whether a pixel's features have it.
    pub fn matches(self, f: &Features) -> bool {
        match self {
            Seek::Tir => f.tir,
            Seek::Blocked => f.blocked,
            Seek::Refraction => f.refraction,
            Seek::Deep(k) => f.depth >= k,
            Seek::Cutoff => f.cutoff,
            Seek::Miss => f.miss,
        }
    }

    /// In words.
    pub fn name(self) -> String {
        match self {
            Seek::Tir => "total internal reflection".to_owned(),
            Seek::Blocked => "blocked shadow ray".to_owned(),
            Seek::Refraction => "refraction".to_owned(),
            Seek::Deep(k) => format!("depth ≥ {k}"),
            Seek::Cutoff => "weight cutoff".to_owned(),
            Seek::Miss => "miss".to_owned(),
        }
    }
}

/// What the image pane shows over (or instead of) the render.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Overlay {
    /// The render alone.
    #[default]
    None,
    /// The render with the pixels `f` would find marked.
    Marks,
    /// The deepest ray per pixel.
    Depth,
    /// Rays per pixel.
    Rays,
    /// Object and box tests per pixel.
    Tests,
}

impl Overlay {
    /// The next one, as `o` cycles.
    pub fn next(self) -> Self {
        match self {
            Overlay::None => Overlay::Marks,
            Overlay::Marks => Overlay::Depth,
            Overlay::Depth => Overlay::Rays,
            Overlay::Rays => Overlay::Tests,
            Overlay::Tests => Overlay::None,
        }
    }
}

impl App {
    /// The image's features, scanned once per scene.
    pub fn feature_map(&mut self) -> Option<&FeatureMap> {
        if self.features.is_none() {
            let scene = self.scene.as_ref()?;
            let started = Instant::now();
            // Every pixel up to a million; beyond, every other one.
            let s = scene.settings;
            let stride = if u64::from(s.width) * u64::from(s.height) > 1_000_000 {
                2
            } else {
                1
            };
            self.features = Some(super::features::scan(scene, stride));
            self.message = format!(
                "scanned the image in {:.1} s",
                started.elapsed().as_secs_f64()
            );
        }
        self.features.as_ref()
    }

    /// Goes to the next pixel (in reading order) with the sought feature.
    pub fn find(&mut self) {
        let seek = self.seek;
        let from = self.cursor;
        let found = self
            .feature_map()
            .and_then(|m| m.next(from, |f| seek.matches(f)));
        match found {
            Some(p) => {
                self.message = format!(
                    "found: {} (f: next, F: look for something else)",
                    seek.name()
                );
                self.select(p);
            }
            None => {
                self.message = format!(
                    "no pixel has a {} (F: look for something else)",
                    seek.name()
                )
            }
        }
    }

    pub(super) fn cycle_overlay(&mut self) {
        self.overlay = self.overlay.next();
        if self.overlay != Overlay::None && self.feature_map().is_none() {
            self.overlay = Overlay::None;
            self.message = "no scene: no overlays".to_owned();
        }
    }
}
