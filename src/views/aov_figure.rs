//! A per-pixel quantity ([`crate::trace::aov`]) as a figure: the image, and
//! under it a strip with what it shows and its key: a color bar with the range
//! and unit (viridis, a perceptually uniform map, for magnitudes; a diverging
//! map centered on zero for signed values), or a swatch per category.
//! Pixels where the quantity has no value are a gray checkerboard, named so in
//! the key. Colormaps come from `colorous` (d3-scale-chromatic's tables).

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::Rgb;
use crate::figure::pen::{Pen, palette};
use crate::io::image::rgb8;
use crate::trace::aov::{Aov, AovImage, Key, Value};
use crate::views::numbers::num;

/// The two grays of the checkerboard that marks pixels without a value.
pub const UNDEFINED: [Rgb; 2] = [[190, 190, 190], [232, 232, 232]];

/// Category colors: the Okabe–Ito palette ("Color Universal Design", 2008),
/// which stays apart for red–green color-blind readers; black last.
const CATEGORIES: [Rgb; 8] = [
    [230, 159, 0],
    [86, 180, 233],
    [0, 158, 115],
    [240, 228, 66],
    [0, 114, 178],
    [213, 94, 0],
    [204, 121, 167],
    [0, 0, 0],
];

/// Whole-number scales with at most this many values get a step per value.
pub const MAX_STEPS: f64 = 24.0;

/// The narrowest figure: the key needs room for its words.
const MIN_WIDTH: u32 = 640;

/// How numbers map to colors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// The value at the bar's left end.
    pub lo: f64,
    /// The value at its right end.
    pub hi: f64,
    /// Whole numbers with few values: one step per value.
    pub stepped: bool,
    /// A diverging map centered on zero.
    pub signed: bool,
    /// Positive values spanning more than [`LOG_SPAN`]: a logarithmic bar.
    pub log: bool,
}

/// A positive range wider than this ratio gets a logarithmic bar (a distance
/// map with a floor running to the horizon spans three decades).
pub const LOG_SPAN: f64 = 100.0;

impl Range {
    /// The range of `image`'s numbers, `None` when it has none.
    pub fn of(image: &AovImage) -> Option<Range> {
        let Key::Scale { whole, signed, .. } = image.key else {
            return None;
        };
        let numbers = image.values.iter().filter_map(|v| match v {
            Value::Number(x) if x.is_finite() => Some(*x),
            _ => None,
        });
        let (lo, hi) = numbers.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
        let linear = Range {
            lo,
            hi,
            stepped: false,
            signed,
            log: false,
        };
        if lo > hi {
            return Some(Range {
                lo: 0.0,
                hi: 1.0,
                ..linear
            });
        }
        if signed {
            let (lo, hi) = (lo.min(-f64::MIN_POSITIVE), hi.max(f64::MIN_POSITIVE));
            return Some(Range { lo, hi, ..linear });
        }
        Some(Range {
            stepped: whole && hi - lo < MAX_STEPS,
            log: !whole && lo > 0.0 && hi / lo > LOG_SPAN,
            ..linear
        })
    }

    /// Where `x` falls along the bar, 0 to 1. A signed range puts zero in
    /// the middle, each side scaled to its own extreme (the two sides of the
    /// discriminant differ by orders of magnitude).
    fn t(&self, x: f64) -> f64 {
        if self.signed {
            return if x < 0.0 {
                0.5 * (1.0 - x / self.lo)
            } else {
                0.5 + 0.5 * x / self.hi
            }
            .clamp(0.0, 1.0);
        }
        if self.log {
            return ((x / self.lo).ln() / (self.hi / self.lo).ln()).clamp(0.0, 1.0);
        }
        if self.hi > self.lo {
            ((x - self.lo) / (self.hi - self.lo)).clamp(0.0, 1.0)
        } else {
            0.5
        }
    }

    /// The value at `t` along the bar: the inverse of [`Range::t`].
    fn value_at(&self, t: f64) -> f64 {
        if self.signed {
            if t < 0.5 {
                self.lo * (1.0 - 2.0 * t)
            } else {
                self.hi * (2.0 * t - 1.0)
            }
        } else if self.log {
            self.lo * (self.hi / self.lo).powf(t)
        } else {
            self.lo + (self.hi - self.lo) * t
        }
    }

