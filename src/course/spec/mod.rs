//! A lesson's spec file (`lesson.toml`, and a book page's `PAGE.toml`): the
//! raytree commands behind every figure, trace excerpt and number its text
//! quotes, and its exercises. The book is generated from it and a test checks
//! the book against fresh output, so nothing a learner reads is typed by hand.
//! `lessons/README.md` documents the format for writers.
//!
//! ```toml
//! title = "The camera and the image plane"
//! summary = "eye, u, v, n and the image plane; a pixel's (r, c) → (u_c, v_r) → P(r, c)"
//! objectives = ["…", "…"]                    # the frame: crate::course::spec::frame
//! minutes = { reading = 20, exercises = 15, build = 30 }
//!
//! [run.pixel]      # a raytree command; a `raytree trace` is run with --json
//! command = "raytree trace scenes/whitted.json --pixel 416,209"
//!
//! [figure.camera]  # a raytree command that writes a PNG (the book adds -o)
//! command = "raytree diagram scenes/whitted.json --pixel 416,209 --view camera"
//! caption = "The image plane face-on."
//!
//! [image.plain]    # a PNG that other commands read as plain.png, not shown
//! command = "raytree render scenes/whitted.json --width 160 --height 120"
//!
//! [excerpt.camera] # steps of a trace run (or lines of any other run)
//! run = "pixel"
//! steps = [1, 2]
//!
//! [number]         # quoted in the text as {{name}}
//! u_c = { run = "pixel", step = 1, value = "u_c" }   # a step-through name
//! eye = { run = "pixel", json = "/camera/eye" }      # any field of the trace
//! # from any other run: the word after (or before) a text of its output
//! shot = { run = "forward", after = "forward:" }
//! reached = { run = "forward", before = "reached a pixel" }
//!
//! [[exercise]]
//! task = "Change X; predict Y."
//! answer = "raytree says {{u_c}}."
//! ```

pub mod command; // a spec's command lines, and the images and figures each one reads
pub(crate) mod file; // a spec file's TOML as serde reads it
pub mod frame; // what a lesson lets a learner do, how long it takes, whether it is optional
pub mod question; // checked questions: predict a number, checked against raytree's own

use std::collections::BTreeMap;
use std::fmt::Display;
use std::ops::Range;
use std::path::Path;

use crate::course::number::Source;
use crate::course::spec::file::{ExcerptFile, SpecFile};
use crate::course::spec::frame::{Frame, FrameFile};
use crate::course::spec::question::Question;
use crate::course::teacher_file::{self, line_of};

pub use crate::course::spec::command::Command;
use crate::course::spec::command::command;

/// A spec file, read and checked: every name it refers to exists.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// The chapter's title (required of a lesson).
    pub title: Option<String>,
    /// One line on what it teaches (required of a lesson).
    pub summary: Option<String>,
    /// What a learner can do after it, how long it takes, whether it is optional.
    pub frame: Frame,
    /// Commands whose output numbers and excerpts come from, by name.
    pub runs: BTreeMap<String, Run>,
    /// Figures, by name (the file is `NAME.png`).
    pub figures: BTreeMap<String, Figure>,
    /// Images other commands read as `NAME.png`, by name: made, never shown.
    pub images: BTreeMap<String, Image>,
    /// Excerpts of runs' output, by name.
    pub excerpts: BTreeMap<String, Excerpt>,
    /// Numbers, by the name the text quotes them with.
    pub numbers: BTreeMap<String, Number>,
    /// Exercises, in order.
    pub exercises: Vec<Exercise>,
    /// Checked questions, in order.
    pub questions: Vec<Question>,
}

/// A command whose output the text quotes.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// The command.
    pub command: Command,
    /// Line of the spec file it is defined on.
    pub line: usize,
}

/// A figure: a command that writes a PNG, and what it shows.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// The command, without `-o`.
    pub command: Command,
    /// One or two sentences under the figure.
    pub caption: String,
    /// Line of the spec file.
    pub line: usize,
}

/// An image: a command that writes a PNG for other commands to read.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// The command, without `-o`.
    pub command: Command,
    /// Line of the spec file.
    pub line: usize,
}

