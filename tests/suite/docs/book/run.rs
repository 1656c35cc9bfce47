//! Running the spec's raytree commands: the real binary, in the repository,
//! exactly as a learner would type them.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command as Process;

use raytree::course::number::{self, Source};
use raytree::course::spec::{Command, Number, Run, Spec};
use raytree::tree::document::TraceDocument;
use raytree::views::text;

use crate::tools::Need;

/// The repository: commands run here, paths are relative to it.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `raytree ARGS` and returns its standard output. Help text is wrapped
/// at the book's code width whatever the terminal, so the book does not
/// depend on it and the command reference fits its code blocks.
pub fn raytree(args: &[String]) -> Result<Vec<u8>, String> {
    let out = Process::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(root())
        .env("COLUMNS", super::make::CODE_WIDTH.to_string())
        .env_remove("NO_COLOR")
        .output()
        .map_err(|e| format!("cannot run raytree: {e}"))?;
    // `raytree diff` answers 1 when the images differ, `raytree check` when a
    // learner's trace diverges: what a lesson shows.
    let answered =
        args.first().is_some_and(|a| a == "diff" || a == "check") && out.status.code() == Some(1);
    if !out.status.success() && !answered {
        return Err(format!(
            "`raytree {}` failed: {}",
            args.join(" "),
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    Ok(out.stdout)
}

/// What a run gave: a trace document (and its text, as `trace --steps` prints
/// it), or plain text; or nothing, because this machine lacks what it needs.
pub enum Output {
    Trace(Box<TraceDocument>, String),
    Text(String),
    Unmade,
}

/// What `command` itself needs beyond raytree: `raytree postscript` draws
/// with Ghostscript and, given no program file, reads the lecture (`--slips`
/// only prints the list); a command on the SPD's scenes reads them from
/// `../shared/spd/`.
pub fn needs(command: &Command) -> Vec<Need> {
    let args = &command.args;
    if args.iter().any(|a| a.starts_with("../shared/spd/")) {
        return vec![Need::Spd];
    }
    if args[0] != "postscript" || args.iter().any(|a| a == "--slips") {
        return Vec::new();
    }
    let names_a_file = args[1..].iter().any(|a| root().join(a).is_file());
    if names_a_file {
        vec![Need::Ghostscript]
    } else {
        vec![Need::Ghostscript, Need::Lecture]
    }
}

/// The images and figures of one chapter, each made once into a folder of
/// the chapter's own: a command that reads `NAME.png` is given that file.
pub struct Files<'a> {
    spec: &'a Spec,
    dir: tempfile::TempDir,
    made: RefCell<BTreeMap<String, Vec<u8>>>,
}

impl<'a> Files<'a> {
    pub fn new(spec: &'a Spec, scratch: &Path) -> Result<Self, String> {
        Ok(Files {
            spec,
            dir: tempfile::tempdir_in(scratch).map_err(|e| e.to_string())?,
            made: RefCell::default(),
        })
    }

    /// What this machine lacks to run `command`: its own needs and those of
    /// every image it reads.
    pub fn missing(&self, command: &Command) -> Vec<Need> {
        let mut out: Vec<Need> = needs(command)
            .into_iter()
            .chain(
                command
                    .reads
                    .iter()
                    .flat_map(|name| self.missing(self.command(name))),
            )
            .filter(|n| !n.present())
            .collect();
        out.sort();
        out.dedup();
        out
    }

    /// [`Self::missing`] for image or figure `name`.
    pub fn missing_for(&self, name: &str) -> Vec<Need> {
        self.missing(self.command(name))
    }

    fn command(&self, name: &str) -> &'a Command {
        let spec = self.spec;
        match spec.images.get(name) {
            Some(image) => &image.command,
            None => &spec.figures[name].command,
        }
    }

    /// The PNG of image or figure `name`, made by its command with `-o`.
    pub fn png(&self, name: &str) -> Result<Vec<u8>, String> {
        if let Some(png) = self.made.borrow().get(name) {
            return Ok(png.clone());
        }
        let command = self.command(name);
        let path = self.dir.path().join(format!("{name}.png"));
        let mut args = self.args(command)?;
        args.extend(["-o".to_owned(), path.display().to_string()]);
        raytree(&args)?;
        let png =
            std::fs::read(&path).map_err(|e| format!("`{}` wrote no figure: {e}", command.text))?;
        self.made.borrow_mut().insert(name.to_owned(), png.clone());
        Ok(png)
    }

    /// `command`'s arguments, each file it reads made first and named by its path.
    fn args(&self, command: &Command) -> Result<Vec<String>, String> {
        for name in &command.reads {
            self.png(name)?;
        }
        Ok(command
            .args
            .iter()
            .map(|a| match a.strip_suffix(".png") {
                Some(name) if command.reads.iter().any(|r| r == name) => {
                    self.dir.path().join(a).display().to_string()
                }
                _ => a.clone(),
            })
            .collect())
    }

    /// The commands, with their `-o`, that make what `command` reads, in the
    /// order a learner would type them.
    pub fn making(&self, command: &Command) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for name in &command.reads {
            let maker = self.command(name);
            for line in self.making(maker) {
                if !out.contains(&line) {
                    out.push(line);
                }
            }
            let line = format!("{} -o {name}.png", maker.text);
            if !out.contains(&line) {
                out.push(line);
            }
        }
        out
    }
}

