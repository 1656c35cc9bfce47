//! What the tracer tells a recorder, in the order the algorithm runs.
//!
//! The tracer is generic over its [`Recorder`]: the renderer passes [`NoRecorder`],
//! whose empty methods inline to nothing, and events that cost work to prepare are
//! guarded by the constant [`Recorder::ENABLED`], so rendering pays nothing for
//! recording. A tree recorder sees the same calls and builds the ray tree.

use glam::DVec3;

use crate::geometry::hit::{Roots, TestCounts};
use crate::math::ray::Ray;
use crate::shading::phong::Direct;

/// Calls a recorder hook. Built with `RUSTFLAGS="--cfg raytree_no_hooks"`, every
/// hook disappears from the source, which gives the baseline the benchmark
/// compares the no-op recorder against (see the README's performance section).
#[macro_export]
#[doc(hidden)]
macro_rules! record {
    ($($call:tt)*) => {
        #[cfg(not(raytree_no_hooks))]
        {
            $($call)*;
        }
    };
}

/// Why a ray was cast.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RayKind {
    /// From the eye through a pixel.
    Primary,
    /// The mirror direction at a hit.
    Reflected,
    /// Through a transparent surface, by Snell's law.
    Refracted,
    /// From a hit toward a light.
    Shadow,
}

impl RayKind {
    /// The kind in words, as traces, figures and the book name it (and as
    /// its JSON spells it).
    pub fn name(self) -> &'static str {
        match self {
            RayKind::Primary => "primary",
            RayKind::Reflected => "reflected",
            RayKind::Refracted => "refracted",
            RayKind::Shadow => "shadow",
        }
    }
}

/// A ray about to be traced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayStart {
    /// Why it was cast.
    pub kind: RayKind,
    /// 1 for a primary ray, one more for each bounce.
    pub depth: u32,
    /// Origin and direction.
    pub ray: Ray,
    /// The product of the coefficients (`k_rfl`, `k_rfa`) from the eye down to it:
    /// how much its color can still change the pixel.
    pub weight: f64,
    /// Hits count only for `t_min < t < t_max`.
    pub t_min: f64,
    /// See `t_min`.
    pub t_max: f64,
}

/// The closest hit of a ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitEvent {
    /// Index of the object in the scene.
    pub object: usize,
    /// Ray parameter of the hit.
    pub t: f64,
    /// The mesh face hit (0 for other shapes).
    pub face: u32,
    /// World-space hit point.
    pub point: DVec3,
    /// Outward unit geometric normal.
    pub normal: DVec3,
    /// The unit normal used for shading, turned to face the incoming ray.
    pub shading_normal: DVec3,
    /// Whether the ray enters the object, or leaves it (only what it is inside:
    /// see `Tracer::enters`).
    pub entering: bool,
    /// Refractive index on the ray's side.
    pub n1: f64,
    /// Refractive index on the far side.
    pub n2: f64,
}

/// What a shadow ray found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadowOutcome {
    /// The light is behind the surface as seen from the viewer: no ray is cast.
    FacesAway,
    /// The ray reached the light, keeping `transmitted` of it (less than 1 after
    /// passing through transparent objects).
    Reaches {
        /// Share of the light's color that arrives.
        transmitted: f64,
    },
    /// An opaque object is in the way.
    Blocked {
        /// Index of the first opaque blocker found.
        object: usize,
        /// Where along the shadow ray it was met.
        t: f64,
    },
}

/// A shadow ray from a hit toward one light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowEvent {
    /// Index of the light.
    pub light: usize,
    /// Origin (offset off the surface) and direction (to the light: `t = 1` is the light).
    pub ray: Ray,
    /// The ray stops just short of the light.
    pub t_max: f64,
    /// What it found.
    pub outcome: ShadowOutcome,
    /// The boxes and primitives it was tested against.
    pub tested: TestCounts,
    /// The object tried before any other, if this light's shadow rays on this
    /// thread were blocked before (the lecture's "try the recent hit first").
    pub recent: Option<RecentTry>,
}

/// The last blocker of a light's shadow rays, tried first by the next one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecentTry {
    /// Index of the object.
    pub object: usize,
    /// Whether it blocks this shadow ray too (then nothing else was tested).
    pub blocks: bool,
}

/// The start of a hit's local color: the surface's color there and the
/// ambient term made from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalEvent {
    /// The material's color at the point (a checker's square, or its one color).
    pub color: DVec3,
    /// `k_a · color · ambient_light`.
    pub ambient: DVec3,
}

/// One light's share of the local color at a hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightEvent {
    /// Index of the light.
    pub light: usize,
    /// The Phong terms with what they were made from; `None` when the shadow ray
    /// did not reach the light (the light adds nothing).
    pub phong: Option<Direct>,
}

/// Whether a reflected or refracted ray was spawned, and if not, why not.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Branch {
    /// Spawned and traced.
    Traced,
    /// The material's coefficient is zero: not reflective, or opaque.
    NoCoefficient,
    /// The parent was already at the maximum depth.
    MaxDepth,
    /// Its weight would fall below the cutoff (Hall & Greenberg's adaptive depth).
    WeightCutoff,
    /// Refraction impossible: the transmitted share went to the reflected ray.
    TotalInternalReflection,
}

/// A reflected or refracted branch at a hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BranchEvent {
    /// Reflected or refracted.
    pub kind: RayKind,
    /// The coefficient its color is multiplied by: `k_rfl` or `k_rfa`. After total
    /// internal reflection the reflected branch has `k_rfl + k_rfa`, and the
    /// refracted branch records the `k_rfa` it handed over (its color counts 0).
    pub coefficient: f64,
    /// What happened.
    pub branch: Branch,
}

