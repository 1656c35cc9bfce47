//! `raytree diagram`: one pixel's (or one ray's) ray tree drawn over the scene.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use glam::DVec2;
use raytree::figure::canvas::Figure;
use raytree::figure::labels::Label;
use raytree::scene::Scene;
use raytree::tree::document::TraceDocument;
use raytree::views::diagram::options::{Fit, Labels, Options};
use raytree::views::diagram::projection::View;
use raytree::views::diagram::{self, camera_view, object_view};
use raytree::views::{hit_vectors, tree_graph};

use crate::args::{SceneArgs, TargetArgs, parse_from_one, parse_size, usage};
use crate::output;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    #[command(flatten)]
    target: TargetArgs,
    /// Output PNG, or SVG with a .svg name (the same figure as vectors, text as text) [default: the scene's name, the figure and the pixel: whitted-diagram-320-240.png, with --vectors 1 whitted-vectors-P1-320-240.png, with --graph whitted-graph-320-240.png; "ray" for the pixel with --ray].
    #[arg(short, long, value_name = "FIG.png|FIG.svg")]
    output: Option<PathBuf>,
    /// The plane drawn: the plane of incidence at the first hit (auto), the scene's axes, or the image plane face-on (camera).
    #[arg(long, value_enum, default_value = "auto")]
    view: ViewArg,
    /// Also draw the hit object's own frame beside the world: the untransformed primitive and the inverse-transformed ray S' + t·c' (object).
    #[arg(long, value_enum, default_value = "world")]
    space: Space,
    /// What to frame: the first hits and their objects, the whole tree, or the whole scene.
    #[arg(long, value_enum, default_value = "hits")]
    fit: Fit,
    /// An explicit window in drawing-plane coordinates: X0,Y0,X1,Y1 (overrides --fit).
    #[arg(long, value_name = "X0,Y0,X1,Y1", value_parser = parse_window, allow_hyphen_values = true)]
    window: Option<(DVec2, DVec2)>,
    /// Figure size in pixels.
    #[arg(long, value_name = "WxH", default_value = "1200x800", value_parser = parse_size)]
    size: (u32, u32),
    /// Draw only the first D levels of rays, 1 or more (1: the primary ray) [default: all levels].
    #[arg(long, value_name = "D", value_parser = parse_from_one, allow_negative_numbers = true)]
    depth: Option<u32>,
    /// Leave out the shadow rays.
    #[arg(long)]
    no_shadows: bool,
    /// Which labels to write.
    #[arg(long, value_enum, default_value = "all")]
    labels: Labels,
    /// Tick marks along each ray that hits, on the parametric line S + t·c: at every whole t when the hit is at 1 < t ≤ 10, otherwise about five at a round step (1, 2 or 5 times a power of ten), with t = 1 on a primary ray's image plane (most of a primary ray lies outside the frame of --fit hits: add --fit tree).
    #[arg(long)]
    ticks: bool,
    /// Mark the other roots of the hit object's equation on each ray's line: a root past the hit (where the line leaves a sphere), and a root behind the ray's start, with what became of each (the trace's "ignored" roots).
    #[arg(long)]
    roots: bool,
    /// Number the rays and hits as `raytree trace --steps` numbers their steps.
    #[arg(long)]
    steps: bool,
    /// Draw the ray tree as a graph instead of over the scene: a box per ray (kind, depth, weight, the object hit), an edge from each ray to the rays it spawned with its coefficient (PNG).
    #[arg(long, conflicts_with_all = ["view", "space", "fit", "window", "depth", "no_shadows", "labels", "ticks", "steps", "boxes"])]
    graph: bool,
    /// Draw hit P (1: P1, numbered as the diagram numbers hits) enlarged instead: the incoming c, the normal n and the reflected v with the equal angles, and c split into its parts along and across n (PNG).
    #[arg(long, value_name = "P", value_parser = parse_from_one, allow_negative_numbers = true, conflicts_with_all = ["graph", "view", "space", "fit", "window", "depth", "no_shadows", "labels", "ticks", "steps", "boxes"])]
    vectors: Option<u32>,
    /// Also draw the bounding boxes of the scene's hierarchy that the drawn rays were tested against (those entered solid, those missed dotted), with counts; scenes without a hierarchy have none.
    #[arg(long)]
    boxes: bool,
}

