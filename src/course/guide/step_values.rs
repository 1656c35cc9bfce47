//! The numbers a guided step-through's stop may quote by name at a step
//! ([`crate::course::guide`]), and a spec's `[number]` reads by `value`:
//! each named as the step's line in `raytree trace --steps` says it, and
//! only once the algorithm knows it.

use std::collections::BTreeMap;

use crate::tree::arithmetic::Arithmetic;
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{
    Branch, HitRecord, LocalRecord, RayNode, ShadowOutcomeRecord, ShadowRecord, TestRecord,
};
use crate::tree::steps::{StepKind, visit_tests};
use crate::views::numbers::{color, degrees, num, vec3};
use crate::views::walk;

/// The numbers a stop may quote: those of the step's ray (its kind, depth, hit,
/// angles, local color, sum, the boxes and primitives its search tested), the
/// pixel's camera stage, and the step's own (the object tested; the shadow
/// ray's light, its tests and the recent blocker it tried first).
pub fn values(trace: &TraceDocument, sample: usize, step: usize) -> BTreeMap<String, String> {
    let steps = trace.steps(sample);
    let Some(s) = steps.get(step) else {
        return BTreeMap::new();
    };
    let mut v = Values::default();
    pixel(&mut v, trace, sample, step, steps.len());
    let node = &trace.samples[sample].tree.nodes[s.node];
    let known = Known::at(s.kind);
    ray(&mut v, node, s.kind);
    // The search for the closest hit is over once it is chosen (or missed):
    // what it cost is known from then on.
    if known.hit || s.kind == StepKind::Miss {
        v.put("boxes", node.tested.boxes.to_string());
        v.put("primitives", node.tested.primitives.to_string());
    }
    if let Some(h) = node.hit.as_ref().filter(|_| known.hit) {
        hit(&mut v, h, known.angles);
    }
    if let Some(l) = node.local.as_ref().filter(|_| known.local) {
        local(&mut v, l);
    }
    match s.kind {
        StepKind::Visit(k) => visit(&mut v, trace, node, k),
        StepKind::Test(k) => test(&mut v, &node.tests[k]),
        StepKind::Shadow(k) => shadow(&mut v, &node.shadow_rays[k]),
        _ => {}
    }
    v.0
}

/// The names and their values, as the step's line writes them.
#[derive(Default)]
struct Values(BTreeMap<String, String>);

impl Values {
    fn put(&mut self, name: &str, value: String) {
        self.0.insert(name.to_owned(), value);
    }
}

/// What the algorithm knows of a ray by a step: a stop must not give the
/// answer away before the step that computes it.
struct Known {
    /// The closest hit, once chosen.
    hit: bool,
    /// The local color, once shaded.
    local: bool,
    /// The angles of refraction, once the refraction is computed.
    angles: bool,
}

impl Known {
    fn at(kind: StepKind) -> Self {
        Known {
            hit: !matches!(
                kind,
                StepKind::Camera
                    | StepKind::Spawn
                    | StepKind::Visit(_)
                    | StepKind::Test(_)
                    | StepKind::Miss
            ),
            local: matches!(
                kind,
                StepKind::Local
                    | StepKind::Reflect
                    | StepKind::Refract
                    | StepKind::Combine
                    | StepKind::Return
            ),
            angles: matches!(
                kind,
                StepKind::Refract | StepKind::Combine | StepKind::Return
            ),
        }
    }
}

/// The pixel's: the step's place, the camera stage and the image plane; the
/// pixel's color at its last step.
fn pixel(v: &mut Values, trace: &TraceDocument, sample: usize, step: usize, steps: usize) {
    let smp = &trace.samples[sample];
    v.put("step", (step + 1).to_string());
    v.put("steps", steps.to_string());
    if let Some(cam) = &smp.camera {
        v.put("x", num(cam.x));
        v.put("y", num(cam.y));
        v.put("c", num(cam.c));
        v.put("r", num(cam.r));
        v.put("u_c", num(cam.u_c));
        v.put("v_r", num(cam.v_r));
        v.put("P", vec3(cam.point));
    }
    if step + 1 == steps {
        v.put("color", color(smp.color));
    }
    v.put("N", num(trace.camera.distance));
    v.put("W", num(trace.camera.half_width));
    v.put("H", num(trace.camera.half_height));
}

