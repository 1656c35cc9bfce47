//! One chapter made from its text and its spec: every `{{…}}` in the text
//! replaced by what raytree printed or drew, the exercises with their answers
//! folded, the step-through narrated, and a table of where each number came
//! from (which is also how the staleness check names a stale number).

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use std::path::Path;

use raytree::course::lesson::StepThrough;
use raytree::course::number::Source;
use raytree::course::spec::Spec;

mod questions;

use super::run::{self, Output};
use crate::tools::Need;

/// Stands in a made chapter for what this machine could not make (a number,
/// an excerpt): the check compares the text around it.
pub const HOLE: &str = "\u{0}not made here\u{0}";

/// What a page is made from.
pub struct Input<'a> {
    /// The text, relative to the repository (`lessons/03-camera/lesson.md`).
    pub text: &'a str,
    /// The spec, relative to the repository.
    pub spec_path: &'a str,
    /// The spec, read.
    pub spec: &'a Spec,
    /// Where the chapter's figures go, relative to the chapter (`03-camera/`).
    pub figures: &'a str,
    /// A lesson's number and step-through; `None` for a book page.
    pub lesson: Option<(u32, &'a StepThrough)>,
}

/// A number as the chapter quotes it.
pub struct Quoted {
    pub name: String,
    pub value: String,
    pub from: String,
}

/// A made chapter.
pub struct Made {
    /// The Markdown, with a [`HOLE`] for each part in `unmade`.
    pub text: String,
    /// Figures: file name and PNG (`None` if it could not be made here),
    /// with the command that drew it.
    pub figures: Vec<(String, Option<Vec<u8>>, String)>,
    /// The numbers it quotes.
    pub numbers: Vec<Quoted>,
    /// Blocks it shows (excerpts, stops), named, to say which one went stale.
    pub blocks: Vec<(String, String)>,
    /// What could not be made on this machine (`number mean`, `excerpt
    /// compare`, `figure compare.png`), and what it lacks for them.
    pub unmade: Vec<String>,
    pub missing: Vec<Need>,
}

/// The title row of the table of numbers, which the check reads back.
pub const NUMBERS_TITLE: &str = "<summary>Where this chapter's numbers come from</summary>";

/// Makes a chapter. Errors name the file and line at fault.
pub fn make(src: &Input, scratch: &Path) -> Result<Made, String> {
    let spec = src.spec;
    let files = run::Files::new(spec, scratch)?;
    let outputs = run::runs(spec, &files).map_err(|e| format!("{}: {e}", src.spec_path))?;
    let mut numbers = BTreeMap::new();
    let mut unmade = Vec::new();
    let mut missing = Vec::new();
    for (name, n) in &spec.numbers {
        let value = match &outputs[&n.run] {
            Output::Unmade => {
                unmade.push(format!("number {name}"));
                missing.extend(files.missing(&spec.runs[&n.run].command));
                HOLE.to_owned()
            }
            out => run::number(n, out)
                .map_err(|e| format!("{}: line {}: number {name}: {e}", src.spec_path, n.line))?,
        };
        numbers.insert(name.clone(), value);
    }
    let text_path = run::root().join(src.text);
    let text = std::fs::read_to_string(&text_path).map_err(|e| format!("{}: {e}", src.text))?;
    let mut page = Page {
        src,
        outputs: &outputs,
        numbers: &numbers,
        used: BTreeSet::new(),
        figures: Vec::new(),
        blocks: Vec::new(),
        files: &files,
        unmade,
        missing,
    };
    let mut body = page.fill(&text, src.text, true)?;
    page.check_used()?;
    questions::not_shown_before(&body, spec, &numbers)
        .map_err(|e| format!("{}: {e}", src.spec_path))?;
    body.push_str(&numbers_table(spec, &numbers));
    let quoted = spec
        .numbers
        .iter()
        .map(|(name, n)| Quoted {
            name: name.clone(),
            value: numbers[name].clone(),
            from: origin(spec, n),
        })
        .collect();
    let mut seen = BTreeSet::new();
    page.unmade.retain(|u| seen.insert(u.clone()));
    page.missing.sort();
    page.missing.dedup();
    Ok(Made {
        text: body,
        figures: page.figures,
        numbers: quoted,
        blocks: page.blocks,
        unmade: page.unmade,
        missing: page.missing,
    })
}

