//! `raytree postscript`: the lecture's PostScript ray tracer drawn by
//! Ghostscript, its transcription slips repaired (`raytree::io::postscript`),
//! cropped to what it painted, so that lesson 14 can set it beside raytree's
//! twin of its scene. Ghostscript is an outside program: when it is missing,
//! or the program fails or runs too long, the command says so in one line.

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use raytree::figure::canvas::Figure;
use raytree::io::image::linear_to_srgb8;
use raytree::io::input::read_text;
use raytree::io::postscript::{self, SLIPS};

use crate::output;
use crate::signals;

/// Where the course keeps the lecture, beside the repository.
const LECTURE: &str = "shared/lecture-raytracing.md";

/// One point of the page is one pixel: the program's own grid.
const DPI: u32 = 72;

#[derive(clap::Args)]
pub struct Args {
    /// The program: a PostScript file, or a Markdown file holding it in a code
    /// block that starts with %! [default: the lecture, shared/lecture-raytracing.md
    /// beside the current folder or a folder above it].
    source: Option<PathBuf>,
    /// Output image (.png) [default: the source's name with .png].
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// Read the program's gray levels as linear light and encode them as sRGB,
    /// as raytree writes its images, so that the two compare.
    #[arg(long)]
    srgb: bool,
    /// List the lecture copy's transcription slips that raytree repairs, and stop.
    #[arg(long)]
    slips: bool,
    /// Give up on Ghostscript after this many seconds.
    #[arg(long, value_name = "S", default_value_t = 120, value_parser = clap::value_parser!(u64).range(1..=3600))]
    timeout: u64,
}

pub fn run(args: &Args) -> Result<()> {
    if args.slips {
        output::print(slips())?;
        return Ok(());
    }
    let source = match &args.source {
        Some(path) => path.clone(),
        None => find_lecture()?,
    };
    let text = read_text(&source, 16 << 20)
        .map_err(|reason| anyhow::anyhow!("cannot read {}: {reason}", source.display()))?;
    let Some(program) = postscript::program(&text) else {
        bail!(
            "{}: no PostScript program (a file starting with %!, or a code block whose first line does)",
            source.display()
        );
    };
    let (program, repaired) = postscript::repair(program);
    let path = output::name_or(&args.output, || {
        let stem = source.file_stem().unwrap_or("postscript".as_ref());
        output::stem_and(stem, ".png")
    });
    output::require_png(&path, "a Ghostscript image")?;
    let pending = output::create(&path, std::slice::from_ref(&source))?;
    let page = ghostscript(&program, args.srgb, Duration::from_secs(args.timeout))?;
    let (rgb, width, height) = crop(&page, args.srgb)
        .with_context(|| format!("{}: the program painted nothing", source.display()))?;
    let mut fig = Figure::page(width, height).context("the page is too large")?;
    fig.image(0, 0, width, &rgb);
    pending.commit(&fig.png())?;
    output::note(&format!(
        "wrote {} ({width}×{height}, Ghostscript at {DPI} dpi{}), {} transcription slip{} repaired",
        path.display(),
        if args.srgb { ", encoded as sRGB" } else { "" },
        repaired.len(),
        if repaired.len() == 1 { "" } else { "s" }
    ))?;
    Ok(())
}

/// The slips, a numbered paragraph each: what the copy has, what the program
/// needs, and why.
fn slips() -> String {
    SLIPS
        .iter()
        .enumerate()
        .map(|(k, s)| format!("{}. {} → {}: {}\n", k + 1, s.found, s.meant, s.why))
        .collect()
}

/// The lecture, as `shared/lecture-raytracing.md` in the current folder's
/// parent or a folder above it (the course keeps it beside the repository).
fn find_lecture() -> Result<PathBuf> {
    let here = std::env::current_dir().context("cannot tell the current folder")?;
    here.ancestors()
        .map(|dir| dir.join(LECTURE))
        .find(|p| p.is_file())
        .with_context(|| {
            format!(
                "no lecture: {LECTURE} is not beside {} nor above it (give the program's file: raytree postscript FILE)",
                here.display()
            )
        })
}

