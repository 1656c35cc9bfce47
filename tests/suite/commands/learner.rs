//! The learner trace and `raytree check` (issue 25): raytree's own reduced
//! trace checks clean on every pixel of every shipped scene; each classic
//! mistake, applied alone to raytree's own trace in Rust, is the first
//! divergence with its diagnosis at the right ray; a correct trace written
//! differently raises nothing; bad files are one line and exit 2.

use std::path::Path;

use glam::DVec3;
use raytree::course::learner::format::{LearnerRay, LearnerShadow, LearnerTrace};
use raytree::course::learner::report::Report;
use raytree::course::learner::{check, read, reduce};
use raytree::scene::Scene;
use raytree::scene::source::{self, SceneSource};
use raytree::shading::optics::{reflect, refract};
use raytree::tree::document::TraceDocument;

fn load(name: &str) -> (Scene, SceneSource) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    source::load(Some(&path)).unwrap_or_else(|e| panic!("{e}"))
}

/// raytree's trace of a pixel of the Whitted scene (640×480), and its reduction.
fn whitted(x: u32, y: u32) -> (Scene, SceneSource, TraceDocument, LearnerTrace) {
    let (scene, src) = load("whitted.json");
    let trace = check::ours(&scene, src.clone(), (x, y)).unwrap();
    let learner = reduce::reduce(&trace).unwrap();
    (scene, src, trace, learner)
}

/// Checks `learner`, after a trip through its JSON and the strict reader.
fn check(scene: &Scene, src: &SceneSource, px: (u32, u32), learner: &LearnerTrace) -> Report {
    let back = read::parse(&learner.to_json()).unwrap_or_else(|e| panic!("{e}"));
    check::trace(scene, src.clone(), px, &back).unwrap()
}

/// The first divergence is `quantity` of `ray`, diagnosed as `id`.
fn first_is(report: &Report, ray: &str, quantity: &str, id: &str) {
    let first = report
        .divergences()
        .next()
        .unwrap_or_else(|| panic!("no divergence:\n{}", report.text()));
    assert_eq!(first.ray.to_string(), ray, "{}", report.text());
    assert!(
        first.quantity.to_string().starts_with(quantity),
        "{}",
        report.text()
    );
    let diagnosis = first
        .diagnosis
        .as_ref()
        .unwrap_or_else(|| panic!("no diagnosis:\n{}", report.text()));
    assert_eq!(diagnosis.id(), id, "{}", report.text());
    assert!(diagnosis.lesson().starts_with("lessons/"));
    assert!(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(diagnosis.lesson())
            .is_dir(),
        "{}",
        diagnosis.lesson()
    );
}

fn child(ray: &mut LearnerRay, reflected: bool) -> &mut LearnerRay {
    let c = if reflected {
        &mut ray.reflected
    } else {
        &mut ray.refracted
    };
    c.as_mut().unwrap().as_mut().unwrap()
}

fn hit(ray: &mut LearnerRay) -> &mut raytree::course::learner::format::LearnerHit {
    ray.hit.as_mut().unwrap().as_mut().unwrap()
}

#[test]
fn raytree_checks_clean_against_itself_on_every_pixel_of_every_shipped_scene() {
    let mut scenes: Vec<_> =
        std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
    scenes.sort();
    assert!(scenes.len() >= 5);
    for path in scenes {
        let (mut scene, src) = source::load(Some(&path)).unwrap();
        scene.settings.width = 32;
        scene.settings.height = 24;
        for y in 0..24 {
            for x in 0..32 {
                let trace = check::ours(&scene, src.clone(), (x, y)).unwrap();
                let learner = reduce::reduce(&trace).unwrap();
                let r = check(&scene, &src, (x, y), &learner);
                assert!(
                    r.differences.is_empty(),
                    "{} {x},{y}:\n{}",
                    path.display(),
                    r.text()
                );
            }
        }
    }
}

