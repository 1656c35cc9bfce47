//! A scene object: a primitive shape, an optional transform, a material.

use std::sync::Arc;

use glam::DVec3;

use crate::geometry::cuboid::Cuboid;
use crate::geometry::hit::{Roots, Search, Surface, TestCounts};
use crate::geometry::mesh::Mesh;
use crate::geometry::plane::Plane;
use crate::geometry::polygon::Polygon;
use crate::geometry::sphere::Sphere;
use crate::geometry::transform::Transform;
use crate::geometry::triangle::{ShearedRay, Triangle};
use crate::geometry::unit_cone::Cone;
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;
use crate::methods::{IntersectionMethods, TriangleMethod};

/// The primitive shapes, in their own (object) space.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere(Sphere),
    /// An infinite plane bounding a half-space.
    Plane(Plane),
    /// An axis-aligned box.
    Box(Cuboid),
    /// A single triangle.
    Triangle(Triangle),
    /// A triangle mesh (shared: scenes are cloned, meshes can be large).
    Mesh(Arc<Mesh>),
    /// A planar polygon or patch (shared: it may have many vertices).
    Polygon(Arc<Polygon>),
    /// The unit open cone (a cylinder when its radii are equal), placed by
    /// its object's transform.
    Cone(Cone),
}

impl Shape {
    /// The roots of the ray with the shape in `(0, t_max)` as far as a mesh or a
    /// polygon is concerned (a mesh's nearest face, or with [`Search::Any`] the first
    /// found); every root for the other shapes. Primitive and box tests are counted in `tested`.
    #[inline]
    pub fn roots(
        &self,
        ray: &Ray,
        methods: IntersectionMethods,
        t_max: f64,
        search: Search,
        tested: &mut TestCounts,
    ) -> Roots {
        // The analytic shapes inline into the tracer's loop; meshes and single
        // triangles stay out of line so they do not bloat it.
        match self {
            Shape::Sphere(s) => {
                tested.primitives += 1;
                s.roots_by(ray, methods.sphere)
            }
            Shape::Plane(p) => {
                tested.primitives += 1;
                p.roots(ray)
            }
            Shape::Box(b) => {
                tested.primitives += 1;
                b.roots(ray)
            }
            Shape::Triangle(tri) => {
                tested.primitives += 1;
                triangle_roots(tri, ray, methods.triangle)
            }
            Shape::Mesh(m) => m.roots(ray, methods.triangle, t_max, search, tested),
            Shape::Polygon(p) => {
                tested.primitives += 1;
                p.roots(ray, t_max)
            }
            Shape::Cone(c) => {
                tested.primitives += 1;
                c.roots(ray)
            }
        }
    }

    /// The surface at `ray.at(t)`; `face` is the root's mesh face (see [`Roots::face`]).
    pub fn surface(&self, ray: &Ray, t: f64, face: u32, methods: IntersectionMethods) -> Surface {
        match self {
            Shape::Sphere(s) => s.surface(ray, t),
            Shape::Plane(p) => p.surface(ray, t),
            Shape::Box(b) => b.surface(ray, t),
            Shape::Triangle(tri) => {
                let hit = crate::geometry::triangle::TriangleHit {
                    t,
                    bary: tri.barycentric(ray.at(t)),
                };
                tri.surface(&hit, None)
            }
            Shape::Mesh(m) => m.surface(ray, t, face as usize, methods.triangle),
            Shape::Polygon(p) => p.surface(ray, t),
            Shape::Cone(c) => c.surface(ray, t),
        }
    }

    /// Whether `p` lies strictly inside the solid. Triangles, meshes, polygons
    /// and open cones are surfaces, not solids: nothing is inside them.
    pub fn contains(&self, p: DVec3) -> bool {
        match self {
            Shape::Sphere(s) => s.contains(p),
            Shape::Plane(pl) => pl.contains(p),
            Shape::Box(b) => b.contains(p),
            Shape::Triangle(_) | Shape::Mesh(_) | Shape::Polygon(_) | Shape::Cone(_) => false,
        }
    }

    /// Whether the shape is a solid, with an inside [`Shape::contains`] can
    /// tell: not a triangle, a mesh, a polygon or an open cone, which are surfaces.
    pub fn is_solid(&self) -> bool {
        !matches!(
            self,
            Shape::Triangle(_) | Shape::Mesh(_) | Shape::Polygon(_) | Shape::Cone(_)
        )
    }

