//! `raytree lesson`: the lessons, and one lesson's guided step-through, in
//! the inspector when standard output is a terminal, else as text.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow};
use raytree::course::learner::vectors;
use raytree::course::{lesson, number};
use raytree::inspector::{self, App};
use raytree::tree::document::TraceDocument;

use crate::args::usage;
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    /// The lesson to step through (its number); without one, list the lessons.
    #[arg(value_name = "N")]
    number: Option<u32>,
    /// The folder holding the lessons (run from the repository, it is ./lessons).
    #[arg(long, value_name = "DIR", default_value = "lessons")]
    lessons: PathBuf,
    /// Print the step-through as text instead of opening it in the inspector.
    #[arg(long)]
    text: bool,
}

/// How the binary reads a spec's command lines (the words after `raytree`),
/// handed in by `main.rs`, whose grammar holds every command, this one too:
/// so this file never names the crate's root and no import runs in a circle.
pub struct SpecCommands {
    /// Whether the words parse as the command line a learner would type.
    pub check: fn(&[String]) -> Result<(), String>,
    /// The trace document a `raytree trace …` run records, its paths relative to the folder given.
    pub trace: fn(&[String], &Path) -> Result<TraceDocument>,
}

pub fn run(args: &Args, commands: &SpecCommands) -> Result<()> {
    let entries = lessons_in(&args.lessons, "lesson")?;
    let text = match args.number {
        None => {
            format!(
                "{}\n`raytree lesson N` steps through lesson N; the book (book/) has their text; lessons 3 to 11 end with Build it yourself:\nwrite their functions in the Python tracer of lessons/python/ and check it with `raytree check`.\n",
                lesson::list_text(&entries).trim_end()
            )
        }
        Some(n) => {
            held(&args.lessons, &entries, n)?;
            let loaded = lesson::load(&args.lessons, n).map_err(anyhow::Error::msg)?;
            makeable(&loaded.entry, &args.lessons, commands)?;
            let walk = lesson::step_through(&loaded).map_err(anyhow::Error::msg)?;
            if !args.text && output::stdout_is_terminal() {
                return guided(loaded);
            }
            let mut text = lesson::step_through_text(&loaded, &walk);
            if let Some(build) = vectors::build_it_yourself(n) {
                text = format!("{text}\n{build}\n");
            }
            text
        }
    };
    output::print(text)?;
    Ok(())
}

/// The lessons of `dir`, the folder `--lessons` names (`command` is the
/// command that reads it). A name that is no folder, or a folder that holds
/// no lesson, is a usage error; a lesson folder that cannot be read is not.
pub fn lessons_in(dir: &Path, command: &str) -> Result<Vec<lesson::Entry>> {
    let fix = format!("run raytree {command} from the repository, or give --lessons DIR");
    if !dir.exists() {
        return Err(usage(format_args!(
            "{}: no such folder; {fix}",
            dir.display()
        )));
    }
    if !dir.is_dir() {
        return Err(usage(format_args!(
            "{}: not a folder; {fix}",
            dir.display()
        )));
    }
    let entries = lesson::list(dir).map_err(anyhow::Error::msg)?;
    if entries.is_empty() {
        return Err(usage(format_args!(
            "{}: {}; {fix}",
            dir.display(),
            lesson::lessons_held(&entries)
        )));
    }
    Ok(entries)
}

/// Refuses lesson `n` when `entries`, the lessons of `dir`, do not hold it:
/// a usage error.
pub fn held(dir: &Path, entries: &[lesson::Entry], n: u32) -> Result<()> {
    if entries.iter().any(|e| e.number == n) {
        return Ok(());
    }
    Err(usage(format_args!(
        "{}: no lesson {n} ({})",
        dir.display(),
        lesson::lessons_held(entries)
    )))
}

/// Refuses, before the lesson opens, what the book could not make: a run,
/// figure or image whose command raytree's grammar refuses (a misspelt
/// flag), and a number read from a trace (`step` + `value`, or `json`)
/// whose run fails (a pixel off the image), whose step is past the trace's
/// or whose value the step lacks. Each such run is traced once, as `raytree
/// trace` would, typed in the folder holding `lessons` (the repository,
/// for its `lessons/`); the other commands run, and the questions are made,
/// only with the book.
fn makeable(entry: &lesson::Entry, lessons: &Path, read: &SpecCommands) -> Result<()> {
    // `--lessons .` or `..` has no parent to name: its `..` is.
    let root = match (lessons.file_name(), lessons.parent()) {
        (Some(_), Some(parent)) => parent.to_owned(),
        _ => lessons.join(".."),
    };
    let spec = entry.folder.join(lesson::SPEC);
    let s = &entry.spec;
    let commands = (s.runs.iter().map(|(n, r)| ("run", n, r.line, &r.command)))
        .chain(
            s.figures
                .iter()
                .map(|(n, f)| ("figure", n, f.line, &f.command)),
        )
        .chain(
            s.images
                .iter()
                .map(|(n, i)| ("image", n, i.line, &i.command)),
        );
    for (what, name, line, command) in commands {
        (read.check)(&command.args).map_err(|e| {
            anyhow!(
                "{}: line {line}: {what} {name}: `{}`: {e}",
                spec.display(),
                command.text
            )
        })?;
    }
    let mut traces: BTreeMap<&str, TraceDocument> = BTreeMap::new();
    for (name, number) in &entry.spec.numbers {
        let run = &entry.spec.runs[&number.run];
        if !run.command.is_trace() {
            continue;
        }
        if !traces.contains_key(number.run.as_str()) {
            let doc = (read.trace)(&run.command.args, &root).map_err(|e| {
                anyhow!(
                    "{}: line {}: run {}: `{}`: {e:#}",
                    spec.display(),
                    run.line,
                    number.run,
                    run.command.text
                )
            })?;
            traces.insert(&number.run, doc);
        }
        number::from_trace(&number.source, &traces[number.run.as_str()]).map_err(|e| {
            anyhow!(
                "{}: line {}: number {name}: {e}",
                spec.display(),
                number.line
            )
        })?;
    }
    Ok(())
}

/// Opens the lesson's step-through in the inspector, at its first stop.
fn guided(loaded: lesson::Lesson) -> Result<()> {
    let [x, y] = loaded.script.pixel;
    // The frame's time and objectives head the text; the inspector's one
    // status line has room for the time (the objectives are in the book).
    let frame = &loaded.entry.spec.frame;
    let opening = format!(
        "Lesson {}: {}{} · n/p: next/previous stop",
        loaded.entry.number,
        frame.minutes.map_or(String::new(), |m| m.sentence()),
        if frame.beyond_lecture {
            " Beyond the lecture, optional."
        } else {
            ""
        }
    );
    let mut app = App::new(loaded.scene, loaded.source, Some((x, y)), true);
    app.follow(loaded.script).map_err(anyhow::Error::msg)?;
    let (truecolor, note) = inspector::color_support();
    match &note {
        Some(note) => app.set_message(note.clone()),
        None => app.set_message(opening),
    }
    app.set_colors(truecolor, note);
    inspector::run(app).map_err(|e| anyhow!("terminal error: {e}"))
}