    /// The color of `x`. A signed value's sign shows at once: the diverging
    /// map skips its palest middle, so the colors jump at zero.
    pub fn color(&self, x: f64) -> Rgb {
        let c = if self.signed {
            let t = self.t(x);
            let gapped = match t {
                t if t < 0.5 => 0.84 * t,
                t if t > 0.5 => 1.0 - 0.84 * (1.0 - t),
                _ => 0.5,
            };
            colorous::RED_BLUE.eval_continuous(gapped)
        } else if self.stepped {
            let n = (self.hi - self.lo) as usize + 1;
            colorous::VIRIDIS.eval_rational((x - self.lo).round() as usize, n)
        } else {
            colorous::VIRIDIS.eval_continuous(self.t(x))
        };
        [c.r, c.g, c.b]
    }

    /// Round values to label the bar with, about `count` of them.
    fn ticks(&self, count: usize) -> Vec<f64> {
        if self.log {
            return log_ticks(self.lo, self.hi, count);
        }
        if !self.signed {
            return nice_ticks(self.lo, self.hi, count);
        }
        let half = (count / 2).max(1);
        let mut out = nice_ticks(self.lo, 0.0, half);
        out.extend(
            nice_ticks(0.0, self.hi, half)
                .into_iter()
                .filter(|&v| v > 0.0),
        );
        out
    }
}

/// The colors of `aov`'s `n` categories: meaningful ones where the categories
/// have a meaning (lit is yellow, shadow dark), else the Okabe–Ito palette in
/// turn (repeating after eight).
pub fn category_colors(aov: Aov, n: usize) -> Vec<Rgb> {
    const DARK: Rgb = [64, 64, 64];
    match aov {
        Aov::Shadow(Some(_)) => vec![[240, 228, 66], [230, 159, 0], DARK, [0, 114, 178]],
        Aov::Shadow(None) => (0..n)
            .map(|mask| match mask {
                0 => DARK,
                m if m + 1 == n => [240, 228, 66],
                m => CATEGORIES[[0, 1, 2, 4, 5, 6][(m - 1) % 6]],
            })
            .collect(),
        Aov::Tir => vec![[225, 225, 225], [213, 94, 0]],
        _ => (0..n).map(|i| CATEGORIES[i % CATEGORIES.len()]).collect(),
    }
}

/// The image's pixels as 8-bit RGB, rows top first.
pub fn pixels(image: &AovImage) -> Vec<u8> {
    let range = Range::of(image);
    let categories = match &image.key {
        Key::Categories(names) => category_colors(image.aov, names.len()),
        _ => Vec::new(),
    };
    let mut out = Vec::with_capacity(image.values.len() * 3);
    for (i, value) in image.values.iter().enumerate() {
        let (x, y) = (i as u32 % image.width, i as u32 / image.width);
        let rgb = match (*value, &image.key) {
            (Value::Color(n), Key::Normals) => {
                let m = (n + 1.0) / 2.0 * 255.0;
                [m.x, m.y, m.z].map(|v| v.round().clamp(0.0, 255.0) as u8)
            }
            (Value::Color(c), _) => rgb8(c),
            (Value::Number(v), _) => range.map_or(palette::INK, |r| r.color(v)),
            (Value::Category(k), _) => categories.get(k as usize).copied().unwrap_or(palette::INK),
            (Value::Undefined, _) => UNDEFINED[((x / 4 + y / 4) % 2) as usize],
        };
        out.extend_from_slice(&rgb);
    }
    out
}

/// The image alone, pixel for pixel.
pub fn bare(image: &AovImage) -> Option<Figure> {
    let mut fig = Figure::page(image.width, image.height)?;
    fig.image(0, 0, image.width, &pixels(image));
    Some(fig)
}

/// The image with its key in a strip below; `caption` says where it came from
/// (scene, size, settings).
pub fn draw(image: &AovImage, caption: &str) -> Option<Figure> {
    let width = image.width.max(MIN_WIDTH);
    let strip = Strip::new(image, caption, width);
    let mut fig = Figure::page(width, image.height + strip.height())?;
    fig.image((width - image.width) / 2, 0, image.width, &pixels(image));
    strip.draw(&mut fig, image, f64::from(image.height));
    Some(fig)
}

