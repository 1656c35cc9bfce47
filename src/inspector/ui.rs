//! Drawing the inspector: the image pane (half-block cells, two dots each),
//! the ray tree, the selected ray's numbers, the diagram (Braille canvas, the
//! same projection and colors as `raytree diagram`), the step and status lines.

use glam::{DVec2, DVec3};
use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{Canvas, Context, Line as CanvasLine, Points};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget, Wrap};

use super::app::{App, Areas, Focus, Item};
use crate::io::image::rgb8;
use crate::tree::ray_tree::{RayNode, ShadowOutcomeRecord};
use crate::views::clip::{clip_line, clip_segment};
use crate::views::diagram_layout::{Layout as DiagramLayout, Options, layout};
use crate::views::figure::Rgb;
use crate::views::numbers::num;
use crate::views::pen::palette;
use crate::views::projection::Outline;
use crate::views::text::{describe, kind_name};

/// Every key, for the help overlay and the README.
pub const KEYS: &[(&str, &str)] = &[
    (
        "←↑↓→ / hjkl",
        "move the pixel cursor (image pane) or through the tree (tree pane)",
    ),
    ("click", "select a pixel (image pane) or a line (tree pane)"),
    ("+ / -", "zoom in / out around the cursor"),
    ("g", "go to a pixel: type x,y and Enter"),
    ("Tab", "switch between the image and the tree pane"),
    (
        "Enter / →",
        "expand the selected ray (tree pane); from the image, go to the tree",
    ),
    ("←", "collapse the selected ray, or go to its parent"),
    ("e", "expand the whole tree"),
    (
        "s",
        "show the pixel's next sample (with several samples per pixel)",
    ),
    (
        "PgUp / PgDn",
        "scroll the selected ray's numbers (or the mouse wheel over them)",
    ),
    ("n / space", "next step of the algorithm"),
    ("p / Backspace", "previous step"),
    ("?", "this help"),
    ("q / Esc", "quit"),
];

/// Whether the terminal takes 24-bit color (else the 256-color palette).
pub fn truecolor() -> bool {
    std::env::var("COLORTERM").is_ok_and(|v| v.contains("truecolor") || v.contains("24bit"))
}

fn term_color(c: Rgb, truecolor: bool) -> Color {
    if truecolor {
        Color::Rgb(c[0], c[1], c[2])
    } else {
        // The 6 × 6 × 6 color cube of the 256-color palette.
        let q = |v: u8| (u16::from(v) * 5 + 127) / 255;
        Color::Indexed((16 + 36 * q(c[0]) + 6 * q(c[1]) + q(c[2])) as u8)
    }
}

pub(super) fn swatch(c: DVec3, tc: bool) -> Span<'static> {
    Span::styled("██", Style::default().fg(term_color(rgb8(c), tc)))
}

/// Draws the whole inspector.
pub fn draw(frame: &mut Frame, app: &mut App) {
    let tc = app.truecolor;
    let [main, step_line, status_line] = Layout::vertical([
        Constraint::Min(6),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(frame.area());
    let [left, right] =
        Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(main);
    let [image_area, diagram_area] =
        Layout::vertical([Constraint::Percentage(60), Constraint::Percentage(40)]).areas(left);
    let [tree_area, detail_area] =
        Layout::vertical([Constraint::Percentage(45), Constraint::Percentage(55)]).areas(right);

    let focused = |f: Focus| {
        if app.focus == f {
            Style::default()
                .fg(Color::Yellow)
                .add_modifier(Modifier::BOLD)
        } else {
            Style::default()
        }
    };
    let image_block = Block::default()
        .borders(Borders::ALL)
        .title(" image ")
        .border_style(focused(Focus::Image));
    let tree_block = Block::default()
        .borders(Borders::ALL)
        .title(" ray tree ")
        .border_style(focused(Focus::Tree));
    app.areas = Areas {
        image: image_block.inner(image_area),
        tree: tree_block.inner(tree_area),
        details: detail_area,
    };
    app.request_picture();

    frame.render_widget(image_block, image_area);
    frame.render_widget(ImagePane { app, truecolor: tc }, app.areas.image);
    draw_tree(frame, app, tree_block, tree_area, tc);
    draw_details(frame, app, detail_area, tc);
    draw_diagram(frame, app, diagram_area, tc);

    frame.render_widget(Paragraph::new(step_line_text(app)), step_line);
    frame.render_widget(Paragraph::new(status_line_text(app)), status_line);
    if app.help {
        draw_help(frame);
    }
}

/// The step line: the go-to prompt, the current step with its numbers, or how
/// to start stepping.
fn step_line_text(app: &App) -> Line<'static> {
    let bold = Style::default().add_modifier(Modifier::BOLD);
    match (&app.goto, app.step) {
        (Some(typed), _) => Line::from(vec![
            Span::styled("go to pixel (x,y): ", bold),
            Span::raw(format!("{typed}▏")),
        ]),
        (None, Some(s)) => Line::from(vec![
            Span::styled(format!("step {}/{}: ", s + 1, app.steps.len()), bold),
            Span::raw(
                app.trace
                    .as_ref()
                    .map_or_else(String::new, |t| describe(t, app.sample, &app.steps[s]).0),
            ),
        ]),
        (None, None) => Line::from(format!(
            "press n to step through the algorithm ({} steps), ? for every key",
            app.steps.len()
        )),
    }
}

/// The status line: the pixel, the zoom, the scene, the time to trace, any message.
fn status_line_text(app: &App) -> Line<'static> {
    let (w, h) = app.image_size();
    let mut status = format!(
        "pixel {},{} of {w}×{h} · zoom {}× · {} · traced in {:.2} ms",
        app.cursor.0,
        app.cursor.1,
        1u32 << app.zoom,
        app.source.file,
        app.trace_time.as_secs_f64() * 1e3
    );
    if let Some(t) = app.trace.as_ref().filter(|t| t.samples.len() > 1) {
        status = format!(
            "{status} · sample {} of {} (s: next) · pixel mean {}",
            app.sample + 1,
            t.samples.len(),
            crate::views::numbers::color(t.color)
        );
    }
    if !app.message.is_empty() {
        status = format!("{} · {status}", app.message);
    }
    Line::from(vec![
        Span::styled(status, Style::default().add_modifier(Modifier::DIM)),
        Span::raw("   ? help  q quit"),
    ])
}

