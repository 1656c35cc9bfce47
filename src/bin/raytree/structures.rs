//! `raytree structures`: the efficiency slide's comparison, measured: each
//! scene through every structure (or the grid at a sweep of resolutions),
//! its tests per ray and trace time in a table, a chart and a CSV; or the
//! chart and table again from such a CSV, without rendering.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use raytree::io::output::same_file;
use raytree::scene::Scene;
use raytree::scene::overrides::{Overrides, Protocol};
use raytree::trace::structure_sweep::{
    self, Comparison, MAX_RUNS, MAX_SCENES, Mode, Named, parse_csv,
};
use raytree::views::structures_chart;

use crate::args::{SceneArgs, parse_size, usage};
use crate::output;

// This command builds every structure itself, so the grid's and the trees'
// flags apply to the grid and the trees it builds, whatever --accel says
// elsewhere; --accel itself is refused.
#[derive(clap::Args)]
#[command(
    mut_arg("grid_res", |a| a.help("For the grid: cells along the scene's longest side, 1 to 160, the other sides in proportion; auto gives about four cells an object [default: auto]")),
    mut_arg("tree_depth", |a| a.help("For the octree and the k-d tree: the tree's deepest level, 0 (one leaf) to 48; auto is 10 for the octree, 8 + 1.3·log₂(objects) for the k-d tree [default: auto]")),
)]
pub struct Args {
    /// Scene files (JSON, or NFF by the extension .nff), 1 to 16; none with --from.
    #[arg(value_name = "SCENE", required_unless_present = "from")]
    scenes: Vec<PathBuf>,
    /// Render as a benchmark prescribes (see `raytree render --help`): spd, the Standard Procedural Databases' protocol; the flags below, given beside it, win.
    #[arg(long, value_enum)]
    protocol: Option<Protocol>,
    #[command(flatten)]
    overrides: Overrides,
    /// Timed renders per structure, 1 to 20; the table and chart show the median.
    #[arg(long, value_name = "N", default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=MAX_RUNS as i64))]
    runs: u32,
    /// Also write every raw figure to this CSV file (which --from reads back).
    #[arg(long, value_name = "OUT.csv", conflicts_with = "from")]
    csv: Option<PathBuf>,
    /// Output chart (.png).
    #[arg(short, long, value_name = "OUT.png", default_value = "structures.png")]
    output: PathBuf,
    /// For one scene: the grid at --grid-res 2, 4, 8, …, 160 and auto, instead of the five structures.
    #[arg(long, conflicts_with = "from")]
    grid_sweep: bool,
    /// Redraw the chart (and print the table) from a CSV this command wrote, without rendering.
    #[arg(long, value_name = "IN.csv", conflicts_with_all = ["scenes", "protocol", "runs"])]
    from: Option<PathBuf>,
    /// Chart size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1200x800", value_parser = parse_size)]
    size: (u32, u32),
}

pub fn run(args: &Args) -> Result<()> {
    output::require_png(&args.output, "the chart")?;
    let comparison = match &args.from {
        Some(path) => read(path, &args.output)?,
        None => measure(args)?,
    };
    if args.from.is_some() {
        // Only the chart: the CSV it came from is already written.
        let figure = structures_chart::draw(&comparison, args.size.0, args.size.1)
            .context("the chart size is too small")?;
        let png = output::create(&args.output, &[])?;
        png.commit(&figure.png())?;
    }
    output::print(structures_chart::table(&comparison))?;
    output::note(&format!("wrote {}", args.output.display()))?;
    Ok(())
}

/// The comparison a CSV holds, refused in one line naming the line and field.
fn read(path: &Path, out: &Path) -> Result<Comparison> {
    if same_file(path, out) {
        return Err(usage(format_args!(
            "cannot write {}: it is the CSV --from reads",
            out.display()
        )));
    }
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    parse_csv(&text).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))
}

/// Loads the scenes, measures them, writes the chart and the CSV.
fn measure(args: &Args) -> Result<Comparison> {
    refuse_misuse(args)?;
    let (loaded, inputs) = load(args)?;
    let png = output::create(&args.output, &inputs)?;
    let csv = (args.csv.as_deref())
        .map(|p| output::create(p, &inputs))
        .transpose()?;
    let mode = if args.grid_sweep {
        Mode::GridSweep
    } else {
        Mode::Structures
    };
    let rows = measure_rows(&loaded, mode, args.runs)?;
    // Read after the runs: the machine's load as they ended.
    let comparison = Comparison {
        mode,
        about: about(&loaded, args),
        rows,
    };
    let figure = structures_chart::draw(&comparison, args.size.0, args.size.1)
        .context("the chart size is too small")?;
    // Both files or neither.
    let (picture, figures) = (figure.png(), structure_sweep::csv(&comparison));
    let mut files = vec![(png, picture.as_slice())];
    files.extend(csv.map(|file| (file, figures.as_bytes())));
    output::commit_all(files)?;
    if let Some(c) = &args.csv {
        output::note(&format!("wrote {}", c.display()))?;
    }
    Ok(comparison)
}

