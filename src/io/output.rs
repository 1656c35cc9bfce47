//! Output files written atomically: a temporary file beside the target, renamed
//! over it once complete, so an interrupted run never leaves a half-written
//! file. Every temporary file is registered until it is renamed or dropped, so
//! a signal handler can remove them all ([`remove_pending`]): a signal skips the
//! destructors that would.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

use anyhow::{Result, bail};
use tempfile::NamedTempFile;

/// The temporary files of outputs not yet committed.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

/// Removes every pending temporary file; returns how many there were. For a
/// signal handler, just before the process exits.
pub fn remove_pending() -> usize {
    let mut list = pending();
    for path in list.iter() {
        let _ = std::fs::remove_file(path);
    }
    std::mem::take(&mut *list).len()
}

/// An output file, opened as a temporary file beside its target before the work
/// that fills it starts, so a bad path fails at once rather than after a render.
#[derive(Debug)]
pub struct PendingFile {
    target: PathBuf,
    /// `None` once committed.
    temp: Option<NamedTempFile>,
}

impl PendingFile {
    /// Prepares to write `target`, failing with a one-line reason if its folder
    /// does not exist or cannot be written, or if `target` exists and is not a
    /// regular file or is read-only (a read-only file is never replaced).
    pub fn create(target: &Path) -> Result<Self> {
        let dir = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if let Ok(meta) = std::fs::metadata(target) {
            if meta.is_dir() {
                bail!("cannot write {}: it is a directory", target.display());
            }
            if !meta.is_file() {
                bail!(
                    "cannot write {}: it is not a regular file",
                    target.display()
                );
            }
            if meta.permissions().readonly() {
                bail!(
                    "cannot write {}: it is read-only (make it writable, or choose another name)",
                    target.display()
                );
            }
        }
        // Registered under the lock it is created in: a signal arriving between
        // the two cannot leave it behind.
        let mut list = pending();
        let temp = tempfile::Builder::new()
            .prefix(".raytree-")
            .suffix(".part")
            .tempfile_in(dir)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(&e)))?;
        list.push(temp.path().to_owned());
        Ok(Self {
            target: target.to_owned(),
            temp: Some(temp),
        })
    }

    /// Where the temporary file is, until it is committed.
    pub fn temp_path(&self) -> &Path {
        self.temp
            .as_ref()
            .map_or(Path::new(""), NamedTempFile::path)
    }

    /// Writes `bytes` and renames the file into place, keeping the permissions
    /// of the file it replaces (a new file gets `rw-r--r--`).
    pub fn commit(self, bytes: &[u8]) -> Result<()> {
        self.finish(bytes, true)
    }

    /// As [`commit`](Self::commit), but fails rather than replace a file that
    /// appeared at the target meanwhile: for outputs that must be new.
    pub fn commit_new(self, bytes: &[u8]) -> Result<()> {
        self.finish(bytes, false)
    }

    fn finish(mut self, bytes: &[u8], replace: bool) -> Result<()> {
        let Some(mut temp) = self.temp.take() else {
            return Ok(());
        };
        let target = &self.target;
        let fail = |e: std::io::Error| {
            anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(&e))
        };
        let unregister = |path: &Path| pending().retain(|p| p != path);
        let written = temp
            .write_all(bytes)
            .and_then(|()| temp.as_file().sync_all())
            .and_then(|()| keep_permissions(temp.as_file(), target));
        if let Err(e) = written {
            unregister(temp.path());
            return Err(fail(e));
        }
        // Renamed under the lock: a signal handler removes the temporary file
        // either before (nothing is written) or not at all (the file is whole).
        let mut list = pending();
        let path = temp.path().to_owned();
        list.retain(|p| *p != path);
        if replace {
            temp.persist(target).map_err(|e| fail(e.error))?;
        } else {
            temp.persist_noclobber(target).map_err(|e| fail(e.error))?;
        }
        Ok(())
    }
}

impl Drop for PendingFile {
    fn drop(&mut self) {
        if let Some(temp) = &self.temp {
            let path = temp.path().to_owned();
            pending().retain(|p| *p != path);
        }
    }
}

/// Gives `file` the permissions of the file `target` it replaces, or
/// `rw-r--r--` for a new one.
fn keep_permissions(file: &std::fs::File, target: &Path) -> std::io::Result<()> {
    if let Ok(meta) = std::fs::metadata(target) {
        return file.set_permissions(meta.permissions());
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        file.set_permissions(std::fs::Permissions::from_mode(0o644))
    }
    #[cfg(not(unix))]
    Ok(())
}

/// Whether `a` and `b` are the same file: the same file on disk if both exist
/// (through links too), else the same path once their folders are resolved.
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
        use std::os::unix::fs::MetadataExt;
        return (x.dev(), x.ino()) == (y.dev(), y.ino());
    }
    let resolved = |p: &Path| {
        let dir = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        std::fs::canonicalize(dir)
            .ok()
            .zip(p.file_name())
            .map(|(d, f)| d.join(f))
    };
    match (resolved(a), resolved(b)) {
        (Some(x), Some(y)) => x == y,
        _ => a == b,
    }
}

/// The OS's reason without Rust's "(os error N)" suffix.
pub fn io_reason(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.find(" (os error") {
        Some(i) => s[..i].to_owned(),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pending_file_is_registered_until_committed_or_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let listed = |p: &Path| pending().iter().any(|q| q == p);
        let a = PendingFile::create(&dir.path().join("a.txt")).unwrap();
        let temp = a.temp_path().to_owned();
        assert!(listed(&temp) && temp.exists());
        a.commit(b"a").unwrap();
        assert!(!listed(&temp) && !temp.exists());
        assert_eq!(std::fs::read(dir.path().join("a.txt")).unwrap(), b"a");
        let b = PendingFile::create(&dir.path().join("b.txt")).unwrap();
        let temp = b.temp_path().to_owned();
        drop(b);
        assert!(!listed(&temp) && !temp.exists());
    }

    #[test]
    fn commit_new_never_replaces_a_file_that_appeared_meanwhile() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("edit.json");
        let file = PendingFile::create(&target).unwrap();
        let temp = file.temp_path().to_owned();
        std::fs::write(&target, "theirs").unwrap();
        assert!(file.commit_new(b"ours").is_err());
        assert_eq!(std::fs::read(&target).unwrap(), b"theirs");
        assert!(!temp.exists(), "the temporary file is cleaned up");
        let fresh = dir.path().join("fresh.json");
        PendingFile::create(&fresh)
            .unwrap()
            .commit_new(b"ours")
            .unwrap();
        assert_eq!(std::fs::read(&fresh).unwrap(), b"ours");
    }

    #[cfg(unix)]
    #[test]
    fn read_only_files_are_refused_and_modes_kept() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("x.txt");
        std::fs::write(&file, "old").unwrap();
        std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
        PendingFile::create(&file).unwrap().commit(b"new").unwrap();
        let mode = std::fs::metadata(&file).unwrap().permissions().mode();
        assert_eq!(mode & 0o777, 0o600, "the replaced file's mode is kept");
        std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o444)).unwrap();
        let e = PendingFile::create(&file).unwrap_err().to_string();
        assert!(e.contains("read-only"), "{e}");
        assert_eq!(std::fs::read(&file).unwrap(), b"new");
        assert!(same_file(&file, &dir.path().join(".").join("x.txt")));
        assert!(same_file(
            &dir.path().join("new.obj"),
            &dir.path().join("new.obj")
        ));
        assert!(!same_file(&file, &dir.path().join("new.obj")));
    }
}
