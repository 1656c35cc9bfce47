//! The ray tree as a tree: a box per ray (its kind, depth, weight and what it
//! hit), an edge from each ray to the rays it spawned, labelled with the
//! coefficient that weighs the child's color. The diagram shows where the
//! rays go; this shows how the recursion nests, which the geometry hides once
//! rays cross each other. The hits are numbered P1, P2, … in the order the
//! diagram numbers them, so the two figures can be read side by side.

use glam::DVec2;

use crate::figure::canvas::{Anchor, Figure};
use crate::figure::labels::{self, Label, Placed, PxRect, Target};
use crate::figure::pen::{Pen, Rgb, palette};
use crate::trace::recorder::{Branch, RayKind};
use crate::tree::ray_tree::{BranchRecord, RayNode, RayTree};
use crate::views::numbers::num;

/// One ray's box.
#[derive(Clone, Debug, PartialEq)]
pub struct GraphNode {
    /// Its index in the tree.
    pub ray: usize,
    /// Its parent's index.
    pub parent: Option<usize>,
    /// Its kind, which colors its box and the edge into it.
    pub kind: RayKind,
    /// The box's center, in pixels.
    pub center: DVec2,
    /// The text in the box, a line each.
    pub lines: Vec<String>,
}

/// A parent → child edge: the two rays and the coefficient on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Edge {
    /// The parent ray.
    pub from: usize,
    /// The child ray.
    pub to: usize,
    /// `k_rfl = …` or `k_rfa = …`.
    pub label: String,
}

/// The graph laid out on a page.
#[derive(Clone, Debug, PartialEq)]
pub struct Graph {
    /// A box per ray, in the tree's order.
    pub nodes: Vec<GraphNode>,
    /// An edge per parent and child.
    pub edges: Vec<Edge>,
    /// A box's size in pixels.
    pub size: DVec2,
    /// The height of a line of text in a box: [`LINE`], less when the rows
    /// are too close for every line at full size.
    pub line: f64,
}

const TOP: f32 = 60.0;
const MARGIN: f32 = 16.0;
const TEXT: f32 = 13.0;
const LINE: f64 = 17.0;
/// The widest a box is drawn; narrower when the leaves need it.
const BOX_WIDTH: f64 = 180.0;

/// The color of a ray kind, as the diagram draws it.
fn color(kind: RayKind) -> Rgb {
    match kind {
        RayKind::Primary => palette::PRIMARY,
        RayKind::Reflected => palette::REFLECTED,
        RayKind::Refracted => palette::REFRACTED,
        RayKind::Shadow => palette::SHADOW_REACHES,
    }
}

/// Why a branch was not traced, in a few words; `None` when it was, or when
/// the material has no such branch at all (nothing worth a line).
fn stopped(which: &str, branch: Option<&BranchRecord>) -> Option<String> {
    let why = match branch?.outcome {
        Branch::Traced | Branch::NoCoefficient => return None,
        Branch::MaxDepth => "max depth",
        Branch::WeightCutoff => "weight cutoff",
        // Only a refracted branch stops this way.
        Branch::TotalInternalReflection => return Some("no refracted ray: TIR".to_owned()),
    };
    Some(format!("{which}: {why}"))
}

/// The lines of a ray's box; `hit` is its hit's number P1, P2, … if any.
fn lines(i: usize, node: &RayNode, hit: Option<usize>) -> Vec<String> {
    let mut out = vec![
        format!("ray {} · {}", i + 1, node.kind.name()),
        format!("depth {} · weight {}", node.depth, num(node.weight)),
        match (&node.hit, hit) {
            (Some(h), Some(k)) => format!("P{k}: hits {}", h.name),
            _ => "misses: background".to_owned(),
        },
    ];
    out.extend(stopped("reflected", node.reflected.as_ref()));
    out.extend(stopped("refracted", node.refracted.as_ref()));
    out
}

/// The children of every ray, in the tree's order (reflected before refracted).
fn children(tree: &RayTree) -> Vec<Vec<usize>> {
    let mut out = vec![Vec::new(); tree.nodes.len()];
    for (i, node) in tree.nodes.iter().enumerate() {
        if let Some(p) = node.parent.filter(|&p| p < i) {
            out[p].push(i);
        }
    }
    out
}