/// A swatch in a key: a color, or the checkerboard of "no value".
#[derive(Clone, Copy, Debug, PartialEq)]
enum Swatch {
    Solid(Rgb),
    Undefined,
}

/// The key strip under an image.
struct Strip {
    lines: Vec<String>,
    range: Option<Range>,
    /// Swatches with their text, laid out in rows: `(swatch, text, x, row)`.
    entries: Vec<(Swatch, String, f64, usize)>,
    rows: usize,
}

const TEXT: f32 = 14.0;
const SMALL: f32 = 13.0;
const MARGIN: f64 = 24.0;
const LINE: f64 = 20.0;
const BAR: f64 = 22.0;

impl Strip {
    fn new(image: &AovImage, caption: &str, width: u32) -> Self {
        let range = Range::of(image);
        let mut unnamed = 0;
        let mut entries: Vec<(Swatch, String)> = match &image.key {
            Key::Categories(names) => {
                let colors = category_colors(image.aov, names.len());
                let (named, left) = named_categories(image, names.len());
                unnamed = left;
                names
                    .iter()
                    .zip(colors)
                    .zip(named)
                    .filter(|(_, named)| *named)
                    .map(|((n, c), _)| (Swatch::Solid(c), n.clone()))
                    .collect()
            }
            Key::Normals => [
                ([255, 128, 128], "+x"),
                ([0, 128, 128], "−x"),
                ([128, 255, 128], "+y"),
                ([128, 0, 128], "−y"),
                ([128, 128, 255], "+z"),
                ([128, 128, 0], "−z"),
            ]
            .map(|(c, t)| (Swatch::Solid(c), t.to_owned()))
            .to_vec(),
            Key::Colors | Key::Scale { .. } => Vec::new(),
        };
        if image.values.contains(&Value::Undefined) {
            entries.push((Swatch::Undefined, image.undefined.to_owned()));
        }
        let (laid, rows) = flow(entries, f64::from(width) - 2.0 * MARGIN);
        let wrap = |t: &str| Figure::wrap(t, SMALL, width as f32 - 2.0 * MARGIN as f32);
        let mut lines = vec![format!("{}: {}", image.name, image.title)];
        lines.extend(wrap(caption));
        if !image.note.is_empty() {
            lines.extend(wrap(image.note));
        }
        if unnamed > 0 {
            lines.extend(wrap(&format!(
                "The key names the {MOST_NAMED} seen most; {unnamed} more are seen, and the colors repeat (`raytree trace --pixel X,Y` names any one)."
            )));
        }
        Strip {
            lines,
            range,
            entries: laid,
            rows,
        }
    }

    fn height(&self) -> u32 {
        let bar = if self.range.is_some() {
            BAR + 2.5 * LINE
        } else {
            0.0
        };
        (16.0 + LINE * self.lines.len() as f64 + bar + LINE * self.rows as f64 + 14.0) as u32
    }

    fn draw(&self, fig: &mut Figure, image: &AovImage, top: f64) {
        let width = f64::from(fig.size().0);
        let mut y = top + 12.0;
        for (k, line) in self.lines.iter().enumerate() {
            y += LINE;
            let (size, color) = if k == 0 {
                (TEXT + 1.0, palette::INK)
            } else {
                (SMALL, [90, 90, 90])
            };
            let text = fit(line, size, width - 2.0 * MARGIN);
            fig.text_px(
                DVec2::new(MARGIN, y),
                &text,
                size,
                color,
                Anchor::Left,
                false,
            );
        }
        y += 10.0;
        if let (Some(range), Key::Scale { unit, .. }) = (self.range, &image.key) {
            draw_bar(fig, &range, unit, (MARGIN, width - MARGIN), y);
            y += BAR + 2.5 * LINE;
        }
        for (swatch, text, x, row) in &self.entries {
            let at = DVec2::new(MARGIN + x, y + LINE * *row as f64);
            draw_swatch(fig, *swatch, at);
            fig.text_px(
                at + DVec2::new(20.0, 12.0),
                text,
                SMALL,
                palette::INK,
                Anchor::Left,
                false,
            );
        }
    }
}

