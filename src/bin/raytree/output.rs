//! Output files and streams: every file a command writes is a pending file
//! (`raytree::io::output`) until it is committed, never one of the command's
//! inputs; SIGINT, SIGTERM and SIGHUP remove every pending file and give the
//! terminal back; default output names; standard output that tolerates a
//! closed pipe; progress bars.

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use raytree::io::image_file::{self, Format};
use raytree::io::output::{self, PendingFile};

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

/// On SIGINT, SIGTERM or SIGHUP: give the terminal back, remove every pending
/// file, say so in one line and exit with 128 + the signal's number (130 for
/// Ctrl-C), as shells do.
pub fn clean_up_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            raytree::inspector::restore();
            output::remove_pending();
            let what = match signal {
                SIGINT => "interrupted",
                SIGTERM => "terminated (SIGTERM)",
                _ => "hung up (SIGHUP)",
            };
            note(&format!("\n{what}: no output written"));
            std::process::exit(128 + signal);
        }
    });
}

/// A line on standard error; one that cannot be written (a closed or full
/// stream) is dropped rather than ending the program in a panic.
pub fn note(line: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}

/// `given`, or `default` (a name in the current folder).
pub fn name_or(given: &Option<PathBuf>, default: impl FnOnce() -> String) -> PathBuf {
    given.clone().unwrap_or_else(|| PathBuf::from(default()))
}

/// Refuses an output that is not a `.png`; `what` names the figure.
pub fn require_png(path: &Path, what: &str) -> Result<()> {
    if image_file::format_of(path)? != Format::Png {
        bail!("cannot write {}: {what} is a .png", path.display());
    }
    Ok(())
}

/// Writes to standard output; a closed pipe (`| head`) is not an error, a full
/// disk is.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(bytes).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(anyhow::anyhow!(
            "cannot write to standard output: {}",
            output::io_reason(&e)
        )),
        _ => Ok(()),
    }
}

/// The library's `(done, total)` reports, drawn on `bar`.
pub fn on_bar(bar: &ProgressBar) -> impl Fn(u64, u64) + Sync + '_ {
    |done, total| {
        bar.set_length(total);
        bar.set_position(done);
    }
}

/// A bar on stderr, drawn only when stderr is a terminal (hidden when `quiet`),
/// with `template` as indicatif writes it.
pub fn progress_bar(quiet: bool, template: &str) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template(template)
            .expect("valid template")
            .progress_chars("=> "),
    );
    bar
}
