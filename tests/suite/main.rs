//! The integration tests, one binary (one link instead of one per file:
//! the suite builds in a fraction of the time). Each module is one subject;
//! `cargo test --release MODULE` runs one, e.g. `cargo test --release golden_traces`.

mod accel;
mod aov;
mod arithmetic;
mod book;
mod architecture;
mod chart;
mod boxes;
mod cli;
mod common;
mod diagram;
mod forward;
mod fuzz;
mod golden_traces;
mod guide;
mod inputs;
mod inspector;
mod inspector_keys;
mod inspector_teaching;
mod inspector_tmux;
mod media;
mod outputs;
mod postscript;
mod povray;
mod ray_tree;
mod readme;
mod recent;
mod recursion;
mod render;
mod scenes;
mod signals;
mod stability;
mod strip;
mod trace_files;
mod worked;
