//! The lessons and the book. The book (`book/src/`) is made from the lessons
//! (`lessons/`) and the pages in `book/pages/` by running the raytree commands
//! their specs name; the made files are committed, and `book_is_current`
//! makes them afresh and names every figure, number, excerpt or page that
//! differs. After an intended change:
//! `RAYTREE_BLESS=1 cargo test --release book`, then read the diff and look at
//! the figures. `lessons/README.md` explains the format. What this machine
//! lacks the tools for (lesson 14 without Ghostscript or the lecture) is left
//! as committed, the text around it still checked, and said in one line
//! ([`crate::tools`]).

mod check;
mod code_width;
mod frame;
mod links;
mod make;
mod page;
mod stray_lists;
pub(super) mod run;

use std::process::Command;

use raytree::course::lesson;

use crate::tools::{Need, available};

#[test]
fn book_is_current() {
    let files = make::book().unwrap_or_else(|e| panic!("{e}"));
    // What this machine could not make (lesson 14 without Ghostscript or the
    // lecture) is said in one line, left as committed, and checked around.
    let unmade: Vec<String> = files
        .iter()
        .filter(|f| !f.unmade.is_empty())
        .map(|f| format!("{}'s {}", f.path, grouped(&f.unmade)))
        .collect();
    let mut missing: Vec<Need> = files.iter().flat_map(|f| f.missing.clone()).collect();
    missing.sort();
    missing.dedup();
    if !unmade.is_empty() {
        let shown = available(
            &format!("not regenerated, left as committed: {}", unmade.join("; ")),
            &missing,
            "`raytree postscript` draws the lecture's program; the SPD page renders ../shared/spd/",
        );
        assert!(!shown, "made nothing of {unmade:?}, yet it has {missing:?}");
    }
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        check::bless(&files);
        return;
    }
    let stale = check::stale(&files);
    assert!(
        stale.is_empty(),
        "the book is stale; regenerate it with `RAYTREE_BLESS=1 cargo test --release book` and read the diff:\n{}",
        stale.join("\n")
    );
}

