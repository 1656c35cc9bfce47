//! The ray tree: every ray one pixel spawns, recorded; its steps in the order
//! the algorithm ran them; the trace document that saves it as JSON.

pub mod ray_tree; // the rays one pixel spawns, with every number
pub mod arithmetic; // the lecture's quantities of each step, worked out while recording
pub mod shape_arithmetic; // how an object was tested: each shape's own numbers
pub mod record; // recording a pixel or a ray
pub mod steps; // the tree read in the order the algorithm ran
pub mod document; // the trace document: JSON, versioned (writing)
pub mod trace_check; // a trace read from a file holds together, and fits its scene
pub mod reading; // a trace document read back, checked