/// The graph of `tree` on a `width × height` page: a row per depth, the
/// leaves side by side in depth-first order and each parent centered over
/// its children, so no two edges cross.
pub fn layout(tree: &RayTree, width: u32, height: u32) -> Graph {
    let (slot, leaves) = slots(tree);
    let depths = tree.nodes.iter().map(|n| n.depth).max().unwrap_or(1).max(1);
    let (w, h) = (f64::from(width), f64::from(height));
    let (left, top) = (f64::from(MARGIN), f64::from(TOP));
    let column = (w - 2.0 * left) / leaves.max(1.0);
    let row = (h - top - f64::from(MARGIN)) / f64::from(depths);
    let (size, line) = box_size(tree, column, row);
    let mut hits = 0;
    let nodes = (tree.nodes.iter().enumerate())
        .map(|(i, node)| {
            let hit = node.hit.as_ref().map(|_| {
                hits += 1;
                hits
            });
            GraphNode {
                ray: i,
                parent: node.parent,
                kind: node.kind,
                center: DVec2::new(
                    left + column * (slot[i] + 0.5),
                    top + row * (f64::from(node.depth) - 0.5),
                ),
                lines: lines(i, node, hit),
            }
        })
        .collect();
    Graph {
        nodes,
        edges: edges(tree),
        size,
        line,
    }
}

/// Each ray's column, in leaves' widths, and how many leaves there are:
/// depth first from the root, a leaf takes the next slot, a parent the
/// middle of its children's.
fn slots(tree: &RayTree) -> (Vec<f64>, f64) {
    fn place(i: usize, kids: &[Vec<usize>], slot: &mut [f64], leaves: &mut f64) {
        if kids[i].is_empty() {
            slot[i] = *leaves;
            *leaves += 1.0;
            return;
        }
        for &c in &kids[i] {
            place(c, kids, slot, leaves);
        }
        let (first, last) = (kids[i][0], kids[i][kids[i].len() - 1]);
        slot[i] = (slot[first] + slot[last]) / 2.0;
    }
    let kids = children(tree);
    let mut slot = vec![0.0; tree.nodes.len()];
    let mut leaves = 0.0;
    if !tree.nodes.is_empty() {
        place(0, &kids, &mut slot, &mut leaves);
    }
    (slot, leaves)
}

/// A box's size and the height of its lines, in a grid of `column × row`
/// pixels: the box holds its most lines, with a gap of 24 pixels between
/// rows for the coefficients; where the rows are closer, the lines shrink.
fn box_size(tree: &RayTree, column: f64, row: f64) -> (DVec2, f64) {
    let most = tree
        .nodes
        .iter()
        .map(|n| {
            3 + usize::from(stopped("", n.reflected.as_ref()).is_some())
                + usize::from(stopped("", n.refracted.as_ref()).is_some())
        })
        .max()
        .unwrap_or(3);
    let height = (LINE * most as f64 + 8.0).min(row - 24.0);
    let line = LINE.min((height - 8.0) / most as f64);
    (DVec2::new(BOX_WIDTH.min(column - 10.0), height), line)
}

/// An edge from each ray to its parent, with the coefficient that weighs it.
fn edges(tree: &RayTree) -> Vec<Edge> {
    (tree.nodes.iter().enumerate())
        .filter_map(|(i, node)| {
            let parent = &tree.nodes[node.parent.filter(|&p| p < i)?];
            // Under total internal reflection the refracted share goes to the
            // reflected ray: its coefficient is the sum, whatever k_rfl alone is.
            let tir = parent
                .refracted
                .as_ref()
                .is_some_and(|b| b.outcome == Branch::TotalInternalReflection);
            let (name, branch) = match node.kind {
                RayKind::Refracted => ("k_rfa", parent.refracted.as_ref()),
                _ if tir => ("TIR: k_rfl + k_rfa", parent.reflected.as_ref()),
                _ => ("k_rfl", parent.reflected.as_ref()),
            };
            Some(Edge {
                from: node.parent?,
                to: i,
                label: branch.map_or(String::new(), |b| {
                    format!("{name} = {}", num(b.coefficient))
                }),
            })
        })
        .collect()
}

/// Where each of a box's lines is drawn: its baseline's center and its
/// size, smaller than [`TEXT`] where the line is too wide for the box or the
/// rows too close, so no line crosses the box's edge.
pub fn box_lines(graph: &Graph, node: &GraphNode) -> Vec<(DVec2, f32)> {
    let top = node.center.y - graph.size.y / 2.0;
    let room = (graph.size.x - 8.0) as f32;
    let tall = TEXT * (graph.line / LINE) as f32;
    (node.lines.iter().enumerate())
        .map(|(k, line)| {
            let size = tall.min(TEXT * room / Figure::text_width(line, TEXT).max(1.0));
            let at = DVec2::new(node.center.x, top + 4.0 + graph.line * (k as f64 + 0.78));
            (at, size)
        })
        .collect()
}

