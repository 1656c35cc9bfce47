//! The classic mistakes `raytree check` recognises: one variant each, with
//! its id (the JSON report's, a contract with autograders: it never changes)
//! and the lesson that teaches its formula. Each lesson's file below holds
//! the recognisers of its mistakes, so which mistakes lesson 7 knows is
//! `phong.rs`; [`crate::course::learner::diagnose`] says which of them a
//! difference asks.
//!
//! A recogniser recomputes the learner's number with its one mistake from
//! raytree's own inputs (the camera, the recorded roots, the hit's normal and
//! indices, the light's terms) and names it only when that matches within the
//! comparison's tolerance: never guessed, no match, no diagnosis. The
//! formulas are the lecture's (`lecture-raytracing.md`: the ray through a
//! pixel, the sphere's quadratic, the shadow ray, `v = c − 2(n·c)n`, Snell's
//! law, the recursive sum). Every mistake is proved by a mutant of the Python
//! solution (`lessons/python/tools/mutants.py`, run by
//! `tests/suite/tracer/mutants.rs`).
//!
//! To add one: a variant here (in [`Mistake::ALL`], its id and its lesson in
//! the two matches), its recogniser in its lesson's file, asked from
//! `diagnose.rs`, its mutant, and its row in `docs/learner-trace.md` (a test
//! holds the table to this catalogue).

pub mod camera; // lessons/03-camera: the primary ray through the pixel
pub mod sphere; // lessons/05-sphere: which root is the hit
pub mod transforms; // lessons/06-transforms: a transformed object's normal
pub mod phong; // lessons/07-phong: the local color
pub mod shadows; // lessons/08-shadows: the shadow ray, and the offset against acne
pub mod reflection; // lessons/09-reflection: the mirror direction
pub mod refraction; // lessons/10-refraction: Snell's law, the media, the normal's side
pub mod recursion; // lessons/11-recursion: the recursive sum
pub mod image; // the whole image at once: the sRGB encoding, flipped, mirrored, BGR

use glam::DVec3;
use serde::{Serialize, Serializer};

/// Whether a direction remade with a mistake is the learner's, within the
/// ray's tolerance (`None`: the formula gives no direction there, as Snell's
/// past the critical angle).
pub type Same<'a> = dyn Fn(Option<DVec3>) -> bool + 'a;

/// A lesson that teaches the formula of a mistake.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lesson {
    /// The camera and the ray through a pixel.
    Camera,
    /// The ray–sphere roots.
    Sphere,
    /// Transformed objects.
    Transforms,
    /// Phong's local model.
    Phong,
    /// Shadow rays.
    Shadows,
    /// The reflected ray.
    Reflection,
    /// The refracted ray.
    Refraction,
    /// The recursive sum.
    Recursion,
}

impl Lesson {
    /// Its folder, as the report names it: `lessons/03-camera`.
    pub fn path(self) -> &'static str {
        match self {
            Lesson::Camera => "lessons/03-camera",
            Lesson::Sphere => "lessons/05-sphere",
            Lesson::Transforms => "lessons/06-transforms",
            Lesson::Phong => "lessons/07-phong",
            Lesson::Shadows => "lessons/08-shadows",
            Lesson::Reflection => "lessons/09-reflection",
            Lesson::Refraction => "lessons/10-refraction",
            Lesson::Recursion => "lessons/11-recursion",
        }
    }
}

/// Where a vector was used not of unit length: `not-normalized` is taught
/// wherever the vector is made, so its lesson is this one's.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Formula {
    /// The reflected direction, with `n = P − center` (lesson 9).
    Reflection,
    /// Snell's formula, with the incoming direction or the normal unnormalized (lesson 10).
    Refraction,
    /// Phong's N, L or V (lesson 7).
    Phong,
    /// A transformed object's normal, which `(M⁻¹)ᵀ` stretches, used in Phong's formula (lesson 6).
    Transform,
}

