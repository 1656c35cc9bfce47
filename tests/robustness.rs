//! The same scene at scales 1e-3, 1 and 1e4: no shadow acne, no light leaking
//! through a thin blocker or under it, with no per-scene epsilon.
//!
//! In a frame tilted off the world axes (so nothing is exact by accident): a floor
//! plane; a thin wall (a unit sphere scaled to 0.002 × 1 × 2, thickness 0.004)
//! standing on it with a gap of 1e-4 beneath; a flattened ellipsoid ("egg") lying
//! on the floor; a light low on the wall's far side, so the wall's shadow stretches
//! across floor the camera sees, starting right at the wall's foot.
//!
//! Whether a floor point must be in shadow is worked out without the tracer: its
//! segment to the light crosses the wall's mid-plane `x = 0` at a point `q`, with
//! elliptic radius `e = √((q_y - c_y)² + (q_z/2)²)` in the wall's silhouette. The
//! wall's thickness widens its silhouette along an oblique ray by under 0.002·|d_y/d_x|
//! < 0.001, so `e < 0.99` must be blocked (else light leaks) and `e > 1.01` must be
//! lit (else the floor shadows itself: acne). Points whose segment passes within
//! 0.6 of the egg (radius ≤ 0.5) are left out. Points on the egg whose normal
//! faces the light and whose segment clears the wall (`e > 1.01`) must be lit:
//! acne on a transformed, flattened object.

mod common;

use common::scene;
use glam::{DQuat, DVec3};
use raytree::recorder::{HitInfo, Recorder, ShadowInfo, ShadowOutcome};
use raytree::tracer::Tracer;

const GAP: f64 = 1e-4;
const WALL_CENTER: DVec3 = DVec3::new(0.0, 1.0 + GAP, 0.0);
const EGG_CENTER: DVec3 = DVec3::new(3.0, 0.3 + GAP, 4.0);
const LIGHT: DVec3 = DVec3::new(-4.0, 3.0, 0.0);

/// The tilted frame: y along the floor's normal.
fn tilt() -> DQuat {
    DQuat::from_rotation_arc(DVec3::Y, DVec3::new(0.1, 1.0, 0.05).normalize())
}

fn world(p: DVec3, scale: f64) -> DVec3 {
    tilt() * p * scale
}

fn frame(p: DVec3, scale: f64) -> DVec3 {
    tilt().inverse() * p / scale
}

fn scene_at(scale: f64) -> raytree::scene::Scene {
    scene(&scene_json(scale))
}

fn scene_json(scale: f64) -> String {
    let (axis, angle) = tilt().to_axis_angle();
    let v = |p: DVec3| format!("[{:e}, {:e}, {:e}]", p.x, p.y, p.z);
    let rotate = format!(
        r#"{{"rotate": {{"axis": {}, "degrees": {:e}}}}}"#,
        v(axis),
        angle.to_degrees()
    );
    let transform = |size: DVec3, center: DVec3| {
        format!(
            r#"[{{"scale": {}}}, {rotate}, {{"translate": {}}}]"#,
            v(size * scale),
            v(world(center, scale))
        )
    };
    format!(
        r#"{{ "camera": {{"eye": {eye}, "look_at": {look}, "up": {up}, "fov": 50}},
             "render": {{"width": 160, "height": 120}},
             "ambient_light": [0, 0, 0],
             "lights": [{{"position": {light}}}],
             "objects": [
               {{"name": "floor", "plane": {{"point": [0, 0, 0], "normal": {up}}}}},
               {{"name": "wall", "sphere": {{}}, "transform": {wall}}},
               {{"name": "egg", "sphere": {{}}, "transform": {egg}}}
             ] }}"#,
        eye = v(world(DVec3::new(1.0, 6.0, 10.0), scale)),
        look = v(world(DVec3::new(2.5, 0.0, 1.0), scale)),
        up = v(tilt() * DVec3::Y),
        light = v(world(LIGHT, scale)),
        wall = transform(DVec3::new(0.002, 1.0, 2.0), WALL_CENTER),
        egg = transform(DVec3::new(0.5, 0.3, 0.5), EGG_CENTER),
    )
}

/// `e` where the segment from `p` (frame coordinates) to the light crosses the
/// wall's mid-plane, or `None` if it does not cross it.
fn wall_radius(p: DVec3) -> Option<f64> {
    if p.x <= 0.0 {
        return None;
    }
    let q = p + p.x / (p.x - LIGHT.x) * (LIGHT - p);
    Some(((q.y - WALL_CENTER.y).powi(2) + (q.z / 2.0).powi(2)).sqrt())
}

fn passes_near_egg(p: DVec3) -> bool {
    let d = LIGHT - p;
    let s = ((EGG_CENTER - p).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (p + s * d - EGG_CENTER).length() < 0.6
}

/// Keeps the primary hit and its first shadow ray.
#[derive(Default)]
struct FirstHit {
    hit: Option<HitInfo>,
    shadow: Option<ShadowInfo>,
}

impl Recorder for FirstHit {
    const ENABLED: bool = false;
    fn hit(&mut self, hit: &HitInfo) {
        self.hit.get_or_insert(*hit);
    }
    fn shadow_ray(&mut self, shadow: &ShadowInfo) {
        self.shadow.get_or_insert(*shadow);
    }
}

#[derive(Debug, Default, PartialEq)]
struct Counts {
    shadowed: usize,
    leaks: usize,
    open: usize,
    acne: usize,
    egg_lit: usize,
    egg_acne: usize,
}

fn count(scale: f64) -> Counts {
    let s = scene_at(scale);
    let tracer = Tracer::new(&s);
    let camera = s.camera();
    let mut c = Counts::default();
    for y in 0..s.settings.height {
        for x in 0..s.settings.width {
            let mut rec = FirstHit::default();
            let color =
                tracer.trace_primary(camera.pixel_ray(f64::from(x), f64::from(y)), &mut rec);
            assert!(
                color.is_finite(),
                "scale {scale}: non-finite color at ({x}, {y})"
            );
            let (Some(hit), Some(shadow)) = (rec.hit, rec.shadow) else {
                continue;
            };
            let reaches = matches!(shadow.outcome, ShadowOutcome::Reaches { .. });
            let p = frame(hit.point, scale);
            match (hit.object, wall_radius(p)) {
                (0, _) if passes_near_egg(p) => {}
                (0, Some(e)) if e < 0.99 => {
                    c.shadowed += 1;
                    c.leaks += usize::from(reaches);
                }
                (0, e) if e.is_none_or(|e| e > 1.01) => {
                    c.open += 1;
                    c.acne += usize::from(!reaches);
                }
                (2, e)
                    if e.is_none_or(|e| e > 1.01) && shadow.outcome != ShadowOutcome::FacesAway =>
                {
                    c.egg_lit += 1;
                    c.egg_acne += usize::from(!reaches);
                }
                _ => {}
            }
        }
    }
    c
}

#[test]
fn no_acne_and_no_leaks_at_any_scale() {
    for scale in [1e-3, 1.0, 1e4] {
        let c = count(scale);
        println!(
            "scale {scale:e}: floor in the wall's shadow {} (lit: leaks {}), open floor {} (blocked: acne {}), lit side of the egg {} (blocked: acne {})",
            c.shadowed, c.leaks, c.open, c.acne, c.egg_lit, c.egg_acne
        );
        assert!(
            c.shadowed > 1000 && c.open > 1000 && c.egg_lit > 100,
            "scale {scale}: the camera must see every region: {c:?}"
        );
        assert_eq!((c.leaks, c.acne, c.egg_acne), (0, 0, 0), "scale {scale}");
    }
}
