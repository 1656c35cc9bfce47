//! The selected ray's numbers, as the inspector's detail pane lists them: its
//! origin, direction and tests, its hit with the side and indices, each shadow
//! ray, and the color sum term by term; drawn from the line scrolled to, under
//! a title that fits the pane.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph};

use crate::inspector::app::App;
use crate::inspector::colors::swatch;
use crate::inspector::fit::{cut, wrap};
use crate::inspector::state::reveal::RayRevealed;
use crate::inspector::state::selection::Item;
use crate::methods::Accel;
use crate::tree::ray_tree::RayNode;
use crate::tree::steps::StepKind;
use crate::views::explain;
use crate::views::numbers::{color, num, vec3};
use crate::views::text::searched;

/// The selected line's numbers: a shadow ray's, or a ray's with the camera
/// stage (for a pixel's primary ray), its tests, its hit and its color sum,
/// each with the lecture's arithmetic written out. Browsing, the results come
/// first; stepping, only what the algorithm has computed so far, in the order
/// it computed it, so the pane reads like a debugger's.
fn details(app: &App, tc: bool) -> Vec<Line<'static>> {
    let mut out = what_if(app, tc);
    out.extend(selected(app, tc));
    out
}

/// The selected ray's numbers, wrapped to the pane `area` (border included),
/// and how many lines fit.
fn detail_lines(app: &App, area: Rect, tc: bool) -> (Vec<Line<'static>>, usize) {
    let inner_width = usize::from(area.width.saturating_sub(2));
    let lines = wrap(details(app, tc), inner_width);
    (lines, usize::from(area.height.saturating_sub(2)))
}

/// The first line of the numbers shown in `area`: the scroll, kept in range.
/// Stepping, the newest lines are at the bottom, so a scroll past the end
/// shows the end.
pub(in crate::inspector) fn details_top(app: &App, area: Rect) -> usize {
    let (lines, visible) = detail_lines(app, area, app.truecolor());
    usize::from(app.selection().scroll()).min(lines.len().saturating_sub(visible))
}

/// Draws the selected ray's numbers from the first line [`details_top`] gives.
pub(in crate::inspector) fn draw_details(
    frame: &mut Frame,
    app: &App,
    area: Rect,
    tc: bool,
    other: &str,
) {
    let inner_width = usize::from(area.width.saturating_sub(2));
    let (lines, visible) = detail_lines(app, area, tc);
    let top = usize::from(app.selection().scroll()).min(lines.len().saturating_sub(visible));
    let below = lines.len().saturating_sub(top + visible);
    let title = if lines.len() > visible {
        let arrows = format!(
            "{}{}",
            if top > 0 { "↑" } else { "" },
            if below > 0 { "↓" } else { "" }
        );
        let (from, to, of) = (top + 1, (top + visible).min(lines.len()), lines.len());
        fitting_title(
            &[
                format!(" selected ray {arrows} lines {from}–{to} of {of} (PgUp/PgDn){other} "),
                format!(" selected ray {arrows} {from}–{to}/{of} PgUp/PgDn{other} "),
                format!(" ray {arrows} {from}–{to}/{of}{other} "),
            ],
            inner_width,
        )
    } else {
        fitting_title(&[format!(" selected ray{other} ")], inner_width)
    };
    let block = Block::default().borders(Borders::ALL).title(title);
    let shown: Vec<Line> = lines.into_iter().skip(top).take(visible).collect();
    frame.render_widget(Paragraph::new(shown).block(block), area);
}

/// The first of `titles` that fits `width` columns, else the last one cut with a marker.
fn fitting_title(titles: &[String], width: usize) -> Line<'static> {
    let fits = titles.iter().find(|t| t.chars().count() <= width);
    match fits {
        Some(t) => Line::from(t.clone()),
        None => cut(
            Line::from(titles.last().cloned().unwrap_or_default()),
            width,
        ),
    }
}