    /// The box around the shape in its own space; `None` for a plane.
    pub fn bounds(&self) -> Option<Bounds> {
        match self {
            Shape::Sphere(s) => Some(Bounds {
                min: s.center - s.radius,
                max: s.center + s.radius,
            }),
            Shape::Plane(_) => None,
            Shape::Box(b) => Some(b.bounds()),
            Shape::Triangle(t) => Some(Bounds::around([t.a, t.b, t.c])),
            Shape::Mesh(m) => Some(m.bounds()),
            Shape::Polygon(p) => Some(p.bounds()),
            Shape::Cone(c) => Some(c.bounds_under(&glam::DAffine3::IDENTITY)),
        }
    }

    /// A point well inside the shape (its center), or on it for a plane.
    pub fn center(&self) -> DVec3 {
        match self {
            Shape::Sphere(s) => s.center,
            Shape::Plane(p) => p.point,
            _ => self.bounds().map_or(DVec3::ZERO, |b| b.center()),
        }
    }

    /// The shape's kind, as scene files and traces name it.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Sphere(_) => "sphere",
            Shape::Plane(_) => "plane",
            Shape::Box(_) => "box",
            Shape::Triangle(_) => "triangle",
            Shape::Mesh(_) => "mesh",
            Shape::Polygon(_) => "polygon",
            Shape::Cone(_) => "cone",
        }
    }
}

#[inline(never)]
fn triangle_roots(tri: &Triangle, ray: &Ray, method: TriangleMethod) -> Roots {
    let hit = match method {
        TriangleMethod::Watertight => {
            tri.watertight(&ShearedRay::new(ray), f64::NEG_INFINITY, f64::INFINITY)
        }
        TriangleMethod::MollerTrumbore => {
            tri.moller_trumbore(ray, f64::NEG_INFINITY, f64::INFINITY)
        }
    };
    hit.map_or(Roots::NONE, |h| Roots::one(h.t))
}

/// One object of a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Its name, for traces and error messages.
    pub name: String,
    /// The primitive, in object space.
    pub shape: Shape,
    /// Object space to world space; `None` when they coincide. Boxed: most
    /// objects have none, and a small object keeps more of a big scene in cache.
    pub transform: Option<Box<Transform>>,
    /// Index into the scene's materials.
    pub material: usize,
}

impl Object {
    /// Every root of a world ray with the object; `t` refers to the world ray.
    pub fn roots(&self, ray: &Ray, methods: impl Into<IntersectionMethods>) -> Roots {
        self.roots_within(
            ray,
            methods.into(),
            f64::INFINITY,
            Search::Closest,
            &mut TestCounts::default(),
        )
    }

    /// The roots the tracer needs (see [`Shape::roots`]), counting the tests.
    #[inline]
    pub fn roots_within(
        &self,
        ray: &Ray,
        methods: IntersectionMethods,
        t_max: f64,
        search: Search,
        tested: &mut TestCounts,
    ) -> Roots {
        match &self.transform {
            None => self.shape.roots(ray, methods, t_max, search, tested),
            Some(tf) => self
                .shape
                .roots(&tf.ray_to_object(ray), methods, t_max, search, tested),
        }
    }

    /// The world-space surface at `ray.at(t)` on mesh face `face` (see [`Roots::face`]).
    pub fn surface(&self, ray: &Ray, t: f64, face: u32, methods: IntersectionMethods) -> Surface {
        match &self.transform {
            None => self.shape.surface(ray, t, face, methods),
            Some(tf) => {
                tf.surface_to_world(self.shape.surface(&tf.ray_to_object(ray), t, face, methods))
            }
        }
    }

    /// Whether the world point `p` lies strictly inside the object.
    pub fn contains(&self, p: DVec3) -> bool {
        match &self.transform {
            None => self.shape.contains(p),
            Some(tf) => self.shape.contains(tf.to_object.transform_point3(p)),
        }
    }

    /// The world-space box around the object; `None` for an unbounded plane.
    /// A cone's is made around its two end discs in world space, tighter than
    /// its own box transformed.
    pub fn bounds(&self) -> Option<Bounds> {
        if let (Shape::Cone(c), Some(tf)) = (&self.shape, &self.transform) {
            return Some(c.bounds_under(&tf.to_world));
        }
        let b = self.shape.bounds()?;
        Some(match &self.transform {
            None => b,
            Some(tf) => b.transformed(&tf.to_world),
        })
    }

    /// The world-space center of the shape.
    pub fn center(&self) -> DVec3 {
        let c = self.shape.center();
        self.transform
            .as_ref()
            .map_or(c, |tf| tf.to_world.transform_point3(c))
    }
}
