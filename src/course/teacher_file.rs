//! Reading the small TOML files a teacher writes (step-through scripts, lesson
//! specs): bounded in size, and every error one line naming the file and line.

use std::path::Path;

use serde::de::DeserializeOwned;

/// Such files are a page or two; anything larger is not one.
const MAX_BYTES: u64 = 1 << 20;

/// Reads the text of `path`, a regular file of at most a megabyte; `what`
/// names the kind of file in the message.
pub fn read(path: &Path, what: &str) -> Result<String, String> {
    let at = path.display();
    let cannot = |e: std::io::Error| format!("cannot read {at}: {}", crate::io::input::reason(&e));
    let meta = std::fs::metadata(path).map_err(cannot)?;
    if !meta.is_file() {
        return Err(format!("{at}: not a regular file"));
    }
    if meta.len() > MAX_BYTES {
        return Err(format!(
            "{at}: {} bytes; {what} is at most {MAX_BYTES}",
            meta.len()
        ));
    }
    std::fs::read_to_string(path).map_err(cannot)
}

/// The 1-based line of byte offset `at` in `text`.
pub fn line_of(text: &str, at: usize) -> usize {
    text.as_bytes()[..at.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Parses TOML text into `T`; a syntax error or a bad field is
/// `PATH: line N: message`.
pub fn parse<T: DeserializeOwned>(path: &Path, text: &str) -> Result<T, String> {
    toml::from_str(text).map_err(|e| {
        let at = path.display();
        let message = e.message().replace('\n', " ");
        match e.span() {
            Some(s) => format!("{at}: line {}: {}", line_of(text, s.start), message.trim()),
            None => format!("{at}: {}", message.trim()),
        }
    })
}