/// Which of `n` categories occur in the image: the key lists only those.
/// The pixels of each category, of `n`.
fn category_pixels(image: &AovImage, n: usize) -> Vec<usize> {
    let mut count = vec![0; n];
    for v in &image.values {
        if let Value::Category(k) = v
            && let Some(c) = count.get_mut(*k as usize)
        {
            *c += 1;
        }
    }
    count
}

/// The most categories a key names. Past it (the objects of a big scene:
/// the SPD's tetra has 4,096 polygons) a key of every one ran to 14,902
/// pixels high, and its 8 colors repeat anyway; it names those seen most.
const MOST_NAMED: usize = 16;

/// Which categories the key names: those seen, or of more than
/// [`MOST_NAMED`], the ones covering the most pixels (in their order); and
/// how many seen are left unnamed.
fn named_categories(image: &AovImage, n: usize) -> (Vec<bool>, usize) {
    let count = category_pixels(image, n);
    let mut seen: Vec<usize> = (0..n).filter(|&k| count[k] > 0).collect();
    let left = seen.len().saturating_sub(MOST_NAMED);
    if left > 0 {
        seen.sort_by_key(|&k| std::cmp::Reverse(count[k]));
        seen.truncate(MOST_NAMED);
    }
    let mut named = vec![false; n];
    for k in seen {
        named[k] = true;
    }
    (named, left)
}

/// Lays swatch entries out left to right, wrapping within `width`: each
/// entry's x and row, and the number of rows.
fn flow(entries: Vec<(Swatch, String)>, width: f64) -> (Vec<(Swatch, String, f64, usize)>, usize) {
    let (mut x, mut row) = (0.0, 0);
    let mut out = Vec::new();
    for (swatch, text) in entries {
        let w = 20.0 + f64::from(Figure::text_width(&text, SMALL)) + 22.0;
        if x > 0.0 && x + w > width {
            (x, row) = (0.0, row + 1);
        }
        out.push((swatch, text, x, row));
        x += w;
    }
    let rows = if out.is_empty() { 0 } else { row + 1 };
    (out, rows)
}

fn draw_swatch(fig: &mut Figure, swatch: Swatch, at: DVec2) {
    let outline = Some(Pen::solid([120, 120, 120], 1.0));
    match swatch {
        Swatch::Solid(c) => fig.rect_px(at, at + 14.0, Some((c, 255)), outline),
        Swatch::Undefined => {
            for (k, corner) in [(0.0, 0.0), (7.0, 0.0), (0.0, 7.0), (7.0, 7.0)]
                .into_iter()
                .enumerate()
            {
                let c = DVec2::new(corner.0, corner.1);
                let gray = UNDEFINED[[0, 1, 1, 0][k]];
                fig.rect_px(at + c, at + c + 7.0, Some((gray, 255)), None);
            }
            fig.rect_px(at, at + 14.0, None, outline);
        }
    }
}

/// The color bar from `x0` to `x1` at height `y`, with ticks, their values and
/// the unit under them.
pub fn draw_bar(fig: &mut Figure, range: &Range, unit: &str, (x0, x1): (f64, f64), y: f64) {
    let w = x1 - x0;
    let at = |v: f64| x0 + range.t(v) * w;
    let ticks: Vec<(f64, f64)> = if range.stepped {
        // A block per value, its label centered in it.
        let n = (range.hi - range.lo) as usize + 1;
        let block = w / n as f64;
        for i in 0..n {
            let c = range.color(range.lo + i as f64);
            let left = x0 + block * i as f64;
            fig.rect_px(
                DVec2::new(left, y),
                DVec2::new(left + block, y + BAR),
                Some((c, 255)),
                None,
            );
        }
        let every = (40.0 / block).ceil().max(1.0) as usize;
        (0..n)
            .filter(|i| i % every == 0 || *i == n - 1)
            .map(|i| (x0 + block * (i as f64 + 0.5), range.lo + i as f64))
            .collect()
    } else {
        for i in 0..w.ceil() as usize {
            let v = range.value_at((i as f64 + 0.5) / w);
            let left = x0 + i as f64;
            fig.rect_px(
                DVec2::new(left, y),
                DVec2::new(left + 1.0, y + BAR),
                Some((range.color(v), 255)),
                None,
            );
        }
        range
            .ticks((w / 90.0).max(2.0) as usize)
            .into_iter()
            .map(|v| (at(v), v))
            .collect()
    };
    fig.rect_px(
        DVec2::new(x0, y),
        DVec2::new(x1, y + BAR),
        None,
        Some(Pen::solid([120, 120, 120], 1.0)),
    );
    for (x, v) in ticks {
        fig.line_px(
            DVec2::new(x, y + BAR),
            DVec2::new(x, y + BAR + 5.0),
            Pen::solid(palette::INK, 1.0),
        );
        let label = DVec2::new(x.clamp(x0 + 12.0, x1 - 12.0), y + BAR + 19.0);
        fig.text_px(label, &num(v), SMALL, palette::INK, Anchor::Center, false);
    }
    fig.text_px(
        DVec2::new(x0, y + BAR + 19.0 + LINE),
        &bar_caption(range, unit),
        SMALL,
        [90, 90, 90],
        Anchor::Left,
        false,
    );
}

