//! Phong's mistakes (lesson 7), recognised in the local color: the terms of
//! a negative N·L or R·V not clamped at 0, V along the ray instead of back to
//! the viewer, N, L or V not of unit length (a transformed object's normal,
//! which `(M⁻¹)ᵀ` stretches, is lesson 6's), the ambient term left out, and
//! the highlight tinted by the surface's color. Each local color is remade
//! with [`crate::shading::phong`]'s own terms, the tracer's.

use glam::DVec3;

use crate::course::learner::context::Context;
use crate::course::learner::format::LearnerRay;
use crate::course::learner::mistakes::{Diagnosis, Formula, Mistake};
use crate::course::learner::tolerance::same_color;
use crate::shading::phong::{Reflectance, mirrored};
use crate::tree::ray_tree::{HitRecord, LocalRecord};

/// Whether a local color remade with a mistake is the learner's, and the
/// mistake changes it.
type Matches<'a> = dyn Fn(DVec3) -> bool + 'a;

/// The learner's local color at node `i`'s hit, found to be raytree's made
/// with one of Phong's mistakes.
pub fn local(ctx: &Context, l: &LearnerRay, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let (h, rec, got) = (node.hit.as_ref()?, node.local.as_ref()?, l.local?);
    let matches = |c: DVec3| !same_color(c, rec.total) && same_color(got, c);
    let view_sign = matches(remade(ctx, h, rec, |n, l, v, _| (n, l, -v)));
    not_clamped(ctx, h, rec, view_sign, &matches)
        .or_else(|| {
            view_sign.then(|| {
                Diagnosis::new(
                    Mistake::ViewSign,
                    "your local color is Phong's with V along the ray, V = c: V points from the hit back to the viewer, V = −c, so the highlight is where R, the mirrored light, comes toward the eye",
                )
            })
        })
        .or_else(|| view_or_light_length(ctx, l, h, rec, &matches))
        .or_else(|| ambient_or_specular(rec, &matches))
        .or_else(|| normal_length(ctx, l, h, rec, &matches))
}

/// raytree's local color plus the negative terms a clamp at 0 removes.
/// `view_sign`: V = c gives the same numbers, which the words say.
fn not_clamped(
    ctx: &Context,
    h: &HitRecord,
    rec: &LocalRecord,
    view_sign: bool,
    matches: &Matches,
) -> Option<Diagnosis> {
    let (n, v) = (h.shading_normal, -h.incoming);
    let (mut diffuse, mut specular) = (DVec3::ZERO, DVec3::ZERO);
    for light in &ctx.scene.lights {
        let lv = (light.position - h.point).normalize();
        let nl = n.dot(lv);
        let r = mirrored(n, lv, nl);
        let (d, s) = unclamped_extra(rec, nl, r.dot(v), light.color);
        diffuse += d;
        specular += s;
    }
    for (extra, what) in [
        (diffuse, "N·L"),
        (specular, "R·V"),
        (diffuse + specular, "N·L and R·V"),
    ] {
        if extra.abs().max_element() > 0.0 && matches(rec.total + extra) {
            let or = if view_sign {
                " (or V points along the ray, V = c, where it should point back to the viewer, V = −c: here both give these numbers)"
            } else {
                ""
            };
            return Some(Diagnosis::new(
                Mistake::NotClamped,
                format!(
                    "your local color adds the terms of negative {what}: clamp them at 0 (max(0, N·L), max(0, R·V)); a light behind the surface, or a highlight pointing away, adds nothing{or}"
                ),
            ));
        }
    }
    None
}

/// V = −c with the learner's direction c not of unit length, or L = light − P
/// unnormalized.
fn view_or_light_length(
    ctx: &Context,
    l: &LearnerRay,
    h: &HitRecord,
    rec: &LocalRecord,
    matches: &Matches,
) -> Option<Diagnosis> {
    let length = l.direction.length();
    if (length - 1.0).abs() > 1e-3 && matches(remade(ctx, h, rec, |n, l, v, _| (n, l, v * length)))
    {
        return Some(Diagnosis::new(
            Mistake::NotNormalized(Formula::Phong),
            format!(
                "your local color is Phong's with V = −c where c, your ray's direction, has length {length:.4}: V must be a unit vector, −c/|c|, or R·V is no cosine"
            ),
        ));
    }
    matches(remade(ctx, h, rec, |n, l, v, d| (n, l * d, v))).then(|| {
        Diagnosis::new(
            Mistake::NotNormalized(Formula::Phong),
            "your local color is Phong's with L = light − P unnormalized: L must be a unit vector, (light − P)/|light − P|, or N·L and R·V are no cosines",
        )
    })
}

/// raytree's local color without the ambient term, or with each specular
/// term multiplied by the surface's color.
fn ambient_or_specular(rec: &LocalRecord, matches: &Matches) -> Option<Diagnosis> {
    if rec.ambient.abs().max_element() > 0.0 && matches(rec.total - rec.ambient) {
        return Some(Diagnosis::new(
            Mistake::AmbientForgotten,
            "your local color has no ambient term: add k_a·color·ambient_light, which lights even the points no light reaches",
        ));
    }
    // The specular terms as raytree added them (from the recorded R·V).
    let specular: DVec3 = rec
        .lights
        .iter()
        .filter_map(|l| l.phong.as_ref())
        .map(|p| reflectance(rec).terms(p.n_dot_l, p.r_dot_v, p.arriving).1)
        .sum();
    matches(rec.total - specular + specular * rec.color).then(|| {
        Diagnosis::new(
            Mistake::SpecularColored,
            "your specular term is multiplied by the surface's color: Phong's highlight k_s·(R·V)^n·light has the light's color, only the diffuse and ambient terms take the surface's",
        )
    })
}

