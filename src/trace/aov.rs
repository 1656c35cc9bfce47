//! Per-pixel quantities ("arbitrary output values", as renderers call them):
//! instead of a pixel's color, one number, color or category that explains it,
//! such as the reflected term alone, the deepest ray of its tree, or how many
//! intersection tests it cost. They are computed by the same tracer through
//! [`crate::trace::aov_render`]'s recorder; this module says which quantities
//! there are, what each means and how its key reads.

use glam::DVec3;

use crate::geometry::object::Shape;
use crate::scene::Scene;
use crate::trace::recorder::RayKind;

/// A quantity to show per pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aov {
    /// The local color at the primary hit (the background for a miss).
    Local,
    /// `k_rfl · reflected` at the primary hit.
    Reflected,
    /// `k_rfa · refracted` at the primary hit.
    Refracted,
    /// The ambient term at the primary hit.
    Ambient,
    /// The diffuse terms of every light, summed, at the primary hit.
    Diffuse,
    /// The specular terms of every light, summed, at the primary hit.
    Specular,
    /// What the primary hit's shadow rays found: for one light, or which of
    /// all the lights it sees.
    Shadow(Option<usize>),
    /// The deepest ray of the pixel's tree (1: the primary ray alone).
    Depth,
    /// Rays the pixel cast, of one kind or all.
    Rays(Option<RayKind>),
    /// Bounding-box and primitive tests the pixel's rays made.
    Tests,
    /// The unit normal at the primary hit.
    Normal,
    /// The distance from the eye to the primary hit.
    T,
    /// Which object the primary ray hit.
    Object,
    /// `B² − AC` of the primary ray against this sphere (an object index).
    Discriminant(usize),
    /// Whether the pixel's tree holds a total internal reflection.
    Tir,
}

/// Every quantity's name, with what it shows: the `--help` text and the list
/// an unknown name is answered with.
pub const NAMES: &[(&str, &str)] = &[
    (
        "local",
        "the local color at the first hit (the background where the ray misses)",
    ),
    ("reflected", "k_rfl × the reflected color at the first hit"),
    ("refracted", "k_rfa × the refracted color at the first hit"),
    ("ambient", "the ambient term at the first hit"),
    (
        "diffuse",
        "the diffuse terms of all lights at the first hit",
    ),
    (
        "specular",
        "the specular terms of all lights at the first hit",
    ),
    (
        "shadow[=LIGHT]",
        "what the first hit's shadow rays found, for one light or all",
    ),
    ("depth", "the deepest ray of the pixel's tree"),
    (
        "rays[=KIND]",
        "rays per pixel: all, or primary, reflected, refracted, shadow",
    ),
    ("tests", "bounding-box and object tests per pixel"),
    ("normal", "the unit normal at the first hit, as a color"),
    ("t", "the distance from the eye to the first hit"),
    ("object", "which object the primary ray hits"),
    (
        "discriminant[=SPHERE]",
        "B² − AC of the primary ray against a sphere",
    ),
    ("tir", "pixels whose tree holds a total internal reflection"),
];

/// At most this many lights get a category per combination in `shadow`; more
/// are shown as a count of the lights seen.
pub const MAX_COMBINED_LIGHTS: usize = 3;

/// How a quantity's values read, and so how its key is drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum Key {
    /// Linear RGB colors, shown as the render shows its colors.
    Colors,
    /// A unit vector as a color: `(x, y, z) → ((x + 1)/2, (y + 1)/2, (z + 1)/2)`.
    Normals,
    /// A number on a colormap.
    Scale {
        /// Its unit, as the bar reads it.
        unit: String,
        /// Whole numbers only (counts, depths): the bar has a step per value
        /// when there are few.
        whole: bool,
        /// Its sign matters: a diverging colormap centered on zero.
        signed: bool,
    },
    /// One of these categories.
    Categories(Vec<String>),
}

/// One pixel's value.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Value {
    /// A linear RGB color, or a unit normal.
    Color(DVec3),
    /// A number.
    Number(f64),
    /// The index of a category of the key.
    Category(u32),
    /// The quantity has no value here: the primary ray hit nothing.
    #[default]
    Undefined,
}