struct Page<'a> {
    src: &'a Input<'a>,
    outputs: &'a BTreeMap<String, Output>,
    numbers: &'a BTreeMap<String, String>,
    used: BTreeSet<String>,
    figures: Vec<(String, Option<Vec<u8>>, String)>,
    blocks: Vec<(String, String)>,
    files: &'a run::Files<'a>,
    unmade: Vec<String>,
    missing: Vec<Need>,
}

impl Page<'_> {
    /// Replaces every directive of `text` (`at` names it in errors; `top` is
    /// the chapter itself, where the step-through and exercises go).
    fn fill(&mut self, text: &str, at: &str, top: bool) -> Result<String, String> {
        let mut out = String::new();
        let mut rest = text;
        while let Some(i) = rest.find("{{") {
            out.push_str(&rest[..i]);
            let line = text.len() - rest.len() + i;
            let line = raytree::course::teacher_file::line_of(text, line);
            let fail = |e: String| format!("{at}: line {line}: {e}");
            let end = rest[i..]
                .find("}}")
                .ok_or_else(|| fail("{{ without }}".to_owned()))?;
            let inner = rest[i + 2..i + end].trim().to_owned();
            let made = self.directive(&inner, top).map_err(fail)?;
            // A block written indented (in a list item) stays indented on every line.
            let line_start = out.rfind('\n').map_or(0, |n| n + 1);
            let indent = &out[line_start..];
            if indent.chars().all(|c| c == ' ') && !indent.is_empty() {
                let pad = format!("\n{indent}");
                out.push_str(
                    &made
                        .replace('\n', &pad)
                        .replace(&format!("{pad}\n"), "\n\n"),
                );
            } else {
                out.push_str(&made);
            }
            rest = &rest[i + end + 2..];
        }
        out.push_str(rest);
        Ok(out)
    }

    /// What one `{{…}}` stands for: a figure, a figure's number, an
    /// excerpt, the step-through, the exercises or a number.
    fn directive(&mut self, inner: &str, top: bool) -> Result<String, String> {
        let mut words = inner.split_whitespace();
        match (words.next().unwrap_or(""), words.next()) {
            ("figure", Some(name)) => self.figure(name),
            // A figure shown above, by its number, without showing it again.
            ("see", Some(name)) => {
                let file = format!("{name}.png");
                let number =
                    (self.figures.iter().position(|(f, ..)| *f == file)).ok_or_else(|| {
                        format!("{{{{see {name}}}}}: figure {name} is not shown above it")
                    })?;
                Ok(format!("Figure {}", number + 1))
            }
            ("excerpt", Some(name)) => self.excerpt(name),
            ("steps", None) if top => self.steps(),
            ("exercises", None) if top => self.exercises(),
            (name, None) if !name.is_empty() => {
                let spec = self.src.spec;
                let value = self
                    .numbers
                    .get(name)
                    .ok_or_else(|| self.unknown("number", name, spec.numbers.keys()))?;
                self.used.insert(format!("number {name}"));
                Ok(value.clone())
            }
            _ => Err(format!(
                "{{{{{inner}}}}} is not a directive: {{{{NAME}}}}, {{{{figure NAME}}}}, {{{{see NAME}}}}, {{{{excerpt NAME}}}}, {{{{steps}}}} or {{{{exercises}}}}"
            )),
        }
    }

    /// A name the spec does not have, with those it has.
    fn unknown<'k>(
        &self,
        what: &str,
        name: &str,
        have: impl Iterator<Item = &'k String>,
    ) -> String {
        let have: Vec<&str> = have.map(String::as_str).collect();
        format!(
            "no {what} '{name}' in {} (it has: {})",
            self.src.spec_path,
            have.join(", ")
        )
    }

    /// `{{figure NAME}}`: the image, numbered, its caption, and the commands
    /// that make it (what it reads first, a command a line).
    fn figure(&mut self, name: &str) -> Result<String, String> {
        let spec = self.src.spec;
        let figure = spec
            .figures
            .get(name)
            .ok_or_else(|| self.unknown("figure", name, spec.figures.keys()))?;
        self.used.insert(format!("figure {name}"));
        let caption = self.fill(
            &figure.caption,
            &format!("{} (figure {name})", self.src.spec_path),
            false,
        )?;
        let lacks = self.files.missing_for(name);
        let png = if lacks.is_empty() {
            Some(self.files.png(name)?)
        } else {
            self.unmade.push(format!("figure {name}.png"));
            self.missing.extend(lacks);
            None
        };
        let command = format!("{} -o {name}.png", figure.command.text);
        self.figures
            .push((format!("{name}.png"), png, command.clone()));
        let number = self.figures.len();
        let alt = caption.replace(['[', ']', '\n'], " ");
        // What it reads first, a command a line, so a learner can make it all.
        let commands: String = self
            .files
            .making(&figure.command)
            .iter()
            .chain([&command])
            .map(|c| format!(" <br>`{c}`"))
            .collect();
        Ok(format!(
            "![{alt}]({}{name}.png)\n\n**Figure {number}.** {}{commands}",
            self.src.figures, caption
        ))
    }

    /// `{{excerpt NAME}}`: part of a run's output as a code block, under the
    /// commands that make it.
    fn excerpt(&mut self, name: &str) -> Result<String, String> {
        let spec = self.src.spec;
        let x = spec
            .excerpts
            .get(name)
            .ok_or_else(|| self.unknown("excerpt", name, spec.excerpts.keys()))?;
        self.used.insert(format!("excerpt {name}"));
        let run = &spec.runs[&x.run].command;
        let command = &run.text;
        let (shown, body) = match &self.outputs[&x.run] {
            Output::Trace(_, text) => (
                format!("{command} --steps"),
                run::trace_steps(text, x.range),
            ),
            Output::Text(text) => (command.clone(), run::text_lines(text, x.range)),
            Output::Unmade => (command.clone(), Ok(HOLE.to_owned())),
        };
        let body = body.map_err(|e| format!("excerpt {name}: {e}"))?;
        let body = raytree::views::wrap::text(&body, super::make::CODE_WIDTH);
        if body == HOLE {
            self.unmade.push(format!("excerpt {name}"));
            self.missing.extend(self.files.missing(run));
        } else {
            self.blocks.push((format!("excerpt {name}"), body.clone()));
        }
        let making: String = self
            .files
            .making(run)
            .iter()
            .map(|c| format!("$ {c}\n"))
            .collect();
        // An excerpt not made here is a hole on a line of its own, so
        // the closing fence still starts its line (the book's code
        // blocks are found by their fences).
        let end = if body.ends_with('\n') { "" } else { "\n" };
        Ok(format!("```text\n{making}$ {shown}\n{body}{end}```"))
    }

    fn steps(&mut self) -> Result<String, String> {
        let Some((number, walk)) = self.src.lesson else {
            return Err("only a lesson has a step-through".to_owned());
        };
        if !self.used.insert("steps".to_owned()) {
            return Err("{{steps}} twice".to_owned());
        }
        let mut out = format!(
            "<div class=\"raytree-player\" data-lesson=\"{number}\" data-src=\"lessons/{}player.js\"></div>\n\n\
             `raytree lesson {number}` prints this step-through; each stop quotes the trace's own numbers \
             (the pixel has {} steps in all).\n",
            self.src.figures, walk.steps
        );
        for stop in &walk.stops {
            let block = format!(
                "\n- **Step {}** · `{}`\n\n  {}\n",
                stop.step, stop.headline, stop.say
            );
            self.blocks.push((
                format!("step-through stop at step {}", stop.step),
                block.clone(),
            ));
            out.push_str(&block);
        }
        Ok(out.trim_end().to_owned())
    }

    fn exercises(&mut self) -> Result<String, String> {
        if self.src.lesson.is_none() {
            return Err("only a lesson has exercises".to_owned());
        }
        if !self.used.insert("exercises".to_owned()) {
            return Err("{{exercises}} twice".to_owned());
        }
        let mut out = self.questions()?;
        for (k, e) in self.src.spec.exercises.iter().enumerate() {
            let at = format!("{} (exercise at line {})", self.src.spec_path, e.line);
            let task = self.fill(&e.task, &at, false)?;
            let answer = self.fill(&e.answer, &at, false)?;
            if !e.answer.contains("{{") {
                return Err(format!("{at}: the answer quotes nothing raytree computed"));
            }
            let _ = write!(
                out,
                "### Exercise {}\n\n{task}\n\n<details>\n<summary>Answer (computed by raytree)</summary>\n\n{answer}\n\n</details>\n\n",
                k + 1
            );
        }
        Ok(out.trim_end().to_owned())
    }

    /// Everything the spec makes is shown, and a lesson has what every lesson has.
    fn check_used(&self) -> Result<(), String> {
        let spec = self.src.spec;
        let at = self.src.spec_path;
        let all = spec
            .figures
            .iter()
            .map(|(n, f)| (format!("figure {n}"), f.line))
            .chain(
                spec.excerpts
                    .iter()
                    .map(|(n, x)| (format!("excerpt {n}"), x.line)),
            )
            .chain(
                spec.numbers
                    .iter()
                    .map(|(n, x)| (format!("number {n}"), x.line)),
            );
        for (what, line) in all {
            if !self.used.contains(&what) {
                return Err(format!(
                    "{at}: line {line}: {what} is shown nowhere in {}",
                    self.src.text
                ));
            }
        }
        if self.src.lesson.is_some() {
            let need = [
                (spec.figures.len() >= 2, "at least two figures"),
                (spec.exercises.len() >= 2, "at least two exercises"),
                (
                    spec.questions.len() >= 3,
                    "at least three checked questions ([[question]])",
                ),
                (
                    self.used.contains("steps"),
                    "its step-through: {{steps}} in the text",
                ),
                (
                    self.used.contains("exercises"),
                    "its exercises: {{exercises}} in the text",
                ),
            ];
            if let Some((_, what)) = need.iter().find(|(ok, _)| !ok) {
                return Err(format!("{at}: a lesson needs {what}"));
            }
        }
        Ok(())
    }
}

