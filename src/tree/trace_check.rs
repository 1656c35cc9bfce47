//! Checks a trace document read from a file before anything uses it: a saved
//! trace may have been edited, cut short or made by hand, and the views index
//! into it freely. After [`structure`], every index is in range, every sample
//! has a tree, every tree is a tree (parents before children, each node the
//! child of exactly one, depth one more per level), and every name matches the
//! object or light it names; after [`against_scene`], the scene a trace is
//! opened with has the objects and lights it names.
//!
//! Each error is one line naming the place, e.g.
//! `samples[0].tree.nodes[3].reflected.node: 99 is not a node (the tree has 11)`.

use crate::scene::Scene;
use crate::scene::quote::quote;
use crate::scene::source::SceneSource;
use crate::tree::document::{ObjectEntry, TraceDocument};
use crate::tree::ray_tree::{BranchRecord, RayKind, RayNode, RayTree, ShadowOutcomeRecord};

/// Most rays (tree nodes, all samples together) a trace document may hold:
/// 2²⁰. A recorded ray takes at least about a kilobyte of the document (1.7
/// kB for a ray that meets nothing in a scene of one sphere and no light;
/// 8 kB on average in the Whitted scene), so this is about as many as the
/// 1 GiB the reader reads ([`crate::io::input::MAX_INPUT_BYTES`]) can hold.
/// The reader refuses a document with more; the recorder refuses, before
/// tracing, a pixel or ray whose worst case is more
/// ([`crate::tree::record::worst_case_rays`]): the same constant, so what
/// raytree records it can read back.
pub const MAX_TRACE_RAYS: u64 = 1 << 20;

/// A name from the trace quoted in an error: printable, and cut when long.
fn q(name: &str) -> String {
    quote(name, "'")
}

/// Checks that `trace` holds together on its own.
pub fn structure(trace: &TraceDocument) -> Result<(), String> {
    if let Err((field, message)) = trace.settings.validate() {
        return Err(format!("settings.{field}: {message}"));
    }
    let rays: usize = trace.samples.iter().map(|s| s.tree.nodes.len()).sum();
    if rays as u64 > MAX_TRACE_RAYS {
        return Err(format!(
            "samples: {rays} rays in all, more than the {MAX_TRACE_RAYS} a trace holds"
        ));
    }
    printable("scene.file", &trace.scene.file)?;
    for (i, o) in trace.objects.iter().enumerate() {
        printable(&format!("objects[{i}].name"), &o.name)?;
        printable(&format!("objects[{i}].material"), &o.material)?;
        printable(&format!("objects[{i}].kind"), &o.kind)?;
    }
    for (i, l) in trace.lights.iter().enumerate() {
        printable(&format!("lights[{i}].name"), &l.name)?;
    }
    target(trace)?;
    for (k, sample) in trace.samples.iter().enumerate() {
        tree(trace, &sample.tree, &format!("samples[{k}].tree"))?;
    }
    Ok(())
}

/// A pixel inside the image with a camera stage per sample, or one ray.
fn target(trace: &TraceDocument) -> Result<(), String> {
    if trace.samples.is_empty() {
        return Err("samples: empty (a trace has at least one sample)".to_owned());
    }
    let s = &trace.settings;
    match (&trace.pixel, &trace.ray) {
        (Some(p), None) => {
            if p.x >= s.width || p.y >= s.height {
                return Err(format!(
                    "pixel: {},{} is outside the {}×{} image",
                    p.x, p.y, s.width, s.height
                ));
            }
            let most = s.max_samples();
            if trace.samples.len() > most as usize {
                let at_most = if most == s.spp { "" } else { "at most " };
                return Err(format!(
                    "samples: {} samples, but a pixel has {at_most}{most}",
                    trace.samples.len(),
                ));
            }
            for (k, sample) in trace.samples.iter().enumerate() {
                if sample.index >= most || sample.camera.is_none() || sample.position.is_none() {
                    return Err(format!(
                        "samples[{k}]: a pixel's sample needs an index below {most} (got {}), a position and a camera stage",
                        sample.index
                    ));
                }
            }
        }
        (None, Some(_)) => {
            if trace.samples.len() != 1 || trace.samples[0].camera.is_some() {
                return Err(
                    "samples: a traced ray has one sample, without a camera stage".to_owned(),
                );
            }
        }
        _ => return Err("give either pixel or ray (one of them null)".to_owned()),
    }
    Ok(())
}

