//! Scene files: JSON, strict, with defaults. The format is documented field by
//! field in `scenes/README.md`; this module reads it into a [`Scene`].
//!
//! Strict: an unknown field is an error, so a typo never silently falls back to a
//! default. Errors say where: `file:line:column: field.path: what was expected`
//! while parsing, `file: field.path: what is wrong` when a value parses but makes
//! no sense (a negative radius, a singular transform).

use std::fmt::Display;
use std::path::Path;

use glam::{DAffine3, DVec3};

use crate::geometry::cuboid::Cuboid;
use crate::geometry::object::{Object, Shape};
use crate::geometry::plane::Plane;
use crate::geometry::sphere::Sphere;
use crate::geometry::transform::Transform;
use crate::geometry::triangle::Triangle;
use crate::scene::Scene;
use crate::scene::camera::CameraSpec;
use crate::scene::format::{
    BoxFile, CameraFile, LightFile, MaterialFile, MeshFile, ObjectFile, PlaneFile, SceneFile,
    SphereFile, TransformStep, TriangleFile,
};
use crate::scene::light::PointLight;
use crate::scene::overrides::Overrides;
use crate::scene::settings::RenderSettings;
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

/// Reads a scene file's text.
pub fn read(path: &Path) -> Result<String, SceneError> {
    std::fs::read_to_string(path).map_err(|e| SceneError::Read {
        reason: match e.kind() {
            std::io::ErrorKind::NotFound => "no such file".to_owned(),
            std::io::ErrorKind::InvalidData => "not UTF-8 text".to_owned(),
            std::io::ErrorKind::IsADirectory => "it is a directory".to_owned(),
            _ => e.to_string(),
        },
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
        SceneError::Syntax {
            file: file.to_owned(),
            line: e.line(),
            column: e.column(),
            message,
        }
    };
    let de = &mut serde_json::Deserializer::from_str(text);
    let raw: SceneFile = serde_path_to_error::deserialize(&mut *de)
        .map_err(|e| syntax(e.path().to_string(), e.into_inner()))?;
    de.end().map_err(|e| syntax(String::new(), e))?;
    let dir = Path::new(file).parent().unwrap_or(Path::new(""));
    Builder { file, dir }.scene(raw)
}

/// The material objects get when they name none.
const DEFAULT_MATERIAL: &str = "default";

struct Builder<'a> {
    file: &'a str,
    /// Where the scene file is: mesh files are found relative to it.
    dir: &'a Path,
}