/// Part of a run's output, shown as a code block.
#[derive(Clone, Debug, PartialEq)]
pub struct Excerpt {
    /// The run's name.
    pub run: String,
    /// First and last step (of a trace, as `raytree trace --steps` numbers
    /// them) or line (of any other run's output), 1-based; all when `None`.
    pub range: Option<(usize, usize)>,
    /// Line of the spec file.
    pub line: usize,
}

/// A number the text quotes.
#[derive(Clone, Debug, PartialEq)]
pub struct Number {
    /// The run's name.
    pub run: String,
    /// Where in its output.
    pub source: Source,
    /// Line of the spec file.
    pub line: usize,
}

/// "Change X and predict Y", with an answer raytree computes.
#[derive(Clone, Debug, PartialEq)]
pub struct Exercise {
    /// What to change and what to predict (Markdown).
    pub task: String,
    /// The answer (Markdown quoting numbers, figures or excerpts).
    pub answer: String,
    /// Line of the spec file.
    pub line: usize,
}

/// Words a text uses for its own directives, so no number may take them.
pub const RESERVED: &[&str] = &["figure", "see", "excerpt", "steps", "exercises"];

/// Reads a spec file. Errors are one line naming the file and line.
pub fn load(path: &Path) -> Result<Spec, String> {
    let text = teacher_file::read(path, "a spec")?;
    parse(path, &text)
}

/// Parses a spec's text (`path` names it in messages).
pub fn parse(path: &Path, text: &str) -> Result<Spec, String> {
    let file: SpecFile = teacher_file::parse(path, text)?;
    let at = Where { path, text };
    let frame = FrameFile {
        objectives: file.objectives.clone(),
        minutes: file.minutes.clone(),
        beyond_lecture: file.beyond_lecture,
    };
    let frame = frame::check(frame, text).map_err(|(l, e)| at.fail(l, e))?;
    check_names(&file).map_err(|e| format!("{}: {e}", path.display()))?;
    let runs = runs(&file, &at)?;
    let figures = figures(&file, &at)?;
    let images = images(&file, &figures, &at)?;
    let excerpts = excerpts(&file, &runs, &at)?;
    let numbers = numbers(&file, &runs, &at)?;
    let exercises = file
        .exercise
        .iter()
        .map(|e| Exercise {
            task: e.get_ref().task.trim().to_owned(),
            answer: e.get_ref().answer.trim().to_owned(),
            line: at.line(e.span()),
        })
        .collect();
    let questions =
        question::read(&file.question, &numbers, |s| at.line(s)).map_err(|(l, e)| at.fail(l, e))?;
    let mut spec = Spec {
        title: file.title,
        summary: file.summary,
        frame,
        runs,
        figures,
        images,
        excerpts,
        numbers,
        exercises,
        questions,
    };
    resolve_reads(&mut spec).map_err(|(l, e)| at.fail(l, e))?;
    Ok(spec)
}

/// The spec being read, to name a line of it in an error.
struct Where<'a> {
    path: &'a Path,
    text: &'a str,
}

impl Where<'_> {
    /// The line a table or field starts on.
    fn line(&self, span: Range<usize>) -> usize {
        line_of(self.text, span.start)
    }

    /// `PATH: line L: what`.
    fn fail(&self, line: usize, what: impl Display) -> String {
        format!("{}: line {line}: {what}", self.path.display())
    }
}

/// Every name of a run, figure, image, excerpt and number is one the text
/// can write between braces.
fn check_names(file: &SpecFile) -> Result<(), String> {
    for name in file
        .run
        .keys()
        .chain(file.figure.keys())
        .chain(file.image.keys())
        .chain(file.excerpt.keys())
    {
        check_name(name, false)?;
    }
    for name in file.number.keys() {
        check_name(name, true)?;
    }
    Ok(())
}

/// The `[run.NAME]` commands.
fn runs(file: &SpecFile, at: &Where) -> Result<BTreeMap<String, Run>, String> {
    let mut runs = BTreeMap::new();
    for (name, r) in &file.run {
        let l = at.line(r.span());
        let command = command(&r.get_ref().command, false)
            .map_err(|e| at.fail(l, format!("run {name}: {e}")))?;
        runs.insert(name.clone(), Run { command, line: l });
    }
    Ok(runs)
}

