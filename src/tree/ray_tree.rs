//! The ray tree: every ray one pixel (or one chosen ray) spawns, with every
//! number that made its color. Views (the text tree, the JSON trace, the
//! inspector, the diagrams) read this; none of them looks into the tracer.
//!
//! Nodes live in one flat list, parents before children, each naming its parent
//! and its reflected and refracted children by index: easy to walk, to select in
//! a UI, and to write as JSON. `nodes[0]` is the primary ray.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::geometry::hit::TestCounts;
/// The tracer's words for why a ray was cast and how a branch ended are the
/// tree's too.
pub use crate::trace::recorder::{Branch, RayKind};
use crate::tree::arithmetic::{
    Arithmetic, RayRecord, RefractionRecord, RootRecord, TUnit, TestMethod,
};

/// One ray's tree.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RayTree {
    /// The rays, parents before children; `nodes[0]` is the root.
    pub nodes: Vec<RayNode>,
}

/// One ray and everything that happened to it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RayNode {
    /// Primary, reflected or refracted.
    pub kind: RayKind,
    /// 1 for the primary ray, one more per bounce.
    pub depth: u32,
    /// Index of the node that spawned it; `None` for the root.
    pub parent: Option<usize>,
    /// Where it starts.
    pub origin: DVec3,
    /// Where it goes (not normalized: a primary ray reaches the image plane at t = 1).
    pub direction: DVec3,
    /// What `t` counts along this ray.
    pub t_unit: TUnit,
    /// Product of the coefficients from the eye down to this ray.
    pub weight: f64,
    /// Hits count only for `t_min < t < t_max`.
    pub t_min: f64,
    /// `None`: the ray is unbounded.
    pub t_max: Option<f64>,
    /// Every object the ray was tested against, in order, with its roots.
    pub tests: Vec<TestRecord>,
    /// How many bounding boxes and primitives the search for the closest hit
    /// tested: what the hierarchy saved against testing every object.
    pub tested: TestCounts,
    /// The boxes of the scene's hierarchy the search tested, in order (empty
    /// without a hierarchy; left out of the JSON then).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub boxes: Vec<BoxRecord>,
    /// The closest hit; `None` when the ray missed everything.
    pub hit: Option<HitRecord>,
    /// One per light, in the scene's order.
    pub shadow_rays: Vec<ShadowRecord>,
    /// The local color's terms; `None` for a miss.
    pub local: Option<LocalRecord>,
    /// The reflected branch; `None` for a miss.
    pub reflected: Option<BranchRecord>,
    /// The refracted branch; `None` for a miss.
    pub refracted: Option<BranchRecord>,
    /// `color = local + k_rfl·reflected + k_rfa·refracted` with its numbers.
    pub sum: SumRecord,
}

/// A box of the scene's hierarchy a ray was tested against.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxRecord {
    /// The smallest corner, as the hierarchy stores it (rounded outward to f32).
    pub min: DVec3,
    /// The largest corner.
    pub max: DVec3,
    /// The ray met the box within its interval, so the box's children were visited.
    pub met: bool,
    /// How many of the ray's `tests` ran before this box was visited.
    pub after_tests: usize,
}

/// The test of one object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TestRecord {
    /// Index of the object.
    pub object: usize,
    /// Its name.
    pub name: String,
    /// How it was tested.
    pub method: TestMethod,
    /// For a transformed object, the inverse-transformed ray `S' + t·c'` the
    /// untransformed primitive was tested with; its `t` is the world ray's.
    pub object_ray: Option<RayRecord>,
    /// The test's own numbers (the quadratic, the plane equation, …).
    pub arithmetic: Option<Arithmetic>,
    /// Where the ray's line meets it, ascending, each with what became of it;
    /// empty for a miss.
    pub roots: Vec<RootRecord>,
}

/// The closest hit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HitRecord {
    /// Index of the object.
    pub object: usize,
    /// Its name.
    pub name: String,
    /// Its material's name.
    pub material: String,
    /// Ray parameter of the hit.
    pub t: f64,
    /// For a mesh, the index of the face hit.
    pub face: Option<u32>,
    /// The lecture's hit point `S + t·c` on the world ray, as computed. Rounding
    /// (and any error of `t`) leaves it off the surface.
    pub on_ray: DVec3,
    /// How the tracer put it on the surface to make `point`.
    pub placement: Placement,
    /// The world-space point the tracer goes on with: `on_ray` placed on the
    /// surface (for a transformed object, in its own space, then carried back).
    pub point: DVec3,
    /// For a transformed object, the point on the untransformed primitive, `M⁻¹P`.
    pub object_point: Option<DVec3>,
    /// For a transformed object, the outward unit normal `n'` of the untransformed
    /// primitive at `object_point`; `normal` is `(M⁻¹)ᵀn'`, normalized.
    #[serde(default)]
    pub object_normal: Option<DVec3>,
    /// For a transformed object, `M·n'` normalized: the normal transformed like a
    /// point (a direction), the classic mistake. Recorded so a lesson can show how
    /// far it is from `normal` once `M` scales unevenly; never used for shading.
    #[serde(default)]
    pub normal_like_point: Option<DVec3>,
    /// Outward unit geometric normal.
    pub normal: DVec3,
    /// The unit normal the formulas use: the shading normal turned to face the
    /// incoming ray (the outward normal reversed when the ray leaves the object).
    pub shading_normal: DVec3,
    /// Whether the ray enters the object; it leaves only what it is inside.
    pub entering: bool,
    /// Refractive index on the incoming side.
    pub n1: f64,
    /// Refractive index on the far side.
    pub n2: f64,
    /// The incoming direction as a unit vector, `c`.
    pub incoming: DVec3,
    /// `n·c` with the normal the formulas use: negative, the ray arrives against
    /// it; 0 at a tangent touch (a hair above where rounding beside one tilted it).
    pub n_dot_c: f64,
    /// The mirror direction `v = c - 2(n·c)n`.
    pub mirror: DVec3,
    /// Snell's law, for a transparent surface.
    pub refraction: Option<RefractionRecord>,
}

