//! "Try the recent hit first" (the lecture's efficiency slide): a shadow ray
//! first tests the object that blocked the last shadow ray toward its light,
//! which ends the search at once when it blocks again; the test counts show
//! the saving, and the outcome and the color never depend on it.

use glam::DVec3;
use raytree::math::ray::Ray;
use raytree::trace::recorder::{RecentTry, Recorder, ShadowEvent, ShadowOutcome};
use raytree::trace::tracer::Tracer;

/// Keeps every shadow ray.
#[derive(Default)]
struct Shadows(Vec<ShadowEvent>);

impl Recorder for Shadows {
    const ENABLED: bool = true;
    fn shadow_ray(&mut self, shadow: &ShadowEvent) {
        self.0.push(*shadow);
    }
}

/// A floor under one light, a wide opaque umbrella (object 1) between them
/// over x < 0, and 40 small spheres off to the side, so the scene has a hierarchy.
fn scene() -> raytree::scene::Scene {
    let mut objects = vec![
        r#"{ "name": "floor", "plane": { "point": [0, 0, 0], "normal": [0, 1, 0] }, "material": "m" }"#.to_owned(),
        r#"{ "name": "umbrella", "box": { "min": [-20, 5, -20], "max": [0, 5.5, 20] }, "material": "m" }"#.to_owned(),
    ];
    objects.extend((0..40).map(|i| {
        format!(
            r#"{{ "sphere": {{ "center": [{}, 1, 30], "radius": 0.4 }}, "material": "m" }}"#,
            i
        )
    }));
    let text = format!(
        r#"{{ "camera": {{ "eye": [0, 2, -10], "look_at": [0, 0, 0] }},
             "materials": {{ "m": {{ "color": [0.5, 0.5, 0.5] }} }},
             "lights": [{{ "name": "sun", "position": [0, 50, 0] }}],
             "objects": [{}] }}"#,
        objects.join(",\n")
    );
    raytree::scene::loader::parse(&text, "recent.json").unwrap()
}

/// A ray from high above down onto the floor at `x`, below the umbrella's height.
fn down_to(x: f64) -> Ray {
    Ray::new(DVec3::new(x, 4.0, -3.0), DVec3::new(0.0, -1.0, 0.5))
}

#[test]
fn the_last_blocker_is_tried_first() {
    let scene = scene();
    let tracer = Tracer::new(&scene);
    assert!(tracer.accelerator().bvh().is_some());
    let mut rec = Shadows::default();
    let colors: Vec<DVec3> = [-5.0, -6.0, 5.0]
        .iter()
        .map(|&x| tracer.trace_primary(down_to(x), &mut rec))
        .collect();
    let [first, second, lit] = rec.0.as_slice() else {
        panic!("three shadow rays: {:?}", rec.0);
    };
    // The first shadow ray knows nothing yet: it searches the hierarchy.
    assert_eq!(first.recent, None);
    assert!(matches!(
        first.outcome,
        ShadowOutcome::Blocked { object: 1, .. }
    ));
    assert!(
        first.tested.boxes > 0 && first.tested.primitives >= 2,
        "{first:?}"
    );
    // The second tries the umbrella first, and that one test settles it.
    let tried = RecentTry {
        object: 1,
        blocks: true,
    };
    assert_eq!(second.recent, Some(tried));
    assert!(matches!(
        second.outcome,
        ShadowOutcome::Blocked { object: 1, .. }
    ));
    assert_eq!((second.tested.boxes, second.tested.primitives), (0, 1));
    // In the light, the umbrella is tried in vain, and the search goes on without it.
    assert_eq!(
        lit.recent,
        Some(RecentTry {
            object: 1,
            blocks: false
        })
    );
    assert!(matches!(lit.outcome, ShadowOutcome::Reaches { transmitted } if transmitted == 1.0));
    // The colors are those of tracers that remember nothing.
    for (&x, color) in [-5.0, -6.0, 5.0].iter().zip(&colors) {
        let fresh = Tracer::new(&scene).trace_primary(down_to(x), &mut Shadows::default());
        assert_eq!(fresh, *color, "at x = {x}");
    }
}

