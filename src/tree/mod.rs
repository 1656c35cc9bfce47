//! The ray tree: every ray one pixel spawns, recorded; its steps in the order
//! the algorithm ran them; the trace document that saves it as JSON.

pub mod document;
pub mod ray_tree;
pub mod record;
pub mod steps;
