//! Test vectors for a learner's own tracer: for each lesson 03–11, cases of
//! the lecture's functions (pixel → ray, the ray–plane and ray–sphere roots
//! and which root is the hit, the inverse-transformed ray and the transformed
//! normal, Phong's terms, the shadow ray's outcome, the reflected and
//! refracted directions, the color combination), each with its inputs and the
//! output raytree's own code computed for them, read from the recorded traces
//! of the lesson's pixels and rays. Any language's unit tests can load them;
//! the course's Python tracer does (`lessons/python/`).
//!
//! The file's format (`"format": "raytree-vectors"`, version 1) is documented
//! in `lessons/python/README.md`; [`TOLERANCE_WHY`] is the reasoning behind the
//! tolerance it states.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use glam::{DAffine3, DVec3};
use serde_json::{Value, json};

use crate::course::lesson;
use crate::geometry::object::Shape;
use crate::math::ray::Ray;
use crate::scene::Scene;
use crate::scene::source::{self, SceneSource};
use crate::trace::recorder::RayKind;
use crate::tree::arithmetic::{Fate, TestMethod};
use crate::tree::document::TraceDocument;
use crate::tree::ray_tree::{RayNode, ShadowOutcomeRecord};
use crate::tree::record;

/// The tolerance every case passes with, relative to the expected value's
/// size (at least 1); see [`TOLERANCE_WHY`].
pub const TOLERANCE: f64 = 1e-9;

/// Why [`TOLERANCE`] is what it is, written into every file.
pub const TOLERANCE_WHY: &str = "Inputs are written with all their digits, so a correct function computing the same formula differs from raytree only by rounding: a few units in the last place (1e-15 relative). A different but valid formula (the stable quadratic instead of the lecture's, a rotation written another way) loses at most a few more digits on these scenes (1e-12). Every classic mistake is off by far more (1e-3 and up). 1e-9 sits between. A nearly tangent ray's roots are ill-conditioned (the lecture's quadratic loses half its digits as the discriminant nears 0), so such a case states a wider tolerance of its own.";

/// The most cases of one function in one file: enough variety (misses, hits
/// from outside and inside, both roots), few enough to read.
const MOST_PER_FUNCTION: usize = 16;

/// The most cases of one function from one pixel or ray, so every target of
/// a lesson (its hand-picked rays too) has its say.
const MOST_PER_TARGET: usize = 4;

/// The functions each lesson asks the learner to write, in lesson order.
pub const LESSON_FUNCTIONS: [(u32, &[&str]); 9] = [
    (3, &["image_plane_point"]),
    (4, &["primary_ray", "plane_root"]),
    (5, &["sphere_roots", "first_root"]),
    (6, &["to_object_ray", "normal_to_world"]),
    (7, &["phong"]),
    (8, &["shadow_ray"]),
    (9, &["reflect"]),
    (10, &["refract"]),
    (11, &["combine"]),
];

/// Lessons 03–11's "Build it yourself" part in brief: the functions of the
/// Python starter tracer to write, how to run their test vectors, and the
/// check of a whole pixel (the chapter shows a real report).
pub fn build_it_yourself(number: u32) -> Option<String> {
    let (_, functions) = LESSON_FUNCTIONS.iter().find(|(n, _)| *n == number)?;
    let mut names: Vec<&str> = functions.to_vec();
    if number == 11 {
        names.push("raytrace");
    }
    let names = names.join(", ");
    Some(format!(
        "Build it yourself: write {names} in lessons/python/starter/tracer.py, run its test vectors with\n    python3 lessons/python/starter/tracer.py test {number:02}\nand, once it traces pixels, check one ray by ray with `raytree check SCENE --pixel X,Y mine.json`;\nthe chapter's \"Build it yourself\" shows a real report (lessons/python/README.md tells the rest)."
    ))
}

