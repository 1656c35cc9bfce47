//! The whole book made from its sources: a chapter per lesson (`lessons/`),
//! the pages in `book/pages/` (text and spec, like a lesson's), the command
//! reference from the binary's own help, the scene format from
//! `scenes/README.md`, and the table of contents listing what exists.

use std::fmt::Write;
use std::path::Path;

use raytree::course::spec;
use raytree::course::spec::frame::{self, Frame};
use raytree::course::{lesson, player};

use super::page::{self, Input, Quoted};
use super::run;
use crate::tools::Need;

/// A file the book is made of.
pub struct File {
    /// Relative to the repository.
    pub path: String,
    /// What it holds.
    pub content: Content,
    /// What it is made from, for messages.
    pub origin: String,
    /// The numbers a chapter quotes.
    pub numbers: Vec<Quoted>,
    /// The blocks a chapter shows, named.
    pub blocks: Vec<(String, String)>,
    /// The parts of a chapter this machine could not make (each a
    /// [`page::HOLE`] in its text), and what it lacks for them.
    pub unmade: Vec<String>,
    pub missing: Vec<Need>,
}

pub enum Content {
    Text(String),
    Png(Vec<u8>),
    /// A figure this machine cannot draw: the committed one stays as it is.
    Unmade,
}

/// The folders the book's generation owns: every file in them is made by it.
pub const OWNED: &[&str] = &["book/src/lessons", "book/src/figures"];

/// The widest line (in characters) of the book's code blocks: wider, a trace
/// line runs off a phone's screen or a printed page. Longer lines are wrapped
/// with a hanging indent, as the inspector wraps them.
pub const CODE_WIDTH: usize = 90;

/// Book pages: `book/pages/NAME.md` and `NAME.toml`, made into `book/src/NAME.md`.
const PAGES: &[(&str, &str)] = &[("preface", "Preface: reading a trace and a diagram")];

/// Pages after the lessons, before the appendices: `book/pages/NAME.md`.
const AFTER: &[(&str, &str)] = &[("spd", "The Standard Procedural Databases")];

fn text(path: &str, text: String, origin: &str) -> File {
    File {
        path: path.to_owned(),
        content: Content::Text(text),
        origin: origin.to_owned(),
        numbers: Vec::new(),
        blocks: Vec::new(),
        unmade: Vec::new(),
        missing: Vec::new(),
    }
}

/// The line every generated page starts with.
fn generated_from(what: &str) -> String {
    format!(
        "<!-- Made from {what} by `RAYTREE_BLESS=1 cargo test --release book`: edit that, not this file. -->\n\n"
    )
}

/// Makes every file of the book.
pub fn book() -> Result<Vec<File>, String> {
    let scratch = tempfile::tempdir().map_err(|e| e.to_string())?;
    let mut files = Vec::new();
    let entries = lesson::list(&run::root().join("lessons"))?;
    for entry in &entries {
        let loaded = lesson::load(&run::root().join("lessons"), entry.number)?;
        let walk = lesson::step_through(&loaded)?;
        let folder = format!("lessons/{}", entry.name);
        let input = Input {
            text: &format!("{folder}/{}", lesson::TEXT),
            spec_path: &format!("{folder}/{}", lesson::SPEC),
            spec: &entry.spec,
            figures: &format!("{}/", entry.name),
            lesson: Some((entry.number, &walk)),
        };
        // Loaded again by the relative path, which the player's diagram and
        // title name the scene by (the tests run in the repository).
        let relative = lesson::load(Path::new("lessons"), entry.number)?;
        let player = lesson::step_through(&relative)
            .and_then(|walk| player::make(&relative, &walk))
            .and_then(|p| player::script(&p))?;
        files.push(text(
            &format!("book/src/lessons/{}/player.js", entry.name),
            player,
            &format!("{folder}/steps.toml"),
        ));
        let heading = format!(
            "# Lesson {}: {}\n\n{}",
            entry.number,
            entry.title(),
            frame(&entry.spec.frame)
        );
        chapter(
            &input,
            &format!("book/src/lessons/{}", entry.name),
            &heading,
            scratch.path(),
            &mut files,
        )?;
    }
    for (name, _) in PAGES.iter().chain(AFTER) {
        let spec_path = format!("book/pages/{name}.toml");
        let spec = spec::load(&run::root().join(&spec_path))?;
        let input = Input {
            text: &format!("book/pages/{name}.md"),
            spec_path: &spec_path,
            spec: &spec,
            figures: &format!("figures/{name}/"),
            lesson: None,
        };
        chapter(
            &input,
            &format!("book/src/{name}"),
            "",
            scratch.path(),
            &mut files,
        )?;
    }
    files.push(text(
        "book/src/commands.md",
        commands()?,
        "the binary's --help",
    ));
    files.push(text(
        "book/src/scene-format.md",
        scene_format()?,
        "scenes/README.md",
    ));
    files.push(text(
        "book/src/SUMMARY.md",
        summary(&entries),
        "the lessons and pages",
    ));
    Ok(files)
}

