//! The methods the lecture uses beside the ones robust practice uses, each
//! selectable (scene `render` settings, command-line flags), so a lesson can show
//! where the textbook method fails and what the robust one costs. The robust
//! choice is the default where there is one.

use serde::{Deserialize, Serialize};

/// How a ray meets a sphere.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum SphereMethod {
    /// The lecture's quadratic as written.
    Lecture,
    /// The numerically stable form (Ray Tracing Gems ch. 7).
    #[default]
    Stable,
}

/// How a ray meets a triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum TriangleMethod {
    /// The textbook Möller–Trumbore test: rays through shared edges can slip
    /// between two triangles.
    MollerTrumbore,
    /// Woop, Benthin & Wald's watertight test (JCGT 2013).
    #[default]
    Watertight,
}

/// Which acceleration structure the tracer uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Accel {
    /// Chosen from the scene: a hierarchy once there are enough objects to pay
    /// for its box tests, none below.
    #[default]
    Auto,
    /// Test every object, as the lecture's `raytrace` does.
    None,
    /// A bounding volume hierarchy over the objects.
    Bvh,
    /// A uniform voxel grid, walked cell by cell (Amanatides & Woo's 3D-DDA).
    Grid,
    /// An octree, walked front to back.
    Octree,
    /// A BSP tree: the axis-aligned one, a k-d tree built with the surface
    /// area heuristic, walked front to back with the ray's interval.
    Bsp,
}

impl Accel {
    /// The name `--accel` and a scene file's `accel` give it.
    pub fn name(self) -> &'static str {
        match self {
            Accel::Auto => "auto",
            Accel::None => "none",
            Accel::Bvh => "bvh",
            Accel::Grid => "grid",
            Accel::Octree => "octree",
            Accel::Bsp => "bsp",
        }
    }

    /// What one traversal step of this structure is called (`plural` for any
    /// count but one): a box tested in a bounding volume hierarchy, a cell
    /// walked in a grid, a node walked in a tree. Meshes' own boxes count as
    /// box tests under every structure.
    pub fn step_word(self, plural: bool) -> &'static str {
        match (self, plural) {
            (Accel::Grid, false) => "grid cell walked",
            (Accel::Grid, true) => "grid cells walked",
            (Accel::Octree, false) => "octree node walked",
            (Accel::Octree, true) => "octree nodes walked",
            (Accel::Bsp, false) => "k-d tree node walked",
            (Accel::Bsp, true) => "k-d tree nodes walked",
            (_, false) => "box test",
            (_, true) => "box tests",
        }
    }
}

/// The intersection methods a ray is tested with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct IntersectionMethods {
    /// For spheres.
    pub sphere: SphereMethod,
    /// For triangles and meshes.
    pub triangle: TriangleMethod,
}

impl From<SphereMethod> for IntersectionMethods {
    fn from(sphere: SphereMethod) -> Self {
        IntersectionMethods {
            sphere,
            ..IntersectionMethods::default()
        }
    }
}

/// Where a secondary ray (reflected, refracted, shadow) starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Offset {
    /// At the computed hit point: the textbook bug, shadow acne.
    None,
    /// Moved a fixed distance along the normal, toward the side the ray leaves into.
    Epsilon(f64),
    /// Moved just past the hit point's own error bound (pbrt-v4 §6.8.6).
    #[default]
    Robust,
}

impl std::str::FromStr for Offset {
    type Err = String;

    /// `none`, `robust` or `epsilon=E` with `E > 0`, as the command line writes it.
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "none" => Ok(Offset::None),
            "robust" => Ok(Offset::Robust),
            _ => {
                let e = s
                    .strip_prefix("epsilon=")
                    .ok_or("expected none, robust or epsilon=E (e.g. epsilon=1e-4)")?;
                let e: f64 = e.parse().map_err(|_| format!("'{e}' is not a number"))?;
                if e.is_finite() && e > 0.0 {
                    Ok(Offset::Epsilon(e))
                } else {
                    Err(format!("the epsilon must be > 0, got {e}"))
                }
            }
        }
    }
}

/// How a pixel is sampled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Antialiasing {
    /// `spp` samples on an n × n grid of cell centers (1: the lecture's one ray).
    #[default]
    Grid,
    /// Whitted's adaptive corner subdivision ("An Improved Illumination Model for
    /// Shaded Display", 1980): trace the pixel's four corners; where they differ
    /// by more than `threshold` (in any channel, from their mean), split the square
    /// into four and repeat, at most `levels` times; a square's color is the mean of
    /// its corners, a split square's the mean of its quarters.
    Adaptive {
        /// Largest difference of a corner from the corners' mean that is left alone (linear RGB).
        threshold: f64,
        /// How many times a square may be split (3: down to 1/8 of a pixel).
        levels: u32,
    },
    /// The Standard Procedural Databases' protocol (Haines, "A Proposal for
    /// Standard Graphics Environments", 1987): one ray through each of the
    /// `(W + 1) × (H + 1)` pixel corners, each traced once, and a pixel the mean
    /// of its four corners; `spp` is ignored.
    Corners,
}