/// A classic mistake of a learner's tracer, recognised from its numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mistake {
    /// Rows counted from the top where the lecture counts row r up from the bottom.
    RowsFlipped,
    /// The primary ray through a corner of the pixel, not its center.
    PixelCorner,
    /// Primary rays on a grid spaced by 2W/N, not 2W/(N − 1).
    PixelSpacing,
    /// The far root of the quadratic taken for the hit.
    FarRoot,
    /// A negative root, behind the ray's origin, taken for the hit.
    NegativeRoot,
    /// A child or shadow ray meeting the surface it starts on (acne).
    NoOffset,
    /// The outward normal used where the ray leaves the object.
    NormalNotTurned,
    /// The normal turned into the object where the ray arrives from outside.
    NormalInward,
    /// A transformed object's normal carried by `M` or `M⁻¹`, not `(M⁻¹)ᵀ`.
    NormalTransform,
    /// A shadow ray from the light instead of toward it.
    ShadowReversed,
    /// A shadow ray blocked by an object beyond the light.
    ShadowBeyondLight,
    /// A shadow ray stopped by a transparent object.
    TransparentBlocks,
    /// A transparent object's k_rfa applied at each surface crossed.
    TransparentPerSurface,
    /// Phong's terms not clamped at 0.
    NotClamped,
    /// The ambient term left out.
    AmbientForgotten,
    /// The highlight tinted by the surface's color.
    SpecularColored,
    /// V along the ray instead of back to the viewer.
    ViewSign,
    /// The reflected direction `c + 2(n·c)n`.
    ReflectionSign,
    /// A vector used not of unit length.
    NotNormalized(Formula),
    /// Snell's law with η = n₂/n₁.
    EtaSwapped,
    /// Snell's formula with the square root added.
    RefractionRootSign,
    /// Snell's formula with cos θ₁ = n·c, negative.
    RefractionCosSign,
    /// Snell's law with another pair of the scene's indices.
    WrongMedium,
    /// A refracted ray past the critical angle.
    TirNotHandled,
    /// The children's colors summed without their coefficients, or with them twice.
    Coefficients,
}

impl Mistake {
    /// Every mistake, in the order the algorithm meets them.
    pub const ALL: [Mistake; 28] = [
        Mistake::RowsFlipped,
        Mistake::PixelCorner,
        Mistake::PixelSpacing,
        Mistake::FarRoot,
        Mistake::NegativeRoot,
        Mistake::NoOffset,
        Mistake::NormalNotTurned,
        Mistake::NormalInward,
        Mistake::NormalTransform,
        Mistake::ShadowReversed,
        Mistake::ShadowBeyondLight,
        Mistake::TransparentBlocks,
        Mistake::TransparentPerSurface,
        Mistake::NotClamped,
        Mistake::AmbientForgotten,
        Mistake::SpecularColored,
        Mistake::ViewSign,
        Mistake::NotNormalized(Formula::Transform),
        Mistake::NotNormalized(Formula::Phong),
        Mistake::ReflectionSign,
        Mistake::NotNormalized(Formula::Reflection),
        Mistake::EtaSwapped,
        Mistake::RefractionRootSign,
        Mistake::RefractionCosSign,
        Mistake::NotNormalized(Formula::Refraction),
        Mistake::WrongMedium,
        Mistake::TirNotHandled,
        Mistake::Coefficients,
    ];

