//! Structure-aware mutation fuzzing of the readers of outside files: the
//! scene loader, the OBJ reader, the trace reader (issue 12) and the NFF
//! reader (issue 27), the `raytree structures` CSV reader (issue 28) and the
//! learner trace reader of `raytree check` (issue 25). Each case
//! takes a valid seed (a shipped or generated scene, a small OBJ, a real trace)
//! and applies a few mutations chosen from random bytes through `arbitrary`: a
//! value swapped for an edge case (huge, tiny, negative, NaN-like text, a
//! control character), a key dropped, duplicated or unknown, an object written
//! as an array, an index pushed past the end, a line repeated or cut. Every
//! case must end in `Ok` or one-line `Err`, with no panic, within a few
//! seconds, and leave no file behind; an accepted scene must render and trace
//! finite numbers, and an accepted trace must read through the views.
//!
//! `cargo test --release fuzz` runs a fixed few thousand cases in seconds.
//! `RAYTREE_FUZZ_SECONDS=600 cargo test --release fuzz_for_a_while -- --ignored --nocapture`
//! runs fresh cases for that long and prints how many of each were tried.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use arbitrary::Unstructured;
use raytree::scene::source::SceneSource;
use raytree::scene::{generate, loader, obj};
use raytree::tree::reading;
use serde_json::{Value, json};

/// Longest a case may take before it counts as a hang.
const HANG: Duration = Duration::from_secs(5);

/// The readers.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Target {
    Scene,
    Obj,
    Trace,
    Nff,
    StructuresCsv,
    Learner,
}

const TARGETS: [Target; 6] = [
    Target::Scene,
    Target::Obj,
    Target::Trace,
    Target::Nff,
    Target::StructuresCsv,
    Target::Learner,
];

/// `raytree structures` CSVs (issue 28): a comparison of two scenes, and a
/// grid sweep, written by the command's own writer from figures made up here
/// (the reader checks the ratios and medians against them, so a seed is
/// made, not typed).
fn structures_seeds() -> Vec<String> {
    use raytree::methods::{Accel, Level};
    use raytree::trace::structure_sweep::{Comparison, Mode, Row, STRUCTURES, csv};
    let row = |scene: &str, structure: Accel, grid_res: Option<Level>, k: u64| Row {
        scene: scene.to_owned(),
        structure,
        grid_res,
        grid_cells: grid_res.map(|_| [8, 2, 8]),
        objects: 2001,
        rays: 6398 + k,
        steps: 1000 * k,
        primitives: 50_000 / (k + 1),
        build_seconds: 0.001 * k as f64,
        run_seconds: vec![0.01 * (k + 1) as f64, 0.02, 0.005],
    };
    let structures = Comparison {
        mode: Mode::Structures,
        about: "2026-11-25 21:09 UTC, 40×30, no protocol, 3 runs, threads = 1, load 0.5 0.4 0.3"
            .to_owned(),
        rows: ["a.json", "b, \"c\".nff"]
            .iter()
            .flat_map(|s| {
                STRUCTURES.iter().enumerate().map(move |(k, &a)| {
                    row(s, a, (a == Accel::Grid).then_some(Level::Auto), k as u64)
                })
            })
            .collect(),
    };
    let sweep = Comparison {
        mode: Mode::GridSweep,
        about: "x".to_owned(),
        rows: [Level::Given(2), Level::Given(160), Level::Auto]
            .iter()
            .enumerate()
            .map(|(k, &l)| row("a.json", Accel::Grid, Some(l), k as u64))
            .collect(),
    };
    vec![csv(&structures), csv(&sweep)]
}

/// The line-level edge cases for the structures CSV: fields and lines that
/// are almost right.
const CSV_EDITS: LineEdits = LineEdits {
    empty: "# x",
    words: &[
        "", "nan", "-1", "1e999", "grid", "auto", "0", "161", "\"", "a,b",
    ],
    lines: &[
        "",
        "# comment",
        "a.json,grid,auto,1x1x1,1,1,0,0,0,0,0,0,0",
        "a.json,bvh,,,1,0,0,0,0,0,0,0,0",
        "\"unclosed,bvh",
    ],
    tail: ",",
};