impl Builder<'_> {
    fn invalid(&self, field: impl Display, message: impl Display) -> SceneError {
        SceneError::Invalid {
            file: self.file.to_owned(),
            field: field.to_string(),
            message: message.to_string(),
        }
    }

    fn scene(&self, raw: SceneFile) -> Result<Scene, SceneError> {
        let _ = raw.description;
        let settings = self.settings(&raw.render)?;
        let camera = self.camera(&raw.camera)?;
        let background = self.color("background", raw.background.unwrap_or(DVec3::ZERO))?;
        let ambient_light = self.color("ambient_light", raw.ambient_light.unwrap_or(DVec3::ONE))?;
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
        Ok(Scene {
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

    fn camera(&self, c: &CameraFile) -> Result<CameraSpec, SceneError> {
        let eye = c.eye.unwrap_or(DVec3::new(0.0, 0.0, 5.0));
        let frame_given = c.u.is_some()
            || c.v.is_some()
            || c.n.is_some()
            || c.half_width.is_some()
            || c.half_height.is_some()
            || c.distance.is_some();
        if !frame_given {
            return self.look_at_camera(eye, c);
        }
        if c.look_at.is_some() || c.up.is_some() || c.fov.is_some() {
            return Err(self.invalid(
                "camera",
                "give either look_at/up/fov or u/v/n/half_width/half_height/distance, not both",
            ));
        }
        self.frame_camera(eye, c)
    }

    /// A camera given by eye, look-at point, up and field of view.
    fn look_at_camera(&self, eye: DVec3, c: &CameraFile) -> Result<CameraSpec, SceneError> {
        let look_at = c.look_at.unwrap_or(DVec3::ZERO);
        let up = c.up.unwrap_or(DVec3::Y);
        let fov = c.fov.unwrap_or(60.0);
        if (look_at - eye).length() == 0.0 {
            return Err(self.invalid("camera.look_at", "must differ from camera.eye"));
        }
        if up.cross(look_at - eye).length() <= 1e-9 * up.length() * (look_at - eye).length() {
            return Err(self.invalid(
                "camera.up",
                "must not be zero or parallel to the view direction",
            ));
        }
        if !(fov > 0.0 && fov < 180.0) {
            return Err(self.invalid(
                "camera.fov",
                format_args!("must be between 0 and 180 degrees, got {fov}"),
            ));
        }
        Ok(CameraSpec::LookAt {
            eye,
            look_at,
            up,
            fov_degrees: fov,
        })
    }

    /// A camera given by the lecture's own parameters: u, v, n, W, H and N.
    fn frame_camera(&self, eye: DVec3, c: &CameraFile) -> Result<CameraSpec, SceneError> {
        let missing = "missing (an explicit camera needs u, v, n, half_width and half_height)";
        let need = |v: Option<DVec3>, name: &str| {
            v.ok_or_else(|| self.invalid(format_args!("camera.{name}"), missing))
        };
        let (u, v, n) = (need(c.u, "u")?, need(c.v, "v")?, need(c.n, "n")?);
        let mut unit = [DVec3::ZERO; 3];
        for (k, (name, vec)) in [("u", u), ("v", v), ("n", n)].into_iter().enumerate() {
            unit[k] = vec
                .try_normalize()
                .ok_or_else(|| self.invalid(format_args!("camera.{name}"), "must not be zero"))?;
        }
        let [u, v, n] = unit;
        if u.dot(v).abs() > 1e-6 || u.dot(n).abs() > 1e-6 || v.dot(n).abs() > 1e-6 {
            return Err(self.invalid("camera", "u, v and n must be mutually perpendicular"));
        }
        let positive =
            |x: Option<f64>, name: &str, default: Option<f64>| -> Result<f64, SceneError> {
                let x = x
                    .or(default)
                    .ok_or_else(|| self.invalid(format_args!("camera.{name}"), missing))?;
                if x > 0.0 {
                    Ok(x)
                } else {
                    Err(self.invalid(
                        format_args!("camera.{name}"),
                        format_args!("must be > 0, got {x}"),
                    ))
                }
            };
        Ok(CameraSpec::Frame {
            eye,
            u,
            v,
            n,
            half_width: positive(c.half_width, "half_width", None)?,
            half_height: positive(c.half_height, "half_height", None)?,
            distance: positive(c.distance, "distance", Some(1.0))?,
        })
    }

    fn color(&self, field: impl Display, c: DVec3) -> Result<DVec3, SceneError> {
        if c.is_finite() && c.min_element() >= 0.0 {
            Ok(c)
        } else {
            Err(self.invalid(
                field,
                format_args!("a color's components must be finite and ≥ 0, got {c}"),
            ))
        }
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
                let size = ch.size.unwrap_or(1.0);
                if !size.is_finite() || size <= 0.0 {
                    return Err(
                        self.invalid(at("checker.size"), format_args!("must be > 0, got {size}"))
                    );
                }
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
                    Err(self.invalid(at(f), format_args!("must be from 0 to {max}, got {v}")))
                }
            };
        let ior = m.ior.unwrap_or(1.0);
        if !(ior > 0.0 && ior.is_finite()) {
            return Err(self.invalid(
                at("ior"),
                format_args!("a refractive index must be > 0, got {ior}"),
            ));
        }
        Ok(Material {
            name: name.to_owned(),
            pattern,
            ambient: coefficient(m.ambient, "ambient", 0.1, 1e6)?,
            diffuse: coefficient(m.diffuse, "diffuse", 0.7, 1e6)?,
            specular: coefficient(m.specular, "specular", 0.0, 1e6)?,
            shininess: coefficient(m.shininess, "shininess", 50.0, 1e6)?,
            reflective: coefficient(m.reflective, "reflective", 0.0, 1.0)?,
            transparent: coefficient(m.transparent, "transparent", 0.0, 1.0)?,
            ior,
        })
    }

    fn light(&self, i: usize, l: &LightFile) -> Result<PointLight, SceneError> {
        let name = l.name.clone().unwrap_or_else(|| format!("light{i}"));
        let color = self.color(
            format_args!("lights[{i}].color"),
            l.color.unwrap_or(DVec3::ONE),
        )?;
        Ok(PointLight {
            name,
            position: l.position,
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
        match (&o.sphere, &o.plane, &o.aligned_box, &o.triangle, &o.mesh) {
            (Some(s), None, None, None, None) => self.sphere(i, s),
            (None, Some(p), None, None, None) => self.plane(i, p),
            (None, None, Some(b), None, None) => self.cuboid(i, b),
            (None, None, None, Some(t), None) => self.triangle(i, t),
            (None, None, None, None, Some(m)) => self.mesh(i, m),
            _ => Err(self.invalid(
                format_args!("objects[{i}]"),
                "give exactly one shape: \"sphere\", \"plane\", \"box\", \"triangle\" or \"mesh\"",
            )),
        }
    }

    fn sphere(&self, i: usize, s: &SphereFile) -> Result<Shape, SceneError> {
        let radius = s.radius.unwrap_or(1.0);
        if !radius.is_finite() || radius <= 0.0 {
            return Err(self.invalid(
                format_args!("objects[{i}].sphere.radius"),
                format_args!("must be > 0, got {radius}"),
            ));
        }
        Ok(Shape::Sphere(Sphere {
            center: s.center.unwrap_or(DVec3::ZERO),
            radius,
        }))
    }

    fn plane(&self, i: usize, p: &PlaneFile) -> Result<Shape, SceneError> {
        let normal = p
            .normal
            .unwrap_or(DVec3::Y)
            .try_normalize()
            .ok_or_else(|| {
                self.invalid(
                    format_args!("objects[{i}].plane.normal"),
                    "must not be zero",
                )
            })?;
        Ok(Shape::Plane(Plane {
            point: p.point.unwrap_or(DVec3::ZERO),
            normal,
        }))
    }

    fn cuboid(&self, i: usize, b: &BoxFile) -> Result<Shape, SceneError> {
        let min = b.min.unwrap_or(DVec3::splat(-1.0));
        let max = b.max.unwrap_or(DVec3::ONE);
        if !(min.is_finite() && max.is_finite() && min.cmplt(max).all()) {
            return Err(self.invalid(
                format_args!("objects[{i}].box"),
                format_args!("min must be below max on every axis, got min {min} and max {max}"),
            ));
        }
        Ok(Shape::Box(Cuboid { min, max }))
    }

    fn triangle(&self, i: usize, t: &TriangleFile) -> Result<Shape, SceneError> {
        let [a, b, c] = t.vertices;
        let tri = Triangle { a, b, c };
        if !(a.is_finite() && b.is_finite() && c.is_finite()) || tri.normal() == DVec3::ZERO {
            return Err(self.invalid(
                format_args!("objects[{i}].triangle.vertices"),
                "must be three finite points not on one line",
            ));
        }
        Ok(Shape::Triangle(tri))
    }

    /// A mesh from its OBJ file, found relative to the scene file.
    fn mesh(&self, i: usize, m: &MeshFile) -> Result<Shape, SceneError> {
        let path = self.dir.join(&m.file);
        let mesh = crate::scene::obj::load(&path, m.smooth.unwrap_or(true)).map_err(|error| {
            SceneError::Mesh {
                file: self.file.to_owned(),
                field: format!("objects[{i}].mesh.file"),
                error,
            }
        })?;
        Ok(Shape::Mesh(std::sync::Arc::new(mesh)))
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
        let transform = Transform::new(m).ok_or_else(|| {
            self.invalid(
                format_args!("objects[{i}].transform"),
                "is singular (it flattens the object, e.g. a zero scale) and cannot be inverted",
            )
        })?;
        Ok(Some(Box::new(transform)))
    }

    /// One transform step's matrix; steps apply in the order written, so the
    /// whole transform is `M = M_last ⋯ M_first`.
    fn step(&self, i: usize, k: usize, step: &TransformStep) -> Result<DAffine3, SceneError> {
        Ok(match *step {
            TransformStep::Translate(t) => DAffine3::from_translation(t),
            TransformStep::Scale(s) => DAffine3::from_scale(s),
            TransformStep::RotateX(d) => DAffine3::from_rotation_x(d.to_radians()),
            TransformStep::RotateY(d) => DAffine3::from_rotation_y(d.to_radians()),
            TransformStep::RotateZ(d) => DAffine3::from_rotation_z(d.to_radians()),
            TransformStep::Rotate { axis, degrees } => {
                let axis = axis.try_normalize().ok_or_else(|| {
                    self.invalid(
                        format_args!("objects[{i}].transform[{k}].rotate.axis"),
                        "must not be zero",
                    )
                })?;
                DAffine3::from_axis_angle(axis, degrees.to_radians())
            }
        })
    }
}
