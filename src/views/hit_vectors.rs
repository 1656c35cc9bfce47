//! One hit's vectors, enlarged: the incoming direction c, the normal n and
//! the mirror direction v in their plane of incidence, with the equal angles
//! θᵢ and θᵣ; and beside them c split into its part along n, (n·c)·n, and its
//! part across n, c − (n·c)·n, with v made of the same two parts, the one
//! along n flipped. The ray diagram draws these marks a few dozen pixels
//! long beside a whole scene; here the unit vectors span the panel, so the
//! angles and the split can be read. Every vector is the trace's own.

use glam::{DVec2, DVec3};

use crate::figure::canvas::Figure;
use crate::figure::labels::{self, Label, Placed, PxRect, Target};
use crate::figure::pen::{Pen, Rgb, palette};
use crate::tree::ray_tree::HitRecord;
use crate::views::numbers::{degrees, num, vec3};

/// c split at a hit, and v rebuilt from the parts (3D, as the trace has them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parts {
    /// The unit incoming direction c.
    pub c: DVec3,
    /// The unit normal facing the ray, n.
    pub n: DVec3,
    /// `n·c`, negative: the ray arrives against n.
    pub n_dot_c: f64,
    /// `(n·c)·n`: the part of c along n.
    pub along: DVec3,
    /// `c − (n·c)·n`: the part of c across n, in the surface.
    pub across: DVec3,
    /// The trace's mirror direction `v = c − 2(n·c)·n` = across − along.
    pub v: DVec3,
}

/// The parts of `hit`'s incoming direction.
pub fn parts(hit: &HitRecord) -> Parts {
    split(hit.incoming, hit.shading_normal, hit.n_dot_c, hit.mirror)
}

/// The parts of unit `c` at unit normal `n`, with the `n·c` and the mirror
/// direction `v` the tracer computed.
pub fn split(c: DVec3, n: DVec3, n_dot_c: f64, v: DVec3) -> Parts {
    let along = n_dot_c * n;
    Parts {
        c,
        n,
        n_dot_c,
        along,
        across: c - along,
        v,
    }
}

/// The parts in the plane of incidence: x across n (toward where the ray
/// goes), y along n. Returns (c, v) as 2D vectors.
pub fn in_plane(p: &Parts) -> (DVec2, DVec2) {
    let a = p.across.length();
    (DVec2::new(a, p.n_dot_c), DVec2::new(a, -p.n_dot_c))
}

/// Where the right panel's hit point sits, in drawing units (|c| = 1).
const RIGHT: f64 = 3.9;

/// The figure of `hit` (named `name`, e.g. `P1 on 'mirror'`), titled `title`.
pub fn draw(hit: &HitRecord, name: &str, title: &str, width: u32, height: u32) -> Option<Figure> {
    draw_with_labels(hit, name, title, width, height).map(|d| d.figure)
}

/// What [`draw_with_labels`] drew, for tests: where each label went.
pub struct Drawn {
    /// The figure.
    pub figure: Figure,
    /// Every label placed, with its box.
    pub labels: Vec<Placed>,
    /// The labels that found no room.
    pub left_out: Vec<Label>,
    /// The frame (pixels).
    pub frame: PxRect,
}

/// [`draw`], also returning where the labels went: through
/// [`crate::figure::labels`], like a ray diagram's, so none covers another,
/// an arrowhead or the frame's edge.
pub fn draw_with_labels(
    hit: &HitRecord,
    name: &str,
    title: &str,
    width: u32,
    height: u32,
) -> Option<Drawn> {
    let p = parts(hit);
    if p.across.length() < 1e-9 {
        // Head-on: c has no part across n, nothing to split or to angle.
        return None;
    }
    let mut fig = Figure::new(width, height, 64.0, 16.0)?;
    fig.fit(
        DVec2::new(-1.45, -0.55),
        DVec2::new(RIGHT + 1.45, 1.35),
        0.0,
    );
    let (c, v) = in_plane(&p);
    let theta = (-p.n_dot_c).clamp(-1.0, 1.0).acos().to_degrees();
    let mut sketch = Sketch {
        fig,
        arrows: Vec::new(),
        lines: Vec::new(),
    };
    sketch.surfaces();
    let radius = sketch.reflection(c, v);
    sketch.split(c, v);
    let mut requests = hit_labels(&sketch.fig, name, c, v, theta);
    requests.extend(part_labels(&sketch.fig, &p, c, v));
    let frame = PxRect::frame_of(&sketch.fig);
    let (blocked, weighted) = sketch.kept_clear(c, v, radius);
    let (placed, left_out) = labels::place_all(requests, &blocked, &weighted, frame);
    let mut fig = sketch.fig;
    for l in &placed {
        l.draw(&mut fig, 1.0);
    }
    fig.frame_border();
    let caption = format!(
        "{title} · left: c arrives, v = c − 2(n·c)·n leaves, both {} from n · right: c is its part across n plus its part along n; v keeps the first and flips the second",
        degrees(theta)
    );
    fig.caption(&Figure::wrap(&caption, 15.0, fig.frame().width()), 15.0);
    Some(Drawn {
        figure: fig,
        labels: placed,
        left_out,
        frame,
    })
}

