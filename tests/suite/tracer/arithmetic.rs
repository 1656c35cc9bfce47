//! The lecture's quantities in the trace, each checked against a computation of
//! its own from the recorded rays, normals and the scene: the camera stage, the
//! unit-sphere quadratic and its roots, the inverse-transformed ray, what became
//! of each root, `n·c` and the mirror direction, Snell's angles (grazing,
//! inside spheres, through transformed spheres, under total internal
//! reflection), and the Phong terms.

use glam::DVec3;
use raytree::geometry::object::Shape;
use raytree::math::ray::Ray;
use raytree::scene::Scene;
use raytree::scene::source::SceneSource;
use raytree::tree::arithmetic::{Arithmetic, Fate, TUnit};
use raytree::tree::document::TraceDocument;
use raytree::tree::ray_tree::{Branch, RayNode};
use raytree::tree::record;

fn scene(name: &str) -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    raytree::scene::loader::load(&path).unwrap()
}

fn source() -> SceneSource {
    SceneSource::new("test", "")
}

/// Pixels and rays that between them meet every case: the glass ball's total
/// internal reflection, a mirror, a floor point in shadow, transformed spheres
/// (ellipsoids, the nested scene's inner ball), rays inside spheres, a grazing
/// ray, and a ray started inside the glass.
fn traces() -> Vec<(String, Scene, TraceDocument)> {
    let mut out = Vec::new();
    for (name, pixels) in [
        (
            "whitted.json",
            vec![(416, 209), (264, 200), (168, 296), (440, 376)],
        ),
        ("ellipsoids.json", vec![(320, 240), (250, 200), (400, 180)]),
        ("nested.json", vec![(320, 240), (300, 200)]),
        // The horn from inside through its open end, the pillar, the spire.
        ("cones.json", vec![(540, 280), (130, 200), (320, 150)]),
    ] {
        let s = scene(name);
        for (x, y) in pixels {
            let t = record::pixel(&s, source(), x, y, None).unwrap();
            out.push((format!("{name} {x},{y}"), s.clone(), t));
        }
    }
    let s = scene("whitted.json");
    // The glass ball: center (0.9, 1, 1.2), radius 0.9. A ray from the far left
    // passing 0.9·(1 - 1e-6) above its center grazes it.
    let grazing = Ray::new(DVec3::new(-10.0, 1.0 + 0.9 * (1.0 - 1e-6), 1.2), DVec3::X);
    // From the glass ball's center region (between the cavity and the wall), outward and oblique.
    let inside = Ray::new(DVec3::new(0.9, 1.5, 1.2), DVec3::new(0.3, 0.4, 0.2));
    for (label, ray) in [("grazing", grazing), ("inside", inside)] {
        out.push((
            label.to_owned(),
            s.clone(),
            record::ray(&s, source(), ray).unwrap(),
        ));
    }
    out
}

/// Relative closeness with a floor of 1 for the scale.
fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(1.0)
}

fn each_node(f: impl Fn(&str, &Scene, &TraceDocument, usize, &RayNode)) {
    for (label, scene, trace) in traces() {
        for (k, sample) in trace.samples.iter().enumerate() {
            for (i, node) in sample.tree.nodes.iter().enumerate() {
                f(
                    &format!("{label} sample {k} node {i}"),
                    &scene,
                    &trace,
                    k,
                    node,
                );
            }
        }
    }
}

#[test]
fn the_camera_stage_makes_the_primary_ray() {
    for (label, _, trace) in traces() {
        let cam = &trace.camera;
        for sample in &trace.samples {
            let Some(stage) = &sample.camera else {
                assert!(trace.pixel.is_none(), "{label}: a pixel has a camera stage");
                continue;
            };
            let root = &sample.tree.nodes[0];
            // Bit for bit: the primary ray is P(r, c) - eye.
            assert_eq!(stage.point - cam.eye, root.direction, "{label}");
            assert_eq!(root.origin, cam.eye, "{label}");
            assert_eq!(root.t_unit, TUnit::ImagePlane, "{label}");
            // The lecture's formulas, written out once more by hand. Tolerance:
            // a few ULPs of numbers of order W, H and the eye's coordinates.
            assert_eq!(stage.r, f64::from(cam.rows) - 1.0 - stage.y, "{label}");
            let u_c = -cam.half_width + cam.half_width * 2.0 * stage.c / f64::from(cam.columns - 1);
            let v_r = -cam.half_height + cam.half_height * 2.0 * stage.r / f64::from(cam.rows - 1);
            assert!(
                close(stage.u_c, u_c, 1e-14) && close(stage.v_r, v_r, 1e-14),
                "{label}"
            );
            let p = cam.eye - cam.distance * cam.n + u_c * cam.u + v_r * cam.v;
            assert!((p - stage.point).abs().max_element() < 1e-13, "{label}");
            // t = 1 is on the image plane: the point is N in front of the eye along -n.
            assert!(
                close((stage.point - cam.eye).dot(-cam.n), cam.distance, 1e-14),
                "{label}"
            );
        }
    }
}