struct ImagePane<'a> {
    app: &'a App,
    truecolor: bool,
}

impl Widget for ImagePane<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let app = self.app;
        if app.scene.is_none() {
            Paragraph::new("no scene: the image is not available")
                .wrap(Wrap { trim: true })
                .render(area, buf);
            return;
        }
        let window = app.window();
        let unknown = Color::Rgb(40, 40, 40);
        let dot = |i: u16, j: u16| -> Color {
            if app.picture.as_ref().is_some_and(|p| p.window == window) {
                let p = app.picture.as_ref().expect("checked");
                p.dots[usize::from(j) * usize::from(window.cols) + usize::from(i)]
                    .map_or(Color::Reset, |c| term_color(c, self.truecolor))
            } else {
                unknown
            }
        };
        let cursor = window.dot_of(app.cursor.0, app.cursor.1);
        let mark = Color::Rgb(255, 0, 255);
        for row in 0..area.height {
            for col in 0..area.width {
                let (top, bottom) = (2 * row, 2 * row + 1);
                let fg = if cursor == Some((col, top)) {
                    mark
                } else {
                    dot(col, top)
                };
                let bg = if cursor == Some((col, bottom)) {
                    mark
                } else {
                    dot(col, bottom)
                };
                if let Some(cell) = buf.cell_mut((area.x + col, area.y + row)) {
                    cell.set_symbol("▀").set_fg(fg).set_bg(bg);
                }
            }
        }
    }
}

fn ray_line(app: &App, node: &RayNode, n: usize, tc: bool) -> Vec<Span<'static>> {
    let what = node
        .hit
        .as_ref()
        .map_or("background".to_owned(), |h| format!("'{}'", h.name));
    let mut spans = vec![
        Span::styled(
            format!("{} ", kind_name(node.kind)),
            Style::default()
                .fg(term_color(
                    crate::views::diagram_layout::ray_pen(node.kind).color,
                    tc,
                ))
                .add_modifier(Modifier::BOLD),
        ),
        Span::raw(format!("d{} {what} ", node.depth)),
        swatch(node.color(), tc),
    ];
    let why = app.stop_reason(n);
    if !why.is_empty() {
        spans.push(Span::styled(
            format!(" {why}"),
            Style::default().add_modifier(Modifier::DIM),
        ));
    }
    spans
}

pub(super) fn shadow_text(node: &RayNode, k: usize) -> String {
    let s = &node.shadow_rays[k];
    let what = match &s.outcome {
        ShadowOutcomeRecord::FacesAway => "faces away".to_owned(),
        ShadowOutcomeRecord::Reaches { transmitted } if *transmitted == 1.0 => {
            "reaches the light".to_owned()
        }
        ShadowOutcomeRecord::Reaches { transmitted } => {
            format!("reaches the light, keeping {}", num(*transmitted))
        }
        ShadowOutcomeRecord::Blocked { name, t, .. } => {
            format!("blocked by '{name}' at t = {}", num(*t))
        }
    };
    format!("shadow → '{}': {what}", s.name)
}