#[test]
fn a_correct_trace_written_differently_raises_nothing() {
    for px in [(416, 209), (264, 200), (120, 420), (440, 376)] {
        let (scene, src, _, mut learner) = whitted(px.0, px.1);
        // Directions of any length (t in their units), points off by float noise.
        fn redo(r: &mut LearnerRay, k: f64) {
            r.direction *= k;
            r.origin *= 1.0 + 1e-9;
            if let Some(Some(h)) = &mut r.hit {
                h.t = h.t.map(|t| t / k);
                h.normal = h.normal.map(|n| n * 0.5);
                h.point = h.point.map(|p| p * (1.0 - 1e-9));
            }
            for s in r.shadows.iter_mut().flatten() {
                s.direction = s.direction.map(|d| d * 3.0);
            }
            r.color = r.color.map(|c| c * (1.0 + 1e-9));
            for c in [&mut r.reflected, &mut r.refracted]
                .into_iter()
                .flatten()
                .flatten()
            {
                redo(c, k + 1.0);
            }
        }
        redo(&mut learner.ray, 3.7);
        let r = check(&scene, &src, px, &learner);
        assert!(r.agrees(), "{px:?}:\n{}", r.text());
    }
}

#[test]
fn rows_flipped_and_pixel_corners() {
    let (scene, src, _, learner) = whitted(416, 209);
    let camera = scene.camera();
    let mut m = learner.clone();
    m.ray.direction = camera.pixel_ray(416.0, 480.0 - 1.0 - 209.0).dir;
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary",
        "direction",
        "rows-flipped",
    );
    let mut m = learner.clone();
    // The lecture's P(r, c) is the pixel's lower left corner.
    m.ray.direction = camera.pixel_ray(416.0 - 0.5, 209.0 + 0.5).dir;
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary",
        "direction",
        "pixel-corner",
    );
}

/// A primary ray no mistake explains: most often an image of another size.
#[test]
fn a_primary_direction_unexplained_asks_about_the_image_size() {
    let (scene, src, _, mut m) = whitted(416, 209);
    let camera = scene.camera();
    // The same pixel of an image a tenth the size, as the camera would aim it.
    m.ray.direction = camera.pixel_ray(41.6, 20.9).dir * 3.0 + DVec3::new(0.0, 0.1, 0.0);
    let report = check(&scene, &src, (416, 209), &m);
    let first = report.divergences().next().unwrap();
    assert!(
        first.quantity.to_string().starts_with("direction"),
        "{}",
        report.text()
    );
    assert_eq!(first.diagnosis, None, "{}", report.text());
    assert!(
        report.text().contains("raytree's image is 640×480"),
        "{}",
        report.text()
    );
}

#[test]
fn far_and_negative_roots() {
    let (scene, src, trace, learner) = whitted(416, 209);
    let tree = &trace.samples[0].tree;
    let glass = tree.nodes[0]
        .tests
        .iter()
        .find(|t| t.name == "glass")
        .unwrap();
    let far = glass.roots.iter().map(|r| r.t).fold(f64::MIN, f64::max);
    let mut m = learner.clone();
    hit(&mut m.ray).t = Some(far);
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary",
        "hit.t",
        "far-root",
    );
    // The reflected ray leaves the glass and misses; its negative root is behind it.
    let j = tree.nodes[0].reflected.as_ref().unwrap().node.unwrap();
    let neg = tree.nodes[j]
        .tests
        .iter()
        .find(|t| t.name == "glass")
        .unwrap()
        .roots[0]
        .t;
    assert!(neg < -0.1);
    let mut m = learner.clone();
    child(&mut m.ray, true).hit = Some(Some(raytree::course::learner::format::LearnerHit {
        object: Some("glass".into()),
        t: Some(neg),
        ..Default::default()
    }));
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary → reflected d2",
        "hit",
        "negative-root",
    );
}

#[test]
fn no_offset_acne_on_a_child_and_a_shadow_ray() {
    let (scene, src, _, learner) = whitted(416, 209);
    let mut m = learner.clone();
    child(&mut m.ray, true).hit = Some(Some(raytree::course::learner::format::LearnerHit {
        object: Some("glass".into()),
        t: Some(2e-15),
        ..Default::default()
    }));
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary → reflected d2",
        "hit",
        "no-offset",
    );
    let (scene, src, _, mut m) = whitted(120, 420);
    let s = &mut m.ray.shadows.as_mut().unwrap()[0];
    assert!(!s.blocked);
    s.blocked = true;
    s.by = Some(Some("floor".into()));
    first_is(
        &check(&scene, &src, (120, 420), &m),
        "primary",
        "shadows[0].blocked",
        "no-offset",
    );
}

#[test]
fn the_normal_not_turned_where_the_ray_leaves() {
    let (scene, src, _, mut m) = whitted(416, 209);
    // primary → refracted d2 (into the cavity, TIR) → reflected d3 leaves the glass.
    let leaving = child(child(&mut m.ray, false), true);
    assert_eq!(hit(leaving).entering, Some(false));
    let n = hit(leaving).normal.unwrap();
    hit(leaving).normal = Some(-n);
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary → refracted d2 → reflected d3",
        "hit.normal",
        "normal-not-turned",
    );
}

