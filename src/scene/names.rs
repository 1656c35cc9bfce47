//! The names and paths a scene file gives, checked: names printable, and a
//! mesh's file in the scene's folder or below it.

use std::path::Path;

use crate::scene::quote::quote;

/// The longest path a mesh's `file` may be, Linux's `PATH_MAX`: no longer
/// one names a file, and the errors that name the file stay short.
pub const MAX_PATH_BYTES: usize = 4096;

/// A mesh's `file` stays in the scene's folder `dir` or below it: no `..`
/// above the folder, no absolute path or symlink that resolves out of it (the
/// deepest part of the path that exists is resolved). A path out is refused whether or not
/// its file exists, so a scene cannot probe the machine's files.
pub fn within(dir: &Path, file: &str) -> Result<(), String> {
    use std::path::Component;
    if file.len() > MAX_PATH_BYTES {
        return Err(format!(
            "{} is longer than a path can be ({MAX_PATH_BYTES} bytes)",
            quote(file, "'")
        ));
    }
    let leaves = || {
        Err(format!(
            "{} leaves the scene's folder (a mesh is read from the scene's folder or one below it)",
            quote(file, "'")
        ))
    };
    // A relative path climbing above the folder, by its words alone (an
    // absolute path is judged by where it resolves, below).
    let mut depth = 0usize;
    for part in Path::new(file).components() {
        match part {
            Component::Normal(_) => depth += 1,
            Component::ParentDir if depth > 0 => depth -= 1,
            Component::ParentDir => return leaves(),
            Component::CurDir | Component::RootDir | Component::Prefix(_) => {}
        }
    }
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    let Ok(root) = std::fs::canonicalize(dir) else {
        return Ok(());
    };
    let path = dir.join(file);
    let mut part: &Path = &path;
    loop {
        if let Ok(real) = std::fs::canonicalize(part) {
            return if real.starts_with(&root) {
                Ok(())
            } else {
                leaves()
            };
        }
        match part.parent() {
            Some(up) => part = up,
            None => return Ok(()),
        }
    }
}

/// A name shown in traces, errors and the terminal: no control characters,
/// which a terminal would obey (`\u{1b}[2J` clears the screen).
pub fn name_ok(name: &str) -> Result<(), String> {
    match name.chars().find(|c| c.is_control()) {
        Some(c) => Err(format!(
            "{} holds a control character ({}); names must be printable",
            quote(name, "'"),
            c.escape_unicode()
        )),
        None => Ok(()),
    }
}
