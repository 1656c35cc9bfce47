//! What a learner sees of a recorded tree: numbers written for reading, the
//! text trace and its explanations, ray diagrams, and the figures that explain
//! an image (AOVs, filmstrips, differences, charts). Views read the tree and
//! the scene, never the tracer; they draw with [`crate::figure`].

pub mod numbers; // numbers written for reading
pub mod text; // the trace in words
pub mod wrap; // long lines wrapped with a hanging indent, for the inspector and the book
pub mod explain; // the lecture's arithmetic of each step, written out
pub mod walk; // a structure's walk step by step: the box or cell, and the wall a grid cell is left through
pub mod diagram; // a pixel's rays drawn over the scene, in 2D
pub mod hit_vectors; // one hit's c, n and v enlarged, with c split along and across n
pub mod tree_graph; // a pixel's rays as a tree: a box per ray, an edge per parent and child
pub mod aov_figure; // a per-pixel quantity with its color bar or key
pub mod filmstrip; // frames side by side, one per value of a setting
pub mod forward_figure; // a forward run: its counts in words, its sparse image beside the backward render
pub mod difference; // two images side by side with where they differ
pub mod chart; // speed against accuracy as a chart
pub mod lobe; // Phong's highlight (R·V)^shininess against the angle from the mirror direction
pub mod structures_chart; // the structures compared: a table and a chart
