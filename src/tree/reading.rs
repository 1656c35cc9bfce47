//! Reading a trace document back: a file within the input limits, a document
//! of this version, checked to hold together ([`crate::tree::trace_check`])
//! and, where its scene can be found, to fit it. Apart from writing, so the
//! document's shape does not depend on how it is checked.

use std::path::{Path, PathBuf};

use crate::io::headroom;
use crate::io::input::{self, MAX_INPUT_BYTES};
use crate::scene::Scene;
use crate::scene::quote::{printable, quote, shorten_serde};
use crate::scene::source::BUILT_IN;
use crate::scene::strict::in_users_words;
use crate::tree::document::{FORMAT, TraceDocument, VERSION};
use crate::tree::trace_check;

/// Reads a saved trace document (`raytree trace --json -o FILE`): a regular
/// file of at most [`MAX_INPUT_BYTES`], a document this raytree writes, and
/// one that holds together ([`trace_check::structure`]). Errors are one line
/// naming the file.
pub fn read(path: &Path) -> anyhow::Result<TraceDocument> {
    let file = path.display();
    let refused = |reason| anyhow::anyhow!("cannot read {file}: {reason}");
    let text = input::read_text(path, MAX_INPUT_BYTES).map_err(refused)?;
    let need = (text.len() as u64).saturating_mul(headroom::TRACE_PER_BYTE);
    headroom::check(need, headroom::available()).map_err(refused)?;
    parse(&text).map_err(|e| anyhow::anyhow!("{file}:{e}"))
}

/// Parses and checks a trace document's text. The error is one line: a
/// position (`L:C: …`) for a syntax error, else ` field: …`, to follow the
/// file's name.
pub fn parse(text: &str) -> Result<TraceDocument, String> {
    // The format and version first, read leniently: another version's fields
    // differ, and its reader wants to hear which version it has, not which
    // field this version lacks.
    if let Ok(Header { format, version }) = serde_json::from_str::<Header>(text)
        && (format != FORMAT || version != u64::from(VERSION))
    {
        return Err(format!(
            " a {} version {version} document; this raytree reads {FORMAT} version {VERSION}",
            quote(&format, ""),
        ));
    }
    let trace: TraceDocument = serde_json::from_str(text).map_err(|e| {
        format!(
            "{}:{}: not a raytree trace: {}",
            e.line(),
            e.column(),
            printable(&shorten_serde(&in_users_words(without_position(
                &e.to_string()
            ))))
        )
    })?;
    trace_check::structure(&trace).map_err(|e| format!(" {e}"))?;
    Ok(trace)
}

/// Whether `start`, the first bytes of a file, begin a trace document of any
/// version, by its `format` field (which a trace writes first): a trace given
/// where a scene is expected is then named for what it is, not refused for
/// the fields a scene lacks.
pub fn starts_a_trace(start: &str) -> bool {
    let Some(at) = start.find("\"format\"") else {
        return false;
    };
    start[at + "\"format\"".len()..]
        .trim_start()
        .strip_prefix(':')
        .is_some_and(|v| v.trim_start().starts_with(&format!("\"{FORMAT}\"")))
}

/// What every version of the document starts with.
#[derive(serde::Deserialize)]
struct Header {
    format: String,
    version: u64,
}

/// A saved trace with the scene it was made from, when that is at hand.
#[derive(Debug)]
pub struct Opened {
    /// The trace, checked.
    pub trace: TraceDocument,
    /// Its scene with the trace's settings, when found and unchanged (or given).
    pub scene: Option<Scene>,
    /// What a user should know about the scene: not found, changed, or given
    /// in place of the one the trace names.
    pub note: Option<String>,
}

