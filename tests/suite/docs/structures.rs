//! docs/structures.md is today's: each table it shows is what `raytree
//! structures --from` prints for the CSV its command wrote, each chart that
//! CSV redrawn to the byte, and the CSV's counts (rays, traversal steps and
//! primitive tests, exact on one thread) are what `render --stats` counts now
//! for the same scene, structure and settings. Times are not checked: they
//! move with the machine's load, and the page says the load it had.
//!
//! (The BVH's column went stale once: shadow rays began walking its boxes in
//! their stored order, and 2,000 spheres took 22.1 tests a ray where the page
//! still said 23.0.)

use std::path::Path;

use crate::commands::cli::succeeds;
use crate::tools::{Need, available};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The words of a documented command, `{a,b}` expanded as a shell would and
/// the line continuations joined.
fn words(command: &str) -> Vec<String> {
    let mut out = Vec::new();
    for word in command.replace("\\\n", " ").split_whitespace() {
        match (word.find('{'), word.find('}')) {
            (Some(open), Some(close)) if open < close => {
                let (head, tail) = (&word[..open], &word[close + 1..]);
                for part in word[open + 1..close].split(',') {
                    out.push(format!("{head}{part}{tail}"));
                }
            }
            _ => out.push(word.to_owned()),
        }
    }
    out
}

/// Each `raytree structures … --csv FILE` command of the page, as words.
fn documented_runs(page: &str) -> Vec<Vec<String>> {
    page.split("```sh\n")
        .skip(1)
        .filter_map(|block| block.split("```").next())
        .flat_map(|block| block.split("\nraytree ").map(str::to_owned))
        .map(|c| words(c.trim_start_matches("raytree ")))
        .filter(|w| w.first().is_some_and(|c| c == "structures") && w.iter().any(|a| a == "--csv"))
        .collect()
}

/// The value after `flag` in `args`.
fn value<'a>(args: &'a [String], flag: &str) -> Option<&'a str> {
    let at = args.iter().position(|a| a == flag)?;
    args.get(at + 1).map(String::as_str)
}

/// What `render --stats` printed: (rays, steps, primitives) from its first
/// two lines, "N rays: …" and "N tests: … M primitives; …" (all of them
/// primitives when no structure is walked).
fn counted(stats: &str) -> (u64, u64, u64) {
    let number = |s: &str| s.replace(',', "").parse::<u64>().unwrap();
    let mut lines = stats.lines();
    let rays = number(lines.next().unwrap().split(' ').next().unwrap());
    let tests_line = lines.next().unwrap();
    let tests = number(tests_line.split(' ').next().unwrap());
    let head = tests_line.split(';').next().unwrap();
    let primitives = head
        .split(", ")
        .find_map(|part| part.strip_suffix(" primitives"))
        .map_or(tests, |p| number(p.rsplit(' ').next().unwrap()));
    (rays, tests - primitives, primitives)
}

