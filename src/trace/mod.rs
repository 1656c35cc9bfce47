//! Running the lecture's algorithm: the recorder interface the tracer reports
//! to, the tracer itself, the accelerator that picks the objects a ray is tested
//! against, and the renderer that traces every pixel.

pub mod recorder; // what the tracer reports, and to whom
pub mod tracer; // the lecture's raytrace(): closest hit, shadow rays, reflection, refraction
pub mod accelerator; // which objects a ray is tested against
pub mod recent; // try the recent hit first: the last blocker of each light's shadow rays
pub mod pixel; // one pixel's rays: its center, a grid, or adaptive subdivision
pub mod progress; // how far long work got, and whether to stop: closures, no terminal
pub mod render; // the one pixel loop: every pixel (or every n-th, or a window), on all cores
pub mod pixel_record; // one pixel's record: what its rays' trees were made of
pub mod aov; // per-pixel quantities that explain an image: what each is and how it reads
pub mod aov_render; // rendering one, through a recorder
pub mod forward; // rays from the lights to the eye, counted
pub mod frames; // a filmstrip's frames in turn, each with how much it changed
pub mod sweep; // speed against accuracy, measured
pub mod structure_sweep; // the efficiency slide's structures compared, measured
