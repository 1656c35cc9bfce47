//! The efficiency slide's structures compared, measured: each scene rendered
//! through every structure (or through the grid at a sweep of resolutions),
//! counting its traversal steps and primitive tests per ray on one thread,
//! timing its build and its trace; and the figures as CSV, written and read
//! back strictly, so a chart can be redrawn from them without rendering.
//! [`crate::views::structures_chart`] draws them.
//!
//! Everything runs on one thread. The counts are then exact and the same on
//! every run (each thread remembers its own recent shadow blockers, so on
//! several threads they would depend on scheduling), and the times are per
//! core, which is what compares structures rather than machines.

use std::time::Instant;

use crate::geometry::structures::Built;
use crate::methods::{Accel, Level};
use crate::scene::Scene;
use crate::trace::progress::Progress;
use crate::trace::render::{render_counting_with, render_with_tracer};
use crate::trace::tracer::Tracer;

/// The five choices of `--accel`, in the order of the efficiency slide's
/// story: nothing, then the hierarchy of objects, then the subdivisions of space.
pub const STRUCTURES: [Accel; 5] = [
    Accel::None,
    Accel::Bvh,
    Accel::Grid,
    Accel::Octree,
    Accel::Bsp,
];

/// The grid resolutions of the sweep (cells along the scene's longest side),
/// doubling from far too coarse to the largest a user may ask for; the auto
/// rule is measured after them.
pub const GRID_SIDES: [u32; 8] = [2, 4, 8, 16, 32, 64, 128, 160];

/// Most scenes one comparison takes: each costs minutes at the SPD's size.
pub const MAX_SCENES: usize = 16;
/// Most timed runs per structure.
pub const MAX_RUNS: usize = 20;

/// What a comparison measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Every scene through each of [`STRUCTURES`].
    Structures,
    /// One scene through the grid at each of [`GRID_SIDES`], then auto.
    GridSweep,
}

/// One setting measured on one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The scene's file name.
    pub scene: String,
    /// The structure (never [`Accel::Auto`]).
    pub structure: Accel,
    /// For the grid, the resolution asked for; `None` for the others.
    pub grid_res: Option<Level>,
    /// For the grid, the cells it was built with along x, y and z.
    pub grid_cells: Option<[usize; 3]>,
    /// The scene's objects.
    pub objects: u64,
    /// Rays of every kind in the counted render.
    pub rays: u64,
    /// Traversal steps: boxes tested, or cells or nodes walked.
    pub steps: u64,
    /// Primitive tests.
    pub primitives: u64,
    /// Seconds to build the structure.
    pub build_seconds: f64,
    /// Each timed render's seconds, in the order they ran.
    pub run_seconds: Vec<f64>,
}

impl Row {
    /// Traversal steps per ray.
    pub fn steps_per_ray(&self) -> f64 {
        self.steps as f64 / self.rays as f64
    }

    /// Primitive tests per ray.
    pub fn primitives_per_ray(&self) -> f64 {
        self.primitives as f64 / self.rays as f64
    }

    /// Every intersection test per ray: the steps and the primitive tests.
    pub fn tests_per_ray(&self) -> f64 {
        (self.steps + self.primitives) as f64 / self.rays as f64
    }

    /// The median of the timed renders (the upper one of an even count, as
    /// [`crate::trace::sweep`] takes it): one slow run on a busy machine does
    /// not move it.
    pub fn trace_seconds(&self) -> f64 {
        let mut t = self.run_seconds.clone();
        t.sort_by(f64::total_cmp);
        t.get(t.len() / 2).copied().unwrap_or(f64::NAN)
    }

    /// The setting as a reader names it: `bvh`, `grid 16`, `grid auto`.
    pub fn label(&self) -> String {
        match self.grid_res {
            Some(level) if self.structure == Accel::Grid => format!("grid {level}"),
            _ => self.structure.name().to_owned(),
        }
    }
}

/// A comparison: what was measured, how, and the figures.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Structures, or the grid sweep.
    pub mode: Mode,
    /// One line on how it was measured (date, size, protocol, runs, load), the
    /// CSV's first line without its `#`.
    pub about: String,
    /// The figures, scene by scene, setting by setting.
    pub rows: Vec<Row>,
}