/// Runs every run of a spec. A command that writes an image (a render whose
/// `--stats` the text quotes, a strip's printed changes) writes it into the
/// chapter's folder, never into the repository. A run this machine lacks
/// something for is [`Output::Unmade`].
pub fn runs(spec: &Spec, files: &Files) -> Result<BTreeMap<String, Output>, String> {
    spec.runs
        .iter()
        .map(|(name, run)| Ok((name.clone(), output(run, name, files)?)))
        .collect()
}

fn output(run: &Run, name: &str, files: &Files) -> Result<Output, String> {
    if !files.missing(&run.command).is_empty() {
        return Ok(Output::Unmade);
    }
    let mut args = files.args(&run.command)?;
    if run.command.is_trace() {
        let mut with_json = args;
        with_json.push("--json".to_owned());
        let bytes = raytree(&with_json)?;
        let doc: TraceDocument = serde_json::from_slice(&bytes)
            .map_err(|e| format!("`{}`: not a trace: {e}", run.command.text))?;
        let text = text::format(&doc, true);
        Ok(Output::Trace(Box::new(doc), text))
    } else {
        if run.command.writes_image() {
            let image = files.dir.path().join(format!("run-{name}.png"));
            args.extend(["-o".to_owned(), image.display().to_string()]);
        }
        let bytes = raytree(&args)?;
        Ok(Output::Text(String::from_utf8_lossy(&bytes).into_owned()))
    }
}

/// A number's value, written as the trace writes numbers (a trace's as
/// `raytree lesson N` reads it, [`number::from_trace`]).
pub fn number(n: &Number, out: &Output) -> Result<String, String> {
    match (&n.source, out) {
        (Source::Step { .. } | Source::Json(_), Output::Trace(doc, _)) => {
            number::from_trace(&n.source, doc)
        }
        (Source::After(before), Output::Text(text)) => {
            let at = text
                .find(before.as_str())
                .ok_or_else(|| format!("the output has no '{before}'"))?;
            let rest: Vec<char> = text[at + before.len()..].trim_start().chars().collect();
            let end = word_end(&rest);
            word(&rest[..end]).ok_or_else(|| format!("nothing follows '{before}'"))
        }
        (Source::Before(after), Output::Text(text)) => {
            let at = text
                .find(after.as_str())
                .ok_or_else(|| format!("the output has no '{after}'"))?;
            let head = text[..at].trim_end().trim_end_matches([',', ':']);
            let mut head: Vec<char> = head.trim_end().chars().collect();
            head.reverse();
            let mut w: Vec<char> = head[..word_end(&head)].to_vec();
            w.reverse();
            word(&w).ok_or_else(|| format!("nothing comes before '{after}'"))
        }
        _ => Err("the spec checked this pairing; it cannot happen".to_owned()),
    }
}

