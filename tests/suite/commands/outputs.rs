//! What raytree writes never destroys what it reads, and its bounds and small
//! promises hold (issue 12): outputs that are inputs and read-only outputs are
//! refused, `--threads` and the generators are bounded, `diff` reads PPM and
//! survives a closed pipe or a full disk, and every message is one line.

use crate::common::{refused, refused_with};

const SCENE: &[u8] =
    br#"{"render": {"width": 8, "height": 6}, "objects": [{"mesh": {"file": "m.obj"}}]}"#;
const MESH: &[u8] = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

#[test]
fn an_output_that_is_an_input_is_refused() {
    let files: [(&str, &[u8]); 2] = [("s.json", SCENE), ("m.obj", MESH)];
    let e = refused(
        "trace-over-scene",
        &files,
        &["trace", "s.json", "--pixel", "1,1", "-o", "s.json"],
    );
    assert_eq!(
        e,
        "error: cannot write s.json: it is an input, which this command reads (choose another output name)"
    );
    // A text trace (.txt) over a mesh whose file is named .txt.
    let e = refused(
        "trace-over-mesh",
        &[
            (
                "s.json",
                &String::from_utf8_lossy(SCENE)
                    .replace("m.obj", "m.txt")
                    .into_bytes(),
            ),
            ("m.txt", MESH),
        ],
        &["trace", "s.json", "--pixel", "1,1", "-o", "./m.txt"],
    );
    assert!(
        e.starts_with("error: cannot write ./m.txt: it is the same file as the input"),
        "{e}"
    );
    // Two of the command's own names for one file: the command line's fault.
    let e = refused_with(
        2,
        "chart-csv-over-png",
        &files,
        &["chart", "s.json", "-o", "c.png", "--csv", "c.png"],
    );
    assert_eq!(
        e,
        "error: cannot write c.png: the CSV figures and the chart need two files (see raytree chart --help)"
    );
    let mut png = Vec::new();
    image::RgbImage::new(2, 2)
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    let e = crate::common::refused_with(
        2,
        "diff-figure-over-an-image",
        &[("a.png", &png), ("b.png", &png)],
        &["diff", "a.png", "b.png", "-o", "b.png"],
    );
    assert_eq!(
        e,
        "error: cannot write b.png: it is an input, which this command reads (choose another output name)"
    );
    let e = refused_with(
        2,
        "icosphere-over-its-mesh",
        &[],
        &["generate", "icosphere", "--triangles", "20", "-o", "x.obj"],
    );
    assert_eq!(
        e,
        "error: cannot write x.obj: a generated scene is a .json file (its mesh goes beside it, as .obj) (see raytree generate icosphere --help)"
    );
    let e = refused_with(
        2,
        "spheres-as-png",
        &[],
        &["generate", "spheres", "--count", "3", "-o", "x.png"],
    );
    assert_eq!(
        e,
        "error: cannot write x.png: a generated scene is a .json file (see raytree generate spheres --help)"
    );
}

#[cfg(unix)]
#[test]
fn a_read_only_output_is_refused_not_replaced() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("ro.png");
    std::fs::write(&out, b"keep").unwrap();
    std::fs::set_permissions(&out, std::fs::Permissions::from_mode(0o444)).unwrap();
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["render", "--width", "8", "--height", "6", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(
        stderr
            .trim_end()
            .ends_with("ro.png: it is read-only (make it writable, or choose another name)"),
        "{stderr}"
    );
    assert_eq!(std::fs::read(&out).unwrap(), b"keep");
    assert_eq!(
        std::fs::metadata(&out).unwrap().permissions().mode() & 0o777,
        0o444
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "no temporary file left"
    );
}

