//! The line between exit status 2 and 1: a refusal of the command line itself
//! (a flag's value out of its range, flags that do not go together, an output
//! name of the wrong kind, a lesson that is not there) is a usage error, one
//! line ending with the `--help` to read and exit status 2, as clap's own parse
//! errors are; a file's content or a failure to read or write one is exit
//! status 1 (`diff` and `check` answer with 1, so all their errors are 2).

use crate::common::{refused, refused_with};

/// The repository's lessons, for `--lessons` from a fresh folder.
fn lessons() -> String {
    concat!(env!("CARGO_MANIFEST_DIR"), "/lessons").to_owned()
}

/// Runs each of `cases` (a name, the arguments, a part of the message) in a
/// fresh folder and holds it to exit status 2, one line naming the problem and
/// ending with its command's `--help`, and nothing written.
fn usage_errors(cases: &[(&str, &[&str], &str)]) {
    for (name, args, said) in cases {
        let e = refused_with(2, name, &[], args);
        assert!(e.contains(said), "{name}: {e}");
        // `generate` names what it makes: `raytree generate icosphere --help`.
        let words = if args[0] == "generate" { 2 } else { 1 };
        let command = args[..words].join(" ");
        assert!(
            e.ends_with(&format!("(see raytree {command} --help)")),
            "{name}: {e}"
        );
    }
}

/// Flags whose values are out of their range: a name, the arguments, a part
/// of the message.
const FLAGS_OUT_OF_RANGE: &[(&str, &[&str], &str)] = &[
    (
        "width-0",
        &["render", "--width", "0"],
        "'--width <W>': must be 1 to 32768, got 0",
    ),
    (
        "width-negative",
        &["render", "--width", "-1"],
        "'--width <W>': must be 1 to 32768, got -1",
    ),
    (
        "spp-negative",
        &["render", "--spp", "-4"],
        "'--spp <N>': must be a square number of samples (1, 4, 9, … up to 1024) for an n×n grid, got -4",
    ),
    (
        "max-depth-huge",
        &["render", "--max-depth", "99999999999"],
        "'--max-depth <D>': must be 1 to 1000, got 99999999999",
    ),
    (
        "diagram-depth-0",
        &["diagram", "--pixel", "1,1", "--depth", "0"],
        "'--depth <D>': must be 1 or more, got 0",
    ),
    (
        "diagram-vectors-0",
        &["diagram", "--pixel", "1,1", "--vectors", "0"],
        "'--vectors <P>': must be 1 or more, got 0",
    ),
    (
        "diff-tolerance-word",
        &["diff", "a.png", "b.png", "--tolerance", "abc"],
        "'--tolerance <LEVELS>': 'abc' is not a whole number of 8-bit levels (0 to 255)",
    ),
    (
        "spp-3",
        &["render", "--spp", "3"],
        "'--spp <N>': must be a square number of samples",
    ),
    (
        "pixels",
        &["render", "--width", "32768", "--height", "32768"],
        "more than the",
    ),
    (
        "depth-with-cutoff",
        &[
            "trace",
            "--pixel",
            "1,1",
            "--max-depth",
            "64",
            "--cutoff",
            "0",
        ],
        "--max-depth: 64 with cutoff 0",
    ),
    (
        "threads-0",
        &["render", "--threads", "0"],
        "'--threads <N>': must be a whole number from 1 to 256",
    ),
    (
        "threads-forward",
        &["forward", "--threads", "257"],
        "'--threads <N>': must be a whole number from 1 to 256",
    ),
    (
        "pupil-0",
        &["forward", "--pupil", "0"],
        "'--pupil <R>': must be from 1e-9 to 1e9, got 0",
    ),
    (
        "pupil-huge",
        &["forward", "--pupil", "1e300"],
        "'--pupil <R>': must be from 1e-9 to 1e9, got 1e300",
    ),
    (
        "photons-0",
        &["forward", "--photons", "0"],
        "'--photons <N>'",
    ),
    (
        "vary-unknown",
        &["strip", "--vary", "bogus=1,2"],
        "--vary bogus=1: no render setting or scene field 'bogus': the settings are cutoff, height, max_depth, spp, width; the scene's fields are ambient_light,",
    ),
    (
        "vary-empty",
        &["strip", "--vary", "spp="],
        "'--vary <PATH=VALUES>'",
    ),
    (
        "pixel-outside",
        &["trace", "--pixel", "700,1"],
        "pixel 700,1 is outside the 640×480 image",
    ),
    (
        "sample-outside",
        &["trace", "--pixel", "1,1", "--spp", "4", "--sample", "5"],
        "sample 5 does not exist: a pixel has 4 samples (1 to 4)",
    ),
    (
        "diagram-pixel",
        &["diagram", "--pixel", "9999,1", "-o", "d.png"],
        "pixel 9999,1 is outside the 640×480 image",
    ),
    (
        "inspect-pixel",
        &["inspect", "--pixel", "9999,1"],
        "--pixel 9999,1 is outside the 640×480 image",
    ),
    (
        "aov-unknown",
        &["render", "--aov", "colour"],
        "--aov: unknown quantity 'colour'",
    ),
    (
        "lobe-four",
        &["lobe", "--shininess", "1,2,3,4"],
        "--shininess: at most three exponents",
    ),
    (
        "icosphere-too-big",
        &[
            "generate",
            "icosphere",
            "--triangles",
            "20000000",
            "-o",
            "i.json",
        ],
        "--triangles 13107200 or fewer",
    ),
    (
        "vectors-hit",
        &["diagram", "--pixel", "1,1", "--vectors", "9", "-o", "v.png"],
        "--vectors 9: no hit P9",
    ),
];

