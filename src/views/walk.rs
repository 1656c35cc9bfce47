//! A structure's walk as a learner reads it, one visit at a time: which box or
//! cell, what came of it, and for a grid cell the wall the ray leaves it
//! through, which is how the 3D-DDA picks the next cell (Amanatides & Woo,
//! "A Fast Voxel Traversal Algorithm for Ray Tracing", 1987).

use crate::methods::Accel;
use crate::tree::ray_tree::RayNode;
use crate::tree::steps::visit_tests;
use crate::views::explain::Lines;
use crate::views::numbers::{num, vec3};

/// Where a ray leaves a grid cell: on each axis the ray is not parallel to,
/// the wall it is heading for and the `t` at which it reaches it.
#[derive(Clone, Debug, PartialEq)]
pub struct CellExit {
    /// Per axis (x, y, z): the wall's coordinate and `t = (wall − S)/c`; `None`
    /// for an axis the ray is parallel to.
    pub walls: [Option<(f64, f64)>; 3],
    /// The axis whose wall comes first: the next cell lies beyond it.
    pub axis: usize,
    /// Its `t`.
    pub t: f64,
}

/// The walls of cell `k` of `node`'s walk ahead of the ray. The walk itself
/// keeps these `t` per axis and adds one cell's width in `t` at each step;
/// here they are worked out afresh from the recorded cell, `t = (wall − S)/c`,
/// which agrees with the walk's to rounding.
pub fn cell_exit(node: &RayNode, k: usize) -> Option<CellExit> {
    let cell = node.boxes.get(k)?;
    let (s, c) = (node.origin, node.direction);
    let walls: [Option<(f64, f64)>; 3] = [0, 1, 2].map(|a| {
        let wall = if c[a] > 0.0 {
            cell.max[a]
        } else if c[a] < 0.0 {
            cell.min[a]
        } else {
            return None;
        };
        Some((wall, (wall - s[a]) / c[a]))
    });
    let (axis, t) = (0..3)
        .filter_map(|a| walls[a].map(|(_, t)| (a, t)))
        .min_by(|p, q| p.1.total_cmp(&q.1))?;
    Some(CellExit { walls, axis, t })
}

/// The name of axis `a`.
pub fn axis_name(a: usize) -> &'static str {
    ["x", "y", "z"][a]
}

/// Visit `k` of `node`'s search through `structure`: the headline (which box
/// or cell, and what came of it) and, for a grid cell, the wall it is left
/// through.
pub fn visited(node: &RayNode, k: usize, structure: Accel) -> Lines {
    let b = &node.boxes[k];
    let n = node.boxes.len();
    let tests = visit_tests(node, k);
    let s = if tests == 1 { "" } else { "s" };
    let place = format!("{} to {}", vec3(b.min), vec3(b.max));
    match structure {
        Accel::Grid | Accel::Octree | Accel::Bsp => {
            let verb = match structure {
                Accel::Grid => "walk grid cell",
                Accel::Octree => "enter octree cell",
                _ => "enter k-d tree cell",
            };
            let then = if tests > 0 {
                format!("{tests} new object{s} to test")
            } else {
                "no new object to test".to_owned()
            };
            let line = format!("{verb} {} of {n}, {place}: {then}", k + 1);
            let details = match (structure, cell_exit(node, k)) {
                (Accel::Grid, Some(exit)) => vec![exit_words(node, k, &exit)],
                _ => Vec::new(),
            };
            (line, details)
        }
        _ => {
            let fate = if b.met { "met" } else { "missed" };
            // A 4-wide node's boxes are tested together; the leaves met among
            // them have their objects tested next.
            let then = if tests > 0 {
                format!("; then the objects of the leaves met among these boxes: {tests} test{s}")
            } else {
                String::new()
            };
            (
                format!("test box {} of {n}, {place}: {fate}{then}", k + 1),
                Vec::new(),
            )
        }
    }
}

/// "walls ahead: x = 3.784 at t = 14.6, …: the z wall comes first, …".
fn exit_words(node: &RayNode, k: usize, exit: &CellExit) -> String {
    let walls: Vec<String> = (0..3)
        .filter_map(|a| {
            exit.walls[a].map(|(w, t)| format!("{} = {} at t = {}", axis_name(a), num(w), num(t)))
        })
        .collect();
    let first = axis_name(exit.axis);
    let end = match node.hit.as_ref() {
        Some(h) if h.t <= exit.t => format!(
            "the hit at t = {} comes before it, so no later cell can hold a nearer one: the walk stops",
            num(h.t)
        ),
        _ if k + 1 == node.boxes.len() => "beyond it the grid ends".to_owned(),
        _ => "the next cell lies beyond it".to_owned(),
    };
    format!(
        "walls ahead, t = (wall − S)/c: {}; the {first} wall comes first, {end}",
        walls.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ray from the origin along (1, 2, −4) in the unit cell [0, 1]³ shifted
    /// down by one in z: the walls ahead are x = 1 at t = 1, y = 1 at t = 0.5
    /// and z = −1 at t = 0.25, so z comes first. Fails if a wall is taken on
    /// the wrong side of the cell or the nearest is not the smallest t.
    #[test]
    fn the_nearest_wall_ahead_is_the_exit() {
        let node: RayNode = serde_json::from_value(serde_json::json!({
            "kind": "primary", "depth": 1, "parent": null,
            "origin": [0.0, 0.0, 0.0], "direction": [1.0, 2.0, -4.0],
            "t_unit": "image_plane", "weight": 1.0, "t_min": 0.0, "t_max": null,
            "tests": [], "tested": {"boxes": 1, "primitives": 0},
            "boxes": [{"min": [0.0, 0.0, -1.0], "max": [1.0, 1.0, 0.0], "met": true, "after_tests": 0}],
            "hit": null, "shadow_rays": [], "local": null, "reflected": null, "refracted": null,
            "sum": {"local": [0.0, 0.0, 0.0], "k_rfl": 0.0, "reflected": [0.0, 0.0, 0.0],
                    "k_rfa": 0.0, "refracted": [0.0, 0.0, 0.0], "color": [0.0, 0.0, 0.0]}
        }))
        .expect("a node the trace format reads");
        let exit = cell_exit(&node, 0).unwrap();
        assert_eq!(
            exit.walls,
            [Some((1.0, 1.0)), Some((1.0, 0.5)), Some((-1.0, 0.25))]
        );
        assert_eq!((exit.axis, exit.t), (2, 0.25));
    }
}
