//! The media rule at every boundary (issue 12): a ray is in the innermost
//! (last entered) of the transparent objects it is inside, so `n₁` is that
//! medium's index and `n₂` the innermost's on the far side, for overlapping
//! objects as for nested ones; and a ray given by hand starts in the media
//! around its own origin.

use glam::DVec3;
use raytree::math::ray::Ray;
use raytree::scene::source::SceneSource;
use raytree::trace::recorder::{Branch, RayKind};
use raytree::tree::record;

use crate::common::scene;

/// Spheres A (n = 1.2), B (1.5) and C (1.8) of radius 1 at x = 0, 1.2 and 2.4:
/// each overlaps the next, none holds another. Clear glass: only refracted rays.
fn three_overlapping(weights: &str) -> raytree::scene::Scene {
    scene(&format!(
        r#"{{
        "render": {{"weights": "{weights}", "max_depth": 20, "cutoff": 0}},
        "materials": {{
            "a": {{"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.2}},
            "b": {{"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5}},
            "c": {{"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.8}}
        }},
        "objects": [
            {{"name": "A", "sphere": {{"center": [0, 0, 0], "radius": 1}}, "material": "a"}},
            {{"name": "B", "sphere": {{"center": [1.2, 0, 0], "radius": 1}}, "material": "b"}},
            {{"name": "C", "sphere": {{"center": [2.4, 0, 0], "radius": 1}}, "material": "c"}}
        ]
    }}"#
    ))
}

#[test]
fn overlapping_objects_follow_the_media_rule_at_every_crossing() {
    // An oblique ray along the row: in A, in B, out of A (inside B), in C,
    // out of B (inside C), out of C.
    let ray = Ray::new(DVec3::new(-3.0, -0.3, 0.0), DVec3::new(1.0, 0.05, 0.0));
    let expected = [
        (0, true, 1.0, 1.2),
        (1, true, 1.2, 1.5),
        (0, false, 1.5, 1.5),
        (2, true, 1.5, 1.8),
        (1, false, 1.8, 1.8),
        (2, false, 1.8, 1.0),
    ];
    for weights in ["constant", "fresnel"] {
        let scene = three_overlapping(weights);
        let text = format!("{weights}.json");
        let trace = record::ray(&scene, SceneSource::new(&text, ""), ray).unwrap();
        // The chain of refracted rays from the primary one: the crossings in order.
        let nodes = &trace.samples[0].tree.nodes;
        let mut chain = vec![&nodes[0]];
        while let Some(next) = chain
            .last()
            .unwrap()
            .refracted
            .as_ref()
            .and_then(|b| b.node)
        {
            chain.push(&nodes[next]);
        }
        let crossings: Vec<(usize, bool, f64, f64)> = chain
            .iter()
            .filter_map(|n| n.hit.as_ref())
            .map(|h| (h.object, h.entering, h.n1, h.n2))
            .collect();
        assert_eq!(crossings, expected, "{weights}");
        for (k, &(_, _, n1, n2)) in expected.iter().enumerate() {
            let (before, after) = (
                chain[k].direction.normalize(),
                chain[k + 1].direction.normalize(),
            );
            if n1 == n2 {
                // Between equal indices the ray goes straight (to rounding: a
                // few ULPs of a unit vector), and reflects nothing, under
                // Fresnel's weights too.
                assert!(
                    (after - before).length() < 1e-14,
                    "{weights} crossing {k}: {before} → {after}"
                );
                let reflected = chain[k].reflected.as_ref().unwrap();
                assert_eq!(
                    (reflected.coefficient, reflected.outcome),
                    (0.0, Branch::NoCoefficient),
                    "{weights} {k}"
                );
            } else {
                assert!(
                    (after - before).length() > 1e-4,
                    "{weights} crossing {k} should bend"
                );
            }
        }
    }
}

#[test]
fn a_ray_given_by_hand_starts_in_the_media_around_its_origin() {
    // Water (1.33) inside glass (1.5); the ray starts at the center, in water.
    let text = r#"{
        "materials": {
            "glass": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5},
            "water": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.33}
        },
        "objects": [
            {"name": "glass", "sphere": {"radius": 2}, "material": "glass"},
            {"name": "water", "sphere": {"radius": 1}, "material": "water"}
        ]
    }"#;
    let scene = scene(text);
    let ray = Ray::new(DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0, 0.2, 0.0));
    let trace = record::ray(&scene, SceneSource::new("test.json", text), ray).unwrap();
    let hits: Vec<(String, f64, f64)> = trace.samples[0]
        .tree
        .nodes
        .iter()
        .filter(|n| n.kind != RayKind::Reflected)
        .filter_map(|n| n.hit.as_ref())
        .map(|h| (h.name.clone(), h.n1, h.n2))
        .collect();
    assert_eq!(
        hits,
        [
            ("water".to_owned(), 1.33, 1.5),
            ("glass".to_owned(), 1.5, 1.0)
        ]
    );
}

