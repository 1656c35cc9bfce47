//! The tests of the shapes beyond the lecture's sphere, in words: the
//! polygon's plane and crossing number, the open cone's quadratic and which
//! of its crossings fall on the cone.

use crate::tree::arithmetic::Crossing;
use crate::views::numbers::{factor, num};

/// A polygon's test in words: the plane's `t`, then the crossing number's
/// verdict, then what became of the root (`roots`, the fates written out).
pub(super) fn polygon(
    (n_dot_c, numerator, one_sided): (f64, f64, bool),
    (crossings, on_edge): (u32, bool),
    roots: &str,
) -> String {
    if n_dot_c == 0.0 {
        return "n·c = 0: the ray runs parallel to the polygon's plane, no root".to_owned();
    }
    if one_sided && n_dot_c >= 0.0 {
        return format!(
            "n·c = {} ≥ 0: the ray meets the back of a one-sided polygon, no root",
            num(n_dot_c)
        );
    }
    let t = numerator / n_dot_c;
    let plane = format!(
        "n·c = {}, t = (V₀ − S)·n / (n·c) = {} / {} = {}",
        num(n_dot_c),
        num(numerator),
        factor(n_dot_c),
        num(t)
    );
    let inside = on_edge || crossings % 2 == 1;
    let verdict = if on_edge {
        "the ray passes through an edge or a vertex: inside".to_owned()
    } else {
        let times = if crossings == 1 { "once" } else { "times" };
        let count = if crossings == 1 {
            String::new()
        } else {
            format!("{crossings} ")
        };
        let parity = if inside {
            "odd: inside"
        } else {
            "even: outside"
        };
        format!("the half-line from the ray's point crosses the outline {count}{times}, {parity}")
    };
    let outcome = if !roots.is_empty() {
        roots.to_owned()
    } else if !inside {
        "no root".to_owned()
    } else if t <= 0.0 {
        "behind the origin, no root".to_owned()
    } else {
        "not kept: past the ray's end or the nearest hit so far, or within rounding of its start"
            .to_owned()
    };
    format!("{plane}; {verdict}; {outcome}")
}

/// The unit cone's equation and its `A`, `B` and `C` written out with the
/// ray's names `(S, c)`; for a cylinder (`s = 1`), in its shorter form.
pub(super) fn cone_quadratic(ratio: f64, [a, b, c]: [f64; 3], (s, d): (&str, &str)) -> [String; 2] {
    if ratio == 1.0 {
        return [
            "the unit cylinder x² + y² = 1, 0 ≤ z ≤ 1, open at both ends".to_owned(),
            format!(
                "A = {d}x² + {d}y² = {}, B = {s}x·{d}x + {s}y·{d}y = {}, C = {s}x² + {s}y² − 1 = {}",
                num(a),
                num(b),
                num(c)
            ),
        ];
    }
    [
        format!(
            "the unit cone x² + y² = (1 + (s − 1)z)², 0 ≤ z ≤ 1, open at both ends, radius 1 at z = 0 and s = {} at z = 1",
            num(ratio)
        ),
        format!(
            "A = {d}x² + {d}y² − (s − 1)²{d}z² = {}, B = {s}x·{d}x + {s}y·{d}y − (1 + (s − 1){s}z)(s − 1){d}z = {}, C = {s}x² + {s}y² − (1 + (s − 1){s}z)² = {}",
            num(a),
            num(b),
            num(c)
        ),
    ]
}

/// The cone's roots: which the quadratic has (`A` and `B` decide when the
/// ray runs along the surface's lines, then `B² − AC`), each crossing with
/// its height and what became of it.
pub(super) fn cone_roots(
    ratio: f64,
    [a, b]: [f64; 2],
    d: f64,
    crossings: &[Crossing],
    fates: &[(f64, &'static str)],
) -> String {
    let each = crossings
        .iter()
        .map(|x| {
            let why = crossing_fate(x.t, x.z, ratio, fates);
            format!("t = {} at z = {} ({why})", num(x.t), num(x.z))
        })
        .collect::<Vec<_>>()
        .join(", ");
    if a == 0.0 && b == 0.0 {
        "A = B = 0: the ray runs along the surface's lines and never crosses it: no root".to_owned()
    } else if a == 0.0 {
        format!(
            "A = 0: the ray runs parallel to a line of the surface, so 2B t + C = 0 has one root, t = −C/(2B): {each}"
        )
    } else if d < 0.0 {
        format!("B² − AC = {} < 0: no root, the ray misses", num(d))
    } else if d == 0.0 {
        format!("B² − AC = 0: one root, t = −B/A: {each}")
    } else {
        format!(
            "B² − AC = {} > 0: two roots, t = (−B ± √(B² − AC))/A: {each}",
            num(d)
        )
    }
}

/// What became of a crossing of the infinite cone at height `z`: off the open
/// cone it is no root; on it, its fate among the test's roots.
fn crossing_fate(t: f64, z: f64, ratio: f64, fates: &[(f64, &'static str)]) -> &'static str {
    if z < 0.0 {
        "below the open end z = 0: not on the cone"
    } else if ratio < 1.0 && z * (1.0 - ratio) > 1.0 {
        "past the tip, on the other half of the double cone: not on the cone"
    } else if z > 1.0 {
        "past the open end z = 1: not on the cone"
    } else {
        fates
            .iter()
            .find(|(root, _)| *root == t)
            .map_or("on the cone", |(_, why)| why)
    }
}