#[test]
fn a_normal_turned_into_the_object_where_the_ray_enters() {
    let (scene, src, _, mut m) = whitted(416, 209);
    assert_eq!(hit(&mut m.ray).entering, Some(true));
    let n = hit(&mut m.ray).normal.unwrap();
    hit(&mut m.ray).normal = Some(-n);
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary",
        "hit.normal",
        "normal-inward",
    );
}

/// A change to the Phong vectors N, L, V, given the distance to the light.
type Change<'a> = dyn Fn(DVec3, DVec3, DVec3, f64) -> (DVec3, DVec3, DVec3) + 'a;

/// The Phong vectors (lesson 7): V along the ray, and N, V or L used at the
/// length the learner had them, each giving raytree's local color made again
/// with that one vector changed, from the trace's own N, L, V and light.
#[test]
fn phong_with_v_along_the_ray_or_a_vector_not_of_unit_length() {
    let (scene, src) = load("../lessons/07-phong/ball.json");
    let px = (135, 83);
    let trace = check::ours(&scene, src.clone(), px).unwrap();
    let learner = reduce::reduce(&trace).unwrap();
    let node = &trace.samples[0].tree.nodes[0];
    let (h, local) = (node.hit.as_ref().unwrap(), node.local.as_ref().unwrap());
    let phong = |change: &Change| {
        let mut total = local.ambient;
        for light in &local.lights {
            let p = light.phong.as_ref().unwrap();
            let d = (scene.lights[light.light].position - h.point).length();
            let (n, l, v) = change(h.shading_normal, p.l, p.v, d);
            let n_dot_l = n.dot(l);
            if n_dot_l > 0.0 {
                let r_dot_v = (2.0 * n_dot_l * n - l).dot(v).max(0.0);
                total += local.k_d * n_dot_l * local.color * p.arriving
                    + local.k_s * r_dot_v.powf(local.shininess) * p.arriving;
            }
        }
        total
    };
    // Raytree's own numbers made again: the cases below change one thing only.
    let same = phong(&|n, l, v, _| (n, l, v));
    assert!((same - local.total).abs().max_element() < 1e-12, "{same}");
    let c = learner.ray.direction.length();
    assert!((c - 1.0).abs() > 1e-3, "the primary direction is unit: {c}");
    let cases: [(&Change, f64, &str); 4] = [
        (&|n, l, v, _| (n, l, -v), 1.0, "view-sign"),
        (&|n, l, v, _| (n, l, v * c), 1.0, "not-normalized"),
        (&|n, l, v, d| (n, l * d, v), 1.0, "not-normalized"),
        (&|n, l, v, _| (n * 1.25, l, v), 1.25, "not-normalized"),
    ];
    for (change, normal, id) in cases {
        let mut m = learner.clone();
        m.ray.local = Some(phong(change));
        let n = hit(&mut m.ray).normal.unwrap();
        hit(&mut m.ray).normal = Some(n * normal);
        first_is(&check(&scene, &src, px, &m), "primary", "local color", id);
    }
}

/// The primary ray's hit: the unit incoming direction and the normal.
fn incoming(trace: &TraceDocument, node: usize) -> (DVec3, DVec3, f64, f64) {
    let h = trace.samples[0].tree.nodes[node].hit.as_ref().unwrap();
    (h.incoming, h.shading_normal, h.n1, h.n2)
}

#[test]
fn eta_swapped_and_the_wrong_medium() {
    let (scene, src, trace, learner) = whitted(416, 209);
    let (c, n, n1, n2) = incoming(&trace, 0);
    let mut m = learner.clone();
    child(&mut m.ray, false).direction = refract(c, n, n2 / n1).unwrap();
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary → refracted d2",
        "direction",
        "eta-swapped",
    );
    // Leaving the glass into air, a tracer that keeps the glass's index both sides goes straight on.
    let tree = &trace.samples[0].tree;
    let (r2, r3) = (2, 3);
    assert_eq!(tree.nodes[r3].parent, Some(r2));
    let (c, _, n1, n2) = incoming(&trace, r3);
    assert_eq!((n1, n2), (1.5, 1.0));
    let mut m = learner.clone();
    let leaving = child(child(&mut m.ray, false), true);
    child(leaving, false).direction = c;
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary → refracted d2 → reflected d3 → refracted d4",
        "direction",
        "wrong-medium",
    );
}

