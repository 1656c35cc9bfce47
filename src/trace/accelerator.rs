//! Which objects a ray is tested against: all of them (the lecture's loop), or
//! those a structure of the efficiency slide hands it: the leaves of a bounding
//! volume hierarchy, the cells of a uniform grid, the leaves of an octree or of
//! a BSP (k-d) tree the ray reaches. Planes have no bounds and are tested by
//! every ray either way.

use std::cell::Cell;
use std::ops::ControlFlow;

use crate::geometry::bvh::Bvh;
use crate::geometry::grid::Grid;
use crate::geometry::hit::{Roots, Search, TestCounts};
use crate::geometry::kdtree::KdTree;
use crate::geometry::object::{Object, Shape};
use crate::geometry::octree::{self, Octree};
use crate::geometry::sphere::Sphere;
use crate::math::bounds::{Bounds, RayBox};
use crate::math::ray::Ray;
use crate::methods::{Accel, IntersectionMethods, Level};
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
    structure: Option<Structure>,
    /// The object index of each of the structure's primitives (but the BVH's).
    names: Vec<u32>,
    /// The hierarchy's objects in the order its leaves list them: a leaf is a
    /// run of these.
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

/// One of the efficiency slide's structures over the bounded objects.
#[derive(Clone, Debug)]
pub enum Structure {
    /// A bounding volume hierarchy.
    Bvh(Bvh),
    /// A uniform grid.
    Grid(Grid),
    /// An octree.
    Octree(Octree),
    /// A k-d tree (the axis-aligned BSP tree).
    Bsp(KdTree),
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
        let depth = match scene.settings.tree_depth {
            Level::Auto => None,
            Level::Given(d) => Some(d),
        };
        let structure = match accel {
            Accel::Grid => Structure::Grid(match scene.settings.grid_res {
                Level::Auto => Grid::build(&boxes),
                Level::Given(side) => Grid::build_with_side(&boxes, side),
            }),
            Accel::Octree => Structure::Octree(Octree::build_to_depth(
                &boxes,
                depth.unwrap_or(octree::MAX_DEPTH),
            )),
            Accel::Bsp => Structure::Bsp(KdTree::build_to_depth(&boxes, depth)),
            _ => Structure::Bvh(Bvh::build(&boxes)),
        };
        // The BVH's leaves are runs of `leaves`; the other structures hand out
        // their own indices, translated through `bounded` as they visit.
        let (names, leaves) = match &structure {
            Structure::Bvh(bvh) => {
                let leaves = (bvh.leaf_order().iter())
                    .map(|&i| Candidate::of(&scene.objects, bounded[i as usize]))
                    .collect();
                (Vec::new(), leaves)
            }
            _ => (bounded, Vec::new()),
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
        match &self.structure {
            Some(Structure::Bvh(b)) => Some(b),
            _ => None,
        }
    }

    /// The structure over the bounded objects, if any.
    pub fn structure(&self) -> Option<&Structure> {
        self.structure.as_ref()
    }

    /// Which structure the rays go through: the setting, with `auto` resolved
    /// (never [`Accel::Auto`]).
    pub fn kind(&self) -> Accel {
        match &self.structure {
            None => Accel::None,
            Some(Structure::Bvh(_)) => Accel::Bvh,
            Some(Structure::Grid(_)) => Accel::Grid,
            Some(Structure::Octree(_)) => Accel::Octree,
            Some(Structure::Bsp(_)) => Accel::Bsp,
        }
    }

    /// Calls `visit(candidate, t_max)` for every object the ray may meet in
    /// `(t_min, *t_max)`: the unbounded ones first, then the hierarchy's, nearer
    /// leaves first. `visit` may shrink `t_max` or break (see [`Bvh::traverse`]).
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
    /// order, not nearest first (see [`Bvh::traverse_leaves_any`]): for a
    /// shadow ray, which any blocker ends.
    #[inline]
    pub fn visit_any(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        mut visit: impl FnMut(&Candidate, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        if let Some(Structure::Bvh(bvh)) = &self.structure {
            for candidate in &self.always {
                visit(candidate, t_max)?;
            }
            let ray = RayBox::new(ray);
            return bvh.traverse_leaves_any(&ray, t_min, t_max, tested, |run, t| {
                for candidate in &self.leaves[run] {
                    visit(candidate, t)?;
                }
                ControlFlow::Continue(())
            });
        }
        self.visit(ray, t_min, t_max, tested, visit)
    }

    /// [`Accelerator::visit`], also calling `seen(bounds, met)` for every box
    /// of the hierarchy tested (see [`Bvh::traverse_leaves_seeing`]).
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
        let names = &self.names;
        match structure {
            Structure::Bvh(bvh) => {
                let ray = RayBox::new(ray);
                bvh.traverse_leaves_seeing(&ray, t_min, t_max, tested, seen, |run, t| {
                    for candidate in &self.leaves[run] {
                        visit(candidate, t)?;
                    }
                    ControlFlow::Continue(())
                })
            }
            Structure::Grid(g) => g.traverse_seeing(ray, t_min, t_max, tested, seen, |i, t| {
                visit(&Candidate::Object(names[i]), t)
            }),
            Structure::Octree(o) => o.traverse_seeing(ray, t_min, t_max, tested, seen, |i, t| {
                visit(&Candidate::Object(names[i]), t)
            }),
            Structure::Bsp(k) => k.traverse_seeing(ray, t_min, t_max, tested, seen, |i, t| {
                visit(&Candidate::Object(names[i]), t)
            }),
        }
    }
}
