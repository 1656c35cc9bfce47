//! The mistakes in what a local color or a shadow ray adds up, recognised as
//! the other diagnoses are (the learner's number recomputed from raytree's
//! inputs with the one mistake): the ambient term left out, the specular
//! term tinted by the surface's color, and a transparent object's k_rfa
//! applied at each surface the shadow ray crosses instead of once. Apart from
//! [`crate::course::learner::diagnose`] only to keep each file short.

use glam::DVec3;

use crate::course::learner::format::LearnerShadow;
use crate::course::learner::measure::{
    COLOR, Context, before_light, phong, same_color, shadow_roots,
};
use crate::course::learner::mistake::{Diagnosis, found};
use crate::tree::ray_tree::{LocalRecord, ShadowRecord};

/// A local color `got` that is raytree's `rec.total` without the ambient
/// term, or with each specular term multiplied by the surface's color.
pub fn local(rec: &LocalRecord, got: DVec3) -> Option<Diagnosis> {
    let matches = |c: DVec3| !same_color(c, rec.total) && same_color(got, c);
    if rec.ambient.abs().max_element() > 0.0 && matches(rec.total - rec.ambient) {
        return found(
            "ambient-forgotten",
            "your local color has no ambient term: add k_a·color·ambient_light, which lights even the points no light reaches".to_owned(),
        );
    }
    // The specular terms as raytree added them (from the recorded R·V).
    let specular: DVec3 = rec
        .lights
        .iter()
        .filter_map(|l| l.phong.as_ref())
        .map(|p| phong(rec, p.n_dot_l, p.r_dot_v, p.arriving).1)
        .sum();
    if matches(rec.total - specular + specular * rec.color) {
        return found(
            "specular-colored",
            "your specular term is multiplied by the surface's color: Phong's highlight k_s·(R·V)^n·light has the light's color, only the diffuse and ambient terms take the surface's".to_owned(),
        );
    }
    None
}

/// A shadow ray's `transmitted` share that is the product of each
/// transparent object's k_rfa raised to the number of its surfaces the ray
/// crosses before the light (0.88² through a glass ball), where raytree
/// applies each object's once.
pub fn transmitted(
    ctx: &Context,
    s: &LearnerShadow,
    got: f64,
    ours: &ShadowRecord,
    transmitted: f64,
) -> Option<Diagnosis> {
    let mut per_surface = 1.0;
    for i in 0..ctx.scene.objects.len() {
        let k = ctx.scene.material_of(i).transparent;
        let crossed = shadow_roots(ctx, i, ours)
            .as_slice()
            .iter()
            .filter(|&&t| before_light(t, ours))
            .count();
        if k > 0.0 && crossed > 0 {
            per_surface *= k.powi(crossed as i32);
        }
    }
    ((per_surface - transmitted).abs() > COLOR && (got - per_surface).abs() <= COLOR)
        .then_some(())?;
    found(
        "transparent-per-surface",
        format!(
            "your shadow ray toward '{}' keeps {got:.4} of the light, each transparent object's k_rfa applied at every surface it crosses: raytree applies an object's k_rfa once, however many of its surfaces the ray crosses ({transmitted:.4} here)",
            s.light
        ),
    )
}
