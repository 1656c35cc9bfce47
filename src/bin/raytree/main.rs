//! The `raytree` command line: parse, dispatch to the command's file, report.
//! Each command lives in a file of its own; the argument groups they share
//! (and the worker threads) are in `args.rs`; everything printed and every
//! file written goes through `output.rs`, the one door out (which the lint
//! below keeps the only one); what a signal ends is in `signals.rs`.

// `print!` and `eprint!` panic on a closed pipe: write through `output` instead.
#![deny(clippy::print_stdout, clippy::print_stderr)]

mod aov;
mod args;
mod chart;
mod check;
mod convert;
mod diagram;
mod diff;
mod forward;
mod generate;
mod inspect;
mod lesson;
mod lobe;
mod memory;
mod output;
mod postscript;
mod render;
mod signals;
mod strip;
mod structures;
mod trace;
mod vectors;

use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use raytree::scene::strict::printable;
use raytree::tree::document::TraceDocument;

/// A Whitted-style ray tracer that shows its work.
#[derive(Parser)]
#[command(name = "raytree", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene to a PNG or PPM image on all cores.
    Render(render::Args),
    /// Trace one pixel (or one ray) and print every ray it spawns, with every number.
    Trace(trace::Args),
    /// Draw one pixel's (or one ray's) ray tree over the scene as a 2D figure (PNG, or SVG by the name).
    Diagram(diagram::Args),
    /// Explore a scene in the terminal: pick a pixel, walk its ray tree step by step.
    Inspect(inspect::Args),
    /// Chart speed against accuracy over a sweep of settings and methods (a PNG; with --csv FILE also the raw figures), rendered at half the scene's width and height unless --width/--height are given.
    Chart(chart::Args),
    /// Compare the efficiency slide's structures (none, bvh, grid, octree, bsp) on scenes: tests per ray and trace time on one thread, as a table and a chart (PNG), and with --csv FILE the raw figures; or the grid at a sweep of resolutions.
    Structures(structures::Args),
    /// Render one frame per value of a setting or a scene field, side by side, with how much each changed (PNG).
    Strip(strip::Args),
    /// Plot Phong's highlight, (R·V)^shininess against the angle between the mirror direction and the eye, for a few exponents (PNG), and print where each falls to a half.
    Lobe(lobe::Args),
    /// Trace rays forward from the lights and count how few reach the eye, beside the backward render (PNG).
    Forward(forward::Args),
    /// List the lessons, or open lesson N's guided step-through (the trace's own numbers, stop by stop).
    Lesson(lesson::Args),
    /// Compare two images (PNG or PPM): mean and largest difference in 8-bit levels; with -o, a figure of where they differ. Exit status 0 if they are the same (within --tolerance), 1 if they differ, 2 on trouble.
    Diff(diff::Args),
    /// Draw the lecture's PostScript ray tracer with Ghostscript (PNG), its transcription slips repaired.
    Postscript(postscript::Args),
    /// Check a learner's own ray tracer against raytree, ray by ray: `raytree check SCENE --pixel X,Y LEARNER.json` names the first number that differs, where, and the classic mistake behind it. Exit status 0 all agree, 1 a divergence, 2 bad input.
    Check(check::Args),
    /// Write a generated scene file: random spheres, a grid of spheres, or an icosphere mesh.
    Generate(generate::Args),
    /// Write an NFF scene (Haines's Standard Procedural Databases) as a raytree scene JSON file: the same scene render draws from the .nff, in the form you can read and edit.
    Convert(convert::Args),
    /// Write test vectors for your own tracer: lesson N's functions (3 to 11) with inputs and raytree's outputs, as JSON any language's tests can load.
    Vectors(vectors::Args),
}

fn main() -> ExitCode {
    let cli = match grammar()
        .try_get_matches()
        .and_then(|m| Cli::from_arg_matches(&m))
    {
        Ok(cli) => cli,
        Err(e) => return usage_error(&e),
    };
    signals::clean_up_on_signals();
    let result = match cli.command {
        Command::Render(args) => match &args.aov {
            Some(name) => aov::run(&args, name),
            None => render::run(&args),
        },
        Command::Trace(args) => trace::run(&args),
        Command::Diagram(args) => diagram::run(&args),
        Command::Inspect(args) => inspect::run(&args),
        Command::Chart(args) => chart::run(&args),
        Command::Structures(args) => structures::run(&args),
        Command::Strip(args) => strip::run(&args),
        Command::Forward(args) => forward::run(&args),
        Command::Lobe(args) => lobe::run(&args),
        Command::Lesson(args) => lesson::run(&args, &SPEC_COMMANDS),
        // Its exit status is its answer (1: the images differ), so its
        // errors are 2, as cmp's and diff's are.
        Command::Diff(args) => {
            return diff::run(&args)
                .unwrap_or_else(|e| finish_or(Err(e), ExitCode::from(diff::TROUBLE)));
        }
        // Its exit status is its answer (1: a divergence), so bad input is 2.
        Command::Check(args) => {
            return check::run(&args)
                .unwrap_or_else(|e| finish_or(Err(e), ExitCode::from(diff::TROUBLE)));
        }
        Command::Postscript(args) => postscript::run(&args),
        Command::Generate(args) => generate::run(&args),
        Command::Convert(args) => convert::run(&args),
        Command::Vectors(args) => vectors::run(&args),
    };
    finish(result)
}

