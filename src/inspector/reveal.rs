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
    pub nodes: Vec<Progress>,
}

/// How far one ray's computation has come.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Progress {
    /// Spawned.
    pub spawned: bool,
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

impl Revealed {
    /// Everything: what free browsing shows.
    pub fn all(tree: &RayTree) -> Self {
        let done = |n: &crate::tree::ray_tree::RayNode| Progress {
            spawned: true,
            tests: n.tests.len(),
            hit: true,
            shadows: n.shadow_rays.len(),
            local: true,
            reflect: true,
            refract: true,
            color: true,
        };
        Self {
            camera: true,
            nodes: tree.nodes.iter().map(done).collect(),
        }
    }

    /// What steps `0..=current` have computed.
    pub fn until(tree: &RayTree, steps: &[Step], current: usize) -> Self {
        let mut r = Self {
            camera: false,
            nodes: vec![Progress::default(); tree.nodes.len()],
        };
        for step in steps.iter().take(current + 1) {
            let Some(p) = r.nodes.get_mut(step.node) else {
                continue;
            };
            match step.kind {
                StepKind::Camera => r.camera = true,
                StepKind::Spawn => p.spawned = true,
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
    pub fn node(&self, n: usize) -> Progress {
        self.nodes.get(n).copied().unwrap_or_default()
    }
}

/// The recursion from the primary ray down to node `n`, as a call stack:
/// "primary → refracted d2 → reflected d3".
pub fn call_stack(tree: &RayTree, n: usize) -> String {
    let mut chain = Vec::new();
    let mut at = Some(n);
    while let Some(i) = at.filter(|&i| i < tree.nodes.len()) {
        chain.push(i);
        at = tree.nodes[i].parent;
        if chain.len() > tree.nodes.len() {
            break; // a loop in a damaged tree: stop rather than spin
        }
    }
    chain
        .iter()
        .rev()
        .map(|&i| {
            let node = &tree.nodes[i];
            let kind = crate::views::text::kind_name(node.kind);
            if node.depth <= 1 {
                kind.to_owned()
            } else {
                format!("{kind} d{}", node.depth)
            }
        })
        .collect::<Vec<_>>()
        .join(" → ")
}
