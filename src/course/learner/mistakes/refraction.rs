//! The refracted ray's mistakes (lesson 10): in its direction, Snell's law
//! with η upside down, with a sign of the formula turned, with a vector not
//! of unit length, with the outward normal where the ray leaves, or with
//! another medium's index; in the hit's normal, the side it faces; and total
//! internal reflection not handled.

use glam::DVec3;

use crate::course::learner::context::Context;
use crate::course::learner::mistakes::{Diagnosis, Formula, Mistake, Same};
use crate::course::learner::tolerance::{same_direction, tolerance};
use crate::shading::optics::refract;
use crate::trace::recorder::Branch;
use crate::tree::ray_tree::{HitRecord, RayNode};

/// A refracted direction accepted by `same`, made at the hit `h` of the
/// parent ray `parent`.
pub fn direction(ctx: &Context, parent: &RayNode, h: &HitRecord, same: &Same) -> Option<Diagnosis> {
    let (c, n, n1, n2) = (h.incoming, h.shading_normal, h.n1, h.n2);
    if same(refract(c, n, n2 / n1)) {
        return Some(Diagnosis::new(
            Mistake::EtaSwapped,
            format!(
                "your refracted direction is Snell's with η = n₂/n₁ = {n2}/{n1}: the lecture's η is n₁/n₂ = {n1}/{n2} (from the side the ray comes from to the side it goes to)"
            ),
        ));
    }
    signs(c, n, n1 / n2, same)
        .or_else(|| unit_or_side(ctx, parent, h, same))
        .or_else(|| {
            let (a, b) = other_indices(ctx, h, same)?;
            Some(wrong_medium(a, b, n1, n2))
        })
}

/// A refracted direction that is Snell's formula `η·c + (η·cos θ₁ − cos θ₂)·n`
/// (unit `c` and `n` facing it, `η = n₁/n₂`) with one sign turned: `+ cos θ₂`
/// (the square root's sign), or `cos θ₁ = n·c`, negative, where the lecture's
/// is `−n·c`. `same` accepts the learner's direction.
fn signs(c: DVec3, n: DVec3, eta: f64, same: &Same) -> Option<Diagnosis> {
    let with = |cos1: f64, root: f64| {
        let sin2_sq = eta * eta * (1.0 - cos1 * cos1).max(0.0);
        (sin2_sq <= 1.0).then(|| eta * c + (eta * cos1 + root * (1.0 - sin2_sq).sqrt()) * n)
    };
    let cos1 = -n.dot(c);
    if same(with(cos1, 1.0)) {
        return Some(Diagnosis::new(
            Mistake::RefractionRootSign,
            "your refracted direction is η·c + (η·cos θ₁ + cos θ₂)·n: the square root, cos θ₂ = √(1 − η²(1 − cos²θ₁)), enters with a minus sign, η·c + (η·cos θ₁ − cos θ₂)·n; with a plus the ray turns back to the side it came from instead of going through",
        ));
    }
    same(with(-cos1, -1.0)).then(|| {
        Diagnosis::new(
            Mistake::RefractionCosSign,
            "your refracted direction takes cos θ₁ = n·c, which is negative since n faces the incoming ray: the lecture's is cos θ₁ = −n·c, positive",
        )
    })
}

/// Snell's formula applied to the incoming direction as it was (not of unit
/// length), with the outward normal where the ray leaves, or with
/// `n = P − center`.
fn unit_or_side(ctx: &Context, parent: &RayNode, h: &HitRecord, same: &Same) -> Option<Diagnosis> {
    let (c, n, eta) = (h.incoming, h.shading_normal, h.n1 / h.n2);
    let raw = parent.direction;
    if (raw.length() - 1.0).abs() > 1e-3 && same(refract(raw, n, eta)) {
        return Some(Diagnosis::new(
            Mistake::NotNormalized(Formula::Refraction),
            format!(
                "your refracted direction is Snell's formula applied to the incoming direction as it was, of length {:.4}: the formula assumes a unit c (cos θ₁ = −n·c)",
                raw.length()
            ),
        ));
    }
    if !h.entering && same(refract(c, -n, eta)) {
        return Some(Diagnosis::new(
            Mistake::NormalNotTurned,
            "your refracted direction uses the outward normal where the ray leaves the object: turn n to face the incoming ray (n·c < 0) before Snell's law",
        ));
    }
    let r = ctx.sphere_radius(h.object)?;
    same(refract(c, n * r, eta)).then(|| {
        Diagnosis::new(
            Mistake::NotNormalized(Formula::Refraction),
            format!(
                "your refracted direction uses n = P − center, of length r = {r}: Snell's formula assumes a unit normal"
            ),
        )
    })
}

