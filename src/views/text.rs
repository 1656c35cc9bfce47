//! The trace in words: each step of the algorithm explained with its own
//! numbers, and the whole trace as text for a terminal (a header with the
//! pixel's color, then each sample's steps indented by the depth of the ray they
//! belong to, which reads as the tree: a child's steps sit between its parent's
//! "spawn" and the parent's next branch). With numbering, it is the step list
//! the lessons refer to.

use std::fmt::Write;

use crate::geometry::hit::TestCounts;
use crate::methods::{Accel, Antialiasing};
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{Branch, BranchRecord, HitRecord, RayNode, RayTree, SumRecord};
use crate::tree::steps::{Step, StepKind};
use crate::views::explain::{self, Lines};
use crate::views::numbers::{color, num, vec3};
use crate::views::walk;

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
        "{what} of {} ({}×{}, {}, max depth {}, cutoff {})",
        trace.scene.file,
        s.width,
        s.height,
        s.sampling(),
        s.max_depth,
        num(s.cutoff)
    );
    let [r, g, b] = trace.rgb8;
    let _ = writeln!(
        out,
        "color {} → 8-bit sRGB ({r}, {g}, {b})",
        color(trace.color)
    );
    for (k, sample) in trace.samples.iter().enumerate() {
        let _ = writeln!(out);
        if let Some(which) = sample_name(trace, k) {
            let at = sample.position.map_or(String::new(), |[x, y]| {
                format!(" through ({}, {})", num(x), num(y))
            });
            let _ = writeln!(out, "{which}{at}: color {}", color(sample.color));
        }
        for (n, step) in trace.steps(k).iter().enumerate() {
            let depth = sample.tree.nodes[step.node].depth as usize;
            let indent = "    ".repeat(depth.saturating_sub(1));
            // Steps other than a ray's spawn (and the camera stage before it) sit under it.
            let inner = if matches!(step.kind, StepKind::Spawn | StepKind::Camera) {
                ""
            } else {
                "  "
            };
            let number = if numbered {
                format!("{:>4}. ", n + 1)
            } else {
                String::new()
            };
            let (line, details) = describe(trace, k, step);
            let _ = writeln!(out, "{number}{indent}{inner}{line}");
            let pad = " ".repeat(number.chars().count());
            for detail in details {
                let _ = writeln!(out, "{pad}{indent}{inner}    {detail}");
            }
        }
    }
    out
}

/// One step of sample `sample`: a headline, and the lines that work out its
/// arithmetic with its own numbers. What `raytree trace` prints, the
/// inspector's step line, the lessons' narration.
pub fn describe(trace: &TraceDocument, sample: usize, step: &Step) -> Lines {
    let tree = &trace.samples[sample].tree;
    let node = &tree.nodes[step.node];
    let one = |line: String| (line, Vec::new());
    match step.kind {
        StepKind::Camera => {
            let s = &trace.samples[sample];
            let which = sample_name(trace, sample).map_or(String::new(), |w| w + ", ");
            s.camera.as_ref().map_or_else(
                || one(String::new()),
                |c| explain::camera(&trace.camera, c, &which),
            )
        }
        StepKind::Spawn => one(format!(
            "spawn {} ray (depth {}, weight {}) from S = {} along c = {}: {}",
            node.kind.name(),
            node.depth,
            num(node.weight),
            vec3(node.origin),
            vec3(node.direction),
            explain::t_unit(node)
        )),
        StepKind::Visit(k) => walk::visited(node, k, trace.structure),
        StepKind::Test(k) => {
            let test = &node.tests[k];
            let kind = trace
                .objects
                .get(test.object)
                .map_or("object", |o| o.kind.as_str());
            explain::test(test, kind, node)
        }
        StepKind::Hit => node.hit.as_ref().map_or_else(
            || one(String::new()),
            |h| explain::hit(h, &searched(&node.tested, trace.structure)),
        ),
        StepKind::Miss => one(format!(
            "no hit: the ray returns the background {} ({})",
            color(node.sum.color),
            searched(&node.tested, trace.structure)
        )),
        StepKind::Shadow(k) => one(explain::shadow(&node.shadow_rays[k])),
        StepKind::Local => node
            .local
            .as_ref()
            .map_or_else(|| one(String::new()), explain::local),
        StepKind::Reflect | StepKind::Refract => branch_step(step.kind, node),
        StepKind::Combine => one(combined(&node.sum)),
        StepKind::Return => one(format!(
            "return {} to {}",
            color(node.sum.color),
            returned_to(tree, node)
        )),
    }
}

