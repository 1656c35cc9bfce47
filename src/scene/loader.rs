//! Scene files: JSON, strict, with defaults. The format is documented field by
//! field in `scenes/README.md`; this module reads it into a [`Scene`].
//!
//! Strict: an unknown field is an error, so a typo never silently falls back to a
//! default; every struct is a JSON object and every name is given once
//! ([`crate::scene::strict`]); numbers lie in the ranges of
//! [`crate::scene::limits`], which keep every computed number finite. Errors say
//! where: `file:line:column: field.path: what was expected` while parsing,
//! `file: field.path: what is wrong` when a value parses but makes no sense (a
//! negative radius, a singular transform).

use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt::Display;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::DVec3;

use crate::geometry::mesh::Mesh;
use crate::io::headroom;
use crate::io::input::{self, MAX_INPUT_BYTES};
use crate::scene::Scene;
use crate::scene::camera_file;
use crate::scene::format::{CellSize, LightFile, MaterialFile, Root, SceneFile};
use crate::scene::light::PointLight;
use crate::scene::limits;
use crate::scene::names::name_ok;
use crate::scene::nff;
use crate::scene::overrides::Overrides;
use crate::scene::quote;
use crate::scene::settings::RenderSettings;
use crate::scene::strict;
use crate::shading::material::{Material, Pattern};

/// The classic Whitted scene, built into the binary.
pub const WHITTED: &str = include_str!("../../scenes/whitted.json");

pub use crate::scene::scene_error::SceneError;

/// Reads and validates the scene file at `path`.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    parse_file(&read(path)?, &path.display().to_string())
}

/// Parses a scene file's text by its kind: NFF when `file` ends in `.nff`
/// (read into scene JSON first, [`crate::scene::nff`]), else JSON.
pub fn parse_file(text: &str, file: &str) -> Result<Scene, SceneError> {
    if nff::is_nff(file) {
        parse(&nff::to_json(text, file)?, file)
    } else {
        parse(text, file)
    }
}

/// Reads a scene file's text: a regular file of at most
/// [`MAX_INPUT_BYTES`], checked before reading.
pub fn read(path: &Path) -> Result<String, SceneError> {
    let error = |reason| SceneError::Read {
        reason,
        file: path.display().to_string(),
    };
    let text = input::read_text(path, MAX_INPUT_BYTES).map_err(error)?;
    // An NFF file's words are capped well below what memory holds.
    if !nff::is_nff(&path.display().to_string()) {
        let need = headroom::json_scene_need(text.as_bytes());
        headroom::check(need, headroom::available()).map_err(error)?;
    }
    Ok(text)
}

/// The built-in Whitted scene.
pub fn whitted() -> Scene {
    parse(WHITTED, "whitted.json").expect("the built-in scene is valid")
}

/// Parses and validates scene text; `file` names it in errors.
pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    let syntax = |path: String, e: serde_json::Error| {
        let text = e.to_string();
        let message = text
            .rfind(" at line ")
            .map_or(text.as_str(), |i| &text[..i]);
        // serde quotes an unknown key as written: a newline or an escape in it
        // would break the one-line message or reach the terminal, and ten
        // million characters of it would fill the terminal.
        let message = quote::shorten_serde(&strict::in_users_words(message));
        // As the learner-trace reader says it.
        let message = if e.is_eof() {
            format!("the file ends early: {message}")
        } else {
            message
        };
        let message = if path.is_empty() {
            message
        } else {
            format!("{path}: {message}")
        };
        let message = strict::printable(&message);
        SceneError::Syntax {
            file: file.to_owned(),
            line: e.line(),
            column: e.column().max(1),
            message,
        }
    };
    not_json(text, file)?;
    let de = &mut serde_json::Deserializer::from_str(text);
    let Root(raw) = serde_path_to_error::deserialize(&mut *de)
        .map_err(|e| syntax(field_path(e.path()), e.into_inner()))?;
    de.end().map_err(|e| syntax(String::new(), e))?;
    let dir = Path::new(file).parent().unwrap_or(Path::new(""));
    let builder = Builder {
        file,
        dir,
        meshes: RefCell::default(),
    };
    builder.scene(raw)
}

/// Refuses an empty file, or one that does not start as JSON does, in the
/// user's words: serde's "EOF while parsing a value" and "expected value"
/// tell a newcomer who passed a text file or an empty one nothing.
fn not_json(text: &str, file: &str) -> Result<(), SceneError> {
    const KINDS: &str = "a scene file is JSON (see scenes/README.md), or NFF by the extension .nff";
    let syntax = |line: usize, column: usize, message: String| SceneError::Syntax {
        file: file.to_owned(),
        line,
        column,
        message,
    };
    let Some(start) = text.find(|c: char| !c.is_whitespace()) else {
        return Err(syntax(1, 1, format!("empty file: {KINDS}")));
    };
    let first = text[start..].chars().next().unwrap_or(' ');
    if "{[\"-0123456789tfn".contains(first) {
        return Ok(());
    }
    let before = &text[..start];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    Err(syntax(line, column, format!("not JSON: {KINDS}")))
}

