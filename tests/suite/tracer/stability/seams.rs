//! Seams and hits at awkward places: two boxes sharing a face, a large triangle
//! far from the origin, lesson 13's sheet met at a vertex at the origin.

use crate::common::scene;
use glam::DVec3;
use raytree::methods::Offset;
use raytree::trace::recorder::ShadowOutcome;

use super::FirstHit;
use raytree::trace::tracer::Tracer;

/// The slab test computed `0·∞ = NaN` for a ray lying in a face plane and let
/// it fall to one side of `min`/`max` or the other. Where two boxes share a
/// face across z, both let the whole row through to the floor beneath: a crack,
/// like Möller–Trumbore's between triangles. Where they share one across x,
/// one box took the row but lit it with its side's normal, a line across the
/// top. The closed test counts such a ray inside both slabs, and the face it
/// meets is the top it crosses, not the side it runs along.
#[test]
fn two_boxes_sharing_a_face_leave_no_crack() {
    for axis in [0, 2] {
        let (up, min2, max1) = if axis == 0 {
            ("[1, 0, 0]", "[0, 0, -1]", "[0, 1, 1]")
        } else {
            ("[0, 0, 1]", "[-1, 0, 0]", "[1, 1, 0]")
        };
        let s = scene(&format!(
            r#"{{ "camera": {{ "eye": [0, 5, 0], "look_at": [0, 0, 0], "up": {up}, "fov": 60 }},
                 "render": {{ "width": 41, "height": 41 }},
                 "lights": [{{ "position": [0.3, 10, 0.2] }}],
                 "objects": [
                   {{ "name": "floor", "plane": {{ "point": [0, -1, 0], "normal": [0, 1, 0] }} }},
                   {{ "name": "one", "box": {{ "min": [-1, 0, -1], "max": {max1} }} }},
                   {{ "name": "two", "box": {{ "min": {min2}, "max": [1, 1, 1] }} }}
                 ] }}"#
        ));
        let tracer = Tracer::new(&s);
        let camera = s.camera();
        let (mut seam, mut through) = (0, Vec::new());
        for y in 0..s.settings.height {
            for x in 0..s.settings.width {
                let ray = camera.pixel_ray(f64::from(x), f64::from(y));
                let mut rec = FirstHit::default();
                tracer.trace_primary(ray, &mut rec);
                let Some(hit) = rec.hit else { continue };
                // The boxes hide the floor from the eye wherever it lies under them.
                if hit.object == 0 && hit.point.x.abs() <= 1.0 && hit.point.z.abs() <= 1.0 {
                    through.push((x, y));
                }
                if ray.dir[axis] == 0.0 && hit.object != 0 {
                    seam += 1;
                    assert_eq!(
                        hit.normal,
                        DVec3::Y,
                        "axis {axis}, pixel {x},{y}: the top, not a side"
                    );
                }
            }
        }
        println!(
            "boxes sharing a face across axis {axis}: {seam} pixels of the row in its plane on the boxes, {} through to the floor",
            through.len()
        );
        assert_eq!(
            through,
            [],
            "axis {axis}: pixels that see the floor under the boxes"
        );
        assert!(
            seam > 10,
            "axis {axis}: the middle row lies in the shared plane and sees the boxes"
        );
    }
}

// ---------------------------------------------------------------------------
// Acne on a large triangle far from the origin.

