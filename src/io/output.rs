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
            .map_err(|e| {
                // The OS names the file, but what is missing is its folder.
                let why = match std::fs::metadata(dir) {
                    Err(_) => format!("the folder {} does not exist", dir.display()),
                    Ok(m) if !m.is_dir() => format!("{} is not a folder", dir.display()),
                    Ok(_) => io_reason(&e),
                };
                anyhow::anyhow!("cannot write {}: {why}", target.display())
            })?;
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
        self.write(bytes)?;
        let Some(temp) = self.temp.take() else {
            return Ok(());
        };
        // Renamed under the lock: a signal handler removes the temporary file
        // either before (nothing is written) or not at all (the file is whole).
        let mut list = pending();
        list.retain(|p| p != temp.path());
        let target = &self.target;
        let persisted = if replace {
            temp.persist(target)
        } else {
            temp.persist_noclobber(target)
        };
        persisted.map_err(|e| failed(target, &e.error))?;
        Ok(())
    }

    /// Writes `bytes` to the temporary file, syncs it and gives it the
    /// permissions of the file it replaces; on failure the temporary file is
    /// removed.
    fn write(&mut self, bytes: &[u8]) -> Result<()> {
        let Some(temp) = self.temp.as_mut() else {
            return Ok(());
        };
        let written = temp
            .write_all(bytes)
            .and_then(|()| temp.as_file().sync_all())
            .and_then(|()| keep_permissions(temp.as_file(), &self.target));
        if let Err(e) = written {
            let path = temp.path().to_owned();
            pending().retain(|p| *p != path);
            // Dropped, the temporary file is removed.
            self.temp = None;
            return Err(failed(&self.target, &e));
        }
        Ok(())
    }
}

/// Commits several files as one: all of them or none. Every file is written
/// and synced first, so a full disk fails before any target changes; then
/// all are renamed into place under one hold of the pending list, so a
/// signal removes every temporary file or none. Should a rename fail still
/// (a target's folder removed meanwhile, or a folder put in its place), the
/// targets already renamed are removed: no run leaves part of its output.
pub fn commit_all(mut files: Vec<(PendingFile, &[u8])>) -> Result<()> {
    for (file, bytes) in &mut files {
        file.write(bytes)?;
    }
    // Out of their `PendingFile`s, whose drop takes the lock held below.
    let temps: Vec<(NamedTempFile, PathBuf)> = files
        .into_iter()
        .filter_map(|(mut file, _)| Some((file.temp.take()?, file.target.clone())))
        .collect();
    let mut list = pending();
    list.retain(|p| !temps.iter().any(|(t, _)| t.path() == p));
    let mut done: Vec<PathBuf> = Vec::new();
    for (temp, target) in temps {
        if let Err(e) = temp.persist(&target) {
            for renamed in &done {
                let _ = std::fs::remove_file(renamed);
            }
            return Err(failed(&target, &e.error));
        }
        done.push(target);
    }
    Ok(())
}

/// "cannot write TARGET: reason".
fn failed(target: &Path, e: &std::io::Error) -> anyhow::Error {
    anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(e))
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
    fn a_missing_folder_is_named_as_the_reason() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("nodir").join("out.png");
        let e = PendingFile::create(&target).err().unwrap().to_string();
        let folder = dir.path().join("nodir");
        assert_eq!(
            e,
            format!(
                "cannot write {}: the folder {} does not exist",
                target.display(),
                folder.display()
            )
        );
        std::fs::write(&folder, b"").unwrap();
        let e = PendingFile::create(&target).err().unwrap().to_string();
        assert!(
            e.ends_with(&format!("{} is not a folder", folder.display())),
            "{e}"
        );
    }

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
    fn several_files_are_committed_all_or_none() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.png"), dir.path().join("b.csv"));
        let first = PendingFile::create(&a).unwrap();
        let second = PendingFile::create(&b).unwrap();
        let temps = [first.temp_path().to_owned(), second.temp_path().to_owned()];
        // The second target turns into a folder with a file in it: no rename
        // can replace it.
        std::fs::create_dir(&b).unwrap();
        std::fs::write(b.join("x"), "x").unwrap();
        let e = commit_all(vec![(first, b"png"), (second, b"csv")]).unwrap_err();
        assert!(e.to_string().starts_with("cannot write "), "{e}");
        assert!(!a.exists(), "the first file is not left behind");
        for temp in &temps {
            assert!(!temp.exists() && !pending().contains(temp));
        }
        let (c, d) = (dir.path().join("c.png"), dir.path().join("d.csv"));
        let both = vec![
            (PendingFile::create(&c).unwrap(), &b"c"[..]),
            (PendingFile::create(&d).unwrap(), &b"d"[..]),
        ];
        commit_all(both).unwrap();
        assert_eq!(std::fs::read(&c).unwrap(), b"c");
        assert_eq!(std::fs::read(&d).unwrap(), b"d");
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
