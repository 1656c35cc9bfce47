//! Figures: ray diagrams, the hierarchy's boxes, per-pixel quantities, each
//! probed at worked-out pixels and held to golden images.

mod aov;
mod boxes;
mod diagram;
mod lessons;
mod svg;
mod tree_graph;
