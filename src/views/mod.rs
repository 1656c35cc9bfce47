//! What a learner sees of a recorded tree: numbers written for reading, the
//! text trace, the figure toolkit, projections, ray diagrams and charts. Views
//! read the tree and the scene, never the tracer.

pub mod chart;
pub mod clip;
pub mod diagram;
pub mod diagram_layout;
pub mod figure;
pub mod numbers;
pub mod projection;
pub mod text;