impl std::str::FromStr for Antialiasing {
    type Err = String;

    /// `grid`, `corners`, `adaptive` (threshold 0.05) or `adaptive=T` with
    /// `T ≥ 0`, three levels of subdivision, as the command line writes it.
    fn from_str(s: &str) -> Result<Self, String> {
        match s.split_once('=') {
            None if s == "grid" => Ok(Antialiasing::Grid),
            None if s == "corners" => Ok(Antialiasing::Corners),
            None if s == "adaptive" => Ok(Antialiasing::Adaptive {
                threshold: 0.05,
                levels: 3,
            }),
            Some(("adaptive", t)) => match t.parse::<f64>() {
                Ok(threshold) if threshold.is_finite() && threshold >= 0.0 => {
                    Ok(Antialiasing::Adaptive {
                        threshold,
                        levels: 3,
                    })
                }
                _ => Err(format!("'{t}' is not a threshold (a number ≥ 0)")),
            },
            _ => Err(
                "expected grid, corners, adaptive or adaptive=T (e.g. adaptive=0.05)".to_owned(),
            ),
        }
    }
}

/// How a transparent surface splits its light between the reflected and the
/// refracted ray. With reflectance `R`, the reflected ray's weight is
/// `k_rfl + k_rfa·R` and the refracted ray's `k_rfa·(1 - R)`: the two shares of
/// the transmitted light always sum to `k_rfa`, and total internal reflection is
/// `R = 1` under every method.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Weights {
    /// The lecture's constant `k_rfl` and `k_rfa` (`R = 0` unless totally reflected).
    #[default]
    Constant,
    /// Schlick's approximation of the Fresnel reflectance.
    Schlick,
    /// The exact Fresnel equations for a dielectric.
    Fresnel,
}

/// A size of a structure of the efficiency slide: `auto` (its builder's own
/// rule) or a number given by the user (a grid's cells along the scene's
/// longest side, a tree's deepest level). Written `auto` or a whole number, in
/// a scene file as on the command line.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Level {
    /// The builder's own rule.
    #[default]
    Auto,
    /// This many.
    Given(u32),
}

impl Serialize for Level {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Level::Auto => s.serialize_str("auto"),
            Level::Given(n) => s.serialize_u32(*n),
        }
    }
}

impl<'de> Deserialize<'de> for Level {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(LevelVisitor)
    }
}

/// Reads a [`Level`] from `"auto"` or a whole number, with errors in words.
struct LevelVisitor;

impl serde::de::Visitor<'_> for LevelVisitor {
    type Value = Level;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("auto or a whole number")
    }

    fn visit_u64<E: serde::de::Error>(self, n: u64) -> Result<Level, E> {
        u32::try_from(n).map(Level::Given).map_err(|_| {
            E::custom(format!(
                "expected auto or a whole number up to 4294967295, got {n}"
            ))
        })
    }

    fn visit_i64<E: serde::de::Error>(self, n: i64) -> Result<Level, E> {
        u64::try_from(n)
            .map_err(|_| E::custom(format!("expected auto or a whole number, got {n}")))
            .and_then(|n| self.visit_u64(n))
    }

    fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<Level, E> {
        Err(E::custom(format!(
            "expected auto or a whole number, got {x}"
        )))
    }

    fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<Level, E> {
        s.parse().map_err(E::custom)
    }
}

impl std::str::FromStr for Level {
    type Err = String;

    /// `auto` or a whole number.
    fn from_str(s: &str) -> Result<Self, String> {
        if s == "auto" {
            return Ok(Level::Auto);
        }
        s.parse::<u32>()
            .map(Level::Given)
            .map_err(|_| format!("expected auto or a whole number, got '{s}'"))
    }
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Level::Auto => f.write_str("auto"),
            Level::Given(n) => write!(f, "{n}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Accel::name` is the word the command line and a scene file take: a
    /// CSV or a message that writes it can be read back by either.
    #[test]
    fn an_accel_s_name_is_its_flag_and_its_json() {
        for a in <Accel as clap::ValueEnum>::value_variants() {
            let flag = clap::ValueEnum::to_possible_value(a).unwrap();
            assert_eq!(flag.get_name(), a.name());
            assert_eq!(serde_json::to_value(a).unwrap(), a.name());
        }
    }
}