/// With edits in effect: what they are, and the pixel's color and ray count
/// before the first edit and now.
fn what_if(app: &App, tc: bool) -> Vec<Line<'static>> {
    let (Some(before), Some(trace)) = (app.what_if().before(), app.trace()) else {
        return Vec::new();
    };
    if before.pixel != app.cursor() {
        return Vec::new();
    }
    let bold = Style::default().add_modifier(Modifier::BOLD);
    vec![
        Line::from(vec![
            Span::styled("what if  ", bold),
            Span::raw(format!(
                "{} (u: undo all, w: write)",
                app.what_if().edits().join("; ")
            )),
        ]),
        Line::from(vec![
            Span::styled("color    ", bold),
            swatch(before.color, tc),
            Span::raw(format!(" {} → ", color(before.color))),
            swatch(trace.color, tc),
            Span::raw(format!(" {}", color(trace.color))),
        ]),
        Line::from(vec![
            Span::styled("rays     ", bold),
            Span::raw(format!(
                "{} → {} in the first sample's tree",
                before.rays,
                trace.samples[0].tree.nodes.len()
            )),
        ]),
        Line::from(""),
    ]
}

fn selected(app: &App, tc: bool) -> Vec<Line<'static>> {
    let Some(trace) = app.trace() else {
        return vec![];
    };
    let sample = &trace.samples[app.selection().sample()];
    // The camera stage comes before any ray: it is what step 1 computes.
    let camera_step = app
        .current_step()
        .is_some_and(|s| s.kind == StepKind::Camera);
    if let (true, Some(stage)) = (camera_step, &sample.camera) {
        return explained(explain::camera(&trace.camera, stage, ""));
    }
    let Some(item) = app.selected_item() else {
        return vec![];
    };
    let node = &sample.tree.nodes[item.node()];
    if let Item::Shadow(_, k) = item {
        return shadow_details(node, k);
    }
    let kind_of = |test: &crate::tree::ray_tree::TestRecord| {
        trace
            .objects
            .get(test.object)
            .map_or("object", |o| o.kind.as_str())
    };
    let camera = match (&sample.camera, node.parent) {
        (Some(stage), None) => explained(explain::camera(&trace.camera, stage, "")),
        _ => Vec::new(),
    };
    if app.step().is_some() {
        let revealed = app.revealed();
        let p = revealed.node(item.node());
        let mut out = ray_details(node, trace.structure);
        if revealed.camera {
            out.extend(camera);
        }
        out.extend(tests(&node.tests[..p.tests.min(node.tests.len())], |t| {
            explained(explain::test(t, kind_of(t), node))
        }));
        if p.hit {
            out.extend(hit_details(node, trace.structure));
        }
        out.extend(working(node, p, tc));
        return out;
    }
    // The results first (the ray, its hit, its color), then how each was worked out.
    let mut out = ray_details(node, trace.structure);
    out.extend(hit_details(node, trace.structure));
    out.extend(color_sum(node, tc));
    out.push(Line::from(""));
    out.extend(camera);
    out.extend(tests(&node.tests, |t| {
        explained(explain::test(t, kind_of(t), node))
    }));
    out.extend(working(node, RayRevealed::DONE, tc));
    out
}

/// The most object tests the pane writes out for one ray. A ray through a
/// big scene without a structure tests every object, and writing out 838,000
/// of them took the pane 14 GB and minutes a key; past a few screenfuls
/// nobody reads them one by one, and the trace file holds them all.
const MOST_TESTS_SHOWN: usize = 200;

/// Each test's lines, or for more than [`MOST_TESTS_SHOWN`] the first and
/// the last half of that (the last are the newest while stepping) around a
/// line saying how many are left out.
fn tests<T>(tests: &[T], lines: impl Fn(&T) -> Vec<Line<'static>>) -> Vec<Line<'static>> {
    if tests.len() <= MOST_TESTS_SHOWN {
        return tests.iter().flat_map(&lines).collect();
    }
    let half = MOST_TESTS_SHOWN / 2;
    let left_out = tests.len() - 2 * half;
    let mut out: Vec<Line<'static>> = tests[..half].iter().flat_map(&lines).collect();
    out.push(Line::from(format!(
        "… {left_out} more tests here (`raytree trace --json` holds every one)"
    )));
    out.extend(tests[tests.len() - half..].iter().flat_map(&lines));
    out
}

/// A headline and its arithmetic, the arithmetic indented under it.
fn explained((headline, details): explain::Lines) -> Vec<Line<'static>> {
    std::iter::once(Line::from(headline))
        .chain(details.into_iter().map(|d| Line::from(format!("    {d}"))))
        .collect()
}

/// A label in bold, padded to the column the values start at, and its value.
fn row(label: &str, value: String) -> Line<'static> {
    Line::from(vec![
        Span::styled(
            format!("{label:<10}"),
            Style::default().add_modifier(Modifier::BOLD),
        ),
        Span::raw(value),
    ])
}

