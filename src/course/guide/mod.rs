//! Guided step-throughs: a teacher's script of stops along one pixel's steps
//! (`steps.toml`, read in [`script`]), told against a fresh trace with the
//! trace's own numbers ([`narrate`]), each number named as the step's line
//! says it ([`step_values`]).

pub mod narrate; // each stop told against a trace, its placeholders filled
pub mod script; // the script file: scene, pixel, stops, what the book's player draws
pub mod step_values; // the numbers a stop may quote at a step, named as the step's line says them

pub use narrate::{Narration, Untold, narrate, tell};
pub use script::{PlayerView, Script, ScriptStop, load, parse};
pub use step_values::values;
