//! An image in linear RGB, and the one conversion from linear RGB to 8-bit sRGB
//! that every written image, swatch and figure goes through; its files and
//! the difference between two images beside it.

pub mod file; // PNG and PPM
pub mod diff; // how far apart two images are

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
///
/// This is the definition, one `powf` per call; [`linear_to_srgb8`] gives the
/// same byte for every input at a fraction of the cost.
pub fn linear_to_srgb8_exact(v: f64) -> u8 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    let s = if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5).floor() as u8
}

/// Linear RGB to 8-bit sRGB, the same byte as [`linear_to_srgb8_exact`] for
/// every input. The conversion is a step function with 255 steps, so it is
/// enough to know where each step starts: the smallest linear value that the
/// definition maps to each byte, found once by bisection on the definition
/// itself. A table over [`SRGB_CELLS`] equal cells of [0, 1] names the byte at
/// each cell's start; a cell holds at most one step's start (the steepest part
/// of the curve, at 0.0031308, climbs about 0.8 bytes per cell), so one
/// comparison finishes the lookup.
#[inline]
pub fn linear_to_srgb8(v: f64) -> u8 {
    let table = srgb_table();
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    let byte = table.at_cell[(v * SRGB_CELLS as f64) as usize];
    if byte < 255 && v >= table.starts[usize::from(byte)] {
        byte + 1
    } else {
        byte
    }
}

/// An sRGB-encoded component (0 to 1, as a display shows it) as linear RGB:
/// the inverse of the sRGB transfer function (IEC 61966-2-1),
/// `c/12.92` up to 0.04045, `((c + 0.055)/1.055)^2.4` above. Colors written
/// for a screen, as NFF's are, become the light a renderer works in.
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Cells of the lookup table over [0, 1] (see [`linear_to_srgb8`]).
pub const SRGB_CELLS: usize = 4096;

/// Where each byte of the sRGB conversion starts.
struct SrgbTable {
    /// `starts[k]`: the smallest linear value converted to byte `k + 1`.
    starts: [f64; 255],
    /// The byte of each cell's lowest value; the last entry is for 1.0 alone.
    at_cell: [u8; SRGB_CELLS + 1],
}

fn srgb_table() -> &'static SrgbTable {
    static TABLE: std::sync::OnceLock<SrgbTable> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut starts = [0.0; 255];
        for (k, start) in starts.iter_mut().enumerate() {
            *start = srgb_step_start(k as u8 + 1);
        }
        let mut at_cell = [0; SRGB_CELLS + 1];
        for (i, byte) in at_cell.iter_mut().enumerate() {
            *byte = linear_to_srgb8_exact(i as f64 / SRGB_CELLS as f64);
        }
        SrgbTable { starts, at_cell }
    })
}

/// The smallest `v` in [0, 1] with `linear_to_srgb8_exact(v) >= byte`, by
/// bisection over the bit patterns of non-negative doubles (ordered as integers).
fn srgb_step_start(byte: u8) -> f64 {
    let (mut lo, mut hi) = (0.0f64.to_bits(), 1.0f64.to_bits());
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if linear_to_srgb8_exact(f64::from_bits(mid)) >= byte {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    f64::from_bits(hi)
}

/// A color's 8-bit sRGB triple.
pub fn rgb8(c: DVec3) -> [u8; 3] {
    [
        linear_to_srgb8(c.x),
        linear_to_srgb8(c.y),
        linear_to_srgb8(c.z),
    ]
}

/// The image as 8-bit sRGB bytes, rows top first, converted on all cores.
pub fn to_rgb8(image: &Image) -> Vec<u8> {
    use rayon::prelude::*;
    let mut out = vec![0; 3 * image.pixels.len()];
    out.par_chunks_mut(3 * 1024)
        .zip(image.pixels.par_chunks(1024))
        .for_each(|(bytes, pixels)| {
            for (b, &c) in bytes.chunks_exact_mut(3).zip(pixels) {
                b.copy_from_slice(&rgb8(c));
            }
        });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_conversion_matches_the_standard() {
        for f in [linear_to_srgb8, linear_to_srgb8_exact] {
            check_standard_values(f);
        }
    }

    /// The fast conversion and the definition agree exactly where every byte
    /// starts (on the start and on the double just below it, the only places a
    /// step function can disagree with another of the same steps), and on a
    /// dense sweep of [0, 1] and beyond.
    #[test]
    fn fast_srgb_equals_the_definition_at_every_step() {
        let table = srgb_table();
        for (k, &start) in table.starts.iter().enumerate() {
            let byte = k as u8 + 1;
            assert_eq!(linear_to_srgb8_exact(start), byte, "start of {byte}");
            assert_eq!(linear_to_srgb8_exact(start.next_down()), byte - 1);
            assert_eq!(linear_to_srgb8(start), byte, "start of {byte}");
            assert_eq!(linear_to_srgb8(start.next_down()), byte - 1);
        }
        // The definition is monotone, so agreeing on every step's start and the
        // value before it is agreeing everywhere; a sweep checks that premise.
        let mut previous = 0;
        for i in 0..=1_000_000 {
            let v = f64::from(i) * 1.2e-6 - 0.1;
            let exact = linear_to_srgb8_exact(v);
            assert!(exact >= previous, "the definition decreases at {v}");
            previous = exact;
            assert_eq!(linear_to_srgb8(v), exact, "at {v}");
        }
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1.0, 0.0, -0.0] {
            assert_eq!(linear_to_srgb8(v), linear_to_srgb8_exact(v), "at {v}");
        }
    }

    fn check_standard_values(linear_to_srgb8: fn(f64) -> u8) {
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
