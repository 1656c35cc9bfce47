//! The scene file's `objects`, checked into [`Object`]s: each one's shape (a
//! sphere, plane, box, triangle, polygon, cone or OBJ mesh), the transform
//! placing it, and the mesh files it reads, only from the scene's folder.
//! Part of [`crate::scene::loader`], whose `Builder` it extends.

use std::sync::Arc;

use glam::{DAffine3, DVec3};

use crate::geometry::cone::cone_placement;
use crate::geometry::cuboid::Cuboid;
use crate::geometry::object::{Object, Shape};
use crate::geometry::plane::Plane;
use crate::geometry::polygon::Polygon;
use crate::geometry::sphere::Sphere;
use crate::geometry::transform::Transform;
use crate::geometry::triangle::Triangle;
use crate::scene::format::{
    BoxFile, ConeFile, MeshFile, ObjectFile, PlaneFile, PolygonFile, SphereFile, TransformStep,
    TriangleFile,
};
use crate::scene::limits;
use crate::scene::loader::{Builder, SceneError};
use crate::scene::names::{name_ok, within};

impl Builder<'_> {
    pub(super) fn object(
        &self,
        i: usize,
        o: &ObjectFile,
        material: usize,
    ) -> Result<Object, SceneError> {
        let (shape, placed) = self.shape(i, o)?;
        let transform = self.transform(i, placed, &o.transform)?;
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

    /// Object `i`'s one shape and, for a shape made in a unit space of its own
    /// (a cone), the map placing it, which its `transform` steps follow.
    fn shape(&self, i: usize, o: &ObjectFile) -> Result<(Shape, Option<DAffine3>), SceneError> {
        let own = |shape: Result<Shape, SceneError>| shape.map(|s| (s, None));
        let given = [
            o.sphere.is_some(),
            o.plane.is_some(),
            o.aligned_box.is_some(),
            o.triangle.is_some(),
            o.mesh.is_some(),
            o.polygon.is_some(),
            o.cone.is_some(),
        ];
        match (&o.sphere, &o.plane, &o.aligned_box, &o.triangle, &o.mesh, &o.polygon, &o.cone) {
            _ if given.iter().filter(|&&g| g).count() != 1 => Err(self.invalid(
                format_args!("objects[{i}]"),
                "give exactly one shape: \"sphere\", \"plane\", \"box\", \"triangle\", \"mesh\", \"polygon\" or \"cone\"",
            )),
            (Some(s), ..) => own(self.sphere(i, s)),
            (_, Some(p), ..) => own(self.plane(i, p)),
            (_, _, Some(b), ..) => own(self.cuboid(i, b)),
            (_, _, _, Some(t), ..) => own(self.triangle(i, t)),
            (_, _, _, _, Some(m), ..) => own(self.mesh(i, m)),
            (.., Some(p), None) => own(self.polygon(i, p)),
            (.., Some(c)) => self.cone(i, c),
            _ => Err(self.invalid(
                format_args!("objects[{i}]"),
                "give exactly one shape",
            )),
        }
    }

    /// The unit cone and the map placing it between its two ends, made as
    /// [`crate::geometry::cone::cone_object`] makes it; its numbers within
    /// the limits first.
    fn cone(&self, i: usize, c: &ConeFile) -> Result<(Shape, Option<DAffine3>), SceneError> {
        let at = |f: &str| format!("objects[{i}].cone.{f}");
        let base = self.check(at("base"), c.base, limits::point)?;
        let apex = self.check(at("apex"), c.apex, limits::point)?;
        let radius =
            |f: &str, r: f64| self.check(at(f), r, |r| limits::within(r, 0.0, limits::MAX_LENGTH));
        let base_radius = radius("base_radius", c.base_radius)?;
        let apex_radius = radius("apex_radius", c.apex_radius)?;
        let (cone, m) = cone_placement(base, base_radius, apex, apex_radius).map_err(|e| {
            let field = if e.field.is_empty() {
                format!("objects[{i}].cone")
            } else {
                at(e.field)
            };
            self.invalid(field, e.message)
        })?;
        Ok((Shape::Cone(cone), Some(m)))
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
            if f.trim().is_empty() {
                return Err("must name an OBJ file, got an empty name".to_owned());
            }
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

    /// Object `i`'s transform steps, after the map `placed` placing its shape
    /// if it has one, as one invertible transform; `None` without either.
    fn transform(
        &self,
        i: usize,
        placed: Option<DAffine3>,
        steps: &[TransformStep],
    ) -> Result<Option<Box<Transform>>, SceneError> {
        if steps.is_empty() && placed.is_none() {
            return Ok(None);
        }
        let m = steps
            .iter()
            .enumerate()
            .try_fold(placed.unwrap_or(DAffine3::IDENTITY), |m, (k, step)| {
                self.step(i, k, step).map(|s| s * m)
            })?;
        // A cone's own placement alone is named as the cone's.
        let at = if steps.is_empty() {
            format!("objects[{i}].cone")
        } else {
            format!("objects[{i}].transform")
        };
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
