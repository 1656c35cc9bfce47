//! NFF's objects: spheres (`s`), cylinders and cones (`c`), polygons (`p`)
//! and polygonal patches (`pp`), checked in the format's own terms: a vertex
//! by its number from 1 and the line it is on, as a reader of the file counts
//! them, not by the scene JSON's `vertices[0]`; a negative radius as NFF's
//! inside-only object, which raytree does not support.
//!
//! NFF takes a polygon's normal from its first two edges, and asks that they
//! make a convex corner. A first corner that is reflex turns the normal away
//! from the outline's own winding: the polygon would face away, unseen from
//! the side its vertices say is the front. Newell's normal of the whole
//! outline knows the winding whichever corner comes first, so where the two
//! disagree the file is refused, naming the corner (the check is
//! [`plane_normal`]'s, which the scene JSON's polygons share).

use glam::DVec3;

use crate::geometry::cone::cone_object;
use crate::geometry::polygon::Polygon;
use crate::geometry::polygon_plane::{PlaneError, plane_normal};
use crate::scene::format::{ConeFile, ObjectFile, PolygonFile, SphereFile};
use crate::scene::limits;
use crate::scene::nff::MAX_POLYGON_VERTICES;
use crate::scene::nff::reader::{Line, Reader};
use crate::scene::quote::quote;
use crate::scene::scene_error::SceneError;

/// A distance for a message: four significant digits, as short as it reads
/// (`1`, `0.5`, `1.235e-7`).
fn distance(x: f64) -> String {
    let rounded = format!("{x:.3e}").parse::<f64>().unwrap_or(x);
    limits::num(rounded)
}

