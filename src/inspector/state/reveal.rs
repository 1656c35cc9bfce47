//! What the algorithm has computed by a given step, as a debugger would show
//! it: a ray exists once spawned, its tests as they run, its hit once chosen,
//! each shadow ray once cast, its local color once summed, its color once
//! returned. The inspector's panes show only this while stepping, so the
//! answer is never given away before the step that computes it.

use crate::tree::ray_tree::RayTree;
use crate::tree::steps::{Step, StepKind};

/// Per node, how far its computation has come.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Revealed {
    /// The camera stage has run (the pixel's primary ray is known).
    pub camera: bool,
    /// Per node: how many of its stages are done.
    pub nodes: Vec<RayRevealed>,
}

/// How far one ray's computation has come.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayRevealed {
    /// Spawned.
    pub spawned: bool,
    /// Boxes or cells of the scene's structure visited so far.
    pub visits: usize,
    /// Object tests run so far.
    pub tests: usize,
    /// The closest hit (or the miss) is known.
    pub hit: bool,
    /// Shadow rays cast so far.
    pub shadows: usize,
    /// The local color is summed.
    pub local: bool,
    /// The reflected branch has been decided.
    pub reflect: bool,
    /// The refracted branch has been decided.
    pub refract: bool,
    /// The color is combined (and returned).
    pub color: bool,
}

impl RayRevealed {
    /// A computation that is over: every stage done (counts saturated).
    pub const DONE: RayRevealed = RayRevealed {
        spawned: true,
        visits: usize::MAX,
        tests: usize::MAX,
        hit: true,
        shadows: usize::MAX,
        local: true,
        reflect: true,
        refract: true,
        color: true,
    };
}

impl Revealed {
    /// Everything: what free browsing shows.
    pub fn all(tree: &RayTree) -> Self {
        Self {
            camera: true,
            nodes: vec![RayRevealed::DONE; tree.nodes.len()],
        }
    }

    /// What steps `0..=current` have computed.
    pub fn until(tree: &RayTree, steps: &[Step], current: usize) -> Self {
        let mut r = Self {
            camera: false,
            nodes: vec![RayRevealed::default(); tree.nodes.len()],
        };
        for step in steps.iter().take(current + 1) {
            let Some(p) = r.nodes.get_mut(step.node) else {
                continue;
            };
            match step.kind {
                StepKind::Camera => r.camera = true,
                StepKind::Spawn => p.spawned = true,
                StepKind::Visit(k) => p.visits = k + 1,
                StepKind::Test(k) => p.tests = k + 1,
                StepKind::Hit | StepKind::Miss => p.hit = true,
                StepKind::Shadow(k) => p.shadows = k + 1,
                StepKind::Local => p.local = true,
                StepKind::Reflect => p.reflect = true,
                StepKind::Refract => p.refract = true,
                StepKind::Combine | StepKind::Return => p.color = true,
            }
        }
        r
    }

    /// Node `n`'s progress (nothing, for an index past the tree).
    pub fn node(&self, n: usize) -> RayRevealed {
        self.nodes.get(n).copied().unwrap_or_default()
    }
}

/// The recursion from the primary ray down to node `n`, as a call stack:
/// "primary → refracted d2 → reflected d3", within `width` columns: when it is
/// longer, the middle calls give way to "…", the primary ray and the newest
/// calls stay.
pub fn call_stack(tree: &RayTree, n: usize, width: usize) -> String {
    let mut chain = Vec::new();
    let mut at = Some(n);
    while let Some(i) = at.filter(|&i| i < tree.nodes.len()) {
        chain.push(i);
        at = tree.nodes[i].parent;
        if chain.len() > tree.nodes.len() {
            break; // a loop in a damaged tree: stop rather than spin
        }
    }
    let calls: Vec<String> = chain
        .iter()
        .rev()
        .map(|&i| {
            let node = &tree.nodes[i];
            let kind = node.kind.name();
            if node.depth <= 1 {
                kind.to_owned()
            } else {
                format!("{kind} d{}", node.depth)
            }
        })
        .collect();
    let whole = calls.join(" → ");
    if whole.chars().count() <= width || calls.len() < 3 {
        return whole;
    }
    // Keep the first call and as many of the newest as fit after "… → ".
    let mut kept: Vec<&str> = Vec::new();
    let mut used = calls[0].chars().count() + " → … → ".chars().count();
    for call in calls[1..].iter().rev() {
        let add = call.chars().count() + if kept.is_empty() { 0 } else { 3 };
        if used + add > width && !kept.is_empty() {
            break;
        }
        used += add;
        kept.push(call);
    }
    kept.reverse();
    format!("{} → … → {}", calls[0], kept.join(" → "))
}
