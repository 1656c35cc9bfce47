//! A filmstrip: frames of one scene side by side, each labelled above with the
//! value that made it and under it how much it changed from the frame before,
//! so a lesson can show what one setting does (the recursion depth, a glass's
//! index) at a glance. Drawn with the figure toolkit.

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::palette;
use crate::scene::settings::RenderSettings;
use crate::views::numbers::num;

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

impl Frame {
    /// A frame of a strip that varies the field at `path`: labelled with its
    /// `value`, and under it the share of pixels that `changed` from the frame
    /// before (`None`: the first frame).
    pub fn varied(rgb: Vec<u8>, path: &str, value: f64, changed: Option<f64>) -> Self {
        Self {
            rgb,
            label: format!("{path} = {}", num(value)),
            change: match changed {
                None => "the first frame".to_owned(),
                Some(share) => format!("{:.1}% of pixels changed", 100.0 * share),
            },
        }
    }

    /// The frame's line on standard output: its label and its change, with
    /// what the change is measured against when there is a frame before.
    pub fn line(&self, first: bool) -> String {
        let from = if first {
            ""
        } else {
            " (from the frame before, by more than 3/255)"
        };
        format!("{}: {}{from}\n", self.label, self.change)
    }
}

/// The title of a strip of `file` varying `path` over `values`, its frames
/// made with `settings` (the first frame's).
pub fn title(file: &str, path: &str, values: &[f64], settings: &RenderSettings) -> String {
    format!(
        "{file}: {path} from {} to {} · {}×{} · {}{} · under each frame: the share of pixels that changed from the frame before by more than 3/255 (as raytree diff counts)",
        num(values.first().copied().unwrap_or_default()),
        num(values.last().copied().unwrap_or_default()),
        settings.width,
        settings.height,
        settings.sampling(),
        if path.ends_with("max_depth") {
            String::new()
        } else {
            format!(" · max depth {}", settings.max_depth)
        }
    )
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
    // A frame's label and change line wrap to its own width (a label may
    // reach a quarter of the gap on each side): room for the longest of each.
    let labels: Vec<Vec<String>> = frames
        .iter()
        .map(|f| Figure::wrap(&f.label, LABEL, (w + GAP / 2.0) as f32))
        .collect();
    let label_lines = labels.iter().map(Vec::len).max().unwrap_or(1);
    let change_lines = frames
        .iter()
        .map(|f| Figure::wrap(&f.change, SMALL, width as f32).len())
        .max()
        .unwrap_or(1);
    let top = MARGIN + LINE * title_lines.len() as f64 + 8.0;
    let image_top = top + LINE * label_lines as f64;
    let page_h = image_top + h + 8.0 + LINE * change_lines as f64 + MARGIN;
    let mut fig = Figure::page(page_w as u32, page_h as u32)?;
    // caption_at takes the last line's baseline; the first sits one line below the margin.
    let title_step = f64::from(LABEL) * 1.3;
    let last_baseline = MARGIN + LINE - 4.0 + title_step * (title_lines.len() - 1) as f64;
    fig.caption_at(&title_lines, LABEL, MARGIN, last_baseline);
    for (k, frame) in frames.iter().enumerate() {
        let left = MARGIN + k as f64 * (w + GAP);
        let center = left + w / 2.0;
        // The label's last line sits just above the frame, like a one-line label.
        let label = &labels[k];
        for (i, line) in label.iter().enumerate() {
            let up = (label.len() - 1 - i) as f64 * LINE;
            fig.text_px(
                DVec2::new(center, image_top - 5.0 - up),
                line,
                LABEL,
                palette::INK,
                Anchor::Center,
                false,
            );
        }
        fig.image(left as u32, image_top as u32, width, &frame.rgb);
        let below = image_top + h + 8.0;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows `rows` of columns `cols` of the figure hold only the white page.
    fn blank(fig: &Figure, rows: std::ops::Range<u32>, cols: std::ops::Range<u32>) -> bool {
        let (w, _) = fig.size();
        let rgb = fig.rgb();
        rows.flat_map(|y| cols.clone().map(move |x| (y * w + x) as usize * 3))
            .all(|i| rgb[i..i + 3] == [255, 255, 255])
    }

    #[test]
    fn a_long_title_and_wide_labels_stay_on_the_page_and_apart() {
        let (width, height) = (100, 60);
        let frame = |label: &str| Frame {
            rgb: [0, 200, 0].repeat((width * height) as usize),
            label: label.to_owned(),
            change: "changed".to_owned(),
        };
        let frames = [
            frame("forward: 1,000,000 rays from the lights"),
            frame("backward: 83,920 rays from the eye"),
        ];
        let title = "a title long enough to wrap over several lines of the page, \
                     as a scene's path and its settings do in a narrow strip of two frames";
        let fig = draw(&frames, width, height, title).unwrap();
        let (page_w, _) = fig.size();
        let title_lines = Figure::wrap(title, LABEL, page_w as f32 - 2.0 * MARGIN as f32).len();
        assert!(
            title_lines >= 3,
            "the test needs a title of three lines or more"
        );
        // The first title line starts below the top margin: nothing is cut off.
        assert!(blank(&fig, 0..MARGIN as u32 / 2, 0..page_w));
        assert!(!blank(
            &fig,
            MARGIN as u32..(MARGIN + LINE) as u32,
            0..page_w
        ));
        // The two labels wrap instead of running into each other: in the
        // rows between the title and the images, the middle of the gap
        // between the frames stays blank.
        let green = |y: u32| {
            let i = (y * page_w + MARGIN as u32 + 2) as usize * 3;
            fig.rgb()[i..i + 3] == [0, 200, 0]
        };
        let image_top = (0..fig.size().1).find(|&y| green(y)).unwrap();
        let title_end = (MARGIN + LINE * title_lines as f64) as u32;
        let middle = (MARGIN + f64::from(width) + GAP / 2.0) as u32;
        assert!(
            image_top > title_end + 2 * LINE as u32,
            "labels on two lines"
        );
        assert!(blank(&fig, title_end..image_top, middle - 1..middle + 2));
    }
}
