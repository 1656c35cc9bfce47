//! The efficiency slide's comparison as a table and a chart, from the figures
//! [`crate::trace::structure_sweep`] measured (or read back from its CSV):
//! for each scene a group of five bars, the tests a ray made above and the
//! trace time below, both on log scales since the structures differ by orders
//! of magnitude; or, for the grid sweep, steps and primitive tests per ray
//! against the grid's resolution, where too coarse a grid tests many
//! primitives per cell and too fine a one walks many empty cells.

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::{Pen, Rgb, palette};
use crate::methods::{Accel, Level};
use crate::trace::structure_sweep::{Comparison, Mode, Row, STRUCTURES};
use crate::views::numbers::num;

/// One color per structure (Okabe–Ito, as every figure's palette).
fn color(a: Accel) -> Rgb {
    match a {
        Accel::None => palette::SHADOW_BLOCKED,
        Accel::Bvh => palette::PRIMARY,
        Accel::Grid => palette::REFLECTED,
        Accel::Octree => palette::SHADOW_REACHES,
        _ => palette::REFRACTED,
    }
}

/// Seconds for reading: `0.52 s`, `3.1 ms`.
fn seconds(s: f64) -> String {
    if s < 0.1 {
        format!("{} ms", num(s * 1e3))
    } else {
        format!("{} s", num(s))
    }
}

/// The figures as a Markdown table, with the best of each scene in bold.
pub fn table(c: &Comparison) -> String {
    match c.mode {
        Mode::Structures => structures_table(c),
        Mode::GridSweep => sweep_table(c),
    }
}

fn structures_table(c: &Comparison) -> String {
    let mut out = String::from("| scene | objects |");
    let mut rule = String::from("|---|---:|");
    for a in STRUCTURES {
        out.push_str(&format!(" {0} tests/ray | {0} time |", a.name()));
        rule.push_str("---:|---:|");
    }
    out.push('\n');
    out.push_str(&rule);
    out.push('\n');
    for group in c.rows.chunks(STRUCTURES.len()) {
        let fewest = best(group, Row::tests_per_ray);
        let fastest = best(group, Row::trace_seconds);
        out.push_str(&format!("| {} | {} |", group[0].scene, group[0].objects));
        for (k, r) in group.iter().enumerate() {
            out.push_str(&format!(
                " {} | {} |",
                bold(num(r.tests_per_ray()), k == fewest),
                bold(seconds(r.trace_seconds()), k == fastest)
            ));
        }
        out.push('\n');
    }
    out.push_str(&format!(
        "\nTests per ray: traversal steps and primitive tests, counted; time: the trace alone, median of the runs. \
         Bold: each scene's fewest tests and fastest trace. {}\n",
        c.about
    ));
    out
}

fn sweep_table(c: &Comparison) -> String {
    let mut out = String::from(
        "| grid_res | cells | steps/ray | primitives/ray | tests/ray | build | time |\n|---|---|---:|---:|---:|---:|---:|\n",
    );
    let fastest = best(&c.rows, Row::trace_seconds);
    let fewest = best(&c.rows, Row::tests_per_ray);
    for (k, r) in c.rows.iter().enumerate() {
        let res = r.grid_res.map_or("auto".to_owned(), |l| l.to_string());
        let cells = r
            .grid_cells
            .map_or(String::new(), |[x, y, z]| format!("{x}×{y}×{z}"));
        out.push_str(&format!(
            "| {res} | {cells} | {} | {} | {} | {} | {} |\n",
            num(r.steps_per_ray()),
            num(r.primitives_per_ray()),
            bold(num(r.tests_per_ray()), k == fewest),
            seconds(r.build_seconds),
            bold(seconds(r.trace_seconds()), k == fastest)
        ));
    }
    out.push_str(&format!(
        "\n{} ({} objects) through the grid at each resolution (cells along the scene's longest side). Bold: the fewest tests and the fastest trace. {}\n",
        c.rows.first().map_or("", |r| r.scene.as_str()),
        c.rows.first().map_or(0, |r| r.objects),
        c.about
    ));
    out
}