fn draw_tree(frame: &mut Frame, app: &App, block: Block, area: Rect, tc: bool) {
    let Some(trace) = &app.trace else {
        frame.render_widget(Paragraph::new("no pixel traced").block(block), area);
        return;
    };
    let nodes = &trace.samples[app.sample].tree.nodes;
    let inner = block.inner(area);
    let step_node = app.step.map(|s| app.steps[s].node);
    let items = app.items();
    let scroll = app.tree_scroll(inner.height);
    let lines: Vec<Line> = items
        .iter()
        .enumerate()
        .skip(scroll)
        .take(usize::from(inner.height))
        .map(|(row, &(item, indent))| {
            let mut spans = vec![Span::raw("  ".repeat(indent))];
            match item {
                Item::Ray(n) => {
                    let marker = if !app.expandable(n) {
                        "  "
                    } else if app.expanded.contains(&n) {
                        "▾ "
                    } else {
                        "▸ "
                    };
                    spans.push(Span::raw(marker));
                    spans.extend(ray_line(app, &nodes[n], n, tc));
                }
                Item::Shadow(n, k) => spans.push(Span::styled(
                    format!("  {}", shadow_text(&nodes[n], k)),
                    Style::default().fg(term_color(palette::SHADOW_REACHES, tc)),
                )),
            }
            let mut line = Line::from(spans);
            if row == app.selected {
                line = line.style(Style::default().add_modifier(Modifier::REVERSED));
            } else if step_node == Some(item.node()) && matches!(item, Item::Ray(_)) {
                line = line.style(Style::default().add_modifier(Modifier::UNDERLINED));
            }
            line
        })
        .collect();
    frame.render_widget(Paragraph::new(lines).block(block), area);
}

fn draw_details(frame: &mut Frame, app: &App, area: Rect, tc: bool) {
    let lines = super::details::details(app, tc);
    let visible = area.height.saturating_sub(2);
    let scroll = app
        .detail_scroll
        .min((lines.len() as u16).saturating_sub(visible));
    let title = if lines.len() as u16 > visible {
        " selected ray (PgUp/PgDn, wheel: scroll) "
    } else {
        " selected ray "
    };
    let block = Block::default().borders(Borders::ALL).title(title);
    frame.render_widget(
        Paragraph::new(lines)
            .block(block)
            .wrap(Wrap { trim: false })
            .scroll((scroll, 0)),
        area,
    );
}

fn draw_diagram(frame: &mut Frame, app: &App, area: Rect, tc: bool) {
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" diagram: plane of incidence, world up on top ");
    let (Some(trace), Some(scene)) = (&app.trace, &app.scene) else {
        frame.render_widget(Paragraph::new("no scene: no diagram").block(block), area);
        return;
    };
    // The same projection and honesty rules as `raytree diagram`; while stepping,
    // only what the algorithm has computed so far.
    let options = Options {
        sample: app.sample,
        until_step: app.step,
        ..Options::default()
    };
    let Ok(lay) = layout(trace, scene, &options) else {
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

/// Every object: its silhouette dotted and dim, what the drawing plane cuts
/// of it solid; and the image plane.
fn paint_outlines(ctx: &mut Context, lay: &DiagramLayout, window: (DVec2, DVec2), tc: bool) {
    let step = (window.1 - window.0).max_element() / 120.0;
    for shape in &lay.objects {
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
        |s: &&crate::views::diagram_layout::Segment| Some(s.node) == selected && s.stroke.arrow();
    let mut order: Vec<_> = lay.segments.iter().collect();
    order.sort_by_key(|s| (chosen(s), s.stroke.arrow()));
    for s in order {
        let color = if chosen(&s) {
            term_color(SELECTED, tc)
        } else {
            term_color(s.stroke.pen().color, tc)
        };
        let at = |t: f64| s.from + (s.to - s.from) * t;
        let mut cuts = vec![0.0];
        for &[a, b] in &s.passing {
            cuts.extend([a, b]);
        }
        cuts.push(1.0);
        for (k, w) in cuts.windows(2).enumerate() {
            let Some((a, b)) = clip_segment(at(w[0]), at(w[1]), lo, hi) else {
                continue;
            };
            if k % 2 == 1 {
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
const SELECTED: Rgb = [255, 0, 255];

fn draw_help(frame: &mut Frame) {
    let area = frame.area();
    let width = 78.min(area.width);
    let height = (KEYS.len() as u16 + 4).min(area.height);
    let rect = Rect {
        x: area.x + (area.width - width) / 2,
        y: area.y + (area.height - height) / 2,
        width,
        height,
    };
    let lines: Vec<Line> = KEYS
        .iter()
        .map(|(k, what)| {
            Line::from(vec![
                Span::styled(
                    format!("{k:<15}"),
                    Style::default().add_modifier(Modifier::BOLD),
                ),
                Span::raw(*what),
            ])
        })
        .collect();
    frame.render_widget(Clear, rect);
    frame.render_widget(
        Paragraph::new(lines).block(
            Block::default()
                .borders(Borders::ALL)
                .title(" keys (any key closes) "),
        ),
        rect,
    );
}
