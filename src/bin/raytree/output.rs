//! The one door out: everything the binary prints, and the files it writes.
//!
//! Standard output and standard error are written here and nowhere else (the
//! binary denies `print!` and `eprint!`), with `std::io::Write`: a write that
//! fails is an `io::Error` carried up with `?` to `main`, never a panic. There
//! [`closed_pipe`] finds a broken pipe in the error's chain (the reader went
//! away, as `| head` does) and the program ends quietly with exit 0; any other
//! failure (a full disk) is one line and exit 1. Rust ignores SIGPIPE, so a
//! closed pipe always arrives as that error.
//!
//! Every file a command writes is a pending file (`raytree::io::output`) until
//! it is committed, never one of the command's inputs (a signal removes it:
//! `signals.rs`); default output names; progress bars.

use std::ffi::{OsStr, OsString};
use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use anyhow::{Result, bail};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use raytree::io::image;
use raytree::io::image::file::Format;
pub use raytree::io::output::commit_all;
use raytree::io::output::{self, PendingFile};
use raytree::scene::strict::printable;

use crate::args::usage;

/// Writes `text` to standard output, all of it, and flushes it: a table, a
/// trace, a line of figures.
pub fn print(text: impl AsRef<[u8]>) -> io::Result<()> {
    write_all(io::stdout().lock(), "output", text.as_ref())
}

/// A line on standard error: what was written, a warning. Its control
/// characters are escaped (`\u{1b}`), as an error's are: a file name in it is
/// data, and never instructs the terminal or breaks the line.
pub fn note(line: &str) -> io::Result<()> {
    write_all(
        io::stderr().lock(),
        "error",
        format!("{}\n", printable(line)).as_bytes(),
    )
}

/// The program's last line on standard error, an error or a signal: when it
/// cannot be written there is nothing left to do, and the exit code says it.
pub fn last_word(line: &str) {
    let _ = note(line);
}

/// The last word of a program a signal ends, on a line of its own: below the
/// line a progress bar may be drawn on.
pub fn last_word_below_bar(line: &str) {
    if BAR_SHOWN.load(Ordering::Relaxed) {
        let _ = write_all(io::stderr().lock(), "error", b"\n");
    }
    last_word(line);
}

/// clap's help or version text, where clap sends it (standard error for a
/// command line that names no command).
pub fn clap_text(e: &clap::Error) -> io::Result<()> {
    let stream = if e.use_stderr() { "error" } else { "output" };
    e.print().map_err(|e| failed(stream, &e))
}

/// Whether standard output is a terminal (the inspector needs one).
pub fn stdout_is_terminal() -> bool {
    io::stdout().is_terminal()
}

/// Whether `e` is, or was caused by, a closed pipe: the reader of standard
/// output (or error) went away, which ends the program quietly.
pub fn closed_pipe(e: &anyhow::Error) -> bool {
    e.chain()
        .filter_map(|cause| cause.downcast_ref::<io::Error>())
        .any(|io| io.kind() == io::ErrorKind::BrokenPipe)
}

/// Writes `bytes` to `stream` (standard `name`) and flushes it; a failure
/// keeps its kind and names the stream.
fn write_all(mut stream: impl Write, name: &str, bytes: &[u8]) -> io::Result<()> {
    stream
        .write_all(bytes)
        .and_then(|()| stream.flush())
        .map_err(|e| failed(name, &e))
}

/// `e`, of the same kind, as "cannot write to standard `name`: reason".
fn failed(name: &str, e: &io::Error) -> io::Error {
    io::Error::new(
        e.kind(),
        format!("cannot write to standard {name}: {}", output::io_reason(e)),
    )
}

/// Opens `path` for writing as a pending file (removed on a signal), refusing
/// it when it is one of `inputs`, the files the command reads.
pub fn create(path: &Path, inputs: &[PathBuf]) -> Result<PendingFile> {
    if let Some(input) = inputs.iter().find(|i| output::same_file(path, i)) {
        bail!(
            "cannot write {}: it is {}, which this command reads (choose another output name)",
            path.display(),
            if input.as_path() == path {
                "an input".to_owned()
            } else {
                format!("the same file as the input {}", input.display())
            }
        );
    }
    PendingFile::create(path)
}

/// `given`, or `default` (a name in the current folder).
pub fn name_or(given: &Option<PathBuf>, default: impl FnOnce() -> OsString) -> PathBuf {
    given.clone().unwrap_or_else(|| PathBuf::from(default()))
}

/// A default output name: `stem` (an input's name, its bytes kept as they
/// are, UTF-8 or not) followed by `ending` (`-chart.png`).
pub fn stem_and(stem: &OsStr, ending: &str) -> OsString {
    let mut name = stem.to_owned();
    name.push(ending);
    name
}

/// Refuses an output that is not a `.png` (a usage error); `what` names the
/// figure.
pub fn require_png(path: &Path, what: &str) -> Result<()> {
    if !has_extension(path, "png") {
        return Err(usage(format_args!(
            "cannot write {}: {what} is a .png",
            path.display()
        )));
    }
    Ok(())
}

/// The image format an output's name asks for (.png or .ppm); any other
/// name is a usage error.
pub fn image_format(path: &Path) -> Result<Format> {
    image::file::format_of(path).map_err(|e| usage(format_args!("{e:#}")))
}

/// Whether `path` ends in `.extension` (in any case).
pub fn has_extension(path: &Path, extension: &str) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(extension))
}

/// The library's `(done, total)` reports, drawn on `bar`.
pub fn on_bar(bar: &ProgressBar) -> impl Fn(u64, u64) + Sync + '_ {
    |done, total| {
        bar.set_length(total);
        bar.set_position(done);
    }
}

/// Whether a progress bar may be drawn on standard error (a terminal): a
/// signal's last word then starts on a line of its own.
static BAR_SHOWN: AtomicBool = AtomicBool::new(false);

/// A bar on stderr, drawn only when stderr is a terminal (hidden when `quiet`),
/// with `template` as indicatif writes it. A bar never fails the program:
/// indicatif hides it when stderr is not a terminal (a pipe, closed or not)
/// and drops its own write errors (of the calls made here, only
/// `set_tab_width` would panic on one; it is not used).
pub fn progress_bar(quiet: bool, template: &str) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    if io::stderr().is_terminal() {
        BAR_SHOWN.store(true, Ordering::Relaxed);
    }
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template(template)
            .expect("valid template")
            .progress_chars("=> "),
    );
    bar
}
