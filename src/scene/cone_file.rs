//! The scene file's `cone` shape, checked: its points and radii within the
//! limits, then placed as [`crate::geometry::cone::cone_object`] places it,
//! through the same [`cone_placement`].
//!
//! Errors name the field at fault, `(field, message)`, e.g.
//! `("objects[3].cone.base_radius", "…")`, or the cone as a whole for what no
//! one field is to blame for; the loader adds the file.

use glam::DAffine3;

use crate::geometry::cone::{Cone, cone_placement};
use crate::scene::format::ConeFile;
use crate::scene::limits;

/// A field's path and what is wrong with it.
pub(super) type FieldError = (String, String);

/// Object `i`'s unit cone and the map placing it between its two ends.
pub(super) fn placed(i: usize, c: &ConeFile) -> Result<(Cone, DAffine3), FieldError> {
    let at = |f: &str| {
        if f.is_empty() {
            format!("objects[{i}].cone")
        } else {
            format!("objects[{i}].cone.{f}")
        }
    };
    let base = limits::point(c.base).map_err(|e| (at("base"), e))?;
    let apex = limits::point(c.apex).map_err(|e| (at("apex"), e))?;
    let radius =
        |f: &str, r: f64| limits::within(r, 0.0, limits::MAX_LENGTH).map_err(|e| (at(f), e));
    let base_radius = radius("base_radius", c.base_radius)?;
    let apex_radius = radius("apex_radius", c.apex_radius)?;
    cone_placement(base, base_radius, apex, apex_radius).map_err(|e| (at(e.field), e.message))
}
