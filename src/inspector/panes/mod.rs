//! The inspector's panes, each drawing one part of the screen from the state
//! and changing none of it: `ui.rs` places them where `layout.rs` says.

pub mod details; // the selected ray's numbers
pub mod diagram; // the pixel's rays in Braille dots
pub mod image; // the render in half blocks, the cursor, the overlays
pub mod tree; // one line per ray and per shadow ray
