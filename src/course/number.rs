//! A spec's number (`[number]` in `lesson.toml`): where it is read from, a
//! name at a step or a field of a trace, or a word of another run's output,
//! checked as the spec is read; and its value read from a trace, one reading
//! for the book, which quotes it, and for `raytree lesson N`, which refuses a
//! number the book could not make before a teacher builds it.

use serde_json::Value;

use crate::course::guide;
use crate::course::spec::file::NumberFile;
use crate::tree::document::TraceDocument;
use crate::views::numbers::{num, vec3};

/// Where a number comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    /// A name the step-through scripts use (`course::guide::values`) at a step of a trace.
    Step {
        /// The step, 1-based.
        step: usize,
        /// The name, e.g. `u_c`, `discriminant`, `theta1`.
        value: String,
    },
    /// A field of the trace document, by JSON pointer (`/camera/eye`).
    Json(String),
    /// The word after this text in a run's output.
    After(String),
    /// The word before this text in a run's output (`17  reached a pixel`).
    Before(String),
}

impl Source {
    /// The source a `[number]` entry names, from a run that is a trace or
    /// not (`trace`); the error says what such a run's number is.
    pub(crate) fn from_file(n: &NumberFile, trace: bool) -> Result<Self, String> {
        match (&n.step, &n.value, &n.json, &n.after, &n.before) {
            (Some(0), ..) => Err("steps count from 1".to_owned()),
            (Some(step), Some(value), None, None, None) if trace => Ok(Self::Step {
                step: *step,
                value: value.clone(),
            }),
            (None, None, Some(json), None, None) if trace => {
                if json.starts_with('/') {
                    Ok(Self::Json(json.clone()))
                } else {
                    Err(format!(
                        "json = '{json}' is not a JSON pointer (it starts with /)"
                    ))
                }
            }
            (None, None, None, Some(after), None) if !trace => Ok(Self::After(after.clone())),
            (None, None, None, None, Some(before)) if !trace => Ok(Self::Before(before.clone())),
            _ if trace => Err("a trace's number is step + value, or json".to_owned()),
            _ => Err(
                "a number from a run other than a trace is after = \"text before it\" or before = \"text after it\""
                    .to_owned(),
            ),
        }
    }
}

/// The value of `source` in `doc`, written as the trace writes numbers; the
/// error says what the trace has instead.
pub fn from_trace(source: &Source, doc: &TraceDocument) -> Result<String, String> {
    match source {
        Source::Step { step, value } => step_value(doc, *step, value),
        Source::Json(pointer) => json_value(doc, pointer),
        Source::After(_) | Source::Before(_) => {
            Err("after = and before = read a run's text, not a trace".to_owned())
        }
    }
}

fn step_value(doc: &TraceDocument, step: usize, value: &str) -> Result<String, String> {
    let count = doc.steps(0).len();
    if step > count {
        return Err(format!("step {step} is past the trace's {count} steps"));
    }
    let names = guide::values(doc, 0, step - 1);
    names.get(value).cloned().ok_or_else(|| {
        let have: Vec<&str> = names.keys().map(String::as_str).collect();
        format!("step {step} has no {value}; it has {}", have.join(", "))
    })
}

fn json_value(doc: &TraceDocument, pointer: &str) -> Result<String, String> {
    let value = serde_json::to_value(doc).map_err(|e| e.to_string())?;
    let found = value
        .pointer(pointer)
        .ok_or_else(|| format!("the trace has no {pointer}"))?;
    json_number(found)
        .ok_or_else(|| format!("{pointer} is {found}: not a number, a vector or a word"))
}

fn json_number(v: &Value) -> Option<String> {
    match v {
        Value::Number(n) if n.is_u64() || n.is_i64() => Some(n.to_string()),
        Value::Number(n) => n.as_f64().map(num),
        Value::String(s) => Some(s.clone()),
        Value::Bool(b) => Some(b.to_string()),
        Value::Array(a) if a.len() == 3 => {
            let xyz: Option<Vec<f64>> = a.iter().map(Value::as_f64).collect();
            xyz.map(|v| vec3(glam::DVec3::new(v[0], v[1], v[2])))
        }
        _ => None,
    }
}