/// A lesson's frame under its heading: the note that it goes beyond the
/// lecture, what a learner can do after it, and how long it takes.
fn frame(frame: &Frame) -> String {
    let mut out = String::new();
    if frame.beyond_lecture {
        let _ = write!(out, "> {}\n\n", frame::BEYOND_LECTURE);
    }
    if !frame.objectives.is_empty() {
        out.push_str("**After this lesson you can**\n\n");
        for o in &frame.objectives {
            let _ = writeln!(out, "- {o}");
        }
        out.push('\n');
    }
    if let Some(m) = frame.minutes {
        let _ = write!(out, "*{}*\n\n", m.sentence());
    }
    out
}

/// A chapter `out.md` with its figures; `book/src/NAME` puts figures in
/// `book/src/figures/NAME/` and lessons' in `book/src/lessons/NAME/`.
fn chapter(
    input: &Input,
    out: &str,
    heading: &str,
    scratch: &Path,
    files: &mut Vec<File>,
) -> Result<(), String> {
    let made = page::make(input, scratch)?;
    let origin = format!("{} and {}", input.text, input.spec_path);
    let figure_dir = match out.strip_prefix("book/src/lessons/") {
        Some(_) => out.to_owned(),
        None => format!("book/src/figures/{}", out.trim_start_matches("book/src/")),
    };
    for (name, png, command) in made.figures {
        files.push(File {
            path: format!("{figure_dir}/{name}"),
            content: png.map_or(Content::Unmade, Content::Png),
            origin: format!("`{command}`"),
            numbers: Vec::new(),
            blocks: Vec::new(),
            unmade: Vec::new(),
            missing: Vec::new(),
        });
    }
    files.push(File {
        path: format!("{out}.md"),
        content: Content::Text(fit_code_blocks(&format!(
            "{}{heading}{}",
            generated_from(&origin),
            made.text.trim_start()
        ))),
        origin,
        numbers: made.numbers,
        blocks: made.blocks,
        unmade: made.unmade,
        missing: made.missing,
    });
    Ok(())
}

/// The command reference: `raytree --help` and each command's `--help`.
fn commands() -> Result<String, String> {
    let help = |args: &[&str]| -> Result<String, String> {
        let args: Vec<String> = args.iter().map(|a| a.to_string()).collect();
        Ok(String::from_utf8_lossy(&run::raytree(&args)?).into_owned())
    };
    let top = help(&["--help"])?;
    let mut out = generated_from("the binary's own `--help`");
    out.push_str(
        "# Commands\n\nEvery command and flag, as the binary you built explains them (`raytree --help`, \
         `raytree COMMAND --help`): this page is made from that help, so it cannot drift from the program.\n\n",
    );
    let _ = write!(out, "## raytree\n\n```text\n{}```\n", top);
    let names = crate::common::command_names(&top);
    if names.is_empty() {
        return Err("raytree --help lists no commands".to_owned());
    }
    for name in names {
        let _ = write!(
            out,
            "\n## raytree {name}\n\n```text\n{}```\n",
            help(&[name, "--help"])?
        );
    }
    Ok(fit_code_blocks(&out))
}