#[test]
fn the_quadratic_and_the_inverse_transformed_ray_agree_with_the_scene() {
    each_node(|at, scene, _, _, node| {
        for test in &node.tests {
            let object = &scene.objects[test.object];
            let world = Ray::new(node.origin, node.direction);
            // S' = M⁻¹S and c' = M⁻¹c, computed here from the inverse matrix.
            let local = match &object.transform {
                Some(tf) => {
                    let inv = tf.to_world.inverse();
                    let r = test
                        .object_ray
                        .expect("a transformed object records S', c'");
                    let (s, c) = (
                        inv.transform_point3(world.origin),
                        inv.transform_vector3(world.dir),
                    );
                    // Tolerance: the inverse computed twice, rounding at 1e-15 of the scene's size.
                    assert!((r.origin - s).abs().max_element() < 1e-12, "{at}: S'");
                    assert!((r.direction - c).abs().max_element() < 1e-12, "{at}: c'");
                    Ray::new(r.origin, r.direction)
                }
                None => {
                    assert!(test.object_ray.is_none(), "{at}");
                    world
                }
            };
            let Shape::Sphere(sphere) = &object.shape else {
                continue;
            };
            let Some(Arithmetic::Quadratic {
                a,
                b,
                c,
                discriminant,
                ..
            }) = test.arithmetic
            else {
                panic!("{at}: a sphere test records its quadratic");
            };
            // The lecture's A, B, C for the unit sphere, from the ray moved and scaled by hand.
            let s = (local.origin - sphere.center) / sphere.radius;
            let d = local.dir / sphere.radius;
            let (a2, b2, c2) = (
                d.x * d.x + d.y * d.y + d.z * d.z,
                s.x * d.x + s.y * d.y + s.z * d.z,
                s.x * s.x + s.y * s.y + s.z * s.z - 1.0,
            );
            assert!(
                close(a, a2, 1e-13) && close(b, b2, 1e-13) && close(c, c2, 1e-13),
                "{at}: A, B, C"
            );
            assert!(
                close(discriminant, b2 * b2 - a2 * c2, 1e-9),
                "{at}: B² - AC"
            );
            // Its roots are the recorded ones (which the stable form found). The
            // lecture's form loses digits to cancellation near t = 0, so the
            // tolerance is relative to the larger root.
            let roots: Vec<f64> = test.roots.iter().map(|r| r.t).collect();
            if discriminant < 0.0 {
                assert!(roots.is_empty(), "{at}: no real root, none recorded");
            } else if !roots.is_empty() {
                let q = discriminant.sqrt();
                let (t1, t2) = ((-b - q) / a, (-b + q) / a);
                let scale = t1.abs().max(t2.abs()).max(1.0);
                assert!(
                    (roots[0] - t1).abs() <= 1e-9 * scale,
                    "{at}: {roots:?} vs {t1}"
                );
                assert!(
                    (roots[roots.len() - 1] - t2).abs() <= 1e-9 * scale,
                    "{at}: {roots:?} vs {t2}"
                );
            }
        }
    });
}

