//! Text in the embedded font: its width, labels and captions drawn with a
//! white halo so they read over lines, and wrapping so a caption is never cut
//! off. fontdue rasterizes DejaVu Sans (in `fonts/`, with its license) and the
//! coverage is blended here by hand, so a figure has the same bytes on every
//! machine.

use std::sync::OnceLock;

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::{Rgb, palette};

fn font() -> &'static fontdue::Font {
    static FONT: OnceLock<fontdue::Font> = OnceLock::new();
    FONT.get_or_init(|| {
        fontdue::Font::from_bytes(
            &include_bytes!("fonts/DejaVuSans.ttf")[..],
            fontdue::FontSettings::default(),
        )
        .expect("the embedded font parses")
    })
}

impl Figure {
    /// The width of `text` at `size` pixels.
    pub fn text_width(text: &str, size: f32) -> f32 {
        text.chars()
            .map(|c| font().metrics(c, size).advance_width)
            .sum()
    }

    /// Text at pixel position `at` (baseline), white-haloed so it reads over lines;
    /// clipped to the frame when `clip`.
    pub fn text_px(
        &mut self,
        at: DVec2,
        text: &str,
        size: f32,
        color: Rgb,
        anchor: Anchor,
        clip: bool,
    ) {
        let width = Self::text_width(text, size);
        let x0 = match anchor {
            Anchor::Left => at.x as f32,
            Anchor::Center => at.x as f32 - width / 2.0,
            Anchor::Right => at.x as f32 - width,
        };
        if let Some(svg) = &mut self.svg {
            svg.text(DVec2::new(f64::from(x0), at.y), text, size, color, clip);
        }
        for (halo, c) in [(true, palette::PAPER), (false, color)] {
            let mut x = x0;
            for ch in text.chars() {
                let (m, bitmap) = font().rasterize(ch, size);
                let left = (x + m.xmin as f32).round() as i32;
                let top = (at.y as f32 - m.height as f32 - m.ymin as f32).round() as i32;
                let offsets: &[(i32, i32)] = if halo {
                    &[
                        (-1, -1),
                        (0, -1),
                        (1, -1),
                        (-1, 0),
                        (1, 0),
                        (-1, 1),
                        (0, 1),
                        (1, 1),
                    ]
                } else {
                    &[(0, 0)]
                };
                for &(dx, dy) in offsets {
                    self.blend_coverage(left + dx, top + dy, m.width, &bitmap, c, clip);
                }
                x += m.advance_width;
            }
        }
    }

    /// Text next to diagram point `p`, offset by `offset` pixels (y down).
    pub fn label(
        &mut self,
        p: DVec2,
        offset: DVec2,
        text: &str,
        size: f32,
        color: Rgb,
        anchor: Anchor,
    ) {
        let at = self.to_px(p) + offset;
        self.text_px(at, text, size, color, anchor, true);
    }

    fn blend_coverage(
        &mut self,
        left: i32,
        top: i32,
        width: usize,
        coverage: &[u8],
        c: Rgb,
        clip: bool,
    ) {
        let (w, h) = (self.pixmap.width() as i32, self.pixmap.height() as i32);
        let f = self.frame;
        for (i, &a) in coverage.iter().enumerate() {
            if a == 0 {
                continue;
            }
            let (x, y) = (
                left + (i % width.max(1)) as i32,
                top + (i / width.max(1)) as i32,
            );
            if x < 0 || y < 0 || x >= w || y >= h {
                continue;
            }
            if clip
                && !(x as f32 >= f.left()
                    && (x as f32) < f.right()
                    && y as f32 >= f.top()
                    && (y as f32) < f.bottom())
            {
                continue;
            }
            let idx = (y * w + x) as usize * 4;
            let data = self.pixmap.data_mut();
            for k in 0..3 {
                let old = u32::from(data[idx + k]);
                data[idx + k] =
                    ((old * (255 - u32::from(a)) + u32::from(c[k]) * u32::from(a) + 127) / 255)
                        as u8;
            }
        }
    }

    /// The caption above the frame, a line each (see [`Figure::wrap`]).
    pub fn caption(&mut self, lines: &[String], size: f32) {
        let bottom = f64::from(self.frame.top()) - f64::from(size) * 0.6;
        self.caption_at(lines, size, f64::from(self.frame.left()), bottom);
    }

    /// Caption lines starting at pixel `left`, the last line's baseline at `bottom`.
    pub fn caption_at(&mut self, lines: &[String], size: f32, left: f64, bottom: f64) {
        let step = f64::from(size) * 1.3;
        for (k, line) in lines.iter().enumerate() {
            let up = (lines.len() - 1 - k) as f64 * step;
            self.text_px(
                DVec2::new(left, bottom - up),
                line,
                size,
                palette::INK,
                Anchor::Left,
                false,
            );
        }
    }

    /// `text` broken at spaces into lines at most `width` pixels wide at `size`,
    /// so a caption is never cut off.
    pub fn wrap(text: &str, size: f32, width: f32) -> Vec<String> {
        let mut lines: Vec<String> = Vec::new();
        let mut line = String::new();
        for word in text.split(' ') {
            let candidate = if line.is_empty() {
                word.to_owned()
            } else {
                format!("{line} {word}")
            };
            if Self::text_width(&candidate, size) > width && !line.is_empty() {
                lines.push(std::mem::replace(&mut line, word.to_owned()));
            } else {
                line = candidate;
            }
        }
        lines.push(line);
        lines
    }
}
