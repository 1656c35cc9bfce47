//! `raytree postscript`: a PostScript program drawn by Ghostscript and cropped
//! to what it painted, the lecture's copy repaired, and every failure (no
//! Ghostscript, no program, a program that fails or never ends) one line.
//! The drawing tests are skipped, saying why, where Ghostscript or the
//! lecture is missing ([`crate::tools`]); lesson 14's figures draw the
//! lecture's own program.

use std::path::Path;
use std::process::Command;

use crate::common::refused;
use crate::tools::{Need, available};

/// A gray rectangle 20 × 10 points at (100, 100): 20 × 10 pixels at 72 dpi.
const RECTANGLE: &[u8] =
    b"%!PS\n0.5 setgray 100 100 moveto 20 0 rlineto 0 10 rlineto -20 0 rlineto fill showpage\n";

fn raytree(dir: &Path, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

#[test]
fn a_program_is_drawn_cropped_to_what_it_painted() {
    if !available("", &[Need::Ghostscript], "raytree postscript draws with it") {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("r.ps"), RECTANGLE).unwrap();
    // In a Markdown file, the program is the code block that starts with %!.
    let md = format!(
        "# Slide\n\n```\n{}```\n",
        String::from_utf8_lossy(RECTANGLE)
    );
    std::fs::write(dir.path().join("slides.md"), md).unwrap();
    for (args, level) in [
        // Ghostscript rounds 127.5 down.
        (&["postscript", "r.ps", "-o", "a.png"][..], 127),
        (&["postscript", "slides.md", "-o", "b.png"][..], 127),
        // Gray 0.5 as linear light, encoded as sRGB: 188.
        (&["postscript", "r.ps", "--srgb", "-o", "c.png"][..], 188),
    ] {
        let out = raytree(dir.path(), args);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let img = image::open(dir.path().join(args[args.len() - 1]))
            .unwrap()
            .to_rgb8();
        assert_eq!(img.dimensions(), (20, 10), "{args:?}");
        assert!(
            img.pixels().all(|p| p.0 == [level; 3]),
            "{args:?}: {:?}",
            img.get_pixel(0, 0)
        );
    }
    // The default name is the source's, beside it in the current folder.
    let out = raytree(dir.path(), &["postscript", "r.ps"]);
    assert!(out.status.success() && dir.path().join("r.png").is_file());
}

#[test]
fn failures_are_one_line() {
    let md: &[u8] = b"# Slides\n```\nno program here\n```\n";
    let e = refused("ps-no-program", &[("s.md", md)], &["postscript", "s.md"]);
    assert!(e.starts_with("error: s.md: no PostScript program"), "{e}");
    let e = refused("ps-no-lecture", &[], &["postscript"]);
    assert!(
        e.starts_with("error: no lecture: shared/lecture-raytracing.md is not beside"),
        "{e}"
    );
    let e = crate::common::refused_with(
        2,
        "ps-to-ppm",
        &[("r.ps", RECTANGLE)],
        &["postscript", "r.ps", "-o", "r.ppm"],
    );
    assert_eq!(
        e,
        "error: cannot write r.ppm: a Ghostscript image is a .png (see raytree postscript --help)"
    );
    // A program in a file called .png is still an input, never replaced.
    let e = refused(
        "ps-over-itself",
        &[("r.png", RECTANGLE)],
        &["postscript", "r.png", "-o", "r.png"],
    );
    assert!(e.contains("cannot write r.png: it is an input"), "{e}");
    // Without Ghostscript on the PATH.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("r.ps"), RECTANGLE).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["postscript", "r.ps"])
        .current_dir(dir.path())
        .env("PATH", "")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        stderr,
        "error: Ghostscript is not installed (no gs on the PATH): install it, e.g. apt-get install ghostscript\n"
    );
    assert!(!dir.path().join("r.png").exists(), "no output on failure");
    if !available(
        "only Ghostscript's own failures",
        &[Need::Ghostscript],
        "they are Ghostscript failing on a program",
    ) {
        return;
    }
    let bad: &[u8] = b"%!PS\n1 2 nosuchoperator showpage\n";
    let e = refused("ps-fails", &[("bad.ps", bad)], &["postscript", "bad.ps"]);
    assert_eq!(
        e,
        "error: Ghostscript failed on the program: Error: /undefined in nosuchoperator"
    );
    let endless: &[u8] = b"%!PS\n{} loop\n";
    let e = refused(
        "ps-endless",
        &[("loop.ps", endless)],
        &["postscript", "loop.ps", "--timeout", "1"],
    );
    assert_eq!(
        e,
        "error: Ghostscript did not finish within 1 s (--timeout)"
    );
    let blank: &[u8] = b"%!PS\nshowpage\n";
    let e = refused(
        "ps-blank",
        &[("blank.ps", blank)],
        &["postscript", "blank.ps"],
    );
    assert_eq!(e, "error: blank.ps: the program painted nothing");
    let pageless: &[u8] = b"%!PS\n0 0 moveto 10 10 lineto stroke\n";
    let e = refused(
        "ps-no-showpage",
        &[("p.ps", pageless)],
        &["postscript", "p.ps"],
    );
    assert_eq!(
        e,
        "error: the program drew no page: it never calls showpage"
    );
}

#[test]
fn the_lectures_copy_has_every_slip_and_the_list_names_them() {
    let out = raytree(
        Path::new(env!("CARGO_MANIFEST_DIR")),
        &["postscript", "--slips"],
    );
    let list = String::from_utf8(out.stdout).unwrap();
    let slips = raytree::io::postscript::SLIPS;
    assert_eq!(list.lines().count(), slips.len(), "{list}");
    for (k, s) in slips.iter().enumerate() {
        assert!(
            list.contains(&format!("{}. {} → {}: ", k + 1, s.found, s.meant)),
            "{list}"
        );
    }
    if !available(
        "only the slips in the lecture's copy",
        &[Need::Lecture],
        "the lecture's program is read from it",
    ) {
        return;
    }
    let path = crate::tools::lecture().expect("available");
    let text = std::fs::read_to_string(path).unwrap();
    let program = raytree::io::postscript::program(&text).expect("the lecture's program");
    let (repaired, done) = raytree::io::postscript::repair(program);
    assert_eq!(
        done.len(),
        slips.len(),
        "every slip is in the lecture's copy"
    );
    // Repaired, it holds none of them: a second pass finds nothing.
    assert!(raytree::io::postscript::repair(&repaired).1.is_empty());
}