#[test]
fn the_cone_quadratic_agrees_with_the_scene_and_keeps_the_roots_between_its_ends() {
    let seen: [std::cell::Cell<u32>; 3] = Default::default();
    each_node(|at, scene, _, _, node| {
        for test in &node.tests {
            let Shape::Cone(cone) = &scene.objects[test.object].shape else {
                continue;
            };
            let r = test.object_ray.expect("a cone is placed by a transform");
            let Some(Arithmetic::ConeQuadratic {
                ratio,
                a,
                b,
                c,
                discriminant,
                crossings,
                ..
            }) = &test.arithmetic
            else {
                panic!("{at}: a cone test records its quadratic");
            };
            assert_eq!(*ratio, cone.ratio, "{at}");
            // A, B, C of x² + y² = (1 + kz)², k = s − 1, written out by hand
            // from S' + t·c'.
            let (s, d, k) = (r.origin, r.direction, ratio - 1.0);
            let w = 1.0 + k * s.z;
            let a2 = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
            let b2 = s.x * d.x + s.y * d.y - w * k * d.z;
            let c2 = s.x * s.x + s.y * s.y - w * w;
            // Tolerance: the same sums in another order, a few ULPs of their terms.
            assert!(
                close(*a, a2, 1e-13) && close(*b, b2, 1e-12) && close(*c, c2, 1e-12),
                "{at}: A, B, C"
            );
            assert!(
                close(*discriminant, b2 * b2 - a2 * c2, 1e-9),
                "{at}: B² − AC"
            );
            // Each crossing solves the quadratic (relative to its terms' size)
            // at the height recorded; those between the ends are the roots.
            for x in crossings {
                let f = a2 * x.t * x.t + 2.0 * b2 * x.t + c2;
                let size = (a2 * x.t * x.t).abs() + (2.0 * b2 * x.t).abs() + c2.abs();
                assert!(f.abs() <= 1e-9 * size.max(1.0), "{at}: {f} at t = {}", x.t);
                assert!(close(x.z, s.z + x.t * d.z, 1e-15), "{at}: z");
            }
            let kept: Vec<f64> = crossings
                .iter()
                .filter(|x| (0.0..=1.0).contains(&x.z))
                .map(|x| x.t)
                .collect();
            let roots: Vec<f64> = test.roots.iter().map(|r| r.t).collect();
            assert_eq!(roots, kept, "{at}");
            seen[roots.len()].set(seen[roots.len()].get() + 1);
        }
    });
    // Among them: a cone missed, one met once (the other crossing off an
    // end: the horn seen through its open end), one met twice.
    assert!(seen.iter().all(|n| n.get() > 0), "{seen:?}");
}

#[test]
fn normals_come_back_through_the_inverse_transpose() {
    each_node(|at, scene, _, _, node| {
        let Some(hit) = &node.hit else { return };
        let object = &scene.objects[hit.object];
        let (Some(tf), Shape::Sphere(_) | Shape::Cone(_)) = (&object.transform, &object.shape)
        else {
            assert!(
                hit.object_normal.is_none() && hit.normal_like_point.is_none(),
                "{at}"
            );
            return;
        };
        let p = hit.object_point.expect("a transformed hit records P'");
        let n = hit.object_normal.expect("a transformed hit records n'");
        let like_point = hit.normal_like_point.expect("and M·n'");
        // On the untransformed sphere the outward normal points from its center
        // to P'; on the unit cone it is the gradient of x² + y² − (1 + kz)²,
        // k = s − 1: (x, y, −k(1 + kz)).
        let want = match &object.shape {
            Shape::Sphere(sphere) => (p - sphere.center) / sphere.radius,
            Shape::Cone(cone) => {
                let k = cone.ratio - 1.0;
                DVec3::new(p.x, p.y, -k * (1.0 + k * p.z))
            }
            _ => unreachable!("matched above"),
        };
        // Tolerance: P' is M⁻¹ of a rounded point; a few ULPs of 1 after normalizing.
        assert!((n - want.normalize()).length() < 1e-12, "{at}: n'");
        let m = tf.to_world.matrix3;
        let right = (m.inverse().transpose() * n).normalize();
        assert!((hit.normal - right).length() < 1e-12, "{at}: N = (M⁻¹)ᵀn'");
        assert!(
            (like_point - (m * n).normalize()).length() < 1e-12,
            "{at}: M·n'"
        );
    });
    // Worked by hand: the ellipsoid x²/4 + y² = 1 (a unit sphere scaled by 2 along
    // x), hit from above at (√2, √2/2, 0). Its gradient (x/2, 2y, 0) is along
    // (1, 2, 0); n' = (√2/2, √2/2, 0) transformed like a point gives (2, 1, 0)
    // instead, atan(3/4) = 36.87° away.
    let s = crate::common::scene(
        r#"{ "objects": [{ "sphere": {}, "transform": [{ "scale": [2, 1, 1] }] }] }"#,
    );
    let x = 2f64.sqrt();
    let ray = Ray::new(DVec3::new(x, 5.0, 0.0), DVec3::NEG_Y);
    let trace = record::ray(&s, source(), ray).unwrap();
    let hit = trace.samples[0].tree.nodes[0].hit.clone().unwrap();
    let near = |a: DVec3, b: DVec3| (a - b.normalize()).length() < 1e-15;
    assert!(
        near(hit.normal, DVec3::new(1.0, 2.0, 0.0)),
        "{}",
        hit.normal
    );
    assert!(near(hit.object_normal.unwrap(), DVec3::new(1.0, 1.0, 0.0)));
    assert!(near(
        hit.normal_like_point.unwrap(),
        DVec3::new(2.0, 1.0, 0.0)
    ));
    let off = raytree::views::explain::normal_like_point_error(&hit).unwrap();
    // Tolerance: degrees of an angle made from unit vectors good to 1e-16.
    assert!((off - 0.75f64.atan().to_degrees()).abs() < 1e-12, "{off}");
}