/// A flag's value out of its range exits 2, as the same flag's parse error
/// does: `--width -1` and `--width 0`, `--photons 0` and `--pupil 0`.
#[test]
fn a_flag_out_of_its_range_is_a_usage_error() {
    usage_errors(FLAGS_OUT_OF_RANGE);
}

/// A ray outside a scene's limits (±1e9) is refused naming --ray: traced, it
/// gave NaN and infinities in the text, and a JSON trace that would not read
/// back.
#[test]
fn a_ray_beyond_the_scenes_limits_is_a_usage_error() {
    usage_errors(&[
        (
            "ray-origin",
            &["trace", "--ray", "1e308,0,0:-1,0,0"],
            "'--ray <OX,OY,OZ:DX,DY,DZ>': the origin: every coordinate must be within ±1e9, got [1e308, 0, 0]",
        ),
        (
            "ray-origin-json",
            &["trace", "--ray", "0,0,1e10:0,0,-1", "--json"],
            "the origin: every coordinate must be within ±1e9",
        ),
        (
            "ray-direction",
            &["trace", "--ray", "0,0,0:1e308,1e308,1e308"],
            "'--ray <OX,OY,OZ:DX,DY,DZ>': the direction: every coordinate must be within ±1e9",
        ),
        (
            "ray-tiny",
            &["trace", "--ray", "0,0,0:1e-300,0,0"],
            "the direction is too short to normalize",
        ),
        (
            "ray-zero",
            &["diagram", "--ray", "0,0,0:0,0,0"],
            "the direction must not be zero",
        ),
    ]);
    // At the limits every number stays finite, and the JSON reads back.
    let dir = tempfile::tempdir().unwrap();
    for ray in [
        "1e9,1e9,1e9:-1e9,-1e9,-1e9",
        "0,1.6,7:1e-150,-1e-150,-1e-149",
    ] {
        let out = crate::commands::cli::succeeds(&["trace", "--ray", ray], dir.path());
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(
            !text.contains("NaN") && !text.contains("inf"),
            "{ray}: {text}"
        );
        crate::commands::cli::succeeds(&["trace", "--ray", ray, "--json"], dir.path());
    }
}

