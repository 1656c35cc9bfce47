//! A spec's number read from a trace (`step` + `value`, or `json`): one
//! reading for the book, which quotes it, and for `raytree lesson N`, which
//! refuses a number the book could not make before a teacher builds it.

use serde_json::Value;

use crate::course::guide;
use crate::course::lesson_spec::Source;
use crate::tree::document::TraceDocument;
use crate::views::numbers::{num, vec3};

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