#[test]
fn the_reflection_formula_sign_and_an_unnormalized_normal() {
    let (scene, src, trace, learner) = whitted(264, 200);
    assert_eq!(
        trace.samples[0].tree.nodes[0].hit.as_ref().unwrap().name,
        "mirror"
    );
    let (c, n, _, _) = incoming(&trace, 0);
    let mut m = learner.clone();
    child(&mut m.ray, true).direction = c + 2.0 * n.dot(c) * n;
    first_is(
        &check(&scene, &src, (264, 200), &m),
        "primary → reflected d2",
        "direction",
        "reflection-sign",
    );
    let mut m = learner.clone();
    // n = P − center, of length r = 1.3, used as if unit.
    child(&mut m.ray, true).direction = reflect(c, 1.3 * n);
    first_is(
        &check(&scene, &src, (264, 200), &m),
        "primary → reflected d2",
        "direction",
        "not-normalized",
    );
}

#[test]
fn tir_not_handled() {
    let (scene, src, trace, mut m) = whitted(416, 209);
    // The refracted ray inside the glass meets the cavity past the critical
    // angle; a tracer that clamps sin θ₂ at 1 refracts along the surface
    // (cos θ₂ = 0). (Straight on, η = 1, would be the wrong medium's index.)
    let node = trace.samples[0].tree.nodes[0]
        .refracted
        .as_ref()
        .unwrap()
        .node
        .unwrap();
    let (c, n, n1, n2) = incoming(&trace, node);
    let eta = n1 / n2;
    let d = eta * c + eta * (-n.dot(c)) * n;
    let inside = child(&mut m.ray, false);
    assert_eq!(inside.tir, Some(true));
    let at = hit(inside).point.unwrap();
    inside.k_rfl = Some(DVec3::ZERO);
    inside.k_rfa = Some(DVec3::ONE);
    inside.reflected = Some(None);
    inside.refracted = Some(Some(Box::new(LearnerRay::new(
        raytree::course::learner::format::Kind::Refracted,
        at,
        d,
    ))));
    inside.tir = Some(false);
    first_is(
        &check(&scene, &src, (416, 209), &m),
        "primary → refracted d2",
        "k_rfl",
        "tir-not-handled",
    );
}

#[test]
fn coefficients_not_applied_or_applied_twice() {
    let (scene, src, _, learner) = whitted(416, 209);
    let rfl = child(&mut learner.clone().ray, true).color.unwrap();
    let rfa = child(&mut learner.clone().ray, false).color.unwrap();
    let local = learner.ray.local.unwrap();
    for sum in [local + rfl + rfa, local + 0.01 * rfl + 0.88 * 0.88 * rfa] {
        let mut m = learner.clone();
        m.ray.color = Some(sum);
        first_is(
            &check(&scene, &src, (416, 209), &m),
            "primary",
            "color",
            "coefficients",
        );
    }
}

/// A wrong local color on a ray with no children makes its color wrong too,
/// and the sum is not to blame: the first divergence keeps the diagnosis.
#[test]
fn a_wrong_local_color_does_not_blame_the_coefficients() {
    let (scene, src, trace, mut m) = whitted(120, 420);
    let node = &trace.samples[0].tree.nodes[0];
    assert!(node.reflected.as_ref().and_then(|b| b.node).is_none());
    assert!(node.refracted.as_ref().and_then(|b| b.node).is_none());
    let wrong = m.ray.local.unwrap() * 0.5;
    m.ray.local = Some(wrong);
    m.ray.color = Some(wrong);
    let report = check(&scene, &src, (120, 420), &m);
    let color = report
        .divergences()
        .find(|d| d.quantity.to_string() == "color")
        .unwrap_or_else(|| panic!("{}", report.text()));
    assert_eq!(color.diagnosis, None, "{}", report.text());
}

