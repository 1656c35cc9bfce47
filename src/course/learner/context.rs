//! What a comparison works with: the scene with the settings the pixel was
//! traced with, raytree's trace of it, and the pixel; and what the check and
//! the recognisers ask of them (a node's step numbers, its parent's hit, the
//! roots along a shadow ray).

use crate::geometry::hit::Roots;
use crate::geometry::object::Shape;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{HitRecord, RayNode, RayTree, ShadowRecord};
use crate::tree::steps::StepKind;

/// What the comparison works with.
pub struct Context<'a> {
    /// The scene, with the settings the pixel was traced with.
    pub scene: &'a Scene,
    /// raytree's trace of the pixel (one sample).
    pub trace: &'a TraceDocument,
    /// The pixel, image coordinates.
    pub pixel: (u32, u32),
}

impl Context<'_> {
    /// raytree's tree.
    pub fn tree(&self) -> &RayTree {
        &self.trace.samples[0].tree
    }

    /// The 1-based number of node `node`'s step `kind` (the last one of its
    /// node when the tree has no such step).
    pub fn step(&self, node: usize, kind: StepKind) -> usize {
        let steps = self.trace.steps(0);
        steps
            .iter()
            .position(|s| s.node == node && s.kind == kind)
            .or_else(|| steps.iter().rposition(|s| s.node == node))
            .map_or(1, |i| i + 1)
    }

    /// Node `i`'s parent and the parent's hit, for a secondary ray.
    pub fn parent_hit(&self, i: usize) -> Option<(&RayNode, &HitRecord)> {
        let p = &self.tree().nodes[self.tree().nodes[i].parent?];
        Some((p, p.hit.as_ref()?))
    }

    /// The radius of object `index` when it is a sphere, untransformed, whose
    /// radius is not 1: where `P − center`, taken for the normal, is not a
    /// unit vector.
    pub fn sphere_radius(&self, index: usize) -> Option<f64> {
        let object = &self.scene.objects[index];
        match &object.shape {
            Shape::Sphere(s) if object.transform.is_none() && (s.radius - 1.0).abs() > 1e-3 => {
                Some(s.radius)
            }
            _ => None,
        }
    }

    /// Object `index`'s roots along raytree's shadow ray `ours`, found with the
    /// scene's intersection methods, as the tracer found them.
    pub fn shadow_roots(&self, index: usize, ours: &ShadowRecord) -> Roots {
        let ray = Ray::new(ours.origin, ours.direction);
        self.scene.objects[index].roots(&ray, self.scene.settings.intersection_methods())
    }
}

/// Whether root `t` of raytree's shadow ray `ours` lies between the point and
/// the light: `0 < t < t_max`, `t_max` just short of the light at `t = 1`, as
/// the tracer's own shadow test takes it.
pub fn before_light(t: f64, ours: &ShadowRecord) -> bool {
    t > 0.0 && t < ours.t_max
}