/// Small NFF scenes holding every entity: the view, background, lights with
/// and without a color, materials opaque and transmitting, and each primitive.
const NFF_SEEDS: [&str; 2] = [
    "# every entity\nv\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 6 4\nb 0.1 0.2 0.3\nl 2 -3 4\nl -2 -3 4 1 1 1\nf 1 0.5 0.2 0.7 0.3 20 0 0\np 4\n-2 -2 0\n2 -2 0\n2 2 0\n-2 2 0\ns 0 0 1 0.5\nf 0.9 0.9 1 0.1 0.1 100 0.8 1.5\nc\n1 0 0 0.3\n1 0 1 0.1\npp 3\n-1 0 0.5 0 -1 0\n-0.5 0 0.5 0 -1 0\n-0.75 0 1 0 -1 0.2\n",
    "v\nfrom 3 3 3\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.01\nresolution 5 5\nl 1 1 5\nf 1 0 0 1 0 100000 0 0\np 6\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\nc\n0 0 0 0.5\n0 0 1 0.5\n",
];

/// A folder holding what scenes refer to: `m.obj` and `n.obj`.
fn folder() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("m.obj"), OBJ_SEEDS[0]).unwrap();
    std::fs::write(dir.path().join("n.obj"), generate::icosphere_obj(1)).unwrap();
    dir
}

const OBJ_SEEDS: [&str; 3] = [
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n",
    "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nf 1/1 3/1 2/1\nf 1 2 4\nf -1 -2 -3\nf 2 3 4\n",
    "o a\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\no b\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf 4 5 6\n",
];

fn scene_seeds() -> Vec<Value> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut seeds: Vec<Value> = [
        "whitted.json",
        "nested.json",
        "ellipsoids.json",
        "cones.json",
        "polygons.json",
    ]
    .iter()
    .map(|f| serde_json::from_str(&std::fs::read_to_string(root.join(f)).unwrap()).unwrap())
    .collect();
    seeds.push(serde_json::from_str(&generate::random_spheres(12, 1)).unwrap());
    seeds.push(serde_json::from_str(&generate::icosphere_scene("n.obj", 80)).unwrap());
    seeds.push(json!({
        "camera": {"eye": [0, 0, 5], "u": [1, 0, 0], "v": [0, 1, 0], "n": [0, 0, 1], "half_width": 1, "half_height": 0.75},
        "render": {"width": 8, "height": 6, "spp": 4, "weights": "fresnel", "offset": "epsilon=0.001"},
        "materials": {"m": {"checker": {"colors": [[1, 0, 0], [0, 0, 1]], "size": 0.5}}},
        "lights": [{"name": "l", "position": [1, 2, 3]}],
        "objects": [
            {"mesh": {"file": "m.obj", "smooth": false}, "material": "m"},
            {"box": {"min": [-1, -1, -1], "max": [0, 0, 0]}, "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 30}}, {"rotate_x": 10}, {"scale": [1, 2, 3]}]},
            {"triangle": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}},
            {"polygon": {"vertices": [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0.5, 0.2, 1], [0, 1, 1]], "one_sided": true}},
            {"polygon": {"vertices": [[0, 0, -1], [1, 0, -1], [0, 1, -1]], "normals": [[0, 0, 1], [0, 1, 1], [1, 0, 1]]}, "transform": [{"scale": [1, 2, 3]}]}
        ]
    }));
    seeds
}

fn trace_seeds() -> Vec<Value> {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/whitted.json"))
            .unwrap();
    let mut scene = loader::parse(&text, "s.json").unwrap();
    scene.settings.width = 64;
    scene.settings.height = 48;
    let source = SceneSource::new("s.json", &text);
    let pixel = raytree::tree::record::pixel(&scene, source.clone(), 42, 20, None).unwrap();
    scene.settings.spp = 4;
    let four = raytree::tree::record::pixel(&scene, source.clone(), 40, 30, None).unwrap();
    let ray = raytree::math::ray::Ray::new(glam::DVec3::new(0.9, 1.0, 1.2), glam::DVec3::X);
    let given = raytree::tree::record::ray(&scene, source, ray).unwrap();
    [pixel, four, given]
        .iter()
        .map(|t| serde_json::to_value(t).unwrap())
        .collect()
}