/// The index of the row with the least `f`.
fn best(rows: &[Row], f: fn(&Row) -> f64) -> usize {
    (0..rows.len())
        .min_by(|&a, &b| f(&rows[a]).total_cmp(&f(&rows[b])))
        .unwrap_or(0)
}

fn bold(s: String, yes: bool) -> String {
    if yes { format!("**{s}**") } else { s }
}

/// A log-scaled panel: its box in pixels and the powers of ten it spans.
struct Panel {
    left: f64,
    top: f64,
    right: f64,
    bottom: f64,
    lo: f64,
    hi: f64,
}

impl Panel {
    /// A panel spanning the powers of ten around `values` (positive ones; a
    /// zero sits on the floor).
    fn new(rect: [f64; 4], values: impl Iterator<Item = f64>) -> Self {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.filter(|v| *v > 0.0 && v.is_finite()) {
            lo = lo.min(v.log10());
            hi = hi.max(v.log10());
        }
        if lo > hi {
            (lo, hi) = (0.0, 1.0);
        }
        let (lo, mut hi) = (lo.floor(), hi.ceil());
        if hi <= lo {
            hi = lo + 1.0;
        }
        let [left, top, right, bottom] = rect;
        Panel {
            left,
            top,
            right,
            bottom,
            lo,
            hi,
        }
    }

    /// The pixel row of value `v`; values at or below the floor on it.
    fn y(&self, v: f64) -> f64 {
        let l = if v > 0.0 {
            v.log10().max(self.lo)
        } else {
            self.lo
        };
        self.bottom - (l - self.lo) / (self.hi - self.lo) * (self.bottom - self.top)
    }

    /// Grid lines and their values at 1, 2 and 5 times each power of ten
    /// (only the powers when the panel spans more than two), the title above.
    fn axes(&self, fig: &mut Figure, title: &str, label: fn(f64) -> String) {
        let grid = Pen::solid([225, 225, 225], 1.0);
        let steps: &[f64] = if self.hi - self.lo > 2.0 {
            &[1.0]
        } else {
            &[1.0, 2.0, 5.0]
        };
        for k in (self.lo as i32)..=(self.hi as i32) {
            for &m in steps {
                let v = m * 10f64.powi(k);
                if v.log10() > self.hi + 1e-9 {
                    continue;
                }
                let y = self.y(v);
                fig.line_px(DVec2::new(self.left, y), DVec2::new(self.right, y), grid);
                fig.text_px(
                    DVec2::new(self.left - 6.0, y + 4.0),
                    &label(v),
                    12.0,
                    palette::INK,
                    Anchor::Right,
                    false,
                );
            }
        }
        let border = Pen::solid([150, 150, 150], 1.0);
        fig.line_px(
            DVec2::new(self.left, self.top),
            DVec2::new(self.left, self.bottom),
            border,
        );
        fig.line_px(
            DVec2::new(self.left, self.bottom),
            DVec2::new(self.right, self.bottom),
            border,
        );
        fig.text_px(
            DVec2::new(self.left, self.top - 8.0),
            title,
            14.0,
            palette::INK,
            Anchor::Left,
            false,
        );
    }
}

/// A count for an axis: `0.1`, `20`, `1,000`, `1e6`.
fn count_label(v: f64) -> String {
    if v >= 1e6 {
        format!("1e{}", v.log10().round())
    } else if v >= 1.0 {
        crate::views::numbers::thousands(v.round() as u64)
    } else {
        num(v)
    }
}

/// The chart, `width × height` pixels; `None` when too small to draw.
pub fn draw(c: &Comparison, width: u32, height: u32) -> Option<Figure> {
    if width < 400 || height < 300 {
        return None;
    }
    let mut fig = Figure::page(width, height)?;
    let (w, h) = (f64::from(width), f64::from(height));
    let title = match c.mode {
        Mode::Structures => format!("The efficiency slide's structures, measured · {}", c.about),
        Mode::GridSweep => format!(
            "The uniform grid's resolution, swept on {} · {}",
            c.rows.first().map_or("", |r| r.scene.as_str()),
            c.about
        ),
    };
    let lines = Figure::wrap(&title, 15.0, (w - 40.0) as f32);
    let mut y = 24.0;
    for line in &lines {
        fig.text_px(
            DVec2::new(20.0, y),
            line,
            15.0,
            palette::INK,
            Anchor::Left,
            false,
        );
        y += 20.0;
    }
    let top = y + 30.0;
    match c.mode {
        Mode::Structures => draw_structures(&mut fig, c, [78.0, top, w - 20.0, h - 10.0]),
        Mode::GridSweep => draw_sweep(&mut fig, c, [78.0, top, w - 20.0, h - 10.0]),
    }
    Some(fig)
}