/// Output names of the wrong kind: a name, the arguments, a part of the
/// message (which names the kind the command writes).
const OUTPUTS_OF_THE_WRONG_KIND: &[(&str, &[&str], &str)] = &[
    (
        "render-txt",
        &["render", "-o", "foo.txt"],
        "cannot write foo.txt: the output must end in .png or .ppm",
    ),
    (
        "aov-ppm",
        &["render", "--aov", "depth", "-o", "d.ppm"],
        "cannot write d.ppm: a per-pixel quantity is a .png",
    ),
    (
        "convert-txt",
        &["convert", "x.nff", "-o", "x.txt"],
        "cannot write x.txt: a scene is written as a .json file",
    ),
    (
        "convert-json",
        &["convert", "x.json"],
        "cannot convert x.json: raytree converts NFF files (.nff)",
    ),
    (
        "trace-png",
        &["trace", "--pixel", "1,1", "-o", "x.png"],
        "cannot write x.png: a trace is written as .json (the JSON trace, or the learner trace with --learner) or .txt (the text)",
    ),
    (
        "trace-json-as-text",
        &["trace", "--pixel", "1,1", "--json", "-o", "x.txt"],
        "cannot write x.txt: --json writes the JSON trace, a .json",
    ),
    (
        "trace-learner-as-text",
        &["trace", "--pixel", "1,1", "--learner", "-o", "x.txt"],
        "cannot write x.txt: the learner trace is JSON, a .json",
    ),
    (
        "trace-steps-as-json",
        &["trace", "--pixel", "1,1", "--steps", "-o", "x.json"],
        "cannot write x.json: --steps numbers the text trace",
    ),
    (
        "diagram-jpg",
        &["diagram", "--pixel", "1,1", "-o", "fig.jpg"],
        "cannot write fig.jpg: a diagram is a .png or an .svg",
    ),
    (
        "graph-svg",
        &["diagram", "--pixel", "1,1", "--graph", "-o", "g.svg"],
        "cannot write g.svg: the tree graph is drawn as PNG only",
    ),
    (
        "strip-ppm",
        &["strip", "--vary", "spp=1,4", "-o", "s.ppm"],
        "cannot write s.ppm: a strip is a .png",
    ),
    (
        "forward-ppm",
        &["forward", "-o", "f.ppm"],
        "cannot write f.ppm: a forward trace is a .png",
    ),
    (
        "chart-csv-is-png",
        &["chart", "-o", "c.png", "--csv", "c.png"],
        "cannot write c.png: the CSV figures and the chart need two files",
    ),
    (
        "generate-png",
        &["generate", "spheres", "--count", "3", "-o", "x.png"],
        "cannot write x.png: a generated scene is a .json file",
    ),
    // The figure of diff and check is a .png: the message says so, not
    // ".png or .ppm" (a .ppm is refused as well).
    (
        "diff-dot",
        &["diff", "a.png", "b.png", "-o", "."],
        "cannot write .: a difference figure is a .png",
    ),
    (
        "diff-ppm",
        &["diff", "a.png", "b.png", "-o", "d.ppm"],
        "cannot write d.ppm: a difference figure is a .png",
    ),
    (
        "check-dot",
        &["check", "s.json", "--image", "y.png", "-o", "."],
        "cannot write .: a difference figure is a .png",
    ),
];

/// An output name of the wrong kind is a usage error, before anything is
/// read or traced; the message names the kind the command writes.
#[test]
fn an_output_name_of_the_wrong_kind_is_a_usage_error() {
    usage_errors(OUTPUTS_OF_THE_WRONG_KIND);
    // A text trace is written to a .txt name, the JSON trace to a .json one.
    let dir = tempfile::tempdir().unwrap();
    crate::commands::cli::succeeds(&["trace", "--pixel", "1,1", "-o", "t.txt"], dir.path());
    crate::commands::cli::succeeds(&["trace", "--pixel", "1,1", "-o", "t.json"], dir.path());
    let text = std::fs::read_to_string(dir.path().join("t.txt")).unwrap();
    assert!(text.starts_with("pixel 1,1 of "), "{text}");
    let json = std::fs::read_to_string(dir.path().join("t.json")).unwrap();
    assert!(json.starts_with('{'), "{json}");
}

/// `check`'s flags that would change nothing are refused: -o, --tolerance and
/// --worst without --image (clap's `requires` let them pass), --spp and --aa
/// (a check traces one ray through each pixel's center), and the size with
/// --image (the image's own).
#[test]
fn check_refuses_the_flags_that_would_change_nothing() {
    usage_errors(&[
        (
            "check-o-pixel",
            &[
                "check", "s.json", "--pixel", "1,1", "l.json", "-o", "out.png",
            ],
            "-o goes with --image only",
        ),
        (
            "check-tolerance-pixel",
            &[
                "check",
                "s.json",
                "--pixel",
                "1,1",
                "l.json",
                "--tolerance",
                "3",
            ],
            "--tolerance goes with --image only",
        ),
        (
            "check-worst-pixel",
            &[
                "check", "s.json", "--pixel", "1,1", "l.json", "--worst", "3",
            ],
            "--worst goes with --image only",
        ),
        (
            "check-spp-image",
            &["check", "s.json", "--image", "y.png", "--spp", "4"],
            "--spp: a check traces one ray through each pixel's center",
        ),
        (
            "check-aa-pixel",
            &[
                "check", "s.json", "--pixel", "1,1", "l.json", "--aa", "corners",
            ],
            "--aa: a check traces one ray through each pixel's center",
        ),
        (
            "check-width-image",
            &["check", "s.json", "--image", "y.png", "--width", "40"],
            "--width and --height: with --image the size is your image's",
        ),
    ]);
    // The help lists neither --spp nor --aa.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["check", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(!help.contains("--spp") && !help.contains("--aa"), "{help}");
}

