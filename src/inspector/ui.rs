//! Drawing the inspector, reading its state and changing none of it: the
//! panes (each drawn by its module in `panes/`) where `layout.rs` puts them,
//! the guide, step and status lines, and the help.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph};

use super::app::{App, Prompt};
use super::fit::{cut, wrap};
use super::keymap::KEYS;
use super::layout::Panes;
use super::panes::details::draw_details;
use super::panes::diagram::draw_diagram;
use super::panes::image::{ImagePane, legend};
use super::panes::tree::draw_tree;
use super::state::reveal::call_stack;
use super::state::selection::Focus;
use crate::views::text::describe;

/// What the glyphs and colors mean, for the help.
pub const GLYPHS: &[(&str, &str)] = &[
    ("▾ / ▸", "a ray whose children are shown / folded"),
    ("██", "a ray's color, once it is returned"),
    (
        "magenta",
        "the pixel cursor; in the diagram, the selected ray",
    ),
    ("cyan", "overlay: pixels with what f finds"),
    (
        "blue, green, orange",
        "primary, reflected, refracted rays (diagram and tree)",
    ),
    ("yellow", "shadow rays; gray: blocked ones"),
    (
        "dotted",
        "diagram: an outline the drawing plane does not cut, or a ray passing it",
    ),
    ("underlined", "the line of the current step"),
    (
        "…",
        "a line cut to fit: widen the terminal, or scroll the numbers",
    ),
];

/// Draws the whole inspector: a pure function of the state (the update step,
/// [`tick`](crate::inspector::tick), changes what must change before a frame).
pub fn draw(frame: &mut Frame, app: &App) {
    let tc = app.truecolor();
    let area = frame.area();
    let guide_lines = guide_text(app, area);
    let step_lines = step_text(app, area.width);
    let panes = Panes::new(
        area,
        guide_lines.len() as u16,
        step_lines.len() as u16,
        app.screen().pane(),
    );
    let focused = |f: Focus| {
        if app.focus() == f {
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
    let image_inside = image_block.inner(panes.image);
    frame.render_widget(image_block, panes.image);
    frame.render_widget(ImagePane { app, truecolor: tc }, image_inside);
    draw_tree(frame, app, tree_block, panes.tree, tc);
    let other = if panes.wide { "" } else { " · v: diagram" };
    if let Some(d) = panes.details {
        draw_details(frame, app, d, tc, other);
    }
    if let Some(d) = panes.diagram {
        draw_diagram(frame, app, d, tc);
    }
    frame.render_widget(Paragraph::new(guide_lines), panes.guide);
    frame.render_widget(Paragraph::new(step_lines), panes.step);
    frame.render_widget(Paragraph::new(status_text(app, area.width)), panes.status);
    if app.screen().help_open() {
        draw_help(frame, app);
    }
}

/// Where the panes go for `app` on `area`, as [`draw`] lays them out.
pub(super) fn panes(app: &App, area: Rect) -> Panes {
    Panes::new(
        area,
        guide_text(app, area).len() as u16,
        step_text(app, area.width).len() as u16,
        app.screen().pane(),
    )
}

/// The guided step-through's current stop, wrapped; up to a quarter of the
/// terminal's rows (at least 4), a longer stop cut with the marker the help
/// explains. Away from the guide's pixel, only where its stops are, since
/// they quote that pixel's numbers. Nothing when not guided.
fn guide_text(app: &App, area: Rect) -> Vec<Line<'static>> {
    let Some(g) = app.guide() else {
        return Vec::new();
    };
    let Some(told) = g.stop() else {
        return Vec::new();
    };
    let title = g.title().unwrap_or("guided");
    let (at, stops) = g.position();
    let width = usize::from(area.width);
    let bold_cyan = Style::default()
        .fg(Color::Cyan)
        .add_modifier(Modifier::BOLD);
    if !app.guided_here() {
        // Without the title, which would push the way back off a small terminal.
        let (x, y) = g.pixel();
        return wrap(
            vec![Line::from(vec![
                Span::styled("guide paused: ", bold_cyan),
                Span::raw(format!(
                    "its stops tell pixel {x},{y}; g {x},{y} goes back to stop {}",
                    at + 1
                )),
            ])],
            width,
        );
    }
    let head = Span::styled(format!("{title} · stop {}/{stops}: ", at + 1), bold_cyan);
    let line = Line::from(vec![head, Span::raw(told.replace('\n', " "))]);
    let mut lines = wrap(vec![line], width);
    let room = usize::from(area.height / 4).max(4);
    if lines.len() > room {
        lines.truncate(room);
        mark_cut(&mut lines, width);
    }
    lines
}

/// Ends the last of `lines` with the cut marker, within `width` columns.
fn mark_cut(lines: &mut [Line<'static>], width: usize) {
    if let Some(last) = lines.last_mut() {
        *last = cut(last.clone(), width.saturating_sub(1));
        last.spans.push(Span::raw(super::fit::CUT));
    }
}

/// The step lines: a prompt being typed, or any message above the current
/// step and its call stack, or how to start.
fn step_text(app: &App, width: u16) -> Vec<Line<'static>> {
    let bold = Style::default().add_modifier(Modifier::BOLD);
    let w = usize::from(width);
    // A message is wrapped, not cut: a refused edit's reason is read nowhere else.
    let mut said = wrap(vec![Line::from(app.message().to_owned())], w);
    said.retain(|l| l.width() > 0);
    if said.len() > 4 {
        said.truncate(4);
        mark_cut(&mut said, w);
    }
    if let Some(prompt) = app.prompt() {
        let (label, typed) = match prompt {
            Prompt::GoTo(t) => ("go to pixel (x,y): ", t),
            Prompt::Edit(t) => ("what if (field=value, e.g. ior=1.0; Esc cancels): ", t),
            Prompt::Write(t) => ("write the edited scene to (a new file): ", t),
        };
        // Above the prompt, why it is open again (a file that exists).
        let mut lines = said;
        lines.push(cut(
            Line::from(vec![
                Span::styled(label, bold),
                Span::raw(format!("{typed}▏")),
            ]),
            w,
        ));
        return lines;
    }
    let Some(s) = app.step() else {
        if !said.is_empty() {
            return said;
        }
        let find = format!("f: find a {}", app.finding().seek().name());
        return vec![cut(
            Line::from(format!(
                "n: step through the algorithm ({} steps) · {find} · m: what if · ? every key",
                app.steps().len()
            )),
            w,
        )];
    };
    let Some(trace) = app.trace() else {
        return Vec::new();
    };
    let sample = app.selection().sample();
    let node = app.steps()[s].node;
    let head = format!("step {}/{} ", s + 1, app.steps().len());
    let room = w.saturating_sub(head.chars().count() + " in ".len() + " (x: whole tree)".len());
    let stack = call_stack(&trace.samples[sample].tree, node, room);
    let first = Line::from(vec![
        Span::styled(head, bold),
        Span::styled(format!("in {stack}"), Style::default().fg(Color::Cyan)),
        Span::raw(" (x: whole tree)"),
    ]);
    let what = describe(trace, sample, &app.steps()[s]).0;
    let mut lines = said;
    lines.push(cut(first, w));
    let mut told = wrap(vec![Line::from(what)], w);
    if told.len() > 2 {
        told.truncate(2);
        mark_cut(&mut told, w);
    }
    lines.extend(told);
    lines
}

/// The status line: the pixel, the zoom, the scene, the time to
/// trace (or where a saved trace came from), what an overlay shows.
fn status_text(app: &App, width: u16) -> Line<'static> {
    let (w, h) = app.image_size();
    let timing = match app.loaded_from() {
        Some(file) => format!("loaded from {file}"),
        None => format!(
            "traced in {:.2} ms",
            app.selection().traced_in().as_secs_f64() * 1e3
        ),
    };
    let mut parts = vec![
        format!("pixel {},{} of {w}×{h}", app.cursor().0, app.cursor().1),
        format!("zoom {}×", 1u32 << app.zoom()),
        app.source().file.clone(),
        timing,
    ];
    if let Some(t) = app.trace().filter(|t| t.samples.len() > 1) {
        parts.push(format!(
            "sample {} of {} (s: next) · pixel mean {}",
            app.selection().sample() + 1,
            t.samples.len(),
            crate::views::numbers::color(t.color)
        ));
    }
    if let Some(l) = legend(app) {
        parts.insert(0, l);
    }
    if let Some(note) = app.color_note() {
        // The whole note is the opening message; the status keeps its head.
        parts.push(
            note.split_once(':')
                .map_or(note, |(head, _)| head)
                .to_owned(),
        );
    }
    cut(
        Line::from(Span::styled(
            parts.join(" · "),
            Style::default().add_modifier(Modifier::DIM),
        )),
        usize::from(width),
    )
}

