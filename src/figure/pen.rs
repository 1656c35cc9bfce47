//! Colors and pens: what every figure draws with. One palette for all views,
//! so a ray kind has the same color in a diagram, the inspector and the book.

/// An sRGB color.
pub type Rgb = [u8; 3];

/// The colors every ray diagram uses (the inspector's diagram pane too): the
/// Okabe–Ito palette ("Color Universal Design", 2008), chosen to stay apart
/// for readers with red–green color blindness; ray kinds also differ by dash
/// pattern, so a figure reads in gray too.
pub mod palette {
    use super::Rgb;
    /// Primary rays.
    pub const PRIMARY: Rgb = [0, 114, 178];
    /// Reflected rays.
    pub const REFLECTED: Rgb = [0, 158, 115];
    /// Refracted rays.
    pub const REFRACTED: Rgb = [213, 94, 0];
    /// Shadow rays that reach their light.
    pub const SHADOW_REACHES: Rgb = [230, 159, 0];
    /// Shadow rays that are blocked.
    pub const SHADOW_BLOCKED: Rgb = [100, 100, 100];
    /// Surface normals.
    pub const NORMAL: Rgb = [204, 121, 167];
    /// Bounding boxes of the hierarchy (Okabe–Ito sky blue).
    pub const BOX: Rgb = [86, 180, 233];
    /// Object outlines.
    pub const OBJECT: Rgb = [60, 60, 60];
    /// Object fill.
    pub const OBJECT_FILL: Rgb = [232, 232, 232];
    /// Lights.
    pub const LIGHT: Rgb = [255, 200, 0];
    /// Text, the eye, the image plane.
    pub const INK: Rgb = [20, 20, 20];
    /// The page.
    pub const PAPER: Rgb = [255, 255, 255];
}

/// How a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pen {
    /// Its color.
    pub color: Rgb,
    /// Width in pixels.
    pub width: f32,
    /// Dash and gap lengths in pixels, repeating; empty for a solid line.
    pub dash: &'static [f32],
    /// How much the dash lengths are stretched (with the figure's size).
    pub dash_scale: f32,
    /// Opacity, 255 opaque.
    pub alpha: u8,
}

impl Pen {
    /// A solid pen.
    pub const fn solid(color: Rgb, width: f32) -> Self {
        Self::pattern(color, width, &[])
    }

    /// A dashed pen.
    pub const fn dashed(color: Rgb, width: f32) -> Self {
        Self::pattern(color, width, &[7.0, 5.0])
    }

    /// A pen with a dash pattern.
    pub const fn pattern(color: Rgb, width: f32, dash: &'static [f32]) -> Self {
        Self {
            color,
            width,
            dash,
            dash_scale: 1.0,
            alpha: 255,
        }
    }

    /// The same pen `k` times as wide, its dashes too.
    pub fn scaled(self, k: f32) -> Self {
        Self {
            width: self.width * k,
            dash_scale: self.dash_scale * k,
            ..self
        }
    }

    /// The same pen, faint and dotted: a ray where it only passes an object.
    pub fn passing(self) -> Self {
        Self {
            dash: &[2.0, 5.0],
            alpha: 110,
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Rgb;
    use super::palette::*;

    /// sRGB (0–255) to linear RGB (IEC 61966-2-1).
    fn linear(c: Rgb) -> [f64; 3] {
        c.map(|v| {
            let v = f64::from(v) / 255.0;
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        })
    }

    /// Linear RGB to CIELAB (D65), through XYZ.
    fn lab(rgb: [f64; 3]) -> [f64; 3] {
        let [r, g, b] = rgb.map(|v| v.clamp(0.0, 1.0));
        let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
        let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
        let f = |t: f64| {
            if t > 216.0 / 24389.0 {
                t.cbrt()
            } else {
                (24389.0 / 27.0 * t + 16.0) / 116.0
            }
        };
        [
            116.0 * f(y) - 16.0,
            500.0 * (f(x) - f(y)),
            200.0 * (f(y) - f(z)),
        ]
    }

    /// How a color looks with full protanopia or deuteranopia: the matrices of
    /// Machado, Oliveira and Fernandes, "A Physiologically-based Model for
    /// Simulation of Color Vision Deficiency" (IEEE TVCG 2009), severity 1.0,
    /// applied in linear RGB.
    fn simulate(c: Rgb, m: [[f64; 3]; 3]) -> [f64; 3] {
        let v = linear(c);
        m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
    }

    const PROTANOPIA: [[f64; 3]; 3] = [
        [0.152286, 1.052583, -0.204868],
        [0.114503, 0.786281, 0.099216],
        [-0.003882, -0.048116, 1.051998],
    ];
    const DEUTERANOPIA: [[f64; 3]; 3] = [
        [0.367322, 0.860646, -0.227968],
        [0.280085, 0.672501, 0.047413],
        [-0.011820, 0.042940, 0.968881],
    ];

    #[test]
    fn ray_colors_stay_apart_for_red_green_color_blind_readers() {
        let kinds = [
            ("primary", PRIMARY),
            ("reflected", REFLECTED),
            ("refracted", REFRACTED),
            ("shadow", SHADOW_REACHES),
            ("blocked shadow", SHADOW_BLOCKED),
            ("normal", NORMAL),
            ("box", BOX),
        ];
        let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        for (vision, m) in [
            ("normal", identity),
            ("protanopia", PROTANOPIA),
            ("deuteranopia", DEUTERANOPIA),
        ] {
            for (i, (a, ca)) in kinds.iter().enumerate() {
                for (b, cb) in &kinds[i + 1..] {
                    let (la, lb) = (lab(simulate(*ca, m)), lab(simulate(*cb, m)));
                    let de = ((la[0] - lb[0]).powi(2)
                        + (la[1] - lb[1]).powi(2)
                        + (la[2] - lb[2]).powi(2))
                    .sqrt();
                    // ΔE*ab of 10 is a difference anyone sees at a glance on lines
                    // a few pixels wide (2.3 is the just-noticeable one).
                    assert!(de > 10.0, "{vision}: {a} and {b} are only ΔE {de:.1} apart");
                }
            }
        }
    }
}