#[test]
fn each_roots_fate_is_what_the_tracer_did() {
    each_node(|at, _, _, _, node| {
        let chosen: Vec<(usize, f64)> = node
            .tests
            .iter()
            .flat_map(|t| {
                t.roots
                    .iter()
                    .filter(|r| r.fate == Fate::Chosen)
                    .map(|r| (t.object, r.t))
            })
            .collect();
        match &node.hit {
            Some(h) => assert_eq!(
                chosen,
                [(h.object, h.t)],
                "{at}: exactly the hit's root is chosen"
            ),
            None => assert!(chosen.is_empty(), "{at}: a miss chooses nothing"),
        }
        for test in &node.tests {
            for r in &test.roots {
                match r.fate {
                    Fate::Behind => assert!(r.t <= node.t_min, "{at}: {r:?}"),
                    Fate::Farther => {
                        assert!(r.t > node.t_min, "{at}: {r:?}");
                        assert!(node.hit.as_ref().is_none_or(|h| r.t >= h.t), "{at}: {r:?}");
                    }
                    Fate::Beyond => assert!(node.t_max.is_some_and(|m| r.t >= m), "{at}"),
                    Fate::Chosen => {}
                }
                if r.at_start {
                    // Only a secondary ray leaves a surface, and only its own object's root lies on it.
                    assert!(
                        node.parent.is_some(),
                        "{at}: a primary ray leaves no surface"
                    );
                    assert!(r.t.abs() * node.direction.length() < 1e-9, "{at}: {r:?}");
                }
            }
        }
        // A secondary ray leaving a sphere sees that surface at t ≈ 0 and ignores it.
        if node.parent.is_some()
            && node
                .tests
                .iter()
                .any(|t| t.roots.iter().any(|r| r.at_start))
        {
            assert!(
                node.tests
                    .iter()
                    .flat_map(|t| &t.roots)
                    .filter(|r| r.at_start)
                    .all(|r| r.fate == Fate::Behind),
                "{at}: with robust offsets the starting surface is never taken"
            );
        }
    });
}