/// The path serde_path_to_error names (`objects[2].sphere.radius`), each key
/// the file gave cut as [`quote::quote`] cuts it; empty for the whole document.
fn field_path(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for segment in path.iter() {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } | Segment::Enum { variant: key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(&quote::quote(key, ""));
            }
            // Where the key is not read yet (the file ends first), the path
            // stops at what is known.
            Segment::Unknown => {}
        }
    }
    out
}

/// The materials a scene defines, as an error lists them: the first few,
/// each cut as [`quote::quote`] cuts it.
fn defined<'n>(names: impl ExactSizeIterator<Item = &'n String>) -> String {
    const SHOWN: usize = 10;
    let n = names.len();
    if n == 0 {
        return "none are defined".to_owned();
    }
    let mut list: Vec<String> = names.take(SHOWN).map(|m| quote::quote(m, "")).collect();
    if n > SHOWN {
        list.push(format!("and {} more", n - SHOWN));
    }
    format!("defined: {}", list.join(", "))
}

/// The material objects get when they name none.
const DEFAULT_MATERIAL: &str = "default";

pub(super) struct Builder<'a> {
    pub(super) file: &'a str,
    /// Where the scene file is: mesh files are found relative to it.
    pub(super) dir: &'a Path,
    /// Each OBJ file read so far, by its canonical path and whether it is
    /// smooth: a file many objects use is read and parsed once.
    pub(super) meshes: RefCell<HashMap<(PathBuf, bool), Arc<Mesh>>>,
}