/// The learner trace examples of `docs/learner-trace/`, every one of them.
fn learner_seeds() -> Vec<Value> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/learner-trace");
    let mut seeds: Vec<Value> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap())
        .collect();
    seeds.sort_by_key(Value::to_string);
    assert!(seeds.len() >= 2, "{}: the examples", dir.display());
    seeds
}

/// The scene the learner trace examples are of.
const LEARNER_SCENE: &str = "scenes/whitted.json";

/// An accepted learner trace checks against raytree's own: a report, or one
/// line of bad input (a trace of another pixel), never a panic.
fn learner_works(learner: &raytree::course::learner::format::LearnerTrace) -> Result<(), String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(LEARNER_SCENE);
    let text = std::fs::read_to_string(&path).unwrap();
    let scene = loader::parse(&text, LEARNER_SCENE).unwrap();
    let pixel = learner.pixel.map_or((416, 209), |[x, y]| (x, y));
    if pixel.0 >= scene.settings.width || pixel.1 >= scene.settings.height {
        return Ok(());
    }
    let source = SceneSource::new(LEARNER_SCENE, &text);
    match raytree::course::learner::check::trace(&scene, source, pixel, learner) {
        Ok(report) => {
            let _ = (report.text(), report.json());
            Ok(())
        }
        Err(e) => one_line(&e),
    }
}

/// Values that test the edges of every range.
fn edge_value(u: &mut Unstructured, doc: &Value) -> arbitrary::Result<Value> {
    Ok(match u.int_in_range(0..=13)? {
        0 => Value::Null,
        1 => json!(u.arbitrary::<bool>()?),
        2 => json!(*u.choose(&[
            0.0, -0.0, -1.0, 0.5, 1.0, 2.0, 3.0, 9.0, 1024.0, 1025.0, 1000.0, 1001.0, 32768.0
        ])?),
        3 => json!(*u.choose(&[
            1e308, -1e308, 5e-324, 1e-300, 1e9, 2e9, -1e9, 1e-9, 1e-10, 1e6, 1e7, 1e12, 1e13
        ])?),
        4 => json!(*u.choose(&[u64::MAX, u64::from(u32::MAX), 4_294_967_296, 1 << 53])?),
        5 => json!(*u.choose(&[i64::MIN, -1, -2_147_483_649])?),
        6 => json!(
            u.arbitrary::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .unwrap_or(0.0)
        ),
        7 => json!([
            u.arbitrary::<i8>()?,
            u.arbitrary::<i8>()?,
            u.arbitrary::<i8>()?
        ]),
        8 => json!([]),
        9 => json!({}),
        10 => json!(*u.choose(&[
            "",
            "sphere",
            "glass",
            "default",
            "fresnel",
            "epsilon=-1",
            "adaptive=nan",
            "x\u{1b}[2J",
            "a\nb",
            "\u{7f}",
            "é",
            "m.obj",
            "n.obj",
            "/dev/zero",
            "..",
            "none.obj"
        ])?),
        11 => json!(u.arbitrary::<String>()?),
        12 => any_node(u, doc)?.clone(),
        _ => json!(u.int_in_range(0..=20)?),
    })
}

/// A node of `doc` at random (the root included).
fn any_node<'v>(u: &mut Unstructured, doc: &'v Value) -> arbitrary::Result<&'v Value> {
    let mut at = doc;
    while u.ratio(3, 4)? {
        at = match at {
            Value::Array(a) if !a.is_empty() => u.choose(a)?,
            Value::Object(m) if !m.is_empty() => {
                let keys: Vec<&String> = m.keys().collect();
                &m[*u.choose(&keys)?]
            }
            _ => break,
        };
    }
    Ok(at)
}