/// Opens a saved trace with its scene: `scene` when given (it must have the
/// objects and lights the trace names), else the file the trace names, looked
/// for beside the trace first, then from the working folder. A scene that
/// changed since the trace was made is left out, with a note: the trace is then
/// shown without the scene's drawing. Errors are one line naming the file.
pub fn open(path: &Path, scene: Option<&Path>) -> anyhow::Result<Opened> {
    let trace = read(path)?;
    let file = path.display();
    let Some(given) = scene else {
        let (scene, note) = find_scene(&trace, path);
        return Ok(Opened { trace, scene, note });
    };
    let (mut scene, source) = crate::scene::source::load(Some(given))?;
    scene.settings = trace.settings;
    trace_check::against_scene(&trace, &scene)
        .map_err(|e| anyhow::anyhow!("{file} does not fit the scene {}: {e}", given.display()))?;
    let note = (source.hash != trace.scene.hash).then(|| {
        format!(
            "{} is not the scene the trace was made from ({}), but has its objects and lights",
            given.display(),
            trace.scene.file
        )
    });
    Ok(Opened {
        trace,
        scene: Some(scene),
        note,
    })
}

/// The scene `trace` (read from `path`) names, if it is found and unchanged,
/// and a note when it is not.
fn find_scene(trace: &TraceDocument, path: &Path) -> (Option<Scene>, Option<String>) {
    let named = &trace.scene.file;
    let file = if named == BUILT_IN {
        None
    } else {
        let beside = path.parent().unwrap_or(Path::new("")).join(named);
        let places = [beside, PathBuf::from(named)];
        // A regular file first; else something there that is no file (a
        // device, a folder), which loading then names for what it is.
        match places
            .iter()
            .find(|p| p.is_file())
            .or_else(|| places.iter().find(|p| p.exists()))
            .cloned()
        {
            Some(found) => Some(found),
            None => {
                return (
                    None,
                    Some(format!(
                        "scene {named} not found: showing the saved trace only"
                    )),
                );
            }
        }
    };
    let shown = file
        .as_deref()
        .map_or(named.clone(), |p| p.display().to_string());
    let (mut scene, now) = match crate::scene::source::load(file.as_deref()) {
        Ok(found) => found,
        Err(e) => return (None, Some(format!("{e}: showing the saved trace only"))),
    };
    scene.settings = trace.settings;
    if now.hash != trace.scene.hash {
        let note = format!(
            "{shown} changed since the trace was saved: showing the saved trace only (give the scene after the trace to use it anyway)"
        );
        return (None, Some(note));
    }
    match trace_check::against_scene(trace, &scene) {
        Ok(()) => (Some(scene), None),
        Err(e) => (
            None,
            Some(format!(
                "{shown} does not fit the trace ({e}): showing the saved trace only"
            )),
        ),
    }
}

/// A document of `size` bytes, refused when beyond `limit`, what the reader reads.
fn readable_size(size: u64, limit: u64) -> Result<(), String> {
    if size > limit {
        return Err(format!(
            "the trace would be {}, more than the {} raytree reads back; lower spp or max_depth, or raise the cutoff",
            input::bytes_in_words(size),
            input::bytes_in_words(limit)
        ));
    }
    Ok(())
}

/// serde_json's message without its " at line L column C".
fn without_position(message: &str) -> &str {
    message
        .rfind(" at line ")
        .map_or(message, |i| &message[..i])
}

impl TraceDocument {
    /// [`Self::to_json`], read back and compared: JSON cannot hold an infinity
    /// or a NaN (serde_json writes `null`), so a trace that would not read back
    /// exactly is refused rather than written. The scene limits keep every
    /// number finite; this is the guarantee that the format never holds `null`
    /// for a number. A document larger than the reader reads (its rays are
    /// bounded before tracing, but not how many objects each one tests) is
    /// refused too.
    pub fn to_checked_json(&self) -> Result<String, String> {
        let text = self.to_json();
        readable_size(text.len() as u64, MAX_INPUT_BYTES)?;
        match parse(&text) {
            Ok(back) if back == *self => Ok(text),
            Ok(_) => Err("the trace holds a number JSON cannot write (infinite or NaN)".to_owned()),
            Err(e) => Err(format!("the trace would not read back:{e}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trace_larger_than_the_reader_reads_is_not_written() {
        assert_eq!(readable_size(MAX_INPUT_BYTES, MAX_INPUT_BYTES), Ok(()));
        assert_eq!(
            readable_size(1_160_000_000, MAX_INPUT_BYTES).unwrap_err(),
            "the trace would be 1.2 GB, more than the 1 GiB raytree reads back; lower spp or max_depth, or raise the cutoff"
        );
    }
}