/// What a function takes and gives, as the file describes it.
fn signature(function: &str) -> &'static str {
    match function {
        "image_plane_point" => {
            "camera {eye, u, v, n, half_width W, half_height H, distance N, columns N_c, rows N_r}, pixel x (from the left), y (from the top) → the point P(r, c) on the image plane (lecture rows r count from the bottom: r = N_r - 1 - y)"
        }
        "primary_ray" => {
            "camera, x, y as above → {origin: the eye, direction: P(r, c) - eye} (not normalized: t = 1 on the image plane)"
        }
        "plane_root" => {
            "plane point P0 and unit normal n, ray origin S and direction c → t with (S + t·c - P0)·n = 0, or null when the ray is parallel"
        }
        "sphere_roots" => {
            "center, radius, ray origin S, direction c (any length) → the roots t of A t² + 2B t + C = 0, ascending ([] for a miss)"
        }
        "first_root" => {
            "roots (ascending), t_min, t_max (null: none) → the hit: the smallest root with t_min < t < t_max, or null"
        }
        "to_object_ray" => {
            "inverse: M⁻¹ as three rows [a, b, c, t] of an affine map, world ray origin S and direction c → {origin: M⁻¹S, direction: M⁻¹c} (a point and a direction)"
        }
        "normal_to_world" => {
            "inverse M⁻¹ as above, the untransformed primitive's unit normal n' → the world unit normal (M⁻¹)ᵀn' normalized"
        }
        "phong" => {
            "material {ambient, diffuse, specular, shininess}, color, ambient_light, unit normal N (facing the viewer), unit V (to the viewer), lights: [{l: unit L to the light, arriving: its color as it arrives}] for the lights the shadow rays reached → the local color k_a·color·ambient + Σ k_d(N·L)·color·light + k_s(R·V)^shininess·light, R = 2(N·L)N - L, N·L ≤ 0 adds nothing, R·V clamped at 0"
        }
        "shadow_ray" => {
            "scene (a path from the repository), the hit point, its unit normal facing the incoming ray, the light's index → {blocked, by: the opaque object in the way or null, faces_away: the light is behind the surface (no ray cast; blocked true), transmitted: the share of the light arriving (each transparent object crossed keeps its k_rfa; 0 when blocked)}"
        }
        "reflect" => "unit incoming c, unit normal n → the mirror direction v = c - 2(n·c)n",
        "refract" => {
            "unit incoming c, unit normal n facing it (n·c < 0), indices n1 (the ray's side) and n2 → the unit refracted direction by Snell's law, or null for total internal reflection"
        }
        "combine" => {
            "local, k_rfl, reflected color, k_rfa, refracted color → local + k_rfl·reflected + k_rfa·refracted"
        }
        _ => "",
    }
}

/// Where the cases come from: a scene, and the pixels and rays traced in it.
#[derive(Clone, Debug)]
pub struct Target {
    /// The scene, as named from the repository (`scenes/whitted.json`).
    pub scene: PathBuf,
    /// A pixel, or else a ray given by hand.
    pub pixel: Option<(u32, u32)>,
    /// The ray, when no pixel.
    pub ray: Option<Ray>,
    /// How the cases' names call it: `pixel 416,209`, `ray 0,0,5:0,0,-1`.
    pub label: String,
}

/// The targets of lesson `number` in `dir`: its step-through's pixel, the
/// `raytree trace SCENE --pixel X,Y` and `--ray O:D` runs of its spec (given
/// no other flag, so they trace at the scene's own settings), and for the
/// camera lessons (03, 04) the image's four corners and its center.
pub fn lesson_targets(dir: &Path, number: u32) -> Result<(String, Vec<Target>), String> {
    let loaded = lesson::load(dir, number)?;
    let scene = loaded.script.scene.clone();
    let [x, y] = loaded.script.pixel;
    let mut targets = vec![Target {
        scene: scene.clone(),
        pixel: Some((x, y)),
        ray: None,
        label: format!("pixel {x},{y}"),
    }];
    for run in loaded.entry.spec.runs.values() {
        let args = &run.command.args;
        if args.len() != 4 || args[0] != "trace" {
            continue;
        }
        let target = match args[2].as_str() {
            "--pixel" => args[3].split_once(',').and_then(|(x, y)| {
                Some(Target {
                    scene: PathBuf::from(&args[1]),
                    pixel: Some((x.parse().ok()?, y.parse().ok()?)),
                    ray: None,
                    label: format!("pixel {}", args[3]),
                })
            }),
            "--ray" => parse_ray(&args[3]).map(|ray| Target {
                scene: PathBuf::from(&args[1]),
                pixel: None,
                ray: Some(ray),
                label: format!("ray {}", args[3]),
            }),
            _ => None,
        };
        targets.extend(target);
    }
    if number <= 4 {
        let (w, h) = (loaded.scene.settings.width, loaded.scene.settings.height);
        for pixel in [
            (0, 0),
            (w - 1, 0),
            (0, h - 1),
            (w - 1, h - 1),
            (w / 2, h / 2),
        ] {
            targets.push(Target {
                scene: scene.clone(),
                pixel: Some(pixel),
                ray: None,
                label: format!("pixel {},{}", pixel.0, pixel.1),
            });
        }
    }
    Ok((loaded.entry.name.clone(), targets))
}

