//! An image in linear RGB, and the one conversion from linear RGB to 8-bit sRGB
//! that every written image, swatch and figure goes through.

use glam::DVec3;

/// A rendered image in linear RGB, rows top first (image coordinates).
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` colors, row by row from the top.
    pub pixels: Vec<DVec3>,
}

impl Image {
    /// The color at image coordinates `(x, y)`.
    pub fn get(&self, x: u32, y: u32) -> DVec3 {
        self.pixels[y as usize * self.width as usize + x as usize]
    }
}

/// Linear RGB to 8-bit sRGB, for one channel: clamp to [0, 1] (NaN counts as 0),
/// apply the sRGB transfer function (IEC 61966-2-1: `12.92·v` below 0.0031308,
/// else `1.055·v^(1/2.4) - 0.055`), scale to 255 and round to nearest.
pub fn linear_to_srgb8(v: f64) -> u8 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    let s = if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5).floor() as u8
}

/// A color's 8-bit sRGB triple.
pub fn rgb8(c: DVec3) -> [u8; 3] {
    [
        linear_to_srgb8(c.x),
        linear_to_srgb8(c.y),
        linear_to_srgb8(c.z),
    ]
}

/// The image as 8-bit sRGB bytes, rows top first.
pub fn to_rgb8(image: &Image) -> Vec<u8> {
    image.pixels.iter().flat_map(|&c| rgb8(c)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_conversion_matches_the_standard() {
        assert_eq!(linear_to_srgb8(0.0), 0);
        assert_eq!(linear_to_srgb8(1.0), 255);
        assert_eq!(linear_to_srgb8(7.0), 255);
        assert_eq!(linear_to_srgb8(-1.0), 0);
        assert_eq!(linear_to_srgb8(f64::NAN), 0);
        // Linear 0.5 is sRGB 1.055·0.5^(1/2.4) - 0.055 = 0.7354 → 187.5 → 188.
        assert_eq!(linear_to_srgb8(0.5), 188);
        // Linear 0.214 is sRGB 1.055·0.214^(1/2.4) - 0.055 = 0.49996 → 127.49 → 127.
        assert_eq!(linear_to_srgb8(0.214), 127);
        // The linear segment: 0.001 → 12.92·0.001·255 = 3.29 → 3.
        assert_eq!(linear_to_srgb8(0.001), 3);
    }
}
