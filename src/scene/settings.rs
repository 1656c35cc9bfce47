//! Render settings: how big the image is, how pixels are sampled, how deep the
//! recursion goes, and which method each numerical step uses.

use crate::geometry::structures::{grid, octree};
use crate::methods::{
    Accel, Antialiasing, IntersectionMethods, Level, Offset, SphereMethod, TriangleMethod, Weights,
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
    /// The grid's cells along the scene's longest side, the other sides in
    /// proportion (`auto`: about four cells an object, see `geometry::structures::grid`).
    #[serde(default)]
    pub grid_res: Level,
    /// The deepest level of the octree or the k-d tree (`auto`: 10 for the
    /// octree, `8 + 1.3·log₂ N` for the k-d tree).
    #[serde(default)]
    pub tree_depth: Level,
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
    /// Most rays one sample may trace in the worst case
    /// ([`Self::worst_case_rays`]): 2³², just above the 2³² − 1 a fixed depth
    /// of 32 (`cutoff` 0) may take, lesson 11's deepest render. It bounds the work of every
    /// render, whatever the scene; real scenes trace far fewer (that render of
    /// the Whitted scene, under 18 rays a pixel with the shadow rays).
    pub const MAX_RAYS_PER_SAMPLE: f64 = 4_294_967_296.0;

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
            Antialiasing::Corners => "rays through the pixel corners".to_owned(),
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
            Antialiasing::Corners => 4,
            Antialiasing::Adaptive { levels, .. } => {
                (1u32 << levels.min(15)).pow(2) + 2 * (1 << levels.min(15)) + 1
            }
        }
    }

    /// The most rays one sample may trace: its primary ray and every reflected
    /// and refracted ray below it, in the worst case. A ray's hit spawns at
    /// most one reflected and one refracted ray (and one shadow ray per light,
    /// not counted: they spawn nothing), so level `d` of the tree (the primary
    /// ray is level 1) holds at most `2^(d-1)` rays. With a cutoff `c > 0` a
    /// level holds at most `⌈1/c⌉` rays too: a child's weight is its parent's
    /// times `k_rfl` or `k_rfa`, which sum to at most `reflective +
    /// transparent ≤ 1` (the loader's rule), so the weights of one level sum to
    /// at most 1 and at most `1/c` of them reach `c` (up to rounding, a few
    /// ulps a level, far below any cutoff that makes `⌈1/c⌉` the smaller).
    /// So a sample traces at most `Σ_{d=1}^{max_depth} min(2^(d-1), ⌈1/c⌉)`
    /// rays: `2^max_depth - 1` without a cutoff. An `f64`, since that exceeds every
    /// integer type (2¹⁰⁰⁰ at depth 1000); exact below 2⁵³, which covers both
    /// limits it is held against.
    pub fn worst_case_rays(&self) -> f64 {
        let width = if self.cutoff > 0.0 {
            (1.0 / self.cutoff).ceil()
        } else {
            f64::INFINITY
        };
        (0..self.max_depth)
            .map(|d| 2f64.powi(d as i32).min(width))
            .sum()
    }

    /// The deepest `max_depth` whose [`Self::worst_case_rays`] stays within
    /// `limit` under these settings' cutoff (0 if none does).
    pub fn deepest_within(&self, limit: f64) -> u32 {
        let mut s = *self;
        (1..=self.max_depth)
            .take_while(|&d| {
                s.max_depth = d;
                s.worst_case_rays() <= limit
            })
            .last()
            .unwrap_or(0)
    }

    // The rules of single settings, taking any number a command line may
    // hold (a negative one too), so that a flag out of range and the same
    // field of a scene file are refused with the same words.

    /// A width or height: 1 to [`Self::MAX_SIDE`].
    pub fn side_rule(side: i128) -> Result<(), String> {
        if (1..=i128::from(Self::MAX_SIDE)).contains(&side) {
            return Ok(());
        }
        Err(format!("must be 1 to {}, got {side}", Self::MAX_SIDE))
    }

    /// Samples per pixel: a square number up to 1024.
    pub fn spp_rule(spp: i128) -> Result<(), String> {
        if (1..=1024).contains(&spp) && spp.isqrt() * spp.isqrt() == spp {
            return Ok(());
        }
        Err(format!(
            "must be a square number of samples (1, 4, 9, … up to 1024) for an n×n grid, got {spp}"
        ))
    }

    /// The deepest ray: 1 to 1000.
    pub fn max_depth_rule(depth: i128) -> Result<(), String> {
        if (1..=1000).contains(&depth) {
            return Ok(());
        }
        Err(format!("must be 1 to 1000, got {depth}"))
    }

    /// The weight cutoff: from 0 up to (not including) 1.
    pub fn cutoff_rule(cutoff: f64) -> Result<(), String> {
        if cutoff.is_finite() && (0.0..1.0).contains(&cutoff) {
            return Ok(());
        }
        Err(format!(
            "must be a number from 0 up to (not including) 1, got {}",
            limits::num(cutoff)
        ))
    }

    /// Checks the settings, naming the first that is wrong and why.
    pub fn validate(&self) -> Result<(), (&'static str, String)> {
        for (field, side) in [("width", self.width), ("height", self.height)] {
            Self::side_rule(side.into()).map_err(|m| (field, m))?;
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
        Self::spp_rule(self.spp.into()).map_err(|m| ("spp", m))?;
        Self::max_depth_rule(self.max_depth.into()).map_err(|m| ("max_depth", m))?;
        Self::cutoff_rule(self.cutoff).map_err(|m| ("cutoff", m))?;
        let rays = self.worst_case_rays();
        if rays > Self::MAX_RAYS_PER_SAMPLE {
            return Err((
                "max_depth",
                format!(
                    "{} with cutoff {} may trace up to {} rays a sample ({}), more than the {} (2^32) raytree traces; lower max_depth to {} or raise the cutoff",
                    self.max_depth,
                    limits::num(self.cutoff),
                    ray_count(rays),
                    if self.cutoff > 0.0 {
                        "each hit may spawn a reflected and a refracted ray, at most 1/cutoff of them a level"
                    } else {
                        "2^max_depth - 1: each hit may spawn a reflected and a refracted ray"
                    },
                    ray_count(Self::MAX_RAYS_PER_SAMPLE),
                    self.deepest_within(Self::MAX_RAYS_PER_SAMPLE)
                ),
            ));
        }
        if let Level::Given(n) = self.grid_res
            && !(1..=grid::MAX_GIVEN_SIDE).contains(&n)
        {
            return Err((
                "grid_res",
                format!(
                    "must be auto or 1 to {} cells along the scene's longest side, got {n}",
                    grid::MAX_GIVEN_SIDE
                ),
            ));
        }
        if let Level::Given(d) = self.tree_depth
            && d > octree::DEEPEST
        {
            return Err((
                "tree_depth",
                format!("must be auto or 0 to {} levels, got {d}", octree::DEEPEST),
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

/// A count of rays as a learner reads it: whole below 10¹⁵ (`4294967296`),
/// else to two figures (`1.1e301`).
pub fn ray_count(n: f64) -> String {
    if n < 1e15 {
        format!("{n:.0}")
    } else {
        format!("{n:.1e}")
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
            grid_res: Level::Auto,
            tree_depth: Level::Auto,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_worst_case_counts_every_level_up_to_its_width() {
        let with = |max_depth, cutoff| RenderSettings {
            max_depth,
            cutoff,
            ..RenderSettings::default()
        };
        // 1 + 2 + … + 128 rays: the cutoff's width (1024) is never reached.
        assert_eq!(with(8, 1.0 / 1024.0).worst_case_rays(), 255.0);
        // Levels 1 to 11 double up to 1024 (2047 in all); level 12 stays at 1024.
        assert_eq!(with(12, 1.0 / 1024.0).worst_case_rays(), 3071.0);
        // A cutoff of 0.3 lets through at most ⌈1/0.3⌉ = 4 rays a level.
        assert_eq!(with(5, 0.3).worst_case_rays(), 1.0 + 2.0 + 4.0 + 4.0 + 4.0);
        assert_eq!(with(32, 0.0).worst_case_rays(), 4_294_967_295.0);
        assert_eq!(with(1000, 0.0).worst_case_rays(), 2f64.powi(1000));
        assert_eq!(
            with(1000, 0.0).deepest_within(RenderSettings::MAX_RAYS_PER_SAMPLE),
            32
        );
        assert!(with(32, 0.0).validate().is_ok());
        assert!(
            with(1000, RenderSettings::DEFAULT_CUTOFF)
                .validate()
                .is_ok()
        );
        let (field, message) = with(33, 0.0).validate().unwrap_err();
        assert_eq!(field, "max_depth");
        assert_eq!(
            message,
            "33 with cutoff 0 may trace up to 8589934591 rays a sample (2^max_depth - 1: each hit may spawn a reflected and a refracted ray), more than the 4294967296 (2^32) raytree traces; lower max_depth to 32 or raise the cutoff"
        );
        let (_, message) = with(1000, 1e-9).validate().unwrap_err();
        assert!(
            message.starts_with("1000 with cutoff 1e-9 may trace up to 971073741823 rays a sample"),
            "{message}"
        );
        assert!(
            message.ends_with("lower max_depth to 33 or raise the cutoff"),
            "{message}"
        );
        assert_eq!(ray_count(2f64.powi(1000)), "1.1e301");
    }
}
