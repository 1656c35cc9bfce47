//! The ray tree pane: one line per ray (its kind, depth, what it hit, its
//! color once returned, why its branches stopped) and per shadow ray; while
//! stepping, only what has been computed, the current step's line marked.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

use crate::figure::pen::palette;
use crate::inspector::app::App;
use crate::inspector::colors::{swatch, term_color};
use crate::inspector::fit::cut;
use crate::inspector::state::reveal::RayRevealed;
use crate::inspector::state::selection::Item;
use crate::tree::ray_tree::{RayNode, ShadowOutcomeRecord};
use crate::views::numbers::num;

fn ray_line(app: &App, node: &RayNode, n: usize, p: RayRevealed, tc: bool) -> Vec<Span<'static>> {
    let what = match &node.hit {
        _ if !p.hit => "testing…".to_owned(),
        Some(h) => format!("'{}'", h.name),
        None => "background".to_owned(),
    };
    let mut spans = vec![
        Span::styled(
            format!("{} ", node.kind.name()),
            Style::default()
                .fg(term_color(
                    crate::views::diagram::style::ray_pen(node.kind).color,
                    tc,
                ))
                .add_modifier(Modifier::BOLD),
        ),
        Span::raw(format!("d{} {what} ", node.depth)),
    ];
    if p.color {
        spans.push(swatch(node.color(), tc));
    }
    let why = if p.reflect && p.refract || p.color {
        app.selection().stop_reason(n)
    } else {
        String::new()
    };
    if !why.is_empty() {
        spans.push(Span::styled(
            format!(" {why}"),
            Style::default().add_modifier(Modifier::DIM),
        ));
    }
    spans
}

/// A shadow ray's line: the light it goes to and what it met.
fn shadow_text(node: &RayNode, k: usize) -> String {
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

/// Draws the tree pane.
pub fn draw_tree(frame: &mut Frame, app: &App, block: Block, area: Rect, tc: bool) {
    let selection = app.selection();
    let Some(tree) = selection.tree() else {
        frame.render_widget(Paragraph::new("no pixel traced").block(block), area);
        return;
    };
    let nodes = &tree.nodes;
    let inner = block.inner(area);
    let step_node = app.current_step().map(|s| s.node);
    let shown = app.revealed();
    let width = usize::from(inner.width);
    let items = app.items();
    let scroll = selection.tree_scroll(inner.height);
    let lines: Vec<Line> = items
        .iter()
        .enumerate()
        .skip(scroll)
        .take(usize::from(inner.height))
        .map(|(row, &(item, indent))| {
            let mut spans = vec![Span::raw("  ".repeat(indent))];
            match item {
                Item::Ray(n) => {
                    let marker = if !selection.expandable(n) {
                        "  "
                    } else if selection.is_expanded(n) {
                        "▾ "
                    } else {
                        "▸ "
                    };
                    spans.push(Span::raw(marker));
                    spans.extend(ray_line(app, &nodes[n], n, shown.node(n), tc));
                }
                Item::Shadow(n, k) => spans.push(Span::styled(
                    format!("  {}", shadow_text(&nodes[n], k)),
                    Style::default().fg(term_color(palette::SHADOW_REACHES, tc)),
                )),
            }
            let mut line = cut(Line::from(spans), width);
            if row == selection.line() {
                line = line.style(Style::default().add_modifier(Modifier::REVERSED));
            } else if step_node == Some(item.node()) && matches!(item, Item::Ray(_)) {
                line = line.style(Style::default().add_modifier(Modifier::UNDERLINED));
            }
            line
        })
        .collect();
    frame.render_widget(Paragraph::new(lines).block(block), area);
}