/// The line under a color bar: what it measures, its scale and its range,
/// written at [`BAR_TEXT`]; a figure narrower than the line must widen to it.
pub fn bar_caption(range: &Range, unit: &str) -> String {
    let scale = if range.log { " · logarithmic" } else { "" };
    format!(
        "{unit}{scale} · range {} to {}",
        num(range.lo),
        num(range.hi)
    )
}

/// The size of the text under a color bar.
pub const BAR_TEXT: f32 = SMALL;

/// About `count` round values from `lo` to `hi`: steps of 1, 2 or 5 times a
/// power of ten.
pub fn nice_ticks(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    if hi <= lo || !(lo.is_finite() && hi.is_finite()) {
        return vec![lo];
    }
    let raw = (hi - lo) / count.max(1) as f64;
    let power = 10f64.powf(raw.log10().floor());
    // The round step nearest the raw one, on a log scale.
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .min_by(|a, b| (a / raw).ln().abs().total_cmp(&(b / raw).ln().abs()))
        .unwrap_or(power);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// Round values from `lo` to `hi` (both > 0) on a logarithmic axis: 1, 2
/// and 5 times each power of ten, thinned to about `count`.
fn log_ticks(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    let decades = (lo.log10().floor() as i32)..=(hi.log10().ceil() as i32);
    let all = |ms: &[f64]| -> Vec<f64> {
        decades
            .clone()
            .flat_map(|k| ms.iter().map(move |m| m * 10f64.powi(k)))
            .filter(|v| (lo..=hi).contains(v))
            .collect()
    };
    let fine = all(&[1.0, 2.0, 5.0]);
    if fine.len() <= count.max(2) {
        fine
    } else {
        all(&[1.0])
    }
}

/// `text` cut with an ellipsis to fit `width` pixels.
fn fit(text: &str, size: f32, width: f64) -> String {
    if f64::from(Figure::text_width(text, size)) <= width {
        return text.to_owned();
    }
    let mut out: String = text.to_owned();
    while !out.is_empty() && f64::from(Figure::text_width(&format!("{out}…"), size)) > width {
        out.pop();
    }
    format!("{out}…")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_and_inside_the_range() {
        assert_eq!(nice_ticks(0.0, 10.0, 5), [0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
        assert_eq!(nice_ticks(3.2, 9.9, 3), [4.0, 6.0, 8.0]);
        assert_eq!(nice_ticks(2.0, 2.0, 4), [2.0]);
        assert_eq!(log_ticks(3.9, 5321.0, 4), [10.0, 100.0, 1000.0]);
        assert_eq!(log_ticks(3.9, 60.0, 8), [5.0, 10.0, 20.0, 50.0]);
    }

    #[test]
    fn a_diverging_range_is_centered_on_zero() {
        let r = Range {
            lo: -400.0,
            hi: 4.0,
            stepped: false,
            signed: true,
            log: false,
        };
        assert_eq!(
            (r.t(-400.0), r.t(0.0), r.t(4.0), r.t(2.0)),
            (0.0, 0.5, 1.0, 0.75)
        );
        assert_eq!(r.value_at(0.25), -200.0);
        // Red below zero, blue above.
        let (below, above) = (r.color(-1e-9), r.color(1e-9));
        assert!(
            below[0] > below[2] && above[2] > above[0],
            "{below:?} {above:?}"
        );
    }
}