/// A pair of the scene's indices, other than the hit's n₁ → n₂, whose
/// Snell's law gives the direction `same` accepts.
fn other_indices(ctx: &Context, h: &HitRecord, same: &Same) -> Option<(f64, f64)> {
    let (c, n, n1, n2) = (h.incoming, h.shading_normal, h.n1, h.n2);
    let mut indices: Vec<f64> = ctx
        .scene
        .materials
        .iter()
        .map(|m| m.ior)
        .chain([1.0])
        .collect();
    indices.sort_by(f64::total_cmp);
    indices.dedup();
    for &a in &indices {
        for &b in &indices {
            let usual = (a == n1 && b == n2) || (a == n2 && b == n1) || a == b && n1 == n2;
            if !usual && same(refract(c, n, a / b)) {
                return Some((a, b));
            }
        }
    }
    None
}

/// Snell's law with n₁ = `a` → n₂ = `b` where the ray goes from `n1` to `n2`.
fn wrong_medium(a: f64, b: f64, n1: f64, n2: f64) -> Diagnosis {
    Diagnosis::new(
        Mistake::WrongMedium,
        format!(
            "your refracted direction is Snell's with n₁ = {a} → n₂ = {b}; here the ray goes from n₁ = {n1} to n₂ = {n2}: after leaving an object the ray is in the medium around it, not in air or the object's glass"
        ),
    )
}

/// The learner's normal `n` at node `i`'s hit facing the wrong side: into
/// the object where the ray arrives from outside, or outward where it leaves.
pub fn normal_side(ctx: &Context, n: DVec3, i: usize) -> Option<Diagnosis> {
    let node = &ctx.tree().nodes[i];
    let h = node.hit.as_ref()?;
    if !same_direction(n, -h.shading_normal, tolerance(node.depth)) {
        return None;
    }
    Some(if h.entering {
        Diagnosis::new(
            Mistake::NormalInward,
            format!(
                "your normal points into '{}', away from the ray: a ray arriving from outside meets the outward normal N, which faces it (n·c < 0); only a ray leaving the object needs it turned",
                h.name
            ),
        )
    } else {
        Diagnosis::new(
            Mistake::NormalNotTurned,
            format!(
                "your normal is the outward one, but the ray leaves '{}' from inside: the formulas need n turned to face the ray (n = −N, so that n·c < 0)",
                h.name
            ),
        )
    })
}

/// Total internal reflection not handled at node `i`'s hit, where the
/// learner refracted along `refracted`: unless that direction is Snell's
/// with the wrong medium's index, which has no total internal reflection here.
pub fn tir(ctx: &Context, i: usize, refracted: Option<DVec3>) -> Diagnosis {
    let node = &ctx.tree().nodes[i];
    if let (Some(d), Some(h)) = (refracted, node.hit.as_ref()) {
        let tol = tolerance(node.depth + 1);
        let same = |r: Option<DVec3>| r.is_some_and(|r| d.is_finite() && same_direction(d, r, tol));
        if let Some((a, b)) = other_indices(ctx, h, &same) {
            return wrong_medium(a, b, h.n1, h.n2);
        }
    }
    let sin = node
        .hit
        .as_ref()
        .and_then(|h| h.refraction.as_ref())
        .map(|r| r.sin_theta2);
    Diagnosis::new(
        Mistake::TirNotHandled,
        format!(
            "raytree finds total internal reflection here{}: there is no refracted ray, and its share goes to the reflected one",
            sin.map_or(String::new(), |s| format!(
                " (sin θ₂ = (n₁/n₂)·sin θ₁ = {s:.4} > 1)"
            ))
        ),
    )
}

/// A coefficient off at node `i`: after total internal reflection raytree's
/// reflected ray carries the whole share, which a tracer that refracts anyway
/// (along `refracted`) does not.
pub fn coefficient(ctx: &Context, i: usize, refracted: Option<DVec3>) -> Option<Diagnosis> {
    let b = ctx.tree().nodes[i].refracted.as_ref()?;
    (b.outcome == Branch::TotalInternalReflection).then(|| tir(ctx, i, refracted))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::course::learner::tolerance::PRIMARY;

    /// Each sign mistake is recognised from its own direction, and Snell's
    /// own direction is neither: the three differ by far more than the
    /// tolerance at 45° into glass (η = 1/1.5).
    #[test]
    fn each_refraction_sign_is_told_apart() {
        let c = DVec3::new(1.0, -1.0, 0.0).normalize();
        let n = DVec3::Y;
        let eta = 1.0 / 1.5;
        let right = refract(c, n, eta).unwrap();
        let cos1 = -n.dot(c);
        let cos2 = (1.0 - eta * eta * (1.0 - cos1 * cos1)).sqrt();
        let plus = eta * c + (eta * cos1 + cos2) * n;
        let turned = eta * c + (-eta * cos1 - cos2) * n;
        let mistake = |d: DVec3| {
            signs(c, n, eta, &|x: Option<DVec3>| {
                x.is_some_and(|x| same_direction(d, x, PRIMARY))
            })
            .map(|g| g.mistake)
        };
        assert_eq!(mistake(right), None);
        assert_eq!(mistake(plus), Some(Mistake::RefractionRootSign));
        assert_eq!(mistake(turned), Some(Mistake::RefractionCosSign));
    }
}
