//! The trace as text for a terminal: a header with the pixel's color, then each
//! sample's steps indented by the depth of the ray they belong to, which reads as
//! the tree (a child's steps sit between its parent's "spawn" and the parent's
//! next branch). With numbering, it is the step list the lessons refer to.

use std::fmt::Write;

use crate::tree::document::TraceDocument;
use crate::views::numbers::{num, vec3};

/// The trace as an indented text tree; `numbered` prefixes each step with its
/// number in execution order.
pub fn format(trace: &TraceDocument, numbered: bool) -> String {
    let mut out = String::new();
    let s = &trace.settings;
    let what = match (&trace.pixel, &trace.ray) {
        (Some(p), _) => format!("pixel {},{}", p.x, p.y),
        (_, Some(r)) => format!("ray from {} along {}", vec3(r.origin), vec3(r.direction)),
        _ => "nothing".to_owned(),
    };
    let _ = writeln!(
        out,
        "{what} of {} ({}×{}, {} spp, max depth {}, cutoff {})",
        trace.scene.file,
        s.width,
        s.height,
        s.spp,
        s.max_depth,
        num(s.cutoff)
    );
    let [r, g, b] = trace.rgb8;
    let _ = writeln!(
        out,
        "color {} → 8-bit sRGB ({r}, {g}, {b})",
        vec3(trace.color)
    );
    for (k, sample) in trace.samples.iter().enumerate() {
        let _ = writeln!(out);
        if trace.pixel.is_some() && s.spp > 1 {
            let at = sample.position.map_or(String::new(), |[x, y]| {
                format!(" through ({}, {})", num(x), num(y))
            });
            let _ = writeln!(
                out,
                "sample {} of {}{at}: color {}",
                sample.index,
                s.spp,
                vec3(sample.color)
            );
        }
        for (n, step) in trace.steps(k).iter().enumerate() {
            let depth = sample.tree.nodes[step.node].depth as usize;
            let indent = "    ".repeat(depth.saturating_sub(1));
            // Steps other than a ray's spawn sit under it.
            let inner = if matches!(step.kind, crate::tree::steps::StepKind::Spawn) {
                ""
            } else {
                "  "
            };
            let number = if numbered {
                format!("{:>4}. ", n + 1)
            } else {
                String::new()
            };
            let _ = writeln!(out, "{number}{indent}{inner}{}", step.text);
        }
    }
    out
}
