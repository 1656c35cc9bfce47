//! The built book in a real browser: mdBook builds it into a scratch folder
//! and headless Chromium (its own profile, in the scratch folder) opens every
//! page. Each page must load without a console message; each chapter's
//! player, stepped to its last stop by its Next button and back by the arrow
//! key, must at every stop show exactly the rays the trace has spawned by
//! that stop's step; each checked question must say wrong to a wrong answer
//! and right to raytree's value; no page may scroll sideways at 1280 pixels.
//! The page reports what it shows through the probe (`probe.js`), which
//! this test alone adds to each built page it opens and which presses the
//! real controls; what it should show comes from the trace, here. Readers'
//! pages load only `book/player/player.js` and `questions.js`.

use std::path::{Path, PathBuf};
use std::process::Command;

use raytree::course::lesson;
use raytree::tree::ray_tree::{RayTree, ShadowOutcomeRecord};
use raytree::tree::steps::{Step, StepKind};
use serde_json::Value;

use super::book::run;
use crate::tools::{Need, available};

/// The page's width in the browser, as the readers used it.
const WIDTH: u32 = 1280;

/// The probe, added to a built page after the book's own scripts.
const PROBE: &str = include_str!("probe.js");

#[test]
fn the_books_players_and_questions_work_in_a_real_browser() {
    if !available(
        "",
        &[Need::MdBook, Need::Chromium],
        "the book is built with mdBook and read in headless Chromium",
    ) {
        return;
    }
    let scratch = tempfile::tempdir().unwrap();
    let built = scratch.path().join("book");
    let out = Command::new("mdbook")
        .args(["build", "book", "-d"])
        .arg(&built)
        .current_dir(run::root())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "mdbook build: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut failures = Vec::new();
    let size = folder_size(&built);
    if size > 25 * 1024 * 1024 {
        failures.push(format!("the built book is {size} bytes, over 25 MB"));
    }
    let entries = lesson::list(&run::root().join("lessons")).unwrap();
    for e in &entries {
        let page = built.join(format!("lessons/{}.html", e.name));
        let (report, console) = open(&page, scratch.path());
        let loaded = lesson::load(&run::root().join("lessons"), e.number).unwrap();
        let walk = lesson::step_through(&loaded).unwrap();
        failures.extend(
            console
                .into_iter()
                .map(|c| format!("{}: console: {c}", e.name)),
        );
        failures.extend(check_player(&e.name, e.number, &report, &loaded, &walk));
        failures.extend(check_questions(&e.name, &report, e.spec.questions.len()));
        failures.extend(check_parsing(&e.name, &report));
        failures.extend(check_width(&e.name, &report));
    }
    for other in [
        "preface",
        "spd",
        "where-next",
        "commands",
        "scene-format",
        "trace-format",
    ] {
        let (report, console) = open(&built.join(format!("{other}.html")), scratch.path());
        failures.extend(
            console
                .into_iter()
                .map(|c| format!("{other}: console: {c}")),
        );
        failures.extend(check_width(other, &report));
    }
    assert!(
        failures.is_empty(),
        "in the browser:\n{}",
        failures.join("\n")
    );
}

/// Opens `page` (of the scratch build) with the probe added and returns the
/// probe's report and every console message the page logged.
fn open(page: &Path, scratch: &Path) -> (Value, Vec<String>) {
    add_probe(page);
    let profile: PathBuf = scratch.join("chromium-profile");
    let out = Command::new("chromium")
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--no-first-run",
            "--enable-logging=stderr",
            "--v=0",
            &format!("--window-size={WIDTH},900"),
            "--virtual-time-budget=15000",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg("--dump-dom")
        .arg(format!("file://{}", page.display()))
        .output()
        .unwrap();
    let dom = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let console = stderr
        .lines()
        .filter(|l| l.contains(":CONSOLE"))
        .map(|l| l.split_once("] ").map_or(l, |(_, m)| m).to_owned())
        .collect();
    let start = "<pre id=\"raytree-selftest\">";
    let report = dom
        .split_once(start)
        .and_then(|(_, rest)| rest.split_once("</pre>"))
        .map(|(json, _)| json.replace("&quot;", "\"").replace("&amp;", "&"))
        .unwrap_or_else(|| {
            panic!(
                "{}: no self-test report; the page's script did not run (stderr: {})",
                page.display(),
                stderr
                    .lines()
                    .filter(|l| !l.contains("dbus"))
                    .collect::<Vec<_>>()
                    .join(" | ")
            )
        });
    (serde_json::from_str(&report).unwrap(), console)
}