/// A scene to measure, with the name its rows carry.
pub struct Named<'a> {
    /// The scene's file name.
    pub name: String,
    /// The scene, with its settings applied.
    pub scene: &'a Scene,
}

/// Measures `scenes` as `mode` asks, each setting's trace timed `runs` times
/// (alternating over the settings within each round, so that a machine
/// slowing down or speeding up shifts every setting alike). `note` hears
/// which scene, setting and run is under way.
pub fn measure(
    scenes: &[Named],
    mode: Mode,
    runs: usize,
    note: &mut (dyn FnMut(&str) + Send),
) -> Vec<Row> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("one worker thread can be started");
    pool.install(|| {
        scenes
            .iter()
            .flat_map(|named| measure_scene(named, mode, runs.max(1), note))
            .collect()
    })
}

/// The settings `mode` measures on `scene`: (structure, grid resolution).
fn settings(scene: &Scene, mode: Mode) -> Vec<(Accel, Level)> {
    match mode {
        Mode::Structures => STRUCTURES
            .iter()
            .map(|&a| (a, scene.settings.grid_res))
            .collect(),
        Mode::GridSweep => GRID_SIDES
            .iter()
            .map(|&n| (Accel::Grid, Level::Given(n)))
            .chain([(Accel::Grid, Level::Auto)])
            .collect(),
    }
}

/// One scene's rows, on the calling thread's pool.
fn measure_scene(
    named: &Named,
    mode: Mode,
    runs: usize,
    note: &mut (dyn FnMut(&str) + Send),
) -> Vec<Row> {
    let scenes: Vec<Scene> = settings(named.scene, mode)
        .into_iter()
        .map(|(accel, grid_res)| {
            let mut s = named.scene.clone();
            s.settings.accel = accel;
            s.settings.grid_res = grid_res;
            s
        })
        .collect();
    let mut rows = Vec::with_capacity(scenes.len());
    let mut tracers = Vec::with_capacity(scenes.len());
    for scene in &scenes {
        let mut row = Row {
            scene: named.name.clone(),
            structure: scene.settings.accel,
            grid_res: (scene.settings.accel == Accel::Grid).then_some(scene.settings.grid_res),
            grid_cells: None,
            objects: scene.objects.len() as u64,
            rays: 0,
            steps: 0,
            primitives: 0,
            build_seconds: 0.0,
            run_seconds: Vec::with_capacity(runs),
        };
        note(&format!(
            "{}: {}, building and counting",
            row.scene,
            row.label()
        ));
        let building = Instant::now();
        let tracer = Tracer::new(scene);
        row.build_seconds = building.elapsed().as_secs_f64();
        if let Some(Built::Grid(grid)) = tracer.accelerator().structure() {
            row.grid_cells = Some(grid.resolution());
        }
        // A fresh tracer for each render: none starts with another's blockers.
        let (_, counts) = render_counting_with(&tracer.with_settings(scene), &Progress::QUIET)
            .expect("the size was validated");
        (row.rays, row.steps, row.primitives) = (counts.total(), counts.boxes, counts.primitives);
        rows.push(row);
        tracers.push(tracer);
    }
    for run in 0..runs {
        for ((row, tracer), scene) in rows.iter_mut().zip(&tracers).zip(&scenes) {
            note(&format!(
                "{}: {}, run {} of {runs}",
                row.scene,
                row.label(),
                run + 1
            ));
            let fresh = tracer.with_settings(scene);
            let started = Instant::now();
            render_with_tracer(&fresh, &Progress::QUIET).expect("the size was validated");
            row.run_seconds.push(started.elapsed().as_secs_f64());
        }
    }
    rows
}

/// The CSV's header, the line after the comment.
pub const CSV_HEADER: &str = "scene,structure,grid_res,grid_cells,objects,rays,steps,primitives,steps_per_ray,primitives_per_ray,build_seconds,trace_seconds_median,run_seconds";

