//! A figure as SVG, beside its PNG: every primitive that paints the page's
//! pixels also writes one element here when recording is on, in the same
//! pixel coordinates, so a diagram can be shown as vectors (the book's players
//! zoom and highlight parts of one) and still match its PNG shape for shape.
//! Text is written as text in the same font family, not as glyph outlines.

use std::collections::BTreeSet;
use std::fmt::Write;

use glam::DVec2;

use crate::figure::pen::{Pen, Rgb};

/// The elements drawn so far, and the frame's clip path.
#[derive(Clone, Debug)]
pub struct Svg {
    width: u32,
    height: u32,
    clip_id: String,
    defs: String,
    body: String,
    /// Attributes every element gets while set ([`Svg::tag`]).
    tag: String,
    /// Every tag an element was written with: what the drawing holds of
    /// each tagged part, known without reading the document back.
    tagged: BTreeSet<String>,
}

/// How a shape is painted: its fill and its outline.
#[derive(Clone, Copy, Debug)]
pub struct Paint {
    /// The fill color and its opacity (255 opaque).
    pub fill: Option<(Rgb, u8)>,
    /// The outline.
    pub stroke: Option<Pen>,
    /// Whether the shape is clipped to the frame.
    pub clip: bool,
}

impl Svg {
    /// An empty page of `width × height` pixels in `paper`, clipping to `frame`
    /// (left, top, width, height).
    pub fn new(width: u32, height: u32, paper: Rgb, frame: [f32; 4]) -> Self {
        let [x, y, w, h] = frame;
        // Named by its rectangle, so the same figure is the same file every
        // time (the book compares them), and panels pasted onto one page
        // share a clip path exactly when they clip alike.
        let clip_id = format!(
            "frame-{}-{}-{}-{}",
            num(x.into()),
            num(y.into()),
            num(w.into()),
            num(h.into())
        )
        .replace('.', "_");
        let defs = format!(
            "<clipPath id=\"{clip_id}\"><rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\"/></clipPath>"
        );
        let body = format!(
            "<rect width=\"{width}\" height=\"{height}\" fill=\"{}\"/>\n",
            hex(paper)
        );
        Svg {
            width,
            height,
            clip_id,
            defs,
            body,
            tag: String::new(),
            tagged: BTreeSet::new(),
        }
    }

    /// Marks what is written next with `attributes` (`data-ray="2"
    /// data-step="7"`), until set again: a player reveals a diagram part by
    /// part, so each part says which ray it belongs to and from which step
    /// of the algorithm it is drawn. Empty for parts that are always there.
    pub fn tag(&mut self, attributes: &str) {
        self.tag = if attributes.is_empty() {
            String::new()
        } else {
            format!(" {attributes}")
        };
    }

    /// The tags elements were written with so far ([`Svg::tag`]'s attributes).
    pub fn tags(&self) -> &BTreeSet<String> {
        &self.tagged
    }

    /// Notes the current tag as written on an element.
    fn written(&mut self) {
        if let Some(attributes) = self.tag.strip_prefix(' ')
            && !self.tagged.contains(attributes)
        {
            self.tagged.insert(attributes.to_owned());
        }
    }

    /// A polyline or polygon through `points` (pixels).
    pub fn path(&mut self, points: &[DVec2], close: bool, paint: Paint) {
        if points.len() < 2 {
            return;
        }
        // A path's points to a tenth of a pixel, each after the last kept
        // one by at least that much: an object's outline has hundreds of
        // points, and a player's page carries the whole diagram.
        let mut d = String::new();
        let mut last: Option<(String, String)> = None;
        for p in points {
            let at = (coordinate(p.x), coordinate(p.y));
            if last.as_ref() == Some(&at) {
                continue;
            }
            let _ = write!(
                d,
                "{}{} {}",
                if last.is_none() { "M" } else { " " },
                at.0,
                at.1
            );
            last = Some(at);
        }
        if close {
            d.push_str(" Z");
        }
        let attributes = self.paint(paint);
        let _ = writeln!(self.body, "<path d=\"{d}\"{attributes}{}/>", self.tag);
        self.written();
    }

