//! Placing labels so that none collides: each label tries spots around what it
//! names (a point, or the outline of an object) and takes the first that
//! overlaps no other label, no mark that must stay visible (dots, arrowheads,
//! the legend) and stays inside the frame, preferring spots that cross the
//! fewest drawn lines; failing that it moves out with a leader line, and an
//! optional label is left out. A leader never runs through another label,
//! and no label sits on another's leader: a line through text is as
//! unreadable as two texts on top of each other. A label with no such spot
//! at all is left out, and [`place_all`] says which. A greedy pass in
//! priority order, in the manner of the point-feature labelling rules
//! cartographers use (Imhof; Christensen, Marks & Shieber 1995), small
//! enough to read.

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::{Pen, Rgb, palette};

/// An axis-aligned box in pixels (y down).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PxRect {
    /// Top-left.
    pub min: DVec2,
    /// Bottom-right.
    pub max: DVec2,
}

impl PxRect {
    /// The box around `center` of half-size `half`.
    pub fn around(center: DVec2, half: f64) -> Self {
        Self {
            min: center - half,
            max: center + half,
        }
    }

    /// The plot frame of `fig`: the box every label stays inside.
    pub fn frame_of(fig: &Figure) -> Self {
        let f = fig.frame();
        Self {
            min: DVec2::new(f64::from(f.left()), f64::from(f.top())),
            max: DVec2::new(f64::from(f.right()), f64::from(f.bottom())),
        }
    }

    /// Whether the two boxes share any area.
    pub fn overlaps(&self, o: &PxRect) -> bool {
        self.min.x < o.max.x && o.min.x < self.max.x && self.min.y < o.max.y && o.min.y < self.max.y
    }

    /// Whether `inner` lies wholly inside.
    pub fn holds(&self, inner: &PxRect) -> bool {
        inner.min.cmpge(self.min).all() && inner.max.cmple(self.max).all()
    }

    /// The distance from `p` to the box (0 inside).
    pub fn distance(&self, p: DVec2) -> f64 {
        (self.min - p).max(p - self.max).max(DVec2::ZERO).length()
    }

    /// Whether the segment `a → b` crosses the box (Liang–Barsky).
    pub fn crossed_by(&self, a: DVec2, b: DVec2) -> bool {
        crate::figure::clip::clip_segment(a, b, self.min, self.max).is_some()
    }
}

/// What a label names.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    /// A point (pixels), with the radius of the mark drawn there.
    Point {
        /// The point.
        at: DVec2,
        /// The radius of its mark: the label keeps clear of it.
        clearance: f64,
    },
    /// An object: points along its outline (pixels) and a point inside it, so a
    /// label sits just outside the outline, touching it.
    Outline {
        /// Points on the outline, in order of preference.
        points: Vec<DVec2>,
        /// A point inside.
        inside: DVec2,
    },
}

/// A label to place.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The text: a line each, split at `\n` (a name, and its value under it).
    pub text: String,
    /// Font size in pixels.
    pub size: f32,
    /// Its color.
    pub color: Rgb,
    /// What it names.
    pub target: Target,
    /// Drawn as a badge: boxed, on paper.
    pub boxed: bool,
    /// Left out when there is no room (ticks, step numbers), rather than moved out.
    pub optional: bool,
    /// Attributes for its SVG elements ([`Figure::tag`]), empty for none.
    pub tag: String,
}

impl Label {
    /// A plain label naming the point `at` (pixels), kept `clearance` pixels
    /// from it: what most figures place (no badge, never left out, no tag).
    pub fn at_point(text: String, size: f32, color: Rgb, at: DVec2, clearance: f64) -> Label {
        Label {
            text,
            size,
            color,
            target: Target::Point { at, clearance },
            boxed: false,
            optional: false,
            tag: String::new(),
        }
    }
}