/// A legend in one row: a swatch and its text each, from `(x, y)`.
fn legend_row(fig: &mut Figure, at: DVec2, entries: &[(Rgb, u8, &str)]) {
    let mut x = at.x;
    for &(c, alpha, text) in entries {
        fig.rect_px(
            DVec2::new(x, at.y - 10.0),
            DVec2::new(x + 14.0, at.y + 2.0),
            Some((c, alpha)),
            Some(Pen::solid(c, 1.0)),
        );
        fig.text_px(
            DVec2::new(x + 19.0, at.y),
            text,
            13.0,
            palette::INK,
            Anchor::Left,
            false,
        );
        x += 19.0 + f64::from(Figure::text_width(text, 13.0)) + 18.0;
    }
}

/// A small triangle pointing down at `(x, y)`: the best of a group.
fn mark(fig: &mut Figure, x: f64, y: f64) {
    let pts = [
        DVec2::new(x - 5.0, y - 9.0),
        DVec2::new(x + 5.0, y - 9.0),
        DVec2::new(x, y - 2.0),
    ];
    // The page is unfitted: drawing coordinates are pixels with y flipped.
    fig.polygon(
        &pts.map(|p| fig.from_px(p)),
        Some((palette::INK, 255)),
        None,
    );
}

fn draw_structures(fig: &mut Figure, c: &Comparison, [left, top, right, bottom]: [f64; 4]) {
    structures_legend(fig, left, top, right);
    let [upper, lower] = panel_boxes([left, top, right, bottom], 24.0);
    let tests = Panel::new(
        upper,
        c.rows
            .iter()
            .flat_map(|r| [r.tests_per_ray(), r.primitives_per_ray()]),
    );
    let times = Panel::new(lower, c.rows.iter().map(Row::trace_seconds));
    tests.axes(
        fig,
        "tests per ray (traversal steps + primitive tests), log scale",
        count_label,
    );
    times.axes(
        fig,
        "trace time, seconds (one thread, median of the runs), log scale",
        seconds,
    );
    let groups: Vec<&[Row]> = c.rows.chunks(STRUCTURES.len()).collect();
    let slot = (right - left) / groups.len().max(1) as f64;
    let bar = (slot * 0.8 / STRUCTURES.len() as f64).min(40.0);
    let names: Vec<String> = groups.iter().map(|g| group_name(g)).collect();
    let size = name_size(&names, slot);
    for (g, group) in groups.iter().enumerate() {
        let x0 = left + slot * g as f64 + (slot - bar * group.len() as f64) / 2.0;
        draw_bars(fig, group, x0, bar, [&tests, &times]);
        let centre = left + slot * (g as f64 + 0.5);
        for (panel, dy) in [(&tests, 16.0), (&times, 16.0)] {
            fig.text_px(
                DVec2::new(centre, panel.bottom + dy),
                &names[g],
                size,
                palette::INK,
                Anchor::Center,
                false,
            );
        }
    }
}

/// The structures' colors, the two parts of a bar, and the mark of each
/// scene's best, in a row above the panels.
fn structures_legend(fig: &mut Figure, left: f64, top: f64, right: f64) {
    let mut entries: Vec<(Rgb, u8, &str)> = STRUCTURES
        .iter()
        .map(|&a| (color(a), 255, a.name()))
        .collect();
    entries.push(([120, 120, 120], 90, "pale part: traversal steps"));
    entries.push(([120, 120, 120], 255, "solid part: primitive tests"));
    legend_row(fig, DVec2::new(left, top - 14.0), &entries);
    let tri_x = right - 170.0;
    mark(fig, tri_x, top - 12.0);
    fig.text_px(
        DVec2::new(tri_x + 9.0, top - 14.0),
        "each scene's best",
        13.0,
        palette::INK,
        Anchor::Left,
        false,
    );
}