/// The first page Ghostscript draws of `program`: 8-bit RGB, or 16-bit when
/// the levels are to be re-encoded, as a PNG file's bytes.
fn ghostscript(program: &str, deep: bool, timeout: Duration) -> Result<Vec<u8>> {
    let dir = tempfile::Builder::new()
        .prefix("raytree-postscript-")
        .tempdir()
        .context("cannot make a temporary folder")?;
    let page = dir.path().join("page.png");
    let mut child = Command::new("gs")
        .args([
            "-q",
            "-dSAFER",
            "-dBATCH",
            "-dNOPAUSE",
            "-dLastPage=1",
            if deep { "-sDEVICE=png48" } else { "-sDEVICE=png16m" },
            &format!("-r{DPI}"),
            "-dDEVICEWIDTHPOINTS=612",
            "-dDEVICEHEIGHTPOINTS=792",
            "-dFIXEDMEDIA",
            &format!("-sOutputFile={}", page.display()),
            "-",
        ])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| match e.kind() {
            std::io::ErrorKind::NotFound => anyhow::anyhow!(
                "Ghostscript is not installed (no gs on the PATH): install it, e.g. apt-get install ghostscript"
            ),
            _ => anyhow::anyhow!("cannot run Ghostscript (gs): {e}"),
        })?;
    let stdin = child.stdin.take();
    // From here a signal, or an error, ends Ghostscript and removes the folder.
    let gs = signals::Helper::start(child, dir);
    if let Some(mut stdin) = stdin {
        // A program that stops reading early is Ghostscript's error to report.
        let _ = stdin.write_all(program.as_bytes());
    }
    let start = Instant::now();
    while gs.try_wait()?.is_none() {
        if start.elapsed() > timeout {
            // Dropping `gs` kills Ghostscript.
            bail!(
                "Ghostscript did not finish within {} s (--timeout)",
                timeout.as_secs()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = gs.output()?;
    if !out.status.success() {
        let said = String::from_utf8_lossy(&out.stdout).into_owned()
            + &String::from_utf8_lossy(&out.stderr);
        let first = said
            .lines()
            .find(|l| l.starts_with("Error:"))
            .or_else(|| said.lines().find(|l| !l.trim().is_empty()))
            .unwrap_or("no message");
        bail!("Ghostscript failed on the program: {}", first.trim());
    }
    // No page file is the program's doing (it never showed a page), not an
    // error of the file system's to quote.
    match std::fs::read(&page) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            bail!("the program drew no page: it never calls showpage")
        }
        read => read.context("cannot read the page Ghostscript drew"),
    }
}

/// The smallest rectangle holding every painted (not paper-white) pixel of
/// the page, as 8-bit RGB, with its width and height; `None` for a blank page.
fn crop(png: &[u8], deep: bool) -> Option<(Vec<u8>, u32, u32)> {
    let page = image::load_from_memory(png).ok()?.to_rgb16();
    let painted = |p: &image::Rgb<u16>| p.0 != [u16::MAX; 3];
    let (mut x0, mut y0, mut x1, mut y1) = (u32::MAX, u32::MAX, 0, 0);
    for (x, y, p) in page.enumerate_pixels() {
        if painted(p) {
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
        }
    }
    if x0 > x1 {
        return None;
    }
    let level = |v: u16| {
        if deep {
            linear_to_srgb8(f64::from(v) / f64::from(u16::MAX))
        } else {
            (v >> 8) as u8
        }
    };
    let rgb = (y0..=y1)
        .flat_map(|y| (x0..=x1).map(move |x| (x, y)))
        .flat_map(|(x, y)| page.get_pixel(x, y).0.map(level))
        .collect();
    Some((rgb, x1 - x0 + 1, y1 - y0 + 1))
}
