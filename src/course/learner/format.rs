//! The learner trace's fields, version 1. Every field but a ray's `kind`,
//! `origin` and `direction` is optional: the check compares what is there. A
//! hit or a child may also be `null`, which says something ("my ray missed",
//! "I spawned no such ray") where an absent key says nothing.
//!
//! The key tables below are what the reader accepts and what the test holds
//! the published schema (`docs/learner-trace.schema.json`) to, so the two
//! cannot drift apart.

use glam::DVec3;
use serde::Serialize;

/// The value of the `format` field.
pub const FORMAT: &str = "raytree-learner-trace";
/// The value of the `version` field.
pub const VERSION: u64 = 1;
/// The largest file read: a whole tree of depth 8 with every field is about
/// 100 kB, so 8 MiB is far above any honest trace and refuses a runaway one
/// before a byte is read.
pub const MAX_BYTES: u64 = 8 << 20;
/// The deepest ray (the primary ray is 1): above raytree's own default depth
/// of 8 many times over, and far below what would strain the reader.
pub const MAX_DEPTH: u32 = 64;
/// The most rays in one trace.
pub const MAX_RAYS: usize = 100_000;

/// A key of an object of the format, and whether it must be there.
pub type Key = (&'static str, bool);

/// The document's keys.
pub const TRACE_KEYS: &[Key] = &[
    ("format", true),
    ("version", true),
    ("scene", false),
    ("pixel", false),
    ("ray", true),
];
/// A ray's keys.
pub const RAY_KEYS: &[Key] = &[
    ("kind", true),
    ("origin", true),
    ("direction", true),
    ("hit", false),
    ("shadows", false),
    ("local", false),
    ("k_rfl", false),
    ("k_rfa", false),
    ("reflected", false),
    ("refracted", false),
    ("tir", false),
    ("color", false),
];
/// A hit's keys.
pub const HIT_KEYS: &[Key] = &[
    ("object", false),
    ("t", false),
    ("point", false),
    ("normal", false),
    ("entering", false),
];
/// A shadow ray's keys.
pub const SHADOW_KEYS: &[Key] = &[
    ("light", true),
    ("blocked", true),
    ("by", false),
    ("transmitted", false),
    ("origin", false),
    ("direction", false),
];

/// The kinds of ray a learner trace holds (shadow rays sit in `shadows`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// From the eye through the pixel.
    Primary,
    /// The mirror direction at a hit.
    Reflected,
    /// Through a transparent surface.
    Refracted,
}

/// The kinds' names in the file, in the order of [`Kind`].
pub const KINDS: [&str; 3] = ["primary", "reflected", "refracted"];

impl Kind {
    /// Every kind, in the order of [`KINDS`].
    pub const ALL: [Kind; 3] = [Kind::Primary, Kind::Reflected, Kind::Refracted];

    /// Its name in the file.
    pub fn name(self) -> &'static str {
        KINDS[self as usize]
    }

    /// The kind of this name in the file, if any.
    pub fn named(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// A learner trace.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LearnerTrace {
    /// Informative only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scene: Option<String>,
    /// The pixel, `[x, y]` in image coordinates; when given, it must be the one checked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pixel: Option<[u32; 2]>,
    /// The primary ray.
    pub ray: LearnerRay,
}

/// One ray. `Option<Option<T>>`: `None` absent (not compared), `Some(None)` null.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LearnerRay {
    /// Primary, reflected or refracted.
    pub kind: Kind,
    /// Where it starts.
    pub origin: DVec3,
    /// Where it goes, any nonzero length: `t` counts in units of it.
    pub direction: DVec3,
    /// The closest hit; `Some(None)`: the ray missed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hit: Option<Option<LearnerHit>>,
    /// One per light, in the scene's order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shadows: Option<Vec<LearnerShadow>>,
    /// The local (Phong) color at the hit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub local: Option<DVec3>,
    /// The reflected color's coefficient, per channel.
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "coefficient"
    )]
    pub k_rfl: Option<DVec3>,
    /// The refracted color's coefficient, per channel.
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "coefficient"
    )]
    pub k_rfa: Option<DVec3>,
    /// The reflected child; `Some(None)`: not spawned.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reflected: Option<Option<Box<LearnerRay>>>,
    /// The refracted child; `Some(None)`: not spawned.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refracted: Option<Option<Box<LearnerRay>>>,
    /// Total internal reflection at the hit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tir: Option<bool>,
    /// `local + k_rfl·reflected + k_rfa·refracted`, linear, unclamped.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub color: Option<DVec3>,
}

/// A ray's closest hit.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct LearnerHit {
    /// The scene's name of the object.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub object: Option<String>,
    /// Ray parameter, in units of the ray's direction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t: Option<f64>,
    /// The hit point.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<DVec3>,
    /// The unit normal the formulas use: turned to face the incoming ray.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub normal: Option<DVec3>,
    /// Whether the ray enters the object.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub entering: Option<bool>,
}

/// A shadow ray toward one light.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LearnerShadow {
    /// The light's name.
    pub light: String,
    /// An opaque object is in the way.
    pub blocked: bool,
    /// The blocker's name; `Some(None)` written as null.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub by: Option<Option<String>>,
    /// The share of the light that arrives through transparent objects.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transmitted: Option<f64>,
    /// Where the shadow ray starts.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub origin: Option<DVec3>,
    /// Toward the light, any nonzero length.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub direction: Option<DVec3>,
}

impl LearnerRay {
    /// A ray with only the required fields.
    pub fn new(kind: Kind, origin: DVec3, direction: DVec3) -> Self {
        LearnerRay {
            kind,
            origin,
            direction,
            hit: None,
            shadows: None,
            local: None,
            k_rfl: None,
            k_rfa: None,
            reflected: None,
            refracted: None,
            tir: None,
            color: None,
        }
    }

    /// The rays of this tree, this one first, depth first (reflected before refracted).
    pub fn count(&self) -> usize {
        1 + [&self.reflected, &self.refracted]
            .into_iter()
            .flatten()
            .flatten()
            .map(|c| c.count())
            .sum::<usize>()
    }
}

impl LearnerTrace {
    /// The trace as JSON, its number arrays on one line.
    pub fn to_json(&self) -> String {
        let pretty = serde_json::to_string_pretty(&Written::new(self))
            .expect("a learner trace always serializes");
        crate::tree::document::numbers_on_one_line(&pretty)
    }
}

/// The document as written: its format and version, then the trace.
#[derive(Serialize)]
struct Written<'a> {
    format: &'static str,
    version: u64,
    #[serde(flatten)]
    trace: &'a LearnerTrace,
}

impl<'a> Written<'a> {
    fn new(trace: &'a LearnerTrace) -> Self {
        Written {
            format: FORMAT,
            version: VERSION,
            trace,
        }
    }
}

/// A coefficient as a number when its channels agree (raytree's always do).
fn coefficient<S: serde::Serializer>(k: &Option<DVec3>, s: S) -> Result<S::Ok, S::Error> {
    match k {
        Some(k) if k.x == k.y && k.y == k.z => s.serialize_f64(k.x),
        other => other.serialize(s),
    }
}
