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

use glam::{DAffine3, DVec3};

use crate::geometry::cuboid::Cuboid;
use crate::geometry::mesh::Mesh;
use crate::geometry::object::{Object, Shape};
use crate::geometry::plane::Plane;
use crate::geometry::polygon::Polygon;
use crate::geometry::sphere::Sphere;
use crate::geometry::transform::Transform;
use crate::geometry::triangle::Triangle;
use crate::io::input::{self, MAX_INPUT_BYTES};
use crate::scene::Scene;
use crate::scene::camera_file;
use crate::scene::format::{
    BoxFile, CellSize, LightFile, MaterialFile, MeshFile, ObjectFile, PlaneFile, PolygonFile, Root,
    SceneFile, SphereFile, TransformStep, TriangleFile,
};
use crate::scene::light::PointLight;
use crate::scene::limits;
use crate::scene::names::{name_ok, within};
use crate::scene::overrides::Overrides;
use crate::scene::settings::RenderSettings;
use crate::scene::strict;
use crate::shading::material::{Material, Pattern};

/// The classic Whitted scene, built into the binary.
pub const WHITTED: &str = include_str!("../../scenes/whitted.json");

/// Why a scene could not be loaded. Each displays as one line.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read {file}: {reason}")]
    Read {
        /// The file.
        file: String,
        /// The OS's reason.
        reason: String,
    },
    /// The text is not a scene: bad JSON, an unknown field, a wrong type.
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The field path and what was expected.
        message: String,
    },
    /// A mesh's OBJ file cannot be used.
    #[error("{error} (the mesh of {file}: {field})")]
    Mesh {
        /// The scene file.
        file: String,
        /// The object's field, e.g. `objects[3].mesh.file`.
        field: String,
        /// What is wrong in the OBJ file, and where.
        error: crate::scene::obj::ObjError,
    },
    /// A value parses but is not allowed.
    #[error("{file}: {field}: {message}")]
    Invalid {
        /// The file.
        file: String,
        /// Path of the offending field, e.g. `objects[2].sphere.radius`.
        field: String,
        /// What is wrong.
        message: String,
    },
}

/// Reads and validates the scene file at `path`.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    parse(&read(path)?, &path.display().to_string())
}

/// Reads a scene file's text: a regular file of at most
/// [`MAX_INPUT_BYTES`], checked before reading.
pub fn read(path: &Path) -> Result<String, SceneError> {
    input::read_text(path, MAX_INPUT_BYTES).map_err(|reason| SceneError::Read {
        reason,
        file: path.display().to_string(),
    })
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
            .map_or(text.as_str(), |i| &text[..i])
            .to_owned();
        let message = if path == "." || path.is_empty() {
            message
        } else {
            format!("{path}: {message}")
        };
        // serde quotes an unknown key as written: a newline or an escape in it
        // would break the one-line message or reach the terminal.
        let message = strict::printable(&strict::in_users_words(&message));
        SceneError::Syntax {
            file: file.to_owned(),
            line: e.line(),
            column: e.column().max(1),
            message,
        }
    };
    let de = &mut serde_json::Deserializer::from_str(text);
    let Root(raw) = serde_path_to_error::deserialize(&mut *de)
        .map_err(|e| syntax(e.path().to_string(), e.into_inner()))?;
    de.end().map_err(|e| syntax(String::new(), e))?;
    let dir = Path::new(file).parent().unwrap_or(Path::new(""));
    let builder = Builder {
        file,
        dir,
        meshes: RefCell::default(),
    };
    builder.scene(raw)
}

/// The material objects get when they name none.
const DEFAULT_MATERIAL: &str = "default";

struct Builder<'a> {
    file: &'a str,
    /// Where the scene file is: mesh files are found relative to it.
    dir: &'a Path,
    /// Each OBJ file read so far, by its canonical path and whether it is
    /// smooth: a file many objects use is read and parsed once.
    meshes: RefCell<HashMap<(PathBuf, bool), Arc<Mesh>>>,
}

