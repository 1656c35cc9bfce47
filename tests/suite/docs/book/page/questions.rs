//! A chapter's checked questions, written where its exercises go: each a
//! box `book/player/questions.js` turns into an answer field, checked
//! against the value raytree printed in this build; without JavaScript (and
//! on GitHub) the hint and the worked answer are folds, as the exercises are.

use std::fmt::Write;

use raytree::course::spec::question::{self, Question};

use super::{HOLE, Page};

impl Page<'_> {
    /// The questions as HTML boxes around Markdown.
    pub(super) fn questions(&mut self) -> Result<String, String> {
        let spec = self.src.spec;
        let mut out = String::new();
        if spec.questions.is_empty() {
            return Ok(out);
        }
        out.push_str(
            "Predict each number, type it in the box and press Check: the page holds raytree's own \
             value from this book's build and says how close an answer must be. A wrong answer \
             brings a hint; a right one, the worked answer.\n\n",
        );
        for (k, q) in spec.questions.iter().enumerate() {
            let at = format!("{} (question at line {})", self.src.spec_path, q.line);
            let printed = self.numbers[&q.answer].clone();
            self.used.insert(format!("number {}", q.answer));
            typed_by_hand(q, &printed).map_err(|e| format!("{at}: {e}"))?;
            let ask = self.fill(&q.ask, &at, false)?;
            let hint = self.fill(&q.hint, &at, false)?;
            let worked = self.fill(&q.worked, &at, false)?;
            let (value, unit, within) = if printed == HOLE {
                (HOLE.to_owned(), String::new(), HOLE.to_owned())
            } else {
                let (value, unit) = question::answer_value(&printed, q.pick)
                    .map_err(|e| format!("{at}: answer {}: {e}", q.answer))?;
                let within = question::tolerance(q, value);
                (value.to_string(), unit, format!("{within:.3e}"))
            };
            let _ = write!(
                out,
                "<div class=\"raytree-question\" data-answer=\"{value}\" data-within=\"{within}\" data-unit=\"{unit}\">\n\n\
                 **Question {}.** {ask}\n\n\
                 <p class=\"raytree-tolerance\">Checked {}.</p>\n\n\
                 <details class=\"raytree-hint\">\n<summary>Hint</summary>\n\n{hint}\n\n</details>\n\n\
                 <details class=\"raytree-worked\">\n<summary>Answer (computed by raytree)</summary>\n\n{worked}\n\n</details>\n\n\
                 </div>\n\n",
                k + 1,
                question::tolerance_reason(q),
            );
        }
        Ok(out)
    }
}

/// A question asks for a prediction, so the chapter must not have printed
/// its answer before it (in the text, a figure's caption, an excerpt or
/// another question's worked answer): the first place the answer's value
/// appears in `body` must be the question's own box. Values of one or two
/// characters (4, −3) are too common to tell.
pub(super) fn not_shown_before(
    body: &str,
    spec: &raytree::course::spec::Spec,
    numbers: &std::collections::BTreeMap<String, String>,
) -> Result<(), String> {
    let boxes: Vec<usize> = body
        .match_indices("<div class=\"raytree-question\"")
        .map(|(at, _)| at)
        .collect();
    for (q, &at) in spec.questions.iter().zip(&boxes) {
        let Ok((value, _)) = question::answer_value(&numbers[&q.answer], q.pick) else {
            continue;
        };
        let shown = raytree::views::numbers::num(value);
        if shown.trim_start_matches('-').len() < 3 {
            continue;
        }
        if let Some(first) = token(body, &shown).filter(|&first| first < at) {
            let line = body[..first].lines().count();
            return Err(format!(
                "line {}: question: its answer {shown} is printed above it (chapter line {line}): ask for a number the chapter has not shown",
                q.line
            ));
        }
    }
    Ok(())
}

/// The first place `value` appears in `text` as a whole number, not part of
/// a longer one.
fn token(text: &str, value: &str) -> Option<usize> {
    let digit = |c: Option<char>| c.is_some_and(|c| c.is_ascii_digit() || c == '.');
    text.match_indices(value).map(|(i, _)| i).find(|&i| {
        !digit(text[..i].chars().next_back()) && !digit(text[i + value.len()..].chars().next())
    })
}

/// A question's texts quote its answer as `{{name}}`, never as the value
/// typed: a typed value would go stale when the code changes.
fn typed_by_hand(q: &Question, printed: &str) -> Result<(), String> {
    let Ok((value, _)) = question::answer_value(printed, q.pick) else {
        return Ok(());
    };
    let shown = raytree::views::numbers::num(value);
    // Short values (2, 0.5) are too common in prose to mean the answer.
    if shown.len() < 4 {
        return Ok(());
    }
    for (field, text) in [("ask", &q.ask), ("hint", &q.hint), ("worked", &q.worked)] {
        if token(text, &shown).is_some() {
            return Err(format!(
                "{field} types the answer {shown} by hand; quote it as {{{{{}}}}}",
                q.answer
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn question(worked: &str) -> Question {
        Question {
            ask: "At what t?".to_owned(),
            answer: "glass_t".to_owned(),
            pick: None,
            hint: "The smaller root.".to_owned(),
            worked: worked.to_owned(),
            within: None,
            line: 3,
        }
    }

    #[test]
    fn a_question_that_types_its_answer_is_refused() {
        assert_eq!(
            typed_by_hand(&question("t = {{glass_t}}."), "5.014"),
            Ok(())
        );
        let typed = typed_by_hand(&question("t = 5.014, the first root."), "5.014");
        assert_eq!(
            typed,
            Err("worked types the answer 5.014 by hand; quote it as {{glass_t}}".to_owned())
        );
        // Part of a longer number is not the answer.
        assert_eq!(typed_by_hand(&question("t = 15.0145."), "5.014"), Ok(()));
    }
}
