//! Render settings: how big the image is, how pixels are sampled, how deep the
//! recursion goes, and which method each numerical step uses.

use crate::methods::{
    Accel, Antialiasing, IntersectionMethods, Offset, SphereMethod, TriangleMethod, Weights,
};
use crate::scene::limits;

/// How to render: image size, sampling, recursion limits and methods.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSettings {
    /// Image width in pixels (`N_c`).
    pub width: u32,
    /// Image height in pixels (`N_r`).
    pub height: u32,
    /// Samples per pixel: a square `n × n` (1, 4, 9, …).
    pub spp: u32,
    /// Deepest ray traced: 1 traces primary rays only (POV-Ray's `max_trace_level`).
    pub max_depth: u32,
    /// A branch whose weight (product of coefficients down to it) falls below this
    /// is not traced (Hall & Greenberg 1983); 0 turns the cutoff off.
    pub cutoff: f64,
    /// How rays meet spheres.
    pub sphere: SphereMethod,
    /// How rays meet triangles.
    #[serde(default)]
    pub triangle: TriangleMethod,
    /// Where secondary rays start.
    pub offset: Offset,
    /// How transparent surfaces split light between reflection and refraction.
    pub weights: Weights,
    /// How pixels are sampled (`spp` applies to the grid).
    pub aa: Antialiasing,
    /// Which acceleration structure finds the objects a ray may hit.
    #[serde(default)]
    pub accel: Accel,
}

impl RenderSettings {
    /// Largest width or height accepted.
    pub const MAX_SIDE: u32 = 32_768;
    /// Largest number of pixels accepted (an 8192 × 8192 image).
    pub const MAX_PIXELS: u64 = 1 << 26;
    /// Default cutoff: a branch that can change the pixel by less than this is
    /// dropped. Chosen so no 8-bit pixel of the shipped scenes moves by more than
    /// one level against a fixed depth of 32 (see `tests/suite/tracer/recursion.rs`).
    pub const DEFAULT_CUTOFF: f64 = 1.0 / 1024.0;

    /// The intersection methods.
    pub fn intersection_methods(&self) -> IntersectionMethods {
        IntersectionMethods {
            sphere: self.sphere,
            triangle: self.triangle,
        }
    }

    /// How pixels are sampled, for a summary line: `4 spp`, or the adaptive
    /// subdivision (which takes as many samples as a pixel needs, ignoring `spp`).
    pub fn sampling(&self) -> String {
        match self.aa {
            Antialiasing::Grid => format!("{} spp", self.spp),
            Antialiasing::Adaptive { threshold, levels } => {
                format!("adaptive sampling, threshold {threshold}, up to {levels} levels")
            }
        }
    }

    /// `n` of the `n × n` sampling grid.
    pub fn grid(&self) -> u32 {
        self.spp.isqrt()
    }

    /// The most primary rays a pixel may trace: `spp` on a grid; with
    /// adaptive subdivision, every corner of a `2^levels` grid of squares
    /// once, `(2^levels + 1)²`.
    pub fn max_samples(&self) -> u32 {
        match self.aa {
            Antialiasing::Grid => self.spp,
            Antialiasing::Adaptive { levels, .. } => {
                (1u32 << levels.min(15)).pow(2) + 2 * (1 << levels.min(15)) + 1
            }
        }
    }

    /// Checks the settings, naming the first that is wrong and why.
    pub fn validate(&self) -> Result<(), (&'static str, String)> {
        for (field, side) in [("width", self.width), ("height", self.height)] {
            if side == 0 || side > Self::MAX_SIDE {
                return Err((
                    field,
                    format!("must be 1 to {}, got {side}", Self::MAX_SIDE),
                ));
            }
        }
        let pixels = u64::from(self.width) * u64::from(self.height);
        if pixels > Self::MAX_PIXELS {
            return Err((
                "width",
                format!(
                    "{}×{} is {pixels} pixels, more than the {} an image may have",
                    self.width,
                    self.height,
                    Self::MAX_PIXELS
                ),
            ));
        }
        if self.spp == 0 || self.grid() * self.grid() != self.spp || self.spp > 1024 {
            return Err((
                "spp",
                format!(
                    "must be a square number of samples (1, 4, 9, … up to 1024) for an n×n grid, got {}",
                    self.spp
                ),
            ));
        }
        if self.max_depth == 0 || self.max_depth > 1000 {
            return Err((
                "max_depth",
                format!("must be 1 to 1000, got {}", self.max_depth),
            ));
        }
        if !(self.cutoff.is_finite() && (0.0..1.0).contains(&self.cutoff)) {
            return Err((
                "cutoff",
                format!(
                    "must be a number from 0 up to (not including) 1, got {}",
                    limits::num(self.cutoff)
                ),
            ));
        }
        if let Antialiasing::Adaptive { threshold, levels } = self.aa
            && !(threshold.is_finite() && threshold >= 0.0 && levels <= 6)
        {
            return Err((
                "aa",
                format!(
                    "adaptive needs a threshold ≥ 0 and at most 6 levels, got {} and {levels}",
                    limits::num(threshold)
                ),
            ));
        }
        if let Offset::Epsilon(e) = self.offset
            && !(e.is_finite() && e > 0.0)
        {
            return Err((
                "offset",
                format!("an epsilon must be a number > 0, got {}", limits::num(e)),
            ));
        }
        Ok(())
    }
}

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            width: 640,
            height: 480,
            spp: 1,
            max_depth: 8,
            cutoff: Self::DEFAULT_CUTOFF,
            sphere: SphereMethod::default(),
            offset: Offset::default(),
            weights: Weights::default(),
            aa: Antialiasing::default(),
            triangle: TriangleMethod::default(),
            accel: Accel::default(),
        }
    }
}
