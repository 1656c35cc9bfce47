//! `raytree structures`: the five structures compared on two small shipped
//! scenes, its counts per ray the ones `render --stats` prints for the same
//! settings on one thread; `--from` redraws the chart to the byte from its
//! CSV; a damaged CSV is refused naming the line and the field; the grid
//! sweep walks more cells per ray as its cells shrink. No timing is asserted:
//! times move with the machine's load.

use std::path::Path;

use crate::commands::cli::{scenes, succeeds, workdir};
use crate::common::{refused, refused_with};

/// The small size every run here uses: counts are exact at any size.
const SMALL: [&str; 6] = ["--width", "40", "--height", "30", "--runs", "1"];

/// A CSV field by its header name.
fn field<'a>(header: &str, row: &'a [&'a str], name: &str) -> &'a str {
    let k = header
        .split(',')
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header}"));
    row[k]
}

/// What `render --stats --threads 1 --accel ACCEL` prints on its second line
/// for `scene`: (steps per ray, primitives per ray), as written there.
fn stats_per_ray(scene: &Path, accel: &str, dir: &Path) -> (f64, f64) {
    let out = succeeds(
        &[
            "render",
            scene.to_str().unwrap(),
            "--stats",
            "--threads",
            "1",
            "--accel",
            accel,
            "--width",
            "40",
            "--height",
            "30",
            "-o",
            "stats.png",
        ],
        dir,
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let line = text.lines().nth(1).unwrap();
    // "N tests: ... ; T per ray (S <steps word> and P primitives), ..." or, with
    // no structure, "...; T per ray, testing every object".
    let per_ray = |s: &str| s.replace(',', "").parse::<f64>().unwrap();
    let after = line.split("; ").nth(1).unwrap();
    match after.split_once(" per ray (") {
        Some((_, rest)) => {
            let steps = rest.split(' ').next().unwrap();
            let prims = rest
                .split(" and ")
                .nth(1)
                .unwrap()
                .split(' ')
                .next()
                .unwrap();
            (per_ray(steps), per_ray(prims))
        }
        None => (0.0, per_ray(after.split(' ').next().unwrap())),
    }
}

#[test]
fn structures_counts_what_render_stats_counts_and_redraws_from_its_csv() {
    let dir = workdir("structures");
    let (spheres, whitted) = (scenes().join("spheres.json"), scenes().join("whitted.json"));
    let mut args = vec![
        spheres.to_str().unwrap(),
        whitted.to_str().unwrap(),
        "--csv",
        "s.csv",
        "-o",
        "s.png",
    ];
    args.extend(SMALL);
    args.insert(0, "structures");
    let out = succeeds(&args, &dir);
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(
        table.starts_with("| scene | objects | none tests/ray"),
        "{table}"
    );
    let csv = std::fs::read_to_string(dir.join("s.csv")).unwrap();
    let mut lines = csv.lines();
    let comment = lines.next().unwrap();
    assert!(
        comment.starts_with("# ") && comment.contains("40×30") && comment.contains("load "),
        "{comment}"
    );
    let header = lines.next().unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 10, "five structures for each of two scenes");
    for row in &rows {
        let scene = scenes().join(field(header, row, "scene"));
        let accel = field(header, row, "structure");
        let (steps, prims) = stats_per_ray(&scene, accel, &dir);
        // `render --stats` writes four significant digits (views::numbers::num):
        // the same counts agree to that rounding, 5e-4 relative at most.
        for (name, want) in [("steps_per_ray", steps), ("primitives_per_ray", prims)] {
            let got: f64 = field(header, row, name).parse().unwrap();
            assert!(
                (got - want).abs() <= 5e-4 * want.abs().max(1.0),
                "{accel} on {scene:?}: {name} {got}, render --stats {want}"
            );
        }
        // Each row's tests per ray, as the table prints them, is in the table.
        let tests = raytree::views::numbers::num(
            (field(header, row, "steps").parse::<f64>().unwrap()
                + field(header, row, "primitives").parse::<f64>().unwrap())
                / field(header, row, "rays").parse::<f64>().unwrap(),
        );
        assert!(table.contains(&tests), "{tests} not in\n{table}");
    }
    // Testing every object makes more primitive tests on 2,000 spheres than
    // any structure does.
    let prims = |k: usize| {
        field(header, &rows[k], "primitives")
            .parse::<u64>()
            .unwrap()
    };
    assert!((1..5).all(|k| prims(k) * 10 < prims(0)), "{csv}");
    // The chart again from the CSV: the same bytes, and the same table.
    let again = succeeds(&["structures", "--from", "s.csv", "-o", "again.png"], &dir);
    assert_eq!(
        std::fs::read(dir.join("s.png")).unwrap(),
        std::fs::read(dir.join("again.png")).unwrap(),
        "--from redraws the chart to the byte"
    );
    assert_eq!(String::from_utf8(again.stdout).unwrap(), table);
    // A damaged CSV: refused naming its line and field, the chart not written.
    let bad = csv.replacen(",bvh,", ",kdtree,", 1);
    let line = bad.lines().position(|l| l.contains(",kdtree,")).unwrap() + 1;
    let e = refused(
        "structures-csv",
        &[("in.csv", bad.as_bytes())],
        &["structures", "--from", "in.csv", "-o", "out.png"],
    );
    assert!(
        e.contains(&format!("in.csv: line {line}: structure: 'kdtree'")),
        "{e}"
    );
    let cut = csv.lines().take(5).collect::<Vec<_>>().join("\n");
    let e = refused(
        "structures-csv-cut",
        &[("in.csv", cut.as_bytes())],
        &["structures", "--from", "in.csv", "-o", "out.png"],
    );
    assert!(e.contains("3 rows: a comparison has five per scene"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_grid_sweep_walks_more_cells_per_ray_as_they_shrink() {
    let dir = workdir("structures-sweep");
    let spheres = scenes().join("spheres.json");
    let mut args = vec![
        "structures",
        spheres.to_str().unwrap(),
        "--grid-sweep",
        "--csv",
        "g.csv",
        "-o",
        "g.png",
    ];
    args.extend(SMALL);
    succeeds(&args, &dir);
    let csv = std::fs::read_to_string(dir.join("g.csv")).unwrap();
    let header = csv.lines().nth(1).unwrap();
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(2)
        .map(|l| l.split(',').collect())
        .collect();
    let res: Vec<&str> = rows.iter().map(|r| field(header, r, "grid_res")).collect();
    assert_eq!(res, ["2", "4", "8", "16", "32", "64", "128", "160", "auto"]);
    let per_ray = |name: &str| -> Vec<f64> {
        rows[..8]
            .iter()
            .map(|r| field(header, r, name).parse().unwrap())
            .collect()
    };
    let (steps, prims) = (per_ray("steps_per_ray"), per_ray("primitives_per_ray"));
    assert!(
        steps.windows(2).all(|w| w[0] < w[1]),
        "steps per ray {steps:?}"
    );
    // The other side of the trade-off: the coarsest grid tests many times the
    // primitives the finest does.
    assert!(prims[0] > 10.0 * prims[7], "primitives per ray {prims:?}");
    let png = image::open(dir.join("g.png")).unwrap();
    assert_eq!((png.width(), png.height()), (1200, 800));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn structures_refuses_what_it_cannot_do_in_one_line() {
    let scene = scenes().join("whitted.json");
    let scene = scene.to_str().unwrap();
    let seventeen: Vec<&str> = std::iter::once("structures")
        .chain(std::iter::repeat_n(scene, 17))
        .collect();
    let e = refused_with(2, "structures-17", &[], &seventeen);
    assert!(e.contains("17 scenes given: at most 16"), "{e}");
    let e = refused_with(
        2,
        "structures-runs",
        &[],
        &["structures", scene, "--runs", "21"],
    );
    assert!(e.contains("--runs"), "{e}");
    let e = refused_with(
        2,
        "structures-accel",
        &[],
        &["structures", scene, "--accel", "bvh"],
    );
    assert!(e.contains("--accel"), "{e}");
    let e = refused_with(
        2,
        "structures-sweep-two",
        &[],
        &["structures", scene, scene, "--grid-sweep"],
    );
    assert!(e.contains("--grid-sweep: sweeps one scene, got 2"), "{e}");
    let e = refused(
        "structures-header",
        &[("in.csv", b"# x\nscene,structure\n")],
        &["structures", "--from", "in.csv"],
    );
    assert!(e.contains("in.csv: line 2: expected the header"), "{e}");
}