/// The scene format, from the file that documents it beside the scenes.
fn scene_format() -> Result<String, String> {
    let readme = std::fs::read_to_string(run::root().join("scenes/README.md"))
        .map_err(|e| format!("scenes/README.md: {e}"))?;
    Ok(fit_code_blocks(&format!(
        "{}{readme}",
        generated_from("`scenes/README.md`")
    )))
}

/// `markdown` with every line of its fenced code blocks wrapped at
/// [`CODE_WIDTH`] (`raytree::views::wrap`, the inspector's wrapping), so the
/// blocks a lesson's text or a readme writes fit as the excerpts do.
fn fit_code_blocks(markdown: &str) -> String {
    let mut out = String::new();
    let (mut inside, mut shell) = (false, false);
    for line in markdown.split_inclusive('\n') {
        let fence = ["```", "~~~"]
            .iter()
            .any(|f| line.trim_start().starts_with(f));
        if inside && !fence {
            // A command (a shell block's line, or a `$ ` line of an output
            // block) breaks with a backslash, so it still runs when copied.
            if shell || line.starts_with("$ ") {
                out.push_str(&wrap_command(line, CODE_WIDTH));
            } else {
                out.push_str(&raytree::views::wrap::text(line, CODE_WIDTH));
            }
        } else {
            out.push_str(line);
        }
        if fence {
            shell = !inside && line.trim_start()[3..].trim() == "sh";
        }
        inside ^= fence;
    }
    out
}

/// A command line broken between words into lines of at most `width`
/// characters, each but the last ending in ` \` and the rest indented by two.
fn wrap_command(line: &str, width: usize) -> String {
    let (body, end) = line.strip_suffix('\n').map_or((line, ""), |b| (b, "\n"));
    if body.chars().count() <= width {
        return line.to_owned();
    }
    let mut rows: Vec<String> = vec![String::new()];
    for word in body.split(' ') {
        let row = rows.last_mut().expect("one row at least");
        let wide = row.chars().count() + 1 + word.chars().count() + " \\".len();
        if !row.trim().is_empty() && wide > width {
            rows.push(format!("  {word}"));
        } else {
            if !row.is_empty() {
                row.push(' ');
            }
            row.push_str(word);
        }
    }
    format!("{}{end}", rows.join(" \\\n"))
}

/// The table of contents: the preface, the lessons that exist, where next,
/// and the appendices.
fn summary(entries: &[lesson::Entry]) -> String {
    let mut out = generated_from("the lessons in `lessons/`");
    out.push_str("# Summary\n\n");
    for (name, title) in PAGES {
        let _ = writeln!(out, "[{title}]({name}.md)\n");
    }
    out.push_str("# Lessons\n\n");
    for e in entries {
        let _ = writeln!(
            out,
            "- [{}. {}](lessons/{}.md)",
            e.number,
            e.title(),
            e.name
        );
    }
    out.push_str("- [Where next](where-next.md)\n");
    for (name, title) in AFTER {
        let _ = writeln!(out, "- [{title}]({name}.md)");
    }
    out.push_str("\n# Appendices\n\n");
    out.push_str("- [Commands](commands.md)\n- [Scene files](scene-format.md)\n- [The trace format](trace-format.md)\n");
    out
}

/// A command too wide for the book breaks with backslashes: copied, it runs
/// as written.
#[test]
fn a_wide_command_breaks_with_backslashes() {
    let command = format!(
        "$ raytree check {} --pixel 200,70 mine.json\n",
        ["lessons/06-transforms/ellipsoid.json"; 3].join(" ")
    );
    let wrapped = wrap_command(&command, 60);
    let rows: Vec<&str> = wrapped.lines().collect();
    assert!(rows.len() > 1, "{wrapped}");
    for (i, row) in rows.iter().enumerate() {
        assert!(row.chars().count() <= 60, "{row:?}");
        assert_eq!(row.ends_with(" \\"), i + 1 < rows.len(), "{row:?}");
    }
    assert_eq!(wrapped.replace(" \\\n  ", " "), command);
    let narrow = "$ raytree render\n";
    assert_eq!(wrap_command(narrow, 60), narrow);
}
