//! The numbers a guided step-through's stop may quote by name at a step
//! ([`crate::course::guide`]), and a spec's `[number]` reads by `value`:
//! each named as the step's line in `raytree trace --steps` says it, and
//! only once the algorithm knows it.

use std::collections::BTreeMap;

use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{Branch, ShadowOutcomeRecord};
use crate::tree::steps::{StepKind, visit_tests};
use crate::views::numbers::{color, degrees, num, vec3};
use crate::views::walk;

/// The numbers a stop may quote: those of the step's ray (its kind, depth, hit,
/// angles, local color, sum, the boxes and primitives its search tested), the
/// pixel's camera stage, and the step's own (the object tested; the shadow
/// ray's light, its tests and the recent blocker it tried first).
pub fn values(trace: &TraceDocument, sample: usize, step: usize) -> BTreeMap<String, String> {
    let mut v = BTreeMap::new();
    let mut put = |k: &str, s: String| {
        v.insert(k.to_owned(), s);
    };
    let steps = trace.steps(sample);
    let Some(s) = steps.get(step) else {
        return BTreeMap::new();
    };
    let smp = &trace.samples[sample];
    put("step", (step + 1).to_string());
    put("steps", steps.len().to_string());
    if let Some(cam) = &smp.camera {
        put("x", num(cam.x));
        put("y", num(cam.y));
        put("c", num(cam.c));
        put("r", num(cam.r));
        put("u_c", num(cam.u_c));
        put("v_r", num(cam.v_r));
        put("P", vec3(cam.point));
    }
    if step + 1 == steps.len() {
        put("color", color(smp.color));
    }
    put("N", num(trace.camera.distance));
    put("W", num(trace.camera.half_width));
    put("H", num(trace.camera.half_height));
    let node = &smp.tree.nodes[s.node];
    let kind = node.kind.name();
    put("ray", kind.to_owned());
    put("depth", node.depth.to_string());
    put("origin", vec3(node.origin));
    put("direction", vec3(node.direction));
    put("weight", num(node.weight));
    // The step's own ray's weight, where `weight` is its branch's (below).
    put("ray_weight", num(node.weight));
    // Only what the algorithm knows at this step: a stop must not give the
    // answer away before the step that computes it.
    let hit_known = !matches!(
        s.kind,
        StepKind::Camera
            | StepKind::Spawn
            | StepKind::Visit(_)
            | StepKind::Test(_)
            | StepKind::Miss
    );
    let local_known = matches!(
        s.kind,
        StepKind::Local
            | StepKind::Reflect
            | StepKind::Refract
            | StepKind::Combine
            | StepKind::Return
    );
    let angles_known = matches!(
        s.kind,
        StepKind::Refract | StepKind::Combine | StepKind::Return
    );
    if matches!(s.kind, StepKind::Combine | StepKind::Return) {
        put("ray_color", color(node.sum.color));
        put("k_rfl", num(node.sum.k_rfl));
        put("k_rfa", num(node.sum.k_rfa));
    }
    // A branch's step prints its coefficient and the weight of the ray it
    // spawns (or would, below the cutoff): the names say what the line says.
    let branches = [
        (StepKind::Reflect, "k_rfl", &node.reflected),
        (StepKind::Refract, "k_rfa", &node.refracted),
    ];
    for (kind, k, branch) in branches {
        let known = s.kind == kind || (kind == StepKind::Reflect && s.kind == StepKind::Refract);
        if let Some(b) = branch.as_ref().filter(|_| known) {
            put(k, num(b.coefficient));
            if s.kind == kind && matches!(b.outcome, Branch::Traced | Branch::WeightCutoff) {
                put("weight", num(node.weight * b.coefficient));
            }
        }
    }
    // The search for the closest hit is over once it is chosen (or missed):
    // what it cost is known from then on.
    if hit_known || s.kind == StepKind::Miss {
        put("boxes", node.tested.boxes.to_string());
        put("primitives", node.tested.primitives.to_string());
    }
    if let Some(h) = node.hit.as_ref().filter(|_| hit_known) {
        put("object", h.name.clone());
        put("material", h.material.clone());
        put("t", num(h.t));
        put("point", vec3(h.point));
        put("on_ray", vec3(h.on_ray));
        put("normal", vec3(h.shading_normal));
        put("n1", num(h.n1));
        put("n2", num(h.n2));
        put("n_dot_c", num(h.n_dot_c));
        put("mirror", vec3(h.mirror));
        if let Some(p) = h.object_point {
            put("object_point", vec3(p));
        }
        if let (Some(n), Some(wrong)) = (h.object_normal, h.normal_like_point) {
            put("geometric_normal", vec3(h.normal));
            put("object_normal", vec3(n));
            put("normal_like_point", vec3(wrong));
        }
        if let Some(off) = crate::views::explain::normal_like_point_error(h) {
            put("normal_error", degrees(off));
        }
        if let Some(r) = h.refraction.as_ref().filter(|_| angles_known) {
            put("theta1", degrees(r.theta1));
            put("sin_theta1", num(r.sin_theta1));
            put("sin_theta2", num(r.sin_theta2));
            put("eta", num(r.eta));
            if let Some(t2) = r.theta2 {
                put("theta2", degrees(t2));
            }
            if let Some(c) = r.critical {
                put("critical", degrees(c));
            }
        }
    }
    if let Some(l) = node.local.as_ref().filter(|_| local_known) {
        put("local", color(l.total));
        put("ambient", color(l.ambient));
        put("k_a", num(l.k_a));
        put("k_d", num(l.k_d));
        put("k_s", num(l.k_s));
        put("shininess", num(l.shininess));
        for light in &l.lights {
            if let Some(p) = &light.phong {
                put(&format!("n_dot_l.{}", light.name), num(p.n_dot_l));
                put(&format!("r_dot_v.{}", light.name), num(p.r_dot_v));
            }
            put(&format!("diffuse.{}", light.name), color(light.diffuse));
            put(&format!("specular.{}", light.name), color(light.specular));
        }
    }
    match s.kind {
        StepKind::Visit(k) => {
            let visit = node.boxes[k];
            put("visit", (k + 1).to_string());
            put("visit_min", vec3(visit.min));
            put("visit_max", vec3(visit.max));
            put("tests_before", visit.after_tests.to_string());
            put("visit_tests", visit_tests(node, k).to_string());
            if trace.structure == crate::methods::Accel::Grid
                && let Some(exit) = walk::cell_exit(node, k)
            {
                put("exit_axis", walk::axis_name(exit.axis).to_owned());
                put("exit_t", num(exit.t));
                for (a, wall) in exit.walls.iter().enumerate() {
                    if let Some((at, t)) = wall {
                        put(&format!("wall.{}", walk::axis_name(a)), num(*at));
                        put(&format!("wall_t.{}", walk::axis_name(a)), num(*t));
                    }
                }
            }
        }
        StepKind::Test(k) => {
            let test = &node.tests[k];
            put("tested", test.name.clone());
            if let Some(r) = &test.object_ray {
                put("object_origin", vec3(r.origin));
                put("object_direction", vec3(r.direction));
            }
            if let Some(
                crate::tree::arithmetic::Arithmetic::Quadratic {
                    a,
                    b,
                    c,
                    discriminant,
                    ..
                }
                | crate::tree::arithmetic::Arithmetic::ConeQuadratic {
                    a,
                    b,
                    c,
                    discriminant,
                    ..
                },
            ) = &test.arithmetic
            {
                put("A", num(*a));
                put("B", num(*b));
                put("C", num(*c));
                put("discriminant", num(*discriminant));
            }
            let roots: Vec<String> = test.roots.iter().map(|r| num(r.t)).collect();
            put(
                "roots",
                if roots.is_empty() {
                    "none".to_owned()
                } else {
                    roots.join(", ")
                },
            );
        }
        StepKind::Shadow(k) => {
            let shadow = &node.shadow_rays[k];
            put("light", shadow.name.clone());
            put("shadow_boxes", shadow.tested.boxes.to_string());
            put("shadow_primitives", shadow.tested.primitives.to_string());
            if let Some(r) = &shadow.recent {
                put("recent", r.name.clone());
                let blocks = if r.blocks { "blocks" } else { "does not block" };
                put("recent_blocks", blocks.to_owned());
            }
            let outcome = match &shadow.outcome {
                ShadowOutcomeRecord::Reaches { transmitted } if *transmitted == 1.0 => {
                    "reaches the light".to_owned()
                }
                ShadowOutcomeRecord::Reaches { transmitted } => {
                    put("transmitted", num(*transmitted));
                    format!(
                        "reaches the light through transparent objects, keeping {}",
                        num(*transmitted)
                    )
                }
                ShadowOutcomeRecord::Blocked { name, t, .. } => {
                    put("blocker_t", num(*t));
                    // Read in a sentence: "the shadow ray is blocked by the ball".
                    format!("blocked by the {name}")
                }
                ShadowOutcomeRecord::FacesAway => {
                    "not cast: the light is behind the surface".to_owned()
                }
            };
            put("outcome", outcome);
        }
        _ => {}
    }
    v
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// `{k_rfl}` was refused at the step that prints it, and `{weight}` gave
    /// the parent's 1 under a line saying weight 0.85.
    #[test]
    fn a_branch_step_quotes_what_its_line_prints() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json");
        let (scene, source) = crate::scene::source::load(Some(&path)).unwrap();
        let trace = crate::tree::record::pixel(&scene, source, 300, 250, None).unwrap();
        let steps = trace.steps(0);
        let mut seen = 0;
        for (i, step) in steps.iter().enumerate() {
            let k = match step.kind {
                StepKind::Reflect => "k_rfl",
                StepKind::Refract => "k_rfa",
                _ => continue,
            };
            let v = values(&trace, 0, i);
            let line = crate::views::text::describe(&trace, 0, step).0;
            if !line.starts_with("spawn the") {
                continue;
            }
            seen += 1;
            let (k_value, weight) = (&v[k], &v["weight"]);
            assert!(line.contains(&format!("{k} = {k_value}")), "{line} {v:?}");
            assert!(line.contains(&format!("weight {weight}")), "{line} {v:?}");
            let ray = &trace.samples[0].tree.nodes[step.node];
            assert_eq!(v["ray_weight"], num(ray.weight));
        }
        assert!(seen > 0, "the pixel spawns a reflected ray");
    }
}