/// One scene's bars, `bar` pixels wide from `x0`: in the tests panel all
/// its tests pale and its primitive tests solid, in the times panel its
/// trace time; the fewest tests and the fastest trace marked.
fn draw_bars(fig: &mut Figure, group: &[Row], x0: f64, bar: f64, [tests, times]: [&Panel; 2]) {
    let fewest = best(group, Row::tests_per_ray);
    let fastest = best(group, Row::trace_seconds);
    for (k, r) in group.iter().enumerate() {
        let (a, b) = (x0 + bar * k as f64 + 1.0, x0 + bar * (k + 1) as f64 - 1.0);
        let col = color(r.structure);
        let y_all = tests.y(r.tests_per_ray());
        fig.rect_px(
            DVec2::new(a, y_all),
            DVec2::new(b, tests.bottom),
            Some((col, 90)),
            Some(Pen::solid(col, 1.0)),
        );
        let y_prim = tests.y(r.primitives_per_ray());
        fig.rect_px(
            DVec2::new(a, y_prim),
            DVec2::new(b, tests.bottom),
            Some((col, 255)),
            None,
        );
        let y_time = times.y(r.trace_seconds());
        fig.rect_px(
            DVec2::new(a, y_time),
            DVec2::new(b, times.bottom),
            Some((col, 255)),
            None,
        );
        if k == fewest {
            mark(fig, (a + b) / 2.0, y_all);
        }
        if k == fastest {
            mark(fig, (a + b) / 2.0, y_time);
        }
    }
}

/// A group's name under its bars: the scene and its objects.
fn group_name(group: &[Row]) -> String {
    format!("{} ({} objects)", group[0].scene, group[0].objects)
}

/// One size for every scene's name, so none reads as more important: 13
/// pixels, or smaller till the widest fits its slot of `slot` pixels.
pub fn name_size(names: &[String], slot: f64) -> f32 {
    let widest = names
        .iter()
        .map(|n| Figure::text_width(n, 13.0))
        .fold(1.0, f32::max);
    13f32.min(13.0 * (slot as f32 - 4.0) / widest).max(1.0)
}

/// Two panels one above the other in `rect`, with room above each for its
/// title and `below` pixels under each for its labels.
fn panel_boxes([left, top, right, bottom]: [f64; 4], below: f64) -> [[f64; 4]; 2] {
    let title = 34.0;
    let height = (bottom - top - 2.0 * (title + below)) / 2.0;
    let upper = [left, top + title, right, top + title + height];
    let second = upper[3] + below + title;
    [upper, [left, second, right, second + height]]
}

/// The x pixel of grid resolution `n` on a log axis from 1 to 256.
fn res_x(left: f64, right: f64, n: f64) -> f64 {
    left + 12.0 + (n.max(1.0).log2() / 8.0) * (right - left - 24.0)
}

/// Where a row sits on the resolution axis: its asked side, or for auto the
/// cells along its longest side.
fn side(r: &Row) -> f64 {
    match (r.grid_res, r.grid_cells) {
        (Some(Level::Given(n)), _) => f64::from(n),
        (_, Some(cells)) => cells.into_iter().max().unwrap_or(1) as f64,
        _ => 1.0,
    }
}

/// A line of the sweep: its panel, its color, and the figure it draws.
type Series<'a> = (&'a Panel, Rgb, fn(&Row) -> f64);

