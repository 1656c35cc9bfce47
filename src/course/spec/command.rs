//! The commands of a lesson's spec ([`crate::course::spec`]): a command
//! line split into arguments, and which of the spec's images and figures
//! each one reads (an argument `NAME.png`), so the book can make those first.

/// A raytree command line, as written in the spec and as arguments.
#[derive(Clone, Debug, PartialEq)]
pub struct Command {
    /// As written: `raytree trace scenes/whitted.json --pixel 416,209`.
    pub text: String,
    /// The arguments after `raytree`.
    pub args: Vec<String>,
    /// The images and figures of the spec it reads, by name, in the order
    /// its arguments name them (an argument `NAME.png`).
    pub reads: Vec<String>,
}

impl Command {
    /// Whether it is `raytree trace`: run with `--json`, its numbers named.
    pub fn is_trace(&self) -> bool {
        self.args.first().is_some_and(|a| a == "trace")
    }

    /// Whether it writes an image (to a name of its own choosing unless given
    /// `-o`): as a run, the book sends the image to a scratch folder and keeps
    /// what it prints.
    pub fn writes_image(&self) -> bool {
        self.args.first().is_some_and(|a| {
            [
                "render",
                "strip",
                "forward",
                "chart",
                "lobe",
                "structures",
                "diagram",
                "postscript",
            ]
            .contains(&a.as_str())
        })
    }
}

/// raytree's commands, as `raytree --help` lists them: a spec's command
/// names one, or the book would only find out when it ran it (the binary's
/// tests hold this list to its grammar).
pub const COMMANDS: &[&str] = &[
    "render",
    "trace",
    "diagram",
    "inspect",
    "chart",
    "structures",
    "strip",
    "lobe",
    "forward",
    "lesson",
    "diff",
    "postscript",
    "check",
    "generate",
    "convert",
    "vectors",
];

/// Splits `raytree ARGS…` into arguments. The book adds the output options,
/// so a command may not give them.
pub(crate) fn command(text: &str, figure: bool) -> Result<Command, String> {
    if text.contains(['"', '\'', '\\', '|', '>', '<', ';', '&', '$', '`']) {
        return Err(format!(
            "'{text}': plain words only (no quotes or shell syntax)"
        ));
    }
    let mut words = text.split_whitespace().map(str::to_owned);
    if words.next().as_deref() != Some("raytree") {
        return Err(format!("'{text}' does not start with raytree"));
    }
    let args: Vec<String> = words.collect();
    if args.is_empty() {
        return Err("no command after raytree".to_owned());
    }
    let help = ["--help", "-h", "--version", "-V"].contains(&args[0].as_str());
    if !help && !COMMANDS.contains(&args[0].as_str()) {
        return Err(format!(
            "'{}' is not a raytree command (they are: {})",
            args[0],
            COMMANDS.join(", ")
        ));
    }
    let given = |flag: &str| {
        args.iter()
            .any(|a| a == flag || a.starts_with(&format!("{flag}=")))
    };
    if given("-o") || given("--output") {
        return Err(format!("'{text}': leave out -o; the book names the output"));
    }
    if !figure && args[0] == "trace" && (given("--json") || given("--steps")) {
        return Err(format!(
            "'{text}': leave out --json and --steps; the book adds them"
        ));
    }
    Ok(Command {
        text: text.split_whitespace().collect::<Vec<_>>().join(" "),
        args,
        reads: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use crate::course::spec::{Spec, parse};

    fn spec(text: &str) -> Result<Spec, String> {
        parse(Path::new("lessons/03-x/lesson.toml"), text)
    }

    #[test]
    fn commands_read_the_images_and_figures_they_name() {
        let s = spec(
            "[image.a]\ncommand = \"raytree render x.json\"\n\
             [figure.b]\ncommand = \"raytree render y.json\"\ncaption = \"B.\"\n\
             [figure.d]\ncommand = \"raytree diff a.png b.png\"\ncaption = \"D.\"\n\
             [run.d]\ncommand = \"raytree diff b.png scenes/a.png\"\n",
        )
        .unwrap();
        assert_eq!(s.figures["d"].command.reads, ["a", "b"]);
        // A path with a folder is a file of the repository, not one the spec makes.
        assert_eq!(s.runs["d"].command.reads, ["b"]);
        assert!(s.images["a"].command.reads.is_empty());
    }

    /// A typo'd command was once taken for a run other than a trace, and its
    /// number refused for lacking after = or before =.
    #[test]
    fn a_command_raytree_lacks_is_named() {
        let e = spec(
            "[run.t]\ncommand = \"raytree trac scenes/whitted.json --pixel 1,2\"\n\
             [number]\nn = { run = \"t\", step = 1, value = \"t\" }\n",
        )
        .unwrap_err();
        assert!(
            e.contains("line 1: run t: 'trac' is not a raytree command (they are: render, trace,"),
            "{e}"
        );
    }
}