/// The exit code of a command's result, its error reported in one line. A
/// closed pipe anywhere (`raytree trace … | head`) is no failure: the reader
/// has what it wanted, so the program ends quietly with exit 0.
fn finish(result: anyhow::Result<()>) -> ExitCode {
    finish_or(result, ExitCode::FAILURE)
}

/// [`finish`], with `failure` the exit code of an error. A refusal of the
/// command line itself ([`args::Usage`]) is reported as clap's are: ending
/// with the `--help` to read, exit code 2.
fn finish_or(result: anyhow::Result<()>, failure: ExitCode) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if output::closed_pipe(&e) => ExitCode::SUCCESS,
        Err(e) if args::is_usage(&e) => {
            output::last_word(&format!(
                "error: {} (see {} --help)",
                printable(&format!("{e:#}")),
                command_words()
            ));
            ExitCode::from(USAGE)
        }
        Err(e) => {
            output::last_word(&format!("error: {}", printable(&format!("{e:#}"))));
            failure
        }
    }
}

/// Exit code 2: the command line is at fault.
const USAGE: u8 = 2;

/// The command line's grammar, where an option's value may be a negative
/// number (`--pupil -1` is then refused for its value, not taken for a flag).
fn grammar() -> clap::Command {
    fn negative_numbers(command: clap::Command) -> clap::Command {
        command
            .mut_args(|a| {
                if a.get_action().takes_values() {
                    a.allow_negative_numbers(true)
                } else {
                    a
                }
            })
            .mut_subcommands(negative_numbers)
    }
    negative_numbers(Cli::command())
}

/// A malformed command line: clap's message as one line, with where to look,
/// and exit code 2. Help and the version print as clap prints them.
fn usage_error(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(
        e.kind(),
        ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        let printed = output::clap_text(e);
        if e.use_stderr() {
            // The help of a command line that names no command: a usage error.
            return ExitCode::from(USAGE);
        }
        return finish(printed.map_err(anyhow::Error::from));
    }
    output::last_word(&format!(
        "error: {} (see {} --help)",
        printable(&one_line(e)),
        command_words()
    ));
    ExitCode::from(USAGE)
}

/// clap's message in one line. It runs until its usage: the problem, then
/// what it names (missing arguments, possible values) and a tip, each on a
/// line of its own.
fn one_line(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let mut message = String::new();
    for line in text
        .lines()
        .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
        .map(str::trim)
        // The tip on passing a flag as a value after `--` never applies here.
        .filter(|l| !l.is_empty() && !l.starts_with("tip: to pass"))
    {
        let line = line.strip_prefix("error: ").unwrap_or(line);
        if !message.is_empty() {
            let joint = if message.ends_with(':') || line.starts_with('[') {
                " "
            } else {
                "; "
            };
            message.push_str(joint);
        }
        message.push_str(line);
    }
    message
}

/// A command line a lesson's spec writes (the words after `raytree`), read
/// by the grammar a learner's typing meets: `raytree lesson N` refuses one
/// that would fail, and traces a run's pixel as `raytree trace` would.
/// `None`: it asks for help or the version.
fn parse_words(args: &[String]) -> Result<Option<Command>, String> {
    use clap::error::ErrorKind;
    let words = std::iter::once("raytree").chain(args.iter().map(String::as_str));
    match grammar()
        .try_get_matches_from(words)
        .and_then(|m| Cli::from_arg_matches(&m))
    {
        Ok(cli) => Ok(Some(cli.command)),
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => {
            Ok(None)
        }
        Err(e) => Err(one_line(&e)),
    }
}

/// A spec's command lines read by this grammar, for `raytree lesson`.
const SPEC_COMMANDS: lesson::SpecCommands = lesson::SpecCommands {
    check: |words| parse_words(words).map(|_| ()),
    trace: spec_trace,
};

/// The trace document a spec's `raytree trace …` run records, its paths
/// relative to `root`.
fn spec_trace(words: &[String], root: &std::path::Path) -> anyhow::Result<TraceDocument> {
    let Some(Command::Trace(args)) = parse_words(words).map_err(anyhow::Error::msg)? else {
        return Err(anyhow::anyhow!("not a raytree trace"));
    };
    trace::document(args, root)
}

/// The subcommands named first on the command line, e.g. `raytree generate
/// grid`: whose `--help` a usage error points to.
fn command_words() -> String {
    let mut command = vec!["raytree".to_owned()];
    let mut level = grammar();
    for arg in std::env::args().skip(1) {
        let Some(sub) = level.find_subcommand(&arg).cloned() else {
            break;
        };
        command.push(arg);
        level = sub;
    }
    command.join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A spec's command is refused unless it names one of these; a command
    /// added to the grammar and not to the list would be refused too.
    #[test]
    fn the_course_knows_every_command() {
        let grammar = grammar();
        let names: Vec<&str> = grammar
            .get_subcommands()
            .map(clap::Command::get_name)
            .filter(|n| *n != "help")
            .collect();
        assert_eq!(names, raytree::course::spec::command::COMMANDS);
    }
}