/// The player went from the first stop to the last and back, and at every
/// stop its diagram showed the rays spawned by the stop's step, no more, no
/// fewer, and its tree listed as many.
fn check_player(
    name: &str,
    number: u32,
    report: &Value,
    loaded: &lesson::Lesson,
    walk: &lesson::StepThrough,
) -> Vec<String> {
    let players = report["players"].as_array().cloned().unwrap_or_default();
    let [player] = players.as_slice() else {
        return vec![format!(
            "{name}: {} players on the page, not one",
            players.len()
        )];
    };
    let mut out = Vec::new();
    if player["lesson"] != number {
        out.push(format!(
            "{name}: the player is lesson {}'s",
            player["lesson"]
        ));
    }
    let drawn = Drawn {
        steps: walk.trace.steps(loaded.script.sample),
        tree: &walk.trace.samples[loaded.script.sample].tree,
        depth: loaded.script.player.depth.unwrap_or(u32::MAX),
        no_shadows: loaded.script.player.no_shadows,
    };
    out.extend(check_stops(name, player, walk, &drawn));
    out.extend(check_shadow_click(name, player));
    if drawn.tree.nodes.is_empty() {
        out.push(format!("{name}: the traced pixel has no rays"));
    }
    out.extend(check_ray_clicks(name, player, drawn.tree));
    out
}

/// What the trace says the player's diagram draws. It draws rays to the
/// script's [player] depth, and the list names what it draws: those rays,
/// and their shadow rays unless the script leaves them out (lessons 3 to 5
/// once listed eleven rays beside a diagram of one).
struct Drawn<'a> {
    steps: Vec<Step>,
    tree: &'a RayTree,
    depth: u32,
    no_shadows: bool,
}

impl Drawn<'_> {
    fn drawn(&self, s: &Step) -> bool {
        self.tree.nodes[s.node].depth <= self.depth
    }

    /// The drawn rays spawned by `step`, in spawn order.
    fn spawned_by(&self, step: usize) -> Vec<u64> {
        self.steps[..step]
            .iter()
            .filter(|s| s.kind == StepKind::Spawn)
            .filter(|s| self.drawn(s))
            .map(|s| s.node as u64)
            .collect()
    }

    /// Shadow rays cast by then (a light behind the surface casts none).
    fn shadows_by(&self, step: usize) -> u64 {
        let cast = self.steps[..step]
            .iter()
            .filter(|s| match s.kind {
                StepKind::Shadow(k) => !matches!(
                    self.tree.nodes[s.node].shadow_rays[k].outcome,
                    ShadowOutcomeRecord::FacesAway
                ),
                _ => false,
            })
            .filter(|s| self.drawn(s));
        if self.no_shadows {
            0
        } else {
            cast.count() as u64
        }
    }
}

/// At every stop, forward through them all and back by the key to the
/// first, the diagram shows the rays the trace has spawned, the tree lists
/// as many, and every listed shadow ray is drawn.
fn check_stops(
    name: &str,
    player: &Value,
    walk: &lesson::StepThrough,
    drawn: &Drawn,
) -> Vec<String> {
    let mut out = Vec::new();
    let seen = player["seen"].as_array().unwrap();
    let n = walk.stops.len();
    // Forward through every stop, then back by the key to the first.
    let order: Vec<usize> = (0..n).chain((0..n.saturating_sub(1)).rev()).collect();
    if seen.len() != order.len() {
        out.push(format!(
            "{name}: the player showed {} states stepping {n} stops there and back, not {}",
            seen.len(),
            order.len()
        ));
    }
    for (look, &stop) in seen.iter().zip(&order) {
        let step = walk.stops[stop].step;
        out.extend(check_stop(name, look, stop, step, drawn));
    }
    out
}