/// The views the command line offers: the scene's projections, and the camera's.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum ViewArg {
    /// The plane of incidence at the first hit (primary ray and normal), world up on top.
    Auto,
    /// Looking down the world's -y axis.
    Top,
    /// Looking along the world's -x axis.
    Side,
    /// Looking along the world's -z axis.
    Front,
    /// The image plane face-on: the pixel grid around the pixel, u, v, n, W, H, N.
    Camera,
}

/// Which space to draw the hit in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum Space {
    /// The world only.
    World,
    /// The world beside the hit object's own space (for a transformed object).
    Object,
}

/// `X0,Y0,X1,Y1` with `X0 < X1` and `Y0 < Y1`.
fn parse_window(s: &str) -> Result<(DVec2, DVec2), String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|p| p.trim().parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()
        .ok_or_else(|| format!("'{s}' is not four numbers X0,Y0,X1,Y1"))?;
    match v[..] {
        [x0, y0, x1, y1] if x0 < x1 && y0 < y1 => Ok((DVec2::new(x0, y0), DVec2::new(x1, y1))),
        [_, _, _, _] => Err("the window needs X0 < X1 and Y0 < Y1".to_owned()),
        _ => Err(format!("'{s}' is not four numbers X0,Y0,X1,Y1")),
    }
}

pub fn run(args: &Args) -> Result<()> {
    let (scene, source) = args.scene.load()?;
    let path = output::name_or(&args.output, || default_name(args));
    let svg = is_svg(args, &path)?;
    let pending = output::create(&path, &args.scene.inputs(&scene))?;
    let trace = args.target.record(&scene, source)?;
    let figure = if let Some(k) = args.vectors {
        hit_figure(&trace, k, args.size)?
    } else if args.graph {
        graph_figure(&trace, args.size)?
    } else {
        diagram_figure(args, &trace, &scene, svg)?
    };
    match figure.svg().filter(|_| svg) {
        Some(text) => pending.commit(text.as_bytes())?,
        None => pending.commit(&figure.png())?,
    }
    let (w, h) = figure.size();
    output::note(&format!("wrote {} ({w}×{h})", path.display()))?;
    Ok(())
}

/// The figure's default name: the scene's, the kind of figure and the pixel
/// (each kind has a name of its own, so that drawing the vectors or the
/// graph of a pixel keeps its diagram).
fn default_name(args: &Args) -> OsString {
    let kind = match (args.vectors, args.graph) {
        (Some(k), _) => format!("vectors-P{k}"),
        (None, true) => "graph".to_owned(),
        (None, false) => "diagram".to_owned(),
    };
    let at = match args.target.pixel {
        Some((x, y)) => format!("{x}-{y}"),
        None => "ray".to_owned(),
    };
    output::stem_and(args.scene.stem(), &format!("-{kind}-{at}.png"))
}

/// Whether `path` asks for an SVG (else a PNG): any other name, or an SVG
/// of a figure drawn as PNG only, is a usage error.
fn is_svg(args: &Args, path: &Path) -> Result<bool> {
    let extension = path.extension().map(|e| e.to_ascii_lowercase());
    let svg = extension.as_ref().is_some_and(|e| e == "svg");
    if !svg && extension.as_ref().is_none_or(|e| e != "png") {
        return Err(usage(format_args!(
            "cannot write {}: a diagram is a .png or an .svg",
            path.display()
        )));
    }
    if svg && (args.vectors.is_some() || args.graph) {
        return Err(usage(format_args!(
            "cannot write {}: {} drawn as PNG only",
            path.display(),
            if args.graph {
                "the tree graph is"
            } else {
                "the hit's vectors are"
            }
        )));
    }
    Ok(svg)
}