impl Reader<'_> {
    /// `s X Y Z R`.
    pub(super) fn sphere(&self, line: &Line) -> Result<ObjectFile, SceneError> {
        let [_, _, _, r] = self.numbers(line)?;
        let center = self.point(line, 1, "a sphere's center")?;
        let column = line.words[4].0;
        if r < 0.0 {
            return Err(self.error(line.number, column, inside_only("sphere (s)", "radius")));
        }
        let r = limits::length(r)
            .map_err(|e| self.error(line.number, column, format!("a sphere's radius {e}")))?;
        Ok(ObjectFile {
            name: Some(format!("sphere at line {}", line.number)),
            sphere: Some(SphereFile {
                center: Some(center),
                radius: Some(r),
            }),
            ..ObjectFile::default()
        })
    }

    /// `c` and the base `X Y Z R` and the apex `X Y Z R`: eight numbers on its
    /// own line (as the SPD's generators write it) or on the two lines after
    /// it (as NFF's description does).
    pub(super) fn cone(&mut self, line: &Line) -> Result<ObjectFile, SceneError> {
        // Each end's center, radius, and where its radius is (line, column).
        let end = |words: &Line, first: usize, which: &str| {
            let center = self.point(words, first, &format!("the cone's {which}"))?;
            let [r] = self.numbers_from(words, first + 3)?;
            Ok::<_, SceneError>((center, r, (words.number, words.words[first + 3].0)))
        };
        let (base, apex) = match line.words.len() - 1 {
            8 => {
                let _: [f64; 8] = self.numbers_from(line, 1)?;
                (end(line, 1, "base")?, end(line, 5, "apex")?)
            }
            0 => {
                let mut next = |which: &str| {
                    let words = self.next_for("cylinder or cone (c)", line.number)?;
                    let what = format!(
                        "the {which} X Y Z R of the cone (c) on line {}",
                        line.number
                    );
                    self.expect_numbers(&words, 4, &what)?;
                    let center = self.point(&words, 0, &format!("the cone's {which}"))?;
                    let [r] = self.numbers_from(&words, 3)?;
                    Ok::<_, SceneError>((center, r, (words.number, words.words[3].0)))
                };
                (next("base")?, next("apex")?)
            }
            n => {
                return Err(self.error(
                    line.number,
                    line.words[0].0,
                    format!(
                        "a cone (c) takes 8 numbers, base X Y Z R and apex X Y Z R, on its line or on the two after it; got {n}"
                    ),
                ));
            }
        };
        let ((base, base_radius, base_at), (apex, apex_radius, apex_at)) = (base, apex);
        for (r, (number, column), which) in [
            (base_radius, base_at, "base"),
            (apex_radius, apex_at, "apex"),
        ] {
            if r < 0.0 {
                let radius = format!("{which} radius");
                return Err(self.error(
                    number,
                    column,
                    inside_only("cylinder or cone (c)", &radius),
                ));
            }
        }
        let name = format!("cone at line {}", line.number);
        let at = line.words[0].0;
        let refuse = |why: String| Err(self.error(line.number, at, why));
        if base_radius == 0.0 && apex_radius == 0.0 {
            return refuse(
                "the base and apex radii of the cone (c) are both 0: it would be a line".into(),
            );
        }
        if base == apex {
            return refuse(
                "the base and apex of the cone (c) are the same point: it would have no length"
                    .into(),
            );
        }
        if let Err(e) = cone_object(name.clone(), base, base_radius, apex, apex_radius, 0) {
            return refuse(format!("a cone (c): {e}"));
        }
        Ok(ObjectFile {
            name: Some(name),
            cone: Some(ConeFile {
                base,
                base_radius,
                apex,
                apex_radius,
            }),
            ..ObjectFile::default()
        })
    }

    /// `p N` then N lines `X Y Z`, or `pp N` then N lines `X Y Z NX NY NZ`.
    pub(super) fn polygon(
        &mut self,
        line: &Line,
        patch: bool,
        transparent: bool,
    ) -> Result<ObjectFile, SceneError> {
        let count = self.vertex_count(line, patch)?;
        let what = if patch {
            "polygonal patch (pp)"
        } else {
            "polygon (p)"
        };
        let outline = self.outline(line, count, patch, what)?;
        plane_normal(&outline.vertices)
            .map_err(|e| self.plane_error(e, &outline.at, what, line.number))?;
        let normals: Option<Vec<DVec3>> = patch.then_some(outline.normals);
        let one_sided = !patch && !transparent;
        let column = line.words[1].0;
        Polygon::new(outline.vertices.clone(), normals.clone(), one_sided)
            .map_err(|e| self.error(line.number, column, format!("a polygon: {e}")))?;
        let kind = if patch { "patch" } else { "polygon" };
        Ok(ObjectFile {
            name: Some(format!("{kind} at line {}", line.number)),
            polygon: Some(PolygonFile {
                vertices: outline.vertices,
                normals,
                one_sided: one_sided.then_some(true),
            }),
            ..ObjectFile::default()
        })
    }

    /// The vertex count after `p` or `pp` (`patch`) on `line`: 3 to
    /// [`MAX_POLYGON_VERTICES`].
    fn vertex_count(&self, line: &Line, patch: bool) -> Result<usize, SceneError> {
        self.count(line, 1)?;
        let keyword = if patch { "pp" } else { "p" };
        let (column, word) = line.words[1];
        word.parse::<usize>()
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
            })
    }

    /// The `count` vertex lines after `line`, the polygon or patch (`patch`)
    /// named `what`: each a point, and for a patch a normal that is not zero.
    fn outline(
        &mut self,
        line: &Line,
        count: usize,
        patch: bool,
        what: &str,
    ) -> Result<Outline, SceneError> {
        let per_line = if patch { 6 } else { 3 };
        let mut outline = Outline {
            vertices: Vec::with_capacity(count),
            normals: Vec::with_capacity(if patch { count } else { 0 }),
            at: Vec::with_capacity(count),
        };
        for k in 1..=count {
            let v = self.next_for(what, line.number)?;
            let vertex = format!(
                "vertex {k} of {count} of the {what} on line {}",
                line.number
            );
            self.expect_numbers(&v, per_line, &vertex)?;
            outline.vertices.push(self.point(&v, 0, "a vertex")?);
            if patch {
                let n = self.point(&v, 3, "a normal")?;
                limits::direction(n).map_err(|e| {
                    self.error(
                        v.number,
                        v.words[3].0,
                        format!("the normal of {vertex} {e}"),
                    )
                })?;
                outline.normals.push(n);
            }
            outline.at.push((v.number, v.words[0].0));
        }
        Ok(outline)
    }

    /// Why the outline's vertices give the polygon named `what`, begun on
    /// line `from`, no plane NFF can use, at the vertex at fault (`at`: each
    /// vertex's line and column).
    fn plane_error(
        &self,
        e: PlaneError,
        at: &[(usize, usize)],
        what: &str,
        from: usize,
    ) -> SceneError {
        match e {
            PlaneError::Collinear => self.error(
                at[2].0,
                at[2].1,
                format!(
                    "vertices 1 to 3 of the {what} on line {from} lie on one line: they give it no plane (NFF takes the plane from them)"
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
                    "vertex {} of the {what} on line {from} lies {} off the plane of vertices 1 to 3 (allowed: {})",
                    vertex + 1,
                    distance(off),
                    distance(allowed)
                ),
            ),
            PlaneError::ReflexFirstCorner => self.error(
                at[1].0,
                at[1].1,
                format!(
                    "the {what} on line {from} has a reflex first corner, at vertex 2: NFF takes the normal from the first two edges, which must make a convex angle, and these turn it away from the outline's own winding (start the outline at a convex corner)"
                ),
            ),
        }
    }
}

/// A polygon's vertices as read, its normals (a patch's), and where each
/// vertex is: its line and its first column.
struct Outline {
    vertices: Vec<DVec3>,
    normals: Vec<DVec3>,
    at: Vec<(usize, usize)>,
}

/// The refusal of a negative radius, which NFF gives an object seen only
/// from inside: raytree's objects are seen from both sides or from outside.
fn inside_only(object: &str, radius: &str) -> String {
    format!(
        "a negative {radius} makes NFF's inside-only {object}, seen only from inside, which raytree does not support"
    )
}
