//! What a test needs beyond Rust: Ghostscript, tmux, the lecture beside the
//! repository. A test asks [`available`] before using one. On a machine
//! without it the test skips that part and says so in one line on the
//! terminal (written past the test harness's capture, so a passing run shows
//! it too); under `CI=true`, where `.ci/run` has installed the tools and the
//! lecture is checked out beside the clone, a missing one fails the test.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// Something a test needs that a fresh machine with only Rust lacks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Need {
    /// `gs` on the PATH: `raytree postscript` draws with it.
    Ghostscript,
    /// `tmux` on the PATH: the inspector driven in a real terminal.
    Tmux,
    /// `shared/lecture-raytracing.md` beside the repository (or above it), as
    /// `raytree postscript` looks for it.
    Lecture,
    /// `shared/spd/` beside the repository: the Standard Procedural
    /// Databases' NFF files, POV-Ray files and reference pictures.
    Spd,
    /// `python3` on the PATH: the course's Python tracer (`lessons/python/`).
    Python3,
    /// `rsvg-convert` (librsvg) on the PATH: draws a diagram's SVG as pixels.
    Rsvg,
    /// `chromium` on the PATH: the built book read in a real browser.
    Chromium,
    /// `mdbook` on the PATH: builds the book for the browser.
    MdBook,
}

impl Need {
    /// Whether this machine has it (looked up once per test run).
    pub fn present(self) -> bool {
        static FOUND: [OnceLock<bool>; 8] = [
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
            OnceLock::new(),
        ];
        let runs = |program: &str, arg: &str| {
            Command::new(program)
                .arg(arg)
                .output()
                .is_ok_and(|o| o.status.success())
        };
        *FOUND[self as usize].get_or_init(|| match self {
            Need::Ghostscript => runs("gs", "--version"),
            Need::Tmux => runs("tmux", "-V"),
            Need::Lecture => lecture().is_some(),
            Need::Spd => spd().is_some(),
            Need::Python3 => runs("python3", "--version"),
            Need::Rsvg => runs("rsvg-convert", "--version"),
            Need::Chromium => runs("chromium", "--version"),
            Need::MdBook => runs("mdbook", "--version"),
        })
    }

    /// What is missing, in words.
    fn missing(self) -> &'static str {
        match self {
            Need::Ghostscript => "Ghostscript (gs) is not installed",
            Need::Tmux => "tmux is not installed",
            Need::Lecture => "there is no ../shared/lecture-raytracing.md beside the repository",
            Need::Spd => "there is no ../shared/spd/ beside the repository",
            Need::Python3 => "python3 not found",
            Need::Rsvg => "rsvg-convert (librsvg2-bin) is not installed",
            Need::Chromium => "chromium is not installed",
            Need::MdBook => "mdbook is not installed",
        }
    }

    /// How CI gets it; `alone`, the only thing missing.
    fn remedy(self, alone: bool) -> &'static str {
        match (self, alone) {
            (
                Need::Ghostscript
                | Need::Tmux
                | Need::Python3
                | Need::Rsvg
                | Need::Chromium
                | Need::MdBook,
                true,
            ) => ".ci/run installs it",
            (Need::Chromium, false) => ".ci/run installs chromium",
            (Need::MdBook, false) => ".ci/run installs the pinned mdBook",
            (Need::Rsvg, false) => ".ci/run installs librsvg2-bin",
            (Need::Python3, false) => ".ci/run installs python3",
            (Need::Ghostscript, false) => ".ci/run installs Ghostscript",
            (Need::Tmux, false) => ".ci/run installs tmux",
            (Need::Lecture | Need::Spd, _) => "CI checks out ../shared beside the clone",
        }
    }
}

/// The lecture, `shared/lecture-raytracing.md` in the repository's folder or
/// a folder above it: where `raytree postscript` run from the repository
/// finds it.
pub fn lecture() -> Option<PathBuf> {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .map(|d| d.join("shared/lecture-raytracing.md"))
        .find(|p| p.is_file())
}

/// The Standard Procedural Databases' folder, `shared/spd/` in the
/// repository's folder or a folder above it.
pub fn spd() -> Option<PathBuf> {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .map(|d| d.join("shared/spd"))
        .find(|p| p.join("balls.nff").is_file())
}

/// Whether the tests run in CI (`CI=true`, as CI services set it and as
/// `.ci/run` sets it), where nothing may be skipped.
pub fn on_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v.eq_ignore_ascii_case("true") || v == "1")
}

/// Whether everything in `needs` is here. If not, writes one line
///
/// `skipped: TEST (WHAT): Ghostscript (gs) is not installed (WHY; .ci/run installs it)`
///
/// (`TEST` is the test's name; `WHAT` says which part of it is skipped, ""
/// for all of it; `WHY`, what the missing thing is needed for) and returns
/// false; under `CI=true` it panics with that line instead.
#[track_caller]
pub fn available(what: &str, needs: &[Need], why: &str) -> bool {
    let mut missing: Vec<Need> = needs.iter().copied().filter(|n| !n.present()).collect();
    missing.sort();
    missing.dedup();
    if missing.is_empty() {
        return true;
    }
    let test = std::thread::current()
        .name()
        .filter(|n| *n != "main")
        .unwrap_or("a test")
        .to_owned();
    let what = if what.is_empty() {
        test
    } else {
        format!("{test} ({what})")
    };
    let said: Vec<&str> = missing.iter().map(|n| n.missing()).collect();
    let mut remedies: Vec<&str> = missing
        .iter()
        .map(|n| n.remedy(missing.len() == 1))
        .collect();
    // The lecture and the SPD's scenes come the same way: say it once.
    remedies.dedup();
    let line = format!(
        "{what}: {} ({why}; {})",
        said.join(" and "),
        remedies.join("; ")
    );
    if on_ci() {
        panic!("{line}: CI is true, so this fails instead of being skipped");
    }
    // Past the harness's capture: a skip is said even when the test passes.
    let _ = std::io::stderr().write_all(format!("skipped: {line}\n").as_bytes());
    false
}