/// How many of `chars` make one word: up to a space or a bracket, and up to
/// a comma unless it sits between digits (`1,000,000` is one word).
fn word_end(chars: &[char]) -> usize {
    let digit = |i: usize| chars.get(i).is_some_and(char::is_ascii_digit);
    (0..chars.len())
        .find(|&i| {
            let c = chars[i];
            c.is_whitespace()
                || ";()".contains(c)
                || (c == ',' && !(i > 0 && digit(i - 1) && digit(i + 1)))
        })
        .unwrap_or(chars.len())
}

/// A word without the punctuation that ends a sentence or a label.
fn word(chars: &[char]) -> Option<String> {
    let w: String = chars.iter().collect();
    let w = w.trim_end_matches(['.', ':']).to_owned();
    (!w.is_empty()).then_some(w)
}

/// Steps `from..=to` of a trace's text (`raytree trace --steps`), or the whole
/// text; `⋮` marks the steps left out.
pub fn trace_steps(text: &str, range: Option<(usize, usize)>) -> Result<String, String> {
    let Some((from, to)) = range else {
        return Ok(text.to_owned());
    };
    let mut out = String::new();
    let mut current = 0;
    let mut last = 0;
    for line in text.lines() {
        if let Some(n) = step_number(line) {
            current = n;
            last = n;
        }
        // Before step 1 come the trace's header lines: they belong to step 1's excerpt.
        if (from..=to).contains(&current.max(1)) {
            out.push_str(line);
            out.push('\n');
        }
    }
    if to > last {
        return Err(format!("steps {from} to {to}, but the trace has {last}"));
    }
    let before = if from > 1 { "     ⋮\n" } else { "" };
    let after = if to < last { "     ⋮\n" } else { "" };
    Ok(format!("{before}{out}{after}"))
}

/// The number of a line that starts a step (`  12. …`).
fn step_number(line: &str) -> Option<usize> {
    let (head, _) = line.split_once(". ")?;
    (head.len() == 4)
        .then(|| head.trim_start().parse().ok())
        .flatten()
}

/// Lines `from..=to` of a text.
pub fn text_lines(text: &str, range: Option<(usize, usize)>) -> Result<String, String> {
    let Some((from, to)) = range else {
        return Ok(text.to_owned());
    };
    let lines: Vec<&str> = text.lines().collect();
    if to > lines.len() {
        return Err(format!(
            "lines {from} to {to}, but the output has {}",
            lines.len()
        ));
    }
    Ok(lines[from - 1..to].join("\n") + "\n")
}

#[test]
fn a_number_is_the_word_after_or_before_a_text() {
    let out = Output::Text(
        "forward: 1,000,000 rays shot (seed 1, pupil radius 0.3276)\n           17  reached a pixel (0.0017%)\n\
         backward: 336,120 rays (76,800 primary, 180,563 shadow)\npixel 416,209 at x,y.\n"
            .to_owned(),
    );
    let n = |source: Source| {
        let n = Number {
            run: "r".to_owned(),
            source,
            line: 1,
        };
        number(&n, &out)
    };
    let after = |t: &str| n(Source::After(t.to_owned()));
    let before = |t: &str| n(Source::Before(t.to_owned()));
    assert_eq!(after("forward:").unwrap(), "1,000,000");
    assert_eq!(after("pupil radius").unwrap(), "0.3276");
    assert_eq!(after("reached a pixel (").unwrap(), "0.0017%");
    assert_eq!(after("pixel 416,209 at").unwrap(), "x");
    assert_eq!(before("reached a pixel").unwrap(), "17");
    assert_eq!(before("primary").unwrap(), "76,800");
    assert_eq!(before("shadow)").unwrap(), "180,563");
    assert_eq!(before("rays shot").unwrap(), "1,000,000");
    assert_eq!(
        before("backward").unwrap_err(),
        "nothing comes before 'backward'"
    );
    assert_eq!(
        after("reached a pixel").unwrap_err(),
        "nothing follows 'reached a pixel'"
    );
    assert_eq!(after("no such").unwrap_err(), "the output has no 'no such'");
}
