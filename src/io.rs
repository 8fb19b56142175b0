//! Atomic file writes: no file is ever half-written under its own name.
//!
//! What an output path may be: a new file in an existing directory, or an
//! existing regular file, which is replaced whole. A symbolic link is
//! followed: its target is replaced (the link stays a link). An existing
//! path that is not a regular file (a device such as `/dev/full`, a pipe,
//! a socket, a directory) is refused: nothing is created or replaced.

use std::fs::File;
use std::io;
use std::path::{Path, PathBuf};

/// Writes `bytes` to `path` atomically: to a temporary file in the same
/// directory, flushed to disk, then renamed over `path`. An interrupted
/// write leaves any previous file at `path` intact and no partial file
/// under its name.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_atomic_with(path, |mut file| {
        io::Write::write_all(&mut file, bytes)?;
        file.sync_all()
    })
}

/// The file an output path writes: `path` itself, or where its symbolic
/// links lead; an error if that exists and is not a regular file.
pub fn output_target(path: &Path) -> io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(p),
            Err(e) => return Err(e),
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            Ok(m) if m.is_file() => return Ok(p),
            Ok(_) => {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!("{} exists and is not a regular file (not replaced)", p.display()),
                ))
            }
        }
    }
    Err(io::Error::new(
        io::ErrorKind::InvalidInput,
        "too many levels of symbolic links",
    ))
}

/// A temporary name beside `path`: `.NAME.tmp-PID`.
fn temp_beside(path: &Path) -> io::Result<PathBuf> {
    let name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "no file name"))?;
    Ok(path.with_file_name(format!(".{}.tmp-{}", name.to_string_lossy(), std::process::id())))
}

/// [`write_atomic`] with the file's contents written (and synced) by `write`.
pub fn write_atomic_with(path: &Path, write: impl FnOnce(File) -> io::Result<()>) -> io::Result<()> {
    replace_via(path, false, |tmp| write(File::create_new(tmp)?))
}

/// Writes the file at `path` through a temporary path beside its target
/// ([`output_target`]): `write` fills the temporary path, which is then
/// renamed over the target; on any error it is removed. The temporary is
/// `.NAME.tmp-PID`, or with `keep_extension` `.tmp-PID-NAME`, for writers
/// that choose a format by the extension (the figures' image encoder).
pub fn replace_via(path: &Path, keep_extension: bool, write: impl FnOnce(&Path) -> io::Result<()>) -> io::Result<()> {
    let target = output_target(path)?;
    let tmp = match (keep_extension, target.file_name()) {
        (true, Some(name)) => target.with_file_name(format!(".tmp-{}-{}", std::process::id(), name.to_string_lossy())),
        _ => temp_beside(&target)?,
    };
    let result = write(&tmp).and_then(|()| std::fs::rename(&tmp, &target));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes one file's contents (and syncs it).
pub type WriteFile<'a> = dyn Fn(File) -> io::Result<()> + 'a;

/// Writes a set of files into directory `dir` all or nothing: each
/// `(name, write)` into a temporary directory beside `dir`, synced; only
/// when every one is written are they moved into `dir` (created if
/// missing: then the directory itself is renamed into place). On any
/// error the temporary directory is removed and `dir` is as before.
pub fn write_dir_atomic(dir: &Path, files: &[(&str, &WriteFile)]) -> io::Result<()> {
    if let Ok(m) = std::fs::metadata(dir) {
        if !m.is_dir() {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!("{} exists and is not a directory", dir.display()),
            ));
        }
    }
    let tmp = temp_beside(dir)?;
    std::fs::create_dir(&tmp)?;
    let fill = || -> io::Result<()> {
        for (name, write) in files {
            write(File::create_new(tmp.join(name))?)?;
        }
        if !dir.exists() {
            return std::fs::rename(&tmp, dir);
        }
        for (name, _) in files {
            let target = output_target(&dir.join(name))?;
            std::fs::rename(tmp.join(name), target)?;
        }
        std::fs::remove_dir(&tmp)
    };
    let result = fill();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("kef-io-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn special_files_are_refused_and_symlinks_followed() {
        let e = write_atomic(Path::new("/dev/null"), b"x").unwrap_err();
        assert!(e.to_string().contains("not a regular file"), "{e}");
        assert!(std::fs::symlink_metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device_like());
        let d = scratch("link");
        let real = d.join("real.txt");
        std::fs::write(&real, b"old").unwrap();
        let link = d.join("link.txt");
        std::os::unix::fs::symlink("real.txt", &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 2, "no temporary file left");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_failed_set_of_files_leaves_nothing() {
        let d = scratch("dir");
        let out = d.join("npy");
        let ok: &dyn Fn(File) -> io::Result<()> = &|mut f| io::Write::write_all(&mut f, b"x");
        let fail: &dyn Fn(File) -> io::Result<()> = &|_| Err(io::Error::other("disk full"));
        assert!(write_dir_atomic(&out, &[("a.npy", ok), ("b.npy", fail)]).is_err());
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 0, "nothing left behind");
        write_dir_atomic(&out, &[("a.npy", ok), ("b.npy", ok)]).unwrap();
        assert_eq!(std::fs::read_dir(&out).unwrap().count(), 2);
        // Into an existing directory, a failure leaves it as it was.
        assert!(write_dir_atomic(&out, &[("c.npy", ok), ("d.npy", fail)]).is_err());
        assert_eq!(std::fs::read_dir(&out).unwrap().count(), 2);
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1);
        std::fs::remove_dir_all(&d).unwrap();
    }

    trait CharDevice {
        fn is_char_device_like(&self) -> bool;
    }
    impl CharDevice for std::fs::FileType {
        fn is_char_device_like(&self) -> bool {
            use std::os::unix::fs::FileTypeExt;
            self.is_char_device()
        }
    }
}
