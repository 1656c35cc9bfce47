//! What a ray diagram frames: the first hits and the objects they are on
//! (where the optics happen), the whole tree with the eye, or the whole scene;
//! with the hierarchy's boxes drawn, the boxes a ray entered too.

use glam::DVec2;

use crate::views::diagram::layout::Layout;
use crate::views::diagram::options::Fit;

/// The window to frame, per `fit`, with a margin; never degenerate.
pub fn frame(lay: &Layout, fit: Fit) -> (DVec2, DVec2) {
    let (core, near) = framed(lay, fit);
    window(core, near, lay.eye)
}

/// What `fit` frames: the core, never empty, and the points that join it
/// when they are near it.
fn framed(lay: &Layout, fit: Fit) -> (Vec<DVec2>, Vec<DVec2>) {
    let bounded = |i: usize| lay.object(i).and_then(|o| o.silhouette.bounds());
    let corners = |b: Option<(DVec2, DVec2)>| b.into_iter().flat_map(|(a, c)| [a, c]);
    let mut core: Vec<DVec2> = Vec::new();
    let mut near: Vec<DVec2> = Vec::new();
    match fit {
        Fit::Scene => {
            core.extend(
                lay.objects
                    .iter()
                    .flat_map(|o| corners(o.silhouette.bounds())),
            );
            core.extend(lay.lights.iter().copied());
            core.push(lay.eye);
        }
        Fit::Tree => {
            core.push(lay.eye);
            core.extend(lay.image_plane.iter().flat_map(|&(a, b, _)| [a, b]));
            for s in lay.segments.iter().filter(|s| !s.leaves) {
                core.extend([s.from, s.to]);
            }
        }
        Fit::Hits => {
            // The first two levels of hits and the objects they are on make the
            // core; deeper hits and blockers join when near it.
            for h in &lay.hits {
                if h.depth <= 2 {
                    core.push(h.at);
                    core.extend(corners(bounded(h.object)));
                } else {
                    near.push(h.at);
                }
            }
            // A shadow's blocker at the first hits belongs to the story too.
            for b in &lay.marks.blocked {
                if b.depth <= 2 {
                    core.push(b.at);
                } else {
                    near.push(b.at);
                }
            }
        }
    }
    for &(i, _, on_ray, _) in &lay.near_misses {
        core.extend(corners(bounded(i)));
        core.push(on_ray);
    }
    // With the hierarchy's boxes drawn, the boxes the ray entered frame the
    // picture: from the whole hierarchy down to the leaf it was tested in.
    if fit == Fit::Hits {
        core.extend(
            lay.boxes
                .iter()
                .filter(|b| b.met)
                .flat_map(|b| b.outline.clone()),
        );
    }
    if core.is_empty() {
        core.push(lay.eye);
        for s in lay.segments.iter().filter(|s| !s.leaves) {
            core.extend([s.from, s.to]);
        }
    }
    (core, near)
}

/// The window around `core`, with the `near` points within half its size;
/// a lone point (a floor hit in the open) still gets room: a tenth of the
/// distance from the `eye`.
fn window(mut core: Vec<DVec2>, near: Vec<DVec2>, eye: DVec2) -> (DVec2, DVec2) {
    let bounds = |ps: &[DVec2]| {
        (
            ps.iter()
                .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p)),
            ps.iter()
                .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p)),
        )
    };
    let (core_lo, core_hi) = bounds(&core);
    let reach = (core_hi - core_lo).max_element() * 0.5;
    core.extend(
        near.into_iter()
            .filter(|p| p.cmpge(core_lo - reach).all() && p.cmple(core_hi + reach).all()),
    );
    let (lo, hi) = bounds(&core);
    let center = (lo + hi) / 2.0;
    let room = (hi - lo)
        .max_element()
        .max(0.1 * (eye - center).length())
        .max(1e-6);
    let half = ((hi - lo) / 2.0).max(DVec2::splat(room / 2.0)) * 1.12;
    (center - half, center + half)
}
