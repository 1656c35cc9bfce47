//! The mistakes that change a learner's whole image at once: the colors
//! written without the sRGB encoding, the rows upside down, the columns
//! mirrored, red and blue swapped. Each leaves every pixel's rays right, so a
//! pixel's trace agrees while nearly every pixel is off; the check has to see
//! them in the image itself. Each is recognised by making raytree's own image
//! with the mistake (and every combination of them) and finding the learner's
//! clearly closer to it than to raytree's. Their ids are the image report's,
//! a contract as the pixel report's are.

use serde::{Serialize, Serializer};

use crate::io::image::Image;
use crate::io::image::diff::per_pixel;

/// A mistake in writing the whole image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ImageMistake {
    /// The linear colors written as bytes, without the sRGB encoding.
    NoSrgb,
    /// The image upside down.
    RowsFlipped,
    /// The image mirrored left to right.
    ColumnsMirrored,
    /// Red and blue swapped.
    ChannelsSwapped,
}

impl ImageMistake {
    /// Every one, in the order a report names them (and of the bits of a set
    /// of them: bit `1 << i` is `ALL[i]`).
    pub const ALL: [ImageMistake; 4] = [
        ImageMistake::NoSrgb,
        ImageMistake::RowsFlipped,
        ImageMistake::ColumnsMirrored,
        ImageMistake::ChannelsSwapped,
    ];

    /// Its stable id for autograders.
    pub fn id(self) -> &'static str {
        match self {
            ImageMistake::NoSrgb => "no-srgb",
            ImageMistake::RowsFlipped => "rows-flipped",
            ImageMistake::ColumnsMirrored => "columns-mirrored",
            ImageMistake::ChannelsSwapped => "channels-swapped",
        }
    }

    /// What to fix, in one plain sentence.
    pub fn words(self) -> &'static str {
        match self {
            ImageMistake::NoSrgb => {
                "your image holds the linear colors written as bytes (v·255): encode each channel with the sRGB transfer function before writing it, as learner_io.srgb8 does"
            }
            ImageMistake::RowsFlipped => {
                "your image is upside down: write its rows from the top (y down), or map row y to r = rows − 1 − y in the camera"
            }
            ImageMistake::ColumnsMirrored => {
                "your image is mirrored left to right: column x must map to c = x, from the left"
            }
            ImageMistake::ChannelsSwapped => {
                "your image has red and blue swapped: write each pixel's channels as red, green, blue"
            }
        }
    }
}

/// Written as its id.
impl Serialize for ImageMistake {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

/// What the whole-image mistakes explain of a learner's image.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Explained {
    /// The mistakes, in the order of [`ImageMistake::ALL`].
    pub mistakes: Vec<ImageMistake>,
    /// How many pixels would still be off with them fixed.
    pub off: u64,
}

/// The combination of whole-image mistakes that explains `yours` (8-bit,
/// rows from the top) clearly better than raytree's image as it is, or
/// `None`. `ours` is raytree's render in linear RGB, `off` how many pixels are
/// off as it is. "Clearly" is at most a quarter as many pixels off: a left
/// and right symmetric scene is nearly its own mirror image, and a learner's
/// other mistakes leave pixels off either way, so a combination that only
/// shaves a few pixels is chance, not the mistake.
pub fn explain(yours: &[u8], ours: &Image, tolerance: u8, off: u64) -> Option<Explained> {
    if off == 0 {
        return None;
    }
    let srgb = crate::io::image::to_rgb8(ours);
    let linear: Vec<u8> = ours
        .pixels
        .iter()
        .flat_map(|c| [c.x, c.y, c.z])
        .map(linear8)
        .collect();
    let (w, h) = (ours.width as usize, ours.height as usize);
    let mut best: Option<(u32, u64)> = None;
    // Fewer mistakes first, so a tie keeps the simpler explanation.
    let mut sets: Vec<u32> = (1..16).collect();
    sets.sort_by_key(|s| s.count_ones());
    for set in sets {
        let base = if set & 1 != 0 { &linear } else { &srgb };
        let made = with_mistakes(base, w, h, set);
        let count = per_pixel(yours, &made)
            .iter()
            .filter(|d| **d > tolerance)
            .count() as u64;
        if best.is_none_or(|(_, b)| count < b) {
            best = Some((set, count));
        }
    }
    let (set, count) = best?;
    (count < off && count * 4 <= off).then(|| Explained {
        mistakes: (0..4)
            .filter(|i| set & (1 << i) != 0)
            .map(|i| ImageMistake::ALL[i])
            .collect(),
        off: count,
    })
}

