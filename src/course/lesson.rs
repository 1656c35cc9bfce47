//! The lessons: one folder per lecture topic, `lessons/NN-topic/`, holding the
//! text (`lesson.md`), its spec ([`crate::course::spec`]: the commands
//! behind its figures and numbers, its exercises) and a guided step-through
//! ([`crate::course::guide`], `steps.toml`). This module finds them, loads one
//! with its scene, and narrates its step-through against a fresh trace: what
//! `raytree lesson N` shows and the book prints.

use std::fmt::Write;
use std::path::{Component, Path, PathBuf};

use crate::course::guide::{self, Narration, Script};
use crate::course::spec::{self, Spec, frame};
use crate::scene::Scene;
use crate::scene::source::{self, SceneSource};
use crate::tree::document::TraceDocument;
use crate::tree::record;
use crate::views::text;

/// The spec file in a lesson's folder.
pub const SPEC: &str = "lesson.toml";
/// The text.
pub const TEXT: &str = "lesson.md";
/// The guided step-through.
pub const STEPS: &str = "steps.toml";

/// A lesson as the list shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Its number, the folder's `NN`.
    pub number: u32,
    /// The folder's name, `NN-topic`.
    pub name: String,
    /// The folder.
    pub folder: PathBuf,
    /// The spec, read and checked.
    pub spec: Spec,
}

impl Entry {
    /// The chapter's title.
    pub fn title(&self) -> &str {
        self.spec.title.as_deref().unwrap_or_default()
    }

    /// One line on what it teaches.
    pub fn summary(&self) -> &str {
        self.spec.summary.as_deref().unwrap_or_default()
    }
}

/// The number of a lesson folder's name (`03-camera` → 3).
fn number_of(name: &str) -> Option<u32> {
    let (nn, topic) = name.split_once('-')?;
    let topic_ok = !topic.is_empty()
        && topic
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-');
    (nn.len() == 2 && nn.chars().all(|c| c.is_ascii_digit()) && topic_ok)
        .then(|| nn.parse().ok())
        .flatten()
}

/// Every lesson under `dir`, by number. A folder that is not `NN-topic`, two
/// lessons with one number, or a spec without a title or summary is an error
/// naming it.
pub fn list(dir: &Path) -> Result<Vec<Entry>, String> {
    let at = dir.display();
    let read = std::fs::read_dir(dir).map_err(|e| format!("{at}: {e}"))?;
    let mut out: Vec<Entry> = Vec::new();
    for item in read {
        let item = item.map_err(|e| format!("{at}: {e}"))?;
        if !item.path().is_dir() {
            continue;
        }
        let name = item.file_name().to_string_lossy().into_owned();
        // Only a folder named as a lesson (two digits first) is one; a
        // teacher's drafts or notes beside the lessons are passed over.
        if !name.starts_with(|c: char| c.is_ascii_digit()) {
            continue;
        }
        let number = number_of(&name).ok_or_else(|| {
            format!(
                "{at}/{name}: a lesson folder is NN-topic (two digits, a dash, lowercase words)"
            )
        })?;
        let folder = item.path();
        let spec_path = folder.join(SPEC);
        let spec = spec::load(&spec_path)?;
        for (field, value) in [("title", &spec.title), ("summary", &spec.summary)] {
            if value
                .as_deref()
                .is_none_or(|v| v.trim().is_empty() || v.contains('\n'))
            {
                return Err(format!(
                    "{}: a lesson needs a one-line {field}",
                    spec_path.display()
                ));
            }
        }
        need_frame(&spec_path, &spec)?;
        out.push(Entry {
            number,
            name,
            folder,
            spec,
        });
    }
    out.sort_by_key(|e| e.number);
    if let Some(w) = out.windows(2).find(|w| w[0].number == w[1].number) {
        return Err(format!(
            "{at}: {} and {} have the same number",
            w[0].name, w[1].name
        ));
    }
    Ok(out)
}

/// A lesson says what a learner can do after it and how long it takes
/// (`crate::course::spec::frame`); a book page need not.
fn need_frame(spec_path: &Path, spec: &Spec) -> Result<(), String> {
    let at = spec_path.display();
    if spec.frame.objectives.is_empty() {
        return Err(format!(
            "{at}: a lesson needs objectives = [...]: 2 to 4 things a learner can do after it"
        ));
    }
    if spec.frame.minutes.is_none() {
        return Err(format!(
            "{at}: a lesson needs minutes = {{ reading = R, exercises = E, build = B }}: how long it takes"
        ));
    }
    Ok(())
}

/// The list as `raytree lesson` prints it: number, title, minutes and
/// summary, a line each; a lesson beyond the lecture says it is optional.
pub fn list_text(entries: &[Entry]) -> String {
    let width = entries
        .iter()
        .map(|e| e.title().chars().count())
        .max()
        .unwrap_or(0);
    let mut out = String::new();
    for e in entries {
        let minutes = e.spec.frame.minutes.map_or(0, |m| m.total());
        let optional = if e.spec.frame.beyond_lecture {
            "beyond the lecture, optional: "
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "{:>3}  {:<width$}  {minutes:>3} min  {optional}{}",
            e.number,
            e.title(),
            e.summary()
        );
    }
    out
}

