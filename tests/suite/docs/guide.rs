//! Guided step-throughs quote the trace's own numbers.

use std::path::Path;

use raytree::course::guide::{Script, narrate, parse};
use raytree::tree::document::TraceDocument;
use raytree::tree::ray_tree::Branch;
use raytree::tree::steps::StepKind;
use raytree::views::numbers::degrees;

/// Pixel 416,209 of the Whitted scene, which meets total internal reflection.
fn tir_pixel() -> TraceDocument {
    let scene = raytree::scene::loader::whitted();
    raytree::tree::record::pixel(
        &scene,
        raytree::scene::source::SceneSource::new("scenes/whitted.json", ""),
        416,
        209,
        None,
    )
    .unwrap()
}

/// A script of the given stops at pixel 416,209, named `s.toml`.
fn stops_at(stops: &[(usize, &str)]) -> Script {
    let mut text = "scene = \"x\"\npixel = [416, 209]\n".to_owned();
    for (step, say) in stops {
        text.push_str(&format!("[[stop]]\nstep = {step}\nsay = \"{say}\"\n"));
    }
    parse(Path::new("s.toml"), &text).unwrap()
}

#[test]
fn a_stop_at_total_internal_reflection_quotes_the_angles_of_the_trace() {
    let trace = tir_pixel();
    let steps = trace.steps(0);
    let nodes = &trace.samples[0].tree.nodes;
    let tir = steps
        .iter()
        .position(|s| {
            s.kind == StepKind::Refract
                && nodes[s.node].refracted.as_ref().unwrap().outcome
                    == Branch::TotalInternalReflection
        })
        .expect("pixel 416,209 has a total internal reflection");
    let script = parse(
        Path::new("lessons/10/steps.toml"),
        &format!(
            "scene = \"../../scenes/whitted.json\"\npixel = [416, 209]\n\
             [[stop]]\nstep = 1\nsay = \"column {{c}}, row {{r}}\"\n\
             [[stop]]\nstep = {}\nsay = \"θ₁ = {{theta1}} > {{critical}}\"\n",
            tir + 1
        ),
    )
    .unwrap();
    let told = narrate(&script, &trace).unwrap();
    let refraction = nodes[steps[tir].node]
        .hit
        .as_ref()
        .unwrap()
        .refraction
        .unwrap();
    assert_eq!(told[0].text, "column 416, row 270");
    assert_eq!(told[1].step, tir);
    assert_eq!(
        told[1].text,
        format!(
            "θ₁ = {} > {}",
            degrees(refraction.theta1),
            degrees(refraction.critical.unwrap())
        )
    );
}

/// A number the step does not have is named, with what it has.
#[test]
fn a_number_the_step_lacks_is_named_with_those_it_has() {
    let trace = tir_pixel();
    let e = narrate(&stops_at(&[(1, "{theta1}")]), &trace).unwrap_err();
    assert!(
        e.starts_with("s.toml: stop 1 (step 1): no number {theta1} here; this step has "),
        "{e}"
    );
}

#[test]
fn a_stop_past_the_pixels_last_step_is_refused() {
    let trace = tir_pixel();
    let steps = trace.steps(0).len();
    let e = narrate(&stops_at(&[(9999, "")]), &trace).unwrap_err();
    assert_eq!(
        e,
        format!("s.toml: stop 1: step 9999 is past the pixel's {steps} steps")
    );
}

/// Stops go forward; but a step past the end is named first, wherever it
/// is written (it was hidden behind the order of the stops after it).
#[test]
fn stops_go_forward_and_a_step_past_the_end_is_named_first() {
    let trace = tir_pixel();
    let steps = trace.steps(0).len();
    let refused =
        |first: usize, second: usize| narrate(&stops_at(&[(first, ""), (second, "")]), &trace);
    assert_eq!(
        refused(2, 2).unwrap_err(),
        "s.toml: stop 2: step 2 does not come after step 2; stops go forward"
    );
    assert_eq!(
        refused(9999, 11).unwrap_err(),
        format!("s.toml: stop 1: step 9999 is past the pixel's {steps} steps")
    );
}

