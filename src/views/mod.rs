//! What a learner sees of a recorded tree: numbers written for reading, the
//! text trace, the figure toolkit, projections, ray diagrams and charts. Views
//! read the tree and the scene, never the tracer.

pub mod numbers; // numbers written for reading
pub mod text; // the trace in words
pub mod explain; // the lecture's arithmetic of each step, written out
pub mod pen; // the palette and the pens every figure draws with
pub mod figure; // the figure toolkit: a canvas with arrows, labels and a caption
pub mod legend; // a figure's legend box
pub mod clip; // 2D clipping to a frame
pub mod projection; // the scene projected onto a drawing plane
pub mod section; // what the drawing plane cuts, and what a ray only passes
pub mod boxes; // the hierarchy's boxes a ray was tested against, projected
pub mod diagram_layout; // a ray diagram's rays, hits and objects, projected
pub mod diagram_frame; // what a ray diagram frames
pub mod marks; // the angles, indices and badges a slide puts on a diagram
pub mod labels; // labels placed so that none collides
pub mod diagram_labels; // what a ray diagram labels, and drawing the labels
pub mod diagram; // a ray diagram as a PNG figure
pub mod camera_view; // the image plane face-on, with a pixel's place on it
pub mod object_view; // a transformed sphere's hit in its own space, beside the world
pub mod teacher_file; // the small TOML files a teacher writes, read with line-numbered errors
pub mod guide; // a guided step-through: a teacher's stops with the trace's numbers
pub mod lesson_spec; // a lesson's spec: the commands behind its figures and numbers, its exercises
pub mod lesson_command; // a spec's command lines, and the images and figures each one reads
pub mod lesson; // the lessons: finding, loading and narrating one
pub mod chart; // speed against accuracy as a chart
pub mod aov_figure; // a per-pixel quantity with its color bar or key
pub mod filmstrip; // frames side by side, one per value of a setting
pub mod difference; // two images side by side with where they differ
