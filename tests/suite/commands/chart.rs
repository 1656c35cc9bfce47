//! `raytree chart`: a small sweep through the real binary, its PNG and CSV, and
//! the figures behaving as they must (more samples come closer to the converged
//! reference; no origin offset is worse than the robust one).

use crate::commands::cli::succeeds;

#[test]
fn chart_writes_a_png_and_a_csv_whose_figures_make_sense() {
    let dir = std::env::temp_dir().join(format!("raytree-chart-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/whitted.json");
    succeeds(
        &[
            "chart", scene, "--width", "48", "--height", "36", "--runs", "1", "--size", "600x400",
            "-o", "c.png", "--csv", "c.csv",
        ],
        &dir,
    );
    let png = image::open(dir.join("c.png")).unwrap();
    assert_eq!((png.width(), png.height()), (600, 400));
    let csv = std::fs::read_to_string(dir.join("c.csv")).unwrap();
    // Labels are quoted (some hold commas): split after the closing quote.
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|l| {
            let (label, rest) = l[1..].split_once("\",").expect("a quoted label");
            std::iter::once(label).chain(rest.split(',')).collect()
        })
        .collect();
    assert_eq!(
        rows.len(),
        raytree::trace::sweep::sweep(&raytree::scene::settings::RenderSettings::default()).len()
    );
    let rmse = |label: &str| -> f64 {
        let row = rows
            .iter()
            .find(|r| r[0] == label)
            .unwrap_or_else(|| panic!("no row {label} in\n{csv}"));
        let v: f64 = row[8].parse().unwrap();
        assert!(
            v.is_finite() && row[7].parse::<f64>().unwrap() > 0.0,
            "{row:?}"
        );
        v
    };
    assert_eq!(
        rows.iter().filter(|r| r[1] == "true").count(),
        1,
        "one row is the defaults"
    );
    assert!(
        rmse("16 spp") < rmse("4 spp") && rmse("4 spp") < rmse("default"),
        "{csv}"
    );
    assert!(rmse("no offset") > rmse("default"), "{csv}");
    assert!(rmse("depth 2") > rmse("default"), "{csv}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--cost tests` counts intersection tests on one thread instead of timing:
/// two runs draw the same chart to the byte and print the same figures, so the
/// book can show it and notice when it goes stale.
#[test]
fn chart_by_counted_tests_is_the_same_on_every_run() {
    let dir = std::env::temp_dir().join(format!("raytree-chart-tests-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/whitted.json");
    let run = |name: &str| {
        let (png, csv) = (format!("{name}.png"), format!("{name}.csv"));
        let out = succeeds(
            &[
                "chart", scene, "--width", "32", "--height", "24", "--cost", "tests", "--size",
                "600x400", "-o", &png, "--csv", &csv,
            ],
            &dir,
        );
        let png = std::fs::read(dir.join(png)).unwrap();
        let csv = std::fs::read_to_string(dir.join(csv)).unwrap();
        // The counted tests per pixel, the last column; the times are not compared.
        let tests: Vec<f64> = csv
            .lines()
            .skip(1)
            .map(|l| l.rsplit(',').next().unwrap().parse().unwrap())
            .collect();
        (png, tests, String::from_utf8(out.stdout).unwrap())
    };
    let (png_a, tests_a, stdout_a) = run("a");
    let (png_b, tests_b, stdout_b) = run("b");
    assert!(png_a == png_b, "the two charts differ");
    assert_eq!(tests_a, tests_b);
    assert_eq!(stdout_a, stdout_b);
    let settings =
        raytree::trace::sweep::sweep(&raytree::scene::settings::RenderSettings::default()).len();
    assert_eq!(tests_a.len(), settings);
    assert!(tests_a.iter().all(|&t| t > 0.0), "{tests_a:?}");
    // The sweep's second setting, four samples a pixel, traces four rays
    // where the default traces one: about four times the tests.
    assert!(tests_a[1] > 3.0 * tests_a[0], "{tests_a:?}");
    let line = |label: &str| {
        stdout_a
            .lines()
            .find(|l| l.starts_with(&format!("{label}: RMSE ")))
            .unwrap_or_else(|| panic!("no line for {label} in\n{stdout_a}"))
            .to_owned()
    };
    assert!(line("default").ends_with("tests per pixel"), "{stdout_a}");
    assert_eq!(stdout_a.lines().count(), settings);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The points of the committed chart, read back from `docs/chart.csv`.
fn committed_points() -> Vec<raytree::trace::sweep::Point> {
    let csv =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/chart.csv")).unwrap();
    csv.lines()
        .skip(1)
        .map(|l| {
            let (label, rest) = l[1..].split_once("\",").expect("a quoted label");
            let f: Vec<&str> = rest.split(',').collect();
            raytree::trace::sweep::Point {
                label: label.replace("\"\"", "\""),
                settings: raytree::scene::settings::RenderSettings::default(),
                default: f[0] == "true",
                seconds: f[6].parse().unwrap(),
                tests: None,
                rmse: f[7].parse().unwrap(),
                off: f[8].parse().unwrap(),
            }
        })
        .collect()
}

#[test]
fn chart_labels_touch_their_dots_and_never_overlap() {
    let points = committed_points();
    let (_, placed) =
        raytree::views::chart::draw_with_labels(&points, "docs/chart.csv", 1200, 800).unwrap();
    assert_eq!(placed.len(), points.len(), "every point is labelled");
    for (i, a) in placed.iter().enumerate() {
        for b in &placed[i + 1..] {
            assert!(
                !a.rect.overlaps(&b.rect),
                "{} and {}",
                a.label.text,
                b.label.text
            );
        }
        // Touching its dot, or led to it: a label at a corner of its dot sits
        // the clearance (at most 8.5, the defaults' ring) and a gap of 2 plus
        // a pixel of padding away on both axes, (8.5 + 2 + 1)·√2 ≈ 16.3 from
        // the dot's center.
        let touching = |p: &raytree::figure::labels::Placed| p.rect.distance(p.anchor) <= 16.3;
        assert!(
            touching(a) || a.leader.is_some(),
            "{} floats away from its dot",
            a.label.text
        );
    }
    let default = placed.iter().find(|p| p.label.text == "default").unwrap();
    assert!(default.leader.is_none() && default.rect.distance(default.anchor) <= 16.3);
}

/// Settings that change nothing measurable land on the defaults: each shows
/// in its own color at its center, never under the defaults' marker.
#[test]
fn no_point_hides_under_the_defaults_marker() {
    let mut points = committed_points();
    // One exactly on the defaults, beside those a few pixels off it.
    let mut same = points[0].clone();
    same.label = "same as the defaults".to_owned();
    same.default = false;
    points.push(same);
    let (fig, _) =
        raytree::views::chart::draw_with_labels(&points, "docs/chart.csv", 1200, 800).unwrap();
    let (w, _) = fig.size();
    let rgb = fig.rgb();
    let orange = raytree::figure::pen::palette::REFRACTED;
    for p in points.iter().filter(|p| !p.default) {
        let at = fig.to_px(glam::DVec2::new(p.seconds.log10(), p.rmse.log10()));
        let i = (at.y.round() as usize * w as usize + at.x.round() as usize) * 3;
        let c = [rgb[i], rgb[i + 1], rgb[i + 2]];
        // Tolerance: antialiasing blends a few levels at a dot's center at most.
        let near = c.iter().zip(orange).all(|(&a, b)| a.abs_diff(b) <= 24);
        assert!(!near, "'{}' is hidden under the defaults ({c:?})", p.label);
    }
}

#[test]
fn docs_chart_png_is_drawn_from_docs_chart_csv_as_the_code_draws_today() {
    // The timing is not re-run (40 s, and noisy): the committed figures are redrawn.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/chart.png");
    let fig = raytree::views::chart::draw(
        &committed_points(),
        "scenes/whitted.json at 640×480, 5 runs each",
        1200,
        800,
    )
    .unwrap();
    crate::common::matches_golden(&fig, path.as_ref(), "chart");
}