/// Where a number came from, in words a learner can retrace.
fn origin(spec: &Spec, n: &raytree::course::spec::Number) -> String {
    let command = &spec.runs[&n.run].command.text;
    match &n.source {
        Source::Step { step, value } => format!("`{command}`, step {step}, `{value}`"),
        Source::Json(pointer) => format!("`{command} --json`, `{pointer}`"),
        Source::After(before) => format!("`{command}`, after “{before}”"),
        Source::Before(after) => format!("`{command}`, before “{after}”"),
    }
}

/// The folded table of numbers at a chapter's end.
fn numbers_table(spec: &Spec, values: &BTreeMap<String, String>) -> String {
    if spec.numbers.is_empty() {
        return String::new();
    }
    let mut out = format!(
        "\n\n<details>\n{NUMBERS_TITLE}\n\n| number | value | from |\n| --- | --- | --- |\n"
    );
    for (name, n) in &spec.numbers {
        let _ = writeln!(
            out,
            "| `{name}` | {} | {} |",
            values[name].replace('|', "\\|"),
            origin(spec, n)
        );
    }
    out.push_str("\n</details>\n");
    out
}

/// The numbers a committed chapter quotes, read back from its table.
pub fn quoted(text: &str) -> BTreeMap<String, String> {
    let Some(at) = text.find(NUMBERS_TITLE) else {
        return BTreeMap::new();
    };
    text[at..]
        .lines()
        .filter_map(|l| {
            let row = l.strip_prefix("| `")?;
            let (name, rest) = row.split_once("` | ")?;
            let (value, _) = rest.split_once(" | ")?;
            Some((name.to_owned(), value.replace("\\|", "|")))
        })
        .collect()
}