    /// A circle of `radius` pixels around `center`.
    pub fn circle(&mut self, center: DVec2, radius: f32, paint: Paint) {
        let attributes = self.paint(paint);
        let _ = writeln!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{radius}\"{attributes}{}/>",
            num(center.x),
            num(center.y),
            self.tag
        );
        self.written();
    }

    /// `text` with its baseline starting at `at` (pixels), `size` pixels high,
    /// in white-haloed `color`.
    pub fn text(&mut self, at: DVec2, text: &str, size: f32, color: Rgb, clip: bool) {
        let clip = if clip {
            self.clip_attribute()
        } else {
            String::new()
        };
        let _ = writeln!(
            self.body,
            "<text x=\"{}\" y=\"{}\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"{size}\" fill=\"{}\" stroke=\"#ffffff\" stroke-width=\"2\" paint-order=\"stroke\"{clip}{}>{}</text>",
            num(at.x),
            num(at.y),
            hex(color),
            self.tag,
            escape(text)
        );
        self.written();
    }

    /// An 8-bit RGB image, `width` pixels wide, with its top-left corner at `(x, y)`.
    pub fn image(&mut self, x: u32, y: u32, width: u32, rgb: &[u8]) {
        let height = (rgb.len() / 3) as u32 / width.max(1);
        let mut png = Vec::new();
        let encoded = image::ImageEncoder::write_image(
            image::codecs::png::PngEncoder::new(&mut png),
            rgb,
            width,
            height,
            image::ExtendedColorType::Rgb8,
        );
        if encoded.is_ok() {
            let _ = writeln!(
                self.body,
                "<image x=\"{x}\" y=\"{y}\" width=\"{width}\" height=\"{height}\" image-rendering=\"pixelated\" href=\"data:image/png;base64,{}\"/>",
                base64(&png)
            );
        }
    }

    /// Another page's elements, its top-left corner at `(x, y)`.
    pub fn paste(&mut self, panel: &Svg, x: i32, y: i32) {
        if !self.defs.contains(&panel.defs) {
            self.defs.push_str(&panel.defs);
        }
        let _ = writeln!(
            self.body,
            "<g transform=\"translate({x} {y})\">\n{}</g>",
            panel.body
        );
        self.tagged.extend(panel.tagged.iter().cloned());
    }

    /// The whole document.
    pub fn document(&self) -> String {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n<defs>{}</defs>\n{}</svg>\n",
            self.defs,
            self.body,
            w = self.width,
            h = self.height
        )
    }

    fn clip_attribute(&self) -> String {
        format!(" clip-path=\"url(#{})\"", self.clip_id)
    }

    fn paint(&self, paint: Paint) -> String {
        let mut out = String::new();
        match paint.fill {
            Some((c, alpha)) => {
                let _ = write!(out, " fill=\"{}\"", hex(c));
                if alpha < 255 {
                    let _ = write!(out, " fill-opacity=\"{}\"", opacity(alpha));
                }
            }
            None => out.push_str(" fill=\"none\""),
        }
        if let Some(pen) = paint.stroke {
            let _ = write!(
                out,
                " stroke=\"{}\" stroke-width=\"{}\"",
                hex(pen.color),
                pen.width
            );
            if pen.alpha < 255 {
                let _ = write!(out, " stroke-opacity=\"{}\"", opacity(pen.alpha));
            }
            if !pen.dash.is_empty() {
                let dash: Vec<String> = pen
                    .dash
                    .iter()
                    .map(|d| num(f64::from(d * pen.dash_scale)))
                    .collect();
                let _ = write!(out, " stroke-dasharray=\"{}\"", dash.join(" "));
            }
        }
        if paint.clip {
            out.push_str(&self.clip_attribute());
        }
        out
    }
}

/// A path's pixel coordinate to one decimal (a tenth of a pixel is invisible
/// at the size a page shows a figure).
fn coordinate(x: f64) -> String {
    trimmed(format!("{x:.1}"))
}

