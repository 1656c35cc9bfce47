//! One hit's vectors, enlarged: the incoming direction c, the normal n and
//! the mirror direction v in their plane of incidence, with the equal angles
//! θᵢ and θᵣ; and beside them c split into its part along n, (n·c)·n, and its
//! part across n, c − (n·c)·n, with v made of the same two parts, the one
//! along n flipped. The ray diagram draws these marks a few dozen pixels
//! long beside a whole scene; here the unit vectors span the panel, so the
//! angles and the split can be read. Every vector is the trace's own.

use glam::{DVec2, DVec3};

use crate::figure::canvas::{Anchor, Figure};
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
    for center in [DVec2::ZERO, DVec2::new(RIGHT, 0.0)] {
        // The surface: its tangent line, the inside shaded below it.
        let (l, r) = (center - DVec2::new(1.3, 0.0), center + DVec2::new(1.3, 0.0));
        fig.polygon(
            &[l, r, r - DVec2::new(0.0, 0.4), l - DVec2::new(0.0, 0.4)],
            Some((palette::OBJECT_FILL, 255)),
            None,
        );
        fig.line(l, r, Pen::solid(palette::OBJECT, 1.5));
        fig.arrow(center, center + DVec2::Y, Pen::solid(palette::NORMAL, 2.5));
        fig.label(
            center + DVec2::Y,
            DVec2::new(8.0, 4.0),
            "n",
            text,
            palette::NORMAL,
            Anchor::Left,
        );
        fig.dot(center, 4.0, ink, None);
    }
    fig.label(
        DVec2::ZERO,
        DVec2::new(6.0, 18.0),
        name,
        text - 1.0,
        ink,
        Anchor::Left,
    );
    // Left: c arrives, v leaves, the angles from n.
    let incoming = Pen::solid(palette::PRIMARY, 2.5);
    let outgoing = Pen::solid(palette::REFLECTED, 2.5);
    fig.arrow(-c, DVec2::ZERO, incoming);
    fig.label(
        -c,
        DVec2::new(-6.0, -6.0),
        "c",
        text,
        palette::PRIMARY,
        Anchor::Right,
    );
    fig.arrow(DVec2::ZERO, v, outgoing);
    fig.label(
        v,
        DVec2::new(6.0, -6.0),
        "v",
        text,
        palette::REFLECTED,
        Anchor::Left,
    );
    let theta = (-p.n_dot_c).clamp(-1.0, 1.0).acos().to_degrees();
    let radius = 0.28 * fig.scale();
    let arc = Pen::solid(ink, 1.5);
    fig.arc(DVec2::ZERO, radius, DVec2::Y, (-c).normalize(), arc);
    fig.arc(DVec2::ZERO, radius * 0.85, DVec2::Y, v.normalize(), arc);
    // Just above the arcs, either side of n.
    let (i_text, r_text) = (
        format!("θᵢ = {}", degrees(theta)),
        format!("θᵣ = {}", degrees(theta)),
    );
    let at = DVec2::new(0.0, 0.46);
    fig.label(at, DVec2::new(-6.0, 0.0), &i_text, text, ink, Anchor::Right);
    fig.label(at, DVec2::new(6.0, 0.0), &r_text, text, ink, Anchor::Left);
    // Right: c = along + across, head to tail, down to the surface and along
    // it; v = across − along, along the surface and back up.
    let o = DVec2::new(RIGHT, 0.0);
    let (across, along) = (DVec2::new(c.x, 0.0), DVec2::new(0.0, c.y));
    let part = |color| Pen::dashed(color, 2.5);
    let (along_pen, across_pen) = (part(palette::NORMAL), part(palette::SHADOW_REACHES));
    fig.arrow(o - c, o, Pen::solid(palette::PRIMARY, 1.5));
    fig.arrow(o - c, o - c + along, along_pen);
    fig.arrow(o - c + along, o, across_pen);
    fig.arrow(o, o + v, Pen::solid(palette::REFLECTED, 1.5));
    fig.arrow(o, o + across, across_pen);
    fig.arrow(o + across, o + v, along_pen);
    let small = text - 2.0;
    // Each part's name, and under it its value.
    let labels = [
        (
            o - c,
            DVec2::new(0.0, -30.0),
            "c".to_owned(),
            vec3(p.c),
            palette::PRIMARY,
            Anchor::Center,
        ),
        (
            o + v,
            DVec2::new(0.0, -30.0),
            "v = c − 2(n·c)·n".to_owned(),
            vec3(p.v),
            palette::REFLECTED,
            Anchor::Center,
        ),
        (
            o - c + along * 0.5,
            DVec2::new(-8.0, 0.0),
            "along n: (n·c)·n".to_owned(),
            vec3(p.along),
            ink,
            Anchor::Right,
        ),
        (
            o + across - along * 0.5,
            DVec2::new(8.0, 0.0),
            "flipped: −(n·c)·n".to_owned(),
            format!("n·c = {}", num(p.n_dot_c)),
            ink,
            Anchor::Left,
        ),
        (
            o,
            DVec2::new(0.0, 24.0),
            "across n, kept: c − (n·c)·n".to_owned(),
            vec3(p.across),
            ink,
            Anchor::Center,
        ),
    ];
    for (at, offset, words, value, color, anchor) in labels {
        fig.label(at, offset, &words, small, color, anchor);
        fig.label(
            at,
            offset + DVec2::new(0.0, 18.0),
            &value,
            small,
            color,
            anchor,
        );
    }
    fig.frame_border();
    let caption = format!(
        "{title} · left: c arrives, v = c − 2(n·c)·n leaves, both {} from n · right: c is its part across n plus its part along n; v keeps the first and flips the second",
        degrees(theta)
    );
    fig.caption(&Figure::wrap(&caption, 15.0, fig.frame().width()), 15.0);
    Some(fig)
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
