//! Running the lecture's algorithm: the recorder interface the tracer reports
//! to, the tracer itself, the accelerator that picks the objects a ray is tested
//! against, and the renderer that traces every pixel.

pub mod accelerator;
pub mod pixel;
pub mod recorder;
pub mod render;
pub mod sweep;
pub mod tracer;