/// A placed label.
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// The label.
    pub label: Label,
    /// Its box.
    pub rect: PxRect,
    /// Where its text's baseline starts.
    pub baseline: DVec2,
    /// The point of the target it names (the nearest outline point for an object).
    pub anchor: DVec2,
    /// A line from the box to the anchor, when the label had to move away.
    pub leader: Option<[DVec2; 2]>,
}

/// The gray of a leader line from a moved label to what it names.
const LEADER: Rgb = [120, 120, 120];

impl Placed {
    /// Draws the label where it was placed: its leader line, its box when
    /// boxed, its text; line widths times `k` (a figure's size).
    pub fn draw(&self, fig: &mut Figure, k: f32) {
        fig.tag(&self.label.tag);
        if let Some([a, b]) = self.leader {
            fig.line_px(a, b, Pen::solid(LEADER, 0.9).scaled(k));
        }
        if self.label.boxed {
            fig.rect_px(
                self.rect.min,
                self.rect.max,
                Some((palette::PAPER, 240)),
                Some(Pen::solid(self.label.color, 1.2).scaled(k)),
            );
        }
        for (k, line) in self.label.text.split('\n').enumerate() {
            fig.text_px(
                self.baseline + DVec2::new(0.0, LEADING * f64::from(self.label.size) * k as f64),
                line,
                self.label.size,
                self.label.color,
                Anchor::Left,
                false,
            );
        }
        fig.tag("");
    }
}

/// From one line's baseline to the next, in font sizes.
const LEADING: f64 = 1.2;

/// How far a line's letters reach above its baseline, in font sizes (the
/// label font's capitals and ascenders).
const ASCENT: f64 = 0.95;
/// How far they reach below it (descenders), in font sizes.
const DESCENT: f64 = 0.3;
/// From the baseline down to the middle of a line's box, in font sizes:
/// (ASCENT − DESCENT)/2 = 0.325, as first written rounded; kept so that no
/// label moves.
const MIDDLE: f64 = 0.33;
/// Half a line's box height, in font sizes: (ASCENT + DESCENT)/2 = 0.625,
/// rounded as first written, as [`MIDDLE`] is.
const HALF_HEIGHT: f64 = 0.62;

/// The width of the widest line of `text`, and how far its last baseline
/// lies below its first.
fn extent(text: &str, size: f32) -> (f64, f64) {
    let lines = text.split('\n');
    let w = lines
        .clone()
        .map(|l| Figure::text_width(l, size))
        .fold(0.0, f32::max);
    let below = (lines.count() - 1) as f64 * LEADING * f64::from(size);
    (f64::from(w), below)
}

/// The box a label of `text` takes with its (first) baseline start at `at`.
pub fn text_box(text: &str, size: f32, at: DVec2, boxed: bool) -> PxRect {
    let (w, below) = extent(text, size);
    let s = f64::from(size);
    let pad = if boxed { 4.0 } else { 1.0 };
    PxRect {
        min: DVec2::new(at.x - pad, at.y - ASCENT * s - pad),
        max: DVec2::new(at.x + w + pad, at.y + DESCENT * s + below + pad),
    }
}

/// Places `labels` in order (the first placed first) inside `frame`, clear of
/// `blocked` boxes; `lines` are drawn segments a label would rather not cover.
pub fn place(
    labels: Vec<Label>,
    blocked: &[PxRect],
    lines: &[[DVec2; 2]],
    frame: PxRect,
) -> Vec<Placed> {
    let weighted: Vec<([DVec2; 2], usize)> = lines.iter().map(|&l| (l, 1)).collect();
    place_weighted(labels, blocked, &weighted, frame)
}

/// [`place`] with a weight per line: covering a line of weight 3 costs as
/// much as covering three of weight 1 (a figure's main rays against faint
/// shadow rays).
pub fn place_weighted(
    labels: Vec<Label>,
    blocked: &[PxRect],
    lines: &[([DVec2; 2], usize)],
    frame: PxRect,
) -> Vec<Placed> {
    place_all(labels, blocked, lines, frame).0
}

