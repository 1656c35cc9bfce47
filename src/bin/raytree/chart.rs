//! `raytree chart`: speed against accuracy over a sweep of settings.

use std::path::PathBuf;

use anyhow::{Context, Result};
use raytree::io::output::same_file;
use raytree::trace::progress::Progress;
use raytree::trace::sweep::{self, Cost};
use raytree::views::chart;
use raytree::views::numbers::num;

use crate::args::{SceneArgs, parse_size, usage};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Output chart (.png) [default: the scene's name with -chart.png].
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    /// Also write every raw figure to this CSV file.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Renders per setting, 1 to 100; the chart shows the median time.
    #[arg(long, value_name = "N", default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=100))]
    runs: u32,
    /// What a setting costs: wall time (median of --runs), or intersection
    /// tests per pixel, counted in one run (exact and repeatable: the same
    /// chart on every machine).
    #[arg(long, value_enum, default_value_t = Cost::Time)]
    cost: Cost,
    /// Chart size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1200x800", value_parser = parse_size)]
    size: (u32, u32),
}

pub fn run(args: &Args) -> Result<()> {
    let (mut scene, source) = args.scene.load()?;
    // Timed at a quarter of the scene's pixels unless told otherwise: the sweep
    // renders each of its settings `runs` times, and the chart should take
    // seconds, not minutes. The error is measured at the same size.
    let o = &args.scene.overrides;
    if o.width.is_none() && o.height.is_none() {
        scene.settings.width = scene.settings.width.div_ceil(2);
        scene.settings.height = scene.settings.height.div_ceil(2);
    }
    let path = output::name_or(&args.output, || {
        output::stem_and(args.scene.stem(), "-chart.png")
    });
    output::require_png(&path, "a chart")?;
    let inputs = args.scene.inputs(&scene);
    if let Some(csv) = args.csv.as_deref().filter(|c| same_file(c, &path)) {
        return Err(usage(format_args!(
            "cannot write {}: the CSV figures and the chart need two files",
            csv.display()
        )));
    }
    let png = output::create(&path, &inputs)?;
    let csv = (args.csv.as_deref())
        .map(|p| output::create(p, &inputs))
        .transpose()?;
    let progress = output::progress_bar(
        false,
        "{spinner} charting [{bar:40}] {pos}/{len} settings, {elapsed}",
    );
    let points = sweep::measure(
        &scene,
        args.runs as usize,
        args.cost,
        &Progress::reporting(&output::on_bar(&progress)),
    );
    progress.finish_and_clear();
    let s = &scene.settings;
    let how = match args.cost {
        Cost::Time if args.runs == 1 => "1 run each".to_owned(),
        Cost::Time => format!("{} runs each", args.runs),
        Cost::Tests => "tests counted".to_owned(),
    };
    let title = format!("{} at {}×{}, {how}", source.file, s.width, s.height);
    let figure = chart::draw(&points, &title, args.size.0, args.size.1)
        .context("the chart size is too small")?;
    // Both files or neither.
    let (picture, figures) = (figure.png(), chart::csv(&points));
    let mut files = vec![(png, picture.as_slice())];
    files.extend(csv.map(|file| (file, figures.as_bytes())));
    output::commit_all(files)?;
    // The figures on standard output, one setting a line, so they can be
    // read (and quoted) without the CSV.
    let mut table = String::new();
    for p in &points {
        let cost = match p.tests {
            Some(t) => format!("{} tests per pixel", num(t)),
            None => format!("{} s", num(p.seconds)),
        };
        table.push_str(&format!(
            "{}: RMSE {}, {}% of pixels off by more than one level, {cost}\n",
            p.label,
            num(p.rmse),
            num(100.0 * p.off)
        ));
    }
    output::print(table)?;
    output::note(&format!(
        "wrote {}{}",
        path.display(),
        args.csv
            .as_ref()
            .map_or(String::new(), |c| format!(" and {}", c.display()))
    ))?;
    Ok(())
}
