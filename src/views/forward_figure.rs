//! A forward run shown (`raytree forward`): what the light rays did, a line
//! per fate, beside what the backward render of the same image cast; the
//! sparse image the arrivals form; and the figure that sets it beside the
//! backward render, each frame with its rays counted.

use glam::DVec3;

use crate::figure::canvas::Figure;
use crate::io::image::{Image, rgb8, to_rgb8};
use crate::trace::forward::Forward;
use crate::trace::recorder::RayCounter;
use crate::views::filmstrip::{self, Frame};
use crate::views::numbers::{num, thousands};

/// The figures, a line each; they add up to the rays shot. `rays` are the
/// backward render's of the same `w × h` image.
pub fn report(f: &Forward, rays: &RayCounter, seed: u64, pupil: f64, (w, h): (u32, u32)) -> String {
    let c = &f.counts;
    let share = |n: u64| format!("{}%", num(100.0 * n as f64 / c.shot.max(1) as f64));
    let row = |n: u64, what: &str| format!("{:>13}  {what}\n", thousands(n));
    let mut out = format!(
        "forward: {} rays shot from the lights (seed {seed}, pupil radius {})\n",
        thousands(c.shot),
        num(pupil)
    );
    out += &row(
        c.reached,
        &format!("reached a pixel ({})", share(c.reached)),
    );
    out += &row(c.outside_image, "entered the eye from outside the image");
    out += &row(c.left_scene, "left the scene");
    out += &row(c.absorbed, "were absorbed by a surface");
    out += &row(c.max_depth, "were still bouncing at the maximum depth");
    out += &row(c.ended(), "in all");
    out += &format!("{:>13}  segments traced\n", thousands(c.segments));
    out += &format!(
        "backward: {} rays for every pixel of the same {w}×{h} image ({} primary, {} shadow, {} reflected, {} refracted)\n",
        thousands(rays.total()),
        thousands(rays.primary),
        thousands(rays.shadow),
        thousands(rays.reflected),
        thousands(rays.refracted)
    );
    out
}

/// The sparse image alone, pixel for pixel (`--no-key`); `None` when too large.
pub fn bare(f: &Forward, width: u32, height: u32) -> Option<Figure> {
    let sparse = sparse_image(f, width, height, 0);
    let mut fig = Figure::page(width, height)?;
    fig.image(0, 0, width, &sparse);
    Some(fig)
}

/// The sparse image (each arrival 5 pixels wide) beside the `backward` render
/// and its `rays`, under `title`; `None` when too large to draw.
pub fn draw(f: &Forward, backward: &Image, rays: &RayCounter, title: &str) -> Option<Figure> {
    let (width, height) = (backward.width, backward.height);
    let c = &f.counts;
    let frames = [
        Frame {
            rgb: sparse_image(f, width, height, 2),
            label: format!("forward: {} rays from the lights", thousands(c.shot)),
            change: format!(
                "{} of {} reached a pixel ({}%), each shown 5 pixels wide",
                thousands(c.reached),
                thousands(c.shot),
                num(100.0 * c.reached as f64 / c.shot as f64)
            ),
        },
        Frame {
            rgb: to_rgb8(backward),
            label: format!("backward: {} rays from the eye", thousands(rays.total())),
            change: format!(
                "every pixel: {} primary, {} shadow, {} reflected, {} refracted",
                thousands(rays.primary),
                thousands(rays.shadow),
                thousands(rays.reflected),
                thousands(rays.refracted)
            ),
        },
    ];
    filmstrip::draw(&frames, width, height, title)
}

/// The figure's title: the scene's `file`, the image's size, the run's
/// `seed` and `pupil`.
pub fn title(file: &str, (width, height): (u32, u32), seed: u64, pupil: f64) -> String {
    format!(
        "{file}, {width}×{height}: light rays in uniform directions, followed through mirrors and glass (seed {seed}); the eye is a pupil of radius {}",
        num(pupil)
    )
}

/// The image the arrivals form: each pixel the sum of the colors that reached
/// it, as 8-bit sRGB on black; with `grow`, each arrival covers the pixels up
/// to `grow` away as well, so a single one shows in a figure.
pub fn sparse_image(f: &Forward, width: u32, height: u32, grow: i64) -> Vec<u8> {
    let mut sum = vec![DVec3::ZERO; width as usize * height as usize];
    for &(x, y, color) in &f.arrivals {
        for dy in -grow..=grow {
            for dx in -grow..=grow {
                let (px, py) = (i64::from(x) + dx, i64::from(y) + dy);
                if (0..i64::from(width)).contains(&px) && (0..i64::from(height)).contains(&py) {
                    sum[py as usize * width as usize + px as usize] += color;
                }
            }
        }
    }
    sum.iter().flat_map(|&c| rgb8(c)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::forward::ForwardCounts;

    #[test]
    fn an_arrival_grows_into_a_square_clipped_at_the_border() {
        let f = Forward {
            counts: ForwardCounts::default(),
            arrivals: vec![(0, 0, DVec3::ONE), (3, 2, DVec3::new(1.0, 0.0, 0.0))],
        };
        let lit = |rgb: &[u8]| -> Vec<(usize, [u8; 3])> {
            rgb.chunks(3)
                .enumerate()
                .filter(|(_, p)| p.iter().any(|&v| v > 0))
                .map(|(i, p)| (i, [p[0], p[1], p[2]]))
                .collect()
        };
        // Pixel for pixel: the two arrivals, white and red, on black.
        assert_eq!(
            lit(&sparse_image(&f, 5, 4, 0)),
            [(0, [255, 255, 255]), (13, [255, 0, 0])]
        );
        // Grown by 1: a 2×2 corner (clipped at the top left) and a 3×3 block.
        let grown: Vec<usize> = lit(&sparse_image(&f, 5, 4, 1))
            .iter()
            .map(|(i, _)| *i)
            .collect();
        assert_eq!(grown, [0, 1, 5, 6, 7, 8, 9, 12, 13, 14, 17, 18, 19]);
    }
}