/// [`place_weighted`], also returning the labels left out: the optional ones
/// that would have needed a leader, and any that found no free spot at all.
pub fn place_all(
    labels: Vec<Label>,
    blocked: &[PxRect],
    lines: &[([DVec2; 2], usize)],
    frame: PxRect,
) -> (Vec<Placed>, Vec<Label>) {
    let mut placed: Vec<Placed> = Vec::new();
    let mut left_out = Vec::new();
    for label in labels {
        // Leaders that cross nothing first; in a crowd where none can, a
        // leader may cross marks and other leaders rather than the label be
        // lost, but never another label.
        let found = best_spot(&label, blocked, lines, frame, &placed, true)
            .or_else(|| best_spot(&label, blocked, lines, frame, &placed, false));
        match found {
            Some(p) if !(p.label.optional && p.leader.is_some()) => placed.push(p),
            _ => left_out.push(label),
        }
    }
    (placed, left_out)
}

/// The cheapest free spot for `label` (covering the fewest weighted lines,
/// nearest first among equals). A spot is free when its box is in the frame,
/// clear of the marks, the labels placed and their leaders, and its own
/// leader crosses no label; with `clean_leaders`, its leader also crosses no
/// mark and no other leader.
fn best_spot(
    label: &Label,
    blocked: &[PxRect],
    lines: &[([DVec2; 2], usize)],
    frame: PxRect,
    placed: &[Placed],
    clean_leaders: bool,
) -> Option<Placed> {
    let free = |r: &PxRect, leader: Option<[DVec2; 2]>| {
        // A leader ends at its anchor's mark: against marks only the part
        // short of it counts.
        let short = leader.map(|[a, z]| [a, z + (a - z).clamp_length_max(10.0)]);
        let crosses = |b: &PxRect| short.is_some_and(|[a, z]| b.crossed_by(a, z));
        let runs_through = |b: &PxRect| leader.is_some_and(|[a, z]| b.crossed_by(a, z));
        let meets = |[a, z]: [DVec2; 2]| short.is_some_and(|[b, y]| segments_cross(a, z, b, y));
        frame.holds(r)
            && !blocked
                .iter()
                .any(|b| b.overlaps(r) || (clean_leaders && crosses(b)))
            && !placed.iter().any(|p| {
                p.rect.overlaps(r)
                    || runs_through(&p.rect)
                    || p.leader.is_some_and(|[a, z]| r.crossed_by(a, z))
                    || (clean_leaders && p.leader.is_some_and(meets))
            })
    };
    let cost = |r: &PxRect| {
        lines
            .iter()
            .filter(|([a, b], _)| r.crossed_by(*a, *b))
            .map(|(_, w)| w)
            .sum::<usize>()
    };
    let mut best: Option<(usize, usize, Placed)> = None;
    for (rank, (baseline, anchor, leader, last_resort)) in spots(label).into_iter().enumerate() {
        let rect = text_box(&label.text, label.size, baseline, label.boxed);
        let leader = leader.map(|l| [l, anchor]);
        if !free(&rect, leader) {
            continue;
        }
        let c = cost(&rect)
            + if leader.is_some() { 3 } else { 0 }
            + if last_resort { LAST_RESORT } else { 0 };
        if best
            .as_ref()
            .is_none_or(|(bc, br, _)| (c, rank) < (*bc, *br))
        {
            let p = Placed {
                label: label.clone(),
                rect,
                baseline,
                anchor,
                leader,
            };
            best = Some((c, rank, p));
        }
        if c == 0 && leader.is_none() {
            break;
        }
    }
    best.map(|(_, _, p)| p)
}

/// What a last-resort spot costs on top of its lines: more than any ordinary
/// spot's, so it is taken only where no ordinary spot is free.
const LAST_RESORT: usize = 1_000_000;

/// A candidate spot: the baseline, the point it names, the leader's start
/// when it stands off, and whether it is a last resort.
type Spot = (DVec2, DVec2, Option<DVec2>, bool);