/// The step's ray: what it is, its sum once combined, and at a branch's step
/// the coefficient and the weight of the ray it spawns.
fn ray(v: &mut Values, node: &RayNode, kind: StepKind) {
    v.put("ray", node.kind.name().to_owned());
    v.put("depth", node.depth.to_string());
    v.put("origin", vec3(node.origin));
    v.put("direction", vec3(node.direction));
    v.put("weight", num(node.weight));
    // The step's own ray's weight, where `weight` is its branch's (below).
    v.put("ray_weight", num(node.weight));
    if matches!(kind, StepKind::Combine | StepKind::Return) {
        v.put("ray_color", color(node.sum.color));
        v.put("k_rfl", num(node.sum.k_rfl));
        v.put("k_rfa", num(node.sum.k_rfa));
    }
    // A branch's step prints its coefficient and the weight of the ray it
    // spawns (or would, below the cutoff): the names say what the line says.
    let branches = [
        (StepKind::Reflect, "k_rfl", &node.reflected),
        (StepKind::Refract, "k_rfa", &node.refracted),
    ];
    for (branch_kind, k, branch) in branches {
        let known =
            kind == branch_kind || (branch_kind == StepKind::Reflect && kind == StepKind::Refract);
        if let Some(b) = branch.as_ref().filter(|_| known) {
            v.put(k, num(b.coefficient));
            if kind == branch_kind && matches!(b.outcome, Branch::Traced | Branch::WeightCutoff) {
                v.put("weight", num(node.weight * b.coefficient));
            }
        }
    }
}

/// The closest hit: where, on what, its normals, and Snell's angles once
/// the refraction is computed (`angles`).
fn hit(v: &mut Values, h: &HitRecord, angles: bool) {
    v.put("object", h.name.clone());
    v.put("material", h.material.clone());
    v.put("t", num(h.t));
    v.put("point", vec3(h.point));
    v.put("on_ray", vec3(h.on_ray));
    v.put("normal", vec3(h.shading_normal));
    v.put("n1", num(h.n1));
    v.put("n2", num(h.n2));
    v.put("n_dot_c", num(h.n_dot_c));
    v.put("mirror", vec3(h.mirror));
    if let Some(p) = h.object_point {
        v.put("object_point", vec3(p));
    }
    if let (Some(n), Some(wrong)) = (h.object_normal, h.normal_like_point) {
        v.put("geometric_normal", vec3(h.normal));
        v.put("object_normal", vec3(n));
        v.put("normal_like_point", vec3(wrong));
    }
    if let Some(off) = crate::views::explain::normal_like_point_error(h) {
        v.put("normal_error", degrees(off));
    }
    if let Some(r) = h.refraction.as_ref().filter(|_| angles) {
        v.put("theta1", degrees(r.theta1));
        v.put("sin_theta1", num(r.sin_theta1));
        v.put("sin_theta2", num(r.sin_theta2));
        v.put("eta", num(r.eta));
        if let Some(t2) = r.theta2 {
            v.put("theta2", degrees(t2));
        }
        if let Some(c) = r.critical {
            v.put("critical", degrees(c));
        }
    }
}