#[test]
fn mirror_directions_and_snells_angles_check_out() {
    let mut refractions = 0;
    let mut tirs = 0;
    for (label, _, trace) in traces() {
        for sample in &trace.samples {
            let nodes = &sample.tree.nodes;
            for (i, node) in nodes.iter().enumerate() {
                let Some(h) = &node.hit else { continue };
                let at = format!("{label} node {i}");
                let n = h.shading_normal;
                // c is the unit incoming direction, n faces it.
                assert!(close(h.incoming.length(), 1.0, 1e-15), "{at}");
                assert!(
                    (h.incoming - node.direction.normalize()).length() < 1e-15,
                    "{at}"
                );
                assert!(
                    h.n_dot_c <= 0.0 && close(h.n_dot_c, n.dot(h.incoming), 1e-15),
                    "{at}"
                );
                // Equal angles: the mirror direction makes the same angle with n.
                // Tolerance: unit vectors, a few ULPs.
                assert!(
                    close(h.mirror.dot(n), -h.incoming.dot(n), 1e-14),
                    "{at}: θi = θr"
                );
                if let Some(child) = node.reflected.as_ref().and_then(|b| b.node) {
                    assert_eq!(
                        nodes[child].direction, h.mirror,
                        "{at}: the reflected ray is v"
                    );
                }
                let Some(r) = &h.refraction else { continue };
                // θ₁ by pbrt-v4's AngleBetween, 2·asin(|a − b|/2) for unit a = −c,
                // b = n: a form of its own, accurate near 0 as acos is not.
                let theta1 = 2.0 * ((-h.incoming - n).length() / 2.0).min(1.0).asin();
                assert!(close(r.theta1, theta1.to_degrees(), 1e-12), "{at}: θ₁");
                let refracted = node
                    .refracted
                    .as_ref()
                    .expect("a transparent hit has a refracted branch");
                if refracted.outcome == Branch::TotalInternalReflection {
                    tirs += 1;
                    assert!(
                        r.sin_theta2 > 1.0 && r.theta2.is_none() && r.direction.is_none(),
                        "{at}"
                    );
                    let critical = (h.n2 / h.n1).asin().to_degrees();
                    assert!(
                        close(r.critical.unwrap(), critical, 1e-12) && r.theta1 > critical,
                        "{at}"
                    );
                    continue;
                }
                // Snell's law on the recorded vectors: the refracted ray's angle to -n.
                let dir = r.direction.expect("refracts");
                if let Some(child) = refracted.node {
                    assert_eq!(nodes[child].direction, dir, "{at}: the refracted ray is t");
                }
                refractions += 1;
                let theta2 = (-n).dot(dir).clamp(-1.0, 1.0).acos();
                assert!(
                    close(r.theta2.unwrap(), theta2.to_degrees(), 1e-9),
                    "{at}: θ₂ {} vs {}",
                    r.theta2.unwrap(),
                    theta2.to_degrees()
                );
                assert!(
                    close(
                        h.n1 * r.theta1.to_radians().sin(),
                        h.n2 * theta2.sin(),
                        1e-12
                    ),
                    "{at}: n₁ sin θ₁ = n₂ sin θ₂"
                );
                // The refracted direction stays in the plane of c and n.
                assert!(h.incoming.cross(n).dot(dir).abs() < 1e-14, "{at}");
            }
        }
    }
    assert!(
        refractions >= 4 && tirs >= 1,
        "{refractions} refractions, {tirs} total internal reflections"
    );
}

#[test]
fn phong_terms_are_made_of_their_recorded_parts() {
    each_node(|at, _, _, _, node| {
        let (Some(h), Some(local)) = (&node.hit, &node.local) else {
            return;
        };
        let n = h.shading_normal;
        // Tolerance: products of a handful of numbers near 1, a few ULPs each.
        assert!(
            (local.ambient - local.k_a * local.color * local.ambient_light)
                .abs()
                .max_element()
                < 1e-15,
            "{at}"
        );
        for l in &local.lights {
            let Some(p) = &l.phong else {
                assert_eq!((l.diffuse, l.specular), (DVec3::ZERO, DVec3::ZERO), "{at}");
                continue;
            };
            assert!(close(p.n_dot_l, n.dot(p.l), 1e-15), "{at}: N·L");
            assert!(
                (p.r - (2.0 * p.n_dot_l * n - p.l)).length() < 1e-15,
                "{at}: R"
            );
            assert!(
                close(p.v.length(), 1.0, 1e-15) && (p.v + h.incoming).length() < 1e-15,
                "{at}: V"
            );
            assert!(close(p.r_dot_v, p.r.dot(p.v).max(0.0), 1e-15), "{at}: R·V");
            let diffuse = local.k_d * p.n_dot_l * local.color * p.arriving;
            assert!(
                (l.diffuse - diffuse).abs().max_element() < 1e-15,
                "{at}: diffuse"
            );
            let highlight = if local.k_s > 0.0 && p.r_dot_v > 0.0 {
                local.k_s * p.r_dot_v.powf(local.shininess)
            } else {
                0.0
            };
            assert!(
                (l.specular - highlight * p.arriving).abs().max_element() < 1e-15,
                "{at}: specular"
            );
        }
    });
}

