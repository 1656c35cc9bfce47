//! Two images and where they differ: side by side, with a third frame that
//! colors each pixel by how far apart the two are there (its largest channel
//! difference, in 8-bit levels, on viridis like every magnitude raytree maps)
//! and that frame's color bar under all three. `raytree diff -o` draws it, so
//! a lesson can show where a textbook method, or another renderer, departs.

use crate::figure::canvas::Figure;
use crate::io::image_diff::{Difference, per_pixel};
use crate::views::aov_figure::{MAX_STEPS, Range, draw_bar};
use crate::views::filmstrip::{self, Frame};
use crate::views::numbers::num;

/// One image of the pair: 8-bit RGB, rows top first, and what to call it.
pub struct Side<'a> {
    /// The pixels.
    pub rgb: &'a [u8],
    /// Its name above its frame (the file name).
    pub name: &'a str,
}

const MARGIN: f64 = 16.0;
const BAR_HEIGHT: f64 = 80.0;

/// The difference frame: each pixel's largest channel difference on the
/// color bar's scale (0 to the largest difference found), and that scale.
pub fn colored(a: &[u8], b: &[u8]) -> (Vec<u8>, Range) {
    let diff = per_pixel(a, b);
    let hi = f64::from(diff.iter().copied().max().unwrap_or(0).max(1));
    let range = Range {
        lo: 0.0,
        hi,
        stepped: hi < MAX_STEPS,
        signed: false,
        log: false,
    };
    let rgb = diff
        .iter()
        .flat_map(|&v| range.color(f64::from(v)))
        .collect();
    (rgb, range)
}

/// The figure: `a`, `b` (both `width × height`) and their difference, titled
/// with the figures `d` of the pair.
pub fn draw(a: &Side, b: &Side, width: u32, height: u32, d: &Difference) -> Option<Figure> {
    let (rgb, range) = colored(a.rgb, b.rgb);
    let size = format!("{width}×{height}");
    let frames = [
        Frame {
            rgb: a.rgb.to_vec(),
            label: format!("A: {}", a.name),
            change: size.clone(),
        },
        Frame {
            rgb: b.rgb.to_vec(),
            label: format!("B: {}", b.name),
            change: size,
        },
        Frame {
            rgb,
            label: "|A − B|".to_owned(),
            change: format!(
                "{}% of pixels off by more than 3/255",
                num(100.0 * d.share_over_3)
            ),
        },
    ];
    let title = format!(
        "{} against {}: mean absolute difference {}/255, largest {}/255",
        a.name,
        b.name,
        num(d.mean),
        d.max
    );
    let strip = filmstrip::draw(&frames, width, height, &title)?;
    let (w, h) = strip.size();
    let mut fig = Figure::page(w, h + BAR_HEIGHT as u32)?;
    fig.paste(&strip, 0, 0);
    draw_bar(
        &mut fig,
        &range,
        "|A − B| in 8-bit levels, the largest of a pixel's three channels",
        (MARGIN, f64::from(w) - MARGIN),
        f64::from(h),
    );
    Some(fig)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::image_diff::difference;

    #[test]
    fn the_difference_frame_maps_each_pixels_largest_channel_difference() {
        let a = [10, 20, 30, 10, 20, 30, 10, 20, 30];
        let b = [10, 20, 30, 10, 23, 30, 10, 220, 28];
        let (rgb, range) = colored(&a, &b);
        // Largest channel differences 0, 3 and 200: the scale runs to 200.
        assert_eq!(range.hi, 200.0);
        let at = |k: usize| [rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2]];
        assert_eq!(at(0), range.color(0.0));
        assert_eq!(at(1), range.color(3.0));
        assert_eq!(at(2), range.color(200.0));
        assert_ne!(at(0), at(2));
        // Identical images: a scale of 0 to 1, every pixel at 0.
        let (same, r) = colored(&a, &a);
        assert_eq!((r.hi, r.stepped), (1.0, true));
        assert!(same.chunks(3).all(|c| c == r.color(0.0)));
    }

    #[test]
    fn the_figure_holds_the_three_frames_and_the_bar() {
        let a = image::RgbImage::from_pixel(100, 60, image::Rgb([10, 20, 30]));
        let mut b = a.clone();
        b.put_pixel(7, 3, image::Rgb([10, 220, 30]));
        let d = difference(&a, &b).unwrap();
        let side = |rgb, name| Side { rgb, name };
        let fig = draw(
            &side(a.as_raw(), "a.png"),
            &side(b.as_raw(), "b.png"),
            100,
            60,
            &d,
        )
        .unwrap();
        let (w, h) = fig.size();
        assert!(w >= 3 * 100 && h >= 60 + BAR_HEIGHT as u32, "{w}×{h}");
    }
}