#[test]
fn a_recorded_trace_shows_the_recent_blocker() {
    // A mirror floor under the umbrella and a wall beside it: the ray hits the
    // floor in the umbrella's shadow, its reflection the wall, also in that
    // shadow, so the second shadow ray toward the light tries the umbrella first.
    let text = r#"{ "camera": { "eye": [0, 2, -10], "look_at": [0, 0, 0] },
        "materials": { "m": { "color": [0.5, 0.5, 0.5] },
                       "mirror": { "color": [0.5, 0.5, 0.5], "reflective": 0.5 } },
        "lights": [{ "name": "sun", "position": [0, 50, 0] }],
        "objects": [
            { "name": "floor", "plane": { "point": [0, 0, 0], "normal": [0, 1, 0] }, "material": "mirror" },
            { "name": "umbrella", "box": { "min": [-20, 5, -20], "max": [0, 5.5, 20] }, "material": "m" },
            { "name": "wall", "box": { "min": [-11, 0, -20], "max": [-10, 4.9, 20] }, "material": "m" }
        ] }"#;
    let scene = raytree::scene::loader::parse(text, "recent.json").unwrap();
    let source = raytree::scene::source::SceneSource::new("recent.json", text);
    let ray = Ray::new(DVec3::new(-2.0, 4.0, -3.0), DVec3::new(-1.0, -1.0, 0.5));
    let doc = raytree::tree::record::ray(&scene, source, ray).unwrap();
    let json = serde_json::to_string(&doc).unwrap();
    assert_eq!(json.matches(r#""recent":null"#).count(), 1, "{json}");
    assert!(
        json.contains(r#""recent":{"object":1,"name":"umbrella","blocks":true}"#),
        "{json}"
    );
    let text = raytree::views::text::format(&doc, false);
    assert!(
        text.contains("tried 'umbrella' first, the last blocker of this light: the only test"),
        "{text}"
    );
}

#[test]
fn a_mesh_tried_first_costs_its_own_boxes_and_triangles() {
    // The umbrella as a mesh of 8 triangles: tried first, it is still one
    // object's test, but that test walks the mesh's own hierarchy, so the
    // counts show boxes and triangles, not "one primitive and no box"
    // (book/src/trace-format.md, `recent`).
    let dir = std::env::temp_dir().join(format!("raytree-recent-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut obj = String::new();
    for i in 0..=4 {
        let z = -20.0 + 10.0 * f64::from(i);
        obj += &format!("v -20 5 {z}\nv 0 5 {z}\n");
    }
    for i in 0..4 {
        let (a, b, c, d) = (2 * i + 1, 2 * i + 2, 2 * i + 3, 2 * i + 4);
        obj += &format!("f {a} {b} {d}\nf {a} {d} {c}\n");
    }
    std::fs::write(dir.join("umbrella.obj"), obj).unwrap();
    let text = r#"{ "camera": { "eye": [0, 2, -10], "look_at": [0, 0, 0] },
        "materials": { "m": { "color": [0.5, 0.5, 0.5] } },
        "lights": [{ "name": "sun", "position": [0, 50, 0] }],
        "objects": [
            { "name": "floor", "plane": { "point": [0, 0, 0], "normal": [0, 1, 0] }, "material": "m" },
            { "name": "umbrella", "mesh": { "file": "umbrella.obj" }, "material": "m" }
        ] }"#;
    std::fs::write(dir.join("scene.json"), text).unwrap();
    let scene = raytree::scene::loader::load(&dir.join("scene.json")).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let tracer = Tracer::new(&scene);
    let mut rec = Shadows::default();
    for x in [-5.0, -6.0] {
        tracer.trace_primary(down_to(x), &mut rec);
    }
    let [first, second] = rec.0.as_slice() else {
        panic!("two shadow rays: {:?}", rec.0);
    };
    assert!(matches!(
        first.outcome,
        ShadowOutcome::Blocked { object: 1, .. }
    ));
    assert_eq!(
        second.recent,
        Some(RecentTry {
            object: 1,
            blocks: true
        })
    );
    // The mesh's own boxes, and at least the triangle that blocks.
    assert!(
        second.tested.boxes > 0 && second.tested.primitives >= 1,
        "{second:?}"
    );
}
