//! The tracer is right: against the lecture's formulas, hand-worked colors,
//! every object tested, golden traces, and the renderer's own invariants.

mod accel;
mod arithmetic;
mod forward;
mod golden_traces;
mod media;
mod mutants;
mod polygons;
mod povray;
mod python;
mod ray_tree;
mod recent;
mod recursion;
mod render;
mod scenes;
mod structures;
mod stability;
mod worked;
