//! How an object was tested, for the trace: each shape's own test numbers, worked out with the shape's
//! own functions so the numbers shown are those that decided: the sphere's and
//! the cone's quadratics, the box's slabs, the polygon's plane and crossings.

use crate::geometry::cuboid::{Cuboid, SlabSpan};
use crate::geometry::hit::Roots;
use crate::geometry::object::{Object, Shape};
use crate::geometry::polygon::Polygon;
use crate::geometry::sphere::Sphere;
use crate::geometry::triangle::ShearedRay;
use crate::geometry::unit_cone::Cone;
use crate::math::ray::Ray;
use crate::methods::{IntersectionMethods, SphereMethod, TriangleMethod};
use crate::tree::arithmetic::{Arithmetic, Crossing, RayRecord, Slab, TestMethod};

/// How `object` was tested against the world ray `ray`, the ray in its own
/// frame when it is transformed (the lecture's `S' + t·c'`), and the test's
/// own numbers (for a mesh or triangle, at the root found).
pub fn object_test(
    object: &Object,
    ray: &Ray,
    methods: IntersectionMethods,
    roots: &Roots,
) -> (TestMethod, Option<RayRecord>, Option<Arithmetic>) {
    let local = object.transform.as_ref().map(|tf| tf.ray_to_object(ray));
    let own = local.unwrap_or(*ray);
    let object_ray = local.map(|r| RayRecord {
        origin: r.origin,
        direction: r.dir,
    });
    let triangle_method = match methods.triangle {
        TriangleMethod::Watertight => TestMethod::Watertight,
        TriangleMethod::MollerTrumbore => TestMethod::MollerTrumbore,
    };
    let first = roots.as_slice().first().copied();
    let (method, arithmetic) = match &object.shape {
        Shape::Sphere(s) => {
            let method = match methods.sphere {
                SphereMethod::Lecture => TestMethod::LectureQuadratic,
                SphereMethod::Stable => TestMethod::StableQuadratic,
            };
            (method, Some(quadratic(s, &own)))
        }
        Shape::Plane(p) => (
            TestMethod::PlaneEquation,
            Some(Arithmetic::Plane {
                n_dot_c: own.dir.dot(p.normal),
                numerator: (p.point - own.origin).dot(p.normal),
            }),
        ),
        Shape::Box(b) => (TestMethod::Slabs, Some(slabs(b, &own))),
        Shape::Cone(c) => (TestMethod::StableQuadratic, Some(cone_quadratic(c, &own))),
        Shape::Triangle(t) => (
            triangle_method,
            first.map(|t_hit| Arithmetic::Barycentric {
                weights: t.barycentric(own.at(t_hit)).to_array(),
            }),
        ),
        Shape::Mesh(m) => (
            triangle_method,
            first.map(|t_hit| Arithmetic::Face {
                face: roots.face(),
                weights: m
                    .triangle(roots.face() as usize)
                    .barycentric(own.at(t_hit))
                    .to_array(),
            }),
        ),
        Shape::Polygon(p) => (TestMethod::CrossingNumber, Some(polygon(p, &own))),
    };
    (method, object_ray, arithmetic)
}

/// A polygon's test, by the polygon's own functions, so the numbers are those
/// that decided. The crossings are counted even where the tracer stopped at `t`.
pub(super) fn polygon(p: &Polygon, ray: &Ray) -> Arithmetic {
    let (n_dot_c, numerator) = p.plane(ray);
    let crossings = p.crossings(&ShearedRay::new(ray));
    Arithmetic::Polygon {
        n_dot_c,
        numerator,
        one_sided: p.one_sided(),
        crossings: crossings.count,
        on_edge: crossings.on_edge,
    }
}

/// The lecture's unit-sphere quadratic for `ray` (in the sphere's object frame).
pub(super) fn quadratic(s: &Sphere, ray: &Ray) -> Arithmetic {
    let q = s.unit_quadratic(ray);
    Arithmetic::Quadratic {
        origin: q.origin,
        direction: q.direction,
        a: q.a,
        b: q.b,
        c: q.c,
        discriminant: q.discriminant,
    }
}

/// The unit cone's quadratic for `ray` (in the cone's own space), with every
/// crossing and its height: the cone test's own numbers.
pub(super) fn cone_quadratic(cone: &Cone, ray: &Ray) -> Arithmetic {
    let q = cone.quadratic(ray);
    Arithmetic::ConeQuadratic {
        origin: q.origin,
        direction: q.direction,
        ratio: cone.ratio,
        a: q.a,
        b: q.b,
        c: q.c,
        discriminant: q.discriminant,
        crossings: q
            .crossings
            .as_slice()
            .iter()
            .map(|&t| Crossing { t, z: q.height(t) })
            .collect(),
    }
}

/// Each axis's slab interval (Kay & Kajiya), ordered near to far: the box
/// test's own, so the trace shows the numbers that decided.
pub(super) fn slabs(b: &Cuboid, ray: &Ray) -> Arithmetic {
    let axes = b.slabs(ray).map(|slab| match slab {
        SlabSpan::Crossing { near, far } => Slab::Crossing { near, far },
        SlabSpan::Parallel { inside } => Slab::Parallel { inside },
    });
    Arithmetic::Slabs { axes }
}