#[test]
fn t_counts_what_each_ray_says() {
    each_node(|at, _, trace, _, node| match node.t_unit {
        TUnit::ImagePlane => assert!(trace.pixel.is_some() && node.parent.is_none(), "{at}"),
        TUnit::Direction => assert!(trace.ray.is_some() && node.parent.is_none(), "{at}"),
        TUnit::Distance => {
            assert!(node.parent.is_some(), "{at}");
            assert!(
                close(node.direction.length(), 1.0, 1e-15),
                "{at}: a unit direction"
            );
        }
    });
}

#[test]
fn the_tir_pixel_reads_as_the_lecture_writes_it() {
    // What the issue asked to see at the README's total-internal-reflection pixel.
    let s = scene("whitted.json");
    let trace = record::pixel(&s, source(), 416, 209, None).unwrap();
    let text = raytree::views::text::format(&trace, false);
    for expected in [
        "camera: pixel 416,209",
        "u_c = −W + W·2c/(N_c − 1)",
        "v_r = −H + H·2r/(N_r − 1)",
        "P(r, c) = eye − N·n + u_c·u + v_r·v",
        "t = 1 on the image plane",
        "B² − AC = ",
        "A = |c₁|² = ",
        "(the surface the ray starts on: ignored)",
        "(behind the origin: ignored)",
        "Snell: n₁ sin θ₁ = n₂ sin θ₂ with θ₁ = atan2(|n × c|, −n·c) = ",
        "θ₂ = ",
        "> 1: no angle has that sine; θ₁ is beyond the critical angle asin(n₂/n₁) = asin(1/1.5) = 41.81°",
        "N·L = ",
        "R·V = ",
        "c is a unit vector, so t is the distance",
    ] {
        assert!(
            text.contains(expected),
            "missing {expected:?} in the trace of 416,209"
        );
    }
    // A shadow ray's t is a fraction of the way to its light.
    let shadowed = record::pixel(&s, source(), 168, 296, None).unwrap();
    let text = raytree::views::text::format(&shadowed, false);
    assert!(
        text.contains("blocked by 'mirror' at t = ") && text.contains("(t = 1 at the light)"),
        "{text}"
    );
}

/// Where the lecture's B² − AC cancels (lesson 13's far ball, seen grazing
/// from 1e7 radii away), the text says so when the stable form decided
/// otherwise, rather than print "one root" beside two.
#[test]
fn a_cancelled_discriminant_is_named_when_the_stable_form_disagrees() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/13-numerics/far.json");
    let mut far = raytree::scene::loader::load(&path).unwrap();
    far.settings.sphere = raytree::methods::SphereMethod::Stable;
    let trace = record::pixel(&far, source(), 32, 32, None).unwrap();
    let test = &trace.samples[0].tree.nodes[0].tests[0];
    let Some(Arithmetic::Quadratic { discriminant, .. }) = test.arithmetic else {
        panic!("a sphere test records its quadratic");
    };
    assert_eq!(discriminant, 0.0, "the lecture's form cancels here");
    assert_eq!(test.roots.len(), 2, "the stable form finds two roots");
    let text = raytree::views::text::format(&trace, false);
    assert!(
        text.contains("B² − AC = 0 as the lecture writes it (nearly equal numbers subtracted: rounding decides); the stable form (Ray Tracing Gems ch. 7) finds 2 roots"),
        "{text}"
    );
    // With the lecture's form itself, the count follows B² − AC as before.
    far.settings.sphere = raytree::methods::SphereMethod::Lecture;
    let trace = record::pixel(&far, source(), 32, 32, None).unwrap();
    let text = raytree::views::text::format(&trace, false);
    assert!(text.contains("B² − AC = 0: one root"), "{text}");
}

