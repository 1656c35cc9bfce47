//! Input files read safely: only regular files (a device such as `/dev/zero`,
//! a pipe or a socket could be endless or block), and only up to a size limit
//! checked before anything is read, so a wrong path fails at once with one
//! line instead of filling the memory. A text file must be text: a binary
//! one (a NUL byte) is refused from its first bytes, and a byte-order mark is
//! named for what it is, not left for a parser to stumble on.

use std::io::Read;
use std::path::Path;

use crate::io::headroom;
pub use crate::io::sizes::bytes_in_words;

/// The largest scene, OBJ or trace file raytree reads: 1 GiB, far above any
/// real scene (the 2,000-sphere scene is 0.2 MB, a million generated spheres
/// about 90 MB) and below what would exhaust a small machine's memory.
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

/// How much of a text file is looked at before the rest is read: a binary
/// file (an image, an archive, a file of zeros) shows a NUL byte, or bytes
/// that are not UTF-8, within its first few, and is refused before the whole
/// of it fills the memory.
const SNIFF_BYTES: u64 = 64 << 10;

/// Reads the file at `path` whole, if it is a regular file of at most `limit`
/// bytes. The error is the reason alone (`no such file`, `not a regular file
/// …`, `it is … bytes, more than …`); the caller names the file.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>, String> {
    let (mut file, len) = open(path, limit)?;
    headroom::check(len, headroom::available())?;
    read_rest(&mut file, Vec::with_capacity(len as usize), limit)
}

/// As [`read_bytes`], for a UTF-8 text file; one that is not text
/// ([`NotText`]) is refused, a binary one from its first bytes.
pub fn read_text(path: &Path, limit: u64) -> Result<String, String> {
    let (mut file, len) = open(path, limit)?;
    let mut bytes = Vec::with_capacity(len.min(SNIFF_BYTES) as usize);
    (&mut file)
        .take(SNIFF_BYTES)
        .read_to_end(&mut bytes)
        .map_err(|e| reason(&e))?;
    if let Some(not) = check_text(&bytes, true) {
        return Err(not.to_string());
    }
    // Text, as far as it shows: then whether it fits at all.
    headroom::check(len, headroom::available())?;
    bytes.reserve((len as usize).saturating_sub(bytes.len()));
    let bytes = read_rest(&mut file, bytes, limit)?;
    match check_text(&bytes, false) {
        Some(not) => Err(not.to_string()),
        None => String::from_utf8(bytes).map_err(|_| "not UTF-8 text".to_owned()),
    }
}

/// The regular file at `path`, if it is one of at most `limit` bytes, and its
/// size.
fn open(path: &Path, limit: u64) -> Result<(std::fs::File, u64), String> {
    let meta = std::fs::metadata(path).map_err(|e| reason(&e))?;
    if meta.is_dir() {
        return Err("it is a directory".to_owned());
    }
    if !meta.is_file() {
        return Err(
            "not a regular file (a device, pipe or socket cannot be read as one)".to_owned(),
        );
    }
    if meta.len() > limit {
        return Err(too_big(meta.len(), limit));
    }
    let file = std::fs::File::open(path).map_err(|e| reason(&e))?;
    Ok((file, meta.len()))
}

/// `bytes`, read so far, with the rest of `file`: never more than `limit`
/// in all, as the file may have grown since its size was checked.
fn read_rest(file: &mut std::fs::File, mut bytes: Vec<u8>, limit: u64) -> Result<Vec<u8>, String> {
    let left = (limit + 1).saturating_sub(bytes.len() as u64);
    file.take(left)
        .read_to_end(&mut bytes)
        .map_err(|e| reason(&e))?;
    if bytes.len() as u64 > limit {
        return Err(too_big(bytes.len() as u64, limit));
    }
    Ok(bytes)
}

/// Why bytes are no text file raytree reads. Each displays as the reason
/// alone, its line in words (`not UTF-8 text (line 3)`); the caller names
/// the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NotText {
    /// A UTF-8 byte-order mark first, which some Windows editors write: no
    /// format raytree reads allows one, and a reader would take it for part
    /// of the first word (a `v` that is not `v`, a JSON value that is none).
    ByteOrderMark,
    /// A NUL byte, on this 1-based line: a binary file, or a damaged one.
    Nul(usize),
    /// Bytes that are not UTF-8, from this 1-based line.
    NotUtf8(usize),
}

