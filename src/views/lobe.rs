//! The lobe of Phong's highlight: the specular factor (R·V)^shininess against
//! the angle α between the mirror direction R and the eye V, one curve per
//! shininess, so a learner sees why a larger exponent makes a smaller
//! highlight. Every value is the shader's own ([`phong::direct`]), asked at a
//! point where R·V = cos α, not a second copy of the formula.

use glam::{DVec2, DVec3};

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::pen::{Pen, palette};
use crate::shading::material::{Material, Pattern};
use crate::shading::phong;
use crate::views::numbers::num;

/// The widest angle drawn: past 90° the eye is behind the mirror direction.
const MAX_ANGLE: f64 = 90.0;
/// Drawing units per degree, so that 90° spans 1.5 and the value 0..1 spans
/// 1 (the canvas keeps one scale for both axes).
const PER_DEGREE: f64 = 1.5 / MAX_ANGLE;
/// Points per curve: under half a degree apart, smooth at any figure size.
const SAMPLES: usize = 361;

/// The specular factor at angle `alpha` (degrees) between R and V, for
/// `shininess`: what [`phong::direct`] gives with k_s = 1 and a white light,
/// the light 30° from the normal and the eye turned `alpha` from R.
pub fn specular(alpha: f64, shininess: f64) -> f64 {
    let material = Material {
        name: "lobe".into(),
        pattern: Pattern::Solid(DVec3::ONE),
        ambient: 0.0,
        diffuse: 0.0,
        specular: 1.0,
        shininess,
        reflective: 0.0,
        transparent: 0.0,
        ior: 1.0,
    };
    let at = |degrees: f64| {
        let a = degrees.to_radians();
        DVec3::new(a.sin(), a.cos(), 0.0)
    };
    // L at +30° from the normal Y, so R = 2(N·L)N − L is at −30°; V is R
    // turned by α toward L, which keeps it above the surface up to 90°.
    let (light, eye) = (at(30.0), at(-30.0 + alpha));
    let d = phong::direct(&material, DVec3::ONE, DVec3::Y, light, eye, DVec3::ONE);
    d.specular.x
}

/// The curve for `shininess`: (α in degrees, specular factor), α from 0 to 90°.
pub fn curve(shininess: f64) -> Vec<(f64, f64)> {
    (0..SAMPLES)
        .map(|i| {
            let alpha = MAX_ANGLE * i as f64 / (SAMPLES - 1) as f64;
            (alpha, specular(alpha, shininess))
        })
        .collect()
}

/// The angle (degrees) at which the factor falls to `level`: cos α = level^(1/n).
pub fn angle_at(level: f64, shininess: f64) -> f64 {
    level.powf(1.0 / shininess).acos().to_degrees()
}

/// A curve's point in drawing coordinates.
pub fn point(alpha: f64, value: f64) -> DVec2 {
    DVec2::new(alpha * PER_DEGREE, value)
}

/// One line per shininess: where the factor falls to a half and to a hundredth.
pub fn text(shininess: &[f64]) -> String {
    shininess
        .iter()
        .map(|&n| {
            format!(
                "shininess {}: (R·V)^{} is 1/2 at α = {}°, 1/100 at α = {}°\n",
                num(n),
                num(n),
                num(angle_at(0.5, n)),
                num(angle_at(0.01, n))
            )
        })
        .collect()
}

/// The pens of the curves, told apart by color: the first (the lesson's) thicker.
fn pens(count: usize) -> Vec<Pen> {
    let colors = [palette::PRIMARY, palette::REFRACTED, palette::REFLECTED];
    (0..count)
        .map(|k| {
            let color = colors[k % colors.len()];
            Pen::solid(color, if k == 0 { 3.5 } else { 2.0 })
        })
        .collect()
}

/// The figure: a curve per shininess (the first emphasized), the half level
/// marked on each (its angle in the legend), on axes of α (degrees) and the factor (0 to 1).
pub fn draw(shininess: &[f64], width: u32, height: u32) -> Option<Figure> {
    let mut fig = Figure::new(width, height, 56.0, 16.0)?;
    fig.fit(point(-14.0, -0.14), point(MAX_ANGLE + 3.0, 1.06), 0.0);
    draw_axes(&mut fig);
    let pens = pens(shininess.len());
    // The others first, so the lesson's curve is drawn on top.
    for (k, &n) in shininess.iter().enumerate().rev() {
        let points: Vec<DVec2> = curve(n).into_iter().map(|(a, v)| point(a, v)).collect();
        for w in points.windows(2) {
            fig.line(w[0], w[1], pens[k]);
        }
    }
    let half = point(0.0, 0.5);
    fig.line(
        half,
        point(MAX_ANGLE, 0.5),
        Pen::dashed([150, 150, 150], 1.0),
    );
    for (k, &n) in shininess.iter().enumerate() {
        let alpha = angle_at(0.5, n);
        fig.dot(point(alpha, 0.5), 5.0, pens[k].color, Some(palette::INK));
    }
    let labels: Vec<String> = shininess
        .iter()
        .enumerate()
        .map(|(k, &n)| {
            let whose = if k == 0 { " (the lesson's)" } else { "" };
            format!(
                "shininess {}{whose}: (cos α)^{}, ½ at α = {}°",
                num(n),
                num(n),
                num(angle_at(0.5, n))
            )
        })
        .collect();
    let entries: Vec<(Pen, &str)> = pens
        .iter()
        .zip(&labels)
        .map(|(p, l)| (*p, l.as_str()))
        .collect();
    fig.legend(&entries, 14.0, 0);
    fig.frame_border();
    let title = "The highlight's lobe: k_s·(R·V)^shininess ÷ k_s against α, the angle between the mirror direction R and the eye V (R·V = cos α), as raytree's shader computes it";
    fig.caption(&Figure::wrap(title, 15.0, fig.frame().width()), 15.0);
    Some(fig)
}