/// One structural mutation somewhere in `doc`.
fn mutate_json(u: &mut Unstructured, doc: &mut Value) -> arbitrary::Result<()> {
    let replacement = edge_value(u, doc)?;
    // Walk down to a node, noting its JSON pointer, then take it mutably.
    let mut pointer = String::new();
    let mut here: &Value = doc;
    while u.ratio(4, 5)? {
        here = match here {
            Value::Array(a) if !a.is_empty() => {
                let i = u.choose_index(a.len())?;
                pointer.push_str(&format!("/{i}"));
                &a[i]
            }
            Value::Object(m) if !m.is_empty() => {
                let keys: Vec<&String> = m.keys().collect();
                let k = *u.choose(&keys)?;
                pointer.push_str(&format!("/{}", k.replace('~', "~0").replace('/', "~1")));
                &m[k]
            }
            _ => break,
        };
    }
    let Some(at) = doc.pointer_mut(&pointer) else {
        return Ok(());
    };
    match (u.int_in_range(0..=7)?, &mut *at) {
        (0, Value::Object(m)) if !m.is_empty() => {
            let keys: Vec<String> = m.keys().cloned().collect();
            m.remove(u.choose(&keys)?);
        }
        (1, Value::Object(m)) => {
            let key = u.choose(&[
                "name",
                "radius",
                "unknown",
                "sphere",
                "plane",
                "mesh",
                "transform",
                "ior",
            ])?;
            m.insert((*key).to_owned(), replacement);
        }
        (2, Value::Object(m)) => *at = Value::Array(m.values().cloned().collect()),
        (3, Value::Array(a)) if !a.is_empty() => {
            let i = u.choose_index(a.len())?;
            if u.arbitrary()? {
                a.remove(i);
            } else {
                let copy = a[i].clone();
                a.push(copy);
            }
        }
        (4, Value::Number(n)) => {
            let x = n.as_f64().unwrap_or(0.0);
            let f = *u.choose(&[-1.0, 0.0, 2.0, 1e10, 1e-10, 1.000_000_1])?;
            *at = json!(if f == 0.0 { x + 1.0 } else { x * f });
        }
        (5, Value::Number(n)) => {
            let x = n.as_u64().unwrap_or(0);
            *at = json!(x + u.int_in_range(1..=3)?);
        }
        _ => *at = replacement,
    }
    Ok(())
}

/// Text-level damage JSON values cannot express: a key written twice, a cut,
/// a stray byte.
fn damage_text(u: &mut Unstructured, text: &mut String) -> arbitrary::Result<()> {
    match u.int_in_range(0..=9)? {
        0 => {
            if let Some(i) = text.find('{') {
                let key =
                    u.choose(&["\"name\": \"x\", ", "\"radius\": 1, ", "\"objects\": [], "])?;
                if text[i + 1..].trim_start().starts_with('"') {
                    text.insert_str(i + 1, key);
                }
            }
        }
        1 => {
            let cut = u.choose_index(text.len().max(1))?;
            let cut = (0..=cut)
                .rev()
                .find(|&c| text.is_char_boundary(c))
                .unwrap_or(0);
            text.truncate(cut);
        }
        2 => {
            let at = u.choose_index(text.len().max(1))?;
            let at = (0..=at)
                .rev()
                .find(|&c| text.is_char_boundary(c))
                .unwrap_or(0);
            let c = *u.choose(&['{', '}', '[', ']', ',', ':', '"', '\\', '\u{1b}', '\0'])?;
            text.insert(at, c);
        }
        _ => {}
    }
    Ok(())
}

/// What a line-level mutator may put in: a line for an emptied file, words
/// to swap in, whole lines to swap in, and a word to append.
struct LineEdits {
    empty: &'static str,
    words: &'static [&'static str],
    lines: &'static [&'static str],
    tail: &'static str,
}