#[test]
fn the_structures_page_shows_todays_counts_and_its_own_tables() {
    let page = std::fs::read_to_string(root().join("docs/structures.md")).unwrap();
    let runs = documented_runs(&page);
    assert!(runs.len() >= 3, "{} structures commands found", runs.len());
    let dir = crate::commands::cli::workdir("structures-page");
    let mut checked = 0;
    for run in &runs {
        let csv = value(run, "--csv").unwrap();
        let png = value(run, "-o").unwrap();
        let needs_spd = run.iter().any(|a| a.starts_with("../shared/spd/"));
        if needs_spd && !available(csv, &[Need::Spd], "its scenes are the SPD's") {
            continue;
        }
        shows_its_table_and_chart(&page, csv, png, &dir);
        checked += counts_again(run, csv, &dir);
    }
    assert!(checked > 0 || !crate::tools::on_ci(), "no row checked");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The page shows the table `raytree structures --from CSV` prints, and its
/// chart `png` is that CSV redrawn, to the byte.
fn shows_its_table_and_chart(page: &str, csv: &str, png: &str, dir: &Path) {
    let redrawn = dir.join("redrawn.png");
    let from = succeeds(
        &[
            "structures",
            "--from",
            root().join(csv).to_str().unwrap(),
            "-o",
            redrawn.to_str().unwrap(),
        ],
        root(),
    );
    let table = String::from_utf8(from.stdout).unwrap();
    assert!(
        page.contains(table.trim()),
        "docs/structures.md does not show what `raytree structures --from {csv}` prints:\n{table}"
    );
    assert!(
        std::fs::read(&redrawn).unwrap() == std::fs::read(root().join(png)).unwrap(),
        "{png} is not {csv} redrawn"
    );
}

/// The CSV's counts, each row rendered again by the page's command `run`;
/// how many rows were checked. Rows that traced for over a second on one
/// thread are left out (testing every object of a thousand-object scene, the
/// coarsest grids): the suite stays quick, and the rows kept walk every
/// structure and every scene.
fn counts_again(run: &[String], csv: &str, dir: &Path) -> usize {
    let text = std::fs::read_to_string(root().join(csv)).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let jobs: Vec<Row> = rows
        .iter()
        .map(|cells| Row {
            header: &header,
            cells,
        })
        .filter(|r| r.get("trace_seconds_median").parse::<f64>().unwrap() <= 1.0)
        .collect();
    // Two at a time: the machine has two cores.
    let (even, odd): (Vec<_>, Vec<_>) = jobs.iter().enumerate().partition(|(i, _)| i % 2 == 0);
    std::thread::scope(|s| {
        s.spawn(|| {
            odd.iter()
                .for_each(|(_, r)| counts_the_same(run, csv, r, dir))
        });
        even.iter()
            .for_each(|(_, r)| counts_the_same(run, csv, r, dir));
    });
    jobs.len()
}

/// One line of a CSV, its cells found by the header's names.
struct Row<'a> {
    header: &'a [&'a str],
    cells: &'a [&'a str],
}

impl Row<'_> {
    /// The cell of the column `name`.
    fn get(&self, name: &str) -> &str {
        self.cells[self.header.iter().position(|h| *h == name).unwrap()]
    }
}

/// `render --stats` of the row's scene through its structure, at the size and
/// protocol of the page's command `run`, counts the row's rays, steps and
/// primitive tests.
fn counts_the_same(run: &[String], csv: &str, row: &Row, dir: &Path) {
    let name = row.get("scene");
    let scene = run[1..]
        .iter()
        .take_while(|a| !a.starts_with("--"))
        .find(|s| s.ends_with(&format!("/{name}")))
        .unwrap_or_else(|| panic!("{csv}: no scene {name} in its command"));
    let structure = row.get("structure");
    let out = dir.join(format!("{name}-{structure}.png"));
    let mut args = vec![
        "render",
        scene.as_str(),
        "--stats",
        "--threads",
        "1",
        "--accel",
        structure,
        "-o",
        out.to_str().unwrap(),
    ];
    for flag in ["--protocol", "--width", "--height"] {
        if let Some(v) = value(run, flag) {
            args.extend([flag, v]);
        }
    }
    let grid_res = row.get("grid_res");
    if !grid_res.is_empty() {
        args.extend(["--grid-res", grid_res]);
    }
    let stats = String::from_utf8(succeeds(&args, root()).stdout).unwrap();
    let number = |c: &str| row.get(c).parse::<u64>().unwrap();
    let documented = (number("rays"), number("steps"), number("primitives"));
    assert_eq!(
        counted(&stats),
        documented,
        "{csv}: {name} through {structure} (grid_res {grid_res:?}) counts (rays, steps, primitives) differently now; remake the page with its command",
    );
}

#[test]
fn a_documented_command_is_read_as_a_shell_reads_it() {
    assert_eq!(
        words("structures scenes/{a,b}.json \\\n    --width 8"),
        [
            "structures",
            "scenes/a.json",
            "scenes/b.json",
            "--width",
            "8"
        ]
    );
    assert_eq!(
        counted("10 rays: 8 primary\n30 tests: 20 box tests, 10 primitives; 3 per ray (…)\n"),
        (10, 20, 10)
    );
    assert_eq!(
        counted(
            "10 rays: 8 primary\n1,234 tests: 0 box tests, 1,234 primitives; 123.4 per ray, testing every object\n"
        ),
        (10, 0, 1234)
    );
}
