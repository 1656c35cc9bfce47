//! Runs that end well (issue 29): whatever raytree accepts it finishes in
//! bounded time and memory, or refuses at once with the estimate; whatever it
//! writes it reads back; an output of two files is both or neither; `diff`
//! answers with its exit status; a script's pixel off the image is refused.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs raytree with `args` in a fresh folder holding `files` and expects a
/// refusal within a few seconds (a run that would not finish is killed, and
/// fails the test): exit code `code`, one line on stderr, no file added.
/// Returns the line.
fn refused_at_once(code: i32, files: &[(&str, &[u8])], args: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    for (file, bytes) in files {
        std::fs::write(dir.path().join(file), bytes).unwrap();
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(dir.path())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // A refusal comes before any work: seconds are ample on a busy machine.
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(20) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("raytree {}: still running after 20 s", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let shown = args.join(" ");
    assert_eq!(out.status.code(), Some(code), "raytree {shown}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "raytree {shown}: {stderr:?}");
    assert!(stderr.starts_with("error: "), "raytree {shown}: {stderr}");
    let left = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(left, files.len(), "raytree {shown}: a file was left");
    stderr.trim_end().to_owned()
}

/// Settings that could not finish: refused before any work, the flags' as a
/// usage error (2), a scene file's as the file's (1).
#[test]
fn settings_that_could_not_finish_are_refused_up_front() {
    // Rays double a level where a glass surface reflects and refracts: 2^1000.
    // Asked by the flags, it is a usage error (2); by a scene file, the file's (1).
    assert_eq!(
        refused_at_once(2, &[], &["render", "--max-depth", "1000", "--cutoff", "0"]),
        "error: --max-depth: 1000 with cutoff 0 may trace up to 1.1e301 rays a sample (2^max_depth - 1: each hit may spawn a reflected and a refracted ray), more than the 4294967296 (2^32) raytree traces; lower max_depth to 32 or raise the cutoff (see raytree render --help)"
    );
    let scene = br#"{"render": {"max_depth": 40, "cutoff": 0}, "objects": [{"sphere": {}}]}"#;
    let e = refused_at_once(1, &[("deep.json", scene)], &["render", "deep.json"]);
    assert!(
        e.starts_with(
            "error: deep.json: render.max_depth: 40 with cutoff 0 may trace up to 1099511627775 rays a sample"
        ),
        "{e}"
    );
    // The trace that needed 9.4 GB: refused by the same rule.
    let e = refused_at_once(
        2,
        &[],
        &[
            "trace",
            "--pixel",
            "416,209",
            "--spp",
            "1024",
            "--max-depth",
            "300",
            "--cutoff",
            "0",
            "--json",
        ],
    );
    assert!(
        e.starts_with("error: --max-depth: 300 with cutoff 0"),
        "{e}"
    );
}

/// Within the render's bound, beyond what a trace holds and is read back:
/// the settings asked are too many for a trace, a usage error too.
#[test]
fn settings_too_many_for_a_trace_are_refused_up_front() {
    assert_eq!(
        refused_at_once(
            2,
            &[],
            &[
                "trace",
                "--pixel",
                "416,209",
                "--max-depth",
                "21",
                "--cutoff",
                "0",
                "--json"
            ]
        ),
        "error: pixel 416,209 may record up to 2097151 rays, more than the 1048576 a trace holds (and raytree reads back); lower max_depth, or raise the cutoff (see raytree trace --help)"
    );
    assert_eq!(
        refused_at_once(
            2,
            &[],
            &[
                "trace",
                "--pixel",
                "1,1",
                "--spp",
                "1024",
                "--max-depth",
                "12",
                "--cutoff",
                "0",
                "-o",
                "t.json",
            ]
        ),
        "error: pixel 1,1 may record up to 4193280 rays (1024 samples of up to 4095), more than the 1048576 a trace holds (and raytree reads back); lower spp or max_depth, or raise the cutoff (see raytree trace --help)"
    );
    let e = refused_at_once(
        2,
        &[],
        &[
            "trace",
            "--ray",
            "0,1,5:0,0,-1",
            "--max-depth",
            "21",
            "--cutoff",
            "0",
        ],
    );
    assert!(
        e.starts_with("error: the ray may record up to 2097151 rays"),
        "{e}"
    );
}

#[test]
fn the_deepest_trace_without_a_cutoff_is_recorded_and_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let deepest = ["--pixel", "416,209", "--max-depth", "20", "--cutoff", "0"];
    crate::commands::cli::succeeds(
        &[&["trace"][..], &deepest, &["-o", "t.json"]].concat(),
        dir.path(),
    );
    let trace = raytree::tree::reading::read(&dir.path().join("t.json")).unwrap();
    assert_eq!(trace.settings.max_depth, 20);
}

#[test]
fn generate_refuses_an_icosphere_the_mesh_reader_would_refuse() {
    // 20·4^10 triangles: about 2.4 GB of OBJ; 20·4^11: about 10 GB.
    assert_eq!(
        refused_at_once(
            2,
            &[],
            &[
                "generate",
                "icosphere",
                "--triangles",
                "20000000",
                "-o",
                "big.json"
            ]
        ),
        "error: an icosphere of 20971520 triangles would be an OBJ file of about 2.7 GB, more than the 1 GiB raytree reads; the most it makes is 5242880 triangles (--triangles 13107200 or fewer) (see raytree generate icosphere --help)"
    );
    let e = refused_at_once(
        2,
        &[],
        &[
            "generate",
            "icosphere",
            "--triangles",
            "100000000",
            "-o",
            "big.json",
        ],
    );
    assert!(
        e.contains("83886080 triangles would be an OBJ file of about 10.9 GB"),
        "{e}"
    );
}

/// Runs raytree in `dir` under bash with files limited to `blocks` KiB
/// (`ulimit -f`): a write past it fails as on a full disk (SIGXFSZ ignored, so
/// the write returns an error instead of ending the process).
fn with_small_disk(blocks: u32, args: &[&str], dir: &Path) -> std::process::Output {
    Command::new("bash")
        .arg("-c")
        .arg(format!(
            "ulimit -f {blocks} && trap '' XFSZ && exec \"$0\" \"$@\""
        ))
        .arg(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

#[test]
fn an_output_of_two_files_is_both_or_neither() {
    if Command::new("bash").arg("-c").arg("true").status().is_err() {
        println!("skipped: an_output_of_two_files_is_both_or_neither: no bash");
        return;
    }
    // The icosphere's scene names its mesh twice: a long name makes the scene
    // (written second) larger than the mesh, so a 2 KiB limit stops it alone.
    let stem = "i".repeat(240);
    let (scene, mesh) = (format!("{stem}.json"), format!("{stem}.obj"));
    let args = ["generate", "icosphere", "--triangles", "1", "-o", &scene];
    let open = tempfile::tempdir().unwrap();
    crate::commands::cli::succeeds(&args, open.path());
    let size = |name: &str| std::fs::metadata(open.path().join(name)).unwrap().len();
    assert!(
        size(&mesh) <= 2048 && size(&scene) > 2048,
        "the case needs the mesh within 2 KiB and the scene beyond: {} and {}",
        size(&mesh),
        size(&scene)
    );
    let full = tempfile::tempdir().unwrap();
    let out = with_small_disk(2, &args, full.path());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(
        stderr,
        format!("error: cannot write {scene}: File too large\n")
    );
    let left: Vec<_> = std::fs::read_dir(full.path()).unwrap().collect();
    assert!(left.is_empty(), "left behind: {left:?}");

    // A second file that cannot be renamed into place (a name ending in a
    // slash is taken for a folder): the first is removed again.
    let e = refused_at_once(
        1,
        &[],
        &[
            "chart", "--cost", "tests", "--runs", "1", "--width", "8", "--height", "6", "--size",
            "64x64", "-o", "c.png", "--csv", "c.csv/",
        ],
    );
    assert_eq!(e, "error: cannot write c.csv/: Not a directory");
    let e = refused_at_once(
        1,
        &[],
        &[
            "generate",
            "icosphere",
            "--triangles",
            "1",
            "-o",
            "ico.json/",
        ],
    );
    assert_eq!(e, "error: cannot write ico.json/: Not a directory");
}

#[test]
fn diff_answers_with_its_exit_status() {
    let dir = tempfile::tempdir().unwrap();
    for (name, depth) in [("one.png", "1"), ("two.png", "3")] {
        crate::commands::cli::succeeds(
            &[
                "render",
                "-q",
                "--width",
                "32",
                "--height",
                "24",
                "--max-depth",
                depth,
                "-o",
                name,
            ],
            dir.path(),
        );
    }
    let diff = |args: &[&str]| {
        let out = crate::commands::cli::raytree(&[&["diff"][..], args].concat(), dir.path());
        assert!(
            out.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        (
            out.status.code().unwrap(),
            String::from_utf8(out.stdout).unwrap(),
        )
    };
    let (code, same) = diff(&["one.png", "one.png"]);
    assert_eq!(code, 0, "{same}");
    assert!(
        same.starts_with(
            "same within tolerance 0: largest 0/255; mean absolute difference 0.000/255"
        )
    );
    let (code, different) = diff(&["one.png", "two.png"]);
    assert_eq!(code, 1, "{different}");
    assert!(different.starts_with("different: largest "), "{different}");
    assert!(different.contains("/255 > tolerance 0;"), "{different}");
    let largest: u8 = different
        .split("largest ")
        .nth(1)
        .and_then(|s| s.split('/').next())
        .and_then(|s| s.parse().ok())
        .unwrap();
    assert!(largest > 0);
    let tolerance = |t: u8| diff(&["one.png", "two.png", "--tolerance", &t.to_string()]).0;
    assert_eq!((tolerance(largest), tolerance(largest - 1)), (0, 1));
    // The answer is known before it is printed: a reader gone keeps it.
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let gone = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["diff", "one.png", "two.png"])
        .current_dir(dir.path())
        .stdout(writer)
        .output()
        .unwrap();
    assert_eq!((gone.status.code(), gone.stderr.len()), (Some(1), 0));
    // Trouble is 2, never taken for "different".
    let png = std::fs::read(dir.path().join("one.png")).unwrap();
    let e = refused_at_once(2, &[("a.png", &png)], &["diff", "a.png", "missing.png"]);
    assert_eq!(e, "error: cannot read missing.png: no such file");
    let mut small = Vec::new();
    image::RgbImage::new(2, 2)
        .write_to(
            &mut std::io::Cursor::new(&mut small),
            image::ImageFormat::Png,
        )
        .unwrap();
    let e = refused_at_once(
        2,
        &[("a.png", &png), ("b.png", &small)],
        &["diff", "a.png", "b.png"],
    );
    assert_eq!(e, "error: the images differ in size: 32×24 and 2×2");
    let e = refused_at_once(2, &[], &["diff", "a.png", "b.png", "--tolerance", "256"]);
    assert!(e.ends_with("(see raytree diff --help)"), "{e}");
}

#[test]
fn a_scripts_pixel_off_the_image_is_refused_by_inspect_as_by_lesson() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lessons = tempfile::tempdir().unwrap();
    let folder = lessons.path().join("01-off");
    std::fs::create_dir(&folder).unwrap();
    std::fs::copy(
        root.join("lessons/01-forward/lesson.toml"),
        folder.join("lesson.toml"),
    )
    .unwrap();
    let scene = root.join("scenes/whitted.json");
    let script = folder.join("steps.toml");
    std::fs::write(
        &script,
        format!(
            "title = \"Off the image\"\nscene = {:?}\npixel = [640, 10]\n\n[[stop]]\nstep = 1\nsay = \"here\"\n",
            scene.to_str().unwrap()
        ),
    )
    .unwrap();
    let expected = format!(
        "error: {}: line 3: pixel 640,10 is outside the 640×480 image (x is 0 to 639, y is 0 to 479)",
        script.display()
    );
    let inspect = refused_at_once(1, &[], &["inspect", "--script", script.to_str().unwrap()]);
    assert_eq!(inspect, expected);
    let lesson = refused_at_once(
        1,
        &[],
        &[
            "lesson",
            "1",
            "--text",
            "--lessons",
            lessons.path().to_str().unwrap(),
        ],
    );
    assert_eq!(lesson, expected);
}

/// A scene that would not fit in the memory the process may have is refused
/// before it is parsed, in one line with the figures, exit 1: not the
/// allocator's abort and a backtrace halfway (here under `ulimit -v`).
#[test]
fn a_scene_too_big_for_the_memory_is_refused_before_it_is_read() {
    if Command::new("bash").arg("-c").arg("true").status().is_err() {
        println!("skipped: a_scene_too_big_for_the_memory_is_refused_before_it_is_read: no bash");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let args = ["generate", "spheres", "--count", "200000", "-o", "big.json"];
    crate::commands::cli::succeeds(&args, dir.path());
    let out = Command::new("bash")
        .arg("-c")
        .arg("ulimit -v 150000 && exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_raytree"))
        .args(["render", "big.json", "--width", "8", "--height", "8"])
        .current_dir(dir.path())
        .env_remove("RUST_BACKTRACE")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("big.json: loading it takes about ")
            && stderr.contains(" of memory, more than the "),
        "{stderr}"
    );
    assert!(!dir.path().join("big.png").exists());
}
