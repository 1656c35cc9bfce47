//! The `raytree` binary on good and bad input: every bad input ends with exit
//! code 1, one line on stderr starting `error:`, no panic, and no output file.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn raytree(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the binary runs")
}

/// Runs raytree in `dir` and expects it to succeed (its stderr otherwise).
pub fn succeeds(args: &[&str], dir: &Path) -> Output {
    let out = raytree(args, dir);
    assert!(
        out.status.success(),
        "raytree {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

pub fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// A fresh empty folder for one test, removed when the test ends, passed or
/// failed: each run of the suite had left its folders behind (hundreds of
/// them, a few hundred kilobytes each, in the temporary directory).
pub fn workdir(name: &str) -> Workdir {
    let dir = std::env::temp_dir().join(format!("raytree-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    Workdir(dir)
}

/// A test's folder; see [`workdir`].
pub struct Workdir(PathBuf);

impl std::ops::Deref for Workdir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Workdir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Workdir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs `render` on `scene_text` (written to `bad.json`) with extra arguments and
/// checks the failure contract; returns the error line.
pub fn fails(name: &str, scene_text: Option<&str>, extra: &[&str]) -> String {
    fails_in("render", name, scene_text, extra)
}

/// As [`fails`], for any subcommand: the contract of [`crate::common::refused`].
pub fn fails_in(command: &str, name: &str, scene_text: Option<&str>, extra: &[&str]) -> String {
    let mut args = vec![command];
    let files: Vec<(&str, &[u8])> = scene_text
        .map(|t| ("bad.json", t.as_bytes()))
        .into_iter()
        .collect();
    if scene_text.is_some() {
        args.push("bad.json");
    }
    args.extend_from_slice(extra);
    crate::common::refused(name, &files, &args)
}

/// Runs `command` with `extra` in a fresh folder and expects a usage error:
/// [`crate::common::refused_with`] exit code 2, the line ending with the
/// command's `--help`; returns the line without that ending.
pub fn usage_in(command: &str, name: &str, extra: &[&str]) -> String {
    let e = crate::common::refused_with(2, name, &[], &[&[command][..], extra].concat());
    e.strip_suffix(&format!(" (see raytree {command} --help)"))
        .unwrap_or_else(|| panic!("{name}: {e}"))
        .to_owned()
}

#[test]
fn bad_command_line_settings() {
    let scene = scenes().join("whitted.json");
    let scene = scene.to_str().unwrap();
    // Settings the flags make impossible are the command line's fault: exit 2,
    // ending with the help to read.
    let usage = |name: &str, extra: &[&str]| {
        let args = [&["render", scene][..], extra].concat();
        let e = crate::common::refused_with(2, name, &[], &args);
        e.strip_suffix(" (see raytree render --help)")
            .unwrap_or_else(|| panic!("{name}: {e}"))
            .to_owned()
    };
    assert_eq!(
        usage("cli-spp", &["--spp", "5"]),
        "error: invalid value '5' for '--spp <N>': must be a square number of samples (1, 4, 9, … up to 1024) for an n×n grid, got 5"
    );
    assert!(
        usage("cli-size", &["--width", "0"])
            .starts_with("error: invalid value '0' for '--width <W>': must be 1 to 32768")
    );
    assert!(
        usage("cli-cutoff", &["--cutoff", "NaN"])
            .starts_with("error: invalid value 'NaN' for '--cutoff <W>': must be a number from 0")
    );
    assert!(
        usage("cli-depth", &["--max-depth", "0"])
            .starts_with("error: invalid value '0' for '--max-depth <D>': must be 1 to 1000")
    );
    // The structures' sizes (issue 28): 0 or 10⁹ grid cells, a depth of 10⁶.
    for (name, flag, value, said) in [
        (
            "cli-grid0",
            "--grid-res",
            "0",
            "error: --grid-res: must be auto or 1 to 160 cells along the scene's longest side, got 0",
        ),
        (
            "cli-grid9",
            "--grid-res",
            "1000000000",
            "error: --grid-res: must be auto or 1 to 160 cells along the scene's longest side, got 1000000000",
        ),
        (
            "cli-deep",
            "--tree-depth",
            "1000000",
            "error: --tree-depth: must be auto or 0 to 48 levels, got 1000000",
        ),
    ] {
        assert_eq!(usage(name, &[flag, value]), said);
    }
    // The same settings in the scene file are the file's fault: exit 1.
    let in_file = std::fs::read_to_string(scenes().join("whitted.json")).unwrap();
    let bad = in_file.replacen(
        "\"max_depth\": 8",
        "\"max_depth\": 8, \"grid_res\": \"fine\"",
        1,
    );
    assert_ne!(bad, in_file, "the scene's render block moved");
    let e = fails("cli-grid-file", Some(&bad), &[]);
    assert!(
        e.contains("bad.json") && e.contains("expected auto or a whole number, got 'fine'"),
        "{e}"
    );
    let bad = in_file.replacen("\"spp\": 1", "\"spp\": 3", 1);
    assert_ne!(bad, in_file, "the scene's render block moved");
    let e = fails("cli-spp-file", Some(&bad), &[]);
    assert!(
        e.starts_with("error: bad.json: ") && e.contains("spp") && !e.contains("--help"),
        "{e}"
    );
    assert_eq!(
        usage("cli-threads", &["--threads", "0"]),
        "error: invalid value '0' for '--threads <N>': must be a whole number from 1 to 256"
    );
}

#[test]
fn unwritable_or_unsupported_output() {
    let e = fails("unwritable", None, &["-o", "no/such/folder/out.png"]);
    assert_eq!(
        e,
        "error: cannot write no/such/folder/out.png: the folder no/such/folder does not exist"
    );
    let e = crate::common::refused_with(2, "jpeg", &[], &["render", "-o", "out.jpg"]);
    assert_eq!(
        e,
        "error: cannot write out.jpg: the output must end in .png or .ppm (see raytree render --help)"
    );
}

#[test]
fn usage_errors_exit_2_and_help_explains_every_flag() {
    let dir = workdir("usage");
    let out = raytree(&["render", "--bogus"], &dir);
    assert_eq!(out.status.code(), Some(2));
    let out = raytree(&["render", "--help"], &dir);
    assert_eq!(out.status.code(), Some(0));
    let help = String::from_utf8(out.stdout).unwrap();
    for flag in [
        "--output",
        "--width",
        "--height",
        "--spp",
        "--max-depth",
        "--cutoff",
        "--threads",
        "--quiet",
        "--stats",
    ] {
        assert!(help.contains(flag), "--help lacks {flag}:\n{help}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn renders_the_builtin_scene_and_a_shipped_one() {
    let dir = workdir("good");
    let out = raytree(&["render", "--width", "64", "--height", "48"], &dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = std::fs::read(dir.join("whitted.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let decoded = image::load_from_memory(&png).unwrap();
    assert_eq!((decoded.width(), decoded.height()), (64, 48));

    let scene = scenes().join("nested.json");
    let out = raytree(
        &[
            "render",
            scene.to_str().unwrap(),
            "--width",
            "32",
            "--height",
            "24",
            "--spp",
            "4",
            "-o",
            "n.ppm",
            "--quiet",
        ],
        &dir,
    );
    assert!(
        out.status.success() && out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let ppm = std::fs::read(dir.join("n.ppm")).unwrap();
    assert!(ppm.starts_with(b"P6\n32 24\n255\n") && ppm.len() == 13 + 32 * 24 * 3);
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 2, "no temporary files left: {names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn trace_prints_the_tree_of_a_glass_pixel() {
    let dir = workdir("trace-text");
    let scene = scenes().join("whitted.json");
    let out = raytree(
        &["trace", scene.to_str().unwrap(), "--pixel", "416,209"],
        &dir,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    for expected in [
        "pixel 416,209 of ",
        "spawn primary ray (depth 1",
        "closest hit: 'glass'",
        "spawn refracted ray (depth 2",
        "spawn reflected ray (depth 2",
        "shadow ray to light 'key'",
        "total internal reflection",
        "return ",
    ] {
        assert!(text.contains(expected), "missing {expected:?} in:\n{text}");
    }
    let numbered = raytree(
        &[
            "trace",
            scene.to_str().unwrap(),
            "--pixel",
            "416,209",
            "--steps",
        ],
        &dir,
    );
    assert!(
        String::from_utf8(numbered.stdout)
            .unwrap()
            .lines()
            .any(|l| l.trim_start().starts_with("2. spawn primary ray"))
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn trace_json_reads_back_and_output_file_matches_stdout() {
    let dir = workdir("trace-json");
    let scene = scenes().join("whitted.json");
    let scene = scene.to_str().unwrap();
    let out = raytree(
        &[
            "trace", scene, "--pixel", "100,100", "--json", "--width", "200", "--height", "150",
            "--spp", "4",
        ],
        &dir,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let trace: raytree::tree::document::TraceDocument =
        serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        (trace.format.as_str(), trace.version),
        ("raytree-trace", raytree::tree::document::VERSION)
    );
    assert_eq!(
        (
            trace.settings.width,
            trace.settings.height,
            trace.samples.len()
        ),
        (200, 150, 4)
    );
    assert!(trace.scene.hash.starts_with("fnv1a64:"));

    let one = raytree(
        &[
            "trace", scene, "--pixel", "100,100", "--width", "200", "--height", "150", "--spp",
            "4", "--sample", "3", "-o", "t.json",
        ],
        &dir,
    );
    assert!(one.status.success() && one.stdout.is_empty());
    let picked: raytree::tree::document::TraceDocument =
        serde_json::from_str(&std::fs::read_to_string(dir.join("t.json")).unwrap()).unwrap();
    assert_eq!(picked.samples.len(), 1);
    assert_eq!(picked.samples[0], trace.samples[2]);
    assert_eq!(
        picked.color, trace.color,
        "the pixel's color stays the mean of all samples"
    );

    let ray = raytree(
        &["trace", scene, "--ray", "0,1.6,7:0.1,-0.1,-1", "--json"],
        &dir,
    );
    let ray: raytree::tree::document::TraceDocument = serde_json::from_slice(&ray.stdout).unwrap();
    assert!(ray.pixel.is_none() && ray.ray.is_some() && ray.samples.len() == 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn trace_refuses_pixels_and_samples_that_do_not_exist() {
    // A pixel or sample the image does not have is the command line's fault:
    // exit 2, the help to read.
    let usage = |name: &str, extra: &[&str]| {
        crate::common::refused_with(2, name, &[], &[&["trace"][..], extra].concat())
    };
    assert_eq!(
        usage("trace-x", &["--pixel", "640,0"]),
        "error: pixel 640,0 is outside the 640×480 image (x is 0 to 639, y is 0 to 479) (see raytree trace --help)"
    );
    assert_eq!(
        usage(
            "trace-y",
            &["--pixel", "0,480", "--width", "100", "--height", "480"]
        ),
        "error: pixel 0,480 is outside the 100×480 image (x is 0 to 99, y is 0 to 479) (see raytree trace --help)"
    );
    assert_eq!(
        usage(
            "trace-sample",
            &["--pixel", "1,1", "--spp", "4", "--sample", "5"]
        ),
        "error: sample 5 does not exist: a pixel has 4 samples (1 to 4) (see raytree trace --help)"
    );
    assert_eq!(
        fails_in(
            "trace",
            "trace-out",
            None,
            &["--pixel", "1,1", "-o", "missing/t.json"]
        ),
        "error: cannot write missing/t.json: the folder missing does not exist"
    );
    let e = fails_in(
        "trace",
        "trace-scene",
        Some(r#"{"objects": [{"sphere": {"radius": -2}}]}"#),
        &["--pixel", "1,1"],
    );
    assert_eq!(
        e,
        "error: bad.json: objects[0].sphere.radius: must be from 1e-9 to 1e9, got -2"
    );
}

#[test]
fn trace_usage_errors_exit_2() {
    let dir = workdir("trace-usage");
    for args in [
        &["trace"][..],
        &["trace", "--pixel", "a,b"],
        &["trace", "--pixel", "1,2", "--ray", "0,0,0:0,0,1"],
        &["trace", "--ray", "0,0,0:0,0,0"],
        &["trace", "--ray", "1,2:3,4,5"],
    ] {
        let out = raytree(args, &dir);
        assert_eq!(
            out.status.code(),
            Some(2),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn diagram_writes_a_png_of_the_asked_size() {
    let dir = workdir("diagram");
    let scene = scenes().join("whitted.json");
    let out = raytree(
        &[
            "diagram",
            scene.to_str().unwrap(),
            "--pixel",
            "416,209",
            "--size",
            "640x400",
            "--depth",
            "2",
            "--no-shadows",
            "--labels",
            "objects",
            "--view",
            "side",
        ],
        &dir,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = image::open(dir.join("whitted-diagram-416-209.png")).unwrap();
    assert_eq!((png.width(), png.height()), (640, 400));
    // The vectors and the graph of the same pixel keep the diagram: each
    // figure has a default name of its own.
    let plain = std::fs::read(dir.join("whitted-diagram-416-209.png")).unwrap();
    for (extra, name) in [
        ("--vectors", "whitted-vectors-P1-416-209.png"),
        ("--graph", "whitted-graph-416-209.png"),
    ] {
        let mut args = vec![
            "diagram",
            scene.to_str().unwrap(),
            "--pixel",
            "416,209",
            "--size",
            "1400x1000",
            extra,
        ];
        if extra == "--vectors" {
            args.push("1");
        }
        let out = raytree(&args, &dir);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(dir.join(name).exists(), "{name}");
    }
    assert_eq!(
        std::fs::read(dir.join("whitted-diagram-416-209.png")).unwrap(),
        plain
    );
    let out = raytree(
        &["diagram", "--ray", "0,1.6,7:0.1,-0.1,-1", "-o", "ray.png"],
        &dir,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.join("ray.png").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn diagram_refuses_bad_requests() {
    let usage = |name: &str, extra: &[&str]| {
        crate::common::refused_with(2, name, &[], &[&["diagram"][..], extra].concat())
    };
    assert_eq!(
        usage("diagram-jpg", &["--pixel", "1,1", "-o", "fig.jpg"]),
        "error: cannot write fig.jpg: a diagram is a .png or an .svg (see raytree diagram --help)"
    );
    assert_eq!(
        usage("diagram-ppm", &["--pixel", "1,1", "-o", "fig.ppm"]),
        "error: cannot write fig.ppm: a diagram is a .png or an .svg (see raytree diagram --help)"
    );
    assert_eq!(
        usage("diagram-px", &["--pixel", "9999,1", "-o", "fig.png"]),
        "error: pixel 9999,1 is outside the 640×480 image (x is 0 to 639, y is 0 to 479) (see raytree diagram --help)"
    );
    let dir = workdir("diagram-usage");
    for args in [
        &["diagram", "--pixel", "1,1", "--size", "10x10"][..],
        &["diagram", "--pixel", "1,1", "--view", "up"],
        &["diagram", "--pixel", "1,1", "--labels", "some"],
    ] {
        let out = raytree(args, &dir);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn inspect_refuses_to_run_without_a_terminal_or_with_a_bad_trace() {
    // The test harness captures standard output, so it is not a terminal.
    assert_eq!(
        fails_in("inspect", "inspect-tty", None, &[]),
        "error: raytree inspect needs a terminal (standard output is not one)"
    );
    // A script once got only that, with no way to read it as text.
    let scene = scenes().join("whitted.json");
    let script = format!(
        "scene = \"{}\"\npixel = [1, 2]\n[[stop]]\nstep = 1\nsay = \"c = {{c}}\"\n",
        scene.display()
    );
    let e = crate::common::refused(
        "inspect-script-tty",
        &[("mine.toml", script.as_bytes())],
        &["inspect", "--script", "mine.toml"],
    );
    assert!(
        e.contains("to print a script as text, name it steps.toml in a folder NN-topic")
            && e.contains("raytree lesson --lessons DIR N --text"),
        "{e}"
    );
}

/// `--stats` prints its counts on standard output (the rays by kind, the tests
/// they made, tests per ray), where a script or the book can read them; the
/// summary of what was written stays on stderr. On one thread the counts are
/// the same on every run (each thread remembers its own recent blockers).
#[test]
fn stats_print_rays_and_tests_per_ray_on_stdout() {
    let dir = workdir("stats");
    let stdout = render_with_stats(&dir);
    // "5,130 rays: 768 primary (700 hit), …; 2.1 M rays/s",
    // "40,211 tests: 30,000 box tests, 10,211 primitives; 7.838 per ray (5.849
    // box tests and 1.989 primitives), through a bounding volume hierarchy (--accel bvh)" and
    // "time: 0.012 s preprocessing (0.010 s reading, 0.002 s building), 0.100 s tracing".
    let mut lines = stdout.lines();
    let (rays, tests, time) = (
        lines.next().unwrap(),
        lines.next().unwrap(),
        lines.next().unwrap(),
    );
    assert_eq!(lines.next(), None, "{stdout}");
    let total_rays = check_ray_counts(rays, &stdout);
    check_test_counts(tests, total_rays, &stdout);
    check_times(time, &stdout);
    assert_eq!(
        render_with_stats(&dir).lines().nth(1),
        Some(tests.trim_end()),
        "one thread, same tests"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `raytree render spheres.json --stats` at 32×24 on one thread, in `dir`:
/// its standard output, once its summary on stderr has named what each of
/// its times covers.
fn render_with_stats(dir: &Path) -> String {
    let scene = scenes().join("spheres.json");
    let out = raytree(
        &[
            "render",
            scene.to_str().unwrap(),
            "--width",
            "32",
            "--height",
            "24",
            "--threads",
            "1",
            "--stats",
            "-o",
            "s.png",
        ],
        dir,
    );
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.starts_with("wrote s.png (32×24"), "{stderr}");
    assert!(!stderr.contains("rays:"), "{stderr}");
    // The summary names what each of its times covers, as the stats'
    // own line does: reading, then building and tracing together.
    let (_, times) = stderr.split_once("max depth 8): ").expect(&stderr);
    let words: Vec<&str> = times.split_whitespace().collect();
    assert_eq!(
        (words[1..5].join(" "), words[6..11].join(" ")),
        (
            "s reading the scene,".to_owned(),
            "s building and tracing on".to_owned()
        ),
        "{stderr}"
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The numbers on a line of `--stats`, thousands separators dropped.
fn counts(line: &str) -> Vec<f64> {
    line.replace(',', "")
        .split(|c: char| !c.is_ascii_digit() && c != '.')
        .filter_map(|w| w.parse().ok())
        .collect()
}

/// The rays' line of `--stats` (of the whole `stdout`): the total is the
/// sum of the kinds, every pixel's primary ray is there, the hits are some
/// of them. Returns the total.
fn check_ray_counts(rays: &str, stdout: &str) -> f64 {
    let r = counts(rays);
    assert_eq!(
        r.len(),
        7,
        "total, primary, hits, three kinds, speed: {stdout}"
    );
    assert_eq!(r[1], (32 * 24) as f64, "{stdout}");
    assert!(
        r[2] > 0.0 && r[2] <= r[1],
        "hits are primary rays: {stdout}"
    );
    assert_eq!(r[0], r[1] + r[3] + r[4] + r[5], "{stdout}");
    assert!(rays.ends_with(" M rays/s"), "{stdout}");
    r[0]
}

/// The tests' line of `--stats`: boxes and primitives add up, the steps are
/// named for the structure, and each per-ray figure is the count over
/// `total_rays`.
fn check_test_counts(tests: &str, total_rays: f64, stdout: &str) {
    let t = counts(tests);
    assert_eq!(
        t.len(),
        6,
        "total, boxes, primitives, per ray, and per ray again as boxes and primitives: {stdout}"
    );
    assert!(t[1] > 0.0, "spheres.json has a hierarchy: {stdout}");
    assert!(
        tests.contains(" box tests, ") && tests.ends_with("(--accel bvh)"),
        "the steps are named for the structure: {stdout}"
    );
    assert_eq!(t[1] + t[2], t[0], "{stdout}");
    // Each per-ray figure is written to 4 significant digits.
    assert!((t[3] - t[0] / total_rays).abs() <= 5e-4 * t[3], "{stdout}");
    assert!((t[4] - t[1] / total_rays).abs() <= 5e-4 * t[4], "{stdout}");
    assert!((t[5] - t[2] / total_rays).abs() <= 5e-4 * t[5], "{stdout}");
}

/// The time's line of `--stats`: preprocessing is reading and building.
fn check_times(time: &str, stdout: &str) {
    let s = counts(time);
    assert_eq!(
        s.len(),
        4,
        "preprocessing, reading, building, tracing: {stdout}"
    );
    // Each is rounded to the millisecond, so the sum may be off by one in the last place.
    assert!((s[0] - (s[1] + s[2])).abs() <= 0.0015, "{stdout}");
    assert!(
        time.starts_with("time: ") && time.ends_with(" s tracing"),
        "{stdout}"
    );
}

/// `--protocol spd` (issue 27) fixes the SPD's settings: 512×512, the pixel
/// corners, depth 5, no cutoff, Fresnel weights; a flag given beside it wins.
#[test]
fn the_spd_protocol_sets_what_it_fixes_and_flags_beside_it_win() {
    let settings = |extra: &[&str]| -> serde_json::Value {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(["trace", "--pixel", "256,256", "--json", "--protocol", "spd"])
            .args(extra)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        doc["settings"].clone()
    };
    let s = settings(&[]);
    assert_eq!(
        (
            &s["width"],
            &s["height"],
            &s["aa"],
            &s["max_depth"],
            &s["cutoff"],
            &s["weights"]
        ),
        (
            &serde_json::json!(512),
            &serde_json::json!(512),
            &serde_json::json!("corners"),
            &serde_json::json!(5),
            &serde_json::json!(0.0),
            &serde_json::json!("fresnel")
        )
    );
    assert_eq!(settings(&["--max-depth", "3"])["max_depth"], 3);
    // Sampling a grid again takes --aa grid beside --spp; Schlick's weights
    // keep the protocol's reflected ray at every transmitting hit.
    let grid = settings(&["--aa", "grid", "--spp", "4", "--weights", "schlick"]);
    assert_eq!(
        (&grid["spp"], &grid["weights"]),
        (&serde_json::json!(4), &serde_json::json!("schlick"))
    );
}