/// The size of the figure's names; the parts' values are a little smaller.
const TEXT: f32 = 15.0;

/// The figure as it is drawn, with every arrow and line kept for the labels
/// to keep off.
struct Sketch {
    fig: Figure,
    /// Every arrow drawn: (tail, head).
    arrows: Vec<[DVec2; 2]>,
    /// The surfaces' lines.
    lines: Vec<[DVec2; 2]>,
}

impl Sketch {
    fn arrow(&mut self, a: DVec2, b: DVec2, pen: Pen) {
        self.fig.arrow(a, b, pen);
        self.arrows.push([a, b]);
    }

    /// At both panels' hit points: the surface's tangent line, the inside
    /// shaded below it, and the normal n.
    fn surfaces(&mut self) {
        for center in [DVec2::ZERO, DVec2::new(RIGHT, 0.0)] {
            let (l, r) = (center - DVec2::new(1.3, 0.0), center + DVec2::new(1.3, 0.0));
            self.fig.polygon(
                &[l, r, r - DVec2::new(0.0, 0.4), l - DVec2::new(0.0, 0.4)],
                Some((palette::OBJECT_FILL, 255)),
                None,
            );
            self.fig.line(l, r, Pen::solid(palette::OBJECT, 1.5));
            self.lines.push([l, r]);
            self.arrow(center, center + DVec2::Y, Pen::solid(palette::NORMAL, 2.5));
            self.fig.dot(center, 4.0, palette::INK, None);
        }
    }

    /// Left: c arrives, v leaves, the arcs of their angles from n. Returns
    /// the arcs' radius (pixels).
    fn reflection(&mut self, c: DVec2, v: DVec2) -> f64 {
        self.arrow(-c, DVec2::ZERO, Pen::solid(palette::PRIMARY, 2.5));
        self.arrow(DVec2::ZERO, v, Pen::solid(palette::REFLECTED, 2.5));
        let radius = 0.28 * self.fig.scale();
        let arc = Pen::solid(palette::INK, 1.5);
        self.fig
            .arc(DVec2::ZERO, radius, DVec2::Y, (-c).normalize(), arc);
        self.fig
            .arc(DVec2::ZERO, radius * 0.85, DVec2::Y, v.normalize(), arc);
        radius
    }

    /// Right: c = along + across, head to tail, down to the surface and along
    /// it; v = across − along, along the surface and back up.
    fn split(&mut self, c: DVec2, v: DVec2) {
        let o = DVec2::new(RIGHT, 0.0);
        let (across, along) = (DVec2::new(c.x, 0.0), DVec2::new(0.0, c.y));
        let part = |color| Pen::dashed(color, 2.5);
        let (along_pen, across_pen) = (part(palette::NORMAL), part(palette::SHADOW_REACHES));
        self.arrow(o - c, o, Pen::solid(palette::PRIMARY, 1.5));
        self.arrow(o - c, o - c + along, along_pen);
        self.arrow(o - c + along, o, across_pen);
        self.arrow(o, o + v, Pen::solid(palette::REFLECTED, 1.5));
        self.arrow(o, o + across, across_pen);
        self.arrow(o + across, o + v, along_pen);
    }

    /// What the labels keep off: the arrowheads and the hit points, which
    /// stay visible; and the lines they would rather not cover, the arrows,
    /// the surfaces and the arcs (as chords), crossing an arrow costing more
    /// than a leader: the arrows are the figure.
    fn kept_clear(
        &mut self,
        c: DVec2,
        v: DVec2,
        radius: f64,
    ) -> (Vec<PxRect>, Vec<([DVec2; 2], usize)>) {
        let fig = &self.fig;
        let mut blocked: Vec<PxRect> = (self.arrows.iter())
            .map(|[_, b]| PxRect::around(fig.to_px(*b), 6.0))
            .collect();
        let hits = [DVec2::ZERO, DVec2::new(RIGHT, 0.0)];
        blocked.extend(hits.map(|h| PxRect::around(fig.to_px(h), 5.0)));
        let chords = |to: DVec2, r: f64| {
            let (a0, a1) = (DVec2::Y.to_angle(), to.to_angle());
            (0..6).map(move |k| {
                let at = |k: u32| DVec2::from_angle(a0 + (a1 - a0) * f64::from(k) / 6.0) * r;
                [at(k), at(k + 1)]
            })
        };
        let r = radius / fig.scale();
        self.lines.extend(self.arrows.iter().copied());
        self.lines
            .extend(chords((-c).normalize(), r).chain(chords(v.normalize(), r * 0.85)));
        let weighted = (self.lines.iter())
            .map(|[a, b]| ([fig.to_px(*a), fig.to_px(*b)], 4))
            .collect();
        (blocked, weighted)
    }
}