/// The help: every key and what the glyphs and colors mean, as wide as the
/// terminal allows (lines wrap, never cut) and scrollable when taller.
fn draw_help(frame: &mut Frame, app: &App) {
    let area = frame.area();
    let width = area.width.min(96);
    let inner = usize::from(width.saturating_sub(2));
    let row = |k: &str, what: &str, w: usize| {
        Line::from(vec![
            Span::styled(
                format!("{k:<w$} "),
                Style::default().add_modifier(Modifier::BOLD),
            ),
            Span::raw(what.to_owned()),
        ])
    };
    let key_w = KEYS
        .iter()
        .map(|b| b.keys.chars().count())
        .max()
        .unwrap_or(0);
    let glyph_w = GLYPHS
        .iter()
        .map(|(k, _)| k.chars().count())
        .max()
        .unwrap_or(0);
    let mut lines: Vec<Line<'static>> = KEYS.iter().map(|b| row(b.keys, b.what, key_w)).collect();
    lines.push(Line::from(""));
    lines.push(Line::from(Span::styled(
        "what you see",
        Style::default().add_modifier(Modifier::BOLD),
    )));
    lines.extend(GLYPHS.iter().map(|(k, w)| row(k, w, glyph_w)));
    let lines = wrap(lines, inner);
    let height = (lines.len() as u16 + 2).min(area.height);
    let visible = usize::from(height.saturating_sub(2));
    let top = usize::from(app.screen().help_scroll()).min(lines.len().saturating_sub(visible));
    let rect = Rect {
        x: area.x + (area.width - width) / 2,
        y: area.y + (area.height - height) / 2,
        width,
        height,
    };
    let title = if lines.len() > visible {
        format!(
            " keys {}–{} of {} (↑↓ scroll, any other key closes) ",
            top + 1,
            top + visible,
            lines.len()
        )
    } else {
        " keys (any key closes) ".to_owned()
    };
    frame.render_widget(Clear, rect);
    frame.render_widget(
        Paragraph::new(
            lines
                .into_iter()
                .skip(top)
                .take(visible)
                .collect::<Vec<_>>(),
        )
        .block(Block::default().borders(Borders::ALL).title(title)),
        rect,
    );
}