/// A quantity rendered for every pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct AovImage {
    /// What was rendered.
    pub aov: Aov,
    /// Its name as given on the command line, e.g. `shadow=key`.
    pub name: String,
    /// What it shows, in a line.
    pub title: String,
    /// How its values read.
    pub key: Key,
    /// What an [`Value::Undefined`] pixel means.
    pub undefined: &'static str,
    /// A line more for the key, where the values need one.
    pub note: &'static str,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row by row from the top.
    pub values: Vec<Value>,
}

impl AovImage {
    /// The value at image coordinates `(x, y)`.
    pub fn get(&self, x: u32, y: u32) -> Value {
        self.values[y as usize * self.width as usize + x as usize]
    }
}

impl Aov {
    /// Reads `NAME[=ARGUMENT]`, naming lights and spheres of `scene`; the error
    /// is one line saying what is known.
    pub fn parse(spec: &str, scene: &Scene) -> Result<Aov, String> {
        let (name, arg) = match spec.split_once('=') {
            Some((n, a)) => (n.trim(), Some(a.trim())),
            None => (spec.trim(), None),
        };
        let plain = match name {
            "local" => Some(Aov::Local),
            "reflected" => Some(Aov::Reflected),
            "refracted" => Some(Aov::Refracted),
            "ambient" => Some(Aov::Ambient),
            "diffuse" => Some(Aov::Diffuse),
            "specular" => Some(Aov::Specular),
            "depth" => Some(Aov::Depth),
            "tests" => Some(Aov::Tests),
            "normal" => Some(Aov::Normal),
            "t" => Some(Aov::T),
            "object" => Some(Aov::Object),
            "tir" => Some(Aov::Tir),
            _ => None,
        };
        match (plain, name, arg) {
            (Some(aov), _, None) => Ok(aov),
            (Some(_), _, Some(_)) => Err(format!("'{name}' takes no value (got '{spec}')")),
            (None, "shadow", arg) => shadow(arg, scene),
            (None, "rays", arg) => rays(arg),
            (None, "discriminant", arg) => discriminant(arg, scene),
            _ => {
                let known: Vec<&str> = NAMES.iter().map(|(n, _)| *n).collect();
                Err(format!(
                    "unknown quantity '{name}' (known: {})",
                    known.join(", ")
                ))
            }
        }
    }

    /// The name as the command line gives it, e.g. `shadow=key`.
    pub fn name(&self, scene: &Scene) -> String {
        let simple = |s: &str| s.to_owned();
        match *self {
            Aov::Local => simple("local"),
            Aov::Reflected => simple("reflected"),
            Aov::Refracted => simple("refracted"),
            Aov::Ambient => simple("ambient"),
            Aov::Diffuse => simple("diffuse"),
            Aov::Specular => simple("specular"),
            Aov::Shadow(None) => simple("shadow"),
            Aov::Shadow(Some(l)) => format!("shadow={}", scene.lights[l].name),
            Aov::Depth => simple("depth"),
            Aov::Rays(None) => simple("rays"),
            Aov::Rays(Some(kind)) => format!("rays={}", kind.name()),
            Aov::Tests => simple("tests"),
            Aov::Normal => simple("normal"),
            Aov::T => simple("t"),
            Aov::Object => simple("object"),
            Aov::Discriminant(i) => format!("discriminant={}", scene.objects[i].name),
            Aov::Tir => simple("tir"),
        }
    }

