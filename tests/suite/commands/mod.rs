//! The command-line contract: what each command writes, how every bad input
//! or signal ends (one line, exit 1 or 2, nothing half-written), fuzzed inputs.

pub mod cli;
mod bounds;
mod chart;
mod fuzz;
mod inputs;
mod learner;
mod learner_image;
mod lobe;
mod nff;
mod outputs;
mod pipes;
mod postscript;
mod readers;
mod scene_files;
mod signals;
mod strip;
mod structures;
mod trace_files;
mod usage;
