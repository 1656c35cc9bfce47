//! A lesson's frame, what a teacher says before the first word of it: what
//! the learner will be able to do afterwards (two to four objectives, each
//! finishing "After this lesson you can …"), how long it honestly takes
//! (reading, the exercises, building it yourself), and whether it goes beyond
//! the lecture and may be skipped. Written at the top of `lesson.toml`:
//!
//! ```toml
//! objectives = ["turn a pixel's column and row into the point P(r, c) on the image plane", "…"]
//! minutes = { reading = 20, exercises = 15, build = 30 }
//! beyond_lecture = true   # only where the lesson goes past the lecture
//! ```
//!
//! The book prints it under the chapter's heading, `raytree lesson` lists the
//! minutes, and `raytree lesson N` heads its step-through with it.

use serde::Deserialize;
use toml::Spanned;

/// Fewer than two objectives says too little; more than four, too much to
/// hold in mind while reading.
pub const OBJECTIVES: std::ops::RangeInclusive<usize> = 2..=4;

/// An objective is read at a glance, so it is one line of a page.
const OBJECTIVE_CHARS: usize = 140;

/// A lesson is one sitting: longer than this is two lessons.
const MOST_MINUTES: u32 = 240;

/// How long a lesson takes, in minutes, part by part.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Minutes {
    /// Reading the chapter, its figures and excerpts, and its step-through.
    pub reading: u32,
    /// Doing its exercises before opening the answers.
    pub exercises: u32,
    /// Writing its functions in the Python tracer (lessons 3 to 11).
    #[serde(default)]
    pub build: u32,
}

impl Minutes {
    /// All of it.
    pub fn total(&self) -> u32 {
        self.reading + self.exercises + self.build
    }

    /// `About 65 minutes: 20 reading, 15 for the exercises, 30 to build it yourself.`
    pub fn sentence(&self) -> String {
        let mut parts = vec![format!("{} reading", self.reading)];
        if self.exercises > 0 {
            parts.push(format!("{} for the exercises", self.exercises));
        }
        if self.build > 0 {
            parts.push(format!("{} to build it yourself", self.build));
        }
        format!("About {} minutes: {}.", self.total(), parts.join(", "))
    }
}

/// The one-line note a lesson beyond the lecture opens with.
pub const BEYOND_LECTURE: &str = "Beyond the lecture, and optional: this lesson goes past what the lecture teaches; skip it on a first pass.";

/// The frame's fields as serde reads them, with their spans for messages.
#[derive(Default)]
pub(crate) struct FrameFile {
    pub(crate) objectives: Option<Spanned<Vec<String>>>,
    pub(crate) minutes: Option<Spanned<Minutes>>,
    pub(crate) beyond_lecture: Option<bool>,
}

/// The frame, read and checked.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frame {
    /// What the learner can do after the lesson, each finishing "After this
    /// lesson you can …"; empty when the file gives none (a book page).
    pub objectives: Vec<String>,
    /// How long it takes, when the file says.
    pub minutes: Option<Minutes>,
    /// Whether it goes beyond the lecture and is optional.
    pub beyond_lecture: bool,
}

/// Checks the frame's fields; an error is the line (of `text`, the spec) and
/// what is wrong there.
pub(crate) fn check(file: FrameFile, text: &str) -> Result<Frame, (usize, String)> {
    let line = |at: usize| crate::course::teacher_file::line_of(text, at);
    let mut objectives = Vec::new();
    if let Some(o) = file.objectives {
        let l = line(o.span().start);
        let list = o.into_inner();
        if !OBJECTIVES.contains(&list.len()) {
            return Err((
                l,
                format!(
                    "objectives: {} given; a lesson has {} to {} (each finishing \"After this lesson you can …\")",
                    list.len(),
                    OBJECTIVES.start(),
                    OBJECTIVES.end()
                ),
            ));
        }
        for (k, o) in list.iter().enumerate() {
            let o = o.trim();
            let bad = if o.is_empty() {
                Some("is empty".to_owned())
            } else if o.contains('\n') {
                Some("is more than one line".to_owned())
            } else if o.chars().count() > OBJECTIVE_CHARS {
                Some(format!("is longer than {OBJECTIVE_CHARS} characters"))
            } else if o.to_lowercase().starts_with("after this lesson") {
                Some("repeats \"After this lesson you can\": write only what follows it".to_owned())
            } else {
                None
            };
            if let Some(bad) = bad {
                return Err((l, format!("objectives: objective {} {bad}", k + 1)));
            }
            objectives.push(o.to_owned());
        }
    }
    let minutes = match file.minutes {
        Some(m) => {
            let l = line(m.span().start);
            let m = m.into_inner();
            if m.reading == 0 {
                return Err((l, "minutes: reading takes more than 0 minutes".to_owned()));
            }
            if m.total() > MOST_MINUTES {
                return Err((
                    l,
                    format!(
                        "minutes: {} in all is more than one sitting ({MOST_MINUTES}); split the lesson",
                        m.total()
                    ),
                ));
            }
            Some(m)
        }
        None => None,
    };
    Ok(Frame {
        objectives,
        minutes,
        beyond_lecture: file.beyond_lecture.unwrap_or(false),
    })
}