/// Flags that do not go together: usage errors.
#[test]
fn flags_that_do_not_go_together_are_usage_errors() {
    usage_errors(&[
        (
            "structures-accel",
            &["structures", "a.json", "--accel", "bvh"],
            "--accel: structures measures every structure itself",
        ),
        (
            "structures-sweep-two",
            &["structures", "a.json", "b.json", "--grid-sweep"],
            "--grid-sweep: sweeps one scene, got 2",
        ),
        (
            "vary-and-flag",
            &["strip", "--vary", "max_depth=1..3", "--max-depth", "3"],
            "--vary max_depth and --max-depth both set max_depth: give one",
        ),
        (
            "spd-constant-weights",
            &["render", "--protocol", "spd", "--weights", "constant"],
            "--weights constant: --protocol spd spawns a reflected and a refracted ray at every transmitting hit",
        ),
        (
            "spd-spp",
            &["render", "--protocol", "spd", "--spp", "4"],
            "--spp: samples the --aa grid only, and --protocol spd traces one ray through each pixel corner",
        ),
        (
            "corners-spp",
            &["trace", "--pixel", "1,1", "--aa", "corners", "--spp", "4"],
            "--spp: samples the --aa grid only, and --aa corners traces",
        ),
        (
            "adaptive-spp",
            &["render", "--aa", "adaptive", "--spp", "1"],
            "--spp: samples the --aa grid only, and --aa adaptive takes",
        ),
        (
            "grid-res-auto",
            &["render", "--grid-res", "10"],
            "--grid-res: sets the grid's cells, and the scene is traced with --accel auto",
        ),
        (
            "grid-res-bvh",
            &[
                "trace",
                "--pixel",
                "1,1",
                "--accel",
                "bvh",
                "--grid-res",
                "10",
            ],
            "--accel bvh; give --accel grid beside it",
        ),
        (
            "tree-depth-grid",
            &["render", "--accel", "grid", "--tree-depth", "5"],
            "--tree-depth: sets the octree's or the k-d tree's depth, and the scene is traced with --accel grid; give --accel octree or --accel bsp beside it",
        ),
    ]);
}

/// A pixel with a negative coordinate: a usage error naming the edge it
/// counts from, whichever command is given it.
#[test]
fn a_negative_pixel_is_a_usage_error() {
    usage_errors(&[
        (
            "trace-pixel-negative",
            &["trace", "--pixel", "-1,5"],
            "x -1 is outside the image: x counts from 0 at its left edge",
        ),
        (
            "diagram-pixel-negative",
            &["diagram", "--pixel", "3,-5"],
            "y -5 is outside the image: y counts from 0 at its top edge",
        ),
        (
            "check-pixel-negative",
            &["check", "s.json", "--pixel", "-1,-1", "x.json"],
            "x -1 is outside the image",
        ),
        (
            "inspect-pixel-negative",
            &["inspect", "--pixel", "-2,0"],
            "x -2 is outside the image",
        ),
    ]);
}

/// The lesson that is not there, or a lessons folder that is not one: usage
/// errors, in the lesson's folder or out of it.
#[test]
fn a_missing_lesson_is_a_usage_error() {
    let lessons = lessons();
    usage_errors(&[
        (
            "lesson-99",
            &["lesson", "99", "--lessons", &lessons],
            "no lesson 99 (there are: 1, 2,",
        ),
        (
            "vectors-99",
            &["vectors", "99", "--lessons", &lessons],
            "lesson 99: vectors exist for lessons 3 to 11",
        ),
        (
            "lesson-no-folder",
            &["lesson", "5", "--lessons", "nosuch"],
            "nosuch: no such folder",
        ),
        (
            "lesson-not-a-folder",
            &["lesson", "5", "--lessons", "/dev/null"],
            "/dev/null: not a folder",
        ),
        (
            "lesson-no-lessons",
            &["lesson", "5", "--lessons", "/etc"],
            "/etc: the folder holds no lessons",
        ),
        (
            "lessons-listed-no-lessons",
            &["lesson", "--lessons", "/etc"],
            "/etc: the folder holds no lessons",
        ),
    ]);
}

/// What is wrong in a file stays exit status 1, named in one line: a lesson
/// folder without its steps.toml names the file, in words (not "os error 2").
#[test]
fn a_lesson_without_its_steps_is_a_file_error_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let from = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/05-sphere");
    let to = dir.path().join("05-sphere");
    std::fs::create_dir(&to).unwrap();
    for f in ["lesson.toml", "lesson.md"] {
        std::fs::copy(from.join(f), to.join(f)).unwrap();
    }
    let folder = dir.path().display().to_string();
    for command in ["lesson", "vectors"] {
        let e = refused(
            &format!("{command}-no-steps"),
            &[],
            &[command, "5", "--lessons", &folder],
        );
        assert_eq!(
            e,
            format!("error: cannot read {folder}/05-sphere/steps.toml: no such file"),
            "{command}"
        );
    }
}