/// The `[figure.NAME]` commands and their captions.
fn figures(file: &SpecFile, at: &Where) -> Result<BTreeMap<String, Figure>, String> {
    let mut figures = BTreeMap::new();
    for (name, f) in &file.figure {
        let l = at.line(f.span());
        let command = command(&f.get_ref().command, true)
            .map_err(|e| at.fail(l, format!("figure {name}: {e}")))?;
        let caption = f.get_ref().caption.trim().to_owned();
        figures.insert(
            name.clone(),
            Figure {
                command,
                caption,
                line: l,
            },
        );
    }
    Ok(figures)
}

/// The `[image.NAME]` commands: no image takes a figure's name, since both
/// are read as `NAME.png`.
fn images(
    file: &SpecFile,
    figures: &BTreeMap<String, Figure>,
    at: &Where,
) -> Result<BTreeMap<String, Image>, String> {
    let mut images = BTreeMap::new();
    for (name, i) in &file.image {
        let l = at.line(i.span());
        if figures.contains_key(name) {
            return Err(at.fail(l, format!("image {name}: a figure has that name")));
        }
        let command = command(&i.get_ref().command, true)
            .map_err(|e| at.fail(l, format!("image {name}: {e}")))?;
        images.insert(name.clone(), Image { command, line: l });
    }
    Ok(images)
}

/// The run `what` (on line `l`) quotes; an error lists the runs there are.
fn run_of<'r>(
    runs: &'r BTreeMap<String, Run>,
    what: &str,
    run: &str,
    l: usize,
    at: &Where,
) -> Result<&'r Run, String> {
    runs.get(run).ok_or_else(|| {
        let have: Vec<&str> = runs.keys().map(String::as_str).collect();
        at.fail(
            l,
            format!("{what}: no run '{run}' (runs: {})", have.join(", ")),
        )
    })
}

/// The `[excerpt.NAME]` entries: a trace is cut by steps, any other run's
/// output by lines.
fn excerpts(
    file: &SpecFile,
    runs: &BTreeMap<String, Run>,
    at: &Where,
) -> Result<BTreeMap<String, Excerpt>, String> {
    let mut excerpts = BTreeMap::new();
    for (name, x) in &file.excerpt {
        let l = at.line(x.span());
        let x = x.get_ref();
        let run = run_of(runs, &format!("excerpt {name}"), &x.run, l, at)?;
        let range = excerpt_range(x, run.command.is_trace())
            .map_err(|e| at.fail(l, format!("excerpt {name}: {e}")))?;
        excerpts.insert(
            name.clone(),
            Excerpt {
                run: x.run.clone(),
                range,
                line: l,
            },
        );
    }
    Ok(excerpts)
}

/// An excerpt's steps (of a trace) or lines (of another run), counted from 1.
fn excerpt_range(x: &ExcerptFile, trace: bool) -> Result<Option<(usize, usize)>, String> {
    let range = match (trace, x.steps, x.lines) {
        (_, Some(_), Some(_)) => return Err("steps or lines, not both".to_owned()),
        (true, _, Some(_)) => return Err("a trace is cut by steps, not lines".to_owned()),
        (false, Some(_), _) => {
            return Err(format!(
                "only a trace has steps; cut run '{}' by lines",
                x.run
            ));
        }
        (_, s, ls) => s.or(ls),
    };
    match range {
        Some([a, b]) if a == 0 || b < a => Err(format!("[{a}, {b}] is not a range counted from 1")),
        r => Ok(r.map(|[a, b]| (a, b))),
    }
}

/// The `[number]` entries, each read from a run by where it stands there.
fn numbers(
    file: &SpecFile,
    runs: &BTreeMap<String, Run>,
    at: &Where,
) -> Result<BTreeMap<String, Number>, String> {
    let mut numbers = BTreeMap::new();
    for (name, n) in &file.number {
        let l = at.line(n.span());
        let n = n.get_ref();
        let run = run_of(runs, &format!("number {name}"), &n.run, l, at)?;
        let source = Source::from_file(n, run.command.is_trace())
            .map_err(|e| at.fail(l, format!("number {name}: {e}")))?;
        numbers.insert(
            name.clone(),
            Number {
                run: n.run.clone(),
                source,
                line: l,
            },
        );
    }
    Ok(numbers)
}

