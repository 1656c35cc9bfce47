//! The bounding boxes a ray was tested against, as a diagram draws them: each
//! box the ray tree recorded (the scene hierarchy's, in the order the search
//! tested them), projected onto the drawing plane as the outline of its
//! shadow there, and whether the ray met it. The lecture's efficiency slide
//! in one picture: the boxes the ray entered lead to the few objects it was
//! tested against; the ones it missed are whole subtrees never opened.

use glam::{DVec2, DVec3};

use crate::tree::ray_tree::BoxRecord;
use crate::views::diagram::projection::Projection;

/// One box, projected.
#[derive(Clone, Debug, PartialEq)]
pub struct BoxMark {
    /// The outline of the box's projection (a convex polygon, counterclockwise).
    pub outline: Vec<DVec2>,
    /// The ray met the box, so its children were tested next.
    pub met: bool,
    /// The ray (tree node) that tested it.
    pub node: usize,
    /// Which of that ray's recorded boxes it is.
    pub index: usize,
}

/// The recorded boxes of `node`, projected by `proj`.
pub fn project(node: usize, boxes: &[BoxRecord], proj: &Projection) -> Vec<BoxMark> {
    boxes
        .iter()
        .enumerate()
        .map(|(index, b)| BoxMark {
            outline: hull(&corners(b.min, b.max).map(|c| proj.point(c))),
            met: b.met,
            node,
            index,
        })
        .collect()
}

/// How many boxes a diagram's rays tested, and how many of those they met.
pub fn counts(marks: &[BoxMark]) -> (usize, usize) {
    (marks.len(), marks.iter().filter(|m| m.met).count())
}

fn corners(min: DVec3, max: DVec3) -> [DVec3; 8] {
    std::array::from_fn(|k| {
        DVec3::new(
            if k & 1 == 0 { min.x } else { max.x },
            if k & 2 == 0 { min.y } else { max.y },
            if k & 4 == 0 { min.z } else { max.z },
        )
    })
}

/// The convex hull of a few points, counterclockwise (Andrew's monotone chain).
fn hull(points: &[DVec2]) -> Vec<DVec2> {
    let mut p: Vec<DVec2> = points.to_vec();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut lower: Vec<DVec2> = Vec::new();
    for &q in &p {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], q) <= 0.0 {
            lower.pop();
        }
        lower.push(q);
    }
    let mut upper: Vec<DVec2> = Vec::new();
    for &q in p.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], q) <= 0.0 {
            upper.pop();
        }
        upper.push(q);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_of_a_projected_cube_is_its_outline() {
        // A cube seen along a diagonal-free axis: a square; corners inside are dropped.
        let square = hull(&[
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(0.5, 0.5),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ]);
        assert_eq!(square.len(), 4);
        assert!(!square.contains(&DVec2::new(0.5, 0.5)));
        // Counterclockwise: positive area.
        let area: f64 = (0..square.len())
            .map(|i| square[i].perp_dot(square[(i + 1) % square.len()]))
            .sum::<f64>()
            / 2.0;
        assert!((area - 1.0).abs() < 1e-12, "{area}");
    }
}
