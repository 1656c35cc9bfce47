//! The selected ray's numbers, as the inspector's detail pane lists them: its
//! origin, direction and tests, its hit with the side and indices, each shadow
//! ray, and the color sum term by term.

use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};

use super::app::{App, Item};
use super::ui::{shadow_text, swatch};
use crate::tree::ray_tree::RayNode;
use crate::views::numbers::{num, vec3};
use crate::views::text::{kind_name, searched};

/// The selected line's numbers: a shadow ray's, or a ray's with its hit and
/// its color sum.
pub(super) fn details(app: &App, tc: bool) -> Vec<Line<'static>> {
    let (Some(trace), Some(item)) = (&app.trace, app.selected_item()) else {
        return vec![];
    };
    let node = &trace.samples[0].tree.nodes[item.node()];
    if let Item::Shadow(_, k) = item {
        return shadow_details(node, k);
    }
    let mut out = ray_details(node);
    out.extend(hit_details(node));
    out.extend(color_sum(node, tc));
    out
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
        Line::from(shadow_text(node, k)),
        row("origin", vec3(s.origin)),
        row(
            "direction",
            format!("{} (t = 1 at the light)", vec3(s.direction)),
        ),
        row("interval", format!("t in (0, {})", num(s.t_max))),
    ]
}

/// The ray itself and what it was tested against.
fn ray_details(node: &RayNode) -> Vec<Line<'static>> {
    let tests: Vec<String> = node
        .tests
        .iter()
        .map(|t| {
            if t.roots.is_empty() {
                format!("{} miss", t.name)
            } else {
                let roots: Vec<String> = t.roots.iter().map(|&r| num(r)).collect();
                format!("{} t={}", t.name, roots.join(","))
            }
        })
        .collect();
    vec![
        Line::from(format!(
            "{} ray · depth {} · weight {}",
            kind_name(node.kind),
            node.depth,
            num(node.weight)
        )),
        row("origin", vec3(node.origin)),
        row("direction", vec3(node.direction)),
        row(
            "interval",
            format!(
                "t in ({}, {})",
                num(node.t_min),
                node.t_max.map_or("∞".to_owned(), num)
            ),
        ),
        row(
            "tested",
            format!("{}: {}", searched(&node.tested), tests.join(" · ")),
        ),
    ]
}

/// What the ray hit, on which side, and its shadow rays.
fn hit_details(node: &RayNode) -> Vec<Line<'static>> {
    let Some(h) = &node.hit else {
        return vec![row(
            "hit",
            format!("nothing: background {}", vec3(node.sum.color)),
        )];
    };
    let side = if h.entering { "entering" } else { "leaving" };
    let mut out = vec![
        row(
            "hit",
            format!("'{}' (material {}) at t = {}", h.name, h.material, num(h.t)),
        ),
        row("point", vec3(h.point)),
        row(
            "normal",
            format!("{} (shading {})", vec3(h.normal), vec3(h.shading_normal)),
        ),
        row("side", format!("{side}, n {} → {}", num(h.n1), num(h.n2))),
    ];
    for k in 0..node.shadow_rays.len() {
        out.push(row(
            if k == 0 { "shadows" } else { "" },
            shadow_text(node, k),
        ));
    }
    out
}

/// `color = ambient + Σ (diffuse + specular) + k_rfl·reflected + k_rfa·refracted`,
/// term by term, ending in the color and its swatch.
fn color_sum(node: &RayNode, tc: bool) -> Vec<Line<'static>> {
    let s = &node.sum;
    let mut out = Vec::new();
    if let Some(local) = &node.local {
        out.push(Line::from(vec![
            Span::styled("color     ", Style::default().add_modifier(Modifier::BOLD)),
            Span::raw(format!("  ambient {}", vec3(local.ambient))),
        ]));
        for l in &local.lights {
            out.push(Line::from(format!(
                "          + '{}': diffuse {} + specular {}",
                l.name,
                vec3(l.diffuse),
                vec3(l.specular)
            )));
        }
        out.push(Line::from(format!("          = local {}", vec3(s.local))));
        out.push(Line::from(format!(
            "          + {} × reflected {}",
            num(s.k_rfl),
            vec3(s.reflected)
        )));
        out.push(Line::from(format!(
            "          + {} × refracted {}",
            num(s.k_rfa),
            vec3(s.refracted)
        )));
    }
    out.push(Line::from(vec![
        Span::raw(format!("          = {} ", vec3(s.color))),
        swatch(s.color, tc),
    ]));
    out
}
