//! The selected ray's numbers, as the inspector's detail pane lists them: its
//! origin, direction and tests, its hit with the side and indices, each shadow
//! ray, and the color sum term by term.

use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};

use super::app::{App, Item};
use super::colors::swatch;
use crate::tree::ray_tree::RayNode;
use crate::views::explain;
use crate::views::numbers::{color, num, vec3};
use crate::views::text::{kind_name, searched};

/// The selected line's numbers: a shadow ray's, or a ray's with the camera
/// stage (for a pixel's primary ray), its tests, its hit and its color sum,
/// each with the lecture's arithmetic written out.
pub(super) fn details(app: &App, tc: bool) -> Vec<Line<'static>> {
    let (Some(trace), Some(item)) = (&app.trace, app.selected_item()) else {
        return vec![];
    };
    let sample = &trace.samples[app.sample];
    let node = &sample.tree.nodes[item.node()];
    if let Item::Shadow(_, k) = item {
        return shadow_details(node, k);
    }
    // The results first (the ray, its hit, its color), then how each was worked out.
    let mut out = ray_details(node);
    out.extend(hit_details(node));
    out.extend(color_sum(node, tc));
    out.push(Line::from(""));
    if let (Some(stage), None) = (&sample.camera, node.parent) {
        out.extend(explained(explain::camera(&trace.camera, stage, "")));
    }
    for test in &node.tests {
        let kind = trace
            .objects
            .get(test.object)
            .map_or("object", |o| o.kind.as_str());
        out.extend(explained(explain::test(test, kind, node)));
    }
    out.extend(working(node));
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
fn ray_details(node: &RayNode) -> Vec<Line<'static>> {
    vec![
        Line::from(format!(
            "{} ray · depth {} · weight {}",
            kind_name(node.kind),
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
        row("tested", searched(&node.tested)),
    ]
}

/// What the ray hit, on which side, with the normal the formulas use.
fn hit_details(node: &RayNode) -> Vec<Line<'static>> {
    let Some(h) = &node.hit else {
        return vec![row(
            "hit",
            format!("nothing: background {}", color(node.sum.color)),
        )];
    };
    explained(explain::hit(h, &searched(&node.tested)))
}

/// How the hit's color was worked out: the shadow rays, the Phong terms, and
/// the reflected and refracted directions with their formulas.
fn working(node: &RayNode) -> Vec<Line<'static>> {
    let (Some(h), Some(local)) = (&node.hit, &node.local) else {
        return Vec::new();
    };
    let mut out: Vec<Line<'static>> = node
        .shadow_rays
        .iter()
        .map(|s| Line::from(explain::shadow(s)))
        .collect();
    out.extend(explain::local(local).1.into_iter().map(Line::from));
    if node.reflected.is_some() {
        out.push(Line::from(format!("reflect: {}", explain::reflection(h))));
    }
    for line in explain::refraction(h) {
        out.push(Line::from(format!("refract: {line}")));
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
