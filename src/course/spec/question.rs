//! Checked questions: "predict the number" asked in a chapter, answered in a
//! box in the page and checked against raytree's own value. The answer is
//! never written in the spec: it names one of the spec's `[number]`s, so the
//! book fills it in from a fresh run, and a test fails when a question's
//! texts type that value by hand instead of quoting it.
//!
//! ```toml
//! [[question]]
//! ask = "At what t does the primary ray meet the glass ball?"
//! answer = "glass_t"             # a [number]; `pick = 2` takes its second value
//! hint = "Solve the sphere's quadratic; the smaller positive root wins."
//! worked = "t = {{glass_t}}: the smaller of the two roots {{glass_roots}}."
//! within = 0.01                  # optional: absolute tolerance …
//! why = "the roots are printed to four digits"   # … and why (required with it)
//! ```

use std::collections::BTreeMap;

use serde::Deserialize;

/// One question as the spec file has it.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct QuestionFile {
    ask: String,
    answer: String,
    pick: Option<usize>,
    hint: String,
    worked: String,
    within: Option<f64>,
    why: Option<String>,
}

/// A question, read and checked against the spec's numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct Question {
    /// What to predict (Markdown, may quote `{{numbers}}`).
    pub ask: String,
    /// The `[number]` whose value is the answer.
    pub answer: String,
    /// Which value of it, 1-based, when it has several (a point, two roots).
    pub pick: Option<usize>,
    /// Said after a wrong answer (Markdown).
    pub hint: String,
    /// The worked answer, said after a right one (Markdown quoting numbers).
    pub worked: String,
    /// How far off an answer may be, absolute, and why; `None`: the default
    /// [`DEFAULT_RELATIVE`].
    pub within: Option<(f64, String)>,
    /// Line of the spec file.
    pub line: usize,
}

/// The default tolerance, relative to the answer: a calculation by hand
/// carried to three significant digits lands within 1 % of raytree's value,
/// while the classic mistakes (a sign, the wrong root, a missing factor)
/// land far outside it.
pub const DEFAULT_RELATIVE: f64 = 0.01;

/// Reads the questions, each answer naming one of `numbers`.
pub(crate) fn read<N>(
    files: &[toml::Spanned<QuestionFile>],
    numbers: &BTreeMap<String, N>,
    line: impl Fn(std::ops::Range<usize>) -> usize,
) -> Result<Vec<Question>, (usize, String)> {
    files
        .iter()
        .map(|q| {
            let l = line(q.span());
            let q = q.get_ref();
            let fail = |what: String| (l, format!("question: {what}"));
            if !numbers.contains_key(&q.answer) {
                return Err(fail(format!(
                    "answer '{}' is no [number]: an answer is a number raytree computes, never one typed",
                    q.answer
                )));
            }
            if q.pick == Some(0) {
                return Err(fail("pick counts from 1".to_owned()));
            }
            let within = match (q.within, &q.why) {
                (Some(w), Some(why)) if w.is_finite() && w > 0.0 && !why.trim().is_empty() => {
                    Some((w, why.trim().to_owned()))
                }
                (Some(w), Some(_)) if !(w.is_finite() && w > 0.0) => {
                    return Err(fail(format!("within {w} is not a positive tolerance")));
                }
                (Some(_), _) => {
                    return Err(fail("within needs its why: say why that tolerance".to_owned()));
                }
                (None, Some(_)) => return Err(fail("why without within".to_owned())),
                (None, None) => None,
            };
            for (field, text) in [("ask", &q.ask), ("hint", &q.hint), ("worked", &q.worked)] {
                if text.trim().is_empty() {
                    return Err(fail(format!("{field} is empty")));
                }
            }
            Ok(Question {
                ask: q.ask.trim().to_owned(),
                answer: q.answer.clone(),
                pick: q.pick,
                hint: q.hint.trim().to_owned(),
                worked: q.worked.trim().to_owned(),
                within,
                line: l,
            })
        })
        .collect()
}

