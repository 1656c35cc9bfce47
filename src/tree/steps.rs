//! The ray tree read as the algorithm ran: spawn a ray, test each object, take
//! the closest hit, cast each shadow ray, sum the local color, spawn the reflected
//! ray (and everything under it), spawn the refracted ray, combine, return. Each
//! step points at its node and explains itself with its own numbers. Derived from
//! the tree alone, so every view steps through the same list.

use serde::Serialize;

use crate::trace::recorder::{Branch, RayKind};
use crate::tree::ray_tree::{BranchRecord, RayNode, RayTree, ShadowOutcomeRecord};
use crate::views::numbers::{num, vec3};

/// What kind of step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StepKind {
    /// A ray is spawned.
    Spawn,
    /// One object is tested.
    Test,
    /// The closest hit is chosen.
    Hit,
    /// Nothing was hit.
    Miss,
    /// A shadow ray toward one light.
    Shadow,
    /// The local color is summed.
    Local,
    /// The reflected branch.
    Reflect,
    /// The refracted branch.
    Refract,
    /// `color = local + k_rfl·reflected + k_rfa·refracted`.
    Combine,
    /// The color goes back to the parent (or the pixel).
    Return,
}

/// One step of the algorithm.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Step {
    /// Index of the node (ray) it belongs to.
    pub node: usize,
    /// What kind of step.
    pub kind: StepKind,
    /// One line, with its numbers.
    pub text: String,
}

/// The steps of `tree` in execution order. `kind_of(object)` names an object's
/// shape ("sphere", "plane") for the test steps.
pub fn steps(tree: &RayTree, kind_of: &dyn Fn(usize) -> String) -> Vec<Step> {
    let mut out = Vec::new();
    if !tree.nodes.is_empty() {
        walk(tree, 0, kind_of, &mut out);
    }
    out
}

/// How much searching a ray's closest hit took.
pub fn searched(t: &crate::geometry::hit::TestCounts) -> String {
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

fn walk(tree: &RayTree, i: usize, kind_of: &dyn Fn(usize) -> String, out: &mut Vec<Step>) {
    let node = &tree.nodes[i];
    let mut push = |kind, text: String| {
        out.push(Step {
            node: i,
            kind,
            text,
        })
    };
    push(
        StepKind::Spawn,
        format!(
            "spawn {} ray (depth {}, weight {}) from {} along {}",
            kind_name(node.kind),
            node.depth,
            num(node.weight),
            vec3(node.origin),
            vec3(node.direction)
        ),
    );
    for test in &node.tests {
        let found = if test.roots.is_empty() {
            "miss".to_owned()
        } else {
            format!(
                "t = {}",
                test.roots
                    .iter()
                    .map(|&t| num(t))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        push(
            StepKind::Test,
            format!("test {} '{}': {found}", kind_of(test.object), test.name),
        );
    }
    let to = node.parent.map_or("the pixel".to_owned(), |p| {
        format!("its parent, the {} ray", kind_name(tree.nodes[p].kind))
    });
    let Some(hit) = &node.hit else {
        push(
            StepKind::Miss,
            format!(
                "no hit: the ray returns the background {} ({})",
                vec3(node.sum.color),
                searched(&node.tested)
            ),
        );
        push(
            StepKind::Return,
            format!("return {} to {to}", vec3(node.sum.color)),
        );
        return;
    };
    let side = if hit.entering { "entering" } else { "leaving" };
    push(
        StepKind::Hit,
        format!(
            "closest hit: '{}' at t = {}, point {}, normal {}, {side}, n {} → {} ({})",
            hit.name,
            num(hit.t),
            vec3(hit.point),
            vec3(hit.normal),
            num(hit.n1),
            num(hit.n2),
            searched(&node.tested)
        ),
    );
    for s in &node.shadow_rays {
        let what = match &s.outcome {
            ShadowOutcomeRecord::FacesAway => {
                "the light is behind the surface: no ray cast".to_owned()
            }
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
        push(
            StepKind::Shadow,
            format!("shadow ray to light '{}': {what}", s.name),
        );
    }
    if let Some(local) = &node.local {
        let lights: Vec<String> = local
            .lights
            .iter()
            .map(|l| {
                format!(
                    "'{}' (diffuse {} + specular {})",
                    l.name,
                    vec3(l.diffuse),
                    vec3(l.specular)
                )
            })
            .collect();
        let lights = if lights.is_empty() {
            String::new()
        } else {
            format!(" + {}", lights.join(" + "))
        };
        push(
            StepKind::Local,
            format!(
                "local = ambient {}{lights} = {}",
                vec3(local.ambient),
                vec3(local.total)
            ),
        );
    }
    // Children interleave with the branch steps, as the recursion runs them.
    for (kind, child) in [
        (StepKind::Reflect, &node.reflected),
        (StepKind::Refract, &node.refracted),
    ] {
        let Some(child) = child else { continue };
        out.push(Step {
            node: i,
            kind,
            text: branch_text(kind, child, node),
        });
        if let Some(c) = child.node {
            walk(tree, c, kind_of, out);
        }
    }
    let s = &node.sum;
    out.push(Step {
        node: i,
        kind: StepKind::Combine,
        text: format!(
            "color = local {} + {} × reflected {} + {} × refracted {} = {}",
            vec3(s.local),
            num(s.k_rfl),
            vec3(s.reflected),
            num(s.k_rfa),
            vec3(s.refracted),
            vec3(s.color)
        ),
    });
    out.push(Step {
        node: i,
        kind: StepKind::Return,
        text: format!("return {} to {to}", vec3(s.color)),
    });
}

fn branch_text(kind: StepKind, child: &BranchRecord, node: &RayNode) -> String {
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
            num(child.coefficient),
            num(child.coefficient - r.coefficient),
            num(r.coefficient)
        ),
        _ => num(child.coefficient),
    };
    match child.outcome {
        Branch::Traced => format!(
            "spawn the {name} ray ({k} = {k_value}, weight {})",
            num(node.weight * child.coefficient)
        ),
        Branch::NoCoefficient => format!("no {name} ray: {k} = 0"),
        Branch::MaxDepth => format!("no {name} ray: depth {} is the maximum", node.depth),
        Branch::WeightCutoff => format!(
            "no {name} ray: its weight {} is below the cutoff",
            num(node.weight * child.coefficient)
        ),
        Branch::TotalInternalReflection => format!(
            "no refracted ray: total internal reflection (n {} → {} beyond the critical angle); its share {} went to the reflected ray",
            node.hit.as_ref().map_or(String::new(), |h| num(h.n1)),
            node.hit.as_ref().map_or(String::new(), |h| num(h.n2)),
            num(child.coefficient)
        ),
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