/// The targets of a scene given by itself: the centers of a 5 × 5 grid of
/// equal cells over its image, so most of what it shows is met.
pub fn scene_targets(scene_path: &Path) -> Result<Vec<Target>, String> {
    let (scene, _) = source::load(Some(scene_path)).map_err(|e| format!("{e:#}"))?;
    let (w, h) = (scene.settings.width, scene.settings.height);
    let at = |i: u32, size: u32| (2 * i + 1) * size / 10;
    Ok((0..25)
        .map(|k| {
            let (x, y) = (at(k % 5, w), at(k / 5, h));
            Target {
                scene: scene_path.to_owned(),
                pixel: Some((x, y)),
                ray: None,
                label: format!("pixel {x},{y}"),
            }
        })
        .collect())
}

/// `OX,OY,OZ:DX,DY,DZ`, as a lesson's spec writes a ray.
fn parse_ray(text: &str) -> Option<Ray> {
    let (o, d) = text.split_once(':')?;
    let three = |s: &str| -> Option<DVec3> {
        let v: Vec<f64> = s
            .split(',')
            .map(|x| x.parse().ok())
            .collect::<Option<_>>()?;
        (v.len() == 3).then(|| DVec3::new(v[0], v[1], v[2]))
    };
    Some(Ray::new(three(o)?, three(d)?))
}

/// The vectors document for `functions`, made from the traces of `targets`:
/// `name` is the lesson's folder name or the scene's path, `made_by` the
/// command that makes it (`raytree vectors 5`).
pub fn document(
    name: &str,
    made_by: &str,
    functions: &[&str],
    targets: &[Target],
) -> Result<String, String> {
    let mut cases = Cases::new(functions);
    let mut scenes: Vec<(PathBuf, Scene, SceneSource)> = Vec::new();
    for target in targets {
        if !scenes.iter().any(|(p, ..)| *p == target.scene) {
            let (scene, source) =
                source::load(Some(&target.scene)).map_err(|e| format!("{e:#}"))?;
            scenes.push((target.scene.clone(), scene, source));
        }
        let (_, scene, source) = scenes
            .iter()
            .find(|(p, ..)| *p == target.scene)
            .expect("loaded just above");
        let trace = match (target.pixel, target.ray) {
            (Some((x, y)), _) => record::pixel(scene, source.clone(), x, y, None),
            (None, Some(ray)) => record::ray(scene, source.clone(), ray),
            (None, None) => continue,
        };
        let trace = trace.map_err(|e| format!("{}: {e}", target.scene.display()))?;
        let scene_name = target.scene.display().to_string().replace('\\', "/");
        cases.add_trace(scene, &scene_name, &target.label, &trace);
    }
    let described: serde_json::Map<String, Value> = functions
        .iter()
        .map(|f| ((*f).to_owned(), Value::from(signature(f))))
        .collect();
    let head = json!({
        "format": "raytree-vectors",
        "version": 1,
        "lesson": name,
        "made_by": made_by,
        "tolerance": TOLERANCE,
        "tolerance_rule": "a number passes when |got - expected| <= tolerance · max(1, |expected|), component by component; null, true, false and names must match exactly; a case's own tolerance wins",
        "tolerance_why": TOLERANCE_WHY,
        "functions": described,
    });
    Ok(layout(&head, &cases.list))
}

/// The document as a reader scans it: the head's fields in their order, one
/// to a line, then the cases one to a line (`name`, `function`, `input`,
/// `expected`, and a `tolerance` of its own where it has one), so that a
/// stale file's diff names the cases that changed.
fn layout(head: &Value, cases: &[Value]) -> String {
    let one = |v: &Value| serde_json::to_string(v).expect("a JSON value writes");
    let mut out = String::from("{\n");
    for key in [
        "format",
        "version",
        "lesson",
        "made_by",
        "tolerance",
        "tolerance_rule",
        "tolerance_why",
        "functions",
    ] {
        out += &format!("  {}: {},\n", one(&Value::from(key)), one(&head[key]));
    }
    out += "  \"cases\": [\n";
    for (i, case) in cases.iter().enumerate() {
        let fields: Vec<String> = ["name", "function", "input", "expected", "tolerance"]
            .into_iter()
            .filter(|k| case.get(*k).is_some())
            .map(|k| format!("{}: {}", one(&Value::from(k)), one(&case[k])))
            .collect();
        let comma = if i + 1 < cases.len() { "," } else { "" };
        out += &format!("    {{{}}}{comma}\n", fields.join(", "));
    }
    out += "  ]\n}\n";
    out
}