/// The normal the learner wrote, not of unit length, used as it is: lesson
/// 6's where the object is transformed (`(M⁻¹)ᵀ` changes a normal's length).
fn normal_length(
    ctx: &Context,
    l: &LearnerRay,
    h: &HitRecord,
    rec: &LocalRecord,
    matches: &Matches,
) -> Option<Diagnosis> {
    let normal = l.hit.as_ref()?.as_ref()?.normal?.length();
    if (normal - 1.0).abs() <= 1e-3
        || !matches(remade(ctx, h, rec, |n, l, v, _| (n * normal, l, v)))
    {
        return None;
    }
    let transformed = ctx
        .scene
        .objects
        .get(h.object)
        .is_some_and(|o| o.transform.is_some());
    let (formula, why) = if transformed {
        (
            Formula::Transform,
            "the inverse transpose (M⁻¹)ᵀ changes a normal's length, so normalize it after",
        )
    } else {
        (
            Formula::Phong,
            "N·L and R·V are cosines only between unit vectors",
        )
    };
    Some(Diagnosis::new(
        Mistake::NotNormalized(formula),
        format!(
            "your local color is Phong's with your normal at '{}' as it is, of length {normal:.4}: divide it by its length ({why})",
            h.name
        ),
    ))
}

/// What Phong's terms read of the surface at the hit, as recorded.
fn reflectance(rec: &LocalRecord) -> Reflectance {
    Reflectance {
        color: rec.color,
        k_d: rec.k_d,
        k_s: rec.k_s,
        shininess: rec.shininess,
    }
}

/// raytree's local color at hit `h` made again with each arriving light's N, L
/// and V changed by `change(N, L, V, distance to the light)`: the ambient term,
/// plus each light's terms with R = 2(N·L)N − L.
fn remade(
    ctx: &Context,
    h: &HitRecord,
    rec: &LocalRecord,
    change: impl Fn(DVec3, DVec3, DVec3, f64) -> (DVec3, DVec3, DVec3),
) -> DVec3 {
    let mut total = rec.ambient;
    for light in &rec.lights {
        let (Some(p), Some(at)) = (&light.phong, ctx.scene.lights.get(light.light)) else {
            continue;
        };
        let d = (at.position - h.point).length();
        let (n, l, v) = change(h.shading_normal, p.l, p.v, d);
        let n_dot_l = n.dot(l);
        let r_dot_v = mirrored(n, l, n_dot_l).dot(v);
        let (diffuse, specular) = reflectance(rec).terms(n_dot_l, r_dot_v, p.arriving);
        total += diffuse;
        total += specular;
    }
    total
}

/// What the clamps at 0 of [`Reflectance::terms`] remove: the diffuse term of
/// a negative N·L, or, where N·L ≥ 0, the highlight of a negative R·V, as a
/// tracer that forgets `max(0, …)` adds them. A negative R·V to a fractional
/// shininess has no real power (`powf` gives NaN): that highlight is left
/// out, as the clamp would.
fn unclamped_extra(
    rec: &LocalRecord,
    n_dot_l: f64,
    r_dot_v: f64,
    arriving: DVec3,
) -> (DVec3, DVec3) {
    let k = reflectance(rec);
    if n_dot_l < 0.0 {
        return (k.diffuse(n_dot_l, arriving), DVec3::ZERO);
    }
    let highlight = k.highlight(r_dot_v);
    if r_dot_v < 0.0 && highlight.is_finite() {
        return (DVec3::ZERO, highlight * arriving);
    }
    (DVec3::ZERO, DVec3::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A negative R·V to the power 2.5 is NaN; the clamp a tracer forgot
    /// removes nothing there that a diagnosis could match.
    #[test]
    fn a_fractional_power_of_a_negative_cosine_adds_nothing() {
        let rec = LocalRecord {
            color: DVec3::ONE,
            k_a: 0.0,
            k_d: 0.5,
            k_s: 0.5,
            shininess: 2.5,
            ambient_light: DVec3::ZERO,
            ambient: DVec3::ZERO,
            lights: Vec::new(),
            total: DVec3::ZERO,
        };
        assert!((-0.5f64).powf(2.5).is_nan());
        assert_eq!(
            unclamped_extra(&rec, 0.5, -0.5, DVec3::ONE),
            (DVec3::ZERO, DVec3::ZERO)
        );
        let whole = LocalRecord {
            shininess: 3.0,
            ..rec.clone()
        };
        assert_eq!(
            unclamped_extra(&whole, 0.5, -0.5, DVec3::ONE).1,
            DVec3::splat(-0.0625)
        );
        assert_eq!(
            reflectance(&rec).terms(0.5, -0.5, DVec3::ONE),
            (DVec3::splat(0.25), DVec3::ZERO)
        );
    }
}
