//! Output files and streams: every file a command writes is a pending file
//! registered here until it is committed, so an interrupt can remove it; default
//! output names; standard output that tolerates a closed pipe; progress bars.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{Context, Result, bail};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use raytree::io::image_file::{self, Format};
use raytree::io::output::PendingFile;

/// Temporary output files not yet renamed into place: removed if the user
/// interrupts, since a signal skips the destructors that would remove them.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Opens `path` for writing as a pending file, registered for removal on interrupt.
pub fn create(path: &Path) -> Result<PendingFile> {
    let file = PendingFile::create(path)?;
    PENDING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(file.temp_path().to_owned());
    Ok(file)
}

/// On Ctrl-C: give the terminal back, remove every pending file, exit 130.
pub fn remove_pending_on_interrupt() {
    let _ = ctrlc::set_handler(|| {
        raytree::inspector::restore();
        for path in PENDING.lock().unwrap_or_else(|e| e.into_inner()).drain(..) {
            let _ = std::fs::remove_file(path);
        }
        eprintln!("\ninterrupted: no output written");
        std::process::exit(130);
    });
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

/// Writes to standard output; a closed pipe (`| head`) is not an error.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    match std::io::stdout().lock().write_all(bytes) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(e).context("cannot write to standard output")
        }
        _ => Ok(()),
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

/// A line on standard error; one that cannot be written (a closed or full
/// stream) is dropped rather than ending the program in a panic.
pub fn note(line: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}