/// The cases gathered so far, at most [`MOST_PER_FUNCTION`] of each function,
/// none twice.
struct Cases<'f> {
    functions: &'f [&'f str],
    list: Vec<Value>,
    seen: BTreeSet<String>,
    /// Where the current target's cases start in `list`.
    target_start: usize,
}

impl<'f> Cases<'f> {
    fn new(functions: &'f [&'f str]) -> Self {
        Self {
            functions,
            list: Vec::new(),
            seen: BTreeSet::new(),
            target_start: 0,
        }
    }

    fn push(&mut self, function: &str, name: String, input: Value, expected: Value) {
        self.push_with(function, name, input, expected, None);
    }

    fn push_with(
        &mut self,
        function: &str,
        name: String,
        input: Value,
        expected: Value,
        tolerance: Option<f64>,
    ) {
        if !self.functions.contains(&function) {
            return;
        }
        let count = |list: &[Value]| list.iter().filter(|c| c["function"] == function).count();
        if count(&self.list) >= MOST_PER_FUNCTION
            || count(&self.list[self.target_start..]) >= MOST_PER_TARGET
            || !self.seen.insert(format!("{function} {input}"))
        {
            return;
        }
        let mut case =
            json!({"name": name, "function": function, "input": input, "expected": expected});
        if let Some(t) = tolerance {
            case["tolerance"] = Value::from(t);
        }
        self.list.push(case);
    }

    /// Every case one trace holds.
    fn add_trace(&mut self, scene: &Scene, scene_name: &str, label: &str, trace: &TraceDocument) {
        self.target_start = self.list.len();
        let Some(sample) = trace.samples.first() else {
            return;
        };
        let nodes = &sample.tree.nodes;
        if let (Some(stage), Some(root)) = (&sample.camera, nodes.first()) {
            let c = &trace.camera;
            let camera = json!({
                "eye": v(c.eye), "u": v(c.u), "v": v(c.v), "n": v(c.n),
                "half_width": c.half_width, "half_height": c.half_height, "distance": c.distance,
                "columns": c.columns, "rows": c.rows,
            });
            let [x, y] = stage.pixel;
            let input = json!({"camera": camera, "x": x, "y": y});
            let name = format!("{scene_name} {label}");
            self.push(
                "image_plane_point",
                name.clone(),
                input.clone(),
                v(stage.point),
            );
            let ray = json!({"origin": v(root.origin), "direction": v(root.direction)});
            self.push("primary_ray", name, input, ray);
        }
        for (i, node) in nodes.iter().enumerate() {
            let name = format!("{scene_name} {label} {}", path(nodes, i));
            self.add_node(scene, scene_name, &name, node);
        }
    }

    /// The cases of one ray: its tests, and at its hit the local color, the
    /// shadow rays, the directions and the sum.
    fn add_node(&mut self, scene: &Scene, scene_name: &str, name: &str, node: &RayNode) {
        for test in &node.tests {
            let object = &scene.objects[test.object];
            let (origin, direction) = match &test.object_ray {
                Some(r) => (r.origin, r.direction),
                None => (node.origin, node.direction),
            };
            let here = format!("{name}: {}", test.name);
            let roots: Vec<f64> = test.roots.iter().map(|r| r.t).collect();
            if let (Some(tf), Some(r)) = (&object.transform, &test.object_ray) {
                let input = json!({"inverse": rows(&tf.to_object), "origin": v(node.origin), "direction": v(node.direction)});
                let out = json!({"origin": v(r.origin), "direction": v(r.direction)});
                self.push("to_object_ray", here.clone(), input, out);
            }
            match (&object.shape, test.method) {
                (Shape::Plane(p), TestMethod::PlaneEquation) => {
                    let input = json!({"point": v(p.point), "normal": v(p.normal), "origin": v(origin), "direction": v(direction)});
                    self.push("plane_root", here.clone(), input, json!(roots.first()));
                }
                (Shape::Sphere(s), _) => {
                    let input = json!({"center": v(s.center), "radius": s.radius, "origin": v(origin), "direction": v(direction)});
                    let tolerance = tangent_tolerance(s.center, s.radius, origin, direction);
                    self.push_with("sphere_roots", here.clone(), input, json!(roots), tolerance);
                }
                _ => {}
            }
            if !roots.is_empty() {
                let hit = test
                    .roots
                    .iter()
                    .find(|r| r.t > node.t_min && r.fate != Fate::Beyond)
                    .map(|r| r.t);
                let input = json!({"roots": roots, "t_min": node.t_min, "t_max": node.t_max});
                self.push("first_root", here, input, json!(hit));
            }
        }
        let Some(hit) = &node.hit else {
            return;
        };
        let here = format!("{name}: {}", hit.name);
        if let (Some(n), Some(tf)) = (hit.object_normal, &scene.objects[hit.object].transform) {
            let input = json!({"inverse": rows(&tf.to_object), "normal": v(n)});
            self.push("normal_to_world", here.clone(), input, v(hit.normal));
        }
        let n = hit.shading_normal;
        if let Some(local) = &node.local {
            let lights: Vec<Value> = local
                .lights
                .iter()
                .filter_map(|l| l.phong.as_ref())
                .map(|p| json!({"l": v(p.l), "arriving": v(p.arriving)}))
                .collect();
            let input = json!({
                "material": {"ambient": local.k_a, "diffuse": local.k_d, "specular": local.k_s, "shininess": local.shininess},
                "color": v(local.color), "ambient_light": v(local.ambient_light),
                "normal": v(n), "v": v(-node.direction.normalize()), "lights": lights,
            });
            self.push("phong", here.clone(), input, v(local.total));
        }
        for s in &node.shadow_rays {
            let (blocked, by, faces_away, transmitted) = match &s.outcome {
                ShadowOutcomeRecord::FacesAway => (true, None, true, 0.0),
                ShadowOutcomeRecord::Reaches { transmitted } => (false, None, false, *transmitted),
                ShadowOutcomeRecord::Blocked { name, .. } => (true, Some(name.clone()), false, 0.0),
            };
            let input = json!({"scene": scene_name, "point": v(hit.point), "normal": v(n), "light": s.light});
            let out = json!({"blocked": blocked, "by": by, "faces_away": faces_away, "transmitted": transmitted});
            self.push("shadow_ray", format!("{here} → {}", s.name), input, out);
        }
        let c = hit.incoming;
        let input = json!({"c": v(c), "n": v(n)});
        self.push("reflect", here.clone(), input, v(hit.mirror));
        if let Some(r) = &hit.refraction {
            let input = json!({"c": v(c), "n": v(n), "n1": hit.n1, "n2": hit.n2});
            self.push("refract", here.clone(), input, json!(r.direction.map(v)));
        }
        let s = &node.sum;
        let input = json!({"local": v(s.local), "k_rfl": s.k_rfl, "reflected": v(s.reflected), "k_rfa": s.k_rfa, "refracted": v(s.refracted)});
        self.push("combine", here, input, v(s.color));
    }
}

