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

mod mutate; // the mutations: JSON values and their text, lines of OBJ, NFF and CSV
mod seeds; // the valid inputs the mutations start from

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use arbitrary::Unstructured;
use raytree::scene::source::SceneSource;
use raytree::scene::{loader, obj};
use raytree::tree::reading;
use serde_json::Value;

use crate::commands::fuzz::mutate::{NFF_EDITS, OBJ_EDITS, mutate_lines, mutated, mutated_csv};
use crate::commands::fuzz::seeds::{
    LEARNER_SCENE, NFF_SEEDS, OBJ_SEEDS, folder, learner_seeds, scene_seeds, structures_seeds,
    trace_seeds,
};

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