/// How a ray's color was made: `color = local + k_rfl·reflected + k_rfa·refracted`,
/// with `local = ambient + Σ (diffuse + specular)` over the lights.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SumEvent {
    /// The local color (for a miss, the background).
    pub local: DVec3,
    /// Coefficient of the reflected color.
    pub k_rfl: f64,
    /// Color returned by the reflected ray (zero if not traced).
    pub reflected: DVec3,
    /// Coefficient of the refracted color.
    pub k_rfa: f64,
    /// Color returned by the refracted ray (zero if not traced).
    pub refracted: DVec3,
    /// The result.
    pub color: DVec3,
}

/// A box of the scene's hierarchy that a ray was tested against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxVisit {
    /// The box, as the hierarchy stores it (rounded outward).
    pub bounds: crate::math::bounds::Bounds,
    /// The ray met it within its interval, so its children were visited.
    pub met: bool,
    /// How many objects the search had tested before this visit: places the
    /// visit among the tests, so a step-through walks cells and tests in the
    /// order the search ran them.
    pub after_tests: usize,
}

/// Receives the tracer's events. Every method defaults to doing nothing.
pub trait Recorder {
    /// Whether this recorder wants the events that cost work to prepare
    /// (each object test, hit details, light terms). `false` compiles them away.
    const ENABLED: bool;
    /// A ray is about to be traced; the events up to its `ray_finished` are its own
    /// (with its children's nested inside).
    fn ray_started(&mut self, _start: &RayStart) {}
    /// The ray was tested against object `object`, with these roots.
    fn object_tested(&mut self, _object: usize, _roots: &Roots) {}
    /// The search for the closest hit is over; it tested this many boxes and
    /// primitives (every object without a hierarchy).
    fn tested(&mut self, _tested: &TestCounts) {}
    /// The boxes of the scene's hierarchy the search tested, in order, and
    /// whether the ray met each (none without a hierarchy).
    fn boxes_visited(&mut self, _boxes: &[BoxVisit]) {}
    /// The closest hit was found.
    fn hit(&mut self, _hit: &HitEvent) {}
    /// Nothing was hit: the ray returns the background.
    fn missed(&mut self) {}
    /// A shadow ray was cast (or skipped because the light faces away).
    fn shadow_ray(&mut self, _shadow: &ShadowEvent) {}
    /// The local color's start: the surface color and the ambient term.
    fn local(&mut self, _local: &LocalEvent) {}
    /// One light's terms of the local color.
    fn light_term(&mut self, _term: &LightEvent) {}
    /// The reflected or refracted branch was decided (a traced child follows).
    fn branch(&mut self, _branch: &BranchEvent) {}
    /// The ray's color is known.
    fn ray_finished(&mut self, _sum: &SumEvent) {}
}

/// Records nothing: what the renderer uses.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoRecorder;

impl Recorder for NoRecorder {
    const ENABLED: bool = false;
}

/// Counts rays by kind, and the intersection tests they made: how the
/// benchmark and the CLI report rays per second and tests per ray.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounter {
    /// Primary rays.
    pub primary: u64,
    /// Primary rays that hit an object (the SPD's "eye hit rays").
    pub primary_hits: u64,
    /// Whether the ray started last is a primary ray: its hit, if any, is
    /// reported before any other ray starts.
    in_primary: bool,
    /// Reflected rays.
    pub reflected: u64,
    /// Refracted rays.
    pub refracted: u64,
    /// Shadow rays actually cast.
    pub shadow: u64,
    /// Bounding boxes tested by all rays, shadow rays too.
    pub boxes: u64,
    /// Primitives (objects, and the triangles of meshes) tested by all rays.
    pub primitives: u64,
}

impl RayCounter {
    /// All rays.
    pub fn total(&self) -> u64 {
        self.primary + self.reflected + self.refracted + self.shadow
    }

    /// All intersection tests: boxes and primitives.
    pub fn tests(&self) -> u64 {
        self.boxes + self.primitives
    }

    /// Adds another counter's counts.
    pub fn add(&mut self, other: &RayCounter) {
        self.primary += other.primary;
        self.primary_hits += other.primary_hits;
        self.reflected += other.reflected;
        self.refracted += other.refracted;
        self.shadow += other.shadow;
        self.boxes += other.boxes;
        self.primitives += other.primitives;
    }

    fn count_tests(&mut self, tested: &TestCounts) {
        self.boxes += u64::from(tested.boxes);
        self.primitives += u64::from(tested.primitives);
    }
}

impl Recorder for RayCounter {
    const ENABLED: bool = false;

    fn ray_started(&mut self, start: &RayStart) {
        self.in_primary = start.kind == RayKind::Primary;
        match start.kind {
            RayKind::Primary => self.primary += 1,
            RayKind::Reflected => self.reflected += 1,
            RayKind::Refracted => self.refracted += 1,
            // Shadow rays are reported through `shadow_ray` alone.
            RayKind::Shadow => {}
        }
    }

    fn tested(&mut self, tested: &TestCounts) {
        self.count_tests(tested);
    }

    fn hit(&mut self, _hit: &HitEvent) {
        if self.in_primary {
            self.primary_hits += 1;
            self.in_primary = false;
        }
    }

    fn shadow_ray(&mut self, shadow: &ShadowEvent) {
        if shadow.outcome != ShadowOutcome::FacesAway {
            self.shadow += 1;
        }
        self.count_tests(&shadow.tested);
    }
}
