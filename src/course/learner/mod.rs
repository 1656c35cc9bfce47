//! The learner trace: one pixel's rays as a learner's own tracer writes them
//! (any language, any JSON library), read strictly, made from raytree's own
//! tree, and checked against it ray by ray with the first divergence named
//! and, where its numbers show one, the classic mistake behind it. The format
//! is documented in `docs/learner-trace.md`, with a JSON Schema beside it.

pub mod format; // the fields, their keys (shared with the schema's test) and the writer
pub mod read; // the strict reader: bounded, every error one line with its JSON path
pub mod reduce; // raytree's own trace reduced to the learner's fields
pub mod measure; // the tolerances and why, and what a comparison works with
pub mod compare; // pairing the learner's rays with ours, each quantity within its tolerance
pub mod mistake; // what a diagnosis is, and every id with its lesson
pub mod diagnose; // the classic mistakes, each recognised from its numbers
pub mod pixel_grid; // primary rays spaced by 2W/N, not the lecture's 2W/(N − 1)
pub mod signs; // the sign mistakes: a shadow ray reversed, Snell's formula with a sign turned
pub mod terms; // what a local color or a shadow ray adds up: ambient left out, specular tinted, k_rfa per surface
pub mod report; // the check: the first divergence in the lecture's words, text or JSON
pub mod image; // a learner's whole image beside raytree's render: pixels off, the worst, their commands
pub mod whole_image; // the mistakes that change a whole image at once: no sRGB, flipped, mirrored, BGR