/// A reflect or refract step: whether the branch was traced and with what
/// weight, and, where a direction was made (or Snell's law has none), its
/// arithmetic.
fn branch_step(kind: StepKind, node: &RayNode) -> Lines {
    let reflect = kind == StepKind::Reflect;
    let branch = if reflect {
        &node.reflected
    } else {
        &node.refracted
    };
    let Some(branch) = branch else {
        return (String::new(), Vec::new());
    };
    let line = branched(kind, branch, node);
    let details = match (&node.hit, branch.outcome) {
        (Some(h), Branch::Traced) if reflect => vec![explain::reflection(h)],
        (Some(h), Branch::Traced | Branch::TotalInternalReflection) if !reflect => {
            explain::refraction(h)
        }
        _ => Vec::new(),
    };
    (line, details)
}

fn branched(kind: StepKind, branch: &BranchRecord, node: &RayNode) -> String {
    let (name, k) = if kind == StepKind::Reflect {
        ("reflected", "k_rfl")
    } else {
        ("refracted", "k_rfa")
    };
    let tir = node
        .refracted
        .as_ref()
        .filter(|r| r.outcome == Branch::TotalInternalReflection);
    let k_value = match tir {
        Some(r) if kind == StepKind::Reflect => format!(
            "{} = {} + {} handed over by total internal reflection",
            num(branch.coefficient),
            num(branch.coefficient - r.coefficient),
            num(r.coefficient)
        ),
        _ => num(branch.coefficient),
    };
    let n = |f: fn(&HitRecord) -> f64| node.hit.as_ref().map_or(String::new(), |h| num(f(h)));
    match branch.outcome {
        Branch::Traced => format!(
            "spawn the {name} ray ({k} = {k_value}, weight {})",
            num(node.weight * branch.coefficient)
        ),
        Branch::NoCoefficient => format!("no {name} ray: {k} = 0"),
        Branch::MaxDepth => format!("no {name} ray: depth {} is the maximum", node.depth),
        Branch::WeightCutoff => format!(
            "no {name} ray: its weight {} is below the cutoff",
            num(node.weight * branch.coefficient)
        ),
        Branch::TotalInternalReflection => format!(
            "no refracted ray: total internal reflection (n₁ = {} → n₂ = {} beyond the critical angle); its share {} went to the reflected ray",
            n(|h| h.n1),
            n(|h| h.n2),
            num(branch.coefficient)
        ),
    }
}

fn combined(s: &SumRecord) -> String {
    format!(
        "color = local {} + {} × reflected {} + {} × refracted {} = {}",
        color(s.local),
        num(s.k_rfl),
        color(s.reflected),
        num(s.k_rfa),
        color(s.refracted),
        color(s.color)
    )
}

fn returned_to(tree: &RayTree, node: &RayNode) -> String {
    node.parent.map_or("the pixel".to_owned(), |p| {
        format!("its parent, the {} ray", tree.nodes[p].kind.name())
    })
}

/// How much searching a ray's closest hit took, through `structure`.
pub fn searched(t: &TestCounts, structure: Accel) -> String {
    let s = |n: u32| if n == 1 { "" } else { "s" };
    if t.boxes == 0 {
        format!("{} object test{}", t.primitives, s(t.primitives))
    } else {
        format!(
            "{} {} and {} primitive test{}",
            t.boxes,
            structure.step_word(t.boxes != 1),
            t.primitives,
            s(t.primitives)
        )
    }
}

/// "sample 3 of 4" for a pixel sampled more than once: of `spp` on the grid,
/// of as many as the adaptive subdivision took (when all are recorded).
pub fn sample_name(trace: &TraceDocument, sample: usize) -> Option<String> {
    let s = &trace.settings;
    let index = trace.samples[sample].index + 1;
    let adaptive = matches!(s.aa, Antialiasing::Adaptive { .. });
    match trace.pixel {
        None => None,
        Some(_) if s.aa == Antialiasing::Corners => Some(format!("corner {index} of 4")),
        Some(_) if !adaptive && s.spp > 1 => Some(format!("sample {index} of {}", s.spp)),
        Some(_) if adaptive && trace.samples.len() > 1 => Some(format!(
            "sample {index} of {} (adaptive)",
            trace.samples.len()
        )),
        Some(_) if adaptive => Some(format!("sample {index} (adaptive)")),
        Some(_) => None,
    }
}
