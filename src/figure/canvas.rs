//! The canvas every figure draws on: a page with a frame, a view from drawing
//! coordinates (y up) into it, and the shapes (lines, arrows, arcs, polygons,
//! ellipses, dots, lights, images, pasted panels). tiny-skia draws them; text
//! is in [`crate::figure::text`].

use glam::DVec2;

use crate::figure::pen::{Pen, Rgb, palette};
use crate::figure::svg::{Paint as SvgPaint, Svg};
use tiny_skia::{
    Color, FillRule, Mask, Paint, PathBuilder, Pixmap, Rect, Stroke, StrokeDash, Transform,
};

/// Where a label sits relative to its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at the point (baseline).
    Left,
    /// The text is centered on the point.
    Center,
    /// The text ends at the point.
    Right,
}

/// A figure: a page with a frame, and a view from diagram coordinates into it.
pub struct Figure {
    pub(super) pixmap: Pixmap,
    pub(super) frame: Rect,
    clip: Mask,
    scale: f64,
    offset: DVec2,
    /// The same drawing as SVG, when asked for ([`Figure::with_svg`]).
    pub(super) svg: Option<Svg>,
}

impl Figure {
    /// A white page of `width × height` pixels whose plot frame leaves `top`
    /// pixels above it (for a caption) and `margin` around the other sides.
    pub fn new(width: u32, height: u32, top: f32, margin: f32) -> Option<Self> {
        let mut pixmap = Pixmap::new(width, height)?;
        pixmap.fill(color(palette::PAPER));
        let frame = Rect::from_xywh(
            margin,
            top,
            width as f32 - 2.0 * margin,
            height as f32 - top - margin,
        )?;
        let mut clip = Mask::new(width, height)?;
        clip.fill_path(
            &PathBuilder::from_rect(frame),
            FillRule::Winding,
            false,
            Transform::identity(),
        );
        Some(Self {
            pixmap,
            frame,
            clip,
            scale: 1.0,
            offset: DVec2::ZERO,
            svg: None,
        })
    }

    /// The same figure, also recording every shape as SVG (see [`Figure::svg`]).
    pub fn with_svg(mut self) -> Self {
        let f = self.frame;
        let (w, h) = (self.pixmap.width(), self.pixmap.height());
        self.svg = Some(Svg::new(
            w,
            h,
            palette::PAPER,
            [f.left(), f.top(), f.width(), f.height()],
        ));
        self
    }

    /// Tags what is drawn next in the SVG (see [`Svg::tag`]); the PNG is
    /// the same either way.
    pub fn tag(&mut self, attributes: &str) {
        if let Some(svg) = &mut self.svg {
            svg.tag(attributes);
        }
    }

    /// The figure as an SVG document, if it was made [`Figure::with_svg`].
    pub fn svg(&self) -> Option<String> {
        self.svg.as_ref().map(Svg::document)
    }

    /// The tags the SVG's elements carry ([`Figure::tag`]), beside
    /// [`Figure::svg`]: what was drawn of each tagged part.
    pub fn svg_tags(&self) -> Option<&std::collections::BTreeSet<String>> {
        self.svg.as_ref().map(Svg::tags)
    }

    /// The plot frame, in pixels.
    pub fn frame(&self) -> Rect {
        self.frame
    }

    /// Fits the diagram box `lo..hi` into the frame with equal scale on both axes,
    /// centered, leaving `margin` (a share of the box) around it.
    pub fn fit(&mut self, lo: DVec2, hi: DVec2, margin: f64) {
        let size = (hi - lo).max(DVec2::splat(1e-9));
        let (lo, size) = (lo - size * margin, size * (1.0 + 2.0 * margin));
        let f = self.frame;
        self.scale = (f64::from(f.width()) / size.x).min(f64::from(f.height()) / size.y);
        let used = size * self.scale;
        self.offset = DVec2::new(
            f64::from(f.left()) + (f64::from(f.width()) - used.x) / 2.0,
            f64::from(f.bottom()) - (f64::from(f.height()) - used.y) / 2.0,
        ) - DVec2::new(lo.x, -lo.y) * self.scale;
    }