/// Phong's local color: its terms, and each light's share by name.
fn local(v: &mut Values, l: &LocalRecord) {
    v.put("local", color(l.total));
    v.put("ambient", color(l.ambient));
    v.put("k_a", num(l.k_a));
    v.put("k_d", num(l.k_d));
    v.put("k_s", num(l.k_s));
    v.put("shininess", num(l.shininess));
    for light in &l.lights {
        if let Some(p) = &light.phong {
            v.put(&format!("n_dot_l.{}", light.name), num(p.n_dot_l));
            v.put(&format!("r_dot_v.{}", light.name), num(p.r_dot_v));
        }
        v.put(&format!("diffuse.{}", light.name), color(light.diffuse));
        v.put(&format!("specular.{}", light.name), color(light.specular));
    }
}

/// Box `k` the search visits, and in a grid the wall through which the ray
/// leaves the cell.
fn visit(v: &mut Values, trace: &TraceDocument, node: &RayNode, k: usize) {
    let visit = node.boxes[k];
    v.put("visit", (k + 1).to_string());
    v.put("visit_min", vec3(visit.min));
    v.put("visit_max", vec3(visit.max));
    v.put("tests_before", visit.after_tests.to_string());
    v.put("visit_tests", visit_tests(node, k).to_string());
    if trace.structure == crate::methods::Accel::Grid
        && let Some(exit) = walk::cell_exit(node, k)
    {
        v.put("exit_axis", walk::axis_name(exit.axis).to_owned());
        v.put("exit_t", num(exit.t));
        for (a, wall) in exit.walls.iter().enumerate() {
            if let Some((at, t)) = wall {
                v.put(&format!("wall.{}", walk::axis_name(a)), num(*at));
                v.put(&format!("wall_t.{}", walk::axis_name(a)), num(*t));
            }
        }
    }
}

/// An object tested: the ray in its own space, its quadratic, its roots.
fn test(v: &mut Values, test: &TestRecord) {
    v.put("tested", test.name.clone());
    if let Some(r) = &test.object_ray {
        v.put("object_origin", vec3(r.origin));
        v.put("object_direction", vec3(r.direction));
    }
    if let Some(
        Arithmetic::Quadratic {
            a,
            b,
            c,
            discriminant,
            ..
        }
        | Arithmetic::ConeQuadratic {
            a,
            b,
            c,
            discriminant,
            ..
        },
    ) = &test.arithmetic
    {
        v.put("A", num(*a));
        v.put("B", num(*b));
        v.put("C", num(*c));
        v.put("discriminant", num(*discriminant));
    }
    let roots: Vec<String> = test.roots.iter().map(|r| num(r.t)).collect();
    v.put(
        "roots",
        if roots.is_empty() {
            "none".to_owned()
        } else {
            roots.join(", ")
        },
    );
}

/// A shadow ray: its light, what its search tested, the recent blocker it
/// tried first, and what it found, in a sentence's words.
fn shadow(v: &mut Values, shadow: &ShadowRecord) {
    v.put("light", shadow.name.clone());
    v.put("shadow_boxes", shadow.tested.boxes.to_string());
    v.put("shadow_primitives", shadow.tested.primitives.to_string());
    if let Some(r) = &shadow.recent {
        v.put("recent", r.name.clone());
        let blocks = if r.blocks { "blocks" } else { "does not block" };
        v.put("recent_blocks", blocks.to_owned());
    }
    let outcome = match &shadow.outcome {
        ShadowOutcomeRecord::Reaches { transmitted } if *transmitted == 1.0 => {
            "reaches the light".to_owned()
        }
        ShadowOutcomeRecord::Reaches { transmitted } => {
            v.put("transmitted", num(*transmitted));
            format!(
                "reaches the light through transparent objects, keeping {}",
                num(*transmitted)
            )
        }
        ShadowOutcomeRecord::Blocked { name, t, .. } => {
            v.put("blocker_t", num(*t));
            // Read in a sentence: "the shadow ray is blocked by the ball".
            format!("blocked by the {name}")
        }
        ShadowOutcomeRecord::FacesAway => "not cast: the light is behind the surface".to_owned(),
    };
    v.put("outcome", outcome);
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
