//! The speed-against-accuracy chart: time against error on log axes, with the
//! Pareto front (no other setting is both faster and more accurate) and the
//! defaults marked, from the points [`crate::trace::sweep`] measured. Drawn with
//! the project's figure toolkit ([`crate::figure::canvas`]).

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::labels::{Label, Placed, PxRect, place, text_box};
use crate::figure::pen::{Pen, palette};
use crate::methods::Offset;
use crate::trace::sweep::Point;

/// Indices of the points on the Pareto front (no other point is at least as fast
/// and as accurate and better in one), by increasing time.
pub fn pareto(points: &[(f64, f64)]) -> Vec<usize> {
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| {
            let (t, e) = points[i];
            !points
                .iter()
                .any(|&(t2, e2)| t2 <= t && e2 <= e && (t2 < t || e2 < e))
        })
        .collect();
    front.sort_by(|&a, &b| points[a].0.total_cmp(&points[b].0));
    front
}

/// The CSV of every figure, one row per point.
pub fn csv(points: &[Point]) -> String {
    let mut out = String::from(
        "label,default,spp,max_depth,cutoff,sphere,offset,median_seconds,rmse_linear,share_off_by_more_than_1_in_8bit,tests_per_pixel\n",
    );
    for p in points {
        let s = &p.settings;
        let offset = match s.offset {
            Offset::None => "none".to_owned(),
            Offset::Robust => "robust".to_owned(),
            Offset::Epsilon(e) => format!("epsilon={e}"),
        };
        // Labels may hold commas: quoted, with quotes doubled (RFC 4180).
        let label = format!("\"{}\"", p.label.replace('"', "\"\""));
        let sphere = format!("{:?}", s.sphere).to_lowercase();
        let tests = p.tests.map_or(String::new(), |t| t.to_string());
        out.push_str(&format!(
            "{label},{},{},{},{},{sphere},{offset},{},{},{},{tests}\n",
            p.default, s.spp, s.max_depth, s.cutoff, p.seconds, p.rmse, p.off
        ));
    }
    out
}

/// Whether the chart's cost axis is counted tests (every point has them) or
/// wall time.
fn counted(points: &[Point]) -> bool {
    !points.is_empty() && points.iter().all(|p| p.tests.is_some())
}

/// A point's cost: its tests per pixel when counted, else its time.
fn cost(p: &Point, counted: bool) -> f64 {
    if counted {
        p.tests.unwrap_or(f64::NAN)
    } else {
        p.seconds
    }
}

/// The chart: cost (x, log: time, or tests per pixel when counted) against
/// RMSE (y, log).
pub fn draw(points: &[Point], title: &str, width: u32, height: u32) -> Option<Figure> {
    draw_with_labels(points, title, width, height).map(|(fig, _)| fig)
}

/// [`draw`], also returning where each point's label went (for the tests).
pub fn draw_with_labels(
    points: &[Point],
    title: &str,
    width: u32,
    height: u32,
) -> Option<(Figure, Vec<Placed>)> {
    let mut fig = Figure::new(width, height, 44.0, 12.0)?;
    let xy = log_positions(points);
    let lo = xy
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
    let hi = xy
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
    // Leave room on the left and below for the axes' labels.
    let span = (hi - lo).max(DVec2::splat(0.3));
    fig.fit(
        lo - span * DVec2::new(0.22, 0.16),
        hi + span * DVec2::new(0.08, 0.1),
        0.0,
    );
    let counted = counted(points);
    draw_grid(&mut fig, counted);
    let front = pareto(
        &points
            .iter()
            .map(|p| (cost(p, counted), p.rmse))
            .collect::<Vec<_>>(),
    );
    for w in front.windows(2) {
        fig.line(xy[w[0]], xy[w[1]], Pen::dashed(palette::REFLECTED, 2.0));
    }
    let x_title = if counted {
        "intersection tests per pixel (boxes and primitives, counted), log scale →"
    } else {
        "wall time (median of the runs), log scale →"
    };
    let mut blocked = draw_axis_titles(&mut fig, x_title);
    blocked.push(draw_legend(&mut fig, &xy, counted));
    let placed = draw_points(&mut fig, points, &xy, &front, &blocked);
    fig.frame_border();
    let caption = format!(
        "{title} · each setting's {} against its error; the Pareto front joins those nothing beats on both",
        if counted { "cost" } else { "time" }
    );
    fig.caption(&Figure::wrap(&caption, 15.0, fig.frame().width()), 15.0);
    Some((fig, placed))
}