/// One sample's tree: non-empty, a tree, and every index in range.
fn tree(trace: &TraceDocument, tree: &RayTree, at: &str) -> Result<(), String> {
    let nodes = &tree.nodes;
    let Some(root) = nodes.first() else {
        return Err(format!(
            "{at}.nodes: empty (a tree has at least its primary ray)"
        ));
    };
    if root.parent.is_some() || root.kind != RayKind::Primary || root.depth != 1 {
        return Err(format!(
            "{at}.nodes[0]: the root is the primary ray: no parent, depth 1"
        ));
    }
    let mut claimed = vec![false; nodes.len()];
    for (i, node) in nodes.iter().enumerate() {
        let here = format!("{at}.nodes[{i}]");
        if node.depth > trace.settings.max_depth {
            return Err(format!(
                "{here}.depth: {} is deeper than max_depth {}",
                node.depth, trace.settings.max_depth
            ));
        }
        let children = [
            (&node.reflected, RayKind::Reflected, "reflected"),
            (&node.refracted, RayKind::Refracted, "refracted"),
        ];
        for (branch, kind, name) in children {
            if let Some(c) = child(branch) {
                let what = format!("{here}.{name}.node");
                link(nodes, i, c, kind, &what)?;
                if std::mem::replace(&mut claimed[c], true) {
                    return Err(format!("{what}: node {c} already has a parent"));
                }
            }
        }
        tests(trace, node, &here)?;
        names(trace, node, &here)?;
    }
    match claimed.iter().skip(1).position(|&c| !c) {
        Some(orphan) => Err(format!(
            "{at}.nodes[{}]: no node spawns it (parents list their children)",
            orphan + 1
        )),
        None => Ok(()),
    }
}

fn child(branch: &Option<BranchRecord>) -> Option<usize> {
    branch.as_ref().and_then(|b| b.node)
}

/// Node `c`, spawned by node `p` as a `kind` ray: after it, pointing back, one level down.
fn link(nodes: &[RayNode], p: usize, c: usize, kind: RayKind, what: &str) -> Result<(), String> {
    let Some(node) = nodes.get(c) else {
        return Err(format!(
            "{what}: {c} is not a node (the tree has {})",
            nodes.len()
        ));
    };
    if c <= p || node.parent != Some(p) || node.kind != kind || node.depth != nodes[p].depth + 1 {
        return Err(format!(
            "{what}: node {c} must come after node {p}, name it as its parent, be a {} ray and one level deeper",
            format!("{kind:?}").to_lowercase()
        ));
    }
    Ok(())
}

/// The object `i` of `trace`, named `name` where `at` names it.
fn object<'t>(
    trace: &'t TraceDocument,
    i: usize,
    name: &str,
    at: String,
) -> Result<&'t ObjectEntry, String> {
    match trace.objects.get(i) {
        Some(o) if o.name == name => Ok(o),
        Some(o) => Err(format!(
            "{at}: object {i} is {}, not {}",
            q(&o.name),
            q(name)
        )),
        None => Err(format!(
            "{at}: object {i} does not exist (the trace lists {})",
            trace.objects.len()
        )),
    }
}

/// The light `i` of `trace`, named `name` where `at` names it.
fn light(trace: &TraceDocument, i: usize, name: &str, at: String) -> Result<(), String> {
    match trace.lights.get(i) {
        Some(l) if l.name == name => Ok(()),
        Some(l) => Err(format!(
            "{at}: light {i} is {}, not {}",
            q(&l.name),
            q(name)
        )),
        None => Err(format!(
            "{at}: light {i} does not exist (the trace lists {})",
            trace.lights.len()
        )),
    }
}

