//! A script told against a trace: each stop's placeholders filled with the
//! numbers of its step ([`crate::course::guide::values`]), so the narrative
//! can never disagree with the code; a stop may quote only what the
//! algorithm knows by its step. The inspector plays it (`raytree inspect
//! --script FILE`, `raytree lesson N`) and the book prints it.

use std::collections::BTreeMap;

use crate::course::guide::script::Script;
use crate::course::guide::step_values::values;
use crate::tree::document::TraceDocument;

/// One stop made concrete against a trace: the step's index into
/// [`TraceDocument::steps`] and the sentence with its numbers filled in.
#[derive(Clone, Debug, PartialEq)]
pub struct Narration {
    /// 0-based index of the step.
    pub step: usize,
    /// The sentence.
    pub text: String,
}

/// Fills every stop's placeholders from `trace` (traced at the script's pixel).
/// A stop past the last step (named before any order), stops that do not go
/// forward, or a placeholder the step has no number for, is an error naming
/// the stop and what the step does have.
pub fn narrate(script: &Script, trace: &TraceDocument) -> Result<Vec<Narration>, String> {
    let at = script.path.display();
    if script.sample >= trace.samples.len() {
        return Err(format!(
            "{at}: sample {} but the pixel has {} sample(s)",
            script.sample + 1,
            trace.samples.len()
        ));
    }
    // Each step's range first: a step past the end, written before the
    // others, is the problem, not their order.
    let steps = trace.steps(script.sample).len();
    if let Some(i) = script.stops.iter().position(|s| s.step > steps) {
        return Err(format!(
            "{at}: stop {}: step {} is past the pixel's {steps} steps",
            i + 1,
            script.stops[i].step
        ));
    }
    for (i, pair) in script.stops.windows(2).enumerate() {
        if pair[1].step <= pair[0].step {
            return Err(format!(
                "{at}: stop {}: step {} does not come after step {}; stops go forward",
                i + 2,
                pair[1].step,
                pair[0].step
            ));
        }
    }
    (0..script.stops.len())
        .map(|i| {
            let stop = &script.stops[i];
            tell(script, trace, i).map_err(|untold| match untold {
                Untold::PastEnd { steps } => format!(
                    "{at}: stop {}: step {} is past the pixel's {steps} steps",
                    i + 1,
                    stop.step
                ),
                Untold::NoNumber { name, have } => format!(
                    "{at}: stop {} (step {}): no number {{{name}}} here; this step has {}",
                    i + 1,
                    stop.step,
                    have.join(", ")
                ),
            })
        })
        .collect()
}

/// Why a stop cannot be told against a trace: after a what-if in the
/// inspector, the trace may no longer be the one the teacher wrote it for.
#[derive(Clone, Debug, PartialEq)]
pub enum Untold {
    /// The stop's step is past the last of the pixel's `steps`.
    PastEnd {
        /// How many steps the pixel has.
        steps: usize,
    },
    /// The step has no number called `name`; it has `have`.
    NoNumber {
        /// The placeholder the sentence quotes.
        name: String,
        /// The names the step does have.
        have: Vec<String>,
    },
}

/// Stop `i` of `script` told against `trace`, on its own, so one stop that
/// no longer fits a changed trace leaves the others told.
pub fn tell(script: &Script, trace: &TraceDocument, i: usize) -> Result<Narration, Untold> {
    let stop = &script.stops[i];
    let steps = if script.sample < trace.samples.len() {
        trace.steps(script.sample).len()
    } else {
        0
    };
    if stop.step > steps {
        return Err(Untold::PastEnd { steps });
    }
    let names = values(trace, script.sample, stop.step - 1);
    let text = fill(&stop.say, &names).map_err(|name| Untold::NoNumber {
        name,
        have: names.keys().cloned().collect(),
    })?;
    Ok(Narration {
        step: stop.step - 1,
        text,
    })
}

/// Replaces `{name}` with its value (`{{` and `}}` stand for braces); the
/// error is the first unknown name.
fn fill(say: &str, names: &BTreeMap<String, String>) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = say;
    while let Some(i) = rest.find(['{', '}']) {
        out.push_str(&rest[..i]);
        let tail = &rest[i..];
        if tail.starts_with("{{") || tail.starts_with("}}") {
            out.push_str(&tail[..1]);
            rest = &tail[2..];
            continue;
        }
        if tail.starts_with('}') {
            return Err("}".to_owned());
        }
        let end = tail.find('}').ok_or_else(|| tail.to_owned())?;
        let name = &tail[1..end];
        out.push_str(names.get(name).ok_or_else(|| name.to_owned())?);
        rest = &tail[end + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placeholders_fill_and_unknown_ones_are_named() {
        let names: BTreeMap<String, String> = [("t".to_owned(), "2.5".to_owned())].into();
        assert_eq!(fill("t = {t}, {{t}}", &names).unwrap(), "t = 2.5, {t}");
        assert_eq!(fill("{theta}", &names).unwrap_err(), "theta");
        assert_eq!(fill("open {t", &names).unwrap_err(), "{t");
    }
}
