//! The course: lessons and their specs, the commands behind their figures and
//! numbers, and guided step-throughs of a recorded pixel. Above the views: a
//! lesson may record the pixel it narrates (the one exception beside the
//! inspector), and it reads what the views write.

pub mod teacher_file; // the small TOML files a teacher writes, read with line-numbered errors
pub mod guide; // guided step-throughs: a teacher's stops told with the trace's numbers
pub mod spec; // a lesson's spec: the commands behind its figures and numbers, its frame, exercises and questions
pub mod number; // a spec's number read from a trace, for the book and `raytree lesson`
pub mod lesson; // the lessons: finding, loading and narrating one
pub mod player; // a lesson's step-through as a player for the book's page
pub mod learner; // the learner trace, the check of a learner's tracer against ours, test vectors
