//! What a learner sees of a recorded tree: numbers written for reading, the
//! text trace, the figure toolkit, projections, ray diagrams and charts. Views
//! read the tree and the scene, never the tracer.

pub mod numbers; // numbers written for reading
pub mod text; // the trace in words
pub mod explain; // the lecture's arithmetic of each step, written out
pub mod figure; // the figure toolkit: a canvas with arrows, labels, legend, caption
pub mod clip; // 2D clipping to a frame
pub mod projection; // the scene projected onto a drawing plane
pub mod diagram_layout; // a ray diagram's rays, hits and objects, projected
pub mod diagram; // a ray diagram as a PNG figure
pub mod chart; // speed against accuracy as a chart
