//! One difference between a learner's trace and raytree's, held as what it
//! is: which ray (its path from the primary ray), which quantity, both
//! values, the step, the diagnosis. Each part is written in the report's
//! words by its `Display`, the text and the JSON report alike: those strings
//! are a contract with autograders and stay as they are.

use std::fmt;

use glam::DVec3;
use serde::{Serialize, Serializer};

use crate::course::learner::format::Kind;
use crate::course::learner::mistakes::Diagnosis;
use crate::trace::recorder::Branch;
use crate::views::numbers::{color as color_words, num, vec3 as vec_words};

/// One difference between the learner's trace and raytree's.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// The ray, as its path from the primary ray: `primary → refracted d2`.
    pub ray: RayPath,
    /// What differs: `direction`, `hit.t`, `shadows[1].blocked`, ….
    pub quantity: Quantity,
    /// The learner's value.
    pub learner: Value,
    /// raytree's value.
    pub ours: Value,
    /// The step of raytree's trace where it arises (as `raytree trace --steps` numbers them).
    pub step: usize,
    /// The classic mistake its numbers show, if any.
    pub diagnosis: Option<Diagnosis>,
    /// `false`: a difference tolerated and only said (a branch raytree cut off).
    pub divergence: bool,
}

impl Difference {
    /// A divergence of `quantity` on `ray` at `step`, not (yet) diagnosed.
    pub fn new(
        ray: &RayPath,
        step: usize,
        quantity: Quantity,
        learner: Value,
        ours: Value,
    ) -> Self {
        Difference {
            ray: ray.clone(),
            quantity,
            learner,
            ours,
            step,
            diagnosis: None,
            divergence: true,
        }
    }

    /// With the diagnosis `why`, if any.
    pub fn because(self, why: Option<Diagnosis>) -> Self {
        Difference {
            diagnosis: why,
            ..self
        }
    }
}

/// A ray's path from the primary ray: each ray's kind with its depth (the
/// primary ray is depth 1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RayPath(Vec<(Kind, u32)>);

impl RayPath {
    /// The primary ray.
    pub fn primary() -> Self {
        RayPath(vec![(Kind::Primary, 1)])
    }

    /// This ray's child of `kind` at `depth`.
    pub fn child(&self, kind: Kind, depth: u32) -> Self {
        let mut rays = self.0.clone();
        rays.push((kind, depth));
        RayPath(rays)
    }

    /// Whether this is the primary ray.
    pub fn is_primary(&self) -> bool {
        self.0.len() == 1
    }

    /// The rays from the primary one, each kind with its depth.
    pub fn rays(&self) -> &[(Kind, u32)] {
        &self.0
    }
}

/// `primary → refracted d2 → reflected d3`.
impl fmt::Display for RayPath {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        for (i, (kind, depth)) in self.0.iter().enumerate() {
            if i == 0 {
                write!(f, "{}", kind.name())?;
            } else {
                write!(f, " → {} d{depth}", kind.name())?;
            }
        }
        Ok(())
    }
}

/// A ray's child: reflected or refracted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Child {
    /// The mirror direction, weighted by `k_rfl`.
    Reflected,
    /// Through the surface, weighted by `k_rfa`.
    Refracted,
}

impl Child {
    /// The learner's kind of the ray.
    pub fn kind(self) -> Kind {
        match self {
            Child::Reflected => Kind::Reflected,
            Child::Refracted => Kind::Refracted,
        }
    }
}

/// What differs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// The ray's origin.
    Origin,
    /// The ray's direction, as a unit vector.
    Direction,
    /// Whether the ray hit something.
    Hit,
    /// The object hit.
    HitObject,
    /// The hit's t, as a distance.
    HitT,
    /// The hit point.
    HitPoint,
    /// The hit's normal, as a unit vector.
    HitNormal,
    /// Whether the ray enters the object.
    HitEntering,
    /// How many shadow rays, one per light.
    ShadowCount,
    /// A field of shadow ray `k`.
    Shadow(usize, ShadowField),
    /// The local (Phong) color.
    LocalColor,
    /// A child's coefficient, `k_rfl` or `k_rfa`.
    Coefficient(Child),
    /// A child the learner did not spawn.
    Spawned(Child),
    /// A ray the learner spawned where raytree spawned none.
    Ray,
    /// Total internal reflection at the hit.
    Tir,
    /// The ray's color.
    Color,
}

/// A field of a shadow ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadowField {
    /// The light it goes to.
    Light,
    /// Where it starts.
    Origin,
    /// Its direction, as a unit vector.
    Direction,
    /// Whether it is blocked.
    Blocked,
    /// The object blocking it.
    By,
    /// The share of the light arriving through transparent objects.
    Transmitted,
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let words = match self {
            Quantity::Origin => "origin",
            Quantity::Direction => "direction (as a unit vector)",
            Quantity::Hit => "hit",
            Quantity::HitObject => "hit.object",
            Quantity::HitT => "hit.t (as a distance, t·|direction|)",
            Quantity::HitPoint => "hit.point",
            Quantity::HitNormal => "hit.normal (as a unit vector)",
            Quantity::HitEntering => "hit.entering",
            Quantity::ShadowCount => "shadows (one per light)",
            Quantity::Shadow(k, field) => return write!(f, "shadows[{k}].{field}"),
            Quantity::LocalColor => "local color",
            Quantity::Coefficient(Child::Reflected) => "k_rfl",
            Quantity::Coefficient(Child::Refracted) => "k_rfa",
            Quantity::Spawned(child) => child.kind().name(),
            Quantity::Ray => "ray",
            Quantity::Tir => "tir (total internal reflection)",
            Quantity::Color => "color",
        };
        f.write_str(words)
    }
}

