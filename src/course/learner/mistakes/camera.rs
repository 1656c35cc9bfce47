//! The camera's mistakes (lesson 3), recognised in the primary ray's
//! direction: the rows counted from the top, the ray through a corner of the
//! pixel, and the image plane divided by N instead of N − 1.

use crate::course::learner::context::Context;
use crate::course::learner::mistakes::{Diagnosis, Mistake, Same};
use crate::scene::camera::Camera;

/// A wrong primary direction, accepted by `same`.
pub fn primary(ctx: &Context, same: &Same) -> Option<Diagnosis> {
    let camera = ctx.scene.camera();
    let (x, y) = (f64::from(ctx.pixel.0), f64::from(ctx.pixel.1));
    rows_flipped(ctx, &camera, (x, y), same)
        .or_else(|| corner(&camera, (x, y), same))
        .or_else(|| {
            let size = (ctx.scene.settings.width, ctx.scene.settings.height);
            spacing(&camera, size, (x, y), same)
        })
}

/// The ray of pixel (`x`, N_r − 1 − `y`): rows counted from the top.
fn rows_flipped(
    ctx: &Context,
    camera: &Camera,
    (x, y): (f64, f64),
    same: &Same,
) -> Option<Diagnosis> {
    let flipped = f64::from(ctx.scene.settings.height) - 1.0 - y;
    same(Some(camera.pixel_ray(x, flipped).dir)).then(|| {
        Diagnosis::new(
            Mistake::RowsFlipped,
            format!(
                "your primary ray is raytree's for pixel ({x}, {flipped}): rows counted from the top where the lecture counts row r up from the bottom (r = N_r − 1 − y)"
            ),
        )
    })
}

/// The ray through one of the pixel's corners, half a pixel off its center.
fn corner(camera: &Camera, (x, y): (f64, f64), same: &Same) -> Option<Diagnosis> {
    for (dx, dy, corner) in [
        (-0.5, 0.5, "lower left"),
        (0.5, 0.5, "lower right"),
        (-0.5, -0.5, "upper left"),
        (0.5, -0.5, "upper right"),
    ] {
        if same(Some(camera.pixel_ray(x + dx, y + dy).dir)) {
            return Some(Diagnosis::new(
                Mistake::PixelCorner,
                format!(
                    "your primary ray goes half a pixel toward the pixel's {corner} corner (P(r, c) at c {} ½, r {} ½): raytree takes P(r, c) at the whole c and r as the pixel's center, with no half-pixel shift",
                    if dx < 0.0 { "−" } else { "+" },
                    if dy > 0.0 { "−" } else { "+" },
                ),
            ));
        }
    }
    None
}

/// The ray through pixel (`x`, `y`) of a `columns × rows` image with
/// `u_c = −W + 2W·(c + s)/N_c` (and likewise `v_r`), `s` 0 or ½: the formula
/// of the many books that divide the image plane into N cells and aim at each
/// cell's center or corner, where the lecture's is 2W/(N − 1). Its rays drift
/// from raytree's by up to a pixel across the image, so neither the corner
/// nor the rows diagnosis matches, and the size hint would mislead.
fn spacing(
    camera: &Camera,
    (columns, rows): (u32, u32),
    (x, y): (f64, f64),
    same: &Same,
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
            return Some(Diagnosis::new(
                Mistake::PixelSpacing,
                format!(
                    "your primary ray divides the image plane by N, u_c = −W + 2W·{s}/N_c and v_r = −H + 2H·{t}/N_r: the lecture's camera divides by N − 1, u_c = −W + 2W·c/(N_c − 1), so its first and last pixels sit on the plane's edges (the size is right: your rays drift from raytree's across the image)"
                ),
            ));
        }
    }
    None
}
