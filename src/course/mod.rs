//! The course: lessons and their specs, the commands behind their figures and
//! numbers, and guided step-throughs of a recorded pixel. Above the views: a
//! lesson may record the pixel it narrates (the one exception beside the
//! inspector), and it reads what the views write.

pub mod teacher_file; // the small TOML files a teacher writes, read with line-numbered errors
pub mod step_values; // the numbers a stop may quote at a step, named as the step's line says them
pub mod guide; // a guided step-through: a teacher's stops with the trace's numbers
pub(crate) mod spec_file; // a spec file's TOML as serde reads it
pub mod lesson_spec; // a lesson's spec: the commands behind its figures and numbers, its exercises
pub mod lesson_frame; // what a lesson lets a learner do, how long it takes, whether it is optional
pub mod lesson_command; // a spec's command lines, and the images and figures each one reads
pub mod spec_number; // a spec's number read from a trace, for the book and `raytree lesson`
pub mod lesson; // the lessons: finding, loading and narrating one
pub mod question; // checked questions: predict a number, checked against raytree's own
pub mod player; // a lesson's step-through as a player for the book's page
pub mod learner; // the learner trace, the check of a learner's tracer against ours, test vectors
