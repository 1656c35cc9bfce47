//! Which objects a ray is tested against: all of them (the lecture's loop), or
//! those a structure of the efficiency slide hands it: the leaves of a bounding
//! volume hierarchy, the cells of a uniform grid, the leaves of an octree or of
//! a BSP (k-d) tree the ray reaches. Planes have no bounds and are tested by
//! every ray either way.

use std::cell::Cell;
use std::ops::ControlFlow;

use crate::geometry::hit::{Roots, Search, TestCounts};
use crate::geometry::object::{Object, Shape};
use crate::geometry::sphere::Sphere;
use crate::geometry::structures::bvh::Bvh;
use crate::geometry::structures::{self, Built, Items, Subdivision};
use crate::math::bounds::Bounds;
use crate::math::ray::Ray;
use crate::methods::{Accel, IntersectionMethods};
use crate::scene::Scene;

/// With [`Accel::Auto`], scenes with at least this many bounded objects get a
/// hierarchy. Below it the box tests cost more than the object tests they save
/// (see the README's performance section for the measurement).
pub const AUTO_MIN_OBJECTS: usize = 16;

/// The objects of one scene, arranged for the rays to come.
#[derive(Clone, Debug)]
pub struct Accelerator {
    /// Objects without bounds (planes), or every object when there is no
    /// structure, as candidates (a sphere copied, as in `leaves`).
    always: Vec<Candidate>,
    /// The structure over the bounded objects.
    structure: Option<Built>,
    /// The object index of each of the structure's primitives, for a structure
    /// that hands them out one by one (all but the BVH).
    names: Vec<u32>,
    /// The objects in the order a structure's leaves list them, for one whose
    /// leaves are runs of that order (the BVH): a leaf is a run of these.
    leaves: Vec<Candidate>,
}

/// An object as a visit hands it out: its index, and for a sphere without a
/// transform, a copy of the sphere as well, kept in the order of the
/// hierarchy's leaves (or of the list every ray tests). Its test is then
/// inlined into the visit, where an object's goes through two calls and a
/// jump on its shape. A million random spheres' objects take
/// 120 MB in the order they were read, so a ray's walk waited on memory for
/// each sphere it tested; side by side, a leaf's spheres share cache lines
/// and the objects are not read at all. (Triangles and polygons copied the
/// same way made no difference: 124 and 148 ns a primary ray on the Gaspra
/// mesh's triangles as objects, with copies or without.)
#[derive(Clone, Copy, Debug)]
pub enum Candidate {
    /// Object `i`, to be tested as itself.
    Object(u32),
    /// Object `object`, which is this sphere in world space.
    Sphere {
        /// A copy of the object's sphere.
        sphere: Sphere,
        /// The object's index.
        object: u32,
    },
}

impl Candidate {
    /// The candidate for object `i` of `objects`.
    fn of(objects: &[Object], i: u32) -> Candidate {
        match &objects[i as usize] {
            Object {
                shape: Shape::Sphere(sphere),
                transform: None,
                ..
            } => Candidate::Sphere {
                sphere: *sphere,
                object: i,
            },
            _ => Candidate::Object(i),
        }
    }

    /// The object's index.
    #[inline]
    pub fn object(&self) -> usize {
        match *self {
            Candidate::Object(i) | Candidate::Sphere { object: i, .. } => i as usize,
        }
    }
}

thread_local! {
    /// Accelerators built on this thread so far.
    static BUILT: Cell<u64> = const { Cell::new(0) };
}

impl Accelerator {
    /// Arranges `scene`'s objects as its settings ask.
    pub fn new(scene: &Scene) -> Self {
        BUILT.with(|b| b.set(b.get() + 1));
        let bounds: Vec<Option<Bounds>> = scene.objects.iter().map(|o| o.bounds()).collect();
        let bounded_count = bounds.iter().flatten().count();
        let accel = match scene.settings.accel {
            Accel::Auto if bounded_count >= AUTO_MIN_OBJECTS => Accel::Bvh,
            Accel::Auto => Accel::None,
            other => other,
        };
        let all = 0..scene.objects.len() as u32;
        if accel == Accel::None {
            return Accelerator {
                always: all.map(|i| Candidate::of(&scene.objects, i)).collect(),
                structure: None,
                names: Vec::new(),
                leaves: Vec::new(),
            };
        }
        let (bounded, always): (Vec<u32>, Vec<u32>) =
            all.partition(|&i| bounds[i as usize].is_some());
        let boxes: Vec<Bounds> = bounded
            .iter()
            .map(|&i| bounds[i as usize].expect("bounded"))
            .collect();
        let subdivision = Subdivision {
            grid_res: scene.settings.grid_res,
            depth_limit: scene.settings.tree_depth,
        };
        let structure = structures::build(accel, &boxes, subdivision);
        // A structure whose leaves are runs of one order (the BVH) hands out
        // runs of `leaves`; the others hand out their own indices, translated
        // through `bounded` as they visit.
        let (names, leaves) = match structure.leaf_order() {
            Some(order) => {
                let leaves = (order.iter())
                    .map(|&i| Candidate::of(&scene.objects, bounded[i as usize]))
                    .collect();
                (Vec::new(), leaves)
            }
            None => (bounded, Vec::new()),
        };
        Accelerator {
            always: (always.into_iter())
                .map(|i| Candidate::of(&scene.objects, i))
                .collect(),
            structure: Some(structure),
            names,
            leaves,
        }
    }

