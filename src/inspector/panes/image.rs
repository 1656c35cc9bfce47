//! The image pane: the render in half-block cells (two dots each), the pixel
//! cursor, and the overlays that mark where something happens (the pixels `f`
//! finds) or color the image by depth, rays or tests per pixel.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::widgets::{Paragraph, Widget, Wrap};

use crate::inspector::app::App;
use crate::inspector::colors::term_color;
use crate::inspector::state::features::Features;
use crate::inspector::state::find::Overlay;

/// The color of marked pixels: apart from the magenta cursor and most renders.
const MARK: [u8; 3] = [0, 230, 255];

/// The image pane as a widget.
pub struct ImagePane<'a> {
    /// The inspector.
    pub app: &'a App,
    /// Draw in 24-bit color.
    pub truecolor: bool,
}

/// A scalar overlay's value for a pixel, and the largest over the image.
fn scalar(overlay: Overlay, f: &Features) -> Option<u32> {
    match overlay {
        Overlay::Depth => Some(f.depth),
        Overlay::Rays => Some(f.rays),
        Overlay::Tests => Some(f.tests),
        Overlay::None | Overlay::Marks => None,
    }
}

/// What a scalar overlay shows, for the status line: its name and range.
pub fn legend(app: &App) -> Option<String> {
    let finding = app.finding();
    let map = finding.features()?;
    let max = |o| {
        map.cells
            .iter()
            .filter_map(|f| scalar(o, f))
            .max()
            .unwrap_or(0)
    };
    match finding.overlay() {
        Overlay::None => None,
        Overlay::Marks => Some(format!(
            "overlay: pixels with a {} in cyan (o: next)",
            finding.seek().name()
        )),
        o @ (Overlay::Depth | Overlay::Rays | Overlay::Tests) => {
            let what = match o {
                Overlay::Depth => "deepest ray",
                Overlay::Rays => "rays per pixel",
                _ => "tests per pixel",
            };
            Some(format!(
                "overlay: {what}, 0 dark → {} bright (viridis; o: next)",
                max(o)
            ))
        }
    }
}

impl Widget for ImagePane<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let app = self.app;
        if app.scene().is_none() {
            Paragraph::new("no scene: the image is not available")
                .wrap(Wrap { trim: true })
                .render(area, buf);
            return;
        }
        let window = app.window();
        let (w, h) = app.image_size();
        let unknown = [40, 40, 40];
        let (seek, shows) = (app.finding().seek(), app.finding().overlay());
        let overlay = app.finding().features().filter(|_| shows != Overlay::None);
        let top = overlay.map_or(1, |m| {
            m.cells
                .iter()
                .filter_map(|f| scalar(shows, f))
                .max()
                .unwrap_or(1)
                .max(1)
        });
        // `None`: outside the image (the pane's own background, no half block).
        let dot = |i: u16, j: u16| -> Option<[u8; 3]> {
            let (x, y) = window.pixel_at(i, j, w, h)?;
            let shown = app
                .picture()
                .filter(|p| p.window == window)
                .and_then(|p| p.dots[usize::from(j) * usize::from(window.cols) + usize::from(i)])
                .unwrap_or(unknown);
            let Some(map) = overlay else {
                return Some(shown);
            };
            let f = map.at(x, y);
            Some(match scalar(shows, &f) {
                Some(v) => {
                    let c = colorous::VIRIDIS.eval_continuous(f64::from(v) / f64::from(top));
                    [c.r, c.g, c.b]
                }
                None if seek.matches(&f) => MARK,
                None => shown.map(|v| v / 3),
            })
        };
        let cursor = window.dot_of(app.cursor().0, app.cursor().1);
        let mark = [255, 0, 255];
        let color = |c: Option<[u8; 3]>| c.map_or(Color::Reset, |c| term_color(c, self.truecolor));
        for row in 0..area.height {
            for col in 0..area.width {
                let (t, b) = (2 * row, 2 * row + 1);
                let top_dot = if cursor == Some((col, t)) {
                    Some(mark)
                } else {
                    dot(col, t)
                };
                let bottom_dot = if cursor == Some((col, b)) {
                    Some(mark)
                } else {
                    dot(col, b)
                };
                let Some(cell) = buf.cell_mut((area.x + col, area.y + row)) else {
                    continue;
                };
                if top_dot.is_none() && bottom_dot.is_none() {
                    // Beside a letterboxed image: a plain blank, no stripes.
                    cell.set_symbol(" ")
                        .set_fg(Color::Reset)
                        .set_bg(Color::Reset);
                } else {
                    cell.set_symbol("▀")
                        .set_fg(color(top_dot))
                        .set_bg(color(bottom_dot));
                }
            }
        }
    }
}