impl std::fmt::Display for NotText {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            NotText::ByteOrderMark => {
                f.write_str("starts with a byte-order mark (U+FEFF); save it as UTF-8 without one")
            }
            NotText::Nul(line) => write!(f, "a binary file, not text: a NUL byte (line {line})"),
            NotText::NotUtf8(line) => write!(f, "not UTF-8 text (line {line})"),
        }
    }
}

/// Why `bytes` is no text raytree reads, if it is not: a byte-order mark
/// first, a NUL byte, or bytes that are not UTF-8 (the first of these).
pub fn not_text(bytes: &[u8]) -> Option<NotText> {
    check_text(bytes, false)
}

/// [`not_text`]; with `start`, `bytes` is the start of a file, which may end
/// inside a character.
fn check_text(bytes: &[u8], start: bool) -> Option<NotText> {
    if bytes.starts_with("\u{feff}".as_bytes()) {
        return Some(NotText::ByteOrderMark);
    }
    let line = |at: usize| bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
    // `contains` is a fast search; where, only when there is one.
    let nul = match bytes.contains(&0) {
        true => bytes.iter().position(|&b| b == 0),
        false => None,
    };
    let bad = match std::str::from_utf8(bytes) {
        Err(e) if !(start && e.error_len().is_none()) => Some(e.valid_up_to()),
        _ => None,
    };
    match (nul, bad) {
        (Some(n), Some(b)) if b < n => Some(NotText::NotUtf8(line(b))),
        (Some(n), _) => Some(NotText::Nul(line(n))),
        (None, Some(b)) => Some(NotText::NotUtf8(line(b))),
        (None, None) => None,
    }
}

fn too_big(size: u64, limit: u64) -> String {
    format!(
        "it is {}, more than the {} raytree reads",
        bytes_in_words(size),
        bytes_in_words(limit)
    )
}

/// The OS's reason in words, without Rust's "(os error N)".
pub fn reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".to_owned(),
        std::io::ErrorKind::IsADirectory => "it is a directory".to_owned(),
        std::io::ErrorKind::PermissionDenied => "permission denied".to_owned(),
        _ => {
            let s = e.to_string();
            s.find(" (os error")
                .map_or(s.clone(), |i| s[..i].to_owned())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_within_the_limit() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.txt");
        std::fs::write(&file, "héllo\n").unwrap();
        assert_eq!(read_text(&file, 100).unwrap(), "héllo\n");
        assert_eq!(
            read_bytes(&file, 3).unwrap_err(),
            "it is 7 bytes, more than the 3 bytes raytree reads"
        );
        assert_eq!(
            read_bytes(dir.path(), 100).unwrap_err(),
            "it is a directory"
        );
        assert_eq!(
            read_bytes(&dir.path().join("none"), 100).unwrap_err(),
            "no such file"
        );
        #[cfg(unix)]
        assert!(
            read_bytes(Path::new("/dev/zero"), MAX_INPUT_BYTES)
                .unwrap_err()
                .starts_with("not a regular file")
        );
        std::fs::write(&file, b"ok\nok\n\xff\n").unwrap();
        assert_eq!(
            read_text(&file, 100).unwrap_err(),
            "not UTF-8 text (line 3)"
        );
    }

    #[test]
    fn text_is_text() {
        assert_eq!(not_text("v 0 0 0\né\n".as_bytes()), None);
        assert_eq!(
            not_text("\u{feff}{}".as_bytes()),
            Some(NotText::ByteOrderMark)
        );
        // The first of a NUL and bytes that are not UTF-8 is named.
        assert_eq!(not_text(b"a\nb\0\n\xff"), Some(NotText::Nul(2)));
        assert_eq!(not_text(b"a\n\xff\n\0"), Some(NotText::NotUtf8(2)));
        // The start of a file may end inside a character; the whole may not.
        let cut = &"é".as_bytes()[..1];
        assert_eq!(check_text(cut, true), None);
        assert_eq!(not_text(cut), Some(NotText::NotUtf8(1)));
        assert_eq!(
            NotText::Nul(4).to_string(),
            "a binary file, not text: a NUL byte (line 4)"
        );
        // A NUL past the first bytes is found when the whole is read.
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("late.json");
        let mut late = "{}\n".repeat(SNIFF_BYTES as usize);
        late.push('\0');
        std::fs::write(&file, &late).unwrap();
        let line = SNIFF_BYTES + 1;
        assert_eq!(
            read_text(&file, MAX_INPUT_BYTES).unwrap_err(),
            format!("a binary file, not text: a NUL byte (line {line})")
        );
    }
}