/// Candidate baselines for a label, nearest first: touching the target, then
/// farther out with a leader from the box's nearest point; each says whether
/// it is a last resort.
fn spots(label: &Label) -> Vec<Spot> {
    let (w, below) = extent(&label.text, label.size);
    let text = TextBox {
        w,
        below,
        s: f64::from(label.size),
    };
    match &label.target {
        Target::Point { at, clearance } => text.around_point(*at, *clearance),
        Target::Outline { points, inside } => text.around_outline(points, *inside),
    }
}

/// A label's text box: its width, its depth below the baseline and its font
/// size, which place it around what it names.
struct TextBox {
    w: f64,
    below: f64,
    s: f64,
}

impl TextBox {
    /// The baseline that puts the text box's center at `c`.
    fn centered(&self, c: DVec2) -> DVec2 {
        DVec2::new(c.x - self.w / 2.0, c.y + MIDDLE * self.s - self.below / 2.0)
    }

    /// The box center that makes the box touch `p` from direction `dir`, `gap` away.
    fn touching(&self, p: DVec2, dir: DVec2, gap: f64) -> DVec2 {
        let half = DVec2::new(
            self.w / 2.0 + 2.0,
            HALF_HEIGHT * self.s + self.below / 2.0 + 2.0,
        );
        // How far along `dir` the box's edge is from its center.
        let reach = (half.x / dir.x.abs().max(1e-9)).min(half.y / dir.y.abs().max(1e-9));
        p + dir * (reach + gap)
    }

    /// The box centered at `c` led to `p`: its spot, the leader from the
    /// box's point nearest `p`.
    fn led(&self, c: DVec2, p: DVec2, last_resort: bool) -> Spot {
        let leader = nearest_on_box(c, self.w, self.s, self.below, p);
        (self.centered(c), p, Some(leader), last_resort)
    }

    /// Around a point: the cartographers' eight positions first (the point at
    /// a corner or the middle of an edge of the label, upper right
    /// preferred), then all round, touching, and farther out in rings a
    /// label's height or more apart, with a leader.
    fn around_point(&self, at: DVec2, clearance: f64) -> Vec<Spot> {
        let (w, below, s) = (self.w, self.below, self.s);
        let g = clearance + 2.0;
        let (top, bottom) = (at.y - g - DESCENT * s - below, at.y + g + ASCENT * s);
        let (right, left, middle) = (at.x + g, at.x - g - w, at.x - w / 2.0);
        let level = at.y + MIDDLE * s - below / 2.0;
        let classic = [
            (right, top),
            (right, bottom),
            (left, top),
            (left, bottom),
            (right, level),
            (left, level),
            (middle, top),
            (middle, bottom),
        ];
        let mut out: Vec<Spot> = classic
            .map(|(x, y)| (DVec2::new(x, y), at, None, false))
            .into();
        let dirs = directions();
        for far in [0.0, 1.5, 3.0, 5.0, 8.0, 12.0] {
            for &d in &dirs {
                let c = self.touching(at, d, clearance + 2.0 + far * s);
                out.push(if far > 0.0 {
                    self.led(c, at, false)
                } else {
                    (self.centered(c), at, None, false)
                });
            }
        }
        out
    }

    /// Around an outline: just outside each of its points, then farther out
    /// with a leader; last, for a small outline in a crowd, every direction
    /// from the point of the outline farthest along it, out to a third of a
    /// figure, so a leader can find a gap between the labels around it.
    fn around_outline(&self, points: &[DVec2], inside: DVec2) -> Vec<Spot> {
        let mut out = Vec::new();
        for far in [0.0, 18.0, 40.0, 80.0, 140.0] {
            for &p in points {
                let d = (p - inside).normalize_or(DVec2::Y);
                let c = self.touching(p, d, 1.0 + far);
                out.push(if far > 0.0 {
                    self.led(c, p, false)
                } else {
                    (self.centered(c), p, None, false)
                });
            }
        }
        let dirs = directions();
        for far in [40.0, 80.0, 140.0, 220.0, 320.0] {
            for &d in &dirs {
                let Some(&p) = points.iter().max_by(|a, b| a.dot(d).total_cmp(&b.dot(d))) else {
                    continue;
                };
                let c = self.touching(p, d, 1.0 + far);
                out.push(self.led(c, p, true));
            }
        }
        out
    }
}