/// Grid lines every 15° and every quarter, with their values and the axes' names.
fn draw_axes(fig: &mut Figure) {
    let grid = Pen::solid([225, 225, 225], 1.0);
    let ink = Pen::solid(palette::INK, 1.5);
    for k in 0..=6 {
        let alpha = 15.0 * f64::from(k);
        fig.line(point(alpha, 0.0), point(alpha, 1.0), grid);
        fig.label(
            point(alpha, 0.0),
            DVec2::new(0.0, 18.0),
            &format!("{alpha}°"),
            13.0,
            palette::INK,
            Anchor::Center,
        );
    }
    for k in 0..=4 {
        let value = 0.25 * f64::from(k);
        fig.line(point(0.0, value), point(MAX_ANGLE, value), grid);
        fig.label(
            point(0.0, value),
            DVec2::new(-8.0, 4.0),
            &num(value),
            13.0,
            palette::INK,
            Anchor::Right,
        );
    }
    fig.line(point(0.0, 0.0), point(MAX_ANGLE, 0.0), ink);
    fig.line(point(0.0, 0.0), point(0.0, 1.0), ink);
    fig.label(
        point(MAX_ANGLE, 0.0),
        DVec2::new(0.0, 38.0),
        "α between R and V →",
        14.0,
        palette::INK,
        Anchor::Right,
    );
    fig.label(
        point(0.0, 1.0),
        DVec2::new(10.0, -8.0),
        "↑ (R·V)^shininess",
        14.0,
        palette::INK,
        Anchor::Left,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_curve_is_the_shaders_cosine_power() {
        // Tolerance: R·V comes out of a few unit-vector products and a
        // subtraction, a few ε from cos α; raised to n, that is n times as many
        // relative (4e-13 at n = 320), far below what a figure shows.
        for n in [1.0, 5.0, 40.0, 320.0] {
            let points = curve(n);
            assert_eq!(points.len(), SAMPLES);
            for &(alpha, value) in &points {
                let exact = alpha.to_radians().cos().powf(n);
                assert!(
                    (value - exact).abs() <= 1e-14 * n + 1e-15,
                    "n {n}, α {alpha}: {value} against {exact}"
                );
            }
            // The half level is where the shader's factor is ½.
            let half = specular(angle_at(0.5, n), n);
            assert!((half - 0.5).abs() < 1e-12, "n {n}: {half}");
        }
        // The larger the exponent, the narrower the lobe.
        assert!(angle_at(0.5, 320.0) < angle_at(0.5, 40.0));
        assert!(angle_at(0.5, 40.0) < angle_at(0.5, 5.0));
    }

    #[test]
    fn the_figure_draws_each_curve_through_the_formulas_values() {
        let shininess = [40.0, 5.0];
        let fig = draw(&shininess, 1000, 640).unwrap();
        let (w, _) = fig.size();
        let rgb = fig.rgb();
        let color_near = |p: DVec2, color: [u8; 3]| {
            let c = fig.to_px(p);
            (-2..=2).any(|dy: i32| {
                (-2..=2).any(|dx: i32| {
                    let (x, y) = (c.x as i32 + dx, c.y as i32 + dy);
                    let i = (y as u32 * w + x as u32) as usize * 3;
                    rgb[i..i + 3] == color
                })
            })
        };
        // Points of each curve away from the grid and the half marks: the
        // curve's pixels there are its pen's color.
        for (n, color, alphas) in [
            (40.0_f64, palette::PRIMARY, [4.0_f64, 20.0, 26.0]),
            (5.0, palette::REFRACTED, [20.0, 50.0, 70.0]),
        ] {
            for alpha in alphas {
                let value = alpha.to_radians().cos().powf(n);
                assert!(
                    color_near(point(alpha, value), color),
                    "shininess {n} at α = {alpha}°: no curve at ({alpha}, {value})"
                );
            }
        }
        // And not where the formula does not go: shininess 40 at 50° is ≈ 0,
        // not 0.6.
        assert!(!color_near(point(50.0, 0.6), palette::PRIMARY));
    }
}