fn draw_sweep(fig: &mut Figure, c: &Comparison, [left, top, right, bottom]: [f64; 4]) {
    let steps_c = palette::REFLECTED;
    let prims_c = palette::REFRACTED;
    let time_c = palette::PRIMARY;
    legend_row(
        fig,
        DVec2::new(left, top - 14.0),
        &[
            (steps_c, 255, "grid cells walked per ray"),
            (prims_c, 255, "primitive tests per ray"),
            (time_c, 255, "trace time"),
            (palette::INK, 255, "ringed: the auto rule"),
        ],
    );
    let [upper, lower] = panel_boxes([left, top, right, bottom], 44.0);
    let per_ray = Panel::new(
        upper,
        c.rows
            .iter()
            .flat_map(|r| [r.steps_per_ray(), r.primitives_per_ray()]),
    );
    let times = Panel::new(lower, c.rows.iter().map(Row::trace_seconds));
    per_ray.axes(fig, "per ray, log scale: too coarse tests many primitives in each cell; too fine walks many empty cells", count_label);
    times.axes(
        fig,
        "trace time, seconds (one thread, median of the runs), log scale",
        seconds,
    );
    resolution_axis(fig, [&per_ray, &times], left, right, bottom);
    let mut given: Vec<&Row> = c
        .rows
        .iter()
        .filter(|r| matches!(r.grid_res, Some(Level::Given(_))))
        .collect();
    given.sort_by(|a, b| side(a).total_cmp(&side(b)));
    let series: [Series; 3] = [
        (&per_ray, steps_c, Row::steps_per_ray),
        (&per_ray, prims_c, Row::primitives_per_ray),
        (&times, time_c, Row::trace_seconds),
    ];
    for (k, one) in series.into_iter().enumerate() {
        draw_series(fig, c, &given, one, k, [left, right]);
    }
}

/// The resolution's ticks under both panels, at each power of two from 1 to
/// 256, and its name in the bottom right corner.
fn resolution_axis(fig: &mut Figure, panels: [&Panel; 2], left: f64, right: f64, bottom: f64) {
    for panel in panels {
        for k in 0..=8 {
            let n = 2f64.powi(k);
            let x = res_x(left, right, n);
            fig.line_px(
                DVec2::new(x, panel.bottom),
                DVec2::new(x, panel.bottom + 4.0),
                Pen::solid(palette::INK, 1.0),
            );
            fig.text_px(
                DVec2::new(x, panel.bottom + 17.0),
                &format!("{n}"),
                12.0,
                palette::INK,
                Anchor::Center,
                false,
            );
        }
    }
    fig.text_px(
        DVec2::new(right, bottom - 4.0),
        "grid_res: cells along the scene's longest side, log scale →",
        13.0,
        palette::INK,
        Anchor::Right,
        false,
    );
}

/// Series `k` of the sweep: a line through the resolutions `given`, sorted,
/// and a dot at every row, the auto rule's ringed (and labelled once per
/// panel: below the steps' ring, the primitive tests' ring sitting above it,
/// and above the time's).
fn draw_series(
    fig: &mut Figure,
    c: &Comparison,
    given: &[&Row],
    (panel, col, f): Series,
    k: usize,
    [left, right]: [f64; 2],
) {
    let at = |r: &Row| DVec2::new(res_x(left, right, side(r)), panel.y(f(r)));
    for w in given.windows(2) {
        fig.line_px(at(w[0]), at(w[1]), Pen::solid(col, 2.5));
    }
    for r in &c.rows {
        let p = fig.from_px(at(r));
        if r.grid_res != Some(Level::Auto) {
            fig.dot(p, 4.5, col, Some(palette::INK));
            continue;
        }
        fig.dot(p, 9.0, palette::PAPER, Some(palette::INK));
        fig.dot(p, 5.0, col, Some(palette::INK));
        let cells = r
            .grid_cells
            .map_or(String::new(), |[x, y, z]| format!(" {x}×{y}×{z}"));
        let dy = match k {
            0 => 20.0,
            1 => continue,
            _ => -10.0,
        };
        fig.text_px(
            at(r) + DVec2::new(12.0, dy),
            &format!("auto{cells}"),
            12.0,
            palette::INK,
            Anchor::Left,
            false,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_scene_name_has_one_size_and_fits_its_slot() {
        let names: Vec<String> = [
            "whitted (5 objects)",
            "a very long scene name (40,000 objects)",
        ]
        .map(str::to_owned)
        .to_vec();
        let slot = 200.0;
        let size = name_size(&names, slot);
        assert!(size < 13.0, "the long name needs a smaller size");
        // Tolerance: glyph advances scale with the size up to f32 rounding.
        for n in &names {
            assert!(
                f64::from(Figure::text_width(n, size)) <= slot - 4.0 + 1e-3,
                "{n}"
            );
        }
        assert_eq!(name_size(&names[..1], slot), 13.0, "a short name keeps 13");
    }
}