/// What the player showed at one stop (`look`), held to the trace.
fn check_stop(name: &str, look: &Value, stop: usize, step: usize, drawn: &Drawn) -> Option<String> {
    let mut want = drawn.spawned_by(step);
    want.sort_unstable();
    let listed = want.len();
    let shown: Vec<u64> = look["rays"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_u64().unwrap())
        .collect();
    if look["stop"] != stop || look["step"] != step {
        Some(format!(
            "{name}: expected stop {} (step {step}), the player is at {look}",
            stop + 1
        ))
    } else if shown != want {
        Some(format!(
            "{name}: at stop {} (step {step}) the diagram shows rays {shown:?}, but the trace has spawned {want:?} by then",
            stop + 1
        ))
    } else if look["tree"] != listed {
        Some(format!(
            "{name}: at stop {} the tree lists {} rays, not the {listed} drawn",
            stop + 1,
            look["tree"],
        ))
    } else if look["shadows"] != look["shadowsShown"]
        || look["shadows"]
            .as_u64()
            .is_none_or(|n| n > drawn.shadows_by(step))
    {
        // Every listed shadow ray is drawn, and none the trace has not cast.
        Some(format!(
            "{name}: at stop {} the tree lists {} shadow rays, the diagram shows {}, the trace has cast {}",
            stop + 1,
            look["shadows"],
            look["shadowsShown"],
            drawn.shadows_by(step)
        ))
    } else {
        None
    }
}

/// A shadow ray clicked in the list shows its own line, and the diagram
/// marks that shadow ray alone.
fn check_shadow_click(name: &str, player: &Value) -> Option<String> {
    let seen = player["seen"].as_array().unwrap();
    let listed = seen.iter().any(|l| l["shadows"].as_u64() > Some(0));
    let shadow = &player["shadow"];
    let shows = shadow["shows"]
        .as_str()
        .is_some_and(|s| s.starts_with("shadow ray to '"))
        && shadow["marked"].as_u64().is_some_and(|m| m > 0)
        && shadow["markedShadow"] == true;
    (listed && !shows).then(|| {
        format!(
            "{name}: clicking the last listed shadow ray gave {shadow}, not its line and its mark in the diagram"
        )
    })
}

/// A ray clicked, in the tree or in the diagram, shows its own numbers.
fn check_ray_clicks(name: &str, player: &Value, tree: &RayTree) -> Vec<String> {
    let mut out = Vec::new();
    let clicked = player["clicked"].as_array().cloned().unwrap_or_default();
    if clicked.len() != 2 {
        out.push(format!(
            "{name}: {} rays could be clicked, not 2 (the tree's last and the diagram's primary)",
            clicked.len()
        ));
    }
    for c in &clicked {
        let ray = c["ray"].as_u64().unwrap_or(u64::MAX) as usize;
        let kind = tree
            .nodes
            .get(ray)
            .map(|n| format!("{:?}", n.kind).to_lowercase());
        // Numbered from 1, as the tree graph numbers them.
        let want = format!("ray {}: {}, depth", ray + 1, kind.unwrap_or_default());
        if !c["shows"].as_str().is_some_and(|s| s.starts_with(&want)) {
            out.push(format!(
                "{name}: clicking ray {ray} shows {}, not '{want} …'",
                c["shows"]
            ));
        }
    }
    out
}

/// Adds the probe to a built page, as the last script of its body: it runs
/// after the book's scripts, once they have started the page.
fn add_probe(page: &Path) {
    let html = std::fs::read_to_string(page).unwrap();
    let at = html
        .rfind("</body>")
        .unwrap_or_else(|| panic!("{}: no </body>", page.display()));
    let probed = format!("{}<script>\n{PROBE}</script>\n{}", &html[..at], &html[at..]);
    std::fs::write(page, probed).unwrap();
}

