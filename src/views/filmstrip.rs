//! A filmstrip: frames of one scene side by side, each labelled above with the
//! value that made it and under it how much it changed from the frame before,
//! so a lesson can show what one setting does (the recursion depth, a glass's
//! index) at a glance. Drawn with the figure toolkit.

use glam::DVec2;

use crate::views::figure::{Anchor, Figure};
use crate::views::pen::palette;

/// One frame: its image and its two lines of text.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// 8-bit RGB, rows top first.
    pub rgb: Vec<u8>,
    /// Above the frame: the value that made it, e.g. `max_depth = 3`.
    pub label: String,
    /// Under the frame: how it differs from the one before.
    pub change: String,
}

const MARGIN: f64 = 16.0;
const GAP: f64 = 12.0;
const LABEL: f32 = 15.0;
const SMALL: f32 = 13.0;
const LINE: f64 = 20.0;

/// The strip of `frames`, each `width × height` pixels, under `title`.
pub fn draw(frames: &[Frame], width: u32, height: u32, title: &str) -> Option<Figure> {
    let n = frames.len().max(1) as f64;
    let (w, h) = (f64::from(width), f64::from(height));
    let page_w = (2.0 * MARGIN + n * w + (n - 1.0) * GAP).max(480.0);
    let title_lines = Figure::wrap(title, LABEL, (page_w - 2.0 * MARGIN) as f32);
    // Each frame's change line wraps to its own width: room for the longest.
    let change_lines = frames
        .iter()
        .map(|f| Figure::wrap(&f.change, SMALL, width as f32).len())
        .max()
        .unwrap_or(1);
    let top = MARGIN + LINE * title_lines.len() as f64 + 8.0;
    let page_h = top + LINE + h + 8.0 + LINE * change_lines as f64 + MARGIN;
    let mut fig = Figure::page(page_w as u32, page_h as u32)?;
    fig.caption_at(&title_lines, LABEL, MARGIN, MARGIN + LINE - 4.0);
    for (k, frame) in frames.iter().enumerate() {
        let left = MARGIN + k as f64 * (w + GAP);
        let center = left + w / 2.0;
        fig.text_px(
            DVec2::new(center, top + LINE - 5.0),
            &frame.label,
            LABEL,
            palette::INK,
            Anchor::Center,
            false,
        );
        fig.image(left as u32, (top + LINE) as u32, width, &frame.rgb);
        let below = top + LINE + h + 8.0;
        for (i, line) in Figure::wrap(&frame.change, SMALL, width as f32)
            .iter()
            .enumerate()
        {
            fig.text_px(
                DVec2::new(center, below + LINE * (i as f64 + 0.7)),
                line,
                SMALL,
                [70, 70, 70],
                Anchor::Center,
                false,
            );
        }
    }
    Some(fig)
}
