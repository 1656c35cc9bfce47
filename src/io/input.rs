//! Input files read safely: only regular files (a device such as `/dev/zero`,
//! a pipe or a socket could be endless or block), and only up to a size limit
//! checked before anything is read, so a wrong path fails at once with one
//! line instead of filling the memory.

use std::io::Read;
use std::path::Path;

/// The largest scene, OBJ or trace file raytree reads: 1 GiB, far above any
/// real scene (the 2,000-sphere scene is 0.2 MB, a million generated spheres
/// about 90 MB) and below what would exhaust a small machine's memory.
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

/// Reads the file at `path` whole, if it is a regular file of at most `limit`
/// bytes. The error is the reason alone (`no such file`, `not a regular file
/// …`, `it is … bytes, more than …`); the caller names the file.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>, String> {
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
    // The file may grow after the check: never read more than the limit.
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| reason(&e))?;
    if bytes.len() as u64 > limit {
        return Err(too_big(bytes.len() as u64, limit));
    }
    Ok(bytes)
}

/// As [`read_bytes`], for a UTF-8 text file.
pub fn read_text(path: &Path, limit: u64) -> Result<String, String> {
    String::from_utf8(read_bytes(path, limit)?).map_err(|e| {
        let line = e.as_bytes()[..e.utf8_error().valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1;
        format!("not UTF-8 text (line {line})")
    })
}

fn too_big(size: u64, limit: u64) -> String {
    format!(
        "it is {}, more than the {} raytree reads",
        bytes_in_words(size),
        bytes_in_words(limit)
    )
}

/// A size as people say it: `512 bytes`, `3.4 MB`, `1.1 GB` (powers of 1000),
/// or `1 GiB` for an exact power of 1024.
pub fn bytes_in_words(n: u64) -> String {
    const GIB: u64 = 1 << 30;
    if n >= GIB && n.is_multiple_of(GIB) {
        return format!("{} GiB", n / GIB);
    }
    let x = n as f64;
    match n {
        0..1_000 => format!("{n} bytes"),
        1_000..1_000_000 => format!("{:.1} kB", x / 1e3),
        1_000_000..1_000_000_000 => format!("{:.1} MB", x / 1e6),
        _ => format!("{:.1} GB", x / 1e9),
    }
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
    fn sizes_in_words() {
        assert_eq!(bytes_in_words(999), "999 bytes");
        assert_eq!(bytes_in_words(3_400_000), "3.4 MB");
        assert_eq!(bytes_in_words(1 << 30), "1 GiB");
        assert_eq!(bytes_in_words(11_000_000_000), "11.0 GB");
    }
}