/// Every question said wrong to a wrong answer and right to raytree's.
fn check_questions(name: &str, report: &Value, count: usize) -> Vec<String> {
    let asked = report["questions"].as_array().cloned().unwrap_or_default();
    let mut out = Vec::new();
    if asked.len() != count {
        out.push(format!(
            "{name}: {} question boxes work on the page, the spec has {count}",
            asked.len()
        ));
    }
    for (k, q) in asked.iter().enumerate() {
        let (wrong, right) = (
            q["wrong"].as_str().unwrap_or(""),
            q["right"].as_str().unwrap_or(""),
        );
        let typed = q["typedVerdict"].as_str().unwrap_or("");
        if !typed.contains("rq-right") {
            out.push(format!(
                "{name}: question {}: the right answer typed as a reader types it, {}, got '{typed}'",
                k + 1,
                q["typed"]
            ));
        }
        // A whole answer of 1,000 or more typed with thousands commas
        // ("336,120", which could also be 336.12) is right too.
        if let Some(commas) = q["commasVerdict"].as_str()
            && !commas.contains("rq-right")
        {
            out.push(format!(
                "{name}: question {}: the right answer typed with thousands commas, {}, got '{commas}'",
                k + 1,
                q["commas"]
            ));
        }
        if !wrong.contains("rq-wrong") || !right.contains("rq-right") {
            out.push(format!(
                "{name}: question {}: a wrong answer got '{wrong}', the right one '{right}'",
                k + 1
            ));
        }
    }
    out
}

/// Answers typed as readers type them are read as the numbers they mean. A
/// lone comma is a decimal comma: "0,9514" was once read as 9514, and a
/// reader typing the right answer the European way was told "too high".
fn check_parsing(name: &str, report: &Value) -> Vec<String> {
    let want = [
        ("0,9514", 0.9514),
        ("\u{2212}0,2328", -0.2328),
        ("1,5", 1.5),
        ("0.5", 0.5),
        ("\u{2212}0.2328", -0.2328),
        ("336 120", 336_120.0),
        ("1,234.5", 1234.5),
        ("1,234,567", 1_234_567.0),
        ("2,5 px", 2.5),
        ("\u{2212} 7", -7.0),
        ("45\u{b0}", 45.0),
        ("1e3", 1000.0),
        // Not numbers, though they begin like one: once read as 1.2, 1.234
        // and 1. NaN, which the report's JSON writes as null.
        ("1,2,3", f64::NAN),
        ("1.234,5", f64::NAN),
        ("1e", f64::NAN),
    ];
    let parsed = report["parsed"].as_array().cloned().unwrap_or_default();
    let mut out = Vec::new();
    if parsed.len() != want.len() {
        out.push(format!(
            "{name}: the probe read {} typed answers, not {}",
            parsed.len(),
            want.len()
        ));
    }
    for (got, (text, value)) in parsed.iter().zip(want) {
        let read = got[1].as_f64();
        // Both sides are the nearest double to the same decimal; the
        // tolerance only allows for a different rounding in the parse.
        let right = if value.is_nan() {
            got[1].is_null()
        } else {
            read.is_some_and(|r| (r - value).abs() <= 1e-12 * value.abs())
        };
        if got[0] != text || !right {
            out.push(format!(
                "{name}: the answer typed {} is read as {}, not {value}",
                got[0], got[1]
            ));
        }
    }
    out
}

/// The page does not scroll sideways.
fn check_width(name: &str, report: &Value) -> Vec<String> {
    let (scroll, width) = (&report["scrollWidth"], &report["width"]);
    match (scroll.as_u64(), width.as_u64()) {
        (Some(s), Some(w)) if s <= w => Vec::new(),
        _ => vec![format!(
            "{name}: the page is {scroll} pixels wide in a {width}-pixel window: it scrolls sideways"
        )],
    }
}

/// Bytes in a folder and all below it.
fn folder_size(dir: &Path) -> u64 {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            let meta = e.metadata().unwrap();
            if meta.is_dir() {
                folder_size(&e.path())
            } else {
                meta.len()
            }
        })
        .sum()
}
