//! How a ray diagram draws: one pen per kind of line (color and dash both
//! differ, so kinds read apart in gray and for color-blind readers), the
//! materials' pale fills, and sizes that scale with the figure.

use glam::DVec3;

use crate::figure::pen::{Pen, Rgb, palette};
use crate::shading::material::{Material, Pattern};
use crate::tree::ray_tree::RayKind;

/// What a drawn line is; each kind differs by dash pattern as well as color.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    /// A ray of this kind.
    Ray(RayKind),
    /// A shadow ray that reaches its light.
    ShadowReaches,
    /// A shadow ray up to its blocker.
    ShadowBlocked,
    /// The rest of a blocked shadow ray, from the blocker to the light.
    ShadowPastBlocker,
}

impl Stroke {
    /// How it is drawn.
    pub fn pen(self) -> Pen {
        match self {
            Stroke::Ray(kind) => ray_pen(kind),
            Stroke::ShadowReaches => Pen::solid(palette::SHADOW_REACHES, 1.0),
            Stroke::ShadowBlocked => Pen::solid(palette::SHADOW_BLOCKED, 1.3),
            Stroke::ShadowPastBlocker => Pen::pattern(palette::SHADOW_BLOCKED, 1.0, &[2.0, 4.0]),
        }
    }

    /// Whether it ends in an arrowhead.
    pub fn arrow(self) -> bool {
        matches!(self, Stroke::Ray(_))
    }
}

/// The pen a ray of this kind is drawn with: color and dash pattern both differ,
/// so the kinds read apart in gray and for color-blind readers.
pub fn ray_pen(kind: RayKind) -> Pen {
    match kind {
        RayKind::Primary => Pen::solid(palette::PRIMARY, 2.5),
        RayKind::Reflected => Pen::pattern(palette::REFLECTED, 2.5, &[12.0, 5.0]),
        RayKind::Refracted => Pen::pattern(palette::REFRACTED, 2.5, &[12.0, 4.0, 2.5, 4.0]),
        RayKind::Shadow => Pen::solid(palette::SHADOW_REACHES, 1.0),
    }
}

/// The pen of surface normals.
pub const NORMAL: Pen = Pen::solid(palette::NORMAL, 2.0);

/// The pen of a box a ray entered.
pub const MET_BOX: Pen = Pen::solid(palette::BOX, 1.2);

/// The pen of a box tested and missed.
pub const MISSED_BOX: Pen = Pen::pattern(palette::BOX, 0.9, &[2.0, 3.0]);

/// Sizes scaled with the figure, so 600×400 reads as well as 1200×800.
#[derive(Clone, Copy, Debug)]
pub struct Scale {
    /// 1 at 1200×800.
    pub k: f64,
    /// Label text size.
    pub text: f32,
}

impl Scale {
    /// The scale for a figure of `width × height` pixels.
    pub fn of(width: u32, height: u32) -> Self {
        let k = (f64::from(width) / 1200.0)
            .min(f64::from(height) / 800.0)
            .clamp(0.5, 2.5);
        Self {
            k,
            text: (15.0 * k as f32).max(10.0),
        }
    }

    /// A length of `x` pixels at 1200×800, at this figure's size.
    pub fn px(&self, x: f64) -> f64 {
        x * self.k
    }

    /// The pen widened (and its dashes stretched) to this figure's size.
    pub fn pen(&self, pen: Pen) -> Pen {
        pen.scaled(self.k as f32)
    }
}

/// A pale fill that hints at the material: glass blue, mirrors gray, others a
/// washed-out version of their color.
pub fn pale(material: &Material) -> (Rgb, u8) {
    if material.transparent > 0.0 {
        return ([200, 225, 250], 150);
    }
    if material.reflective >= 0.5 {
        return ([215, 215, 220], 200);
    }
    let c = match material.pattern {
        Pattern::Solid(c) => c,
        Pattern::Checker { colors, .. } => (colors[0] + colors[1]) / 2.0,
    };
    let srgb = crate::io::image::rgb8(c.min(DVec3::ONE));
    (
        srgb.map(|v| (255 - (255 - u16::from(v)) * 35 / 100) as u8),
        255,
    )
}