    /// Pixels per diagram unit.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Diagram coordinates to pixel coordinates (y down).
    pub fn to_px(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            p.x * self.scale + self.offset.x,
            -p.y * self.scale + self.offset.y,
        )
    }

    /// Pixel coordinates to diagram coordinates.
    pub fn from_px(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            (p.x - self.offset.x) / self.scale,
            -(p.y - self.offset.y) / self.scale,
        )
    }

    /// The frame in diagram coordinates: `(lo, hi)`.
    pub fn visible(&self) -> (DVec2, DVec2) {
        let f = self.frame;
        let a = self.from_px(DVec2::new(f64::from(f.left()), f64::from(f.bottom())));
        let b = self.from_px(DVec2::new(f64::from(f.right()), f64::from(f.top())));
        (a, b)
    }

    /// Whether drawing point `p` is inside the visible window.
    pub fn shows(&self, p: DVec2) -> bool {
        let (lo, hi) = self.visible();
        p.cmpge(lo).all() && p.cmple(hi).all()
    }

    pub(super) fn stroke_px(&mut self, points: &[DVec2], pen: Pen, close: bool) {
        if let Some(svg) = &mut self.svg {
            let paint = SvgPaint {
                fill: None,
                stroke: Some(pen),
                clip: true,
            };
            svg.path(points, close, paint);
        }
        let Some(path) = polyline(points, close) else {
            return;
        };
        let mut stroke = Stroke {
            width: pen.width,
            ..Stroke::default()
        };
        if !pen.dash.is_empty() {
            let dash = pen.dash.iter().map(|d| d * pen.dash_scale).collect();
            stroke.dash = StrokeDash::new(dash, 0.0);
        }
        self.pixmap.stroke_path(
            &path,
            &paint(pen.color, pen.alpha),
            &stroke,
            Transform::identity(),
            Some(&self.clip),
        );
    }

    fn fill_px(&mut self, points: &[DVec2], fill: Rgb, alpha: u8) {
        if let Some(svg) = &mut self.svg {
            let paint = SvgPaint {
                fill: Some((fill, alpha)),
                stroke: None,
                clip: true,
            };
            svg.path(points, true, paint);
        }
        if let Some(path) = polyline(points, true) {
            self.pixmap.fill_path(
                &path,
                &paint(fill, alpha),
                FillRule::Winding,
                Transform::identity(),
                Some(&self.clip),
            );
        }
    }

    /// A line from `a` to `b` (diagram coordinates), clipped to the frame.
    pub fn line(&mut self, a: DVec2, b: DVec2, pen: Pen) {
        let (a, b) = (self.to_px(a), self.to_px(b));
        self.stroke_px(&[a, b], pen, false);
    }

    /// A line from `a` to `b` in the SVG only, not in the PNG: a part a
    /// player shows for a while and the still figure never has (its tag
    /// should hide it, `display="none"`).
    pub fn svg_only_line(&mut self, a: DVec2, b: DVec2, pen: Pen) {
        let (a, b) = (self.to_px(a), self.to_px(b));
        if let Some(svg) = &mut self.svg {
            let paint = SvgPaint {
                fill: None,
                stroke: Some(pen),
                clip: true,
            };
            svg.path(&[a, b], false, paint);
        }
    }

    /// [`Figure::arrow`] in the SVG only, as [`Figure::svg_only_line`].
    pub fn svg_only_arrow(&mut self, a: DVec2, b: DVec2, pen: Pen) {
        let (pa, pb) = (self.to_px(a), self.to_px(b));
        let (Some(svg), Some(dir)) = (&mut self.svg, (pb - pa).try_normalize()) else {
            return;
        };
        let head = (4.0 * f64::from(pen.width)).max(9.0);
        let (base, side) = (pb - dir * head, dir.perp() * head * 0.4);
        let stroke = SvgPaint {
            fill: None,
            stroke: Some(pen),
            clip: true,
        };
        svg.path(&[pa, base], false, stroke);
        let fill = SvgPaint {
            fill: Some((pen.color, pen.alpha)),
            stroke: None,
            clip: true,
        };
        svg.path(&[pb, base + side, base - side], true, fill);
    }

    /// A line from `a` to `b` with an arrowhead at `b`.
    pub fn arrow(&mut self, a: DVec2, b: DVec2, pen: Pen) {
        let (pa, pb) = (self.to_px(a), self.to_px(b));
        let Some(dir) = (pb - pa).try_normalize() else {
            return;
        };
        let head = (4.0 * f64::from(pen.width)).max(9.0);
        let base = pb - dir * head;
        self.stroke_px(&[pa, base], pen, false);
        let side = dir.perp() * head * 0.4;
        self.fill_px(&[pb, base + side, base - side], pen.color, pen.alpha);
    }

    /// An arc of `radius` pixels around diagram point `center`, from unit
    /// direction `from` to `to` (diagram coordinates) the short way.
    pub fn arc(&mut self, center: DVec2, radius: f64, from: DVec2, to: DVec2, pen: Pen) {
        let c = self.to_px(center);
        // Pixels run y down: a diagram angle a is the pixel angle -a.
        let a0 = -from.y.atan2(from.x);
        let mut sweep = -(to.y.atan2(to.x)) - a0;
        if sweep > std::f64::consts::PI {
            sweep -= std::f64::consts::TAU;
        } else if sweep < -std::f64::consts::PI {
            sweep += std::f64::consts::TAU;
        }
        let points: Vec<DVec2> = (0..=24)
            .map(|k| {
                let a = a0 + sweep * f64::from(k) / 24.0;
                c + radius * DVec2::new(a.cos(), a.sin())
            })
            .collect();
        self.stroke_px(&points, pen, false);
    }

    /// A cross of half-size `half` pixels at diagram point `at`.
    pub fn cross(&mut self, at: DVec2, half: f64, pen: Pen) {
        let c = self.to_px(at);
        self.stroke_px(&[c - half, c + half], pen, false);
        self.stroke_px(
            &[c + DVec2::new(-half, half), c + DVec2::new(half, -half)],
            pen,
            false,
        );
    }

    /// A line between two pixel positions.
    pub fn line_px(&mut self, a: DVec2, b: DVec2, pen: Pen) {
        self.stroke_px(&[a, b], pen, false);
    }

    /// A box between two pixel corners, filled and outlined.
    pub fn rect_px(&mut self, min: DVec2, max: DVec2, fill: Option<(Rgb, u8)>, pen: Option<Pen>) {
        let corners = [min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)];
        if let Some((c, a)) = fill {
            self.fill_px(&corners, c, a);
        }
        if let Some(pen) = pen {
            self.stroke_px(&corners, pen, true);
        }
    }

    /// A closed polygon through `points`, filled and outlined.
    pub fn polygon(&mut self, points: &[DVec2], fill: Option<(Rgb, u8)>, pen: Option<Pen>) {
        let px: Vec<DVec2> = points.iter().map(|&p| self.to_px(p)).collect();
        if let Some((c, a)) = fill {
            self.fill_px(&px, c, a);
        }
        if let Some(pen) = pen {
            self.stroke_px(&px, pen, true);
        }
    }

    /// The ellipse `center + cos θ·axes[0] + sin θ·axes[1]`.
    pub fn ellipse(
        &mut self,
        center: DVec2,
        axes: [DVec2; 2],
        fill: Option<(Rgb, u8)>,
        pen: Option<Pen>,
    ) {
        let points: Vec<DVec2> = (0..256)
            .map(|i| {
                let t = std::f64::consts::TAU * f64::from(i) / 256.0;
                center + t.cos() * axes[0] + t.sin() * axes[1]
            })
            .collect();
        self.polygon(&points, fill, pen);
    }

    /// A filled dot of `radius` pixels at `p`, with an outline.
    pub fn dot(&mut self, p: DVec2, radius: f32, fill: Rgb, outline: Option<Rgb>) {
        let c = self.to_px(p);
        if let Some(svg) = &mut self.svg {
            let paint = SvgPaint {
                fill: Some((fill, 255)),
                stroke: outline.map(|o| Pen::solid(o, 1.2)),
                clip: true,
            };
            svg.circle(c, radius, paint);
        }
        if let Some(path) = PathBuilder::from_circle(c.x as f32, c.y as f32, radius) {
            self.pixmap.fill_path(
                &path,
                &paint(fill, 255),
                FillRule::Winding,
                Transform::identity(),
                Some(&self.clip),
            );
            if let Some(o) = outline {
                let stroke = Stroke {
                    width: 1.2,
                    ..Stroke::default()
                };
                self.pixmap.stroke_path(
                    &path,
                    &paint(o, 255),
                    &stroke,
                    Transform::identity(),
                    Some(&self.clip),
                );
            }
        }
    }

    /// A light: a small sun at `p`.
    pub fn light(&mut self, p: DVec2) {
        let c = self.to_px(p);
        for k in 0..8 {
            let a = std::f64::consts::TAU * f64::from(k) / 8.0;
            let d = DVec2::new(a.cos(), a.sin());
            self.stroke_px(
                &[c + d * 8.0, c + d * 13.0],
                Pen::solid(palette::INK, 1.5),
                false,
            );
        }
        self.dot(p, 6.0, palette::LIGHT, Some(palette::INK));
    }

    /// A thin border around the frame.
    pub fn frame_border(&mut self) {
        let f = self.frame;
        if let Some(svg) = &mut self.svg {
            let corners = [
                (f.left(), f.top()),
                (f.right(), f.top()),
                (f.right(), f.bottom()),
                (f.left(), f.bottom()),
            ];
            let points: Vec<DVec2> = corners
                .iter()
                .map(|&(x, y)| DVec2::new(f64::from(x), f64::from(y)))
                .collect();
            let paint = SvgPaint {
                fill: None,
                stroke: Some(Pen::solid([180, 180, 180], 1.0)),
                clip: false,
            };
            svg.path(&points, true, paint);
        }
        let path = PathBuilder::from_rect(f);
        self.pixmap.stroke_path(
            &path,
            &paint([180, 180, 180], 255),
            &Stroke {
                width: 1.0,
                ..Stroke::default()
            },
            Transform::identity(),
            None,
        );
    }

    /// A blank page of `width × height` pixels to paste panels onto.
    pub fn page(width: u32, height: u32) -> Option<Self> {
        Self::new(width, height, 0.0, 0.0)
    }

    /// Copies `panel` onto this page with its top-left corner at pixel `(x, y)`:
    /// how a figure of several panels is put together.
    pub fn paste(&mut self, panel: &Figure, x: i32, y: i32) {
        if let (Some(svg), Some(inner)) = (&mut self.svg, &panel.svg) {
            svg.paste(inner, x, y);
        }
        self.pixmap.draw_pixmap(
            x,
            y,
            panel.pixmap.as_ref(),
            &tiny_skia::PixmapPaint::default(),
            Transform::identity(),
            None,
        );
    }

    /// Copies an 8-bit RGB image (`rgb`, rows top first, `width` pixels wide)
    /// onto the page with its top-left corner at pixel `(x, y)`: a rendered
    /// image inside a figure, pixel for pixel.
    pub fn image(&mut self, x: u32, y: u32, width: u32, rgb: &[u8]) {
        if let Some(svg) = &mut self.svg {
            svg.image(x, y, width, rgb);
        }
        let (w, h) = (self.pixmap.width(), self.pixmap.height());
        let data = self.pixmap.data_mut();
        for (i, p) in rgb.chunks_exact(3).enumerate() {
            let (px, py) = (x + i as u32 % width.max(1), y + i as u32 / width.max(1));
            if px < w && py < h {
                let at = (py as usize * w as usize + px as usize) * 4;
                data[at..at + 4].copy_from_slice(&[p[0], p[1], p[2], 255]);
            }
        }
    }

    /// The figure as 8-bit RGB, rows top first.
    pub fn rgb(&self) -> Vec<u8> {
        // Everything is drawn on an opaque page, so premultiplied equals straight RGB.
        self.pixmap
            .data()
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect()
    }

    /// The figure's size in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.pixmap.width(), self.pixmap.height())
    }

    /// The figure as PNG bytes.
    pub fn png(&self) -> Vec<u8> {
        let mut out = Vec::new();
        let encoder = image::codecs::png::PngEncoder::new(&mut out);
        image::ImageEncoder::write_image(
            encoder,
            &self.rgb(),
            self.pixmap.width(),
            self.pixmap.height(),
            image::ExtendedColorType::Rgb8,
        )
        .expect("PNG encoding into memory cannot fail");
        out
    }
}