/// Water (1.33, radius 1) inside glass (1.5, radius 2), both centered on the
/// origin, with the eye inside the water looking out at a checkered floor:
/// the objects listed water first when `water_first`.
fn eye_in_water_in_glass(water_first: bool) -> raytree::scene::Scene {
    let glass = r#"{"name": "glass", "sphere": {"radius": 2}, "material": "glass"}"#;
    let water = r#"{"name": "water", "sphere": {"radius": 1}, "material": "water"}"#;
    let (first, second) = if water_first {
        (water, glass)
    } else {
        (glass, water)
    };
    let mut s = scene(&format!(
        r#"{{
        "camera": {{"eye": [0, 0.2, 0.5], "look_at": [0, -3, -4]}},
        "lights": [{{"position": [3, 6, 4]}}],
        "materials": {{
            "glass": {{"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5}},
            "water": {{"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.33}},
            "floor": {{"checker": {{"size": 0.5, "colors": [[1, 1, 1], [0.2, 0.3, 0.8]]}}}}
        }},
        "objects": [
            {first},
            {second},
            {{"name": "floor", "plane": {{"point": [0, -3, 0], "normal": [0, 1, 0]}}, "material": "floor"}}
        ]
    }}"#
    ));
    s.settings.width = 64;
    s.settings.height = 48;
    s
}

#[test]
fn the_media_around_the_eye_follow_containment_not_the_files_order() {
    use raytree::trace::render::render;
    use raytree::trace::tracer::Tracer;
    let quiet = &raytree::trace::progress::Progress::QUIET;
    let glass_first = eye_in_water_in_glass(false);
    let water_first = eye_in_water_in_glass(true);
    // The same scene either way: the same picture, bit for bit.
    assert!(
        render(&glass_first, quiet).unwrap() == render(&water_first, quiet).unwrap(),
        "the order of the objects in the file changed the image"
    );
    // The center pixel's primary ray leaves the water into the glass (1.33 →
    // 1.5), then the glass into the air (1.5 → 1), in either order.
    // A ray given by hand from the same point (`trace --ray`) starts in the same media.
    for (s, given) in [&glass_first, &water_first]
        .into_iter()
        .flat_map(|s| [(s, false), (s, true)])
    {
        let mut log = crate::common::Log::default();
        let ray = s.camera().pixel_ray(32.0, 24.0);
        if given {
            Tracer::new(s).trace_given(ray, &mut log);
        } else {
            Tracer::new(s).trace_primary(ray, &mut log);
        }
        let name = |h: &raytree::trace::recorder::HitEvent| s.objects[h.object].name.clone();
        let crossings: Vec<(String, bool, f64, f64)> = log
            .hits
            .iter()
            .take(2)
            .map(|h| (name(h), h.entering, h.n1, h.n2))
            .collect();
        assert_eq!(
            crossings,
            [
                ("water".to_owned(), false, 1.33, 1.5),
                ("glass".to_owned(), false, 1.5, 1.0)
            ],
            "objects {:?}, ray given by hand: {given}",
            s.objects.iter().map(|o| &o.name).collect::<Vec<_>>()
        );
    }
}

#[test]
fn a_ray_touching_a_glass_ball_from_the_air_enters_it() {
    // From (0, 1, 5) along -z the line touches the unit ball at (0, 1, 0), where
    // n·c = 0 exactly: the geometry cannot say which side the ray is on. It
    // starts in the air, so it can only enter the glass: n₁ = 1 → n₂ = 1.5, and
    // a ray going into a denser medium is never totally reflected.
    let text = r#"{
        "materials": {"glass": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5}},
        "objects": [{"name": "glass", "sphere": {"radius": 1}, "material": "glass"}]
    }"#;
    let scene = scene(text);
    let ray = Ray::new(DVec3::new(0.0, 1.0, 5.0), DVec3::NEG_Z);
    let trace = record::ray(&scene, SceneSource::new("test.json", text), ray).unwrap();
    let root = &trace.samples[0].tree.nodes[0];
    let hit = root.hit.as_ref().expect("the ray touches the ball");
    assert_eq!(hit.point, DVec3::new(0.0, 1.0, 0.0));
    assert_eq!(hit.n_dot_c, 0.0);
    assert_eq!((hit.entering, hit.n1, hit.n2), (true, 1.0, 1.5));
    let refracted = root.refracted.as_ref().unwrap();
    assert_ne!(refracted.outcome, Branch::TotalInternalReflection);
    assert!(hit.refraction.as_ref().unwrap().direction.is_some());
    // And the refracted ray, inside the glass, leaves it where it meets it again.
    let inner = &trace.samples[0].tree.nodes[refracted.node.unwrap()];
    let out = inner.hit.as_ref().unwrap();
    assert_eq!((out.entering, out.n1, out.n2), (false, 1.5, 1.0));
}

