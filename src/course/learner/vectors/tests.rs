//! Tests of the test vectors: how a lesson's rays are read, how a map is
//! written, when a grazing ray widens the tolerance, and that each case's
//! expected output is what its formula makes of its inputs.

use super::*;

fn three(v: &Value) -> DVec3 {
    let f = |i: usize| v[i].as_f64().unwrap();
    DVec3::new(f(0), f(1), f(2))
}

#[test]
fn a_lesson_writes_rays_as_origin_colon_direction() {
    let ray = parse_ray("0,1,5:0,0,-1").unwrap();
    assert_eq!(
        (ray.origin, ray.dir),
        (DVec3::new(0.0, 1.0, 5.0), DVec3::NEG_Z)
    );
    for bad in ["0,1,5", "0,1:0,0,-1", "0,1,x:0,0,-1", ""] {
        assert!(parse_ray(bad).is_none(), "{bad}");
    }
}

#[test]
fn an_affine_map_is_written_as_its_rows() {
    let m = DAffine3::from_translation(DVec3::new(5.0, 6.0, 7.0))
        * DAffine3::from_scale(DVec3::new(2.0, 3.0, 4.0));
    assert_eq!(
        rows(&m),
        json!([
            [2.0, 0.0, 0.0, 5.0],
            [0.0, 3.0, 0.0, 6.0],
            [0.0, 0.0, 4.0, 7.0]
        ])
    );
    // Not symmetric: row i, column j is the map's (i, j).
    let r = rows(&DAffine3::from_rotation_z(90f64.to_radians()));
    assert!((r[0][1].as_f64().unwrap() + 1.0).abs() < 1e-15, "{r}");
    assert!((r[1][0].as_f64().unwrap() - 1.0).abs() < 1e-15, "{r}");
}

#[test]
fn only_a_nearly_tangent_ray_widens_the_tolerance() {
    let (center, radius) = (DVec3::ZERO, 1.0);
    let head_on = tangent_tolerance(center, radius, DVec3::new(0.0, 0.0, 5.0), DVec3::NEG_Z);
    assert_eq!(head_on, None);
    // 1e-12 inside the edge: the discriminant is ~2e-12, the roots lose
    // half their digits, so the case needs far more than 1e-9.
    let grazing = DVec3::new(0.0, 1.0 - 1e-12, 5.0);
    let wide = tangent_tolerance(center, radius, grazing, DVec3::NEG_Z).unwrap();
    assert!(wide > 1e3 * TOLERANCE, "{wide}");
    // A miss and an exact touch have no second root to lose.
    assert_eq!(
        tangent_tolerance(center, radius, DVec3::new(0.0, 2.0, 5.0), DVec3::NEG_Z),
        None
    );
    assert_eq!(
        tangent_tolerance(center, radius, DVec3::new(0.0, 1.0, 5.0), DVec3::NEG_Z),
        None
    );
}

#[test]
fn each_case_holds_what_its_formula_makes_of_its_inputs() {
    let target = Target {
        scene: PathBuf::from("scenes/whitted.json"),
        pixel: Some((416, 209)),
        ray: None,
        label: "pixel 416,209".to_owned(),
    };
    let functions = ["sphere_roots", "reflect", "refract", "combine"];
    let text = document("test", "a test", &functions, &[target]).unwrap();
    let doc: Value = serde_json::from_str(&text).unwrap();
    let cases = doc["cases"].as_array().unwrap();
    for f in functions {
        assert!(cases.iter().any(|c| c["function"] == f), "no {f} case");
    }
    assert!(
        cases
            .iter()
            .all(|c| functions.contains(&c["function"].as_str().unwrap()))
    );
    // Recomputed here the lecture's way; 1e-12: a few roundings of
    // numbers of size ~10 (the roots), far below the file's 1e-9.
    for case in cases {
        let (i, want) = (&case["input"], &case["expected"]);
        match case["function"].as_str().unwrap() {
            "sphere_roots" => {
                let (s, c) = (
                    three(&i["origin"]) - three(&i["center"]),
                    three(&i["direction"]),
                );
                let r = i["radius"].as_f64().unwrap();
                for t in want.as_array().unwrap() {
                    let p = s + t.as_f64().unwrap() * c;
                    assert!((p.length() - r).abs() < 1e-12, "{case}");
                }
            }
            "reflect" => {
                let (c, n) = (three(&i["c"]), three(&i["n"]));
                assert!(
                    (c - 2.0 * n.dot(c) * n - three(want)).length() < 1e-12,
                    "{case}"
                );
            }
            "refract" if !want.is_null() => {
                // Snell's law: n1 sin θ1 = n2 sin θ2, the sines from cross products.
                let (c, n, t) = (three(&i["c"]), three(&i["n"]), three(want));
                let (n1, n2) = (i["n1"].as_f64().unwrap(), i["n2"].as_f64().unwrap());
                let (sin1, sin2) = (c.cross(n).length(), t.cross(n).length());
                assert!((n1 * sin1 - n2 * sin2).abs() < 1e-12, "{case}");
            }
            "combine" => {
                let k = |f: &str| i[f].as_f64().unwrap();
                let sum = three(&i["local"])
                    + k("k_rfl") * three(&i["reflected"])
                    + k("k_rfa") * three(&i["refracted"]);
                assert!((sum - three(want)).length() < 1e-12, "{case}");
            }
            _ => {}
        }
    }
    // The glass ball at this pixel shows a total internal reflection.
    assert!(
        cases
            .iter()
            .any(|c| c["function"] == "refract" && c["expected"].is_null())
    );
}