    /// Its stable id for autograders: `rows-flipped`, `far-root`, ….
    pub fn id(self) -> &'static str {
        match self {
            Mistake::RowsFlipped => "rows-flipped",
            Mistake::PixelCorner => "pixel-corner",
            Mistake::PixelSpacing => "pixel-spacing",
            Mistake::FarRoot => "far-root",
            Mistake::NegativeRoot => "negative-root",
            Mistake::NoOffset => "no-offset",
            Mistake::NormalNotTurned => "normal-not-turned",
            Mistake::NormalInward => "normal-inward",
            Mistake::NormalTransform => "normal-transform",
            Mistake::ShadowReversed => "shadow-reversed",
            Mistake::ShadowBeyondLight => "shadow-beyond-light",
            Mistake::TransparentBlocks => "transparent-blocks",
            Mistake::TransparentPerSurface => "transparent-per-surface",
            Mistake::NotClamped => "not-clamped",
            Mistake::AmbientForgotten => "ambient-forgotten",
            Mistake::SpecularColored => "specular-colored",
            Mistake::ViewSign => "view-sign",
            Mistake::ReflectionSign => "reflection-sign",
            Mistake::NotNormalized(_) => "not-normalized",
            Mistake::EtaSwapped => "eta-swapped",
            Mistake::RefractionRootSign => "refraction-root-sign",
            Mistake::RefractionCosSign => "refraction-cos-sign",
            Mistake::WrongMedium => "wrong-medium",
            Mistake::TirNotHandled => "tir-not-handled",
            Mistake::Coefficients => "coefficients",
        }
    }

    /// The lesson that teaches its formula.
    pub fn lesson(self) -> Lesson {
        match self {
            Mistake::RowsFlipped | Mistake::PixelCorner | Mistake::PixelSpacing => Lesson::Camera,
            Mistake::FarRoot | Mistake::NegativeRoot => Lesson::Sphere,
            Mistake::NormalTransform | Mistake::NotNormalized(Formula::Transform) => {
                Lesson::Transforms
            }
            Mistake::NotClamped
            | Mistake::AmbientForgotten
            | Mistake::SpecularColored
            | Mistake::ViewSign
            | Mistake::NotNormalized(Formula::Phong) => Lesson::Phong,
            Mistake::NoOffset
            | Mistake::ShadowReversed
            | Mistake::ShadowBeyondLight
            | Mistake::TransparentBlocks
            | Mistake::TransparentPerSurface => Lesson::Shadows,
            Mistake::ReflectionSign | Mistake::NotNormalized(Formula::Reflection) => {
                Lesson::Reflection
            }
            Mistake::NormalNotTurned
            | Mistake::NormalInward
            | Mistake::EtaSwapped
            | Mistake::RefractionRootSign
            | Mistake::RefractionCosSign
            | Mistake::NotNormalized(Formula::Refraction)
            | Mistake::WrongMedium
            | Mistake::TirNotHandled => Lesson::Refraction,
            Mistake::Coefficients => Lesson::Recursion,
        }
    }
}

/// Written as its id.
impl Serialize for Mistake {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

/// A classic mistake recognised in the numbers, with what they show.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnosis {
    /// The mistake.
    pub mistake: Mistake,
    /// What the numbers show, in the lecture's words.
    pub words: String,
}

impl Diagnosis {
    /// `mistake`, shown by the numbers as `words` say.
    pub fn new(mistake: Mistake, words: impl Into<String>) -> Self {
        Diagnosis {
            mistake,
            words: words.into(),
        }
    }

    /// The mistake's id.
    pub fn id(&self) -> &'static str {
        self.mistake.id()
    }

    /// The folder of the lesson that teaches its formula.
    pub fn lesson(&self) -> &'static str {
        self.mistake.lesson().path()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `docs/learner-trace.md` lists every id with its lessons, and no other:
    /// the table an autograder's author reads is the catalogue.
    #[test]
    fn the_documented_table_is_the_catalogue() {
        let docs = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/learner-trace.md"),
        )
        .unwrap();
        let table = &docs[docs.find("## The diagnoses").unwrap()..];
        let table = &table[..table.find("\n## ").unwrap()];
        let rows: Vec<(&str, &str)> = table
            .lines()
            .filter_map(|l| {
                let cells: Vec<&str> = l.split(" | ").collect();
                let id = cells.first()?.strip_prefix("| `")?.strip_suffix('`')?;
                Some((id, *cells.last()?))
            })
            .collect();
        for m in Mistake::ALL {
            let (_, lessons) = rows
                .iter()
                .find(|(id, _)| *id == m.id())
                .unwrap_or_else(|| panic!("{}: not in docs/learner-trace.md", m.id()));
            let number = &m.lesson().path()["lessons/".len()..];
            assert!(lessons.contains(number), "{}: {lessons}", m.id());
        }
        for (id, _) in &rows {
            assert!(
                Mistake::ALL.iter().any(|m| m.id() == *id),
                "{id}: documented, not in the catalogue"
            );
        }
    }
}