/// A linear channel written as a byte without the encoding, rounded: what
/// `int(round(v * 255))` writes (a tracer that truncates is a level lower,
/// within the default tolerance).
fn linear8(v: f64) -> u8 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    (v * 255.0).round() as u8
}

/// `rgb` (w × h, rows from the top) with the mistakes of `set` (bit 1 rows
/// flipped, bit 2 columns mirrored, bit 3 red and blue swapped).
fn with_mistakes(rgb: &[u8], w: usize, h: usize, set: u32) -> Vec<u8> {
    let mut out = vec![0; rgb.len()];
    for y in 0..h {
        let sy = if set & 2 != 0 { h - 1 - y } else { y };
        for x in 0..w {
            let sx = if set & 4 != 0 { w - 1 - x } else { x };
            let (i, s) = (3 * (y * w + x), 3 * (sy * w + sx));
            out[i..i + 3].copy_from_slice(&rgb[s..s + 3]);
            if set & 8 != 0 {
                out.swap(i, i + 2);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// An image with no symmetry: a gradient across, another down, and a
    /// blue that differs from its red, so every mistake changes it.
    fn scene_image() -> Image {
        let (width, height) = (16, 12);
        let pixels = (0..height)
            .flat_map(|y| {
                (0..width).map(move |x| {
                    DVec3::new(
                        f64::from(x) / 15.0,
                        f64::from(y) / 11.0,
                        0.2 + 0.05 * f64::from((x * 7 + y * 3) % 11),
                    )
                })
            })
            .collect();
        Image {
            width,
            height,
            pixels,
        }
    }

    fn off(yours: &[u8], ours: &Image) -> u64 {
        per_pixel(yours, &crate::io::image::to_rgb8(ours))
            .iter()
            .filter(|d| **d > 1)
            .count() as u64
    }

    /// Each mistake alone, and gamma forgotten with the rows flipped, made
    /// the way a learner's writer makes them (truncating, as `int(v*255)`
    /// does, for the linear bytes), is named exactly, and with it fixed no
    /// pixel is off.
    #[test]
    fn each_mistake_and_a_pair_are_named() {
        let img = scene_image();
        let (w, h) = (16, 12);
        let srgb = crate::io::image::to_rgb8(&img);
        let truncated: Vec<u8> = img
            .pixels
            .iter()
            .flat_map(|c| [c.x, c.y, c.z])
            .map(|v| (v * 255.0) as u8)
            .collect();
        use ImageMistake::*;
        let cases: [(Vec<u8>, &[ImageMistake]); 5] = [
            (truncated.clone(), &[NoSrgb]),
            (with_mistakes(&srgb, w, h, 2), &[RowsFlipped]),
            (with_mistakes(&srgb, w, h, 4), &[ColumnsMirrored]),
            (with_mistakes(&srgb, w, h, 8), &[ChannelsSwapped]),
            (with_mistakes(&truncated, w, h, 2), &[NoSrgb, RowsFlipped]),
        ];
        for (yours, mistakes) in cases {
            let as_is = off(&yours, &img);
            assert!(as_is > 0, "{mistakes:?}: the mistake changes the image");
            let found = explain(&yours, &img, 1, as_is).expect("explained");
            assert_eq!(found.mistakes, mistakes);
            assert_eq!(found.off, 0, "{mistakes:?}");
        }
    }

    /// An image off by some other mistake (every pixel a little too dark) is
    /// no closer to any whole-image mistake, and none is named; nor for an
    /// image that agrees.
    #[test]
    fn another_mistake_is_not_named() {
        let img = scene_image();
        let darker: Vec<u8> = crate::io::image::to_rgb8(&img)
            .iter()
            .map(|b| b.saturating_sub(20))
            .collect();
        let as_is = off(&darker, &img);
        assert!(as_is > 0);
        assert_eq!(explain(&darker, &img, 1, as_is), None);
        assert_eq!(explain(&crate::io::image::to_rgb8(&img), &img, 1, 0), None);
    }
}
