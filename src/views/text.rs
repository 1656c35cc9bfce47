//! The trace in words: each step of the algorithm explained with its own
//! numbers, and the whole trace as text for a terminal (a header with the
//! pixel's color, then each sample's steps indented by the depth of the ray they
//! belong to, which reads as the tree: a child's steps sit between its parent's
//! "spawn" and the parent's next branch). With numbering, it is the step list
//! the lessons refer to.

use std::fmt::Write;

use crate::geometry::hit::TestCounts;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{
    Branch, BranchRecord, HitRecord, LocalRecord, RayKind, RayNode, RayTree, ShadowOutcomeRecord,
    ShadowRecord, SumRecord, TestRecord,
};
use crate::tree::steps::{Step, StepKind};
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
            let inner = if step.kind == StepKind::Spawn {
                ""
            } else {
                "  "
            };
            let number = if numbered {
                format!("{:>4}. ", n + 1)
            } else {
                String::new()
            };
            let text = describe(trace, k, step);
            let _ = writeln!(out, "{number}{indent}{inner}{text}");
        }
    }
    out
}

/// One step of sample `sample` in one line, with its numbers: what
/// `raytree trace` prints, the inspector's step line, the lessons' narration.
pub fn describe(trace: &TraceDocument, sample: usize, step: &Step) -> String {
    let tree = &trace.samples[sample].tree;
    let node = &tree.nodes[step.node];
    match step.kind {
        StepKind::Spawn => spawned(node),
        StepKind::Test(k) => tested(trace, &node.tests[k]),
        StepKind::Hit => node.hit.as_ref().map_or_else(String::new, |h| hit(h, node)),
        StepKind::Miss => format!(
            "no hit: the ray returns the background {} ({})",
            vec3(node.sum.color),
            searched(&node.tested)
        ),
        StepKind::Shadow(k) => shadow(&node.shadow_rays[k]),
        StepKind::Local => node.local.as_ref().map_or_else(String::new, local),
        StepKind::Reflect | StepKind::Refract => {
            let branch = if step.kind == StepKind::Reflect {
                &node.reflected
            } else {
                &node.refracted
            };
            branch
                .as_ref()
                .map_or_else(String::new, |b| branched(step.kind, b, node))
        }
        StepKind::Combine => combined(&node.sum),
        StepKind::Return => format!(
            "return {} to {}",
            vec3(node.sum.color),
            returned_to(tree, node)
        ),
    }
}

fn spawned(node: &RayNode) -> String {
    format!(
        "spawn {} ray (depth {}, weight {}) from {} along {}",
        kind_name(node.kind),
        node.depth,
        num(node.weight),
        vec3(node.origin),
        vec3(node.direction)
    )
}

fn tested(trace: &TraceDocument, test: &TestRecord) -> String {
    let kind = trace
        .objects
        .get(test.object)
        .map_or("object", |o| o.kind.as_str());
    let found = if test.roots.is_empty() {
        "miss".to_owned()
    } else {
        let roots: Vec<String> = test.roots.iter().map(|&t| num(t)).collect();
        format!("t = {}", roots.join(", "))
    };
    format!("test {kind} '{}': {found}", test.name)
}

fn hit(hit: &HitRecord, node: &RayNode) -> String {
    let side = if hit.entering { "entering" } else { "leaving" };
    format!(
        "closest hit: '{}' at t = {}, point {}, normal {}, {side}, n {} → {} ({})",
        hit.name,
        num(hit.t),
        vec3(hit.point),
        vec3(hit.normal),
        num(hit.n1),
        num(hit.n2),
        searched(&node.tested)
    )
}

fn shadow(s: &ShadowRecord) -> String {
    let what = match &s.outcome {
        ShadowOutcomeRecord::FacesAway => "the light is behind the surface: no ray cast".to_owned(),
        ShadowOutcomeRecord::Reaches { transmitted } if *transmitted == 1.0 => {
            "reaches the light".to_owned()
        }
        ShadowOutcomeRecord::Reaches { transmitted } => format!(
            "reaches the light through transparent objects, keeping {}",
            num(*transmitted)
        ),
        ShadowOutcomeRecord::Blocked { name, t, .. } => {
            format!("blocked by '{name}' at t = {}", num(*t))
        }
    };
    format!("shadow ray to light '{}': {what}", s.name)
}

fn local(local: &LocalRecord) -> String {
    let lights: String = local
        .lights
        .iter()
        .map(|l| {
            format!(
                " + '{}' (diffuse {} + specular {})",
                l.name,
                vec3(l.diffuse),
                vec3(l.specular)
            )
        })
        .collect();
    format!(
        "local = ambient {}{lights} = {}",
        vec3(local.ambient),
        vec3(local.total)
    )
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
            "no refracted ray: total internal reflection (n {} → {} beyond the critical angle); its share {} went to the reflected ray",
            n(|h| h.n1),
            n(|h| h.n2),
            num(branch.coefficient)
        ),
    }
}

fn combined(s: &SumRecord) -> String {
    format!(
        "color = local {} + {} × reflected {} + {} × refracted {} = {}",
        vec3(s.local),
        num(s.k_rfl),
        vec3(s.reflected),
        num(s.k_rfa),
        vec3(s.refracted),
        vec3(s.color)
    )
}

fn returned_to(tree: &RayTree, node: &RayNode) -> String {
    node.parent.map_or("the pixel".to_owned(), |p| {
        format!("its parent, the {} ray", kind_name(tree.nodes[p].kind))
    })
}

/// How much searching a ray's closest hit took.
pub fn searched(t: &TestCounts) -> String {
    let s = |n: u32| if n == 1 { "" } else { "s" };
    if t.boxes == 0 {
        format!("{} object test{}", t.primitives, s(t.primitives))
    } else {
        format!(
            "{} box test{} and {} primitive test{}",
            t.boxes,
            s(t.boxes),
            t.primitives,
            s(t.primitives)
        )
    }
}

/// The word for a ray kind.
pub fn kind_name(kind: RayKind) -> &'static str {
    match kind {
        RayKind::Primary => "primary",
        RayKind::Reflected => "reflected",
        RayKind::Refracted => "refracted",
        RayKind::Shadow => "shadow",
    }
}
