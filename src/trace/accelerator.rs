//! Which objects a ray is tested against: all of them (the lecture's loop), or
//! those in the leaves of a bounding volume hierarchy the ray reaches. Planes have
//! no bounds and are tested by every ray either way.

use std::cell::Cell;
use std::ops::ControlFlow;

use crate::geometry::bvh::Bvh;
use crate::geometry::hit::TestCounts;
use crate::math::bounds::{Bounds, RayBox};
use crate::math::ray::Ray;
use crate::methods::Accel;
use crate::scene::Scene;

/// With [`Accel::Auto`], scenes with at least this many bounded objects get a
/// hierarchy. Below it the box tests cost more than the object tests they save
/// (see the README's performance section for the measurement).
pub const AUTO_MIN_OBJECTS: usize = 16;

/// The objects of one scene, arranged for the rays to come.
#[derive(Clone, Debug)]
pub struct Accelerator {
    /// Objects without bounds (planes), or every object when there is no hierarchy.
    always: Vec<u32>,
    /// The hierarchy over the bounded objects; its leaves hold object indices.
    bvh: Option<Bvh>,
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
        let use_bvh = match scene.settings.accel {
            Accel::None => false,
            Accel::Bvh => true,
            Accel::Auto => bounded_count >= AUTO_MIN_OBJECTS,
        };
        let all = 0..scene.objects.len() as u32;
        if !use_bvh {
            return Accelerator {
                always: all.collect(),
                bvh: None,
            };
        }
        let (bounded, always): (Vec<u32>, Vec<u32>) =
            all.partition(|&i| bounds[i as usize].is_some());
        let boxes: Vec<Bounds> = bounded
            .iter()
            .map(|&i| bounds[i as usize].expect("bounded"))
            .collect();
        let mut bvh = Bvh::build(&boxes);
        bvh.relabel(|i| bounded[i as usize]);
        Accelerator {
            always,
            bvh: Some(bvh),
        }
    }

    /// How many accelerators this thread has built so far: a test counts them
    /// to check that work which should reuse one (the inspector's keys)
    /// builds none.
    pub fn built_on_this_thread() -> u64 {
        BUILT.with(Cell::get)
    }

    /// The hierarchy, if there is one.
    pub fn bvh(&self) -> Option<&Bvh> {
        self.bvh.as_ref()
    }

    /// Calls `visit(object, t_max)` for every object the ray may meet in
    /// `(t_min, *t_max)`: the unbounded ones first, then the hierarchy's, nearer
    /// leaves first. `visit` may shrink `t_max` or break (see [`Bvh::traverse`]).
    #[inline]
    pub fn visit(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.visit_seeing(ray, t_min, t_max, tested, |_, _| {}, visit)
    }

    /// [`Accelerator::visit`], also calling `seen(bounds, met)` for every box
    /// of the hierarchy tested (see [`Bvh::traverse_seeing`]).
    #[inline]
    pub fn visit_seeing(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: &mut f64,
        tested: &mut TestCounts,
        seen: impl FnMut(Bounds, bool),
        mut visit: impl FnMut(usize, &mut f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        for &i in &self.always {
            visit(i as usize, t_max)?;
        }
        match &self.bvh {
            None => ControlFlow::Continue(()),
            Some(bvh) => bvh.traverse_seeing(&RayBox::new(ray), t_min, t_max, tested, seen, visit),
        }
    }
}
