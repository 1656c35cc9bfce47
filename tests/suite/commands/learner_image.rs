//! `raytree check --image`: a learner's whole image against raytree's render
//! at its size. raytree's own PPM agrees; pixels painted over are counted,
//! listed worst first with the command that checks each, and drawn with -o;
//! a bad image is one line and exit 2, never a half-written figure.

use crate::commands::cli::{raytree, scenes, workdir};

fn whitted() -> String {
    scenes().join("whitted.json").display().to_string()
}

/// raytree's own render, written as PPM (the format the Python starter writes),
/// checks clean: the render at the image's size is the same image.
#[test]
fn raytree_s_own_image_checks_clean() {
    let dir = workdir("check-image-clean");
    let ppm = dir.join("mine.ppm").display().to_string();
    let w = whitted();
    crate::commands::cli::succeeds(
        &["render", &w, "--width", "40", "--height", "30", "-o", &ppm],
        &dir,
    );
    let out = raytree(&["check", &w, "--image", &ppm], &dir);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains("every pixel agrees within 1 level (largest difference 0)"),
        "{text}"
    );
}

/// Twelve pixels painted over: exactly those are off, the worst listed first
/// (a larger change before a smaller one, then top to bottom), each with its
/// command; the JSON says the same; -o writes the figure.
#[test]
fn painted_pixels_are_counted_listed_and_drawn() {
    let dir = workdir("check-image-off");
    let png = dir.join("base.png");
    let w = whitted();
    crate::commands::cli::succeeds(
        &[
            "render",
            &w,
            "--width",
            "40",
            "--height",
            "30",
            "-o",
            &png.display().to_string(),
        ],
        &dir,
    );
    let mut img = image::open(&png).unwrap().to_rgb8();
    // Ten pixels set to black on row 3, two set to a nearby color (2 levels
    // off on one channel, just over the default tolerance of 1) on row 20.
    for x in 5..15 {
        img.put_pixel(x, 3, image::Rgb([0, 0, 0]));
    }
    for x in [7, 8] {
        let p = img.get_pixel(x, 20).0;
        img.put_pixel(x, 20, image::Rgb([p[0].wrapping_add(2).max(2), p[1], p[2]]));
    }
    let yours = dir.join("yours.png");
    img.save(&yours).unwrap();
    let y = yours.display().to_string();
    let fig = dir.join("where.png");
    let out = raytree(
        &[
            "check",
            &w,
            "--image",
            &y,
            "-o",
            &fig.display().to_string(),
            "--worst",
            "12",
        ],
        &dir,
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("12 of 1200 pixels (1.00 %)"), "{text}");
    let listed: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with('('))
        .collect();
    assert_eq!(listed.len(), 12, "{text}");
    assert!(listed[0].starts_with("  (5, 3):"), "{text}");
    assert!(listed[11].starts_with("  (8, 20): 2 levels off"), "{text}");
    assert!(
        text.contains(&format!(
            "raytree check {w} --pixel 5,3 --width 40 --height 30 TRACE.json"
        )),
        "{text}"
    );
    let figure = image::open(&fig).expect("the figure is a PNG");
    assert!(figure.width() > 80, "three panels side by side");
    let out = raytree(&["check", &w, "--image", &y, "--json"], &dir);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["format"], "raytree-image-check");
    assert_eq!(doc["pixels_off"], 12);
    assert_eq!(doc["worst"][0]["x"], 5);
    assert_eq!(out.status.code(), Some(1));
}

