//! Each lesson's frame (`raytree::course::spec::frame`): what a learner can
//! do after it and how long it takes, in every lesson, honest about the
//! chapter's length, shown under the chapter's heading and by `raytree
//! lesson`; lesson 13 marked as going beyond the lecture.

use raytree::course::learner::vectors;
use raytree::course::lesson;
use raytree::course::spec::frame::{BEYOND_LECTURE, OBJECTIVES};

use super::run::root;

fn lessons() -> Vec<lesson::Entry> {
    lesson::list(&root().join("lessons")).unwrap_or_else(|e| panic!("{e}"))
}

/// Reading a chapter with figures, formulas and trace excerpts goes at 90 to
/// 200 words a minute; a time outside that is a guess, not an estimate.
#[test]
fn every_lesson_has_a_frame_true_to_its_chapter() {
    for e in lessons() {
        let frame = &e.spec.frame;
        let at = &e.name;
        assert!(
            OBJECTIVES.contains(&frame.objectives.len()),
            "{at}: {:?}",
            frame.objectives
        );
        let m = frame.minutes.unwrap_or_else(|| panic!("{at}: no minutes"));
        let chapter = std::fs::read_to_string(root().join(format!("book/src/lessons/{at}.md")))
            .unwrap_or_else(|e| panic!("{at}: {e}"));
        let words = chapter.split_whitespace().count() as f64;
        let reading = f64::from(m.reading);
        assert!(
            (words / 200.0..=words / 90.0).contains(&reading),
            "{at}: {} minutes to read {words} words",
            m.reading
        );
        // A few minutes an exercise, to predict before opening the answer.
        let exercises = e.spec.exercises.len() as u32;
        assert!(
            (3 * exercises..=10 * exercises).contains(&m.exercises),
            "{at}: {} minutes for {exercises} exercises",
            m.exercises
        );
        // Building it yourself takes time only where the lesson has that part.
        assert_eq!(
            m.build > 0,
            vectors::build_it_yourself(e.number).is_some(),
            "{at}: build = {}",
            m.build
        );
        assert_eq!(frame.beyond_lecture, e.number == 13, "{at}: beyond_lecture");
    }
}

#[test]
fn the_frame_opens_the_chapter_and_raytree_lesson() {
    for e in lessons() {
        let chapter =
            std::fs::read_to_string(root().join(format!("book/src/lessons/{}.md", e.name)))
                .unwrap();
        let heading = format!("# Lesson {}: {}\n\n", e.number, e.title());
        let at = chapter
            .find(&heading)
            .unwrap_or_else(|| panic!("{}: no heading", e.name));
        let top = &chapter[at + heading.len()..];
        let m = e.spec.frame.minutes.unwrap();
        let objectives: String = e
            .spec
            .frame
            .objectives
            .iter()
            .map(|o| format!("- {o}\n"))
            .collect();
        let want = format!(
            "**After this lesson you can**\n\n{objectives}\n*{}*\n\n",
            m.sentence()
        );
        let want = if e.spec.frame.beyond_lecture {
            format!("> {}\n\n{want}", BEYOND_LECTURE)
        } else {
            want
        };
        assert!(
            top.starts_with(&want),
            "{}:\n{}",
            e.name,
            &top[..want.len().min(top.len())]
        );
    }

    let (ok, list, _) = super::raytree(&["lesson"]);
    assert!(ok);
    for e in lessons() {
        let line = list
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{} ", e.number)))
            .unwrap();
        let minutes = e.spec.frame.minutes.unwrap().total();
        assert!(line.contains(&format!(" {minutes} min ")), "{line}");
        assert_eq!(
            line.contains("beyond the lecture, optional"),
            e.number == 13,
            "{line}"
        );
    }
    let (ok, text, _) = super::raytree(&["lesson", "3", "--text"]);
    let three = &lessons()[2];
    let header = format!(
        "Lesson 3: {}\nAfter this lesson you can\n  - {}\n",
        three.title(),
        three.spec.frame.objectives[0]
    );
    assert!(ok && text.starts_with(&header), "{text}");
    assert!(
        text.contains(&three.spec.frame.minutes.unwrap().sentence()),
        "{text}"
    );
}

#[test]
fn a_lesson_with_a_bad_or_missing_frame_is_one_line_naming_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("07-light");
    std::fs::create_dir(&folder).unwrap();
    let top = "title = \"Light\"\nsummary = \"the light\"\n";
    let dir_arg = dir.path().display().to_string();
    let cases = [
        (
            format!("{top}objectives = [\"see\"]\nminutes = {{ reading = 10, exercises = 5 }}\n"),
            "07-light/lesson.toml: line 3: objectives: 1 given; a lesson has 2 to 4",
        ),
        (
            format!(
                "{top}objectives = [\"see\", \"shade\"]\nminutes = {{ reading = \"ten\", exercises = 5 }}\n"
            ),
            "07-light/lesson.toml: line 4: invalid type",
        ),
        (
            format!("{top}objectives = [\"see\", \"shade\"]\nminutes = 15\noptional = true\n"),
            "07-light/lesson.toml: line 4: invalid type",
        ),
        (
            format!("{top}objectives = [\"see\", \"shade\"]\nbeyond = true\n"),
            "07-light/lesson.toml: line 4: unknown field `beyond`",
        ),
        (
            format!("{top}minutes = {{ reading = 10, exercises = 5 }}\n"),
            "07-light/lesson.toml: a lesson needs objectives",
        ),
        (
            format!("{top}objectives = [\"see\", \"shade\"]\n"),
            "07-light/lesson.toml: a lesson needs minutes",
        ),
    ];
    for (spec, want) in cases {
        std::fs::write(folder.join("lesson.toml"), &spec).unwrap();
        let (ok, _, err) = super::raytree(&["lesson", "--lessons", &dir_arg]);
        assert!(!ok && err.contains(want), "{spec}\n{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}