const OBJ_EDITS: LineEdits = LineEdits {
    empty: "f 1 2 3",
    words: &[
        "0",
        "-1",
        "-9",
        "99",
        "1e308",
        "nan",
        "inf",
        "-inf",
        "2e9",
        "1/",
        "//",
        "1//9",
        "x",
        "",
        "4294967296",
        "-2147483649",
    ],
    lines: &[
        "f 1",
        "f 1 2",
        "f 1 1 1",
        "v 1",
        "vn 0 0 0",
        "vt",
        "l 1 2",
        "p 1",
        "mtllib x.mtl",
        "usemtl red",
        "o",
        "g",
        "s off",
    ],
    tail: " 1e-300",
};

/// NFF's: entities with wrong counts, degenerate shapes, huge vertex counts.
const NFF_EDITS: LineEdits = LineEdits {
    empty: "s 0 0 0 1",
    words: &[
        "0",
        "-1",
        "1",
        "2",
        "3",
        "1e308",
        "nan",
        "NaN",
        "inf",
        "-inf",
        "2e9",
        "1e-300",
        "x",
        "",
        "4294967296",
        "99999999",
        "0.5",
        "-0",
    ],
    lines: &[
        "p 2",
        "p 3",
        "p 1000000000",
        "pp 3",
        "p 3\n0 0 0\n1 1 1\n2 2 2",
        "p 3\n0 0 0\n0 0 0\n1 0 0",
        "c\n0 0 0 0\n0 0 1 0",
        "c\n0 0 0 1\n0 0 0 1",
        "c\n0 0 0 -1\n0 0 1 1",
        "s 0 0 0 0",
        "s 0 0 0 -1",
        "f 1 1 1 1 0.6 10 0.6 1.5",
        "f 1 1 1 1 0 10 0.5 0",
        "v",
        "b 1 1",
        "l 1 2",
        "up 0 0 0",
        "angle 180",
        "resolution 0 4",
        "# comment",
        "q 1 2 3",
    ],
    tail: " 1",
};

/// A seed of a line-based format (OBJ, NFF) with a few line-level
/// mutations: lines dropped, repeated, swapped or cut short, words and lines
/// swapped for `edits`' edge cases, and now and then a byte that is not UTF-8.
fn mutate_lines(u: &mut Unstructured, text: &str, edits: &LineEdits) -> arbitrary::Result<Vec<u8>> {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    for _ in 0..u.int_in_range(1..=4)? {
        if lines.is_empty() {
            lines.push(edits.empty.to_owned());
        }
        let i = u.choose_index(lines.len())?;
        match u.int_in_range(0..=7)? {
            0 => {
                lines.remove(i);
            }
            1 => lines.insert(i, lines[i].clone()),
            2 => {
                let mut words: Vec<String> = lines[i].split(' ').map(str::to_owned).collect();
                let w = u.choose_index(words.len())?;
                words[w] = (*u.choose(edits.words)?).to_owned();
                lines[i] = words.join(" ");
            }
            3 => lines[i] = (*u.choose(edits.lines)?).to_owned(),
            4 => {
                let j = u.choose_index(lines.len())?;
                lines.swap(i, j);
            }
            5 => lines[i] = u.arbitrary::<String>()?,
            6 => lines.truncate(i),
            _ => lines[i].push_str(edits.tail),
        }
    }
    let mut bytes = lines.join("\n").into_bytes();
    if u.ratio(1, 20)? {
        let at = u.choose_index(bytes.len().max(1))?.min(bytes.len());
        bytes.insert(at, 0xff);
    }
    Ok(bytes)
}

/// The seeds, made once.
struct Seeds {
    scenes: Vec<Value>,
    traces: Vec<Value>,
    csvs: Vec<String>,
    learners: Vec<Value>,
}

