//! A laid-out ray diagram: a pixel's rays, hits and the scene's objects in
//! drawing coordinates, with the window worth framing. [`crate::views::diagram::arrange`]
//! makes it; the figure ([`crate::views::diagram::draw`]) and the inspector's
//! diagram pane both draw from it.

use glam::{DVec2, DVec3};

use crate::methods::Accel;
use crate::tree::ray_tree::RayKind;
use crate::views::diagram::boxes::BoxMark;
use crate::views::diagram::marks::Marks;
use crate::views::diagram::projection::{Outline, Projection};
use crate::views::diagram::style::Stroke;

/// One drawn line, in diagram coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// Where it starts.
    pub from: DVec2,
    /// Where it ends: its hit, its light, or far out for a ray that leaves the scene.
    pub to: DVec2,
    /// The ray leaves the scene: it runs on to the frame's edge.
    pub leaves: bool,
    /// What it is.
    pub stroke: Stroke,
    /// The tree node it belongs to.
    pub node: usize,
    /// Which of the node's shadow rays it draws, for a shadow ray.
    pub shadow: Option<usize>,
    /// Parameter intervals of `from → to` where it only passes in front of or
    /// behind an object's silhouette: drawn faded and dotted.
    pub passing: Vec<[f64; 2]>,
    /// The 3D ends, for marks along it.
    pub ends: (DVec3, DVec3),
}

impl Segment {
    /// The line in pieces, in order: `(from, to, passing, last)`, where a
    /// piece is `passing` (drawn faint and dotted) inside one of the
    /// [`passing`](Self::passing) intervals and `last` when it ends the line.
    pub fn pieces(&self) -> impl Iterator<Item = (DVec2, DVec2, bool, bool)> + '_ {
        let at = |t: f64| self.from + (self.to - self.from) * t;
        let cuts: Vec<f64> = std::iter::once(0.0)
            .chain(self.passing.iter().flatten().copied())
            .chain(std::iter::once(1.0))
            .collect();
        (0..cuts.len() - 1)
            .map(move |k| (at(cuts[k]), at(cuts[k + 1]), k % 2 == 1, cuts[k + 1] == 1.0))
    }
}

/// A hit point, drawn as a dot with its normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitMark {
    /// The tree node whose hit it is.
    pub node: usize,
    /// That node's depth.
    pub depth: u32,
    /// The object hit.
    pub object: usize,
    /// Where.
    pub at: DVec2,
    /// The normal the formulas use, in the drawing.
    pub normal: DVec2,
    /// The kind of the ray that hit.
    pub kind: RayKind,
}

/// An object as drawn: its silhouette (a ghost) and what the drawing plane cuts of it.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectShape {
    /// Its index in the scene's objects.
    pub object: usize,
    /// The outline of everything it hides.
    pub silhouette: Outline,
    /// Its cross-section with the drawing plane; `None` when the plane misses it.
    pub section: Option<Outline>,
    /// A ray hit it or it blocked a shadow ray.
    pub touched: bool,
}

/// Everything a diagram shows, projected, with the window to fit.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// The projection.
    pub proj: Projection,
    /// Shadow rays first, then rays.
    pub segments: Vec<Segment>,
    /// Hit points in the order they were found.
    pub hits: Vec<HitMark>,
    /// The objects projected (every one, or those the rays met), in the
    /// order of their indices.
    pub objects: Vec<ObjectShape>,
    /// The eye.
    pub eye: DVec2,
    /// The image plane's cut (two ends) and the pixel on it.
    pub image_plane: Option<(DVec2, DVec2, DVec2)>,
    /// The lights.
    pub lights: Vec<DVec2>,
    /// The angles, indices, badges and marks a slide needs.
    pub marks: Marks,
    /// The window the drawing should fit: `(lo, hi)`.
    pub window: (DVec2, DVec2),
    /// For a ray that hit nothing: the objects it passed nearest, each with its
    /// gap and the closest approach drawn (from the ray, to the object).
    pub near_misses: Vec<(usize, f64, DVec2, DVec2)>,
    /// With `boxes`: the hierarchy's boxes the drawn rays were tested against
    /// (the cells or nodes they walked, for a grid or a tree).
    pub boxes: Vec<BoxMark>,
    /// The structure the boxes are of (the trace's).
    pub structure: Accel,
}

impl Layout {
    /// Object `i` as drawn, if it was projected.
    pub fn object(&self, i: usize) -> Option<&ObjectShape> {
        self.objects
            .binary_search_by_key(&i, |o| o.object)
            .ok()
            .map(|k| &self.objects[k])
    }
}
