//! NFF's polygons (`p`) and polygonal patches (`pp`), checked in the format's
//! own terms: a vertex by its number from 1 and the line it is on, as a
//! reader of the file counts them, not by the scene JSON's `vertices[0]`.
//!
//! NFF takes a polygon's normal from its first two edges, and asks that they
//! make a convex corner. A first corner that is reflex turns the normal away
//! from the outline's own winding: the polygon would face away, unseen from
//! the side its vertices say is the front. Newell's normal of the whole
//! outline knows the winding whichever corner comes first, so where the two
//! disagree the file is refused, naming the corner.

use glam::DVec3;
use serde_json::{Value, json};

use crate::geometry::polygon::Polygon;
use crate::geometry::polygon_plane::{PlaneError, newell_normal, plane_normal};
use crate::scene::limits;
use crate::scene::nff::{Line, MAX_POLYGON_VERTICES, Reader};
use crate::scene::nff_json::xyz;
use crate::scene::quote::quote;
use crate::scene::scene_error::SceneError;

/// A distance for a message: four significant digits, as short as it reads
/// (`1`, `0.5`, `1.235e-7`).
fn distance(x: f64) -> String {
    let rounded = format!("{x:.3e}").parse::<f64>().unwrap_or(x);
    limits::num(rounded)
}

impl Reader<'_> {
    /// `p N` then N lines `X Y Z`, or `pp N` then N lines `X Y Z NX NY NZ`.
    pub(super) fn polygon(
        &mut self,
        line: &Line,
        patch: bool,
        transparent: bool,
    ) -> Result<Value, SceneError> {
        self.count(line, 1)?;
        let keyword = if patch { "pp" } else { "p" };
        let (column, word) = line.words[1];
        let count = word
            .parse::<usize>()
            .ok()
            .filter(|n| (3..=MAX_POLYGON_VERTICES).contains(n))
            .ok_or_else(|| {
                self.error(
                    line.number,
                    column,
                    format!(
                        "{} is not a vertex count for '{keyword}' (a whole number from 3 to {MAX_POLYGON_VERTICES})",
                        quote(word, "'")
                    ),
                )
            })?;
        let what = if patch {
            "polygonal patch (pp)"
        } else {
            "polygon (p)"
        };
        let per_line = if patch { 6 } else { 3 };
        let mut vertices = Vec::with_capacity(count);
        let mut normals = Vec::with_capacity(if patch { count } else { 0 });
        // Where each vertex is: its line and its first column.
        let mut at = Vec::with_capacity(count);
        for k in 1..=count {
            let v = self.next_for(what, line.number)?;
            let vertex = format!(
                "vertex {k} of {count} of the {what} on line {}",
                line.number
            );
            self.expect_numbers(&v, per_line, &vertex)?;
            vertices.push(self.point(&v, 0, "a vertex")?);
            if patch {
                let n = self.point(&v, 3, "a normal")?;
                limits::direction(n).map_err(|e| {
                    self.error(
                        v.number,
                        v.words[3].0,
                        format!("the normal of {vertex} {e}"),
                    )
                })?;
                normals.push(n);
            }
            at.push((v.number, v.words[0].0));
        }
        let normal = plane_normal(&vertices).map_err(|e| match e {
            PlaneError::Collinear => self.error(
                at[2].0,
                at[2].1,
                format!(
                    "vertices 1 to 3 of the {what} on line {} lie on one line: they give it no plane (NFF takes the plane from them)",
                    line.number
                ),
            ),
            PlaneError::OffPlane {
                vertex,
                off,
                allowed,
            } => self.error(
                at[vertex].0,
                at[vertex].1,
                format!(
                    "vertex {} of the {what} on line {} lies {} off the plane of vertices 1 to 3 (allowed: {})",
                    vertex + 1,
                    line.number,
                    distance(off),
                    distance(allowed)
                ),
            ),
        })?;
        if newell_normal(&vertices).dot(normal) < 0.0 {
            return Err(self.error(
                at[1].0,
                at[1].1,
                format!(
                    "the {what} on line {} has a reflex first corner, at vertex 2: NFF takes the normal from the first two edges, which must make a convex angle, and these turn it away from the outline's own winding (start the outline at a convex corner)",
                    line.number
                ),
            ));
        }
        let normals: Option<Vec<DVec3>> = patch.then_some(normals);
        let one_sided = !patch && !transparent;
        Polygon::new(vertices.clone(), normals.clone(), one_sided)
            .map_err(|e| self.error(line.number, column, format!("a polygon: {e}")))?;
        let kind = if patch { "patch" } else { "polygon" };
        let mut polygon = json!({
            "vertices": vertices.iter().map(|&v| xyz(v)).collect::<Vec<_>>(),
        });
        if let Some(normals) = normals {
            polygon["normals"] = json!(normals.iter().map(|&n| xyz(n)).collect::<Vec<_>>());
        }
        if one_sided {
            polygon["one_sided"] = json!(true);
        }
        Ok(json!({
            "name": format!("{kind} at line {}", line.number),
            "polygon": polygon,
        }))
    }
}