/// A truncated or foreign file, a missing one, or --image with --pixel: one
/// line, exit 2, and no figure left behind.
#[test]
fn bad_images_are_one_line_and_exit_2() {
    let dir = workdir("check-image-bad");
    let w = whitted();
    let png = dir.join("t.png");
    crate::commands::cli::succeeds(
        &[
            "render",
            &w,
            "--width",
            "20",
            "--height",
            "15",
            "-o",
            &png.display().to_string(),
        ],
        &dir,
    );
    let bytes = std::fs::read(&png).unwrap();
    let cut = dir.join("cut.png");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let text = dir.join("notes.ppm");
    std::fs::write(&text, "P3\n2 2\n255\n1 2 three\n").unwrap();
    let fig = dir.join("where.png");
    for args in [
        vec![
            "check",
            &w,
            "--image",
            cut.to_str().unwrap(),
            "-o",
            fig.to_str().unwrap(),
        ],
        vec!["check", &w, "--image", text.to_str().unwrap()],
        vec!["check", &w, "--image", "missing.png"],
        vec![
            "check",
            &w,
            "--image",
            png.to_str().unwrap(),
            "--pixel",
            "1,1",
        ],
    ] {
        let out = raytree(&args, &dir);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(
            err.starts_with("error:") && !err.contains("panicked"),
            "{args:?}: {err}"
        );
        assert!(!fig.exists(), "{args:?} left a figure behind");
    }
}

/// The teacher's Python solution writing its image with one whole-image
/// mistake (in the writer, where a learner makes it): raytree names the
/// mistake before the pixel list and, with it fixed, no pixel is off; the
/// unmutated image checks clean. The Python writes the linear bytes by
/// truncating, as `int(v * 255)` does, one level below rounding.
#[test]
fn whole_image_mistakes_of_the_python_writer_are_named() {
    use crate::tools::{Need, available};
    if !available("", &[Need::Python3], "runs the course's Python tracer") {
        return;
    }
    const WRITER: &str = r#"
import importlib.util, sys
sys.path.insert(0, "lessons/python")
import learner_io
spec = importlib.util.spec_from_file_location("solution", "lessons/python/teacher/solution.py")
sol = importlib.util.module_from_spec(spec)
spec.loader.exec_module(sol)
mistake, scene, out = sys.argv[1:]
encode = learner_io.srgb8
if mistake == "no-srgb":
    encode = lambda v: int(min(max(v, 0.0), 1.0) * 255.0)
def ppm(w, h, colors):
    rows = [list(colors[y * w:(y + 1) * w]) for y in range(h)]
    if mistake == "rows-flipped":
        rows.reverse()
    if mistake == "columns-mirrored":
        rows = [r[::-1] for r in rows]
    if mistake == "channels-swapped":
        rows = [[(c[2], c[1], c[0]) for c in r] for r in rows]
    body = bytes(encode(v) for r in rows for c in r for v in c)
    return b"P6\n%d %d\n255\n" % (w, h) + body
learner_io.ppm = ppm
sys.exit(learner_io.main(sol, [scene, "--width", "32", "--height", "24", "-o", out]))
"#;
    let dir = workdir("check-image-mistakes");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let w = whitted();
    for mistake in [
        "none",
        "no-srgb",
        "rows-flipped",
        "columns-mirrored",
        "channels-swapped",
    ] {
        let ppm = dir.join(format!("{mistake}.ppm")).display().to_string();
        let made = std::process::Command::new("python3")
            .args(["-c", WRITER, mistake, &w, &ppm])
            .current_dir(root)
            .output()
            .unwrap();
        assert!(
            made.status.success(),
            "{mistake}: {}",
            String::from_utf8_lossy(&made.stderr)
        );
        let out = raytree(&["check", &w, "--image", &ppm, "--json"], &dir);
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        if mistake == "none" {
            assert_eq!(out.status.code(), Some(0), "{doc:#}");
            assert_eq!(doc["mistakes"], serde_json::json!([]), "{doc:#}");
            continue;
        }
        assert_eq!(out.status.code(), Some(1), "{mistake}: {doc:#}");
        let ids: Vec<&str> = doc["mistakes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["id"].as_str().unwrap())
            .collect();
        assert_eq!(ids, [mistake], "{doc:#}");
        assert_eq!(doc["off_if_fixed"], 0, "{mistake}: {doc:#}");
        let text = raytree(&["check", &w, "--image", &ppm], &dir);
        let text = String::from_utf8_lossy(&text.stdout);
        let named = text.find("With that fixed, 0 of 768 pixels").expect(&text);
        assert!(named < text.find("the worst").unwrap(), "{text}");
    }
}
