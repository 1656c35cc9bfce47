//! How far apart two 8-bit images are: what `raytree diff` prints, and how the
//! POV-Ray comparison judges agreement.

use anyhow::{Result, bail};

/// The differences between two images of the same size, over every channel of
/// every pixel, in 8-bit levels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Difference {
    /// Mean absolute difference (0–255).
    pub mean: f64,
    /// Largest absolute difference.
    pub max: u8,
    /// Share of pixels where some channel differs by more than 3 levels.
    pub share_over_3: f64,
}

/// Compares two images.
pub fn difference(a: &image::RgbImage, b: &image::RgbImage) -> Result<Difference> {
    if a.dimensions() != b.dimensions() {
        bail!(
            "the images differ in size: {}×{} and {}×{}",
            a.width(),
            a.height(),
            b.width(),
            b.height()
        );
    }
    let (mut sum, mut max, mut over) = (0u64, 0u8, 0u64);
    for (p, q) in a.pixels().zip(b.pixels()) {
        let mut worst = 0;
        for c in 0..3 {
            let d = p[c].abs_diff(q[c]);
            sum += u64::from(d);
            worst = worst.max(d);
        }
        max = max.max(worst);
        over += u64::from(worst > 3);
    }
    let pixels = u64::from(a.width()) * u64::from(a.height());
    Ok(Difference {
        mean: sum as f64 / (3 * pixels).max(1) as f64,
        max,
        share_over_3: over as f64 / pixels.max(1) as f64,
    })
}

/// Per pixel of two 8-bit RGB buffers of one size, the largest of its three
/// channels' absolute differences (what `share_over_3` counts above 3).
pub fn per_pixel(a: &[u8], b: &[u8]) -> Vec<u8> {
    a.chunks_exact(3)
        .zip(b.chunks_exact(3))
        .map(|(p, q)| (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_levels_per_channel() {
        let a = image::RgbImage::from_pixel(2, 1, image::Rgb([10, 20, 30]));
        let mut b = a.clone();
        b.put_pixel(1, 0, image::Rgb([16, 20, 30]));
        let d = difference(&a, &b).unwrap();
        // One channel of six is 6 levels off: mean 1, max 6, one pixel of two over 3.
        assert_eq!((d.mean, d.max, d.share_over_3), (1.0, 6, 0.5));
        let small = image::RgbImage::new(1, 1);
        assert!(difference(&a, &small).is_err());
    }
}