/// What [`draw_with_labels`] drew, for tests.
pub struct Drawn {
    /// The figure.
    pub figure: Figure,
    /// The layout drawn.
    pub graph: Graph,
    /// The coefficients placed on the edges, with their boxes.
    pub labels: Vec<Placed>,
    /// The coefficients that found no room.
    pub left_out: Vec<Label>,
    /// The frame (pixels).
    pub frame: PxRect,
}

/// The figure of `tree`, titled with `title` (the scene and the pixel).
pub fn draw(tree: &RayTree, title: &str, width: u32, height: u32) -> Option<Figure> {
    draw_with_labels(tree, title, width, height).map(|d| d.figure)
}

/// [`draw`], also returning the layout and where the coefficients went:
/// through [`crate::figure::labels`], each at its edge and clear of the
/// boxes, the other coefficients and the frame.
pub fn draw_with_labels(tree: &RayTree, title: &str, width: u32, height: u32) -> Option<Drawn> {
    let graph = layout(tree, width, height);
    if graph.size.x < 60.0 || graph.line < 9.0 {
        return None;
    }
    let mut fig = Figure::new(width, height, TOP, MARGIN)?;
    let edges = draw_edges(&mut fig, &graph);
    let half = graph.size / 2.0;
    let boxes: Vec<PxRect> = (graph.nodes.iter())
        .map(|n| PxRect {
            min: n.center - half,
            max: n.center + half,
        })
        .collect();
    let frame = PxRect::frame_of(&fig);
    let requests = coefficients(&graph, &edges);
    let (placed, left_out) = labels::place_all(requests, &boxes, &edges, frame);
    draw_boxes(&mut fig, &graph);
    for p in &placed {
        p.draw(&mut fig, 1.0);
    }
    fig.frame_border();
    let caption = format!(
        "{title} · the ray tree as a tree: a box per ray (its kind, depth, weight and hit), an edge from each ray to those it spawned with the coefficient on it; hits numbered as the diagram numbers them"
    );
    fig.caption(&Figure::wrap(&caption, 15.0, fig.frame().width()), 15.0);
    Some(Drawn {
        figure: fig,
        graph,
        labels: placed,
        left_out,
        frame,
    })
}

/// Each edge, from the bottom of the parent's box to the top of the child's,
/// in the child's color; returns them in pixels, for the labels to weigh.
fn draw_edges(fig: &mut Figure, graph: &Graph) -> Vec<([DVec2; 2], usize)> {
    let half = graph.size / 2.0;
    let mut edges = Vec::new();
    for e in &graph.edges {
        let (a, b) = (&graph.nodes[e.from], &graph.nodes[e.to]);
        let from = a.center + DVec2::new(0.0, half.y);
        let to = b.center - DVec2::new(0.0, half.y);
        fig.line_px(from, to, Pen::solid(color(b.kind), 2.0));
        edges.push(([from, to], 1));
    }
    edges
}

/// The coefficients on paper at the edges' middles (`drawn`, in pixels).
fn coefficients(graph: &Graph, drawn: &[([DVec2; 2], usize)]) -> Vec<Label> {
    (graph.edges.iter().zip(drawn))
        .filter(|(e, _)| !e.label.is_empty())
        .map(|(e, &([from, to], _))| Label {
            text: e.label.clone(),
            size: TEXT - 1.0,
            color: color(graph.nodes[e.to].kind),
            target: Target::Point {
                at: (from + to) / 2.0,
                clearance: 0.0,
            },
            boxed: true,
            optional: false,
            tag: String::new(),
        })
        .collect()
}

/// A box per ray on paper over the edges: its first line in its kind's
/// color, its depth and hit in ink, why a branch stopped in gray.
fn draw_boxes(fig: &mut Figure, graph: &Graph) {
    let half = graph.size / 2.0;
    for n in &graph.nodes {
        let (min, max) = (n.center - half, n.center + half);
        let pen = Pen::solid(color(n.kind), 2.0);
        fig.rect_px(min, max, Some((palette::PAPER, 255)), Some(pen));
        for (k, (line, (at, size))) in n.lines.iter().zip(box_lines(graph, n)).enumerate() {
            let ink = match k {
                0 => color(n.kind),
                1 | 2 => palette::INK,
                _ => [110, 110, 110],
            };
            fig.text_px(at, line, size, ink, Anchor::Center, false);
        }
    }
}
