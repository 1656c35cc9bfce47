//! A primary ray on a pixel grid spaced by 2W/N instead of the lecture's
//! 2W/(N − 1): the formula of the many books that divide the image plane into
//! N cells and aim at each cell's center or corner. Its rays drift from
//! raytree's by up to a pixel across the image, so neither the corner nor
//! the rows diagnosis matches, and the size hint would mislead.

use glam::DVec3;

use crate::course::learner::mistake::{Diagnosis, found};
use crate::scene::camera::Camera;

/// The diagnosis when the learner's primary direction, accepted by `same`,
/// is the one through pixel (`x`, `y`) of a `columns × rows` image with
/// `u_c = −W + 2W·(c + s)/N_c` (and likewise `v_r`), `s` 0 or ½.
pub fn spacing(
    camera: &Camera,
    (columns, rows): (u32, u32),
    (x, y): (f64, f64),
    same: &dyn Fn(Option<DVec3>) -> bool,
) -> Option<Diagnosis> {
    if columns < 2 || rows < 2 {
        return None;
    }
    let (nc, nr) = (f64::from(columns), f64::from(rows));
    let r = nr - 1.0 - y;
    for shift in [0.0, 0.5] {
        // The same point of the plane as raytree's pixel at these fractional coordinates.
        let c = (x + shift) * (nc - 1.0) / nc;
        let r = (r + shift) * (nr - 1.0) / nr;
        if same(Some(camera.pixel_ray(c, nr - 1.0 - r).dir)) {
            let s = if shift == 0.0 { "c" } else { "(c + ½)" };
            let t = if shift == 0.0 { "r" } else { "(r + ½)" };
            return found(
                "pixel-spacing",
                format!(
                    "your primary ray divides the image plane by N, u_c = −W + 2W·{s}/N_c and v_r = −H + 2H·{t}/N_r: the lecture's camera divides by N − 1, u_c = −W + 2W·c/(N_c − 1), so its first and last pixels sit on the plane's edges (the size is right: your rays drift from raytree's across the image)"
                ),
            );
        }
    }
    None
}
