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
use crate::figure::pen::{Pen, palette};
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
    let ink = palette::INK;
    let text = 15.0;
    // Every arrow drawn, for the labels to keep off: (tail, head).
    let mut arrows: Vec<[DVec2; 2]> = Vec::new();
    let mut arrow = |fig: &mut Figure, a: DVec2, b: DVec2, pen: Pen| {
        fig.arrow(a, b, pen);
        arrows.push([a, b]);
    };
    let mut lines: Vec<[DVec2; 2]> = Vec::new();
    for center in [DVec2::ZERO, DVec2::new(RIGHT, 0.0)] {
        // The surface: its tangent line, the inside shaded below it.
        let (l, r) = (center - DVec2::new(1.3, 0.0), center + DVec2::new(1.3, 0.0));
        fig.polygon(
            &[l, r, r - DVec2::new(0.0, 0.4), l - DVec2::new(0.0, 0.4)],
            Some((palette::OBJECT_FILL, 255)),
            None,
        );
        fig.line(l, r, Pen::solid(palette::OBJECT, 1.5));
        lines.push([l, r]);
        arrow(
            &mut fig,
            center,
            center + DVec2::Y,
            Pen::solid(palette::NORMAL, 2.5),
        );
        fig.dot(center, 4.0, ink, None);
    }
    // Left: c arrives, v leaves, the angles from n.
    let incoming = Pen::solid(palette::PRIMARY, 2.5);
    let outgoing = Pen::solid(palette::REFLECTED, 2.5);
    arrow(&mut fig, -c, DVec2::ZERO, incoming);
    arrow(&mut fig, DVec2::ZERO, v, outgoing);
    let theta = (-p.n_dot_c).clamp(-1.0, 1.0).acos().to_degrees();
    let radius = 0.28 * fig.scale();
    let arc = Pen::solid(ink, 1.5);
    fig.arc(DVec2::ZERO, radius, DVec2::Y, (-c).normalize(), arc);
    fig.arc(DVec2::ZERO, radius * 0.85, DVec2::Y, v.normalize(), arc);
    // Right: c = along + across, head to tail, down to the surface and along
    // it; v = across − along, along the surface and back up.
    let o = DVec2::new(RIGHT, 0.0);
    let (across, along) = (DVec2::new(c.x, 0.0), DVec2::new(0.0, c.y));
    let part = |color| Pen::dashed(color, 2.5);
    let (along_pen, across_pen) = (part(palette::NORMAL), part(palette::SHADOW_REACHES));
    arrow(&mut fig, o - c, o, Pen::solid(palette::PRIMARY, 1.5));
    arrow(&mut fig, o - c, o - c + along, along_pen);
    arrow(&mut fig, o - c + along, o, across_pen);
    arrow(&mut fig, o, o + v, Pen::solid(palette::REFLECTED, 1.5));
    arrow(&mut fig, o, o + across, across_pen);
    arrow(&mut fig, o + across, o + v, along_pen);
    // The labels, most important first, each at what it names; on the right
    // each part's name with its value under it.
    let small = text - 2.0;
    let label = |words: String, size: f32, color, at: DVec2, clearance: f64| {
        Label::at_point(words, size, color, fig.to_px(at), clearance)
    };
    // Just above the arcs, either side of n: each angle on its own side.
    let above = DVec2::new(0.0, 0.46);
    let side = |dx: f64| Target::Point {
        at: fig.to_px(above) + DVec2::new(dx, 0.0),
        clearance: 1.0,
    };
    let mut requests = vec![
        label(name.to_owned(), text - 1.0, ink, DVec2::ZERO, 5.0),
        label("n".to_owned(), text, palette::NORMAL, DVec2::Y, 6.0),
        label("c".to_owned(), text, palette::PRIMARY, -c, 4.0),
        label("v".to_owned(), text, palette::REFLECTED, v, 7.0),
        Label {
            target: side(-5.0),
            ..label(format!("θᵢ = {}", degrees(theta)), text, ink, above, 0.0)
        },
        Label {
            target: side(5.0),
            ..label(format!("θᵣ = {}", degrees(theta)), text, ink, above, 0.0)
        },
        label("n".to_owned(), text, palette::NORMAL, o + DVec2::Y, 6.0),
    ];
    // The parts first, their sums after: v can take a leader from afar.
    requests.extend([
        label(
            format!("c\n{}", vec3(p.c)),
            small,
            palette::PRIMARY,
            o - c,
            4.0,
        ),
        label(
            format!("across n, kept: c − (n·c)·n\n{}", vec3(p.across)),
            small,
            ink,
            o - across * 0.5,
            7.0,
        ),
        label(
            format!("flipped: −(n·c)·n\nn·c = {}", num(p.n_dot_c)),
            small,
            ink,
            o + across - along * 0.5,
            7.0,
        ),
        label(
            format!("along n: (n·c)·n\n{}", vec3(p.along)),
            small,
            ink,
            o - c + along * 0.5,
            7.0,
        ),
        label(
            format!("v = c − 2(n·c)·n\n{}", vec3(p.v)),
            small,
            palette::REFLECTED,
            o + v,
            7.0,
        ),
    ]);
    let f = fig.frame();
    let frame = PxRect {
        min: DVec2::new(f64::from(f.left()), f64::from(f.top())),
        max: DVec2::new(f64::from(f.right()), f64::from(f.bottom())),
    };
    // Arrowheads and the hit points stay visible; the arrows, the surfaces
    // and the arcs (as chords) are lines a label would rather not cover.
    let mut blocked: Vec<PxRect> = arrows
        .iter()
        .map(|[_, b]| PxRect::around(fig.to_px(*b), 6.0))
        .collect();
    blocked.extend([DVec2::ZERO, o].map(|h| PxRect::around(fig.to_px(h), 5.0)));
    let chords = |to: DVec2, r: f64| {
        let (a0, a1) = (DVec2::Y.to_angle(), to.to_angle());
        (0..6).map(move |k| {
            let at = |k: u32| DVec2::from_angle(a0 + (a1 - a0) * f64::from(k) / 6.0) * r;
            [at(k), at(k + 1)]
        })
    };
    let r = radius / fig.scale();
    lines.extend(arrows.iter().copied());
    lines.extend(chords((-c).normalize(), r).chain(chords(v.normalize(), r * 0.85)));
    // Crossing an arrow costs more than a leader: the arrows are the figure.
    let weighted: Vec<([DVec2; 2], usize)> = lines
        .iter()
        .map(|[a, b]| ([fig.to_px(*a), fig.to_px(*b)], 4))
        .collect();
    let (placed, left_out) = labels::place_all(requests, &blocked, &weighted, frame);
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
