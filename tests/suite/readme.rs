//! The README's example output is what the program prints today.
//! `RAYTREE_BLESS=1 cargo test --release readme` rewrites it.

use std::process::Command;

#[test]
fn readme_trace_example_is_current() {
    let root = env!("CARGO_MANIFEST_DIR");
    let path = format!("{root}/README.md");
    let readme = std::fs::read_to_string(&path).unwrap();
    let marker = "<!-- trace: ";
    let start = readme.find(marker).expect("the README shows a trace");
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
        "README.md's trace example is stale: RAYTREE_BLESS=1 cargo test --release readme"
    );
}

#[test]
fn readme_image_is_the_builtin_scene_as_rendered_today() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/whitted.png");
    let scene = raytree::scene::loader::whitted();
    let image = raytree::trace::render::render(&scene, &indicatif::ProgressBar::hidden()).unwrap();
    let now = raytree::io::image::to_rgb8(&image);
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::write(
            path,
            raytree::io::image_file::encode(&image, raytree::io::image_file::Format::Png).unwrap(),
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
fn readme_lists_the_inspectors_keys_as_the_help_does() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    for b in raytree::inspector::KEYS {
        let row = format!("| {} | {} |", b.keys, b.what);
        assert!(readme.contains(&row), "README.md lacks the row {row}");
    }
}

#[test]
fn readme_inspector_capture_is_the_snapshot_the_tests_check() {
    let root = env!("CARGO_MANIFEST_DIR");
    let readme = std::fs::read_to_string(format!("{root}/README.md")).unwrap();
    let marker = "<!-- inspector: ";
    let at = readme
        .find(marker)
        .expect("README.md has an inspector capture");
    let rest = &readme[at + marker.len()..];
    let file = &rest[..rest.find(" -->").unwrap()];
    let block = rest.split("```text\n").nth(1).unwrap();
    let block = &block[..block.find("```").unwrap()];
    let snapshot = std::fs::read_to_string(format!("{root}/{file}")).unwrap();
    assert!(
        block == snapshot,
        "README.md's inspector capture differs from {file} (copy it in after re-blessing)"
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
fn readme_figures_are_what_the_commands_draw_today() {
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
fn readme_forward_report_is_current() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/README.md");
    let readme = std::fs::read_to_string(path).unwrap();
    let marker = "$ raytree forward scenes/whitted.json --photons 1000000\n";
    let start = readme
        .find(marker)
        .expect("the README shows a forward report")
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
        "README.md's forward report is stale: RAYTREE_BLESS=1 cargo test --release readme"
    );
}