impl fmt::Display for ShadowField {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(match self {
            ShadowField::Light => "light",
            ShadowField::Origin => "origin",
            ShadowField::Direction => "direction (as a unit vector)",
            ShadowField::Blocked => "blocked",
            ShadowField::By => "by",
            ShadowField::Transmitted => "transmitted",
        })
    }
}

/// One side's value of a quantity.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A point or a direction.
    Vector(DVec3),
    /// A linear color.
    Color(DVec3),
    /// A number: a distance, a share.
    Number(f64),
    /// A coefficient per channel, said as one number where the channels agree.
    Coefficient(DVec3),
    /// A count.
    Count(usize),
    /// Yes or no.
    Flag(bool),
    /// An object or a light of the scene, by name.
    Named(String),
    /// A light's name the scene has no light of.
    UnknownLight(String),
    /// The scene's light number `number`.
    SceneLight {
        /// Its name.
        name: String,
        /// Its place in the scene's list.
        number: usize,
    },
    /// The ray hit `object` at `distance` (t·|direction|).
    HitAt {
        /// The object's name.
        object: String,
        /// How far along the ray.
        distance: f64,
    },
    /// The ray hit an object it does not name.
    Something,
    /// The ray missed.
    Missed,
    /// Entering the object, or leaving it.
    Entering(bool),
    /// A child spawned, with its depth where raytree's says it.
    Spawned(Option<u32>),
    /// No such child, with why where raytree has none.
    NotSpawned(Option<NoChild>),
    /// A shadow ray reaching its light.
    Reaches,
    /// A shadow ray blocked, by the object named if any.
    Blocked(Option<String>),
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            Value::Vector(v) => f.write_str(&vec_words(*v)),
            Value::Color(c) => f.write_str(&color_words(*c)),
            Value::Number(x) => f.write_str(&num(*x)),
            // A number written as one is said as one.
            Value::Coefficient(k) if k.x == k.y && k.y == k.z => f.write_str(&num(k.x)),
            Value::Coefficient(k) => f.write_str(&vec_words(*k)),
            Value::Count(n) => write!(f, "{n}"),
            Value::Flag(b) => write!(f, "{b}"),
            Value::Named(name) => write!(f, "'{name}'"),
            Value::UnknownLight(name) => {
                write!(f, "'{name}' (the scene has no light of that name)")
            }
            Value::SceneLight { name, number } => {
                write!(f, "'{name}' (the scene's light number {number})")
            }
            Value::HitAt { object, distance } => {
                write!(f, "'{object}' at distance {}", num(*distance))
            }
            Value::Something => f.write_str("something"),
            Value::Missed => f.write_str("missed"),
            Value::Entering(true) => f.write_str("entering"),
            Value::Entering(false) => f.write_str("leaving"),
            Value::Spawned(None) => f.write_str("spawned"),
            Value::Spawned(Some(depth)) => write!(f, "spawned (depth {depth})"),
            Value::NotSpawned(None) => f.write_str("not spawned"),
            Value::NotSpawned(Some(why)) => write!(f, "not spawned ({why})"),
            Value::Reaches => f.write_str("reaches the light"),
            Value::Blocked(Some(by)) => write!(f, "blocked by '{by}'"),
            Value::Blocked(None) => f.write_str("blocked (no blocker named)"),
        }
    }
}

/// Why raytree has no child where the learner traced one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoChild {
    /// The ray was at the scene's `max_depth`.
    MaxDepth,
    /// Its weight was below the cutoff.
    WeightCutoff,
    /// Its coefficient is 0.
    NoCoefficient,
    /// Total internal reflection: no refracted ray.
    TotalInternalReflection,
    /// raytree's ray missed.
    Missed,
}

impl NoChild {
    /// Why raytree's branch of this `outcome` (none: the ray missed) has no ray.
    pub fn of(outcome: Option<Branch>) -> Self {
        match outcome {
            Some(Branch::MaxDepth) => NoChild::MaxDepth,
            Some(Branch::WeightCutoff) => NoChild::WeightCutoff,
            Some(Branch::NoCoefficient) => NoChild::NoCoefficient,
            Some(Branch::TotalInternalReflection) => NoChild::TotalInternalReflection,
            Some(Branch::Traced) | None => NoChild::Missed,
        }
    }

    /// Whether a learner's child here is tolerated: raytree only stopped
    /// early (for its depth, its weight, a zero coefficient), where a tracer
    /// may go on.
    pub fn tolerated(self) -> bool {
        matches!(
            self,
            NoChild::MaxDepth | NoChild::WeightCutoff | NoChild::NoCoefficient
        )
    }
}

impl fmt::Display for NoChild {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(match self {
            NoChild::MaxDepth => "raytree stopped at the scene's max_depth",
            NoChild::WeightCutoff => "raytree skipped it: its weight is below the cutoff",
            NoChild::NoCoefficient => "raytree spawns none: its coefficient is 0",
            NoChild::TotalInternalReflection => {
                "total internal reflection: there is no refracted ray"
            }
            NoChild::Missed => "raytree's ray missed: it has no children",
        })
    }
}

/// Written as the report's words.
impl Serialize for RayPath {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// Written as the report's words.
impl Serialize for Quantity {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// Written as the report's words.
impl Serialize for Value {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}