/// A pixel coordinate to two decimals (a hundredth of a pixel is invisible).
fn num(x: f64) -> String {
    trimmed(format!("{x:.2}"))
}

/// A fixed-point number without its trailing zeros (and `-0` as `0`).
fn trimmed(s: String) -> String {
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

fn opacity(alpha: u8) -> String {
    num(f64::from(alpha) / 255.0)
}

fn hex(c: Rgb) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// Text made safe inside an XML element.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Standard base64 (RFC 4648), for an image embedded as a data URI.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * k) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::canvas::{Anchor, Figure};
    use crate::figure::pen::palette;

    #[test]
    fn base64_is_rfc_4648() {
        // RFC 4648 §10's test vectors.
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    fn drawn(svg: bool) -> Figure {
        let fig = Figure::new(200, 120, 20.0, 10.0).unwrap();
        let mut fig = if svg { fig.with_svg() } else { fig };
        fig.fit(DVec2::ZERO, DVec2::new(4.0, 2.0), 0.0);
        fig.line(
            DVec2::ZERO,
            DVec2::new(4.0, 2.0),
            Pen::dashed(palette::REFLECTED, 2.0),
        );
        fig.arrow(
            DVec2::new(0.0, 2.0),
            DVec2::new(2.0, 1.0),
            Pen::solid(palette::PRIMARY, 2.5),
        );
        fig.dot(
            DVec2::new(1.0, 1.0),
            4.0,
            palette::LIGHT,
            Some(palette::INK),
        );
        fig.label(
            DVec2::new(2.0, 1.0),
            DVec2::ZERO,
            "P1 <a & b>",
            12.0,
            palette::INK,
            Anchor::Left,
        );
        fig.caption(&["a caption".to_owned()], 12.0);
        fig
    }

    #[test]
    fn every_shape_is_written_where_the_png_paints_it() {
        let fig = drawn(true);
        let svg = fig.svg().expect("recording was on");
        assert!(
            svg.starts_with(
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"120\""
            )
        );
        // The line from (0, 0) to (4, 2) in diagram units lands where to_px puts it.
        let (a, b) = (fig.to_px(DVec2::ZERO), fig.to_px(DVec2::new(4.0, 2.0)));
        let d = format!(
            "M{} {} {} {}",
            coordinate(a.x),
            coordinate(a.y),
            coordinate(b.x),
            coordinate(b.y)
        );
        assert!(svg.contains(&d), "no {d} in\n{svg}");
        assert!(
            svg.contains("stroke=\"#009e73\"") && svg.contains("stroke-dasharray"),
            "{svg}"
        );
        assert_eq!(svg.matches("<circle").count(), 1, "{svg}");
        assert!(svg.contains(">P1 &lt;a &amp; b&gt;</text>"), "{svg}");
        assert!(svg.contains(">a caption</text>"), "{svg}");
        // Every element is closed: as many openings as closings.
        for tag in ["svg", "defs", "text", "clipPath"] {
            assert_eq!(
                svg.matches(&format!("<{tag}")).count(),
                svg.matches(&format!("</{tag}>")).count(),
                "{tag} in\n{svg}"
            );
        }
    }

    #[test]
    fn recording_svg_leaves_the_png_as_it_was() {
        assert_eq!(drawn(true).png(), drawn(false).png());
        assert!(drawn(false).svg().is_none());
    }

    #[test]
    fn a_pasted_panel_and_an_image_come_along() {
        let mut page = Figure::page(300, 100).unwrap().with_svg();
        page.paste(&drawn(true), 100, 0);
        page.image(0, 0, 2, &[255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255]);
        let svg = page.svg().unwrap();
        assert!(svg.contains("<g transform=\"translate(100 0)\">"), "{svg}");
        assert!(
            svg.contains("<image x=\"0\" y=\"0\" width=\"2\" height=\"2\""),
            "{svg}"
        );
        assert_eq!(
            svg.matches("<clipPath").count(),
            2,
            "the page's and the panel's"
        );
        // The same figure twice is the same file.
        assert_eq!(drawn(true).svg(), drawn(true).svg());
    }
}