/// The reviewers' floor: one large triangle whose corners lie 12 units and
/// more from the origin, under a light near and low. Its shadow rays met the
/// triangle they left (`blocked by 'triangle1' at t = 3.295e-16`): the hit points
/// near the origin are exact in y and the robust offset a few ULPs of them, but
/// the watertight test's `t` for a ray running more along x than y is off by
/// rounding errors of the corners' size, and nothing bounded them. Every pixel
/// of the floor must be lit, as it is with a fixed epsilon of 1e-9.
#[test]
fn a_large_far_floor_triangle_is_lit_everywhere() {
    let text = r#"{ "camera": { "eye": [0, 6, -0.5], "look_at": [0, 0, 0], "fov": 60 },
             "render": { "width": 160, "height": 120 },
             "lights": [{ "position": [-6.8, 5, -3.6] }],
             "objects": [
               { "name": "floor", "triangle": { "vertices": [[-12, 0, -12], [36, 0, -12], [-12, 0, 36]] } }
             ] }"#;
    let mut s = scene(text);
    let mut blocked = Vec::new();
    for (name, offset) in [
        ("epsilon 1e-9", Offset::Epsilon(1e-9)),
        ("robust (default)", Offset::Robust),
    ] {
        s.settings.offset = offset;
        let tracer = Tracer::new(&s);
        let camera = s.camera();
        let (mut floor, mut dark) = (0, 0);
        for y in 0..s.settings.height {
            for x in 0..s.settings.width {
                let mut rec = FirstHit::default();
                tracer.trace_primary(camera.pixel_ray(f64::from(x), f64::from(y)), &mut rec);
                let (Some(_), Some(shadow)) = (rec.hit, rec.shadow) else {
                    continue;
                };
                floor += 1;
                dark += usize::from(!matches!(shadow.outcome, ShadowOutcome::Reaches { .. }));
            }
        }
        println!(
            "offset {name:>16}: floor pixels {floor:>5}, shadowed by the floor itself {dark:>4}"
        );
        assert_eq!(floor, 160 * 120, "{name}: the floor fills the picture");
        blocked.push(dark);
    }
    assert_eq!(
        blocked,
        [0, 0],
        "floor pixels in the floor's own shadow (epsilon, robust)"
    );
}

// ---------------------------------------------------------------------------
// A hit at the world origin.

/// Lesson 13's sheet has a vertex at the origin, and the ray of its center
/// pixel 120,120 meets the sheet exactly there. The hit point's error bound
/// was relative to the point, so nearly zero, and the robust offset one
/// subnormal step: under Möller–Trumbore the shadow ray met the sheet again at
/// t = 1.0e-18, and the lesson counted that pixel among the cracks. The sheet
/// is flat and faces its lamp: no pixel on it is in its own shadow, under
/// either test.
#[test]
fn the_sheet_shadows_itself_nowhere_not_even_at_the_origin() {
    use raytree::methods::TriangleMethod;
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/13-numerics/sheet.json");
    let mut s = raytree::scene::loader::load(&path).unwrap();
    for method in [TriangleMethod::MollerTrumbore, TriangleMethod::Watertight] {
        s.settings.triangle = method;
        let tracer = Tracer::new(&s);
        let camera = s.camera();
        let mut center = FirstHit::default();
        tracer.trace_primary(camera.pixel_ray(120.0, 120.0), &mut center);
        let hit = center.hit.expect("the center pixel sees the sheet");
        // The origin up to the barycentric weights' rounding (about 1e-15).
        assert!(
            hit.point.length() < 1e-14,
            "{method:?}: the center pixel's ray meets the origin: {}",
            hit.point
        );
        assert!(
            matches!(
                center.shadow.map(|s| s.outcome),
                Some(ShadowOutcome::Reaches { .. })
            ),
            "{method:?}: pixel 120,120 shadows itself: {:?}",
            center.shadow
        );
        let (mut sheet, mut dark) = (0, Vec::new());
        for y in 0..s.settings.height {
            for x in 0..s.settings.width {
                let mut rec = FirstHit::default();
                tracer.trace_primary(camera.pixel_ray(f64::from(x), f64::from(y)), &mut rec);
                let Some(shadow) = rec.shadow else { continue };
                sheet += 1;
                if !matches!(shadow.outcome, ShadowOutcome::Reaches { .. }) {
                    dark.push((x, y));
                }
            }
        }
        println!(
            "{method:?}: {sheet} pixels on the sheet, {} in its own shadow",
            dark.len()
        );
        assert!(sheet > 40_000, "{method:?}: the sheet fills the picture");
        assert_eq!(dark, [], "{method:?}: pixels in the sheet's own shadow");
    }
}
