//! Finding pixels worth a look (a total internal reflection, a blocked shadow
//! ray, …) and the image overlays that mark them or color the image by a
//! per-pixel count.

use std::thread::JoinHandle;
use std::time::Instant;

use super::features::{FeatureMap, Features};
use super::traced_scene::TracedScene;

/// What `f` looks for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Seek {
    /// A total internal reflection.
    #[default]
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

/// What `f` seeks, what the image pane overlays, and the image's features
/// both read (scanned on the first find or overlay, again after an edit).
///
/// The scan traces every pixel, a second or two for a large scene, so the
/// live inspector scans on a thread of its own: the key that asked returns at
/// once, the overlay appears and a pending `f` jumps when the scan arrives.
/// Without a worker (tests) it scans here and now.
#[derive(Debug, Default)]
pub(in crate::inspector) struct Finding {
    features: Option<FeatureMap>,
    /// The scan under way on its own thread, and when it started.
    scanning: Option<(JoinHandle<FeatureMap>, Instant)>,
    /// Whether to scan on a thread of its own.
    background: bool,
    /// `f` was pressed here before the features were known: find from here
    /// once they are.
    pending: Option<(u32, u32)>,
    seek: Seek,
    overlay: Overlay,
}

/// What a finished scan brought.
pub(in crate::inspector) struct Arrived {
    /// The pixel a pending `f` finds, if one was pending and something was found.
    pub found: Option<(u32, u32)>,
    /// What to tell.
    pub said: String,
}

impl Finding {
    /// Scans on a thread of its own (the live inspector) or here and now.
    pub fn new(background: bool) -> Self {
        Self {
            background,
            ..Self::default()
        }
    }

    /// What `f` looks for.
    pub fn seek(&self) -> Seek {
        self.seek
    }

    /// What the image pane shows.
    pub fn overlay(&self) -> Overlay {
        self.overlay
    }

    /// The image's features, once scanned.
    pub fn features(&self) -> Option<&FeatureMap> {
        self.features.as_ref()
    }

    /// The scene changed: its features are scanned again when next needed
    /// (a scan under way, of the old scene, is left to finish unread).
    pub fn forget(&mut self) {
        self.features = None;
        self.scanning = None;
        self.pending = None;
    }

    /// Starts scanning `scene`'s features if they are neither known nor
    /// under way; says how long it took when it scanned here and now.
    fn scan(&mut self, traced: Option<&TracedScene>) -> Option<String> {
        if self.features.is_some() || self.scanning.is_some() {
            return None;
        }
        let traced = traced?.clone();
        let started = Instant::now();
        // Every pixel up to a million; beyond, every other one.
        let s = traced.scene().settings;
        let stride = if u64::from(s.width) * u64::from(s.height) > 1_000_000 {
            2
        } else {
            1
        };
        let scan = move || super::features::scan_with(&traced.tracer(), stride);
        if self.background {
            self.scanning = Some((std::thread::spawn(scan), started));
            return None;
        }
        self.features = Some(scan());
        Some(scanned(started))
    }

    /// Takes the scan if it finished: what a pending `f` finds (if the cursor
    /// is still at `cursor`, where it was pressed), and what to tell. `None`
    /// while nothing arrived.
    pub fn receive(&mut self, cursor: (u32, u32)) -> Option<Arrived> {
        if !self.scanning.as_ref()?.0.is_finished() {
            return None;
        }
        let (scan, started) = self.scanning.take()?;
        let Ok(map) = scan.join() else {
            self.pending = None;
            return Some(Arrived {
                found: None,
                said: "the scan of the image failed".to_owned(),
            });
        };
        self.features = Some(map);
        Some(match self.pending.take().filter(|&from| from == cursor) {
            Some(from) => {
                let (found, said) = self.found(from);
                Arrived { found, said }
            }
            None => Arrived {
                found: None,
                said: scanned(started),
            },
        })
    }

    /// The next pixel after `from` (in reading order) with what is sought, and
    /// what to tell about it; while the features are being scanned, nothing
    /// yet (it is found from `from` when they arrive: [`Finding::receive`]).
    pub fn find(
        &mut self,
        scene: Option<&TracedScene>,
        from: (u32, u32),
    ) -> (Option<(u32, u32)>, String) {
        self.scan(scene);
        if self.scanning.is_some() {
            self.pending = Some(from);
            return (
                None,
                format!(
                    "scanning the image for a {}: the cursor goes there when found",
                    self.seek.name()
                ),
            );
        }
        self.found(from)
    }

    /// The next pixel after `from` with what is sought, in the features known.
    fn found(&self, from: (u32, u32)) -> (Option<(u32, u32)>, String) {
        let seek = self.seek;
        match self
            .features
            .as_ref()
            .and_then(|m| m.next(from, |f| seek.matches(f)))
        {
            Some(p) => (
                Some(p),
                format!(
                    "found: {} (f: next, F: look for something else)",
                    seek.name()
                ),
            ),
            None => (
                None,
                format!(
                    "no pixel has a {} (F: look for something else)",
                    seek.name()
                ),
            ),
        }
    }

    /// Seeks the next kind of feature, as `F` cycles.
    pub fn seek_next(&mut self) {
        let k = Seek::ALL.iter().position(|&s| s == self.seek).unwrap_or(0);
        self.seek = Seek::ALL[(k + 1) % Seek::ALL.len()];
    }

    /// The next overlay, as `o` cycles; what to tell, if anything (a scan, or
    /// that there is no scene to overlay).
    pub fn next_overlay(&mut self, scene: Option<&TracedScene>) -> Option<String> {
        self.overlay = self.overlay.next();
        if self.overlay == Overlay::None {
            return None;
        }
        let scanned = self.scan(scene);
        if self.features.is_none() && self.scanning.is_none() {
            self.overlay = Overlay::None;
            return Some("no scene: no overlays".to_owned());
        }
        match self.scanning {
            Some(_) => Some("scanning the image: the overlay shows when done".to_owned()),
            None => scanned,
        }
    }
}

/// How long a scan took, in words.
fn scanned(started: Instant) -> String {
    format!(
        "scanned the image in {:.1} s",
        started.elapsed().as_secs_f64()
    )
}