/// `figure a.png, number x, number y` as `figure a.png, numbers x and y`.
fn grouped(parts: &[String]) -> String {
    let mut kinds: Vec<(&str, Vec<&str>)> = Vec::new();
    for part in parts {
        let (kind, name) = part.split_once(' ').unwrap_or(("", part));
        match kinds.iter_mut().find(|(k, _)| *k == kind) {
            Some((_, names)) => names.push(name),
            None => kinds.push((kind, vec![name])),
        }
    }
    let and = |names: &[&str]| match names {
        [one] => (*one).to_owned(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
        [] => String::new(),
    };
    kinds
        .iter()
        .map(|(kind, names)| {
            let s = if names.len() > 1 { "s" } else { "" };
            format!("{kind}{s} {}", and(names))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

#[test]
fn every_lesson_loads_and_its_step_through_narrates() {
    let dir = run::root().join("lessons");
    let entries = lesson::list(&dir).unwrap_or_else(|e| panic!("{e}"));
    assert!(!entries.is_empty(), "no lessons in lessons/");
    for e in &entries {
        let loaded = lesson::load(&dir, e.number).unwrap_or_else(|e| panic!("{e}"));
        let walk = lesson::step_through(&loaded).unwrap_or_else(|e| panic!("{e}"));
        assert!(!walk.stops.is_empty(), "{}: no stops", e.name);
        for stop in &walk.stops {
            assert!(
                !stop.say.contains('{') && !stop.headline.is_empty(),
                "{}: step {} narrates {:?}",
                e.name,
                stop.step,
                stop.say
            );
        }
    }
}

fn raytree(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(run::root())
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn raytree_lesson_lists_the_lessons_and_steps_through_one() {
    let (ok, list, _) = raytree(&["lesson"]);
    assert!(ok);
    assert!(
        list.contains("lessons 3 to 11 end with Build it yourself"),
        "{list}"
    );
    let entries = lesson::list(&run::root().join("lessons")).unwrap();
    for e in &entries {
        let line = list
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{} ", e.number)));
        let line = line.unwrap_or_else(|| panic!("no line for lesson {}:\n{list}", e.number));
        assert!(
            line.contains(e.title()) && line.contains(e.summary()),
            "{line}"
        );
    }
    let (ok, text, _) = raytree(&["lesson", "3"]);
    assert!(ok);
    assert!(
        text.starts_with("Lesson 3: The camera and the image plane\n"),
        "{text}"
    );
    assert!(text.contains("\nstep 1 · camera: pixel "), "{text}");
    // Lessons 03–11 end with their Build-it-yourself part; 12 has none.
    assert!(
        text.contains(
            "\nBuild it yourself: write image_plane_point in lessons/python/starter/tracer.py"
        ) && text.contains("python3 lessons/python/starter/tracer.py test 03")
            && text.contains("raytree check SCENE --pixel X,Y mine.json"),
        "{text}"
    );
    let (ok, text, _) = raytree(&["lesson", "11", "--text"]);
    assert!(ok && text.contains("write combine, raytrace in"), "{text}");
    let (ok, text, _) = raytree(&["lesson", "12", "--text"]);
    assert!(ok && !text.contains("Build it yourself"), "{text}");

    let (ok, _, err) = raytree(&["lesson", "99"]);
    assert!(!ok);
    let numbers: Vec<String> = entries.iter().map(|e| e.number.to_string()).collect();
    let want = format!(
        "error: lessons: no lesson 99 (there are: {}) (see raytree lesson --help)\n",
        numbers.join(", ")
    );
    assert_eq!(err, want);
    let (ok, _, err) = raytree(&["lesson", "--lessons", "no/such/dir"]);
    assert!(!ok && err.contains("no/such/dir: no such folder"), "{err}");
}

/// The least a lesson's spec holds: a title, a summary and its frame.
const FRAME: &str = "title = \"Light\"\nsummary = \"the light\"\nobjectives = [\"see\", \"shade\"]\n\
                     minutes = { reading = 10, exercises = 5 }\n";

#[test]
fn a_broken_lesson_is_one_line_naming_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let lesson = dir.path().join("07-light");
    std::fs::create_dir(&lesson).unwrap();
    std::fs::write(
        lesson.join("lesson.toml"),
        format!("{FRAME}[number]\nx = {{ run = \"nope\", json = \"/a\" }}\n"),
    )
    .unwrap();
    let dir_arg = dir.path().display().to_string();
    let (ok, _, err) = raytree(&["lesson", "--lessons", &dir_arg]);
    assert!(!ok);
    assert!(
        err.contains("07-light/lesson.toml: line 6: number x: no run 'nope'"),
        "{err}"
    );
    std::fs::write(lesson.join("lesson.toml"), FRAME).unwrap();
    std::fs::write(
        lesson.join("steps.toml"),
        "scene = \"x.json\"\npixel = [1, 2]\n[[stop]]\nstep = 1\nsay = \"{nope}\"\n",
    )
    .unwrap();
    let (ok, _, err) = raytree(&["lesson", "--lessons", &dir_arg, "7"]);
    assert!(
        !ok && err.contains("x.json") && err.contains("steps.toml"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
}

/// `raytree lesson N` refuses, before it shows anything, a number the book
/// could not make: it once opened a lesson whose numbers named a step's
/// value it lacks, a step past the trace, or a pixel off the image, and only
/// the book's build found out.
#[test]
fn raytree_lesson_refuses_a_number_the_book_could_not_make() {
    let dir = tempfile::tempdir().unwrap();
    let lesson = dir.path().join("07-light");
    std::fs::create_dir(&lesson).unwrap();
    let scene = run::root().join("scenes/whitted.json");
    let scene = scene.display();
    std::fs::write(
        lesson.join("steps.toml"),
        format!(
            "scene = \"{scene}\"\npixel = [300, 250]\n[[stop]]\nstep = 1\nsay = \"c = {{c}}\"\n"
        ),
    )
    .unwrap();
    let dir_arg = dir.path().display().to_string();
    let cases = [
        ("--pixel 300,250", "step = 7, value = \"t\"", None),
        (
            "--pixel 300,250",
            "step = 7, value = \"tt\"",
            Some("lesson.toml: line 8: number n: step 7 has no tt; it has "),
        ),
        (
            "--pixel 300,250",
            "step = 700, value = \"t\"",
            Some("lesson.toml: line 8: number n: step 700 is past the trace's "),
        ),
        (
            "--pixel 300,2500",
            "step = 7, value = \"t\"",
            Some("lesson.toml: line 5: run p: `raytree trace"),
        ),
        (
            "--pixel 300,250",
            "json = \"/no/such\"",
            Some("lesson.toml: line 8: number n: the trace has no /no/such"),
        ),
    ];
    for (pixel, source, want) in cases {
        std::fs::write(
            lesson.join("lesson.toml"),
            format!(
                "{FRAME}[run.p]\ncommand = \"raytree trace {scene} {pixel}\"\n\
                 [number]\nn = {{ run = \"p\", {source} }}\n"
            ),
        )
        .unwrap();
        let (ok, text, err) = raytree(&["lesson", "--lessons", &dir_arg, "7", "--text"]);
        match want {
            None => assert!(ok && text.contains("c = "), "{err}"),
            Some(want) => {
                assert!(!ok && err.contains(want), "{pixel} {source}: {err}");
                assert_eq!(err.lines().count(), 1, "{err}");
            }
        }
    }
    // A figure's misspelt flag is refused too, before the book would draw it.
    std::fs::write(
        lesson.join("lesson.toml"),
        format!(
            "{FRAME}[figure.f]\ncommand = \"raytree diagram {scene} --pixel 1,2 --sise 9x9\"\n\
             caption = \"F.\"\n"
        ),
    )
    .unwrap();
    let (ok, _, err) = raytree(&["lesson", "--lessons", &dir_arg, "7", "--text"]);
    assert!(
        !ok && err.contains("lesson.toml: line 5: figure f: `raytree diagram")
            && err.contains("unexpected argument '--sise'"),
        "{err}"
    );
}

/// A folder that is not a lesson (a teacher's `drafts/`, notes) is passed
/// over, so it breaks no lesson; one named as a lesson but misnumbered is
/// still refused, naming it.
#[test]
fn a_folder_that_is_no_lesson_is_passed_over() {
    let dir = tempfile::tempdir().unwrap();
    let lesson = dir.path().join("07-light");
    std::fs::create_dir(&lesson).unwrap();
    std::fs::write(lesson.join("lesson.toml"), FRAME).unwrap();
    std::fs::create_dir(dir.path().join("drafts")).unwrap();
    std::fs::create_dir(dir.path().join(".cache")).unwrap();
    let dir_arg = dir.path().display().to_string();
    let (ok, list, err) = raytree(&["lesson", "--lessons", &dir_arg]);
    assert!(ok, "{err}");
    assert!(list.contains("Light") && !list.contains("drafts"), "{list}");
    std::fs::create_dir(dir.path().join("8-shadows")).unwrap();
    let (ok, _, err) = raytree(&["lesson", "--lessons", &dir_arg]);
    assert!(
        !ok && err.contains("8-shadows: a lesson folder is NN-topic"),
        "{err}"
    );
}

/// A player is the page's heaviest part: each stays within 300 KB (the
/// diagram's SVG is most of it), so a chapter opens quickly on a slow line.
#[test]
fn every_player_stays_within_300_kb() {
    let entries = lesson::list(&run::root().join("lessons")).unwrap();
    assert!(!entries.is_empty());
    for e in &entries {
        let path = run::root().join(format!("book/src/lessons/{}/player.js", e.name));
        let size = std::fs::metadata(&path)
            .unwrap_or_else(|err| panic!("{}: {err}", path.display()))
            .len();
        assert!(
            size <= 300 * 1024,
            "{}: {size} bytes, over 300 KB",
            path.display()
        );
    }
}

/// Every lesson's chapter reads the same way round: its step-through under
/// "Step through it" and its exercises under "Exercises", each heading just
/// above what it heads (lesson 14 once had neither); and no figure is shown
/// twice (an exercise refers back with `{{see NAME}}`, as lesson 10's once
/// embedded its figures again mid-sentence).
#[test]
fn every_chapter_heads_its_parts_and_shows_each_figure_once() {
    let dir = run::root().join("book/src/lessons");
    let mut chapters = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "md") {
            continue;
        }
        chapters += 1;
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.display();
        let steps = text.find("## Step through it\n\n");
        // The checked questions open the exercises, then exercise 1.
        let exercises = text
            .find("## Exercises\n\n")
            .filter(|&at| text[at..].contains("\n### Exercise 1\n"));
        assert!(steps.is_some(), "{name}: no \"## Step through it\" heading");
        assert!(
            exercises.is_some(),
            "{name}: no \"## Exercises\" heading above exercise 1"
        );
        assert!(
            steps < exercises,
            "{name}: the exercises come before the step-through"
        );
        let mut shown = std::collections::BTreeSet::new();
        for line in text.lines().filter(|l| l.starts_with("![")) {
            let file = line.rsplit('(').next().unwrap_or(line);
            assert!(shown.insert(file), "{name}: figure {file} is shown twice");
        }
    }
    let lessons = lesson::list(&run::root().join("lessons")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(chapters, lessons.len(), "a chapter per lesson");
}