/// The frame as text, one item a line: what `raytree lesson N` prints under
/// its heading (the book writes the same in Markdown).
pub fn text(frame: &Frame) -> String {
    let mut out = String::new();
    if frame.beyond_lecture {
        out.push_str(BEYOND_LECTURE);
        out.push('\n');
    }
    if !frame.objectives.is_empty() {
        out.push_str("After this lesson you can\n");
        for o in &frame.objectives {
            out.push_str(&format!("  - {o}\n"));
        }
    }
    if let Some(m) = frame.minutes {
        out.push_str(&m.sentence());
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use crate::course::spec::parse;

    const TOP: &str = "title = \"T\"\nsummary = \"S\"\n";

    #[test]
    fn a_frame_reads_and_says_its_minutes() {
        let spec = parse(
            Path::new("lessons/03-x/lesson.toml"),
            &format!(
                "{TOP}objectives = [\"aim a ray\", \" find its hit \"]\n\
                 minutes = {{ reading = 20, exercises = 15, build = 30 }}\nbeyond_lecture = true\n"
            ),
        )
        .unwrap();
        let frame = spec.frame;
        assert_eq!(frame.objectives, ["aim a ray", "find its hit"]);
        assert!(frame.beyond_lecture);
        let m = frame.minutes.unwrap();
        assert_eq!(m.total(), 65);
        assert_eq!(
            m.sentence(),
            "About 65 minutes: 20 reading, 15 for the exercises, 30 to build it yourself."
        );
        let text = super::text(&frame);
        assert!(
            text.starts_with("Beyond the lecture, and optional")
                && text.contains("After this lesson you can\n  - aim a ray\n  - find its hit\n"),
            "{text}"
        );
        // Without a build part, the sentence leaves it out; a page has no frame.
        let m = super::Minutes {
            reading: 30,
            exercises: 15,
            build: 0,
        };
        assert_eq!(
            m.sentence(),
            "About 45 minutes: 30 reading, 15 for the exercises."
        );
        let page = parse(Path::new("book/pages/p.toml"), TOP).unwrap();
        assert_eq!(page.frame, super::Frame::default());
        assert_eq!(super::text(&page.frame), "");
    }

    #[test]
    fn a_bad_frame_field_is_one_line_naming_file_and_line() {
        let cases = [
            (
                "objectives = [\"one\"]\n",
                "line 3: objectives: 1 given; a lesson has 2 to 4",
            ),
            (
                "objectives = [\"a\", \"b\", \"c\", \"d\", \"e\"]\n",
                "line 3: objectives: 5 given",
            ),
            (
                "objectives = [\"a\", \" \"]\n",
                "line 3: objectives: objective 2 is empty",
            ),
            (
                "objectives = [\"a\", \"b\\nc\"]\n",
                "objective 2 is more than one line",
            ),
            (
                "objectives = [\"After this lesson you can aim\", \"b\"]\n",
                "line 3: objectives: objective 1 repeats",
            ),
            ("objectives = \"aim\"\n", "line 3: invalid type"),
            ("minutes = 45\n", "line 3: invalid type"),
            (
                "minutes = { reading = 20, exercise = 5 }\n",
                "line 3: unknown field `exercise`",
            ),
            (
                "minutes = { exercises = 5 }\n",
                "line 3: missing field `reading`",
            ),
            (
                "minutes = { reading = 0, exercises = 5 }\n",
                "line 3: minutes: reading takes more than 0 minutes",
            ),
            (
                "minutes = { reading = 200, exercises = 50 }\n",
                "line 3: minutes: 250 in all is more than one sitting",
            ),
            ("minutes = { reading = -5, exercises = 5 }\n", "line 3: "),
            ("beyond_lecture = \"yes\"\n", "line 3: invalid type"),
            ("beyond = true\n", "line 3: unknown field `beyond`"),
        ];
        for (field, want) in cases {
            let text = format!("{TOP}{field}");
            let e = parse(Path::new("lessons/13-x/lesson.toml"), &text).unwrap_err();
            assert!(
                e.starts_with("lessons/13-x/lesson.toml: ") && e.contains(want),
                "{field:?}: {e:?} should contain {want:?}"
            );
            assert!(!e.contains('\n'), "{e:?} is more than one line");
        }
    }
}