/// A ray lying in one of a box's face planes (issue 29): the trace printed the
/// slabs' intervals overlapping ("y parallel, inside") and then "the slabs'
/// intervals do not overlap: no root". The intervals the trace records are the
/// ones the test used, and the verdict follows from them: for a ray in each of
/// the six face planes, whatever the sign of its zero components.
#[test]
fn a_ray_in_a_face_plane_reads_as_its_slabs_decide() {
    use raytree::tree::arithmetic::Slab;
    let text = r#"{ "camera": { "eye": [0, 0, 10], "look_at": [0, 0, 0] },
        "lights": [{ "position": [3, 4, 5] }],
        "objects": [{ "name": "crate", "box": { "min": [-1, -1, -1], "max": [1, 1, 1] } }] }"#;
    let s = raytree::scene::loader::parse(text, "crate.json").unwrap();
    for axis in 0..3 {
        let (along, third) = ((axis + 1) % 3, (axis + 2) % 3);
        for side in [-1.0, 1.0] {
            for zero in [0.0, -0.0] {
                let mut origin = DVec3::ZERO;
                origin[axis] = side;
                origin[along] = -5.0;
                origin[third] = 0.25;
                let mut dir = DVec3::splat(zero);
                dir[along] = 1.0;
                let what = format!("face {side} of axis {axis}, zeros {zero:?}");
                let trace = record::ray(
                    &s,
                    SceneSource::new("crate.json", text),
                    Ray::new(origin, dir),
                )
                .unwrap();
                let test = &trace.samples[0].tree.nodes[0].tests[0];
                let Some(Arithmetic::Slabs { axes }) = test.arithmetic else {
                    panic!("{what}: a box test records its slabs");
                };
                let (mut enter, mut leave, mut open) = (f64::NEG_INFINITY, f64::INFINITY, true);
                for slab in axes {
                    match slab {
                        Slab::Crossing { near, far } => {
                            enter = enter.max(near);
                            leave = leave.min(far);
                        }
                        Slab::Parallel { inside } => open &= inside,
                    }
                }
                let overlap = open && enter <= leave;
                let roots: Vec<f64> = test.roots.iter().map(|r| r.t).collect();
                assert!(
                    overlap,
                    "{what}: the ray runs along the box's face: {axes:?}"
                );
                assert_eq!(
                    roots,
                    [enter, leave],
                    "{what}: the roots are the overlap's ends"
                );
                let printed = raytree::views::text::format(&trace, false);
                let line = printed
                    .lines()
                    .find(|l| l.contains("test box 'crate'"))
                    .unwrap_or_else(|| panic!("{what}: no test line in {printed}"));
                assert!(!line.contains("do not overlap"), "{what}: {printed}");
                assert!(
                    line.contains("overlap"),
                    "{what}: the verdict names the overlap: {printed}"
                );
            }
        }
    }
}

#[test]
fn snells_angles_resolve_a_ray_five_nanoradians_off_the_normal() {
    // Glass below the plane y = 0; the ray comes down δ = 5e-9 rad off its
    // normal. acos(−n·c) cannot see it: cos δ = 1 − 1.25e-17 rounds to 1.
    let text = r#"{
        "materials": {"glass": {"ambient": 0, "diffuse": 0, "transparent": 1, "ior": 1.5}},
        "objects": [{"name": "pool", "plane": {"point": [0, 0, 0], "normal": [0, 1, 0]}, "material": "glass"}]
    }"#;
    let scene = raytree::scene::loader::parse(text, "test.json").unwrap();
    let delta = 5e-9f64;
    let ray = Ray::new(DVec3::Y, DVec3::new(delta.sin(), -delta.cos(), 0.0));
    let trace = record::ray(&scene, SceneSource::new("test.json", text), ray).unwrap();
    let hit = trace.samples[0].tree.nodes[0].hit.as_ref().unwrap();
    let r = hit.refraction.as_ref().unwrap();
    // Tolerance: relative 1e-12. The vectors are exact here (c = (5e-9, −1, 0),
    // n = (0, 1, 0)), so the angle is off only by the rounding of atan2 and of
    // the trip through degrees, a few 1e-16 of it; acos's 0 is off by all of it.
    let rel = |got: f64, want: f64| ((got - want) / want).abs();
    assert!(
        rel(r.theta1.to_radians(), delta) < 1e-12,
        "θ₁ = {}°",
        r.theta1
    );
    assert!(
        rel(r.sin_theta1, delta.sin()) < 1e-12,
        "sin θ₁ = {}",
        r.sin_theta1
    );
    // Snell: sin θ₂ = sin θ₁ / 1.5, and at this angle θ₂ = sin θ₂ to 1e-17.
    let theta2 = (delta.sin() / 1.5).asin();
    assert!(
        rel(r.theta2.unwrap().to_radians(), theta2) < 1e-12,
        "θ₂ = {:?}°",
        r.theta2
    );
    // The text prints the formula it used, and its value.
    let lines = raytree::views::explain::refraction(hit).join("\n");
    assert!(
        lines.contains("θ₁ = atan2(|n × c|, −n·c) = 2.865e-7°") && lines.contains("θ₂ = 1.910e-7°"),
        "{lines}"
    );
}

