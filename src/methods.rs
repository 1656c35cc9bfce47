//! The methods the lecture uses beside the ones robust practice uses, each
//! selectable (scene `render` settings, command-line flags), so a lesson can show
//! where the textbook method fails and what the robust one costs. The robust
//! choice is the default where there is one.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::geometry::hit::Surface;
use crate::math::float::offset_ray_origin;

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
}

/// The intersection methods a ray is tested with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Intersection {
    /// For spheres.
    pub sphere: SphereMethod,
    /// For triangles and meshes.
    pub triangle: TriangleMethod,
}

impl From<SphereMethod> for Intersection {
    fn from(sphere: SphereMethod) -> Self {
        Intersection {
            sphere,
            ..Intersection::default()
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

impl Offset {
    /// The origin of a ray leaving `surface` in direction `dir`.
    #[inline]
    pub fn origin(self, surface: &Surface, dir: DVec3) -> DVec3 {
        match self {
            Offset::None => surface.point,
            Offset::Epsilon(e) => {
                surface.point + if dir.dot(surface.normal) < 0.0 { -e } else { e } * surface.normal
            }
            Offset::Robust => {
                offset_ray_origin(surface.point, surface.point_error, surface.normal, dir)
            }
        }
    }
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
}

impl std::str::FromStr for Antialiasing {
    type Err = String;

    /// `grid`, `adaptive` (threshold 0.05) or `adaptive=T` with `T ≥ 0`, three
    /// levels of subdivision, as the command line writes it.
    fn from_str(s: &str) -> Result<Self, String> {
        match s.split_once('=') {
            None if s == "grid" => Ok(Antialiasing::Grid),
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
            _ => Err("expected grid, adaptive or adaptive=T (e.g. adaptive=0.05)".to_owned()),
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

impl Weights {
    /// The reflectance `R` for light arriving at `cos_i` (cosine of the angle to
    /// the normal, on the incoming side) from index `n1` into index `n2`.
    pub fn reflectance(self, cos_i: f64, n1: f64, n2: f64) -> f64 {
        let cos_i = cos_i.clamp(0.0, 1.0);
        let eta = n1 / n2;
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        let cos_t = (1.0 - sin2_t).sqrt();
        match self {
            Weights::Constant => 0.0,
            Weights::Schlick => schlick(cos_i, cos_t, n1, n2),
            Weights::Fresnel => fresnel_dielectric(cos_i, cos_t, n1, n2),
        }
    }
}

/// Schlick's approximation ("An Inexpensive BRDF Model for Physically-based
/// Rendering", 1994): `R = R₀ + (1 - R₀)(1 - cos θ)⁵`, `R₀ = ((n₁ - n₂)/(n₁ + n₂))²`.
/// Going into a less dense medium, θ is the transmitted angle (de Greve,
/// "Reflections and Refractions in Ray Tracing", 2006), else it misses the
/// rise of `R` toward the critical angle.
pub fn schlick(cos_i: f64, cos_t: f64, n1: f64, n2: f64) -> f64 {
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    let c = if n1 > n2 { cos_t } else { cos_i };
    r0 + (1.0 - r0) * (1.0 - c).powi(5)
}

/// The Fresnel equations for unpolarized light at a dielectric boundary (pbrt-v4
/// §9.3.2, `FrDielectric`): the mean of the parallel and perpendicular reflectances
/// `r∥ = (n₂ cos θᵢ - n₁ cos θₜ)/(n₂ cos θᵢ + n₁ cos θₜ)`,
/// `r⊥ = (n₁ cos θᵢ - n₂ cos θₜ)/(n₁ cos θᵢ + n₂ cos θₜ)`.
pub fn fresnel_dielectric(cos_i: f64, cos_t: f64, n1: f64, n2: f64) -> f64 {
    let parallel = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    let perpendicular = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    (parallel * parallel + perpendicular * perpendicular) / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_matches_known_values() {
        // Head-on into glass: ((1 - 1.5)/(1 + 1.5))² = 0.04, for both methods.
        assert!((Weights::Fresnel.reflectance(1.0, 1.0, 1.5) - 0.04).abs() < 1e-15);
        assert!((Weights::Schlick.reflectance(1.0, 1.0, 1.5) - 0.04).abs() < 1e-15);
        // Brewster's angle atan(1.5) = 56.31°: the parallel part vanishes, so R = r⊥²/2.
        // r⊥ = (cos θᵢ - 1.5 cos θₜ)/(cos θᵢ + 1.5 cos θₜ) with θₜ = 90° - θᵢ: (0.5547 - 1.5·0.8321)/(0.5547 + 1.5·0.8321) = -0.3846.
        let brewster = 1.5f64.atan();
        let r = Weights::Fresnel.reflectance(brewster.cos(), 1.0, 1.5);
        assert!((r - 0.384_615_4f64.powi(2) / 2.0).abs() < 1e-7, "{r}");
        // Grazing: everything reflects.
        assert!(Weights::Fresnel.reflectance(1e-9, 1.0, 1.5) > 0.999_999);
        // Beyond the critical angle from inside glass: total internal reflection under every method.
        for w in [Weights::Constant, Weights::Schlick, Weights::Fresnel] {
            assert_eq!(w.reflectance(0.5, 1.5, 1.0), 1.0);
        }
        assert_eq!(Weights::Constant.reflectance(0.9, 1.0, 1.5), 0.0);
    }

    #[test]
    fn epsilon_offset_moves_along_the_normal_toward_the_ray() {
        let s = Surface {
            point: DVec3::ZERO,
            point_error: DVec3::ZERO,
            normal: DVec3::Y,
            shading_normal: DVec3::Y,
            pattern_point: DVec3::ZERO,
        };
        assert_eq!(
            Offset::Epsilon(0.1).origin(&s, DVec3::new(1.0, 1.0, 0.0)),
            DVec3::new(0.0, 0.1, 0.0)
        );
        assert_eq!(
            Offset::Epsilon(0.1).origin(&s, DVec3::new(1.0, -1.0, 0.0)),
            DVec3::new(0.0, -0.1, 0.0)
        );
        assert_eq!(Offset::None.origin(&s, DVec3::Y), DVec3::ZERO);
    }
}
