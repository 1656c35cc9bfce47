//! Secondary ray directions: the mirror reflection and Snell's refraction, and
//! the stack of media a ray is inside.

use glam::DVec3;

/// The lecture's reflected direction `v = c - 2(n·c)n` for incoming direction `c`
/// and unit normal `n` (either side; the formula is the same).
pub fn reflect(c: DVec3, n: DVec3) -> DVec3 {
    c - 2.0 * n.dot(c) * n
}

/// The refracted direction by Snell's law `n₁ sin θ₁ = n₂ sin θ₂` in vector form
/// (Heckbert's derivation; pbrt-v4 §9.3.2): for unit incoming `i`, unit normal `n`
/// facing it (`n·i < 0`) and `eta = n₁/n₂`,
/// `t = eta·i + (eta·cos θ₁ - cos θ₂)·n` with `cos θ₂ = √(1 - eta²(1 - cos² θ₁))`.
/// `None` is total internal reflection: `sin θ₂` would exceed 1.
pub fn refract(i: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let cos_i = -n.dot(i);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(eta * i + (eta * cos_i - cos_t) * n)
}

/// How deep transparent objects may nest (glass in water in glass…) before the
/// innermost are no longer tracked.
pub const MAX_NESTED_MEDIA: usize = 8;

/// The transparent objects a ray is inside, innermost last. The medium a ray
/// travels through is the innermost's; outside all of them it is air (n = 1).
/// A small copyable stack so each ray carries its own without allocating.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Media {
    len: u8,
    objects: [u32; MAX_NESTED_MEDIA],
}

impl Media {
    /// The objects, outermost first.
    pub fn as_slice(&self) -> &[u32] {
        &self.objects[..usize::from(self.len)]
    }

    /// The innermost object, if any.
    pub fn innermost(&self) -> Option<usize> {
        self.as_slice().last().map(|&o| o as usize)
    }

    /// The stack after entering `object`.
    pub fn entered(mut self, object: usize) -> Self {
        if usize::from(self.len) < MAX_NESTED_MEDIA {
            self.objects[usize::from(self.len)] = object as u32;
            self.len += 1;
        }
        self
    }

    /// The stack after leaving `object` (wherever it sits in the stack: media
    /// need not be left in the order they were entered).
    pub fn left(mut self, object: usize) -> Self {
        if let Some(pos) = self.as_slice().iter().rposition(|&o| o as usize == object) {
            self.objects
                .copy_within(pos + 1..usize::from(self.len), pos);
            self.len -= 1;
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_mirrors_about_the_normal() {
        // Down-right onto a floor: (1, -1, 0) reflects to (1, 1, 0).
        assert_eq!(
            reflect(DVec3::new(1.0, -1.0, 0.0), DVec3::Y),
            DVec3::new(1.0, 1.0, 0.0)
        );
        // Same result with the normal flipped.
        assert_eq!(
            reflect(DVec3::new(1.0, -1.0, 0.0), DVec3::NEG_Y),
            DVec3::new(1.0, 1.0, 0.0)
        );
        // Head-on: straight back.
        assert_eq!(reflect(DVec3::NEG_Z, DVec3::Z), DVec3::Z);
    }

    #[test]
    fn snell_bends_toward_the_normal_entering_glass() {
        // 45° from air (1.0) into glass (1.5): sin θ₂ = sin 45° / 1.5 = 0.4714045.
        let i = DVec3::new(1.0, -1.0, 0.0).normalize();
        let t = refract(i, DVec3::Y, 1.0 / 1.5).unwrap();
        assert!((t.length() - 1.0).abs() < 1e-15);
        let sin_t = t.x;
        // Tolerance: a few ULPs of the arithmetic above.
        assert!(
            (sin_t - 45f64.to_radians().sin() / 1.5).abs() < 1e-15,
            "{sin_t}"
        );
        assert!(t.y < 0.0);
        // Head-on passes straight through.
        assert!(
            refract(DVec3::NEG_Y, DVec3::Y, 1.0 / 1.5)
                .unwrap()
                .abs_diff_eq(DVec3::NEG_Y, 1e-15)
        );
    }

    #[test]
    fn total_internal_reflection_at_and_around_the_critical_angle() {
        // Glass to air: critical angle asin(1/1.5) = 41.81°.
        let eta: f64 = 1.5;
        let critical = (1.0 / eta).asin();
        let dir = |theta: f64| DVec3::new(theta.sin(), -theta.cos(), 0.0);
        // Just below: refracts, leaving almost along the surface (sin θ₂ near 1).
        let below = refract(dir(critical - 1e-6), DVec3::Y, eta).unwrap();
        assert!(below.x > 0.999_99 && below.y <= 0.0, "{below}");
        // Just above and far above: no refracted ray.
        assert!(refract(dir(critical + 1e-6), DVec3::Y, eta).is_none());
        assert!(refract(dir(80f64.to_radians()), DVec3::Y, eta).is_none());
        // Into a denser medium there is never total internal reflection.
        assert!(refract(dir(89.9f64.to_radians()), DVec3::Y, 1.0 / eta).is_some());
    }

    #[test]
    fn media_stack_enters_and_leaves_in_any_order() {
        let m = Media::default().entered(3).entered(5);
        assert_eq!(m.innermost(), Some(5));
        assert_eq!(m.left(5).innermost(), Some(3));
        assert_eq!(m.left(3).as_slice(), &[5]);
        assert_eq!(Media::default().left(2).as_slice(), &[] as &[u32]);
    }
}