fn shadow_details(node: &RayNode, k: usize) -> Vec<Line<'static>> {
    let s = &node.shadow_rays[k];
    vec![
        Line::from(explain::shadow(s)),
        row("origin", vec3(s.origin)),
        row(
            "direction",
            format!("{} (t = 1 at the light)", vec3(s.direction)),
        ),
        row("interval", format!("t in (0, {})", num(s.t_max))),
    ]
}

/// The ray itself: where it starts, where it goes, what `t` counts.
fn ray_details(node: &RayNode, structure: Accel) -> Vec<Line<'static>> {
    vec![
        Line::from(format!(
            "{} ray · depth {} · weight {}",
            node.kind.name(),
            node.depth,
            num(node.weight)
        )),
        row("origin", format!("S = {}", vec3(node.origin))),
        row("direction", format!("c = {}", vec3(node.direction))),
        row("t", explain::t_unit(node)),
        row(
            "interval",
            format!(
                "t in ({}, {})",
                num(node.t_min),
                node.t_max.map_or("∞".to_owned(), num)
            ),
        ),
        row("tested", searched(&node.tested, structure)),
    ]
}

/// What the ray hit, on which side, with the normal the formulas use.
fn hit_details(node: &RayNode, structure: Accel) -> Vec<Line<'static>> {
    let Some(h) = &node.hit else {
        return vec![row(
            "hit",
            format!("nothing: background {}", color(node.sum.color)),
        )];
    };
    explained(explain::hit(h, &searched(&node.tested, structure)))
}

/// How the hit's color was worked out, as far as `p` has come: the shadow
/// rays, the Phong terms, the reflected and refracted directions with their
/// formulas and, stepping, the color sum once it is returned.
fn working(node: &RayNode, p: RayRevealed, tc: bool) -> Vec<Line<'static>> {
    let Some(h) = &node.hit else {
        return Vec::new();
    };
    let mut out: Vec<Line<'static>> = node
        .shadow_rays
        .iter()
        .take(p.shadows)
        .map(|s| Line::from(explain::shadow(s)))
        .collect();
    if let Some(local) = node.local.as_ref().filter(|_| p.local) {
        let (headline, arithmetic) = explain::local(local);
        if p != RayRevealed::DONE {
            out.push(Line::from(headline));
        }
        out.extend(
            arithmetic
                .into_iter()
                .map(|d| Line::from(format!("    {d}"))),
        );
    }
    if p.reflect && node.reflected.is_some() {
        out.push(Line::from(format!("reflect: {}", explain::reflection(h))));
    }
    if p.refract {
        for line in explain::refraction(h) {
            out.push(Line::from(format!("refract: {line}")));
        }
    }
    if p.color && p != RayRevealed::DONE {
        out.extend(color_sum(node, tc).into_iter().skip(1));
    }
    out
}

/// `color = ambient + Σ (diffuse + specular) + k_rfl·reflected + k_rfa·refracted`,
/// term by term with the Phong arithmetic, ending in the color and its swatch.
fn color_sum(node: &RayNode, tc: bool) -> Vec<Line<'static>> {
    let s = &node.sum;
    let mut out = Vec::new();
    if let Some(local) = &node.local {
        out.push(Line::from(explain::local(local).0));
        out.push(Line::from(format!(
            "color = local {} + {} × reflected {} + {} × refracted {}",
            color(s.local),
            num(s.k_rfl),
            color(s.reflected),
            num(s.k_rfa),
            color(s.refracted)
        )));
    }
    out.push(Line::from(vec![
        Span::raw(format!("      = {} ", color(s.color))),
        swatch(s.color, tc),
    ]));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_of_many_tests_shows_the_first_and_last_and_counts_the_rest() {
        let one = |k: &usize| vec![Line::from(format!("test {k}"))];
        let few: Vec<usize> = (0..MOST_TESTS_SHOWN).collect();
        assert_eq!(tests(&few, one).len(), MOST_TESTS_SHOWN);
        let many: Vec<usize> = (0..838_000).collect();
        let shown = tests(&many, one);
        assert_eq!(shown.len(), MOST_TESTS_SHOWN + 1);
        let text: Vec<String> = shown.iter().map(|l| l.to_string()).collect();
        assert_eq!(text[0], "test 0");
        assert_eq!(
            text[MOST_TESTS_SHOWN / 2],
            "… 837800 more tests here (`raytree trace --json` holds every one)"
        );
        assert_eq!(text[MOST_TESTS_SHOWN], "test 837999");
    }
}
