//! The diagram pane: the selected pixel's rays in Braille dots, with the same
//! projection and honesty rules as `raytree diagram`; while stepping, only the
//! rays found so far; the selected ray in magenta over the rest.

use glam::DVec2;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::canvas::{Canvas, Context, Line as CanvasLine, Points};
use ratatui::widgets::{Block, Borders, Paragraph};

use crate::figure::clip::{clip_line, clip_segment};
use crate::figure::pen::Rgb;
use crate::figure::pen::palette;
use crate::inspector::app::App;
use crate::inspector::colors::term_color;
use crate::views::diagram::layout::Layout as DiagramLayout;
use crate::views::diagram::projection::Outline;

/// Draws the diagram pane.
pub fn draw_diagram(frame: &mut Frame, app: &App, area: Rect, tc: bool) {
    let title = [
        " diagram: plane of incidence, world up on top ",
        " diagram: plane of incidence ",
        " diagram ",
    ]
    .into_iter()
    .find(|t| t.chars().count() + 2 <= usize::from(area.width))
    .unwrap_or("");
    let block = Block::default().borders(Borders::ALL).title(title);
    if app.trace().is_none() || app.scene().is_none() {
        frame.render_widget(Paragraph::new("no scene: no diagram").block(block), area);
        return;
    }
    let Some(lay) = app.diagram() else {
        return;
    };
    let (lo, hi) = braille_window(&lay, block.inner(area));
    let selected = app.selected_item().map(|i| i.node());
    let canvas = Canvas::default()
        .block(block)
        .marker(Marker::Braille)
        .x_bounds([lo.x, hi.x])
        .y_bounds([lo.y, hi.y])
        .paint(move |ctx: &mut Context| {
            paint_outlines(ctx, &lay, (lo, hi), tc);
            paint_rays(ctx, &lay, selected, (lo, hi), tc);
        });
    frame.render_widget(canvas, area);
}

/// The layout's window widened to the pane's shape. Braille dots are about
/// square: 2 across and 4 down per cell, a cell twice as tall as wide.
fn braille_window(lay: &DiagramLayout, inner: Rect) -> (DVec2, DVec2) {
    let (dots_w, dots_h) = (
        f64::from(inner.width.max(1)) * 2.0,
        f64::from(inner.height.max(1)) * 4.0,
    );
    let (lo, hi) = lay.window;
    let size = (hi - lo).max(DVec2::splat(1e-9));
    let center = (lo + hi) / 2.0;
    let per_dot = (size.x / dots_w).max(size.y / dots_h);
    let half = DVec2::new(dots_w, dots_h) * per_dot / 2.0;
    (center - half, center + half)
}

fn segment(ctx: &mut Context, a: DVec2, b: DVec2, color: Color) {
    ctx.draw(&CanvasLine {
        x1: a.x,
        y1: a.y,
        x2: b.x,
        y2: b.y,
        color,
    });
}

/// A dotted line: every other short piece, for ghosts and rays passing an object.
fn dotted(ctx: &mut Context, a: DVec2, b: DVec2, color: Color, step: f64) {
    let n = ((b - a).length() / step).ceil().clamp(1.0, 400.0) as u32;
    for k in (0..n).step_by(2) {
        let (s0, s1) = (f64::from(k) / f64::from(n), f64::from(k + 1) / f64::from(n));
        segment(ctx, a + (b - a) * s0, a + (b - a) * s1, color);
    }
}

fn outline_lines(outline: &Outline, (lo, hi): (DVec2, DVec2)) -> Vec<[DVec2; 2]> {
    match outline {
        Outline::Ellipse { center, axes } => {
            let at = |k: u32| {
                let t = std::f64::consts::TAU * f64::from(k) / 96.0;
                *center + t.cos() * axes[0] + t.sin() * axes[1]
            };
            (0..96).map(|k| [at(k), at(k + 1)]).collect()
        }
        Outline::Line { point, dir, .. } => clip_line(*point, *dir, lo, hi)
            .map(|(a, b)| vec![[a, b]])
            .unwrap_or_default(),
        Outline::Polygon { points } => (0..points.len())
            .map(|k| [points[k], points[(k + 1) % points.len()]])
            .collect(),
        Outline::Segments { segments } => segments.clone(),
        Outline::Parallel => Vec::new(),
    }
}

/// Every object laid out: its silhouette dotted and dim, what the drawing
/// plane cuts of it solid (none whose silhouette lies outside the pane); and
/// the image plane.
fn paint_outlines(ctx: &mut Context, lay: &DiagramLayout, window: (DVec2, DVec2), tc: bool) {
    let step = (window.1 - window.0).max_element() / 120.0;
    let outside = |(lo, hi): (DVec2, DVec2)| hi.cmplt(window.0).any() || lo.cmpgt(window.1).any();
    for shape in &lay.objects {
        if shape.silhouette.bounds().is_some_and(outside) {
            continue;
        }
        for [a, b] in outline_lines(&shape.silhouette, window) {
            dotted(ctx, a, b, term_color([90, 90, 90], tc), step / 3.0);
        }
        if let Some(section) = &shape.section {
            let c = if shape.touched {
                [200, 200, 200]
            } else {
                [140, 140, 140]
            };
            for [a, b] in outline_lines(section, window) {
                segment(ctx, a, b, term_color(c, tc));
            }
        }
    }
    if let Some((a, b, _)) = lay.image_plane {
        segment(ctx, a, b, Color::Gray);
    }
}

/// The rays (the selected one last, in its own color, over the others), the
/// hits, the lights and the eye.
fn paint_rays(
    ctx: &mut Context,
    lay: &DiagramLayout,
    selected: Option<usize>,
    (lo, hi): (DVec2, DVec2),
    tc: bool,
) {
    let step = (hi - lo).max_element() / 120.0;
    let chosen =
        |s: &&crate::views::diagram::layout::Segment| Some(s.node) == selected && s.stroke.arrow();
    let mut order: Vec<_> = lay.segments.iter().collect();
    order.sort_by_key(|s| (chosen(s), s.stroke.arrow()));
    for s in order {
        let color = if chosen(&s) {
            term_color(SELECTED, tc)
        } else {
            term_color(s.stroke.pen().color, tc)
        };
        for (from, to, passing, _) in s.pieces() {
            let Some((a, b)) = clip_segment(from, to, lo, hi) else {
                continue;
            };
            if passing {
                dotted(ctx, a, b, color, step);
            } else {
                segment(ctx, a, b, color);
            }
        }
    }
    let hits: Vec<(f64, f64)> = lay.hits.iter().map(|h| (h.at.x, h.at.y)).collect();
    ctx.draw(&Points {
        coords: &hits,
        color: Color::White,
    });
    let lights: Vec<(f64, f64)> = lay.lights.iter().map(|p| (p.x, p.y)).collect();
    ctx.draw(&Points {
        coords: &lights,
        color: term_color(palette::LIGHT, tc),
    });
    ctx.print(
        lay.eye.x,
        lay.eye.y,
        Span::styled("eye", Style::default().fg(Color::Gray)),
    );
}

/// The selected ray's color in the diagram pane: apart from every ray kind and
/// from the gray outlines.
pub const SELECTED: Rgb = [255, 0, 255];
