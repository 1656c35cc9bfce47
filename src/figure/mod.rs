//! The drawing toolkit every figure uses: a canvas in drawing coordinates
//! (y up) fitted into a frame on a page, pens and one palette, text in an
//! embedded font, labels placed so that none collides, a legend, clipping.
//! It knows nothing of rays or scenes (a test holds it to using nothing else
//! of the crate), so a diagram, a chart and the inspector draw alike.

pub mod pen; // the palette and the pens every figure draws with
pub mod canvas; // the page, its frame, and the shapes drawn on it
pub mod text; // text in the embedded font: widths, wrapping, captions
pub mod clip; // 2D clipping to a frame
pub mod labels; // labels placed so that none collides
pub mod legend; // a figure's legend box
pub mod svg; // the same figure as SVG, shape for shape
