//! The README and the page it sends readers to for each command,
//! `docs/commands.md`, show what the program prints and draws today, and every
//! command the README shows runs. `RAYTREE_BLESS=1 cargo test --release readme`
//! rewrites the example output and figures.

use std::path::Path;
use std::process::Command;

/// The page explaining each command, where the README's long examples live.
const COMMANDS_PAGE: &str = "docs/commands.md";

#[test]
fn trace_example_is_current() {
    let root = env!("CARGO_MANIFEST_DIR");
    let path = format!("{root}/{COMMANDS_PAGE}");
    let readme = std::fs::read_to_string(&path).unwrap();
    let marker = "<!-- trace: ";
    let start = readme.find(marker).expect("docs/commands.md shows a trace");
    let args_end = readme[start..].find(" -->").unwrap() + start;
    let args: Vec<&str> = readme[start + marker.len()..args_end]
        .split_whitespace()
        .collect();
    let block_start = readme[args_end..].find("```text\n").unwrap() + args_end + "```text\n".len();
    let block_end = readme[block_start..].find("```").unwrap() + block_start;

    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .arg("trace")
        .args(&args)
        .current_dir(root)
        .output()
        .unwrap();
    assert!(out.status.success());
    let now = String::from_utf8(out.stdout).unwrap();
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::write(
            &path,
            format!("{}{now}{}", &readme[..block_start], &readme[block_end..]),
        )
        .unwrap();
        return;
    }
    assert_eq!(
        &readme[block_start..block_end],
        now,
        "docs/commands.md's trace example is stale: RAYTREE_BLESS=1 cargo test --release readme"
    );
}

#[test]
fn readme_image_is_the_builtin_scene_as_rendered_today() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/whitted.png");
    let scene = raytree::scene::loader::whitted();
    let image =
        raytree::trace::render::render(&scene, &raytree::trace::progress::Progress::QUIET).unwrap();
    let now = raytree::io::image::to_rgb8(&image);
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::write(
            path,
            raytree::io::image::file::encode(&image, raytree::io::image::file::Format::Png)
                .unwrap(),
        )
        .unwrap();
        return;
    }
    let shown = image::open(path).unwrap().to_rgb8();
    assert_eq!((shown.width(), shown.height()), (image.width, image.height));
    assert!(
        shown.as_raw() == &now,
        "docs/whitted.png is stale: RAYTREE_BLESS=1 cargo test --release readme"
    );
}

#[test]
fn commands_page_lists_the_inspectors_keys_as_the_help_does() {
    let root = env!("CARGO_MANIFEST_DIR");
    let readme = std::fs::read_to_string(format!("{root}/{COMMANDS_PAGE}")).unwrap();
    for b in raytree::inspector::KEYS {
        let row = format!("| {} | {} |", b.keys, b.what);
        assert!(readme.contains(&row), "{COMMANDS_PAGE} lacks the row {row}");
    }
}

#[test]
fn inspector_capture_is_the_snapshot_the_tests_check() {
    let root = env!("CARGO_MANIFEST_DIR");
    let readme = std::fs::read_to_string(format!("{root}/{COMMANDS_PAGE}")).unwrap();
    let marker = "<!-- inspector: ";
    let at = readme
        .find(marker)
        .expect("docs/commands.md has an inspector capture");
    let rest = &readme[at + marker.len()..];
    let file = &rest[..rest.find(" -->").unwrap()];
    let block = rest.split("```text\n").nth(1).unwrap();
    let block = &block[..block.find("```").unwrap()];
    let snapshot = std::fs::read_to_string(format!("{root}/{file}")).unwrap();
    assert!(
        block == snapshot,
        "{COMMANDS_PAGE}'s inspector capture differs from {file} (copy it in after re-blessing)"
    );
}