/// A lesson ready to step through: its spec, its script and the script's scene.
#[derive(Clone, Debug)]
pub struct Lesson {
    /// The lesson.
    pub entry: Entry,
    /// The step-through, read and checked.
    pub script: Script,
    /// The scene the script follows.
    pub scene: Scene,
    /// What names the scene in a trace.
    pub source: SceneSource,
}

/// Loads lesson `number` from `dir`: its spec, its step-through script and the
/// script's scene, each checked. Errors are one line naming the file (and the
/// line where there is one).
pub fn load(dir: &Path, number: u32) -> Result<Lesson, String> {
    let entries = list(dir)?;
    let Some(entry) = entries.iter().find(|e| e.number == number).cloned() else {
        return Err(format!(
            "{}: no lesson {number} ({})",
            dir.display(),
            lessons_held(&entries)
        ));
    };
    let mut script = guide::load(&entry.folder.join(STEPS))?;
    script.scene = tidy(&script.scene);
    let (scene, source) = source::load(Some(&script.scene))
        .map_err(|e| format!("{e} (the scene of {})", script.path.display()))?;
    script.fits(&scene.settings)?;
    Ok(Lesson {
        entry,
        script,
        scene,
        source,
    })
}

/// Which lessons a folder holds, in words: "there are: 1, 2, 3", or that it
/// holds none.
pub fn lessons_held(entries: &[Entry]) -> String {
    if entries.is_empty() {
        return "the folder holds no lessons: a lesson is a folder NN-topic with a lesson.toml"
            .to_owned();
    }
    let have: Vec<String> = entries.iter().map(|e| e.number.to_string()).collect();
    format!("there are: {}", have.join(", "))
}

/// `a/b/../c` → `a/c`, without asking the file system, so traces name a lesson's
/// scene as a learner would type it from the repository (`scenes/whitted.json`).
fn tidy(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(out.components().next_back(), Some(Component::Normal(_))) =>
            {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// One stop of a step-through as told: the step's headline as the trace
/// prints it, and the script's sentence with its numbers filled in.
#[derive(Clone, Debug, PartialEq)]
pub struct NarratedStop {
    /// The step, 1-based.
    pub step: usize,
    /// The step's first line in `raytree trace --steps`.
    pub headline: String,
    /// The sentence.
    pub say: String,
}

/// The step-through made concrete: the pixel's trace and each stop.
#[derive(Clone, Debug)]
pub struct StepThrough {
    /// The trace the stops quote.
    pub trace: TraceDocument,
    /// How many steps the traced sample has.
    pub steps: usize,
    /// The stops, in order.
    pub stops: Vec<NarratedStop>,
}

/// Traces the script's pixel and fills in its stops.
pub fn step_through(lesson: &Lesson) -> Result<StepThrough, String> {
    let [x, y] = lesson.script.pixel;
    let trace = record::pixel(&lesson.scene, lesson.source.clone(), x, y, None)
        .map_err(|e| format!("{}: {e}", lesson.script.path.display()))?;
    let told: Vec<Narration> = guide::narrate(&lesson.script, &trace)?;
    let steps = trace.steps(lesson.script.sample);
    let stops = told
        .into_iter()
        .map(|n| NarratedStop {
            step: n.step + 1,
            headline: text::describe(&trace, lesson.script.sample, &steps[n.step]).0,
            say: n.text,
        })
        .collect();
    Ok(StepThrough {
        steps: steps.len(),
        trace,
        stops,
    })
}

/// The step-through as text, as `raytree lesson N` prints it.
pub fn step_through_text(lesson: &Lesson, walk: &StepThrough) -> String {
    let [x, y] = lesson.script.pixel;
    let scene = lesson.script.scene.display();
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Lesson {}: {}",
        lesson.entry.number,
        lesson.entry.title()
    );
    out.push_str(&frame::text(&lesson.entry.spec.frame));
    out.push('\n');
    let what = lesson.script.title.as_deref().unwrap_or("Step-through");
    let _ = writeln!(
        out,
        "{what}: pixel {x},{y} of {scene}, {} steps; walk them all with `raytree inspect {scene} --pixel {x},{y}`",
        walk.steps
    );
    for stop in &walk.stops {
        let _ = write!(
            out,
            "\nstep {} · {}\n    {}\n",
            stop.step, stop.headline, stop.say
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lesson_folders_are_numbered_topics() {
        assert_eq!(number_of("03-camera"), Some(3));
        assert_eq!(number_of("14-postscript-twin"), Some(14));
        for bad in ["3-camera", "03", "03-", "03-Camera", "x3-camera", "003-a"] {
            assert_eq!(number_of(bad), None, "{bad}");
        }
    }

    #[test]
    fn paths_are_tidied_as_written() {
        let p = tidy(Path::new("lessons/03-camera/../../scenes/whitted.json"));
        assert_eq!(p, Path::new("scenes/whitted.json"));
        assert_eq!(tidy(Path::new("../a/./b")), Path::new("../a/b"));
    }
}