    /// How many accelerators this thread has built so far: a test counts them
    /// to check that work which should reuse one (the inspector's keys)
    /// builds none.
    pub fn built_on_this_thread() -> u64 {
        BUILT.with(Cell::get)
    }

    /// The roots of `ray` with a candidate a visit handed out, as
    /// [`Object::roots_within`] finds them for its object: a copied sphere's
    /// are the object's own, the same test on the same numbers.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub fn roots(
        &self,
        candidate: &Candidate,
        objects: &[Object],
        ray: &Ray,
        methods: IntersectionMethods,
        t_max: f64,
        search: Search,
        tested: &mut TestCounts,
    ) -> Roots {
        match candidate {
            Candidate::Object(i) => {
                objects[*i as usize].roots_within(ray, methods, t_max, search, tested)
            }
            Candidate::Sphere { sphere, .. } => {
                tested.primitives += 1;
                sphere.roots_by(ray, methods.sphere)
            }
        }
    }

    /// The hierarchy, if the structure is one.
    pub fn bvh(&self) -> Option<&Bvh> {
        self.structure.as_ref().and_then(Built::bvh)
    }

    /// The structure over the bounded objects, if any.
    pub fn structure(&self) -> Option<&Built> {
        self.structure.as_ref()
    }

    /// Which structure the rays go through: the setting, with `auto` resolved
    /// (never [`Accel::Auto`]).
    pub fn kind(&self) -> Accel {
        self.structure.as_ref().map_or(Accel::None, Built::accel)
    }

    /// The candidates a structure hands out: a run of `leaves`, or the object
    /// of `names` a primitive index stands for.
    #[inline]
    fn items(&self) -> Items<'_, Candidate, impl Fn(usize) -> Candidate + '_> {
        Items {
            in_leaf_order: &self.leaves,
            named: |i| Candidate::Object(self.names[i]),
        }
    }

    /// Calls `visit(candidate, t_max)` for every object the ray may meet in
    /// `(t_min, *t_max)`: the unbounded ones first, then the hierarchy's, nearer
    /// leaves first. `visit` may shrink `t_max` or break (see [`Structure::walk`]).
    ///
    /// [`Structure::walk`]: crate::geometry::structures::Structure::walk
    #[inline]
    pub fn visit(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        visit: impl FnMut(&Candidate, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.visit_seeing(ray, t_min, t_max, tested, |_, _| {}, visit)
    }

    /// [`Accelerator::visit`] with the hierarchy's boxes taken in their stored
    /// order, not nearest first (see [`Built::walk_items_any`]): for a shadow
    /// ray, which any blocker ends.
    #[inline]
    pub fn visit_any(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut visit: impl FnMut(&Candidate, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        for candidate in &self.always {
            visit(candidate, t_max)?;
        }
        let Some(structure) = &self.structure else {
            return ControlFlow::Continue(());
        };
        structure.walk_items_any(ray, t_min, t_max, tested, self.items(), visit)
    }

    /// [`Accelerator::visit`], also calling `seen(bounds, met)` for every box
    /// or cell of the structure tested (see [`Structure::walk`]).
    ///
    /// [`Structure::walk`]: crate::geometry::structures::Structure::walk
    #[inline]
    pub fn visit_seeing(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(&Candidate, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        for candidate in &self.always {
            visit(candidate, t_max)?;
        }
        let Some(structure) = &self.structure else {
            return ControlFlow::Continue(());
        };
        structure.walk_items(ray, t_min, t_max, tested, seen, self.items(), visit)
    }
}
