//! The sign mistakes of the lecture's vectors, recognised as the other
//! diagnoses are (the learner's number recomputed from raytree's inputs with
//! the one mistake): a shadow ray sent from the light instead of toward it,
//! and Snell's formula with the square root's sign or cos θ₁'s turned. Apart
//! from [`crate::course::learner::diagnose`] only to keep each file short.

use glam::DVec3;

use crate::course::learner::format::LearnerShadow;
use crate::course::learner::measure::same_direction;
use crate::course::learner::mistake::{Diagnosis, found};
use crate::tree::ray_tree::ShadowRecord;

/// A shadow ray's direction `d` that differs from raytree's `ours`: the
/// learner's is `origin − light` (the lecture's is `light − origin`), within
/// `tol` as a unit vector.
pub fn shadow_direction(
    s: &LearnerShadow,
    d: DVec3,
    ours: &ShadowRecord,
    tol: f64,
) -> Option<Diagnosis> {
    same_direction(d, -ours.direction, tol).then_some(())?;
    found(
        "shadow-reversed",
        format!(
            "your shadow ray toward '{}' points away from the light: its direction is origin − light, where the lecture's is light − origin (t = 1 at the light), so it tests the objects behind the point instead of those before the light",
            s.light
        ),
    )
}

/// A refracted direction that is Snell's formula `η·c + (η·cos θ₁ − cos θ₂)·n`
/// (unit `c` and `n` facing it, `η = n₁/n₂`) with one sign turned: `+ cos θ₂`
/// (the square root's sign), or `cos θ₁ = n·c`, negative, where the lecture's
/// is `−n·c`. `same` accepts the learner's direction.
pub fn refracted(
    c: DVec3,
    n: DVec3,
    eta: f64,
    same: &dyn Fn(Option<DVec3>) -> bool,
) -> Option<Diagnosis> {
    let with = |cos1: f64, root: f64| {
        let sin2_sq = eta * eta * (1.0 - cos1 * cos1).max(0.0);
        (sin2_sq <= 1.0).then(|| eta * c + (eta * cos1 + root * (1.0 - sin2_sq).sqrt()) * n)
    };
    let cos1 = -n.dot(c);
    if same(with(cos1, 1.0)) {
        return found(
            "refraction-root-sign",
            "your refracted direction is η·c + (η·cos θ₁ + cos θ₂)·n: the square root, cos θ₂ = √(1 − η²(1 − cos²θ₁)), enters with a minus sign, η·c + (η·cos θ₁ − cos θ₂)·n; with a plus the ray turns back to the side it came from instead of going through".to_owned(),
        );
    }
    if same(with(-cos1, -1.0)) {
        return found(
            "refraction-cos-sign",
            "your refracted direction takes cos θ₁ = n·c, which is negative since n faces the incoming ray: the lecture's is cos θ₁ = −n·c, positive".to_owned(),
        );
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::course::learner::measure::PRIMARY;
    use crate::shading::optics::refract;

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
        let id = |d: DVec3| {
            refracted(c, n, eta, &|x: Option<DVec3>| {
                x.is_some_and(|x| same_direction(d, x, PRIMARY))
            })
            .map(|g| g.id)
        };
        assert_eq!(id(right), None);
        assert_eq!(id(plus), Some("refraction-root-sign"));
        assert_eq!(id(turned), Some("refraction-cos-sign"));
    }
}
