//! Output files written atomically: a temporary file beside the target, renamed
//! over it once complete, so an interrupted run never leaves a half-written file.

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use tempfile::NamedTempFile;

/// An output file, opened as a temporary file beside its target before the work
/// that fills it starts, so a bad path fails at once rather than after a render.
#[derive(Debug)]
pub struct PendingFile {
    target: PathBuf,
    temp: NamedTempFile,
}

impl PendingFile {
    /// Prepares to write `target`, failing with a one-line reason if its folder
    /// does not exist or cannot be written.
    pub fn create(target: &Path) -> Result<Self> {
        let dir = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if target.is_dir() {
            bail!("cannot write {}: it is a directory", target.display());
        }
        let temp = tempfile::Builder::new()
            .prefix(".raytree-")
            .suffix(".part")
            .tempfile_in(dir)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(&e)))?;
        Ok(Self {
            target: target.to_owned(),
            temp,
        })
    }

    /// Where the temporary file is, until it is committed.
    pub fn temp_path(&self) -> &Path {
        self.temp.path()
    }

    /// Writes `bytes` and renames the file into place.
    pub fn commit(self, bytes: &[u8]) -> Result<()> {
        let Self { target, mut temp } = self;
        let fail = |e: std::io::Error| {
            anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(&e))
        };
        temp.write_all(bytes).map_err(fail)?;
        temp.as_file().sync_all().map_err(fail)?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            temp.as_file()
                .set_permissions(std::fs::Permissions::from_mode(0o644))
                .map_err(fail)?;
        }
        temp.persist(&target).map_err(|e| fail(e.error))?;
        Ok(())
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