/// How the tracer puts a hit on the surface, starting from `S + t·c`: placed
/// there, a point's own error is a few ULPs of its size however long the ray
/// was, so a secondary ray need only start just past it (pbrt-v4 §6.8.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Placement {
    /// Projected onto the sphere along the line from its center:
    /// `C + r·(S + t·c - C)/|S + t·c - C|`.
    OntoSphere,
    /// Projected onto the plane (a plane's, or a polygon's) along its normal:
    /// `Q - ((Q - P₀)·n)n`, `Q = S + t·c`.
    OntoPlane,
    /// Put on the face hit: its coordinate across the face set to the face's.
    OntoBoxFace,
    /// Made from the triangle's corners with its barycentric weights at the
    /// hit: `b₀A + b₁B + b₂C`.
    FromCorners,
    /// Put at the radius of its height on the unit cone: `z` kept, `(x, y)`
    /// scaled to `1 + (s − 1)z`.
    OntoCone,
}

/// A shadow ray toward one light.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShadowRecord {
    /// Index of the light.
    pub light: usize,
    /// Its name.
    pub name: String,
    /// Start (just off the surface).
    pub origin: DVec3,
    /// Toward the light: `t = 1` is the light itself.
    pub direction: DVec3,
    /// The ray stops just short of the light.
    pub t_max: f64,
    /// What it found.
    pub outcome: ShadowOutcomeRecord,
    /// The boxes and primitives it was tested against (it stops at the first
    /// opaque blocker).
    pub tested: TestCounts,
    /// The object tried before any other: the last one that blocked a shadow
    /// ray toward this light (the lecture's "try the recent hit first").
    pub recent: Option<RecentRecord>,
}

/// The last blocker of a light's shadow rays, tried first by the next one.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecentRecord {
    /// Index of the object.
    pub object: usize,
    /// Its name.
    pub name: String,
    /// Whether it blocks this shadow ray too: then it was the only test.
    pub blocks: bool,
}

/// What a shadow ray found.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum ShadowOutcomeRecord {
    /// The light is behind the surface: no ray was cast.
    FacesAway,
    /// It reached the light, keeping `transmitted` of it (1 unless transparent
    /// objects were in the way).
    Reaches {
        /// Share of the light that arrives.
        transmitted: f64,
    },
    /// An opaque object is in the way.
    Blocked {
        /// Index of the blocker.
        object: usize,
        /// Its name.
        name: String,
        /// Where along the shadow ray.
        t: f64,
    },
}

/// The local color: `ambient + Σ (diffuse + specular)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LocalRecord {
    /// The material's color at the point.
    pub color: DVec3,
    /// `k_a`, the share of the ambient light reflected.
    pub k_a: f64,
    /// `k_d`, the diffuse coefficient.
    pub k_d: f64,
    /// `k_s`, the specular coefficient.
    pub k_s: f64,
    /// The Phong exponent.
    pub shininess: f64,
    /// The scene's ambient light.
    pub ambient_light: DVec3,
    /// The ambient term `k_a · color · ambient_light`.
    pub ambient: DVec3,
    /// One entry per light.
    pub lights: Vec<LightRecord>,
    /// The sum.
    pub total: DVec3,
}

/// One light's part of the local color.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightRecord {
    /// Index of the light.
    pub light: usize,
    /// Its name.
    pub name: String,
    /// What the terms were made from; `None` when no light arrived.
    pub phong: Option<PhongRecord>,
    /// Diffuse term (zero when the light did not arrive).
    pub diffuse: DVec3,
    /// Specular term (likewise).
    pub specular: DVec3,
}

/// The vectors and products of one light's Phong terms.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhongRecord {
    /// `L`: unit vector from the point to the light.
    pub l: DVec3,
    /// `N·L`.
    pub n_dot_l: f64,
    /// `R = 2(N·L)N - L`.
    pub r: DVec3,
    /// `V`: unit vector from the point to the viewer.
    pub v: DVec3,
    /// `R·V`, at least 0.
    pub r_dot_v: f64,
    /// The light's color as it arrives: its color times what the shadow ray kept.
    pub arriving: DVec3,
}

/// A reflected or refracted branch.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BranchRecord {
    /// The coefficient its color is weighted by.
    pub coefficient: f64,
    /// Traced, or why not.
    pub outcome: Branch,
    /// Index of the child node, when traced.
    pub node: Option<usize>,
}

/// How the node's color was summed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SumRecord {
    /// The local color (the background for a miss).
    pub local: DVec3,
    /// Coefficient of the reflected color.
    pub k_rfl: f64,
    /// The reflected ray's color.
    pub reflected: DVec3,
    /// Coefficient of the refracted color.
    pub k_rfa: f64,
    /// The refracted ray's color.
    pub refracted: DVec3,
    /// `local + k_rfl·reflected + k_rfa·refracted`.
    pub color: DVec3,
}

impl RayNode {
    /// The node's color.
    pub fn color(&self) -> DVec3 {
        self.sum.color
    }

    /// The children that were traced, reflected first.
    pub fn children(&self) -> impl Iterator<Item = usize> + '_ {
        [&self.reflected, &self.refracted]
            .into_iter()
            .flatten()
            .filter_map(|c| c.node)
    }
}