#[test]
fn n_dot_l_not_clamped() {
    // A ball lit from behind: at the pixel in its middle the light is behind the surface.
    let scene = raytree::scene::loader::parse(
        r#"{
      "camera": { "eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40 },
      "render": { "width": 32, "height": 24 },
      "materials": { "m": { "color": [1, 1, 1], "diffuse": 0.8 } },
      "lights": [ { "name": "back", "position": [3, 0, -3], "color": [1, 1, 1] } ],
      "objects": [ { "name": "ball", "sphere": { "center": [0, 0, 0], "radius": 1 }, "material": "m" } ]
    }"#,
        "t.json",
    )
    .unwrap();
    let src = SceneSource {
        file: "t.json".into(),
        hash: String::new(),
    };
    let (px, k) = ((16, 12), 0);
    let trace = check::ours(&scene, src.clone(), px).unwrap();
    let mut m = reduce::reduce(&trace).unwrap();
    let node = &trace.samples[0].tree.nodes[0];
    let (h, local) = (node.hit.as_ref().unwrap(), node.local.as_ref().unwrap());
    let light = &scene.lights[k];
    let nl = h.shading_normal.dot((light.position - h.point).normalize());
    assert!(nl < 0.0);
    m.ray.local = Some(local.total + local.k_d * nl * local.color * light.color);
    first_is(
        &check(&scene, &src, px, &m),
        "primary",
        "local color",
        "not-clamped",
    );
}

#[test]
fn shadows_blocked_beyond_the_light() {
    let scene_text = r#"{
      "camera": { "eye": [0, 3, 6], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40 },
      "render": { "width": 32, "height": 24 },
      "materials": { "m": { "color": [1, 1, 1] } },
      "lights": [ { "name": "lamp", "position": [0, 2, 0], "color": [1, 1, 1] } ],
      "objects": [
        { "name": "floor", "plane": { "point": [0, 0, 0], "normal": [0, 1, 0] }, "material": "m" },
        { "name": "high", "sphere": { "center": [0, 4, 0], "radius": 1.5 }, "material": "m" }
      ]
    }"#;
    let scene = raytree::scene::loader::parse(scene_text, "t.json").unwrap();
    let src = SceneSource {
        file: "t.json".into(),
        hash: String::new(),
    };
    let px = (16, 14);
    let trace = check::ours(&scene, src.clone(), px).unwrap();
    let mut m = reduce::reduce(&trace).unwrap();
    assert_eq!(hit(&mut m.ray).object.as_deref(), Some("floor"));
    let s = &mut m.ray.shadows.as_mut().unwrap()[0];
    assert!(!s.blocked);
    s.blocked = true;
    s.by = Some(Some("high".into()));
    first_is(
        &check(&scene, &src, px, &m),
        "primary",
        "shadows[0].blocked",
        "shadow-beyond-light",
    );
}

/// A shadow ray stopped by the glass ball, which lets its share through.
#[test]
fn a_transparent_object_taken_for_a_blocker() {
    let (scene, src, trace, mut m) = whitted(440, 376);
    let ours = &trace.samples[0].tree.nodes[0].shadow_rays[0];
    assert!(
        matches!(
            ours.outcome,
            raytree::tree::ray_tree::ShadowOutcomeRecord::Reaches { transmitted } if transmitted < 1.0
        ),
        "{:?}",
        ours.outcome
    );
    let s = &mut m.ray.shadows.as_mut().unwrap()[0];
    s.blocked = true;
    s.by = Some(Some("glass".into()));
    first_is(
        &check(&scene, &src, (440, 376), &m),
        "primary",
        "shadows[0].blocked",
        "transparent-blocks",
    );
}