#[test]
fn threads_and_generators_are_bounded() {
    let e = refused_with(2, "threads-huge", &[], &["render", "--threads", "10000"]);
    assert_eq!(
        e,
        "error: invalid value '10000' for '--threads <N>': must be a whole number from 1 to 256 (see raytree render --help)"
    );
    let e = refused_with(2, "threads-zero", &[], &["render", "--threads", "0"]);
    assert_eq!(
        e,
        "error: invalid value '0' for '--threads <N>': must be a whole number from 1 to 256 (see raytree render --help)"
    );
    // The generator estimates first; a 2 GB address-space limit is what it may take.
    let dir = tempfile::tempdir().unwrap();
    let run = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v 2000000 && exec {} generate spheres --count 10000000 -o big.json",
            env!("CARGO_BIN_EXE_raytree")
        ))
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.starts_with(
            "error: making 10000000 spheres needs about 2.5 GB of memory, more than the "
        ) && stderr.lines().count() == 1,
        "{stderr}"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn diff_reads_ppm_and_survives_closed_and_full_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let raytree = env!("CARGO_BIN_EXE_raytree");
    for out in ["a.ppm", "b.png"] {
        let made = std::process::Command::new(raytree)
            .args(["render", "--width", "8", "--height", "6", "-q", "-o", out])
            .current_dir(dir.path())
            .status()
            .unwrap();
        assert!(made.success());
    }
    let same = std::process::Command::new(raytree)
        .args(["diff", "a.ppm", "b.png"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(
        same.status.success(),
        "{}",
        String::from_utf8_lossy(&same.stderr)
    );
    assert!(
        String::from_utf8_lossy(&same.stdout).starts_with(
            "same within tolerance 0: largest 0/255; mean absolute difference 0.000/255"
        )
    );
    // Standard output closed before raytree writes: quiet, exit 0.
    let mut child = std::process::Command::new(raytree)
        .args(["diff", "a.ppm", "b.png"])
        .current_dir(dir.path())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let closed = child.wait_with_output().unwrap();
    assert_eq!(
        closed.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&closed.stderr)
    );
    assert!(closed.stderr.is_empty());
    // A full disk: one line, exit 2 (diff's trouble; 1 says the images differ).
    let full = std::process::Command::new(raytree)
        .args(["diff", "a.ppm", "b.png"])
        .current_dir(dir.path())
        .stdout(std::fs::File::create("/dev/full").unwrap())
        .output()
        .unwrap();
    assert_eq!(full.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&full.stderr),
        "error: cannot write to standard output: No space left on device\n"
    );
}

#[test]
fn small_promises_hold() {
    let e = refused(
        "diagram-small",
        &[],
        &["diagram", "--pixel", "1,1", "--size", "64x64"],
    );
    assert!(
        e.starts_with("error: a 64×64 figure leaves ")
            && e.ends_with("the drawing needs at least 40×40 (try 400x300 or more)"),
        "{e}"
    );
    let e = refused_with(
        2,
        "diagram-depth-0",
        &[],
        &["diagram", "--pixel", "1,1", "--depth", "0"],
    );
    assert!(
        e.contains("'--depth <D>'") && e.ends_with("(see raytree diagram --help)"),
        "{e}"
    );
    let e = refused_with(2, "usage-one-line", &[], &["render", "--bogus"]);
    assert_eq!(
        e,
        "error: unexpected argument '--bogus' found (see raytree render --help)"
    );
    // The one line keeps what clap's message names: the missing arguments,
    // the possible values and a near miss.
    let e = refused_with(2, "usage-missing", &[], &["trace"]);
    assert!(
        e.starts_with(
            "error: the following required arguments were not provided: <--pixel <X,Y>|--ray"
        ),
        "{e}"
    );
    let e = refused_with(2, "usage-values", &[], &["render", "--weights", "frenel"]);
    assert_eq!(
        e,
        "error: invalid value 'frenel' for '--weights <WEIGHTS>' [possible values: constant, \
         schlick, fresnel]; tip: a similar value exists: 'fresnel' (see raytree render --help)"
    );
    // A negative number is a value, refused for what it is.
    let e = refused_with(2, "usage-negative", &[], &["forward", "--pupil", "-1"]);
    assert_eq!(
        e,
        "error: invalid value '-1' for '--pupil <R>': must be from 1e-9 to 1e9, got -1 (see raytree forward --help)"
    );
    let e = refused_with(
        2,
        "usage-generate",
        &[],
        &["generate", "grid", "--size", "0x0x0"],
    );
    assert!(e.ends_with("(see raytree generate grid --help)"), "{e}");
    // --help in the user's words: no rustdoc links or paths.
    let commands: &[&[&str]] = &[
        &[],
        &["render"],
        &["trace"],
        &["diagram"],
        &["inspect"],
        &["chart"],
        &["diff"],
        &["generate"],
        &["generate", "spheres"],
        &["generate", "grid"],
        &["generate", "icosphere"],
    ];
    for command in commands {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(*command)
            .arg("--help")
            .output()
            .unwrap();
        assert!(out.status.success());
        let help = String::from_utf8(out.stdout).unwrap();
        for rustdoc in ["[`", "`]", "crate::", "Self::"] {
            assert!(
                !help.contains(rustdoc),
                "{command:?} --help holds {rustdoc}:\n{help}"
            );
        }
    }
}

