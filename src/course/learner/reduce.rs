//! raytree's own trace reduced to the learner's fields (`raytree trace
//! --learner`): what a learner's tracer should write for the pixel, and the
//! check's first test (it must check clean against itself).
//!
//! The coefficients are those the color's sum used: after total internal
//! reflection the reflected ray carries `k_rfl + k_rfa` and the refracted
//! share is 0, as `raytree trace` prints.

use crate::course::learner::format::{Kind, LearnerHit, LearnerRay, LearnerShadow, LearnerTrace};
use crate::trace::recorder::{Branch, RayKind};
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayTree, ShadowOutcomeRecord};

/// The learner trace of a pixel's trace document: one sample, or why not.
pub fn reduce(trace: &TraceDocument) -> Result<LearnerTrace, String> {
    let [sample] = trace.samples.as_slice() else {
        return Err(format!(
            "a learner trace holds one ray per pixel, and this trace has {} samples: use --spp 1",
            trace.samples.len()
        ));
    };
    let Some(pixel) = trace.pixel else {
        return Err("a learner trace is of a pixel: use --pixel X,Y".to_owned());
    };
    Ok(LearnerTrace {
        scene: Some(trace.scene.file.clone()),
        pixel: Some([pixel.x, pixel.y]),
        ray: ray(&sample.tree, 0),
    })
}

/// The learner's kind of a tree's ray.
pub fn kind(kind: RayKind) -> Kind {
    match kind {
        RayKind::Reflected => Kind::Reflected,
        RayKind::Refracted => Kind::Refracted,
        RayKind::Primary | RayKind::Shadow => Kind::Primary,
    }
}

/// Node `i` of `tree` and everything under it.
pub fn ray(tree: &RayTree, i: usize) -> LearnerRay {
    let node = &tree.nodes[i];
    let mut out = LearnerRay::new(kind(node.kind), node.origin, node.direction);
    out.color = Some(node.color());
    let Some(hit) = &node.hit else {
        out.hit = Some(None);
        return out;
    };
    out.hit = Some(Some(LearnerHit {
        object: Some(hit.name.clone()),
        t: Some(hit.t),
        point: Some(hit.point),
        normal: Some(hit.shading_normal),
        entering: Some(hit.entering),
    }));
    out.shadows = Some(
        node.shadow_rays
            .iter()
            .map(|s| {
                let cast = !matches!(s.outcome, ShadowOutcomeRecord::FacesAway);
                LearnerShadow {
                    light: s.name.clone(),
                    blocked: matches!(s.outcome, ShadowOutcomeRecord::Blocked { .. }),
                    by: Some(match &s.outcome {
                        ShadowOutcomeRecord::Blocked { name, .. } => Some(name.clone()),
                        _ => None,
                    }),
                    transmitted: match s.outcome {
                        ShadowOutcomeRecord::Reaches { transmitted } => Some(transmitted),
                        _ => None,
                    },
                    origin: cast.then_some(s.origin),
                    direction: cast.then_some(s.direction),
                }
            })
            .collect(),
    );
    out.local = node.local.as_ref().map(|l| l.total);
    out.k_rfl = Some(glam::DVec3::splat(node.sum.k_rfl));
    out.k_rfa = Some(glam::DVec3::splat(node.sum.k_rfa));
    let child = |b: &Option<crate::tree::ray_tree::BranchRecord>| {
        Some(
            b.as_ref()
                .and_then(|b| b.node)
                .map(|c| Box::new(ray(tree, c))),
        )
    };
    out.reflected = child(&node.reflected);
    out.refracted = child(&node.refracted);
    out.tir = Some(
        node.refracted
            .as_ref()
            .is_some_and(|b| b.outcome == Branch::TotalInternalReflection),
    );
    out
}