/// A glass cube of six separate polygons (as the SPD's gears are made): a
/// ray enters through one face and leaves through another, and there it goes
/// from glass back into air (n 1.5 → 1), not from glass into glass, so the
/// exit bends it and reflects part of it (issue 27).
#[test]
fn a_solid_of_separate_faces_is_left_through_another_face() {
    let face =
        |v: [[f64; 3]; 4]| serde_json::json!({"polygon": {"vertices": v}, "material": "glass"});
    let faces = vec![
        face([
            [-1., -1., -1.],
            [-1., 1., -1.],
            [1., 1., -1.],
            [1., -1., -1.],
        ]),
        face([[-1., -1., 1.], [1., -1., 1.], [1., 1., 1.], [-1., 1., 1.]]),
        face([
            [-1., -1., -1.],
            [1., -1., -1.],
            [1., -1., 1.],
            [-1., -1., 1.],
        ]),
        face([[-1., 1., -1.], [-1., 1., 1.], [1., 1., 1.], [1., 1., -1.]]),
        face([
            [-1., -1., -1.],
            [-1., -1., 1.],
            [-1., 1., 1.],
            [-1., 1., -1.],
        ]),
        face([[1., -1., -1.], [1., 1., -1.], [1., 1., 1.], [1., -1., 1.]]),
    ];
    let scene_json = serde_json::json!({
        "render": {"weights": "fresnel", "max_depth": 3},
        "materials": {"glass": {"color": [1, 1, 1], "transparent": 0.9, "ior": 1.5}},
        "objects": faces,
    });
    let s = scene(&scene_json.to_string());
    let tracer = raytree::trace::tracer::Tracer::new(&s);
    let mut log = crate::common::Log::default();
    let ray = raytree::math::ray::Ray::new(
        glam::DVec3::new(0.2, 0.1, 5.0),
        glam::DVec3::new(0.1, 0.05, -1.0),
    );
    tracer.trace_given(ray, &mut log);
    // The primary ray enters (air → glass), the refracted ray leaves (glass → air).
    assert_eq!((log.hits[0].n1, log.hits[0].n2), (1.0, 1.5));
    assert!(log.hits[0].entering);
    let exit = log.hits[1];
    assert!(!exit.entering);
    assert_eq!((exit.n1, exit.n2), (1.5, 1.0), "leaves the glass into air");
    // Leaving the glass, the Fresnel reflectance is above 0: a reflected ray too.
    assert!(
        log.of_kind(raytree::trace::recorder::RayKind::Reflected)
            .len()
            >= 2,
        "a reflected ray at the entry and at the exit"
    );
}