/// Lesson 12 quotes what a search cost: the boxes and primitives of a ray's
/// closest-hit search from the step that chooses the hit on, and at a shadow
/// ray its own tests and the recent blocker it tried first. Pixel 184,280 of
/// the 2,000 spheres has a shadow ray whose recent blocker blocks again.
#[test]
fn stops_quote_the_tests_a_search_made_and_the_recent_blocker() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/spheres.json");
    let scene = raytree::scene::loader::load(&path).unwrap();
    let source = raytree::scene::source::SceneSource::new("scenes/spheres.json", "");
    let trace = raytree::tree::record::pixel(&scene, source, 184, 280, None).unwrap();
    let steps = trace.steps(0);
    let nodes = &trace.samples[0].tree.nodes;
    let at = |kind: &dyn Fn(StepKind) -> bool| steps.iter().position(|s| kind(s.kind)).unwrap();
    let (test, hit) = (
        at(&|k| matches!(k, StepKind::Test(_))),
        at(&|k| k == StepKind::Hit),
    );
    let values = |step: usize| raytree::course::guide::values(&trace, 0, step);
    // Not while the search runs: only once the hit is chosen.
    assert!(!values(test).contains_key("boxes"));
    let tested = nodes[steps[hit].node].tested;
    assert_eq!(values(hit)["boxes"], tested.boxes.to_string());
    assert_eq!(values(hit)["primitives"], tested.primitives.to_string());
    let recent = steps
        .iter()
        .position(|s| match s.kind {
            StepKind::Shadow(k) => nodes[s.node].shadow_rays[k].recent.is_some(),
            _ => false,
        })
        .expect("pixel 184,280 tries a recent blocker first");
    let StepKind::Shadow(k) = steps[recent].kind else {
        unreachable!()
    };
    let shadow = &nodes[steps[recent].node].shadow_rays[k];
    let tried = shadow.recent.as_ref().unwrap();
    let v = values(recent);
    assert_eq!(v["recent"], tried.name);
    assert_eq!(
        v["recent_blocks"],
        if tried.blocks {
            "blocks"
        } else {
            "does not block"
        }
    );
    assert_eq!(v["shadow_boxes"], shadow.tested.boxes.to_string());
    assert_eq!(v["shadow_primitives"], shadow.tested.primitives.to_string());
    // A blocker tried first that blocks again is the only test the ray makes.
    if tried.blocks {
        assert_eq!(
            (v["shadow_boxes"].as_str(), v["shadow_primitives"].as_str()),
            ("0", "1")
        );
    }
    // A shadow ray that tried nothing first has no `recent`.
    let first = at(&|k| matches!(k, StepKind::Shadow(_)));
    assert!(nodes[steps[first].node].shadow_rays[0].recent.is_none());
    assert!(!values(first).contains_key("recent"));
}

#[test]
fn shadow_and_object_space_stops_quote_what_the_trace_recorded() {
    use raytree::course::guide::values;
    use raytree::tree::ray_tree::ShadowOutcomeRecord;
    use raytree::views::numbers::{num, vec3};
    let source = || raytree::scene::source::SceneSource::new("test", "");
    // Floor pixel 440,376 of the Whitted scene is lit through the glass ball by both lights.
    let scene = raytree::scene::loader::whitted();
    let trace = raytree::tree::record::pixel(&scene, source(), 440, 376, None).unwrap();
    let steps = trace.steps(0);
    let node = &trace.samples[0].tree.nodes[0];
    let at = steps
        .iter()
        .position(|s| s.kind == StepKind::Shadow(0) && s.node == 0)
        .unwrap();
    let ShadowOutcomeRecord::Reaches { transmitted } = node.shadow_rays[0].outcome else {
        panic!("the key's shadow ray reaches the light through the glass");
    };
    let v = values(&trace, 0, at);
    assert_eq!(v["transmitted"], num(transmitted));
    assert_eq!(
        v["outcome"],
        format!(
            "reaches the light through transparent objects, keeping {}",
            num(transmitted)
        )
    );
    // A transformed object: S' and c' at its test, P' and the normals at the hit.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/ellipsoids.json");
    let scene = raytree::scene::loader::load(&path).unwrap();
    let trace = raytree::tree::record::pixel(&scene, source(), 320, 240, None).unwrap();
    let steps = trace.steps(0);
    let node = &trace.samples[0].tree.nodes[0];
    let hit = node.hit.as_ref().unwrap();
    let test = node
        .tests
        .iter()
        .position(|t| t.object == hit.object)
        .unwrap();
    let at = steps
        .iter()
        .position(|s| s.kind == StepKind::Test(test) && s.node == 0)
        .unwrap();
    let ray = node.tests[test].object_ray.unwrap();
    let v = values(&trace, 0, at);
    assert_eq!(v["object_origin"], vec3(ray.origin));
    assert_eq!(v["object_direction"], vec3(ray.direction));
    let at = steps
        .iter()
        .position(|s| s.kind == StepKind::Hit && s.node == 0)
        .unwrap();
    let v = values(&trace, 0, at);
    assert_eq!(v["object_point"], vec3(hit.object_point.unwrap()));
    assert_eq!(v["object_normal"], vec3(hit.object_normal.unwrap()));
    assert_eq!(v["normal_like_point"], vec3(hit.normal_like_point.unwrap()));
    assert!(v["normal_error"].ends_with('°'), "{}", v["normal_error"]);
}
