//! Guided step-throughs quote the trace's own numbers.

use std::path::Path;

use raytree::tree::ray_tree::Branch;
use raytree::tree::steps::StepKind;
use raytree::views::guide::{narrate, parse};
use raytree::views::numbers::degrees;

#[test]
fn a_stop_at_total_internal_reflection_quotes_the_angles_of_the_trace() {
    let scene = raytree::scene::loader::whitted();
    let trace = raytree::tree::record::pixel(
        &scene,
        raytree::scene::source::SceneSource::new("scenes/whitted.json", ""),
        416,
        209,
        None,
    )
    .unwrap();
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
    // A number the step does not have is named, with what it has.
    let wrong = parse(
        Path::new("s.toml"),
        "scene = \"x\"\npixel = [416, 209]\n[[stop]]\nstep = 1\nsay = \"{theta1}\"\n",
    )
    .unwrap();
    let e = narrate(&wrong, &trace).unwrap_err();
    assert!(
        e.starts_with("s.toml: stop 1 (step 1): no number {theta1} here; this step has "),
        "{e}"
    );
    let past = parse(
        Path::new("s.toml"),
        "scene = \"x\"\npixel = [416, 209]\n[[stop]]\nstep = 9999\nsay = \"\"\n",
    )
    .unwrap();
    let e = narrate(&past, &trace).unwrap_err();
    assert_eq!(
        e,
        format!(
            "s.toml: stop 1: step 9999 is past the pixel's {} steps",
            steps.len()
        )
    );
}