/// The path through `points` (pixels), closed or open.
fn polyline(points: &[DVec2], close: bool) -> Option<tiny_skia::Path> {
    let mut pb = PathBuilder::new();
    for (i, p) in points.iter().enumerate() {
        if i == 0 {
            pb.move_to(p.x as f32, p.y as f32)
        } else {
            pb.line_to(p.x as f32, p.y as f32)
        }
    }
    if close {
        pb.close();
    }
    pb.finish()
}

fn color(c: Rgb) -> Color {
    Color::from_rgba8(c[0], c[1], c[2], 255)
}

fn paint(c: Rgb, alpha: u8) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(c[0], c[1], c[2], alpha);
    p.anti_alias = true;
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_maps_the_box_into_the_frame_with_y_up() {
        let mut fig = Figure::new(400, 300, 40.0, 10.0).unwrap();
        fig.fit(DVec2::new(0.0, 0.0), DVec2::new(10.0, 5.0), 0.0);
        // The frame is 380 × 250; the box's aspect 2:1 limits the scale to 38.
        assert_eq!(fig.scale(), 38.0);
        let a = fig.to_px(DVec2::new(0.0, 0.0));
        let b = fig.to_px(DVec2::new(10.0, 5.0));
        assert!((a.x - 10.0).abs() < 1e-9 && b.y < a.y, "{a} {b}");
        assert!(
            fig.from_px(fig.to_px(DVec2::new(3.0, 4.0)))
                .abs_diff_eq(DVec2::new(3.0, 4.0), 1e-12)
        );
    }
}