/// A file name is data, not a command to the terminal: a "wrote" line escapes
/// its control characters as an error does (issue 29).
#[cfg(unix)]
#[test]
fn a_success_line_escapes_the_file_names_it_names() {
    let dir = tempfile::tempdir().unwrap();
    let scene = br#"{"render": {"width": 4, "height": 3}, "objects": []}"#;
    std::fs::write(dir.path().join("a\u{1b}]0;pwned\u{7}.json"), scene).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args([
            "render",
            "a\u{1b}]0;pwned\u{7}.json",
            "-o",
            "b\u{1b}[2J.png",
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains(['\u{1b}', '\u{7}']), "{stderr:?}");
    assert!(stderr.starts_with("wrote b\\u{1b}[2J.png ("), "{stderr:?}");
    assert!(dir.path().join("b\u{1b}[2J.png").exists());
    // The default output name of a trace: the scene's stem, escaped when named.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(["render", "a\u{1b}]0;pwned\u{7}.json"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.starts_with("wrote a\\u{1b}]0;pwned\\u{7}.png ("),
        "{stderr:?}"
    );
    assert!(dir.path().join("a\u{1b}]0;pwned\u{7}.png").exists());
}

/// A default output name keeps the bytes of its scene's name, even when they
/// are not UTF-8 (`\xff.json` writes `\xff.png`, not `\u{fffd}.png`).
#[cfg(unix)]
#[test]
fn a_default_output_name_keeps_the_scene_names_bytes() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let dir = tempfile::tempdir().unwrap();
    let scene = br#"{"render": {"width": 4, "height": 3}, "objects": []}"#;
    std::fs::write(dir.path().join(OsStr::from_bytes(b"\xff.json")), scene).unwrap();
    for (command, made) in [
        (&["render"][..], &b"\xff.png"[..]),
        (&["chart"][..], &b"\xff-chart.png"[..]),
        (&["render", "--aov", "depth"][..], &b"\xff-depth.png"[..]),
    ] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(&command[..1])
            .arg(OsStr::from_bytes(b"\xff.json"))
            .args(&command[1..])
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{command:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            dir.path().join(OsStr::from_bytes(made)).exists(),
            "{command:?}: {:?}",
            std::fs::read_dir(dir.path())
                .unwrap()
                .map(|e| e.unwrap().file_name())
                .collect::<Vec<_>>()
        );
    }
}

/// A scene with nothing to see renders (a teacher may start from an empty
/// scene), with one line on standard error saying why the image is plain;
/// --quiet keeps it quiet, and a whole scene says nothing of the kind.
#[test]
fn a_scene_without_objects_or_lights_renders_with_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let small = r#""render": {"width": 4, "height": 3}"#;
    let sphere = r#""objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}}]"#;
    let light = r#""lights": [{"position": [0, 5, 5]}]"#;
    for (name, body, said) in [
        (
            "bare",
            small.to_owned(),
            Some("bare.json has no objects and no lights: every pixel is the background"),
        ),
        (
            "dark",
            format!("{small}, {sphere}"),
            Some("dark.json has no lights: surfaces show the ambient light alone"),
        ),
        (
            "void",
            format!("{small}, {light}"),
            Some("void.json has no objects: every pixel is the background"),
        ),
        ("whole", format!("{small}, {sphere}, {light}"), None),
    ] {
        let file = format!("{name}.json");
        std::fs::write(dir.path().join(&file), format!("{{{body}}}")).unwrap();
        let out = crate::commands::cli::succeeds(&["render", &file], dir.path());
        let err = String::from_utf8(out.stderr).unwrap();
        let notes: Vec<&str> = err.lines().filter(|l| l.starts_with("note: ")).collect();
        let want: Vec<String> = said.map(|s| format!("note: {s}")).into_iter().collect();
        assert_eq!(notes, want, "{name}: {err}");
        let quiet = crate::commands::cli::succeeds(&["render", &file, "-q"], dir.path());
        assert!(quiet.stderr.is_empty(), "{name}");
    }
}

/// The library's and the OS's words are replaced by what the user can act on:
/// the folder that is missing, the file that is not an image.
#[test]
fn a_missing_folder_and_a_file_that_is_no_image_are_named() {
    let e = refused(
        "no-folder",
        &[("s.json", b"{}")],
        &["render", "s.json", "-o", "nodir/out.png"],
    );
    assert_eq!(
        e,
        "error: cannot write nodir/out.png: the folder nodir does not exist"
    );
    let e = refused_with(
        2,
        "diff-json",
        &[("s.json", b"{}")],
        &["diff", "s.json", "s.json"],
    );
    assert_eq!(
        e,
        "error: s.json: not a PNG or PPM image, the kinds raytree reads"
    );
}