impl Builder<'_> {
    fn invalid(&self, field: impl Display, message: impl Display) -> SceneError {
        SceneError::Invalid {
            file: self.file.to_owned(),
            field: strict::printable(&field.to_string()),
            message: strict::printable(&message.to_string()),
        }
    }

    /// `value` checked by `check`, or an error naming `field`.
    fn check<T, U>(
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
            self.check(format_args!("materials.{name}"), name.as_str(), name_ok)?;
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
                    let known: Vec<&str> = raw.materials.keys().map(String::as_str).collect();
                    let known = if known.is_empty() {
                        "none are defined".to_owned()
                    } else {
                        format!("defined: {}", known.join(", "))
                    };
                    return Err(self.invalid(
                        format_args!("objects[{i}].material"),
                        format_args!("no material named '{wanted}' ({known})"),
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

    fn color(&self, field: impl Display, c: DVec3) -> Result<DVec3, SceneError> {
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
                    format_args!("'{name}' is already the name of {list}[{first}] (names must differ; one left out is its kind and place, e.g. sphere3 or light0)"),
                ));
            }
        }
        Ok(())
    }

    fn material(&self, name: &str, m: &MaterialFile) -> Result<Material, SceneError> {
        let at = |f: &str| format!("materials.{name}.{f}");
        let pattern = match (&m.color, &m.checker) {
            (Some(_), Some(_)) => {
                return Err(self.invalid(
                    format_args!("materials.{name}"),
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
                format_args!("materials.{name}"),
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

    fn object(&self, i: usize, o: &ObjectFile, material: usize) -> Result<Object, SceneError> {
        let shape = self.shape(i, o)?;
        let transform = self.transform(i, &o.transform)?;
        let name = o
            .name
            .clone()
            .unwrap_or_else(|| format!("{}{i}", shape.kind()));
        Ok(Object {
            name,
            shape,
            transform,
            material,
        })
    }

    /// Object `i`'s one shape.
    fn shape(&self, i: usize, o: &ObjectFile) -> Result<Shape, SceneError> {
        match (&o.sphere, &o.plane, &o.aligned_box, &o.triangle, &o.mesh, &o.polygon) {
            (Some(s), None, None, None, None, None) => self.sphere(i, s),
            (None, Some(p), None, None, None, None) => self.plane(i, p),
            (None, None, Some(b), None, None, None) => self.cuboid(i, b),
            (None, None, None, Some(t), None, None) => self.triangle(i, t),
            (None, None, None, None, Some(m), None) => self.mesh(i, m),
            (None, None, None, None, None, Some(p)) => self.polygon(i, p),
            _ => Err(self.invalid(
                format_args!("objects[{i}]"),
                "give exactly one shape: \"sphere\", \"plane\", \"box\", \"triangle\", \"mesh\" or \"polygon\"",
            )),
        }
    }

    fn sphere(&self, i: usize, s: &SphereFile) -> Result<Shape, SceneError> {
        let at = |f: &str| format!("objects[{i}].sphere.{f}");
        let radius = self.check(at("radius"), s.radius.unwrap_or(1.0), limits::length)?;
        let center = self.check(at("center"), s.center.unwrap_or(DVec3::ZERO), limits::point)?;
        Ok(Shape::Sphere(Sphere { center, radius }))
    }

    fn plane(&self, i: usize, p: &PlaneFile) -> Result<Shape, SceneError> {
        let at = |f: &str| format!("objects[{i}].plane.{f}");
        let normal = self.check(
            at("normal"),
            p.normal.unwrap_or(DVec3::Y),
            limits::direction,
        )?;
        let point = self.check(at("point"), p.point.unwrap_or(DVec3::ZERO), limits::point)?;
        Ok(Shape::Plane(Plane { point, normal }))
    }

    fn cuboid(&self, i: usize, b: &BoxFile) -> Result<Shape, SceneError> {
        let at = |f: &str| format!("objects[{i}].box.{f}");
        let min = self.check(
            at("min"),
            b.min.unwrap_or(DVec3::splat(-1.0)),
            limits::point,
        )?;
        let max = self.check(at("max"), b.max.unwrap_or(DVec3::ONE), limits::point)?;
        if !min.cmplt(max).all() {
            return Err(self.invalid(
                format_args!("objects[{i}].box"),
                format_args!("min must be below max on every axis, got min {min} and max {max}"),
            ));
        }
        Ok(Shape::Box(Cuboid { min, max }))
    }

    fn triangle(&self, i: usize, t: &TriangleFile) -> Result<Shape, SceneError> {
        let at = format!("objects[{i}].triangle.vertices");
        for (k, &v) in t.vertices.iter().enumerate() {
            self.check(format_args!("{at}[{k}]"), v, limits::point)?;
        }
        let [a, b, c] = t.vertices;
        let tri = Triangle { a, b, c };
        if tri.normal() == DVec3::ZERO {
            return Err(self.invalid(at, "must be three points not on one line"));
        }
        Ok(Shape::Triangle(tri))
    }

    /// A polygon or patch: each vertex and normal within the scene's limits,
    /// then [`Polygon::new`]'s own checks (the plane of the first three, every
    /// vertex on it), named by field.
    fn polygon(&self, i: usize, p: &PolygonFile) -> Result<Shape, SceneError> {
        let at = |f: &str| format!("objects[{i}].polygon.{f}");
        for (k, &v) in p.vertices.iter().enumerate() {
            self.check(format_args!("{}[{k}]", at("vertices")), v, limits::point)?;
        }
        if p.vertices.len() < 3 {
            return Err(self.invalid(
                at("vertices"),
                format_args!("give at least 3 vertices, got {}", p.vertices.len()),
            ));
        }
        let normals = match &p.normals {
            None => None,
            Some(ns) => {
                if ns.len() != p.vertices.len() {
                    return Err(self.invalid(
                        at("normals"),
                        format_args!(
                            "give one normal per vertex: {} vertices, {} normals",
                            p.vertices.len(),
                            ns.len()
                        ),
                    ));
                }
                let checked = ns.iter().enumerate().map(|(k, &n)| {
                    self.check(format_args!("{}[{k}]", at("normals")), n, limits::direction)
                });
                Some(checked.collect::<Result<Vec<_>, _>>()?)
            }
        };
        Polygon::new(p.vertices.clone(), normals, p.one_sided.unwrap_or(false))
            .map(|polygon| Shape::Polygon(Arc::new(polygon)))
            .map_err(|why| self.invalid(format_args!("objects[{i}].polygon"), why))
    }

    /// A mesh from its OBJ file, found relative to the scene file; read once
    /// however many objects use it.
    fn mesh(&self, i: usize, m: &MeshFile) -> Result<Shape, SceneError> {
        self.check(format_args!("objects[{i}].mesh.file"), &m.file, |f| {
            name_ok(f)?;
            within(self.dir, f)
        })?;
        let path = self.dir.join(&m.file);
        let key = (
            std::fs::canonicalize(&path).unwrap_or_else(|_| path.clone()),
            m.smooth.unwrap_or(true),
        );
        if let Some(mesh) = self.meshes.borrow().get(&key) {
            return Ok(Shape::Mesh(Arc::clone(mesh)));
        }
        let mesh = crate::scene::obj::load(&path, key.1).map_err(|error| SceneError::Mesh {
            file: self.file.to_owned(),
            field: format!("objects[{i}].mesh.file"),
            error,
        })?;
        let mesh = Arc::new(mesh);
        self.meshes.borrow_mut().insert(key, Arc::clone(&mesh));
        Ok(Shape::Mesh(mesh))
    }

    /// Object `i`'s transform steps as one invertible transform; `None` without steps.
    fn transform(
        &self,
        i: usize,
        steps: &[TransformStep],
    ) -> Result<Option<Box<Transform>>, SceneError> {
        if steps.is_empty() {
            return Ok(None);
        }
        let m = steps
            .iter()
            .enumerate()
            .try_fold(DAffine3::IDENTITY, |m, (k, step)| {
                self.step(i, k, step).map(|s| s * m)
            })?;
        let at = format!("objects[{i}].transform");
        let transform = Transform::new(m).ok_or_else(|| {
            self.invalid(
                &at,
                "is singular (it flattens the object, e.g. a zero scale) and cannot be inverted",
            )
        })?;
        self.check(&at, &transform, |t| {
            limits::transform(&t.to_world, &t.to_object)
        })?;
        Ok(Some(Box::new(transform)))
    }

    /// One transform step's matrix; steps apply in the order written, so the
    /// whole transform is `M = M_last ⋯ M_first`.
    fn step(&self, i: usize, k: usize, step: &TransformStep) -> Result<DAffine3, SceneError> {
        let at = |f: &str| format!("objects[{i}].transform[{k}].{f}");
        let angle = |f: &str, d: f64| {
            let max = limits::MAX_COORDINATE;
            self.check(at(f), d, |d| limits::within(d, -max, max))
                .map(f64::to_radians)
        };
        Ok(match step {
            TransformStep::Translate(t) => {
                DAffine3::from_translation(self.check(at("translate"), *t, limits::point)?)
            }
            TransformStep::Scale(s) => {
                DAffine3::from_scale(self.check(at("scale"), *s, limits::scale)?)
            }
            TransformStep::RotateX(d) => DAffine3::from_rotation_x(angle("rotate_x", *d)?),
            TransformStep::RotateY(d) => DAffine3::from_rotation_y(angle("rotate_y", *d)?),
            TransformStep::RotateZ(d) => DAffine3::from_rotation_z(angle("rotate_z", *d)?),
            TransformStep::Rotate(r) => {
                let axis = self.check(at("rotate.axis"), r.axis, limits::direction)?;
                DAffine3::from_axis_angle(axis, angle("rotate.degrees", r.degrees)?)
            }
        })
    }
}