/// Each point at (log₁₀ seconds, log₁₀ RMSE); an RMSE of 0 sits at half the
/// smallest nonzero one, so it still has a place on a log axis.
fn log_positions(points: &[Point]) -> Vec<DVec2> {
    let counted = counted(points);
    let floor = points
        .iter()
        .map(|p| p.rmse)
        .filter(|&e| e > 0.0)
        .fold(f64::INFINITY, f64::min)
        .min(1.0)
        / 2.0;
    points
        .iter()
        .map(|p| {
            DVec2::new(
                cost(p, counted).max(1e-6).log10(),
                p.rmse.max(floor).log10(),
            )
        })
        .collect()
}

/// Grid lines at every power of ten, with their values (seconds, or tests
/// when `counted`).
fn draw_grid(fig: &mut Figure, counted: bool) {
    let (vlo, vhi) = fig.visible();
    let grid = Pen::solid([225, 225, 225], 1.0);
    for k in (vlo.x.ceil() as i32)..=(vhi.x.floor() as i32) {
        let x = f64::from(k);
        fig.line(DVec2::new(x, vlo.y), DVec2::new(x, vhi.y), grid);
        fig.label(
            DVec2::new(x, vlo.y),
            DVec2::new(0.0, -6.0),
            &if counted {
                tests_label(x)
            } else {
                seconds_label(x)
            },
            13.0,
            palette::INK,
            Anchor::Center,
        );
    }
    for k in (vlo.y.ceil() as i32)..=(vhi.y.floor() as i32) {
        let y = f64::from(k);
        fig.line(DVec2::new(vlo.x, y), DVec2::new(vhi.x, y), grid);
        fig.label(
            DVec2::new(vlo.x, y),
            DVec2::new(6.0, -4.0),
            &format!("1e{k}"),
            13.0,
            palette::INK,
            Anchor::Left,
        );
    }
}

/// The radius of the ring round the defaults' dot.
const RING: f64 = 7.5;

/// Each point as a dot, then the labels, placed by [`crate::figure::labels`]
/// as the diagrams' are: touching their dot where there is room, else with a
/// leader line, never over another label, a dot, the legend or an axis
/// title. The defaults are ringed, under every dot, and their own dot is no
/// bigger than the others' and drawn first: a setting that lands on the
/// defaults (most change nothing measurable) shows on top of it. The
/// defaults are placed first, so their label sits at their dot.
fn draw_points(
    fig: &mut Figure,
    points: &[Point],
    xy: &[DVec2],
    front: &[usize],
    blocked: &[PxRect],
) -> Vec<Placed> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_by_key(|&i| !points[i].default);
    let ring = RING / fig.scale();
    for &i in order.iter().filter(|&&i| points[i].default) {
        fig.ellipse(
            xy[i],
            [DVec2::X * ring, DVec2::Y * ring],
            None,
            Some(Pen::solid(palette::REFRACTED, 2.0)),
        );
    }
    for &i in &order {
        let (p, at) = (&points[i], xy[i]);
        let color = if p.default {
            palette::REFRACTED
        } else if front.contains(&i) {
            palette::REFLECTED
        } else {
            palette::PRIMARY
        };
        fig.dot(at, 5.0, color, Some(palette::INK));
    }
    let px: Vec<DVec2> = xy.iter().map(|&p| fig.to_px(p)).collect();
    let mut avoid: Vec<PxRect> = px.iter().map(|&c| PxRect::around(c, RING)).collect();
    avoid.extend_from_slice(blocked);
    let lines: Vec<[DVec2; 2]> = front.windows(2).map(|w| [px[w[0]], px[w[1]]]).collect();
    let labels = order.iter().map(|&i| {
        let clearance = if points[i].default { RING + 1.0 } else { 5.0 };
        Label::at_point(
            points[i].label.clone(),
            13.0,
            palette::INK,
            px[i],
            clearance,
        )
    });
    let frame = PxRect::frame_of(fig);
    let placed = place(labels.collect(), &avoid, &lines, frame);
    for placed in &placed {
        placed.draw(fig, 1.0);
    }
    placed
}

