//! The learner trace: one pixel's rays as a learner's own tracer writes them
//! (any language, any JSON library), read strictly, made from raytree's own
//! tree, and checked against it ray by ray with the first divergence named
//! and, where its numbers show one, the classic mistake behind it. The format
//! is documented in `docs/learner-trace.md`, with a JSON Schema beside it.
//! Beside it, the test vectors of the lecture's functions a learner's tracer
//! is unit-tested with first.

pub mod format; // the fields, their keys (shared with the schema's test) and the writer
pub mod read; // the strict reader: bounded, every error one line with its JSON path
pub mod reduce; // raytree's own trace reduced to the learner's fields
pub mod check; // `raytree check`: read, trace ours, compare, diagnose, report
pub mod context; // what a comparison works with: the scene, raytree's trace, the pixel
pub mod tolerance; // how close is close enough, and why
pub mod difference; // one difference: the ray's path, the quantity, both values, typed
pub mod compare; // pairing the learner's rays with ours, each quantity within its tolerance
pub mod diagnose; // which recognisers each difference asks, in order
pub mod mistakes; // the catalogue of classic mistakes, their recognisers by lesson
pub mod report; // the first divergence in the lecture's words, text or JSON
pub mod image; // a learner's whole image beside raytree's render: pixels off, the worst, their commands
pub mod vectors; // test vectors of the lecture's functions, from recorded traces of each lesson's pixels