/// The tolerance a sphere's roots need when the ray nearly touches it: the
/// lecture's quadratic gives each root with an error near
/// `ε·(B² + |AC|)/(A·√(B² - AC))`, which grows without bound as the
/// discriminant nears 0 (Ray Tracing Gems ch. 7). `None` where [`TOLERANCE`]
/// covers it a thousand times over.
fn tangent_tolerance(center: DVec3, radius: f64, origin: DVec3, dir: DVec3) -> Option<f64> {
    let (s, c) = ((origin - center) / radius, dir / radius);
    let (a, b, cc) = (c.length_squared(), s.dot(c), s.length_squared() - 1.0);
    let disc = b * b - a * cc;
    if disc <= 0.0 {
        return None;
    }
    let error = f64::EPSILON * (b * b + (a * cc).abs()) / (a * disc.sqrt());
    (error * 1e3 > TOLERANCE).then_some(error * 1e3)
}

/// A vector as JSON: `[x, y, z]`.
fn v(p: DVec3) -> Value {
    json!([p.x, p.y, p.z])
}

/// An affine map as three rows `[a, b, c, t]`.
fn rows(m: &DAffine3) -> Value {
    let l = m.matrix3;
    let t = m.translation;
    json!([
        [l.x_axis.x, l.y_axis.x, l.z_axis.x, t.x],
        [l.x_axis.y, l.y_axis.y, l.z_axis.y, t.y],
        [l.x_axis.z, l.y_axis.z, l.z_axis.z, t.z],
    ])
}

/// A node's path from the primary ray: `primary → refracted → reflected`.
fn path(nodes: &[RayNode], mut i: usize) -> String {
    let name = |kind: RayKind| kind.name();
    let mut kinds = vec![name(nodes[i].kind)];
    while let Some(parent) = nodes[i].parent {
        i = parent;
        kinds.push(name(nodes[i].kind));
    }
    kinds.reverse();
    kinds.join(" → ")
}

#[cfg(test)]
mod tests;