/// Runs the binary from the project's root (so captions name `scenes/…`),
/// writing into a fresh folder; returns its standard output.
fn run_in_root(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn figures_are_what_the_commands_draw_today() {
    let root = env!("CARGO_MANIFEST_DIR");
    let dir = std::env::temp_dir().join(format!("raytree-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let cases: [(&str, Vec<&str>); 2] = [
        (
            "whitted-shadow-key.png",
            vec!["render", "scenes/whitted.json", "--aov", "shadow=key", "-q"],
        ),
        (
            "whitted-strip-max_depth.png",
            vec![
                "strip",
                "scenes/whitted.json",
                "--vary",
                "max_depth=1..5",
                "-q",
            ],
        ),
    ];
    for (name, args) in cases {
        let fresh = dir.join(name);
        let fresh = fresh.to_str().unwrap();
        run_in_root(&[&args[..], &["-o", fresh]].concat());
        let shown = format!("{root}/docs/{name}");
        if std::env::var_os("RAYTREE_BLESS").is_some() {
            std::fs::copy(fresh, &shown).unwrap();
            continue;
        }
        let (now, then) = (
            image::open(fresh).unwrap().to_rgb8(),
            image::open(&shown).unwrap().to_rgb8(),
        );
        assert_eq!(now.dimensions(), then.dimensions(), "{name}");
        let worst = crate::common::worst_difference(now.as_raw(), then.as_raw());
        assert!(
            worst <= crate::common::FIGURE_TOLERANCE,
            "docs/{name} is stale: RAYTREE_BLESS=1 cargo test --release readme"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn forward_report_is_current() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/commands.md");
    let readme = std::fs::read_to_string(path).unwrap();
    let marker = "$ raytree forward scenes/whitted.json --photons 1000000\n";
    let start = readme
        .find(marker)
        .expect("docs/commands.md shows a forward report")
        + marker.len();
    let end = readme[start..].find("```").unwrap() + start;
    let out =
        std::env::temp_dir().join(format!("raytree-readme-forward-{}.png", std::process::id()));
    let now = run_in_root(&[
        "forward",
        "scenes/whitted.json",
        "--photons",
        "1000000",
        "-o",
        out.to_str().unwrap(),
    ]);
    let _ = std::fs::remove_file(&out);
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::write(path, format!("{}{now}{}", &readme[..start], &readme[end..])).unwrap();
        return;
    }
    assert_eq!(
        &readme[start..end],
        now,
        "docs/commands.md's forward report is stale: RAYTREE_BLESS=1 cargo test --release readme"
    );
}

/// The program's arguments on each command line of the README's code blocks,
/// in order: lines starting `raytree ` or `cargo run --release -- ` (the same
/// program), an optional `$ ` prompt and a trailing `# comment` left out.
fn readme_commands(readme: &str) -> Vec<Vec<String>> {
    let mut commands = Vec::new();
    let mut in_block = false;
    for line in readme.lines() {
        if line.trim_start().starts_with("```") {
            in_block = !in_block;
            continue;
        }
        if !in_block {
            continue;
        }
        let line = line.trim().trim_start_matches("$ ");
        let line = line.split(" #").next().unwrap();
        let Some(args) = line
            .strip_prefix("raytree ")
            .or_else(|| line.strip_prefix("cargo run --release -- "))
        else {
            continue;
        };
        // Split on spaces as a shell would only when nothing is quoted,
        // substituted or redirected.
        assert!(
            !args.contains(['\'', '"', '`', '$', '|', '>', '<', ';', '&', '\\']),
            "README.md: split this command by hand in the test: {line}"
        );
        let args: Vec<String> = args.split_whitespace().map(str::to_owned).collect();
        // Outputs land in the copy the test runs in, never in the repository.
        assert!(
            args.iter()
                .all(|a| !a.starts_with('/') && !a.split('/').any(|part| part == "..")),
            "README.md: a command that reaches outside the repository: {line}"
        );
        commands.push(args);
    }
    commands
}

/// Copies the folder `from` into `to`, files and subfolders.
fn copy_folder(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_folder(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).unwrap();
        }
    }
}

/// What a README command needs that this machine may lack, if anything.
fn missing_for(args: &[String], lecture: Option<&Path>) -> Option<&'static str> {
    if args[0] != "postscript" {
        return None;
    }
    let slips_only = args.iter().any(|a| a == "--slips");
    if !slips_only && Command::new("gs").arg("--version").output().is_err() {
        return Some("Ghostscript (gs) is not installed (.ci/run installs it)");
    }
    // Without a SOURCE, the command reads the lecture.
    let takes_value = ["-o", "--output", "--timeout"];
    let source = args[1..]
        .iter()
        .enumerate()
        .any(|(k, a)| !a.starts_with('-') && (k == 0 || !takes_value.contains(&args[k].as_str())));
    if !source && lecture.is_none() {
        return Some("the lecture is not beside the repository (../shared/lecture-raytracing.md)");
    }
    None
}