    /// What the image shows, in a line for its key.
    pub fn title(&self, scene: &Scene) -> String {
        match *self {
            Aov::Local => "local color at the first hit (ambient + diffuse + specular)".into(),
            Aov::Reflected => "k_rfl · reflected at the first hit".into(),
            Aov::Refracted => "k_rfa · refracted at the first hit".into(),
            Aov::Ambient => "ambient term at the first hit".into(),
            Aov::Diffuse => "diffuse terms of all lights at the first hit".into(),
            Aov::Specular => "specular terms of all lights at the first hit".into(),
            Aov::Shadow(Some(l)) => format!(
                "the shadow ray from the first hit to light '{}'",
                scene.lights[l].name
            ),
            Aov::Shadow(None) if scene.lights.len() > MAX_COMBINED_LIGHTS => {
                "lights the first hit's shadow rays reach".into()
            }
            Aov::Shadow(None) => "which lights the first hit's shadow rays reach".into(),
            Aov::Depth => "the deepest ray of each pixel's ray tree".into(),
            Aov::Rays(None) => "rays cast per pixel (every kind)".into(),
            Aov::Rays(Some(k)) => format!("{} rays cast per pixel", k.name()),
            Aov::Tests => "intersection tests per pixel (bounding boxes + objects)".into(),
            Aov::Normal => "unit normal at the first hit".into(),
            Aov::T => "distance from the eye to the first hit".into(),
            Aov::Object => "the object each primary ray hits".into(),
            Aov::Discriminant(i) => format!(
                "B² − AC of the primary ray against sphere '{}'",
                scene.objects[i].name
            ),
            Aov::Tir => "pixels whose ray tree holds a total internal reflection".into(),
        }
    }

    /// How its values read.
    pub fn key(&self, scene: &Scene) -> Key {
        let scale = |unit: &str, whole: bool| Key::Scale {
            unit: unit.to_owned(),
            whole,
            signed: false,
        };
        match *self {
            Aov::Local
            | Aov::Reflected
            | Aov::Refracted
            | Aov::Ambient
            | Aov::Diffuse
            | Aov::Specular => Key::Colors,
            Aov::Normal => Key::Normals,
            Aov::Shadow(Some(_)) => Key::Categories(
                [
                    "lit: the shadow ray reaches the light",
                    "lit through a transparent object (dimmed)",
                    "in shadow: an opaque object blocks the ray",
                    "the light is behind the surface (no ray cast)",
                ]
                .map(String::from)
                .to_vec(),
            ),
            Aov::Shadow(None) if scene.lights.len() > MAX_COMBINED_LIGHTS => {
                scale("lights reached", true)
            }
            Aov::Shadow(None) => Key::Categories(light_combinations(scene)),
            Aov::Depth => scale("depth (1: the primary ray only)", true),
            Aov::Rays(_) => scale("rays per pixel", true),
            Aov::Tests => scale("tests per pixel", true),
            Aov::T => scale("scene units", false),
            Aov::Object => Key::Categories(scene.objects.iter().map(|o| o.name.clone()).collect()),
            Aov::Discriminant(_) => Key::Scale {
                unit: "B² − AC: < 0 no root (miss), 0 one (tangent), > 0 two (hit)".into(),
                whole: false,
                signed: true,
            },
            Aov::Tir => Key::Categories(
                [
                    "no total internal reflection",
                    "a total internal reflection in the tree",
                ]
                .map(String::from)
                .to_vec(),
            ),
        }
    }

    /// What a pixel without a value means (the quantities of the first hit
    /// have none where the primary ray meets nothing).
    pub fn undefined(&self) -> &'static str {
        "no hit: the primary ray meets nothing"
    }

    /// A line more for the key, where the values need one.
    pub fn note(&self) -> &'static str {
        match self {
            Aov::Local | Aov::Reflected | Aov::Refracted => {
                "linear RGB as the render writes it; local + reflected + refracted = the rendered image (a miss: the background is local)"
            }
            Aov::Ambient | Aov::Diffuse | Aov::Specular => {
                "linear RGB as the render writes it; ambient + diffuse + specular = local"
            }
            Aov::Normal => "each component mapped from −1…1 to 0…255: red x, green y, blue z",
            Aov::Discriminant(_) => {
                "the lecture's quadratic for the unit sphere, as raytree trace prints it; each side of 0 scaled to its own extreme"
            }
            Aov::T => "t·|c| along the primary ray S + t·c (t = 1 on the image plane)",
            Aov::Tests => {
                "what the efficiency slide counts: the object tests, plus the structure's steps (box tests, cells) when the title names one"
            }
            _ => "",
        }
    }
}

/// The categories of `shadow` over all lights: each combination of lights
/// reached, as a bit set (bit `i` for light `i`), all first.
fn light_combinations(scene: &Scene) -> Vec<String> {
    let n = scene.lights.len();
    (0..1u32 << n)
        .map(|mask| {
            let seen: Vec<&str> = (0..n)
                .filter(|i| mask & (1 << i) != 0)
                .map(|i| scene.lights[i].name.as_str())
                .collect();
            match seen.len() {
                0 => "reaches no light".to_owned(),
                k if k == n && n > 1 => format!("reaches every light ({})", seen.join(", ")),
                _ => format!("reaches {} only", seen.join(" and ")),
            }
        })
        .collect()
}