/// A plain label at `at` (drawing units).
fn label(fig: &Figure, words: String, size: f32, color: Rgb, at: DVec2, clearance: f64) -> Label {
    Label::at_point(words, size, color, fig.to_px(at), clearance)
}

/// The names at the hits, most important first, each at what it names: the
/// hit, n, c and v, the two angles just above the arcs either side of n (each
/// on its own side), and the right panel's n.
fn hit_labels(fig: &Figure, name: &str, c: DVec2, v: DVec2, theta: f64) -> Vec<Label> {
    let ink = palette::INK;
    let above = DVec2::new(0.0, 0.46);
    let side = |dx: f64| Target::Point {
        at: fig.to_px(above) + DVec2::new(dx, 0.0),
        clearance: 1.0,
    };
    let angle = |words: String, dx: f64| Label {
        target: side(dx),
        ..label(fig, words, TEXT, ink, above, 0.0)
    };
    vec![
        label(fig, name.to_owned(), TEXT - 1.0, ink, DVec2::ZERO, 5.0),
        label(fig, "n".to_owned(), TEXT, palette::NORMAL, DVec2::Y, 6.0),
        label(fig, "c".to_owned(), TEXT, palette::PRIMARY, -c, 4.0),
        label(fig, "v".to_owned(), TEXT, palette::REFLECTED, v, 7.0),
        angle(format!("θᵢ = {}", degrees(theta)), -5.0),
        angle(format!("θᵣ = {}", degrees(theta)), 5.0),
        label(
            fig,
            "n".to_owned(),
            TEXT,
            palette::NORMAL,
            DVec2::new(RIGHT, 0.0) + DVec2::Y,
            6.0,
        ),
    ]
}

/// On the right, each part's name with its value under it: the parts
/// first, their sums after, so v can take a leader from afar.
fn part_labels(fig: &Figure, p: &Parts, c: DVec2, v: DVec2) -> Vec<Label> {
    let o = DVec2::new(RIGHT, 0.0);
    let (across, along) = (DVec2::new(c.x, 0.0), DVec2::new(0.0, c.y));
    let small = TEXT - 2.0;
    let ink = palette::INK;
    vec![
        label(
            fig,
            format!("c\n{}", vec3(p.c)),
            small,
            palette::PRIMARY,
            o - c,
            4.0,
        ),
        label(
            fig,
            format!("across n, kept: c − (n·c)·n\n{}", vec3(p.across)),
            small,
            ink,
            o - across * 0.5,
            7.0,
        ),
        label(
            fig,
            format!("flipped: −(n·c)·n\nn·c = {}", num(p.n_dot_c)),
            small,
            ink,
            o + across - along * 0.5,
            7.0,
        ),
        label(
            fig,
            format!("along n: (n·c)·n\n{}", vec3(p.along)),
            small,
            ink,
            o - c + along * 0.5,
            7.0,
        ),
        label(
            fig,
            format!("v = c − 2(n·c)·n\n{}", vec3(p.v)),
            small,
            palette::REFLECTED,
            o + v,
            7.0,
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_parts_add_up_to_c_and_flipping_one_gives_v() {
        let c = DVec3::new(0.3, -0.8, -0.52).normalize();
        let n = DVec3::new(-0.2, 0.9, 0.3).normalize();
        let n_dot_c = n.dot(c);
        let p = split(c, n, n_dot_c, c - 2.0 * n_dot_c * n);
        // Tolerance: a few roundings of unit-length products.
        assert!((p.along + p.across - c).length() < 1e-15);
        assert!((p.across - p.along - p.v).length() < 1e-15);
        assert!(p.across.dot(n).abs() < 1e-15, "across n");
        assert!(p.along.cross(n).length() < 1e-15, "along n");
        let (c2, v2) = in_plane(&p);
        assert!((c2.length() - 1.0).abs() < 1e-15 && (v2.length() - 1.0).abs() < 1e-15);
        assert_eq!((c2.x, c2.y), (v2.x, -v2.y), "equal angles: mirrored in n");
    }
}