/// One case: `data` chooses a seed and its mutations, the reader runs on the result.
fn run_case(target: Target, seeds: &Seeds, dir: &Path, data: &[u8]) -> Result<(), String> {
    let mut u = Unstructured::new(data);
    match target {
        Target::Obj => {
            let seed = *u.choose(&OBJ_SEEDS).unwrap_or(&OBJ_SEEDS[0]);
            let bytes = mutate_lines(&mut u, seed, &OBJ_EDITS).unwrap_or_default();
            if let Err(e) = obj::parse(&bytes, "m.obj", true) {
                one_line(&e.to_string())?;
            }
        }
        Target::Scene => {
            let text = mutated(&mut u, &seeds.scenes);
            let file = dir.join("fuzz.json").display().to_string();
            match loader::parse(&text, &file) {
                Ok(scene) => scene_works(scene, &text)?,
                Err(e) => one_line(&e.to_string())?,
            }
        }
        Target::Nff => {
            let seed = *u.choose(&NFF_SEEDS).unwrap_or(&NFF_SEEDS[0]);
            let bytes = mutate_lines(&mut u, seed, &NFF_EDITS).unwrap_or_default();
            // The loader takes text: bytes that are not UTF-8 stop at reading (a test of inputs).
            let text = String::from_utf8_lossy(&bytes);
            let file = dir.join("fuzz.nff").display().to_string();
            match loader::parse_file(&text, &file) {
                Ok(scene) => scene_works(scene, &text)?,
                Err(e) => one_line(&e.to_string())?,
            }
        }
        Target::Trace => {
            let text = mutated(&mut u, &seeds.traces);
            match reading::parse(&text) {
                Ok(trace) => trace_works(&trace)?,
                Err(e) => one_line(&e)?,
            }
        }
        Target::StructuresCsv => {
            let text = mutated_csv(&mut u, &seeds.csvs);
            match raytree::trace::structure_sweep::parse_csv(&text) {
                Ok(c) => {
                    // An accepted CSV draws and tabulates without a panic.
                    let _ = raytree::views::structures_chart::draw(&c, 600, 400);
                    let _ = raytree::views::structures_chart::table(&c);
                }
                Err(e) => one_line(&e)?,
            }
        }
        Target::Learner => {
            let text = mutated(&mut u, &seeds.learners);
            match raytree::course::learner::read::parse(&text) {
                Ok(learner) => learner_works(&learner)?,
                Err(e) => one_line(&e)?,
            }
        }
    }
    Ok(())
}

/// A structures CSV seed with line and word mutations, as text.
fn mutated_csv(u: &mut Unstructured, seeds: &[String]) -> String {
    let seed = u.choose(seeds).map_or("", String::as_str);
    let bytes = mutate_lines(u, seed, &CSV_EDITS).unwrap_or_default();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// A seed with 1 to 4 mutations, as text, maybe damaged.
fn mutated(u: &mut Unstructured, seeds: &[Value]) -> String {
    let mut doc = u.choose(seeds).cloned().unwrap_or(Value::Null);
    let n = u.int_in_range(1..=4).unwrap_or(1);
    for _ in 0..n {
        let _ = mutate_json(u, &mut doc);
    }
    let mut text = serde_json::to_string_pretty(&doc).unwrap();
    let _ = damage_text(u, &mut text);
    text
}

fn one_line(message: &str) -> Result<(), String> {
    if super::inputs::names_a_rust_type(message) {
        return Err(format!("names a Rust type: {message:?}"));
    }
    match message.contains('\n') || message.is_empty() {
        true => Err(format!("not one line: {message:?}")),
        false => Ok(()),
    }
}

/// An accepted scene, made small, renders finite pixels and traces a pixel
/// that writes and reads back exactly.
fn scene_works(mut scene: raytree::scene::Scene, text: &str) -> Result<(), String> {
    let s = &mut scene.settings;
    (s.width, s.height, s.spp) = (s.width.min(4), s.height.min(3), s.spp.min(4));
    s.max_depth = s.max_depth.min(6);
    if let raytree::methods::Antialiasing::Adaptive { levels, .. } = &mut s.aa {
        *levels = (*levels).min(1);
    }
    if scene.objects.len() > 64 {
        return Ok(());
    }
    let image = raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET)
        .map_err(|e| e.to_string())?;
    if let Some(p) = image.pixels.iter().find(|p| !p.is_finite()) {
        return Err(format!("a pixel is {p}"));
    }
    let source = SceneSource::new("fuzz.json", text);
    // The pixel at (1, 1), or the last one of a smaller image.
    let (x, y) = (
        scene.settings.width.min(2) - 1,
        scene.settings.height.min(2) - 1,
    );
    let trace =
        raytree::tree::record::pixel(&scene, source, x, y, None).map_err(|e| e.to_string())?;
    trace.to_checked_json().map(|_| ())
}