/// The axis titles, along the bottom and up the left edge of the frame; the
/// boxes they take, which the points' labels keep clear of.
fn draw_axis_titles(fig: &mut Figure, x_title: &str) -> Vec<PxRect> {
    let f = fig.frame();
    let size = 14.0;
    let y_title = "↑ RMSE against the converged reference (linear RGB), log scale";
    let x_at = DVec2::new(f64::from(f.right()) - 10.0, f64::from(f.bottom()) - 26.0);
    let y_at = DVec2::new(f64::from(f.left()) + 8.0, f64::from(f.top()) + 20.0);
    let mut boxes = Vec::new();
    for (at, text, anchor) in [
        (x_at, x_title, Anchor::Right),
        (y_at, y_title, Anchor::Left),
    ] {
        let w = f64::from(Figure::text_width(text, size));
        let left = if anchor == Anchor::Right {
            at.x - w
        } else {
            at.x
        };
        boxes.push(text_box(text, size, DVec2::new(left, at.y), true));
        fig.text_px(at, text, size, palette::INK, anchor, false);
    }
    boxes
}

/// The legend, in the corner with the fewest points near it; its box.
fn draw_legend(fig: &mut Figure, xy: &[DVec2], counted: bool) -> PxRect {
    let front = if counted {
        "Pareto front: nothing is both cheaper and more accurate"
    } else {
        "Pareto front: nothing is both faster and more accurate"
    };
    let legend = [
        (Pen::solid(palette::REFRACTED, 6.0), "the defaults"),
        (Pen::solid(palette::REFLECTED, 6.0), "on the Pareto front"),
        (Pen::dashed(palette::REFLECTED, 2.0), front),
        (Pen::solid(palette::PRIMARY, 6.0), "other settings"),
    ];
    let boxes = fig.legend_boxes(&legend, 13.0);
    let marks: Vec<DVec2> = xy.iter().map(|&p| fig.to_px(p)).collect();
    let covered = |(o, wh): (DVec2, DVec2)| {
        marks
            .iter()
            .filter(|p| p.cmpge(o - 60.0).all() && p.cmple(o + wh + 10.0).all())
            .count()
    };
    let corner = (0..4).min_by_key(|&c| (covered(boxes[c]), c)).unwrap_or(0);
    fig.legend(&legend, 13.0, corner);
    let (origin, wh) = boxes[corner];
    PxRect {
        min: origin,
        max: origin + wh,
    }
}

fn seconds_label(log10: f64) -> String {
    let s = 10f64.powf(log10);
    if s < 1e-3 {
        format!("{} µs", (s * 1e6).round())
    } else if s < 1.0 {
        format!("{} ms", (s * 1e3).round())
    } else {
        format!("{} s", s.round())
    }
}

/// A power of ten of tests: `1`, `10`, `1,000`, `1e6`.
fn tests_label(log10: f64) -> String {
    let n = 10f64.powf(log10).round();
    if n < 1e6 {
        crate::views::numbers::thousands(n as u64)
    } else {
        format!("1e{}", log10.round())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pareto_front_keeps_only_undominated_points() {
        // (time, error): b is dominated by a (slower and worse); d by c.
        let points = [(1.0, 0.5), (2.0, 0.6), (3.0, 0.1), (4.0, 0.2), (0.5, 0.9)];
        assert_eq!(pareto(&points), vec![4, 0, 2]);
    }

    #[test]
    fn tests_axis_labels_read_as_counts() {
        assert_eq!(tests_label(0.0), "1");
        assert_eq!(tests_label(3.0), "1,000");
        assert_eq!(tests_label(5.0), "100,000");
        assert_eq!(tests_label(7.0), "1e7");
    }
}
