//! The integration tests, one binary (one link instead of one per file:
//! the suite builds in a fraction of the time), grouped by kind; each module
//! is one subject. `cargo test --release NAME` runs those whose path holds
//! NAME, e.g. `cargo test --release golden_traces` or `cargo test --release figures`.

mod common; // helpers shared by the tests
mod tools; // what a test needs beyond Rust, skipped (or failed under CI) without it

mod commands; // the command-line contract: outputs, errors, signals, fuzzing
mod docs; // the book, the README, step-throughs, the shape of the house
mod figures; // diagrams, boxes, per-pixel quantities
mod inspector; // the inspector, with and without a terminal
mod tracer; // the tracer's numbers and images