fn shadow(arg: Option<&str>, scene: &Scene) -> Result<Aov, String> {
    if scene.lights.is_empty() {
        return Err("'shadow': the scene has no lights".into());
    }
    let Some(name) = arg else {
        return Ok(Aov::Shadow(None));
    };
    match scene.lights.iter().position(|l| l.name == name) {
        Some(i) => Ok(Aov::Shadow(Some(i))),
        None => Err(format!(
            "unknown light '{name}' (the scene's lights: {})",
            names(scene.lights.iter().map(|l| l.name.as_str()))
        )),
    }
}

fn rays(arg: Option<&str>) -> Result<Aov, String> {
    let kind = match arg {
        None | Some("all") => return Ok(Aov::Rays(None)),
        Some("primary") => RayKind::Primary,
        Some("reflected") => RayKind::Reflected,
        Some("refracted") => RayKind::Refracted,
        Some("shadow") => RayKind::Shadow,
        Some(other) => {
            return Err(format!(
                "unknown ray kind '{other}' (known: all, primary, reflected, refracted, shadow)"
            ));
        }
    };
    Ok(Aov::Rays(Some(kind)))
}

fn discriminant(arg: Option<&str>, scene: &Scene) -> Result<Aov, String> {
    let is_sphere = |i: &usize| matches!(scene.objects[*i].shape, Shape::Sphere(_));
    let spheres = || (0..scene.objects.len()).filter(is_sphere);
    let listed = || names(spheres().map(|i| scene.objects[i].name.as_str()));
    match arg {
        None => spheres()
            .next()
            .map(Aov::Discriminant)
            .ok_or_else(|| "'discriminant': the scene has no sphere".to_owned()),
        Some(name) => match scene.objects.iter().position(|o| o.name == name) {
            Some(i) if is_sphere(&i) => Ok(Aov::Discriminant(i)),
            Some(_) => Err(format!(
                "'{name}' is not a sphere (the scene's spheres: {})",
                listed()
            )),
            None => Err(format!(
                "unknown sphere '{name}' (the scene's spheres: {})",
                listed()
            )),
        },
    }
}

/// Names for an error message, at most a dozen.
fn names<'a>(all: impl Iterator<Item = &'a str>) -> String {
    let all: Vec<&str> = all.collect();
    match all.len() {
        0 => "none".to_owned(),
        n if n > 12 => format!("{}, … ({n} in all)", all[..12].join(", ")),
        _ => all.join(", "),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_read_back_and_errors_say_what_is_known() {
        let scene = crate::scene::loader::whitted();
        for spec in [
            "local",
            "shadow",
            "shadow=key",
            "rays=shadow",
            "discriminant=glass",
            "tir",
        ] {
            let aov = Aov::parse(spec, &scene).unwrap();
            assert_eq!(aov.name(&scene), spec);
        }
        assert_eq!(
            Aov::parse("discriminant", &scene),
            Ok(Aov::Discriminant(1)),
            "the first sphere, 'mirror'"
        );
        let err = |s: &str| Aov::parse(s, &scene).unwrap_err();
        assert!(
            err("shadow=sun").contains("key, fill"),
            "{}",
            err("shadow=sun")
        );
        assert!(err("colour").starts_with("unknown quantity 'colour' (known: local"));
        assert!(err("discriminant=floor").contains("not a sphere"));
        assert!(err("depth=2").contains("takes no value"));
        assert!(err("rays=diffuse").contains("unknown ray kind"));
    }

    #[test]
    fn shadow_categories_name_each_combination_of_lights() {
        let scene = crate::scene::loader::whitted();
        let Key::Categories(names) = Aov::Shadow(None).key(&scene) else {
            panic!("two lights have categories")
        };
        assert_eq!(
            names,
            [
                "reaches no light",
                "reaches key only",
                "reaches fill only",
                "reaches every light (key, fill)"
            ]
        );
    }
}
