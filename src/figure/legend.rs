//! A figure's legend: which pen means what, in a box in a corner of the frame
//! (the caller picks the corner that covers the least).

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::{Pen, palette};

/// The length of a pen's sample line in the legend, in pixels.
const LEGEND_SAMPLE: f64 = 36.0;

impl Figure {
    /// The legend box for `entries` in each corner of the frame, in pixels
    /// (top-left `(x, y)`, then `(w, h)`): top right, top left, bottom right, bottom left.
    pub fn legend_boxes(&self, entries: &[(Pen, &str)], size: f32) -> [(DVec2, DVec2); 4] {
        let line = f64::from(size) * 1.5;
        let text_w = entries
            .iter()
            .map(|(_, t)| Figure::text_width(t, size))
            .fold(0.0, f32::max) as f64;
        let wh = DVec2::new(
            LEGEND_SAMPLE + 18.0 + text_w + 12.0,
            line * entries.len() as f64 + 10.0,
        );
        let f = self.frame();
        let (l, r, t, b) = (
            f64::from(f.left()) + 8.0,
            f64::from(f.right()) - wh.x - 8.0,
            f64::from(f.top()) + 8.0,
            f64::from(f.bottom()) - wh.y - 8.0,
        );
        [
            (DVec2::new(r, t), wh),
            (DVec2::new(l, t), wh),
            (DVec2::new(r, b), wh),
            (DVec2::new(l, b), wh),
        ]
    }

    /// A legend: one line per entry, a pen sample then its text, in the box
    /// `corner` of [`Figure::legend_boxes`].
    pub fn legend(&mut self, entries: &[(Pen, &str)], size: f32, corner: usize) {
        let line = f64::from(size) * 1.5;
        let sample = LEGEND_SAMPLE;
        let (origin, wh) = self.legend_boxes(entries, size)[corner.min(3)];
        let (x0, y0, w, h) = (origin.x, origin.y, wh.x, wh.y);
        self.rect_px(
            DVec2::new(x0, y0),
            DVec2::new(x0 + w, y0 + h),
            Some((palette::PAPER, 235)),
            Some(Pen::solid([190, 190, 190], 1.0)),
        );
        for (i, (pen, text)) in entries.iter().enumerate() {
            let y = y0 + 5.0 + line * (i as f64 + 0.5);
            self.line_px(
                DVec2::new(x0 + 8.0, y),
                DVec2::new(x0 + 8.0 + sample, y),
                *pen,
            );
            self.text_px(
                DVec2::new(x0 + 8.0 + sample + 10.0, y + f64::from(size) * 0.35),
                text,
                size,
                palette::INK,
                Anchor::Left,
                false,
            );
        }
    }
}
