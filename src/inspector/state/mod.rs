//! The inspector's state in owned parts, apart from any terminal: each part
//! keeps its fields private behind a small API, and [`App`](super::App)
//! composes them.

pub mod features; // what each pixel's tree holds, for `f` and the overlays
pub mod find; // what `f` seeks, the overlay, the features' scan
pub mod image_view; // the image pane's zoom, picture and worker
pub mod preview; // the picture traced on its own thread, cancelled when stale
pub mod reveal; // what the algorithm has computed by a step
pub mod selection; // the pixel, its trace, the focus, the tree pane's cursor
pub mod stepping; // where in the algorithm's steps the panes are, the guide
pub mod traced_scene; // the scene with what its tracers share, made once
pub mod whatif; // the what-if edits, undoing and writing them
