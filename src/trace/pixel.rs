//! One pixel's color: the lecture's one ray through its center, an `n × n`
//! stratified grid of rays, Whitted's adaptive subdivision of its corners, or
//! the mean of its four corners (the SPD protocol).
//! The renderer and a recorded trace both call [`pixel_color`], so they agree
//! bit for bit.

use glam::DVec3;

use crate::methods::Antialiasing;
use crate::scene::camera::{Camera, stratum_offset};
use crate::trace::recorder::Recorder;
use crate::trace::tracer::Tracer;

/// The color of pixel `(x, y)` (image coordinates): the mean of its `n × n`
/// stratified samples, or Whitted's adaptive subdivision of its corners (see
/// [`crate::scene::camera`] for where a pixel lies). The renderer and a recorded trace
/// both call this, so they agree bit for bit.
pub fn pixel_color<R: Recorder>(
    tracer: &Tracer,
    camera: &Camera,
    x: u32,
    y: u32,
    rec: &mut R,
) -> DVec3 {
    pixel_color_at(tracer, camera, x, y, rec, None)
}

/// [`pixel_color`], also listing where each primary ray went, in the order traced.
pub fn pixel_color_at<R: Recorder>(
    tracer: &Tracer,
    camera: &Camera,
    x: u32,
    y: u32,
    rec: &mut R,
    mut at: Option<&mut Vec<(f64, f64)>>,
) -> DVec3 {
    let settings = &tracer.scene().settings;
    match settings.aa {
        Antialiasing::Grid => {
            let n = settings.grid();
            let mut sum = DVec3::ZERO;
            for (sx, sy) in sample_points(x, y, n) {
                if let Some(at) = at.as_deref_mut() {
                    at.push((sx, sy));
                }
                sum += tracer.trace_primary(camera.pixel_ray(sx, sy), rec);
            }
            sum / f64::from(n * n)
        }
        Antialiasing::Adaptive { threshold, levels } => {
            // Corners shared by the pixel's squares are traced once.
            let mut traced: Vec<((f64, f64), DVec3)> = Vec::with_capacity(9);
            let mut corner = |sx: f64, sy: f64| {
                if let Some(&(_, c)) = traced.iter().find(|(p, _)| *p == (sx, sy)) {
                    return c;
                }
                if let Some(at) = at.as_deref_mut() {
                    at.push((sx, sy));
                }
                let c = tracer.trace_primary(camera.pixel_ray(sx, sy), rec);
                traced.push(((sx, sy), c));
                c
            };
            adaptive_square(
                &mut corner,
                f64::from(x) - 0.5,
                f64::from(y) - 0.5,
                1.0,
                levels,
                threshold,
            )
        }
        Antialiasing::Corners => {
            let (x0, y0) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
            let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)].map(|(dx, dy)| {
                let (sx, sy) = (x0 + dx, y0 + dy);
                if let Some(at) = at.as_deref_mut() {
                    at.push((sx, sy));
                }
                tracer.trace_primary(camera.pixel_ray(sx, sy), rec)
            });
            corner_mean(corners)
        }
    }
}

/// A pixel's color from its corners' (top left, top right, bottom left,
/// bottom right): their mean, summed in that order by the renderer too, so a
/// recorded pixel and the rendered one agree bit for bit.
pub fn corner_mean(c: [DVec3; 4]) -> DVec3 {
    (c[0] + c[1] + c[2] + c[3]) / 4.0
}

/// Where pixel `(x, y)`'s `n × n` grid samples fall, in image coordinates, in the
/// order they are traced (row by row from the top, left to right).
pub fn sample_points(x: u32, y: u32, n: u32) -> impl Iterator<Item = (f64, f64)> {
    (0..n).flat_map(move |j| {
        (0..n).map(move |i| {
            (
                f64::from(x) + stratum_offset(i, n),
                f64::from(y) + stratum_offset(j, n),
            )
        })
    })
}

/// Whitted's adaptive subdivision of the square at `(x0, y0)` of side `size`.
fn adaptive_square(
    corner: &mut impl FnMut(f64, f64) -> DVec3,
    x0: f64,
    y0: f64,
    size: f64,
    levels: u32,
    threshold: f64,
) -> DVec3 {
    let c = [
        corner(x0, y0),
        corner(x0 + size, y0),
        corner(x0, y0 + size),
        corner(x0 + size, y0 + size),
    ];
    let mean = (c[0] + c[1] + c[2] + c[3]) / 4.0;
    if levels == 0
        || c.iter()
            .all(|&k| (k - mean).abs().max_element() <= threshold)
    {
        return mean;
    }
    let h = size / 2.0;
    let quarters = [(x0, y0), (x0 + h, y0), (x0, y0 + h), (x0 + h, y0 + h)];
    quarters
        .iter()
        .map(|&(qx, qy)| adaptive_square(corner, qx, qy, h, levels - 1, threshold))
        .sum::<DVec3>()
        / 4.0
}