/// Where two opaque objects stand between a point and its light, a correct
/// tracer may name either as the blocker (it stops at the first it tests):
/// on scenes/spheres.json at 22×16, pixel 11,11's primary ray has a shadow
/// ray that both sphere1990 (raytree's) and sphere1590 (the Python
/// solution's) meet before the light. Another object named is still wrong.
#[test]
fn a_shadow_ray_may_name_any_opaque_blocker_on_its_segment() {
    let (mut scene, src) = load("spheres.json");
    scene.settings.width = 22;
    scene.settings.height = 16;
    let px = (11, 11);
    let trace = check::ours(&scene, src.clone(), px).unwrap();
    let ours = reduce::reduce(&trace).unwrap();
    /// The `n`th shadow ray blocked by sphere1990, in the tree's order.
    fn nth<'r>(r: &'r mut LearnerRay, n: &mut usize) -> Option<&'r mut LearnerShadow> {
        let named = Some(Some("sphere1990".to_owned()));
        for s in r.shadows.iter_mut().flatten() {
            if s.by == named {
                if *n == 0 {
                    return Some(s);
                }
                *n -= 1;
            }
        }
        for c in [&mut r.reflected, &mut r.refracted] {
            if let Some(Some(c)) = c
                && let Some(s) = nth(c, n)
            {
                return Some(s);
            }
        }
        None
    }
    assert!(check(&scene, &src, px, &ours).agrees());
    // sphere1590 named instead: clean where it meets that shadow ray too,
    // a divergence of `by` where it does not; both happen on this pixel.
    let (mut clean, mut wrong) = (0, 0);
    for k in 0.. {
        let mut other = ours.clone();
        let Some(s) = nth(&mut other.ray, &mut { k }) else {
            break;
        };
        s.by = Some(Some("sphere1590".into()));
        let report = check(&scene, &src, px, &other);
        match report.divergences().next() {
            None => clean += 1,
            Some(d) => {
                assert!(d.quantity.to_string().ends_with(".by"), "{}", report.text());
                assert_eq!(d.learner.to_string(), "'sphere1590'", "{}", report.text());
                wrong += 1;
            }
        }
    }
    assert!(clean >= 1 && wrong >= 1, "{clean} clean, {wrong} wrong");
    // The floor, below every shadow ray toward these lights, is never on one.
    let mut floor = ours.clone();
    nth(&mut floor.ray, &mut 0).unwrap().by = Some(Some("floor".into()));
    let report = check(&scene, &src, px, &floor);
    let first = report.divergences().next().expect("a divergence");
    assert!(
        first.quantity.to_string().ends_with(".by"),
        "{}",
        report.text()
    );
    assert_eq!(first.learner.to_string(), "'floor'", "{}", report.text());
}

#[test]
fn a_missing_branch_is_a_divergence_and_a_cut_off_one_is_tolerated() {
    let (scene, src, _, mut m) = whitted(416, 209);
    m.ray.reflected = Some(None);
    let r = check(&scene, &src, (416, 209), &m);
    assert_eq!(
        r.divergences().next().unwrap().quantity.to_string(),
        "reflected",
        "{}",
        r.text()
    );
    let (scene, src, _, mut m) = whitted(416, 209);
    let one = child(&mut m.ray, true);
    one.k_rfl = None;
    let r = check(&scene, &src, (416, 209), &m);
    assert!(r.agrees(), "{}", r.text());
}