/// A node's tests name existing objects, each once, and its box visits sit
/// among them in the order the search made them.
fn tests(trace: &TraceDocument, node: &RayNode, here: &str) -> Result<(), String> {
    // Every structure tests an object at most once a ray (the grid and the
    // trees through a mailbox), so a longer list is no trace raytree wrote.
    if node.tests.len() > trace.objects.len() {
        return Err(format!(
            "{here}.tests: {} tests of a scene of {} objects (a ray tests each object at most once)",
            node.tests.len(),
            trace.objects.len()
        ));
    }
    let mut seen = vec![false; trace.objects.len()];
    for (k, test) in node.tests.iter().enumerate() {
        object(
            trace,
            test.object,
            &test.name,
            format!("{here}.tests[{k}].object"),
        )?;
        if std::mem::replace(&mut seen[test.object], true) {
            return Err(format!(
                "{here}.tests[{k}].object: '{}' is tested a second time (a ray tests each object at most once)",
                test.name.escape_debug()
            ));
        }
    }
    let mut before = 0;
    for (k, visit) in node.boxes.iter().enumerate() {
        if visit.after_tests < before || visit.after_tests > node.tests.len() {
            return Err(format!(
                "{here}.boxes[{k}].after_tests: {} is not between {before} (the visit before) and {} (the ray's tests)",
                visit.after_tests,
                node.tests.len()
            ));
        }
        before = visit.after_tests;
    }
    Ok(())
}

/// Every object and light a node's hit, shadow rays and local color name
/// exists, under that name.
fn names(trace: &TraceDocument, node: &RayNode, here: &str) -> Result<(), String> {
    if let Some(hit) = &node.hit {
        let o = object(trace, hit.object, &hit.name, format!("{here}.hit.object"))?;
        if o.material != hit.material {
            return Err(format!(
                "{here}.hit.material: object {} is made of {}",
                hit.object,
                q(&o.material)
            ));
        }
    }
    for (k, shadow) in node.shadow_rays.iter().enumerate() {
        let at = format!("{here}.shadow_rays[{k}]");
        light(trace, shadow.light, &shadow.name, format!("{at}.light"))?;
        if let ShadowOutcomeRecord::Blocked {
            object: i, name, ..
        } = &shadow.outcome
        {
            object(trace, *i, name, format!("{at}.outcome.object"))?;
        }
    }
    for (k, term) in node.local.iter().flat_map(|l| l.lights.iter()).enumerate() {
        let at = format!("{here}.local.lights[{k}].light");
        light(trace, term.light, &term.name, at)?;
    }
    Ok(())
}

/// A name without control characters, which a terminal would obey.
fn printable(at: &str, name: &str) -> Result<(), String> {
    match name.chars().any(char::is_control) {
        true => Err(format!("{at}: {} holds a control character", q(name))),
        false => Ok(()),
    }
}

/// Checks that `scene` has the objects and lights `trace` names, in order, as
/// the trace describes them, and every mesh face a hit names.
pub fn against_scene(trace: &TraceDocument, scene: &Scene) -> Result<(), String> {
    let now = TraceDocument::new(
        scene,
        trace.structure,
        SceneSource::new("", ""),
        trace.color,
        Vec::new(),
    );
    if now.objects.len() != trace.objects.len() || now.lights.len() != trace.lights.len() {
        return Err(format!(
            "the trace names {} objects and {} lights, the scene has {} and {}",
            trace.objects.len(),
            trace.lights.len(),
            now.objects.len(),
            now.lights.len()
        ));
    }
    if let Some(i) = (0..now.objects.len()).find(|&i| now.objects[i] != trace.objects[i]) {
        return Err(format!(
            "object {i} is {} ({} of {}) in the trace, {} ({} of {}) in the scene",
            q(&trace.objects[i].name),
            quote(&trace.objects[i].kind, ""),
            q(&trace.objects[i].material),
            q(&now.objects[i].name),
            quote(&now.objects[i].kind, ""),
            q(&now.objects[i].material)
        ));
    }
    if let Some(i) = (0..now.lights.len()).find(|&i| now.lights[i] != trace.lights[i]) {
        return Err(format!(
            "light {i} ({}) is not where, or not the color, the scene has it",
            q(&trace.lights[i].name)
        ));
    }
    for sample in &trace.samples {
        for hit in sample.tree.nodes.iter().filter_map(|n| n.hit.as_ref()) {
            let faces = match &scene.objects[hit.object].shape {
                crate::geometry::object::Shape::Mesh(m) => m.faces.len(),
                _ => 1,
            };
            if hit.face.is_some_and(|f| f as usize >= faces) {
                return Err(format!(
                    "a hit on {} names a face the mesh does not have",
                    q(&hit.name)
                ));
            }
        }
    }
    Ok(())
}