/// Every raw figure as CSV: the comment line (`# ` and [`Comparison::about`]),
/// the header, a row per setting. Each run's seconds share one field,
/// separated by `;`; numbers are written so they read back exactly.
pub fn csv(c: &Comparison) -> String {
    let mut out = format!("# {}\n{CSV_HEADER}\n", c.about);
    for r in &c.rows {
        let runs: Vec<String> = r.run_seconds.iter().map(f64::to_string).collect();
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            quoted(&r.scene),
            r.structure.name(),
            r.grid_res.map_or(String::new(), |l| l.to_string()),
            r.grid_cells
                .map_or(String::new(), |[x, y, z]| format!("{x}x{y}x{z}")),
            r.objects,
            r.rays,
            r.steps,
            r.primitives,
            r.steps_per_ray(),
            r.primitives_per_ray(),
            r.build_seconds,
            r.trace_seconds(),
            runs.join(";"),
        ));
    }
    out
}

/// A field quoted when it holds a comma or a quote (RFC 4180: quotes doubled).
fn quoted(s: &str) -> String {
    if s.contains([',', '"']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_owned()
    }
}

/// Reads a CSV [`csv`] wrote, strictly: every field checked, the ratios and
/// the median against the counts and runs they come from, the rows a whole
/// comparison (every structure for each scene, in order, or one scene's grid
/// sweep). An error names the line and the field.
pub fn parse_csv(text: &str) -> Result<Comparison, String> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    let about = match lines.next() {
        Some((_, l)) if l.starts_with("# ") => l[2..].to_owned(),
        _ => {
            return Err(
                "line 1: expected a comment starting with '# ' (how it was measured)".to_owned(),
            );
        }
    };
    if about.chars().any(char::is_control) || about.chars().count() > 300 {
        return Err("line 1: the comment must be printable and at most 300 characters".to_owned());
    }
    match lines.next() {
        Some((_, l)) if l == CSV_HEADER => {}
        _ => return Err(format!("line 2: expected the header {CSV_HEADER}")),
    }
    let mut rows = Vec::new();
    for (n, line) in lines {
        rows.push(parse_row(line).map_err(|e| format!("line {n}: {e}"))?);
    }
    let mode = check_rows(&rows)?;
    Ok(Comparison { mode, about, rows })
}

/// The fields of one line: plain, or quoted with quotes doubled.
fn fields(line: &str) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let mut chars = line.chars().peekable();
    loop {
        let mut field = String::new();
        if chars.peek() == Some(&'"') {
            chars.next();
            loop {
                match chars.next() {
                    Some('"') if chars.peek() == Some(&'"') => {
                        chars.next();
                        field.push('"');
                    }
                    Some('"') => break,
                    Some(c) => field.push(c),
                    None => return Err("a quoted field is not closed".to_owned()),
                }
            }
            if !matches!(chars.peek(), None | Some(',')) {
                return Err("text after a quoted field's closing quote".to_owned());
            }
        } else {
            while let Some(&c) = chars.peek() {
                if c == ',' {
                    break;
                }
                if c == '"' {
                    return Err("a quote inside an unquoted field".to_owned());
                }
                field.push(c);
                chars.next();
            }
        }
        out.push(field);
        if chars.next().is_none() {
            return Ok(out);
        }
    }
}

