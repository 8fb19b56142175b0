//! Atomic file writes: no file is ever half-written under its own name.

use std::fs::File;
use std::path::Path;

/// Writes `bytes` to `path` atomically: to a temporary file in the same
/// directory, flushed to disk, then renamed over `path`. An interrupted
/// write leaves any previous file at `path` intact and no partial file
/// under its name.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomic_with(path, |mut file| {
        std::io::Write::write_all(&mut file, bytes)?;
        file.sync_all()
    })
}

/// [`write_atomic`] with the file's contents written (and synced) by `write`.
pub fn write_atomic_with(path: &Path, write: impl FnOnce(File) -> std::io::Result<()>) -> std::io::Result<()> {
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "no file name"))?;
    let tmp = path.with_file_name(format!(".{}.tmp-{}", name.to_string_lossy(), std::process::id()));
    let result = File::create(&tmp)
        .and_then(write)
        .and_then(|()| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
