//! What a diagnosis is, and every one the check knows with the lesson that
//! teaches its formula: shared by the files that recognise them
//! ([`crate::course::learner::diagnose`] and the smaller ones beside it), so
//! none of them imports another.

/// A classic mistake recognised in the numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnosis {
    /// A stable name for autograders: `rows-flipped`, `far-root`, ….
    pub id: &'static str,
    /// What the numbers show, in the lecture's words.
    pub words: String,
    /// The lesson that teaches the formula: `lessons/03-camera`.
    pub lesson: &'static str,
}

/// Every diagnosis's id and lesson, in the order the algorithm meets them.
pub const MISTAKES: &[(&str, &str)] = &[
    ("rows-flipped", "lessons/03-camera"),
    ("pixel-corner", "lessons/03-camera"),
    ("pixel-spacing", "lessons/03-camera"),
    ("far-root", "lessons/05-sphere"),
    ("negative-root", "lessons/05-sphere"),
    ("no-offset", "lessons/08-shadows"),
    ("normal-not-turned", "lessons/10-refraction"),
    ("normal-inward", "lessons/10-refraction"),
    ("normal-transform", "lessons/06-transforms"),
    ("shadow-reversed", "lessons/08-shadows"),
    ("shadow-beyond-light", "lessons/08-shadows"),
    ("transparent-blocks", "lessons/08-shadows"),
    ("transparent-per-surface", "lessons/08-shadows"),
    ("not-clamped", "lessons/07-phong"),
    ("ambient-forgotten", "lessons/07-phong"),
    ("specular-colored", "lessons/07-phong"),
    ("view-sign", "lessons/07-phong"),
    ("reflection-sign", "lessons/09-reflection"),
    ("not-normalized", "lessons/09-reflection"),
    ("eta-swapped", "lessons/10-refraction"),
    ("refraction-root-sign", "lessons/10-refraction"),
    ("refraction-cos-sign", "lessons/10-refraction"),
    ("wrong-medium", "lessons/10-refraction"),
    ("tir-not-handled", "lessons/10-refraction"),
    ("coefficients", "lessons/11-recursion"),
];

/// The diagnosis `id` with its words, in the lesson [`MISTAKES`] gives it.
pub fn found(id: &'static str, words: String) -> Option<Diagnosis> {
    let lesson = MISTAKES
        .iter()
        .find(|(i, _)| *i == id)
        .map_or("", |(_, l)| l);
    Some(Diagnosis { id, words, lesson })
}