/// Sixteen directions round, from +x, turning up (pixels, y down).
fn directions() -> [DVec2; 16] {
    std::array::from_fn(|k| {
        let a = std::f64::consts::TAU * k as f64 / 16.0;
        DVec2::new(a.cos(), -a.sin())
    })
}

/// Whether segments `a → b` and `c → d` cross (touching ends count).
fn segments_cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    d1 * d2 <= 0.0 && d3 * d4 <= 0.0 && (d1 != 0.0 || d2 != 0.0 || d3 != 0.0 || d4 != 0.0)
}

/// The point of the label box centered at `c` nearest to `p`: where a leader starts.
fn nearest_on_box(c: DVec2, w: f64, s: f64, below: f64, p: DVec2) -> DVec2 {
    let half = DVec2::new(w / 2.0 + 1.0, HALF_HEIGHT * s + below / 2.0 + 1.0);
    p.clamp(c - half, c + half)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rounded middle and half height stay the font metrics' own, within
    /// their rounding: a change to the ascent or descent must change them too.
    #[test]
    fn the_box_middle_and_half_height_follow_the_font_metrics() {
        assert!((MIDDLE - (ASCENT - DESCENT) / 2.0).abs() <= 0.005 + 1e-12);
        assert!((HALF_HEIGHT - (ASCENT + DESCENT) / 2.0).abs() <= 0.005 + 1e-12);
    }

    fn point(text: &str, at: DVec2) -> Label {
        Label::at_point(text.into(), 14.0, [0, 0, 0], at, 4.0)
    }

    #[test]
    fn crowded_labels_never_overlap_and_stay_in_the_frame() {
        let frame = PxRect {
            min: DVec2::ZERO,
            max: DVec2::new(300.0, 200.0),
        };
        // Ten labels on nearly the same point, one near the frame's corner.
        let mut labels: Vec<Label> = (0..10)
            .map(|k| point(&format!("P{k}"), DVec2::new(150.0 + f64::from(k), 100.0)))
            .collect();
        labels.push(point("corner", DVec2::new(2.0, 2.0)));
        let legend = PxRect {
            min: DVec2::new(200.0, 0.0),
            max: DVec2::new(300.0, 60.0),
        };
        let (placed, left_out) = place_all(labels, &[legend], &[], frame);
        // Those touching the point ring it round; the rest lead out between
        // them while there is a way through, and past that are left out
        // (and said to be) rather than drawn over another.
        assert_eq!(placed.len() + left_out.len(), 11, "each placed or named");
        assert!(placed.len() >= 9, "only {} placed", placed.len());
        assert!(placed.iter().any(|p| p.label.text == "corner"));
        for (i, a) in placed.iter().enumerate() {
            assert!(
                frame.holds(&a.rect) && !a.rect.overlaps(&legend),
                "{}",
                a.label.text
            );
            for b in &placed[i + 1..] {
                assert!(
                    !a.rect.overlaps(&b.rect),
                    "{} and {}",
                    a.label.text,
                    b.label.text
                );
            }
            for b in &placed {
                assert!(
                    !a.leader.is_some_and(|[p, q]| b.rect.crossed_by(p, q)) || a == b,
                    "the leader of {} runs through {}",
                    a.label.text,
                    b.label.text
                );
            }
            // Touching its point, or joined to it by a leader.
            let touches = a.rect.distance(a.anchor) <= 4.0 + 2.0 + 2.0;
            assert!(
                touches || a.leader.is_some(),
                "{} floats free",
                a.label.text
            );
        }
    }
}
