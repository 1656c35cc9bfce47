//! Point lights.

use glam::DVec3;

/// A point light: light arrives from one point, with one color.
#[derive(Clone, Debug, PartialEq)]
pub struct PointLight {
    /// Its name, for traces.
    pub name: String,
    /// Where it is.
    pub position: DVec3,
    /// Its color and intensity (linear RGB, may exceed 1).
    pub color: DVec3,
}