#[test]
fn every_command_in_the_readme_runs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let commands = readme_commands(&readme);
    assert!(commands.len() >= 12, "{commands:?}");

    // A copy of what the commands read, run from as from the repository's root:
    // the scenes, the lessons (`raytree lesson` reads ./lessons), any other
    // top-level folder an argument names, and the lecture beside it as
    // `postscript` looks for it.
    let tmp = tempfile::tempdir().unwrap();
    let copy = tmp.path().join("raytree");
    let mut folders = vec!["scenes".to_owned(), "lessons".to_owned()];
    for arg in commands.iter().flatten() {
        let first = arg.split('/').next().unwrap();
        if arg.contains('/') && root.join(first).is_dir() && !folders.iter().any(|f| f == first) {
            folders.push(first.to_owned());
        }
    }
    for folder in &folders {
        copy_folder(&root.join(folder), &copy.join(folder));
    }
    let lecture = root
        .ancestors()
        .map(|d| d.join("shared/lecture-raytracing.md"))
        .find(|p| p.is_file());
    if let Some(lecture) = &lecture {
        std::fs::create_dir_all(tmp.path().join("shared")).unwrap();
        std::fs::copy(lecture, tmp.path().join("shared/lecture-raytracing.md")).unwrap();
    }

    for args in &commands {
        let shown = format!("raytree {}", args.join(" "));
        if let Some(why) = missing_for(args, lecture.as_deref()) {
            println!("skipped `{shown}`: {why}");
            continue;
        }
        let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
            .args(args)
            .current_dir(&copy)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        if args[0] == "inspect" {
            // The inspector needs a terminal, and the test has none: it reads
            // its arguments, the scene and the pixel first, so this refusal
            // means all of them were accepted. inspector/tmux.rs drives it in
            // a real terminal.
            assert_eq!(
                (out.status.code(), stderr.as_ref()),
                (
                    Some(1),
                    "error: raytree inspect needs a terminal (standard output is not one)\n"
                ),
                "README.md: `{shown}`"
            );
            continue;
        }
        // `raytree lesson N` prints its step-through when the output is not a
        // terminal, as here; the other commands run as they would for a reader.
        // diff answers 1 for images that differ, as the README's do.
        let answer = if args[0] == "diff" { Some(1) } else { Some(0) };
        assert_eq!(
            out.status.code(),
            answer,
            "README.md: `{shown}` failed: {stderr}"
        );
    }
}

#[test]
fn the_readme_shows_every_command() {
    let out = Command::new(env!("CARGO_BIN_EXE_raytree"))
        .arg("--help")
        .output()
        .unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    let names = crate::common::command_names(&help);
    assert!(
        !names.is_empty(),
        "raytree --help lists no commands: {help}"
    );
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let commands = readme_commands(&readme);
    for name in names {
        assert!(
            commands.iter().any(|args| args[0] == name),
            "README.md has no example of `raytree {name}`"
        );
    }
}

/// The Embree comparisons' one ratio is against Embree's time as measured
/// (docs/performance.md says why): the "net" ratio subtracted Embree's own
/// per-call cost along with the binding's, and is gone from the scripts'
/// output and from what they measure (the native one included).
#[test]
fn the_embree_comparison_prints_no_net_ratio() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for file in [
        "benches/embree/compare.sh",
        "benches/embree/embree_rays.py",
        "benches/embree/native.sh",
        "benches/embree_native.rs",
    ] {
        let text = std::fs::read_to_string(root.join(file)).unwrap();
        for word in ["net", "overhead"] {
            let found = text
                .split(|c: char| !c.is_alphanumeric())
                .any(|w| w.eq_ignore_ascii_case(word));
            assert!(!found, "{file} still has a {word:?}");
        }
    }
}