/// One row, its fields checked against each other.
fn parse_row(line: &str) -> Result<Row, String> {
    let f = fields(line)?;
    let names: Vec<&str> = CSV_HEADER.split(',').collect();
    if f.len() != names.len() {
        return Err(format!("expected {} fields, got {}", names.len(), f.len()));
    }
    let whole = |k: usize| -> Result<u64, String> {
        f[k].parse::<u64>()
            .map_err(|_| format!("{}: '{}' is not a whole number", names[k], f[k]))
    };
    let seconds = |k: usize, s: &str| -> Result<f64, String> {
        s.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && *v >= 0.0 && *v < 1e9)
            .ok_or_else(|| format!("{}: '{s}' is not a number of seconds", names[k]))
    };
    let scene = f[0].clone();
    if scene.is_empty() || scene.chars().any(char::is_control) || scene.chars().count() > 100 {
        return Err("scene: must be a printable name of 1 to 100 characters".to_owned());
    }
    let structure = parse_structure(&f[1])?;
    let grid_res = parse_grid_res(structure, &f[1], &f[2])?;
    let grid_cells = parse_grid_cells(structure, &f[1], &f[3])?;
    let (objects, rays, steps, primitives) = (whole(4)?, whole(5)?, whole(6)?, whole(7)?);
    if rays == 0 {
        return Err("rays: must be at least 1".to_owned());
    }
    let run_seconds = f[12]
        .split(';')
        .map(|s| seconds(12, s))
        .collect::<Result<Vec<f64>, String>>()?;
    if run_seconds.len() > MAX_RUNS {
        return Err(format!("run_seconds: more than {MAX_RUNS} runs"));
    }
    let row = Row {
        scene,
        structure,
        grid_res,
        grid_cells,
        objects,
        rays,
        steps,
        primitives,
        build_seconds: seconds(10, &f[10])?,
        run_seconds,
    };
    check_ratios(&row, &f, &names)?;
    Ok(row)
}

/// The `structure` field: one of [`STRUCTURES`], by its name.
fn parse_structure(field: &str) -> Result<Accel, String> {
    STRUCTURES
        .iter()
        .copied()
        .find(|a| a.name() == field)
        .ok_or_else(|| format!("structure: '{field}' is not none, bvh, grid, octree or bsp"))
}

/// The `grid_res` field: empty but for the grid (named `name`), whose is
/// `auto` or a side of 1 to 160.
fn parse_grid_res(structure: Accel, name: &str, field: &str) -> Result<Option<Level>, String> {
    match (structure == Accel::Grid, field) {
        (false, "") => Ok(None),
        (false, s) => Err(format!(
            "grid_res: '{s}' given for {name}, which is no grid"
        )),
        (true, "auto") => Ok(Some(Level::Auto)),
        (true, s) => Ok(Some(Level::Given(
            s.parse::<u32>()
                .ok()
                .filter(|n| (1..=160).contains(n))
                .ok_or_else(|| format!("grid_res: '{s}' is not auto or 1 to 160"))?,
        ))),
    }
}

/// The `grid_cells` field: empty but for the grid (named `name`), whose is
/// `XxYxZ`, each 1 to 1024.
fn parse_grid_cells(
    structure: Accel,
    name: &str,
    field: &str,
) -> Result<Option<[usize; 3]>, String> {
    match (structure == Accel::Grid, field) {
        (false, "") => Ok(None),
        (false, s) => Err(format!(
            "grid_cells: '{s}' given for {name}, which is no grid"
        )),
        (true, s) => {
            let n: Vec<usize> = s
                .split('x')
                .map(|v| v.parse::<usize>().ok().filter(|&n| (1..=1024).contains(&n)))
                .collect::<Option<_>>()
                .filter(|n: &Vec<usize>| n.len() == 3)
                .ok_or_else(|| format!("grid_cells: '{s}' is not XxYxZ, each 1 to 1024"))?;
            Ok(Some([n[0], n[1], n[2]]))
        }
    }
}

/// The ratios and the median of the line's fields `f` (named `names`) are
/// the row's own. Written from the counts and runs by the same arithmetic, in
/// numbers that read back exactly: any difference is an edit, not rounding.
fn check_ratios(row: &Row, f: &[String], names: &[&str]) -> Result<(), String> {
    for (k, want) in [
        (8, row.steps_per_ray()),
        (9, row.primitives_per_ray()),
        (11, row.trace_seconds()),
    ] {
        if f[k].parse::<f64>().ok() != Some(want) {
            return Err(format!(
                "{}: '{}' is not {want}, from the row's figures",
                names[k], f[k]
            ));
        }
    }
    Ok(())
}