/// Refuses what the measurement cannot do: too many scenes, `--accel`, a grid
/// sweep of several scenes or of a given resolution, the CSV in the chart's file.
fn refuse_misuse(args: &Args) -> Result<()> {
    if args.scenes.len() > MAX_SCENES {
        return Err(usage(format_args!(
            "{} scenes given: at most {MAX_SCENES} (each takes minutes at the SPD's size)",
            args.scenes.len()
        )));
    }
    if args.overrides.accel.is_some() {
        return Err(usage(
            "--accel: structures measures every structure itself; leave it out",
        ));
    }
    if args.grid_sweep {
        if args.scenes.len() != 1 {
            return Err(usage(format_args!(
                "--grid-sweep: sweeps one scene, got {}",
                args.scenes.len()
            )));
        }
        if args.overrides.grid_res.is_some() {
            return Err(usage("--grid-res: --grid-sweep sweeps it; leave it out"));
        }
    }
    if let Some(csv) = args.csv.as_deref().filter(|c| same_file(c, &args.output)) {
        return Err(usage(format_args!(
            "cannot write {}: the CSV figures and the chart need two files",
            csv.display()
        )));
    }
    Ok(())
}

/// Scenes, each with the name of its file.
type Loaded = Vec<(String, Scene)>;

/// The scenes, each with its file's name (refused if two share one), and
/// every file they were read from.
fn load(args: &Args) -> Result<(Loaded, Vec<PathBuf>)> {
    let mut loaded: Loaded = Vec::new();
    let mut inputs = Vec::new();
    for path in &args.scenes {
        let scene_args = SceneArgs {
            scene: Some(path.clone()),
            protocol: args.protocol,
            overrides: args.overrides,
        };
        let (scene, _) = scene_args.load_for_every_structure()?;
        let name = path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        if loaded.iter().any(|(n, _)| *n == name) {
            return Err(usage(format_args!(
                "{}: a second scene named {name}; give each scene once",
                path.display()
            )));
        }
        inputs.extend(scene_args.inputs(&scene));
        loaded.push((name, scene));
    }
    Ok((loaded, inputs))
}

/// The measured rows, with progress on standard error. A failure to write it
/// (a closed pipe) is kept and reported after, since the measurement cannot
/// be stopped midway.
fn measure_rows(
    loaded: &[(String, Scene)],
    mode: Mode,
    runs: u32,
) -> Result<Vec<structure_sweep::Row>> {
    let named: Vec<Named> = loaded
        .iter()
        .map(|(name, scene)| Named {
            name: name.clone(),
            scene,
        })
        .collect();
    let mut failed: Option<std::io::Error> = None;
    let rows = structure_sweep::measure(&named, mode, runs as usize, &mut |line: &str| {
        if failed.is_none() {
            failed = output::note(&format!("structures: {line}")).err();
        }
    });
    match failed {
        Some(e) => Err(e.into()),
        None => Ok(rows),
    }
}

/// How it was measured, in one line: the date, the size, the protocol, the
/// runs, one thread, and the machine's load when the runs ended (a loaded
/// machine's times are longer).
fn about(scenes: &[(String, Scene)], args: &Args) -> String {
    let sizes: Vec<(u32, u32)> = scenes
        .iter()
        .map(|(_, s)| (s.settings.width, s.settings.height))
        .collect();
    let size = if sizes.windows(2).all(|w| w[0] == w[1]) {
        sizes
            .first()
            .map_or(String::new(), |(w, h)| format!("{w}×{h}"))
    } else {
        "each scene's own size".to_owned()
    };
    let protocol = match args.protocol {
        Some(Protocol::Spd) => "protocol spd",
        None => "no protocol",
    };
    let runs = match args.runs {
        1 => "1 run".to_owned(),
        n => format!("{n} runs"),
    };
    let load = std::fs::read_to_string("/proc/loadavg")
        .ok()
        .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .filter(|l| !l.is_empty())
        .unwrap_or_else(|| "unknown".to_owned());
    format!(
        "{} UTC, {size}, {protocol}, {runs}, threads = 1, load {load}",
        utc_now()
    )
}

/// The date and minute now, UTC, as `2026-11-25 21:03`.
fn utc_now() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (days, rest) = ((secs / 86_400) as i64, secs % 86_400);
    let (y, m, d) = civil_from_days(days);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}",
        rest / 3600,
        rest % 3600 / 60
    )
}

/// The Gregorian date of a day counted from 1970-01-01 (H. Hinnant's
/// `civil_from_days`, from "chrono-Compatible Low-Level Date Algorithms").
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

#[cfg(test)]
mod tests {
    use super::civil_from_days;

    #[test]
    fn days_become_dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        // 2000-02-29, a leap day of a century divisible by 400: day 11,016.
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        assert_eq!(civil_from_days(-1), (1969, 12, 31));
    }
}
