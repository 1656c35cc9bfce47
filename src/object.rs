//! A scene object: a primitive shape, an optional transform, a material.

use glam::DVec3;

use crate::hit::{Roots, Surface};
use crate::methods::SphereMethod;
use crate::plane::Plane;
use crate::ray::Ray;
use crate::sphere::Sphere;
use crate::transform::Transform;

/// The primitive shapes, in their own (object) space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere(Sphere),
    /// An infinite plane bounding a half-space.
    Plane(Plane),
}

impl Shape {
    /// Every root of the ray with the shape, spheres by `method`.
    #[inline]
    pub fn roots(&self, ray: &Ray, method: SphereMethod) -> Roots {
        match self {
            Shape::Sphere(s) if method == SphereMethod::Lecture => s.lecture_roots(ray),
            Shape::Sphere(s) => s.roots(ray),
            Shape::Plane(p) => p.roots(ray),
        }
    }

    /// The surface at `ray.at(t)`.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        match self {
            Shape::Sphere(s) => s.surface(ray, t),
            Shape::Plane(p) => p.surface(ray, t),
        }
    }

    /// Whether `p` lies strictly inside the solid.
    pub fn contains(&self, p: DVec3) -> bool {
        match self {
            Shape::Sphere(s) => s.contains(p),
            Shape::Plane(pl) => pl.contains(p),
        }
    }

    /// The shape's kind, as scene files and traces name it.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Sphere(_) => "sphere",
            Shape::Plane(_) => "plane",
        }
    }
}

/// One object of a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Its name, for traces and error messages.
    pub name: String,
    /// The primitive, in object space.
    pub shape: Shape,
    /// Object space to world space; `None` when they coincide.
    pub transform: Option<Transform>,
    /// Index into the scene's materials.
    pub material: usize,
}

impl Object {
    /// Every root of a world ray with the object; `t` refers to the world ray.
    #[inline]
    pub fn roots(&self, ray: &Ray, method: SphereMethod) -> Roots {
        match &self.transform {
            None => self.shape.roots(ray, method),
            Some(tf) => self.shape.roots(&tf.ray_to_object(ray), method),
        }
    }

    /// The world-space surface at `ray.at(t)`.
    pub fn surface(&self, ray: &Ray, t: f64) -> Surface {
        match &self.transform {
            None => self.shape.surface(ray, t),
            Some(tf) => tf.surface_to_world(self.shape.surface(&tf.ray_to_object(ray), t)),
        }
    }

    /// Whether the world point `p` lies strictly inside the object.
    pub fn contains(&self, p: DVec3) -> bool {
        match &self.transform {
            None => self.shape.contains(p),
            Some(tf) => self.shape.contains(tf.to_object.transform_point3(p)),
        }
    }
}
