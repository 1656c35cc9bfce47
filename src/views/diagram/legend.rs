//! A ray diagram's legend: a line for each kind of mark the figure draws and
//! no other, in the corner of the frame that hides the fewest of its marks.

use glam::DVec2;

use crate::figure::canvas::Figure;
use crate::figure::labels::PxRect;
use crate::figure::pen::{Pen, palette};
use crate::methods::Accel;
use crate::tree::ray_tree::RayKind;
use crate::views::diagram::boxes;
use crate::views::diagram::layout::Layout;
use crate::views::diagram::projection::Outline;
use crate::views::diagram::style::{MET_BOX, MISSED_BOX, NORMAL, Scale, Stroke, ray_pen};

/// The legend: only what is drawn, in the corner that hides the least.
pub(super) fn draw_legend(fig: &mut Figure, lay: &Layout, scale: &Scale) -> (PxRect, Vec<String>) {
    let mut entries = ray_entries(lay, scale);
    entries.extend(box_entries(lay, scale));
    let legend: Vec<(Pen, &str)> = entries.iter().map(|(p, t)| (*p, t.as_str())).collect();
    let size = scale.text - 2.0;
    let boxes = fig.legend_boxes(&legend, size);
    let corner = least_covered(fig, lay, &boxes);
    fig.legend(&legend, size, corner);
    let (o, wh) = boxes[corner];
    let texts = entries.into_iter().map(|(_, t)| t).collect();
    (
        PxRect {
            min: o,
            max: o + wh,
        },
        texts,
    )
}

/// The legend's lines for what the rays draw: each kind of ray, shadow rays,
/// lights behind surfaces, passing rays, normals.
fn ray_entries(lay: &Layout, scale: &Scale) -> Vec<(Pen, String)> {
    let has = |stroke: Stroke| lay.segments.iter().any(|s| s.stroke == stroke);
    let kinds = [
        (RayKind::Primary, "primary ray"),
        (RayKind::Reflected, "reflected ray"),
        (RayKind::Refracted, "refracted ray"),
    ];
    let mut out: Vec<(Pen, &str)> = (kinds.into_iter())
        .filter(|&(kind, _)| has(Stroke::Ray(kind)))
        .map(|(kind, name)| (scale.pen(ray_pen(kind)), name))
        .collect();
    if has(Stroke::ShadowReaches) {
        out.push((
            scale.pen(Stroke::ShadowReaches.pen()),
            "shadow ray, reaches the light",
        ));
    }
    if has(Stroke::ShadowBlocked) {
        out.push((
            scale.pen(Stroke::ShadowBlocked.pen()),
            "shadow ray up to its blocker (×)",
        ));
    }
    if !lay.marks.behind.is_empty() {
        out.push((
            scale.pen(Pen::pattern(palette::SHADOW_BLOCKED, 1.3, &[2.0, 3.0])),
            "light behind the surface: no shadow ray",
        ));
    }
    if lay.segments.iter().any(|s| !s.passing.is_empty()) {
        out.push((
            scale.pen(ray_pen(RayKind::Primary).passing()),
            "a ray passing in front of or behind an object",
        ));
    }
    if !lay.hits.is_empty() {
        out.push((scale.pen(NORMAL), "surface normal n"));
    }
    (out.into_iter())
        .map(|(pen, text)| (pen, text.to_owned()))
        .collect()
}

/// The legend's lines for the structure's boxes: the ones a ray entered,
/// named for the structure, and the ones tested and missed, each with its count.
fn box_entries(lay: &Layout, scale: &Scale) -> Vec<(Pen, String)> {
    let (tested, met) = boxes::counts(&lay.boxes);
    let mut out = Vec::new();
    if met > 0 {
        let text = match lay.structure {
            Accel::Grid => format!("grid cell the ray walked ({met})"),
            Accel::Octree => format!("octree cube the ray walked ({met})"),
            Accel::Bsp => {
                format!("k-d tree cell the ray walked, sides on splitting planes ({met})")
            }
            _ => format!("box the ray entered ({met})"),
        };
        out.push((scale.pen(MET_BOX), text));
    }
    if tested > met {
        let text = format!("box tested, missed ({})", tested - met);
        out.push((scale.pen(MISSED_BOX), text));
    }
    out
}

/// Which of the legend's four `boxes` covers the fewest of the figure's
/// marks: points along the rays, the hits, and the objects (a legend over a
/// cluster hides what the figure shows); the first such corner.
fn least_covered(fig: &Figure, lay: &Layout, boxes: &[(DVec2, DVec2); 4]) -> usize {
    let marks: Vec<DVec2> = lay
        .segments
        .iter()
        .flat_map(|s| (0..=20).map(move |k| s.from + (s.to - s.from) * (f64::from(k) / 20.0)))
        .chain(lay.hits.iter().map(|h| h.at))
        .chain(lay.objects.iter().flat_map(|o| match o.silhouette {
            Outline::Ellipse { center, axes } => vec![
                center,
                center + axes[0],
                center - axes[0],
                center + axes[1],
                center - axes[1],
            ],
            _ => Vec::new(),
        }))
        .map(|p| fig.to_px(p))
        .collect();
    let covered = |(o, wh): (DVec2, DVec2)| {
        marks
            .iter()
            .filter(|p| p.cmpge(o - 10.0).all() && p.cmple(o + wh + 10.0).all())
            .count()
    };
    (0..4).min_by_key(|&c| (covered(boxes[c]), c)).unwrap_or(0)
}