/// The answer as a number, and what follows it as printed (a unit such as
/// `°`), from a number's printed value (`5.014`, `24.31°`, `(0.7, 1.4, 2)`,
/// `5.014, 6.637`), taking value `pick` (1-based) of several.
pub fn answer_value(printed: &str, pick: Option<usize>) -> Result<(f64, String), String> {
    let values: Vec<&str> = printed
        .trim()
        .trim_start_matches('(')
        .trim_end_matches(')')
        .split(", ")
        .map(str::trim)
        .collect();
    let one = match (pick, values.len()) {
        (None, 1) => values[0],
        (None, n) => {
            return Err(format!(
                "'{printed}' has {n} values: say which with pick = 1 … {n}"
            ));
        }
        (Some(k), n) if k <= n => values[k - 1],
        (Some(k), n) => return Err(format!("pick {k} but '{printed}' has {n} value(s)")),
    };
    // Counts are printed with thousands separators (1,347,578).
    let one = &one.replace(',', "");
    let end = one
        .char_indices()
        .find(|&(i, c)| {
            !(c.is_ascii_digit()
                || c == '.'
                || c == 'e'
                || ((c == '-' || c == '+') && (i == 0 || one[..i].ends_with('e'))))
        })
        .map_or(one.len(), |(i, _)| i);
    let value: f64 = one[..end]
        .parse()
        .map_err(|_| format!("'{one}' (of '{printed}') is not a number"))?;
    Ok((value, one[end..].trim().to_owned()))
}

/// How far off an answer to `value` may be.
pub fn tolerance(q: &Question, value: f64) -> f64 {
    match &q.within {
        Some((w, _)) => *w,
        // A zero answer gets the tolerance of an answer of 1.
        None if value == 0.0 => DEFAULT_RELATIVE,
        None => DEFAULT_RELATIVE * value.abs(),
    }
}

/// Why that tolerance, in words a learner reads under the box.
pub fn tolerance_reason(q: &Question) -> String {
    match &q.within {
        Some((w, why)) => format!("within {w}: {why}"),
        None => format!(
            "within {} %: a calculation by hand to three significant digits lands there",
            DEFAULT_RELATIVE * 100.0
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::course::spec::Spec;

    fn spec(questions: &str) -> Result<Spec, String> {
        let text = format!(
            "[run.p]\ncommand = \"raytree trace scenes/whitted.json --pixel 1,1\"\n[number]\nt = {{ run = \"p\", step = 7, value = \"t\" }}\n{questions}"
        );
        crate::course::spec::parse(std::path::Path::new("l.toml"), &text)
    }

    #[test]
    fn an_answer_names_a_number_and_a_tolerance_says_why() {
        let ok =
            spec("[[question]]\nask = \"a\"\nanswer = \"t\"\nhint = \"h\"\nworked = \"{{t}}\"\n")
                .unwrap();
        assert_eq!(ok.questions[0].answer, "t");
        assert_eq!(ok.questions[0].line, 5);
        let typed =
            spec("[[question]]\nask = \"a\"\nanswer = \"5.014\"\nhint = \"h\"\nworked = \"w\"\n");
        assert_eq!(
            typed.unwrap_err(),
            "l.toml: line 5: question: answer '5.014' is no [number]: an answer is a number raytree computes, never one typed"
        );
        let why = spec(
            "[[question]]\nask = \"a\"\nanswer = \"t\"\nhint = \"h\"\nworked = \"w\"\nwithin = 0.1\n",
        );
        assert!(why.unwrap_err().contains("within needs its why"));
        let zero = spec(
            "[[question]]\nask = \"a\"\nanswer = \"t\"\nhint = \"h\"\nworked = \"w\"\npick = 0\n",
        );
        assert!(zero.unwrap_err().contains("pick counts from 1"));
    }

    #[test]
    fn printed_values_give_their_number_and_unit() {
        assert_eq!(answer_value("5.014", None), Ok((5.014, String::new())));
        assert_eq!(answer_value("24.31°", None), Ok((24.31, "°".to_owned())));
        assert_eq!(answer_value("-1.6e-3", None), Ok((-1.6e-3, String::new())));
        assert_eq!(
            answer_value("(0.7061, 1.394, 1.986)", Some(2)),
            Ok((1.394, String::new()))
        );
        assert_eq!(
            answer_value("5.014, 6.637", Some(2)),
            Ok((6.637, String::new()))
        );
        assert!(
            answer_value("5.014, 6.637", None)
                .unwrap_err()
                .contains("pick = 1 … 2")
        );
        assert!(answer_value("5.014", Some(2)).is_err());
        assert!(answer_value("glass", None).is_err());
        assert_eq!(
            answer_value("1,347,578", None),
            Ok((1_347_578.0, String::new()))
        );
        assert_eq!(answer_value("0.0189%", None), Ok((0.0189, "%".to_owned())));
    }
}
