//! Two images and where they differ: side by side, with a third frame that
//! colors each pixel by how far apart the two are there (its largest channel
//! difference, in 8-bit levels, on viridis like every magnitude raytree maps)
//! and that frame's color bar under all three. `raytree diff -o` draws it, so
//! a lesson can show where a textbook method, or another renderer, departs.

use crate::figure::canvas::Figure;
use crate::io::image::diff::{Difference, per_pixel};
use crate::views::aov_figure::{BAR_TEXT, MAX_STEPS, Range, bar_caption, draw_bar};
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

/// Frames narrower than this are shown larger, so a learner's small test
/// image (64×48) can be read pixel by pixel.
const MIN_FRAME: u32 = 240;

/// The whole factor a `width`-pixel frame is enlarged by: 1 from
/// [`MIN_FRAME`] on, else the smallest that reaches it.
pub fn enlargement(width: u32) -> u32 {
    MIN_FRAME.div_ceil(width.max(1)).max(1)
}

/// `rgb` (`width` pixels a row) with each pixel made a `k × k` block: nearest
/// neighbour, so every pixel keeps its own color and sharp edges.
fn enlarge(rgb: &[u8], width: u32, k: u32) -> Vec<u8> {
    let (w, k) = (width as usize, k as usize);
    let mut out = Vec::with_capacity(rgb.len() * k * k);
    for row in rgb.chunks_exact(3 * w) {
        let wide: Vec<u8> = row.chunks_exact(3).flat_map(|p| p.repeat(k)).collect();
        for _ in 0..k {
            out.extend_from_slice(&wide);
        }
    }
    out
}

/// The words under the color bar.
const BAR_UNIT: &str = "|A − B| in 8-bit levels, the largest of a pixel's three channels";

/// The figure: `a`, `b` (both `width × height`) and their difference, titled
/// with the figures `d` of the pair; small images enlarged (see
/// [`enlargement`]), and the page at least as wide as the bar's caption.
pub fn draw(a: &Side, b: &Side, width: u32, height: u32, d: &Difference) -> Option<Figure> {
    let (rgb, range) = colored(a.rgb, b.rgb);
    let k = enlargement(width);
    let size = if k > 1 {
        format!("{width}×{height}, shown {k}× larger")
    } else {
        format!("{width}×{height}")
    };
    let frames = [
        Frame {
            rgb: enlarge(a.rgb, width, k),
            label: format!("A: {}", a.name),
            change: size.clone(),
        },
        Frame {
            rgb: enlarge(b.rgb, width, k),
            label: format!("B: {}", b.name),
            change: size,
        },
        Frame {
            rgb: enlarge(&rgb, width, k),
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
    let strip = filmstrip::draw(&frames, width * k, height * k, &title)?;
    let (w, h) = strip.size();
    let caption = Figure::text_width(&bar_caption(&range, BAR_UNIT), BAR_TEXT);
    let page_w = w.max((f64::from(caption) + 2.0 * MARGIN).ceil() as u32);
    let mut fig = Figure::page(page_w, h + BAR_HEIGHT as u32)?;
    fig.paste(&strip, 0, 0);
    draw_bar(
        &mut fig,
        &range,
        BAR_UNIT,
        (MARGIN, f64::from(page_w) - MARGIN),
        f64::from(h),
    );
    Some(fig)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::image::diff::difference;

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

    /// A learner's 64×48 test image: each frame shown 4× larger, pixel for
    /// pixel, and the bar's caption (which ran off the page's right edge at
    /// 480 pixels) inside the page with its margin to spare.
    #[test]
    fn a_small_image_is_enlarged_and_its_caption_fits() {
        let (width, height) = (64, 48);
        let a = image::RgbImage::from_fn(width, height, |x, y| {
            image::Rgb([(4 * x) as u8, (5 * y) as u8, 90])
        });
        let mut b = a.clone();
        b.put_pixel(10, 20, image::Rgb([255, 255, 255]));
        let d = difference(&a, &b).unwrap();
        let side = |rgb, name| Side { rgb, name };
        let fig = draw(
            &side(a.as_raw(), "yours"),
            &side(b.as_raw(), "raytree's"),
            width,
            height,
            &d,
        )
        .unwrap();
        assert_eq!(enlargement(width), 4);
        let (w, _) = fig.size();
        assert!(w >= 3 * 4 * width, "{w}");
        let (_, range) = colored(a.as_raw(), b.as_raw());
        let caption = Figure::text_width(&bar_caption(&range, BAR_UNIT), BAR_TEXT);
        assert!(
            f64::from(caption) + 2.0 * MARGIN <= f64::from(w),
            "caption {caption} px on a page of {w}"
        );
        // Nearest neighbour: a 2×1 image becomes two 3×3 blocks of its colors.
        let big = enlarge(&[1, 2, 3, 4, 5, 6], 2, 3);
        assert_eq!(big.len(), 2 * 3 * 3 * 3);
        assert_eq!((&big[0..3], &big[9..12]), (&[1, 2, 3][..], &[4, 5, 6][..]));
        assert_eq!(&big[18 * 2 + 15..18 * 2 + 18], &[4, 5, 6]);
        assert_eq!(enlargement(640), 1);
    }
}