/// `--vectors K`: hit P`k` enlarged, with its vectors.
fn hit_figure(trace: &TraceDocument, k: u32, (width, height): (u32, u32)) -> Result<Figure> {
    let sample = trace.samples.first().context("the trace has no sample")?;
    let hits: Vec<_> = sample
        .tree
        .nodes
        .iter()
        .filter_map(|n| n.hit.as_ref())
        .collect();
    let hit = hits.get(k as usize - 1).ok_or_else(|| {
        usage(format_args!(
            "--vectors {k}: no hit P{k}: the tree has {} hits",
            hits.len()
        ))
    })?;
    let name = format!("P{k} on '{}'", hit.name);
    let title = match &trace.pixel {
        Some(p) => format!("{}, pixel {},{}, {name}", trace.scene.file, p.x, p.y),
        None => format!("{}, the given ray, {name}", trace.scene.file),
    };
    let drawn = hit_vectors::draw_with_labels(hit, &name, &title, width, height).context(
        "the ray meets the surface head-on (nothing to split), or the figure size is too small",
    )?;
    no_room(&drawn.left_out)?;
    Ok(drawn.figure)
}

/// `--graph`: the ray tree as a graph of boxes and edges.
fn graph_figure(trace: &TraceDocument, (width, height): (u32, u32)) -> Result<Figure> {
    let sample = trace.samples.first().context("the trace has no sample")?;
    let title = match &trace.pixel {
        Some(p) => format!("{}, pixel {},{}", trace.scene.file, p.x, p.y),
        None => format!("{}, the given ray", trace.scene.file),
    };
    let drawn = tree_graph::draw_with_labels(&sample.tree, &title, width, height)
        .context("the figure size is too small for this tree")?;
    no_room(&drawn.left_out)?;
    Ok(drawn.figure)
}

/// The ray diagram over the scene: in the world, beside the hit object's
/// own space, or the camera's view; recording an SVG too when `svg`.
fn diagram_figure(args: &Args, trace: &TraceDocument, scene: &Scene, svg: bool) -> Result<Figure> {
    let options = options(args, svg);
    let mut left_out = Vec::new();
    let figure = match (args.view, args.space) {
        (ViewArg::Camera, _) => camera_view::draw(trace, args.size.0, args.size.1),
        (_, Space::Object) => object_view::draw(trace, scene, &options),
        (_, Space::World) => diagram::draw::draw_with_labels(trace, scene, &options).map(|d| {
            left_out = d.left_out;
            d.figure
        }),
    }
    .map_err(anyhow::Error::msg)?;
    no_room(&left_out)?;
    Ok(figure)
}

/// The diagram's options, as the flags set them.
fn options(args: &Args, svg: bool) -> Options {
    let view = match args.view {
        ViewArg::Auto => View::Auto,
        ViewArg::Top => View::Top,
        ViewArg::Side => View::Side,
        ViewArg::Front => View::Front,
        ViewArg::Camera => View::Auto,
    };
    Options {
        width: args.size.0,
        height: args.size.1,
        view,
        depth: args.depth,
        shadows: !args.no_shadows,
        labels: args.labels,
        sample: 0,
        fit: args.fit,
        window: args.window,
        ticks: args.ticks,
        roots: args.roots,
        steps: args.steps,
        until_step: None,
        boxes: args.boxes,
        svg,
    }
}

/// A note naming the labels that found no room, the optional ones (ticks,
/// roots' and steps' numbers, a boundary's indices) aside: the figure is
/// written without them, and the reader should know.
fn no_room(left_out: &[Label]) -> Result<()> {
    let names: Vec<String> = (left_out.iter())
        .filter(|l| !l.optional)
        .map(|l| format!("'{}'", l.text.replace('\n', " ")))
        .collect();
    if !names.is_empty() {
        output::note(&format!(
            "no room for the labels {} without covering another: left out (a smaller --depth or --fit hits makes room)",
            names.join(", ")
        ))?;
    }
    Ok(())
}