/// Whether the rows make a whole comparison, and which.
fn check_rows(rows: &[Row]) -> Result<Mode, String> {
    let Some(first) = rows.first() else {
        return Err("no rows after the header".to_owned());
    };
    // Data lines start at line 3.
    let line = |i: usize| i + 3;
    let runs = first.run_seconds.len();
    if let Some(i) = rows.iter().position(|r| r.run_seconds.len() != runs) {
        return Err(format!(
            "line {}: run_seconds: {} runs where line 3 has {runs}",
            line(i),
            rows[i].run_seconds.len()
        ));
    }
    // A comparison of structures starts each scene with none: rows all of
    // the grid are a sweep.
    let grid_sweep = rows.iter().all(|r| r.structure == Accel::Grid);
    if grid_sweep {
        for (i, r) in rows.iter().enumerate() {
            if r.scene != first.scene || r.objects != first.objects {
                return Err(format!(
                    "line {}: scene: a grid sweep is of one scene, {}",
                    line(i),
                    first.scene
                ));
            }
            if rows[..i].iter().any(|q| q.grid_res == r.grid_res) {
                return Err(format!(
                    "line {}: grid_res: {} measured twice",
                    line(i),
                    r.label()
                ));
            }
        }
        return Ok(Mode::GridSweep);
    }
    if !rows.len().is_multiple_of(STRUCTURES.len()) || rows.len() / STRUCTURES.len() > MAX_SCENES {
        return Err(format!(
            "{} rows: a comparison has five per scene (none, bvh, grid, octree, bsp), for 1 to {MAX_SCENES} scenes",
            rows.len()
        ));
    }
    for (i, r) in rows.iter().enumerate() {
        let head = &rows[i - i % STRUCTURES.len()];
        if r.structure != STRUCTURES[i % STRUCTURES.len()] {
            return Err(format!(
                "line {}: structure: expected {} here (each scene's five in order)",
                line(i),
                STRUCTURES[i % STRUCTURES.len()].name()
            ));
        }
        if r.scene != head.scene || r.objects != head.objects {
            return Err(format!(
                "line {}: scene: {} is not {}, whose rows these are",
                line(i),
                r.scene,
                head.scene
            ));
        }
        if i % STRUCTURES.len() == 0 && rows[..i].iter().any(|q| q.scene == r.scene) {
            return Err(format!(
                "line {}: scene: {} measured twice",
                line(i),
                r.scene
            ));
        }
    }
    Ok(Mode::Structures)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(structure: Accel, grid_res: Option<Level>) -> Row {
        Row {
            scene: "a, \"b\".json".to_owned(),
            structure,
            grid_res,
            grid_cells: grid_res.map(|_| [4, 2, 3]),
            objects: 7,
            rays: 3,
            steps: 10,
            primitives: 1,
            build_seconds: 0.25,
            run_seconds: vec![0.5, 0.125, 0.375],
        }
    }

    #[test]
    fn the_csv_reads_back_exactly() {
        let c = Comparison {
            mode: Mode::Structures,
            about: "made by hand".to_owned(),
            rows: STRUCTURES
                .iter()
                .map(|&a| row(a, (a == Accel::Grid).then_some(Level::Given(8))))
                .collect(),
        };
        let text = csv(&c);
        assert_eq!(parse_csv(&text), Ok(c.clone()));
        // 10 steps over 3 rays: a ratio that is no short decimal, still exact.
        assert!(text.contains(&(10.0f64 / 3.0).to_string()));
        assert_eq!(c.rows[0].trace_seconds(), 0.375);
        let sweep = Comparison {
            mode: Mode::GridSweep,
            about: "x".to_owned(),
            rows: vec![
                row(Accel::Grid, Some(Level::Given(2))),
                row(Accel::Grid, Some(Level::Auto)),
            ],
        };
        assert_eq!(parse_csv(&csv(&sweep)), Ok(sweep));
    }

    #[test]
    fn a_ratio_that_disagrees_with_its_counts_is_refused() {
        let c = Comparison {
            mode: Mode::GridSweep,
            about: "x".to_owned(),
            rows: vec![row(Accel::Grid, Some(Level::Given(2)))],
        };
        let text = csv(&c).replace(&(10.0f64 / 3.0).to_string(), "3.3");
        let e = parse_csv(&text).unwrap_err();
        assert!(e.starts_with("line 3: steps_per_ray:"), "{e}");
    }
}
