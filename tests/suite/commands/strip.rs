//! `raytree strip`: a frame per value with the share of pixels that changed,
//! as `raytree diff` measures it, and one-line errors for a field that does
//! not exist or a value the scene refuses.

use std::process::Command;

use crate::commands::cli::{succeeds, usage_in};

#[test]
fn a_strip_has_a_frame_per_value_and_the_changes_raytree_diff_measures() {
    let dir = std::env::temp_dir().join(format!("raytree-strip-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let run = |args: &[&str]| String::from_utf8(succeeds(args, &dir).stdout).unwrap();
    let size = ["--width", "64", "--height", "48"];
    let printed = run(&[
        &["strip", "--vary", "max_depth=1..3", "-o", "s.png"][..],
        &size,
    ]
    .concat());
    let png = image::open(dir.join("s.png")).unwrap();
    // Three 64-pixel frames with gaps and margins are narrower than the 480-pixel minimum.
    assert_eq!(png.width(), 480);
    // The second frame's share is what raytree diff says of depth 1 against depth 2.
    for depth in ["1", "2"] {
        run(&[
            &[
                "render",
                "--max-depth",
                depth,
                "-q",
                "-o",
                &format!("d{depth}.png"),
            ][..],
            &size,
        ]
        .concat());
    }
    // The frames differ, so diff answers 1.
    let diff = crate::commands::cli::raytree(&["diff", "d1.png", "d2.png"], &dir);
    assert_eq!(diff.status.code(), Some(1), "{diff:?}");
    let diff = String::from_utf8(diff.stdout).unwrap();
    let share = diff.rsplit(", ").next().unwrap().split('%').next().unwrap();
    let share: f64 = share.parse().unwrap();
    let line = printed.lines().nth(1).unwrap();
    assert!(
        line.starts_with(&format!("max_depth = 2: {share:.1}% of pixels changed")),
        "{line} against {diff}"
    );
    // The same strip twice is the same file.
    let again = run(&[
        &["strip", "--vary", "max_depth=1..3", "-o", "t.png"][..],
        &size,
    ]
    .concat());
    assert_eq!(printed, again);
    assert_eq!(
        std::fs::read(dir.join("s.png")).unwrap(),
        std::fs::read(dir.join("t.png")).unwrap()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// An NFF scene is varied by the fields of its scene JSON (what `raytree
/// convert` writes): the strip read the NFF text as JSON, "expected value at
/// line 1 column 1".
#[test]
fn a_strip_varies_an_nff_scene() {
    let dir = tempfile::tempdir().unwrap();
    let nff = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sampler.nff");
    let args = [
        "strip",
        nff,
        "--vary",
        "max_depth=1,2",
        "--width",
        "64",
        "-q",
        "-o",
        "s.png",
    ];
    succeeds(&args, dir.path());
    assert!(dir.path().join("s.png").is_file());
}

#[test]
fn bad_variations_are_one_line_errors() {
    // A variation the scene cannot take is the flag's fault: exit 2.
    let e = usage_in(
        "strip",
        "strip-missing",
        &["--vary", "materials.steel.ior=1,2"],
    );
    assert!(
        e.starts_with("error: --vary materials.steel.ior=1: the scene has no 'materials.steel'"),
        "{e}"
    );
    let e = usage_in("strip", "strip-range", &["--vary", "max_depth=0..2"]);
    assert_eq!(
        e,
        "error: --vary max_depth=0: render.max_depth: must be 1 to 1000, got 0"
    );
    let e = usage_in(
        "strip",
        "strip-ior",
        &["--vary", "materials.glass.ior=1.5,-1"],
    );
    assert!(
        e.contains("a refractive index must be from 0.01 to 100, got -1"),
        "{e}"
    );
    let e = usage_in("strip", "strip-width", &["--vary", "width=100,200"]);
    assert!(e.contains("share one size"), "{e}");
    let e = usage_in(
        "strip",
        "strip-twice",
        &["--vary", "max_depth=1..3", "--max-depth", "3"],
    );
    assert_eq!(
        e,
        "error: --vary max_depth and --max-depth both set max_depth: give one"
    );
    let dir = std::env::temp_dir();
    for bad in ["max_depth", "max_depth=1..40", "max_depth=a,b"] {
        let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(["strip", "--vary", bad])
            .current_dir(&dir)
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(2),
            "{bad}: a malformed command line"
        );
    }
}

/// One side given, the frames keep the scene's shape; the default name is the
/// field's words joined by dashes.
#[test]
fn one_side_given_keeps_the_shape_and_the_default_name_is_tidy() {
    let dir = std::env::temp_dir().join(format!("raytree-strip-side-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args([
            "strip",
            "--vary",
            "lights[0].position[1]=5,9",
            "--width",
            "64",
        ])
        .current_dir(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    // The Whitted scene is 640×480: a 64-pixel frame is 48 high.
    assert_eq!(
        stderr.trim_end(),
        "wrote whitted-strip-lights-0-position-1.png (2 frames of 64×48)"
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        stdout.lines().next(),
        Some("lights[0].position[1] = 5: the first frame")
    );
    // One value: one frame, said so.
    let out = crate::commands::cli::raytree(
        &[
            "strip",
            "--vary",
            "max_depth=3",
            "--width",
            "64",
            "-o",
            "one.png",
        ],
        &dir,
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.trim_end(), "wrote one.png (1 frame of 64×48)");
    std::fs::remove_dir_all(&dir).unwrap();
}