/// Names are what the text writes between braces and what files are called:
/// letters, digits, `_` and `-` (and `.` for numbers, as in `n_dot_l.key`).
fn check_name(name: &str, number: bool) -> Result<(), String> {
    let ok = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-' || (number && c == '.');
    if name.is_empty() || !name.chars().all(ok) {
        return Err(format!(
            "'{name}' is not a name: use letters, digits, _ and -"
        ));
    }
    if number && RESERVED.contains(&name) {
        return Err(format!(
            "'{name}' is a directive of the text; call the number something else"
        ));
    }
    Ok(())
}

/// Finds the files each command reads (an argument `NAME.png` naming an image
/// or a figure of the spec), and refuses a name that is neither, a command
/// that reads itself through others, and an image nothing reads.
fn resolve_reads(spec: &mut Spec) -> Result<(), (usize, String)> {
    let files: Vec<String> = spec
        .images
        .keys()
        .chain(spec.figures.keys())
        .cloned()
        .collect();
    let commands = spec
        .runs
        .iter_mut()
        .map(|(n, r)| (format!("run {n}"), r.line, &mut r.command))
        .chain(
            spec.figures
                .iter_mut()
                .map(|(n, f)| (format!("figure {n}"), f.line, &mut f.command)),
        )
        .chain(
            spec.images
                .iter_mut()
                .map(|(n, i)| (format!("image {n}"), i.line, &mut i.command)),
        );
    for (what, line, command) in commands {
        for arg in &command.args {
            let Some(name) = arg.strip_suffix(".png").filter(|n| !n.contains('/')) else {
                continue;
            };
            if !files.iter().any(|f| f == name) {
                return Err((
                    line,
                    format!("{what}: reads {arg}, but the spec makes no image or figure '{name}'"),
                ));
            }
            command.reads.push(name.to_owned());
        }
    }
    let reads = |name: &str| -> &[String] {
        spec.images
            .get(name)
            .map(|i| &i.command)
            .or(spec.figures.get(name).map(|f| &f.command))
            .map_or(&[], |c| &c.reads)
    };
    for name in &files {
        // Without a cycle, no chain of reads from `name` is longer than there are files.
        let mut frontier = vec![name.as_str()];
        for _ in 0..=files.len() {
            frontier = frontier
                .iter()
                .flat_map(|n| reads(n))
                .map(String::as_str)
                .collect();
            frontier.sort_unstable();
            frontier.dedup();
        }
        if !frontier.is_empty() {
            let line = spec
                .images
                .get(name)
                .map_or_else(|| spec.figures[name].line, |i| i.line);
            return Err((
                line,
                format!("{name} reads a file that is made from itself (a cycle of reads)"),
            ));
        }
    }
    for (name, image) in &spec.images {
        let read = spec
            .runs
            .values()
            .map(|r| &r.command)
            .chain(spec.figures.values().map(|f| &f.command))
            .chain(spec.images.values().map(|i| &i.command))
            .any(|c| c.reads.contains(name));
        if !read {
            return Err((
                image.line,
                format!("image {name} is read by no command (as {name}.png)"),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(text: &str) -> Result<Spec, String> {
        parse(Path::new("lessons/03-x/lesson.toml"), text)
    }

    #[test]
    fn a_spec_reads_with_every_kind_of_entry() {
        let s = spec(
            "title = \"T\"\n[run.p]\ncommand = \"raytree trace  scenes/w.json --pixel 1,2\"\n\
             [run.h]\ncommand = \"raytree --help\"\n\
             [figure.f]\ncommand = \"raytree diagram scenes/w.json --pixel 1,2\"\ncaption = \" A. \"\n\
             [excerpt.x]\nrun = \"p\"\nsteps = [1, 2]\n\
             [number]\nu = { run = \"p\", step = 1, value = \"u_c\" }\n\
             e = { run = \"p\", json = \"/camera/eye\" }\nv = { run = \"h\", after = \"Usage:\" }\n\
             w = { run = \"h\", before = \"Usage:\" }\n\
             [[exercise]]\ntask = \"t\"\nanswer = \"{{u}}\"\n",
        )
        .unwrap();
        assert_eq!(
            s.runs["p"].command.args,
            ["trace", "scenes/w.json", "--pixel", "1,2"]
        );
        assert_eq!(
            s.runs["p"].command.text,
            "raytree trace scenes/w.json --pixel 1,2"
        );
        assert!(s.runs["p"].command.is_trace() && !s.runs["h"].command.is_trace());
        assert!(s.figures["f"].command.writes_image() && !s.runs["p"].command.writes_image());
        assert_eq!(s.figures["f"].caption, "A.");
        assert_eq!(s.excerpts["x"].range, Some((1, 2)));
        assert_eq!(
            s.numbers["u"].source,
            Source::Step {
                step: 1,
                value: "u_c".into()
            }
        );
        assert_eq!(s.numbers["e"].source, Source::Json("/camera/eye".into()));
        assert_eq!(s.numbers["v"].source, Source::After("Usage:".into()));
        assert_eq!(s.numbers["w"].source, Source::Before("Usage:".into()));
        assert_eq!(s.numbers["u"].line, 13);
        assert_eq!(s.exercises[0].line, 17);
    }

    #[test]
    fn bad_specs_are_one_line_naming_file_and_line() {
        let run = "[run.p]\ncommand = \"raytree trace a.json --pixel 1,2\"\n";
        let cases = [
            (
                "titel = 1\n",
                "lessons/03-x/lesson.toml: line 1: unknown field `titel`",
            ),
            (
                &format!("{run}[number]\nu = {{ run = \"q\", step = 1, value = \"u_c\" }}\n"),
                "line 4: number u: no run 'q' (runs: p)",
            ),
            (
                &format!("{run}[number]\nu = {{ run = \"p\", after = \"x\" }}\n"),
                "line 4: number u: a trace's number is step + value, or json",
            ),
            (
                &format!("{run}[number]\nsteps = {{ run = \"p\", json = \"/x\" }}\n"),
                "'steps' is a directive",
            ),
            (
                "[run.h]\ncommand = \"raytree forward\"\n[number]\nu = { run = \"h\", after = \"a\", before = \"b\" }\n",
                "line 4: number u: a number from a run other than a trace is after",
            ),
            (
                &format!("{run}[excerpt.x]\nrun = \"p\"\nlines = [1, 2]\n"),
                "line 3: excerpt x: a trace is cut by steps",
            ),
            (
                &format!("{run}[excerpt.x]\nrun = \"p\"\nsteps = [3, 2]\n"),
                "[3, 2] is not a range",
            ),
            (
                "[run.p]\ncommand = \"cargo run\"\n",
                "line 1: run p: 'cargo run' does not start with raytree",
            ),
            (
                "[run.p]\ncommand = \"raytree trace a.json --pixel 1,2 --json\"\n",
                "leave out --json",
            ),
            (
                "[figure.f]\ncommand = \"raytree diagram a.json -o x.png\"\ncaption = \"\"\n",
                "leave out -o",
            ),
            (
                "[figure.f]\ncommand = \"raytree diagram 'a b.json'\"\ncaption = \"\"\n",
                "plain words only",
            ),
            (
                "[figure.\"a b\"]\ncommand = \"raytree diagram\"\ncaption = \"\"\n",
                "'a b' is not a name",
            ),
            (
                "[run.d]\ncommand = \"raytree diff a.png b.png\"\n",
                "line 1: run d: reads a.png, but the spec makes no image or figure 'a'",
            ),
            (
                "[image.a]\ncommand = \"raytree diff b.png c.png\"\n[image.b]\ncommand = \"raytree diff a.png c.png\"\n\
                 [image.c]\ncommand = \"raytree render\"\n",
                "line 1: a reads a file that is made from itself",
            ),
            (
                "[image.a]\ncommand = \"raytree render\"\n",
                "line 1: image a is read by no command (as a.png)",
            ),
        ];
        for (text, want) in cases {
            let e = spec(text).unwrap_err();
            assert!(e.contains(want), "{e:?} should contain {want:?}");
            assert!(!e.contains('\n'), "{e:?} is more than one line");
        }
    }
}