#[test]
fn the_hit_point_printed_is_s_plus_t_c_and_then_the_point_projected_onto_the_sphere() {
    // Lesson 13's far ball, pixel 32,32, with the lecture's quadratic: its one
    // root puts S + t·c at (0.997, 0, −1.006e-7), inside the ball; the tracer
    // projects that onto the sphere, at (1, 0, −1.009e-7) on the rim.
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/13-numerics/far.json");
    let far = raytree::scene::loader::load(&path).unwrap();
    let trace = record::pixel(&far, source(), 32, 32, None).unwrap();
    let text = raytree::views::text::format(&trace, false);
    assert!(
        text.contains(
            "S + t·c = (0.997, 0, -1.006e-7), projected onto the sphere: P = (1, 0, -1.009e-7)"
        ) && text.contains("P is 0.003 from S + t·c: put on the surface"),
        "{text}"
    );
    // The record keeps both, and the projection is C + r·(Q − C)/|Q − C| of
    // Q = S + t·c (the ball is the unit one at the origin).
    let node = &trace.samples[0].tree.nodes[0];
    let hit = node.hit.as_ref().unwrap();
    assert_eq!(hit.on_ray, node.origin + hit.t * node.direction);
    assert_eq!(
        hit.placement,
        raytree::tree::ray_tree::Placement::OntoSphere
    );
    // Tolerance: a normalisation, a few ULPs of a unit vector.
    assert!((hit.point - hit.on_ray.normalize()).length() < 1e-15);
    assert!(hit.on_ray.length() < 0.998, "S + t·c lies inside the ball");
}

/// The text trace writes a cone's quadratic out and says which crossings fell
/// off its open ends: the horn seen through its wide end, a cylinder (the
/// pillar) in its shorter form, and a ray along the pillar's axis.
#[test]
fn the_text_trace_says_which_crossings_of_a_cone_are_off_its_ends() {
    let s = scene("cones.json");
    let horn = record::pixel(&s, source(), 540, 280, None).unwrap();
    let text = raytree::views::text::format(&horn, false);
    for want in [
        "test cone 'horn': B² − AC = ",
        "> 0: two roots, t = (−B ± √(B² − AC))/A: t = ",
        "(below the open end z = 0: not on the cone), t = ",
        "(the closest hit)",
        "the unit cone x² + y² = (1 + (s − 1)z)², 0 ≤ z ≤ 1, open at both ends, radius 1 at z = 0 and s = 0.4167 at z = 1",
        "A = c'x² + c'y² − (s − 1)²c'z² = ",
        "put at the cone's radius at its height",
    ] {
        assert!(text.contains(want), "{want:?} not in\n{text}");
    }
    let pillar = record::pixel(&s, source(), 130, 200, None).unwrap();
    let text = raytree::views::text::format(&pillar, false);
    for want in [
        "the unit cylinder x² + y² = 1, 0 ≤ z ≤ 1, open at both ends",
        "A = c'x² + c'y² = ",
        "C = S'x² + S'y² − 1 = ",
        "(farther than the closest hit)",
    ] {
        assert!(text.contains(want), "{want:?} not in\n{text}");
    }
    // Down the pillar's axis from above: c' = (0, 0, −c), A = B = 0.
    let down = Ray::new(DVec3::new(-2.2, 5.0, 0.0), DVec3::NEG_Y);
    let text = raytree::views::text::format(&record::ray(&s, source(), down).unwrap(), false);
    assert!(
        text.contains("test cone 'pillar': A = B = 0: the ray runs along the surface's lines and never crosses it: no root"),
        "{text}"
    );
}