impl Builder<'_> {
    pub(super) fn invalid(&self, field: impl Display, message: impl Display) -> SceneError {
        SceneError::Invalid {
            file: self.file.to_owned(),
            field: strict::printable(&field.to_string()),
            message: strict::printable(&message.to_string()),
        }
    }

    /// `value` checked by `check`, or an error naming `field`.
    pub(super) fn check<T, U>(
        &self,
        field: impl Display,
        value: T,
        check: impl FnOnce(T) -> Result<U, String>,
    ) -> Result<U, SceneError> {
        check(value).map_err(|message| self.invalid(field, message))
    }

    fn scene(&self, raw: SceneFile) -> Result<Scene, SceneError> {
        let _ = raw.description;
        let settings = self.settings(&raw.render)?;
        let camera =
            camera_file::spec(&raw.camera).map_err(|(field, msg)| self.invalid(field, msg))?;
        let background = self.color("background", raw.background.unwrap_or(DVec3::ZERO))?;
        let ambient_light = self.color("ambient_light", raw.ambient_light.unwrap_or(DVec3::ONE))?;
        for name in raw.materials.keys() {
            let field = format_args!("materials.{}", quote::quote(name, ""));
            self.check(field, name.as_str(), name_ok)?;
        }
        let mut materials = raw
            .materials
            .iter()
            .map(|(name, m)| self.material(name, m))
            .collect::<Result<Vec<_>, _>>()?;
        let lights = raw
            .lights
            .iter()
            .enumerate()
            .map(|(i, l)| self.light(i, l))
            .collect::<Result<Vec<_>, _>>()?;
        let mut objects = Vec::with_capacity(raw.objects.len());
        for (i, o) in raw.objects.iter().enumerate() {
            let wanted = o.material.as_deref().unwrap_or(DEFAULT_MATERIAL);
            let material = match materials.iter().position(|m| m.name == wanted) {
                Some(m) => m,
                None if wanted == DEFAULT_MATERIAL => {
                    materials.push(self.material(DEFAULT_MATERIAL, &MaterialFile::default())?);
                    materials.len() - 1
                }
                None => {
                    return Err(self.invalid(
                        format_args!("objects[{i}].material"),
                        format_args!(
                            "no material named {} ({})",
                            quote::quote(wanted, "'"),
                            defined(raw.materials.keys())
                        ),
                    ));
                }
            };
            objects.push(self.object(i, o, material)?);
        }
        self.unique("lights", lights.iter().map(|l| l.name.as_str()))?;
        self.unique("objects", objects.iter().map(|o| o.name.as_str()))?;
        let mut mesh_files: Vec<PathBuf> = self
            .meshes
            .borrow()
            .keys()
            .map(|(p, _)| p.clone())
            .collect();
        mesh_files.sort();
        mesh_files.dedup();
        Ok(Scene {
            mesh_files,
            camera,
            settings,
            background,
            ambient_light,
            materials,
            lights,
            objects,
        })
    }

    fn settings(&self, r: &Overrides) -> Result<RenderSettings, SceneError> {
        let s = r.apply(&RenderSettings::default());
        s.validate()
            .map_err(|(field, msg)| self.invalid(format_args!("render.{field}"), msg))?;
        Ok(s)
    }

    pub(super) fn color(&self, field: impl Display, c: DVec3) -> Result<DVec3, SceneError> {
        self.check(field, c, limits::color)
    }

    /// Names must differ within `list` (`objects` or `lights`); one left out
    /// is called by its kind and place (`sphere3`, `light0`), which counts too.
    fn unique<'n>(
        &self,
        list: &str,
        names: impl Iterator<Item = &'n str>,
    ) -> Result<(), SceneError> {
        let mut seen = HashMap::new();
        for (i, name) in names.enumerate() {
            self.check(format_args!("{list}[{i}].name"), name, name_ok)?;
            if let Some(first) = seen.insert(name, i) {
                return Err(self.invalid(
                    format_args!("{list}[{i}].name"),
                    format_args!("{} is already the name of {list}[{first}] (names must differ; one left out is its kind and place, e.g. sphere3 or light0)", quote::quote(name, "'")),
                ));
            }
        }
        Ok(())
    }

    fn material(&self, name: &str, m: &MaterialFile) -> Result<Material, SceneError> {
        let shown = quote::quote(name, "");
        let at = |f: &str| format!("materials.{shown}.{f}");
        let pattern = match (&m.color, &m.checker) {
            (Some(_), Some(_)) => {
                return Err(self.invalid(
                    format_args!("materials.{shown}"),
                    "give color or checker, not both",
                ));
            }
            (Some(c), None) => Pattern::Solid(self.color(at("color"), *c)?),
            (None, Some(ch)) => {
                let side = |s| self.check(at("checker.size"), s, limits::length);
                let size = match ch.size {
                    None => DVec3::ONE,
                    Some(CellSize::Cube(s)) => DVec3::splat(side(s)?),
                    Some(CellSize::Sides(s)) => DVec3::new(side(s.x)?, side(s.y)?, side(s.z)?),
                };
                Pattern::Checker {
                    colors: [
                        self.color(at("checker.colors[0]"), ch.colors[0])?,
                        self.color(at("checker.colors[1]"), ch.colors[1])?,
                    ],
                    size,
                }
            }
            (None, None) => Pattern::Solid(DVec3::splat(0.8)),
        };
        let coefficient =
            |v: Option<f64>, f: &str, default: f64, max: f64| -> Result<f64, SceneError> {
                let v = v.unwrap_or(default);
                if (0.0..=max).contains(&v) {
                    Ok(v)
                } else {
                    Err(self.invalid(
                        at(f),
                        format_args!(
                            "must be from 0 to {}, got {}",
                            limits::num(max),
                            limits::num(v)
                        ),
                    ))
                }
            };
        let (low, high) = limits::IOR;
        let ior = self.check(at("ior"), m.ior.unwrap_or(1.0), |x| {
            limits::within(x, low, high).map_err(|e| format!("a refractive index {e}"))
        })?;
        let reflective = coefficient(m.reflective, "reflective", 0.0, 1.0)?;
        let transparent = coefficient(m.transparent, "transparent", 0.0, 1.0)?;
        if reflective + transparent > 1.0 {
            return Err(self.invalid(
                format_args!("materials.{shown}"),
                format_args!("reflective + transparent must be at most 1 (a surface passes on no more light than arrives), got {} + {}", limits::num(reflective), limits::num(transparent)),
            ));
        }
        let max = limits::MAX_COEFFICIENT;
        Ok(Material {
            name: name.to_owned(),
            pattern,
            ambient: coefficient(m.ambient, "ambient", 0.1, max)?,
            diffuse: coefficient(m.diffuse, "diffuse", 0.7, max)?,
            specular: coefficient(m.specular, "specular", 0.0, max)?,
            shininess: coefficient(m.shininess, "shininess", 50.0, max)?,
            reflective,
            transparent,
            ior,
        })
    }

    fn light(&self, i: usize, l: &LightFile) -> Result<PointLight, SceneError> {
        let name = l.name.clone().unwrap_or_else(|| format!("light{i}"));
        let color = self.color(
            format_args!("lights[{i}].color"),
            l.color.unwrap_or(DVec3::ONE),
        )?;
        let position = self.check(
            format_args!("lights[{i}].position"),
            l.position,
            limits::point,
        )?;
        Ok(PointLight {
            name,
            position,
            color,
        })
    }
}