/// An accepted trace reads through the text view and its steps.
fn trace_works(trace: &raytree::tree::document::TraceDocument) -> Result<(), String> {
    for k in 0..trace.samples.len() {
        let _ = trace.steps(k);
    }
    let text = raytree::views::text::format(trace, true);
    if text.contains('\u{1b}') {
        return Err("an escape reached the text trace".to_owned());
    }
    Ok(())
}

/// Runs `cases` cases of `target`, each from `case_bytes(i)`, in a worker
/// thread watched for hangs; a failing case is saved under `target/fuzz/`.
fn campaign(target: Target, seeds: Seeds, cases: u64, seed: u64, until: Option<Instant>) -> u64 {
    let dir = folder();
    let before = listing(dir.path());
    let (tx, rx) = mpsc::channel::<(u64, Vec<u8>, Result<(), String>)>();
    let work_dir = dir.path().to_owned();
    let worker = std::thread::spawn(move || {
        let mut rng = fastrand::Rng::with_seed(seed);
        for i in 0..cases {
            if until.is_some_and(|t| Instant::now() > t) {
                break;
            }
            let len = rng.usize(16..=512);
            let data: Vec<u8> = std::iter::repeat_with(|| rng.u8(..)).take(len).collect();
            let outcome = catch_unwind(AssertUnwindSafe(|| {
                run_case(target, &seeds, &work_dir, &data)
            }))
            .unwrap_or_else(|p| {
                Err(format!(
                    "panicked: {}",
                    p.downcast_ref::<String>()
                        .cloned()
                        .or_else(|| p.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                        .unwrap_or_default()
                ))
            });
            if tx.send((i, data, outcome)).is_err() {
                break;
            }
        }
    });
    let mut done = 0;
    loop {
        match rx.recv_timeout(HANG) {
            Ok((i, data, outcome)) => {
                done += 1;
                if let Err(e) = outcome {
                    let saved = save(target, &data);
                    panic!(
                        "{target:?} case {i} (seed {seed}): {e}; its bytes are in {}",
                        saved.display()
                    );
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => break,
            Err(mpsc::RecvTimeoutError::Timeout) => {
                panic!("{target:?}: case {done} (seed {seed}) ran over {HANG:?}: a hang");
            }
        }
    }
    worker.join().unwrap();
    assert_eq!(listing(dir.path()), before, "{target:?}: files left behind");
    done
}

fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

fn save(target: Target, data: &[u8]) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fuzz");
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join(format!("{target:?}-{:016x}.bin", fastrand::u64(..)));
    let _ = std::fs::write(&path, data);
    path
}

fn seeds() -> Seeds {
    Seeds {
        scenes: scene_seeds(),
        traces: trace_seeds(),
        csvs: structures_seeds(),
        learners: learner_seeds(),
    }
}

#[test]
fn fuzz_the_scene_loader() {
    assert_eq!(campaign(Target::Scene, seeds(), 1500, 1, None), 1500);
}

#[test]
fn fuzz_the_obj_reader() {
    assert_eq!(campaign(Target::Obj, seeds(), 4000, 2, None), 4000);
}

#[test]
fn fuzz_the_trace_reader() {
    assert_eq!(campaign(Target::Trace, seeds(), 1500, 3, None), 1500);
}

#[test]
fn fuzz_the_nff_reader() {
    assert_eq!(campaign(Target::Nff, seeds(), 3000, 4, None), 3000);
}

#[test]
fn fuzz_the_structures_csv_reader() {
    assert_eq!(
        campaign(Target::StructuresCsv, seeds(), 3000, 5, None),
        3000
    );
}

#[test]
fn fuzz_the_learner_trace_reader() {
    assert_eq!(campaign(Target::Learner, seeds(), 1500, 6, None), 1500);
}

#[test]
fn the_learner_trace_seeds_are_read_whole() {
    for (k, seed) in learner_seeds().iter().enumerate() {
        raytree::course::learner::read::parse(&seed.to_string())
            .unwrap_or_else(|e| panic!("learner trace seed {k}: {e}"));
    }
}

#[test]
fn the_structures_csv_seeds_are_read_whole() {
    for (k, seed) in structures_seeds().iter().enumerate() {
        let c = raytree::trace::structure_sweep::parse_csv(seed)
            .unwrap_or_else(|e| panic!("structures CSV seed {k}: {e}"));
        assert!(c.rows.len() >= 3, "seed {k}");
    }
}

#[test]
fn the_nff_seeds_are_read_whole() {
    // The fuzzer's seeds must be valid, or every case would stop at the first error.
    for (k, seed) in NFF_SEEDS.iter().enumerate() {
        let scene =
            loader::parse_file(seed, "seed.nff").unwrap_or_else(|e| panic!("NFF seed {k}: {e}"));
        assert!(scene.objects.len() >= 2, "seed {k}");
    }
}

/// The long run: `RAYTREE_FUZZ_SECONDS` (default 600) split between the
/// readers, fresh seeds each run; prints the cases tried.
#[test]
#[ignore = "runs for minutes: RAYTREE_FUZZ_SECONDS=600 cargo test --release fuzz_for_a_while -- --ignored --nocapture"]
fn fuzz_for_a_while() {
    let seconds: u64 = std::env::var("RAYTREE_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(600);
    let start = fastrand::u64(..);
    let mut total = 0;
    for (k, target) in TARGETS.into_iter().enumerate() {
        let until = Instant::now() + Duration::from_secs(seconds / TARGETS.len() as u64);
        let tried = campaign(
            target,
            seeds(),
            u64::MAX,
            start.wrapping_add(k as u64),
            Some(until),
        );
        println!(
            "{target:?}: {tried} cases in {} s, no panic, no hang, no file left (seed {})",
            seconds / TARGETS.len() as u64,
            start.wrapping_add(k as u64)
        );
        total += tried;
    }
    println!("all: {total} cases");
}

#[test]
fn mutations_reach_the_interesting_places() {
    // The mutator is not idle: most cases of each reader are rejected, some
    // accepted, so both paths are exercised.
    let seeds = seeds();
    let dir = folder();
    for target in TARGETS {
        let mut rng = fastrand::Rng::with_seed(9);
        let (mut ok, mut err) = (0, 0);
        for _ in 0..300 {
            let data: Vec<u8> = std::iter::repeat_with(|| rng.u8(..)).take(256).collect();
            let mut u = Unstructured::new(&data);
            let accepted = match target {
                Target::Obj => {
                    let bytes = mutate_lines(&mut u, OBJ_SEEDS[1], &OBJ_EDITS).unwrap_or_default();
                    obj::parse(&bytes, "m.obj", true).is_ok()
                }
                Target::Scene => loader::parse(
                    &mutated(&mut u, &seeds.scenes),
                    &dir.path().join("f.json").display().to_string(),
                )
                .is_ok(),
                Target::Trace => reading::parse(&mutated(&mut u, &seeds.traces)).is_ok(),
                Target::Nff => {
                    let bytes = mutate_lines(&mut u, NFF_SEEDS[0], &NFF_EDITS).unwrap_or_default();
                    loader::parse_file(&String::from_utf8_lossy(&bytes), "f.nff").is_ok()
                }
                Target::StructuresCsv => {
                    raytree::trace::structure_sweep::parse_csv(&mutated_csv(&mut u, &seeds.csvs))
                        .is_ok()
                }
                Target::Learner => {
                    raytree::course::learner::read::parse(&mutated(&mut u, &seeds.learners)).is_ok()
                }
            };
            if accepted { ok += 1 } else { err += 1 }
        }
        assert!(
            ok >= 5 && err >= 100,
            "{target:?}: {ok} accepted, {err} rejected"
        );
    }
}