#[test]
fn the_command_answers_with_its_exit_status() {
    let dir = tempfile::tempdir().unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json");
    let (_, _, trace, mut m) = whitted(416, 209);
    let glass = trace.samples[0].tree.nodes[0]
        .tests
        .iter()
        .find(|t| t.name == "glass")
        .unwrap();
    let far = glass.roots.iter().map(|r| r.t).fold(f64::MIN, f64::max);
    let file = dir.path().join("l.json");
    std::fs::write(&file, m.to_json()).unwrap();
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(args)
            .output()
            .unwrap()
    };
    let (s, f) = (scene.to_str().unwrap(), file.to_str().unwrap());
    assert_eq!(
        run(&["check", s, "--pixel", "416,209", f]).status.code(),
        Some(0)
    );
    hit(&mut m.ray).t = Some(far);
    std::fs::write(&file, m.to_json()).unwrap();
    let out = run(&["check", s, "--pixel", "416,209", f, "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["format"], "raytree-check-report");
    assert_eq!(v["agree"], false);
    assert_eq!(v["first"]["diagnosis"]["id"], "far-root");
    // A trace of another pixel, and a pixel off the image: bad input, said
    // in one line naming the learner's file or the flag.
    let other = run(&["check", s, "--pixel", "1,1", f]);
    assert_eq!(other.status.code(), Some(2));
    let said = String::from_utf8_lossy(&other.stderr);
    assert!(
        said.contains(f) && said.contains("pixel 416,209") && said.lines().count() == 1,
        "{said}"
    );
    let off = run(&["check", s, "--pixel", "416,2090", f]);
    assert_eq!(off.status.code(), Some(2));
    let said = String::from_utf8_lossy(&off.stderr);
    assert!(
        said.contains("--pixel 416,2090 is outside the 640×480 image"),
        "{said}"
    );
}

/// A tracer with its rows flipped is diagnosed once, at its primary ray;
/// what follows from that ray (another object hit, its shadow rays, its
/// colors) is listed as consequences, each without a diagnosis of its own:
/// those are recomputed from raytree's inputs, which are no longer the
/// learner's. (Its shadow rays, blocked by the mirror raytree's ray hit,
/// were once taken for acne.)
#[test]
fn a_flipped_tracer_s_consequences_carry_no_diagnosis() {
    let (scene, src) = load("whitted.json");
    let mut consequences = 0;
    for (x, y) in [(190, 175), (416, 209), (100, 60), (500, 400), (300, 330)] {
        let flipped = (x, scene.settings.height - 1 - y);
        let mut m = reduce::reduce(&check::ours(&scene, src.clone(), flipped).unwrap()).unwrap();
        m.pixel = None;
        let report = check(&scene, &src, (x, y), &m);
        first_is(&report, "primary", "direction", "rows-flipped");
        for d in report.divergences().skip(1) {
            consequences += 1;
            assert!(
                d.diagnosis.is_none(),
                "pixel {x},{y}: {} {} diagnosed\n{}",
                d.ray,
                d.quantity,
                report.text()
            );
        }
    }
    assert!(consequences > 10, "{consequences} consequences");
}

/// Bad learner files, each with its name and what its one line says: made
/// from a good trace of whitted.json's pixel 416,209, cut short, mistyped,
/// out of range, or nested too deep.
fn bad_learner_files() -> Vec<(&'static str, String, &'static str)> {
    let (_, _, _, m) = whitted(416, 209);
    let good = m.to_json();
    let deep = format!("{}{}", "[".repeat(1_000_000), "]".repeat(1_000_000));
    let mut nested = String::from(r#"{"format":"raytree-learner-trace","version":1,"ray":"#);
    for _ in 0..70 {
        nested.push_str(r#"{"kind":"reflected","origin":[0,0,0],"direction":[0,0,1],"reflected":"#);
    }
    nested.push_str(&format!("null{}}}", "}".repeat(70)));
    let cases: Vec<(&'static str, String, &'static str)> = vec![
        ("truncated", good[..good.len() / 2].to_owned(), ":"),
        ("empty", String::new(), "1:1: not JSON: the file ends early"),
        (
            "wrong-type",
            good.replacen("\"t\": ", "\"t\": \"x\", \"_\": ", 1),
            "ray.hit",
        ),
        (
            "nan",
            good.replacen("\"t\": ", "\"t\": NaN, \"u\": ", 1),
            "NaN",
        ),
        (
            "infinity",
            good.replacen("\"t\": ", "\"t\": -Infinity, \"u\": ", 1),
            "NaN or Infinity",
        ),
        (
            "unknown",
            good.replacen("\"entering\"", "\"entring\"", 1),
            "ray.hit.entring: unknown field",
        ),
        (
            "duplicate-key",
            good.replacen("\"t\": ", "\"t\": 1, \"t\": ", 1),
            "the key `t` is given twice in one object",
        ),
        ("deep-json", deep, "nested too deep"),
        ("deep-rays", nested, "deeper than the 64 rays"),
        (
            "huge-number",
            good.replacen("\"t\": ", "\"t\": 1e999, \"u\": ", 1),
            ":",
        ),
    ];
    cases
}

#[test]
fn bad_learner_files_are_one_line_and_exit_2() {
    let scene =
        std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json")).unwrap();
    for (name, text, says) in bad_learner_files() {
        let start = std::time::Instant::now();
        let line = common_refused(name, &scene, text.as_bytes());
        assert!(
            line.contains("l.json") && line.contains(says),
            "{name}: {line}"
        );
        assert!(
            start.elapsed().as_secs() < 10,
            "{name} took {:?}",
            start.elapsed()
        );
    }
}

/// A 1 GB file is refused from its size before a byte is read; a folder for
/// what it is: one line each, exit status 2.
#[test]
fn a_huge_learner_file_and_a_folder_are_refused_up_front() {
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.json");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(1 << 30)
        .unwrap();
    let scene_path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json");
    for (file, says) in [
        (big.as_path(), "more than the 8.4 MB"),
        (dir.path(), "directory"),
    ] {
        let start = std::time::Instant::now();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args([
                "check",
                scene_path.to_str().unwrap(),
                "--pixel",
                "1,1",
                file.to_str().unwrap(),
            ])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(says), "{err}");
        assert!(start.elapsed().as_secs() < 5);
    }
}

fn common_refused(name: &str, scene: &[u8], learner: &[u8]) -> String {
    crate::common::refused_with(
        2,
        &format!("learner-{name}"),
        &[("s.json", scene), ("l.json", learner)],
        &["check", "s.json", "--pixel", "416,209", "l.json"],
    )
}

#[test]
fn the_schema_and_the_examples_agree_with_the_reader() {
    use raytree::course::learner::format::{
        HIT_KEYS, KINDS, Key, RAY_KEYS, SHADOW_KEYS, TRACE_KEYS,
    };
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let schema: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(docs.join("learner-trace.schema.json")).unwrap(),
    )
    .unwrap();
    let agree = |at: &serde_json::Value, keys: &[Key], what: &str| {
        let mut props: Vec<&str> = at["properties"]
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        let mut ours: Vec<&str> = keys.iter().map(|(k, _)| *k).collect();
        props.sort();
        ours.sort();
        assert_eq!(props, ours, "{what}: the schema's keys");
        let mut required: Vec<&str> = at["required"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        let mut ours: Vec<&str> = keys.iter().filter(|(_, r)| *r).map(|(k, _)| *k).collect();
        required.sort();
        ours.sort();
        assert_eq!(required, ours, "{what}: the schema's required keys");
        assert_eq!(
            at["additionalProperties"], false,
            "{what}: unknown keys are refused"
        );
    };
    agree(&schema, TRACE_KEYS, "document");
    agree(&schema["$defs"]["ray"], RAY_KEYS, "ray");
    agree(&schema["$defs"]["hit"], HIT_KEYS, "hit");
    agree(&schema["$defs"]["shadow"], SHADOW_KEYS, "shadow");
    assert_eq!(
        schema["$defs"]["ray"]["properties"]["kind"]["enum"],
        serde_json::json!(KINDS)
    );
    assert_eq!(
        schema["properties"]["format"]["const"],
        raytree::course::learner::format::FORMAT
    );
    // Every example reads, and the full one checks clean against its pixel.
    let mut n = 0;
    for e in std::fs::read_dir(docs.join("learner-trace")).unwrap() {
        let path = e.unwrap().path();
        let trace = read::read(&path).unwrap_or_else(|e| panic!("{e}"));
        n += 1;
        let (scene, src) = load("whitted.json");
        let [x, y] = trace.pixel.unwrap();
        let r = check::trace(&scene, src, (x, y), &trace).unwrap();
        assert!(r.agrees(), "{}:\n{}", path.display(), r.text());
    }
    assert!(n >= 2);
}

/// A light's name mistyped is said to be no light of the scene, and a
/// shadow blocked with `"by": null` is said as blocked, naming no blocker
/// (not "blocked by 'something'"). Pixel 168,120 lights the floor from both
/// lights, so both shadow rays reach their lights.
#[test]
fn a_mistyped_light_and_an_unnamed_blocker_are_said_plainly() {
    let (scene, src, _, ours) = whitted(168, 120);
    let mut typo = ours.clone();
    let shadows = typo.ray.shadows.as_mut().unwrap();
    let name = shadows[0].light.clone();
    shadows[0].light = format!("{name}y");
    let report = check(&scene, &src, (168, 120), &typo);
    let first = report.divergences().next().expect("a divergence");
    assert_eq!(
        first.quantity.to_string(),
        "shadows[0].light",
        "{}",
        report.text()
    );
    assert!(
        first
            .learner
            .to_string()
            .contains("the scene has no light of that name"),
        "{}",
        report.text()
    );
    let mut unnamed = ours.clone();
    let s = &mut unnamed.ray.shadows.as_mut().unwrap()[0];
    s.blocked = true;
    s.by = Some(None);
    s.transmitted = None;
    let report = check(&scene, &src, (168, 120), &unnamed);
    let first = report.divergences().next().expect("a divergence");
    assert_eq!(
        first.quantity.to_string(),
        "shadows[0].blocked",
        "{}",
        report.text()
    );
    assert_eq!(first.learner.to_string(), "blocked (no blocker named)");
}

/// `check` with neither mode names both, as a usage error (exit 2); a
/// coefficient written as one number is said as one.
#[test]
fn neither_mode_names_both_and_a_scalar_coefficient_reads_as_written() {
    let dir = crate::commands::cli::workdir("check-neither");
    let scene_file = crate::commands::cli::scenes().join("whitted.json");
    let out = crate::commands::cli::raytree(&["check", scene_file.to_str().unwrap()], &dir);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--pixel X,Y") && err.contains("--image YOURS.png"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    let (scene, src, _, ours) = whitted(200, 280);
    let mut k = ours.clone();
    k.ray.k_rfl = Some(DVec3::splat(0.5));
    let report = check(&scene, &src, (200, 280), &k);
    let first = report.divergences().next().expect("a divergence");
    assert_eq!(first.quantity.to_string(), "k_rfl", "{}", report.text());
    assert_eq!(first.learner.to_string(), "0.5", "{}", report.text());
}
