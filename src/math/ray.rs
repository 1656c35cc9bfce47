//! A ray `S + t·c`, with the lecture's names: origin `S`, direction `c`.
//!
//! Directions are not normalised: a primary ray's direction is `P(r, c) - eye`,
//! so `t = 1` lands on the image plane, and a transformed ray keeps the same `t`
//! as the world ray it came from (lecture, "Final Intersection").

use glam::DVec3;

/// A half-line `origin + t·dir`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts (`S`).
    pub origin: DVec3,
    /// Where it goes (`c`); any non-zero length.
    pub dir: DVec3,
}

impl Ray {
    /// A ray from `origin` along `dir`.
    pub fn new(origin: DVec3, dir: DVec3) -> Self {
        Self { origin, dir }
    }

    /// The point at parameter `t`.
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.dir
    }
}
