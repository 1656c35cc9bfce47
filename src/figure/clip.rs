//! Clipping in 2D (Liang–Barsky): the part of a line, ray or segment inside a
//! box, so figures and the inspector's diagram draw only what their frame shows.

use glam::DVec2;

/// Clips the line `p + s·d` (any s) to the box `lo..hi`: the two ends, if it crosses it.
pub fn clip_line(p: DVec2, d: DVec2, lo: DVec2, hi: DVec2) -> Option<(DVec2, DVec2)> {
    clip_ray(p, d, lo, hi, f64::NEG_INFINITY)
}

/// Clips the ray `p + s·d`, `s ≥ s_min`, to the box (Liang–Barsky).
pub fn clip_ray(p: DVec2, d: DVec2, lo: DVec2, hi: DVec2, s_min: f64) -> Option<(DVec2, DVec2)> {
    clip(p, d, lo, hi, s_min, f64::INFINITY)
}

/// Clips the segment `a..b` to the box.
pub fn clip_segment(a: DVec2, b: DVec2, lo: DVec2, hi: DVec2) -> Option<(DVec2, DVec2)> {
    clip(a, b - a, lo, hi, 0.0, 1.0)
}

fn clip(
    p: DVec2,
    d: DVec2,
    lo: DVec2,
    hi: DVec2,
    s_min: f64,
    s_max: f64,
) -> Option<(DVec2, DVec2)> {
    let (mut s0, mut s1) = (s_min, s_max);
    for (pi, di, l, h) in [(p.x, d.x, lo.x, hi.x), (p.y, d.y, lo.y, hi.y)] {
        if di == 0.0 {
            if pi < l || pi > h {
                return None;
            }
            continue;
        }
        let (a, b) = ((l - pi) / di, (h - pi) / di);
        s0 = s0.max(a.min(b));
        s1 = s1.min(a.max(b));
    }
    (s0 <= s1 && s1.is_finite() && s0.is_finite()).then(|| (p + s0 * d, p + s1 * d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_keeps_the_part_inside() {
        let (lo, hi) = (DVec2::ZERO, DVec2::splat(10.0));
        let (a, b) = clip_ray(DVec2::new(5.0, 5.0), DVec2::X, lo, hi, 0.0).unwrap();
        assert_eq!((a, b), (DVec2::new(5.0, 5.0), DVec2::new(10.0, 5.0)));
        let (a, b) = clip_line(DVec2::new(5.0, 5.0), DVec2::new(1.0, 1.0), lo, hi).unwrap();
        assert_eq!((a, b), (DVec2::ZERO, DVec2::splat(10.0)));
        assert!(clip_ray(DVec2::new(20.0, 5.0), DVec2::X, lo, hi, 0.0).is_none());
    }
}
