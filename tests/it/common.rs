//! Tolerances and helpers shared by the library's integration tests
//! (`tests/it`) and the program's (`cli/tests/cli`, which includes this
//! file by path).
#![allow(dead_code)]

/// Relative agreement with 30-digit quadrature that the issue demands of
/// every model output (MODEL.md §7 values are themselves good to ~1e-15,
/// printed to 11 digits, so this also bounds the printing error).
pub const REFERENCE_REL: f64 = 1e-9;

/// Relative difference, safe at zero.
pub fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// Asserts `|a − b| ≤ tol·max(|a|, |b|)` with a message naming `what`.
#[track_caller]
pub fn assert_rel(what: &str, got: f64, want: f64, tol: f64) {
    let r = rel(got, want);
    assert!(
        r <= tol,
        "{what}: got {got:e}, want {want:e}, relative error {r:e} > {tol:e}"
    );
}

/// A fresh, empty directory under the system's temporary directory,
/// unique to this process and `name`, removed on drop.
pub struct TempDir(pub std::path::PathBuf);

impl TempDir {
    /// Creates (or empties) the directory.
    pub fn new(name: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("kefric-test-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }

    /// A path inside it.
    pub fn join(&self, name: &str) -> std::path::PathBuf {
        self.0.join(name)
    }

    /// A path inside it, as a string argument.
    pub fn arg(&self, name: &str) -> String {
        self.join(name).to_str().unwrap().to_string()
    }

    /// The sorted names in a subdirectory (to spot leftover temporary files).
    pub fn names(&self, sub: &str) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(self.0.join(sub))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The folder of the instruments' example files: `$KEF_TOPOGRAPHIES`, else
/// `shared/topographies` beside the repository; `None` (with a message)
/// where it is absent.
pub fn topographies() -> Option<std::path::PathBuf> {
    let dir = std::env::var_os("KEF_TOPOGRAPHIES")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| {
            // The workspace's root, from whichever crate includes this file.
            let manifest = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
            let root = manifest
                .ancestors()
                .find(|d| d.join("Cargo.lock").is_file())
                .unwrap_or(manifest);
            root.join("../shared/topographies")
        });
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("skipped: {} is absent (set KEF_TOPOGRAPHIES)", dir.display());
        None
    }
}

/// The contact.engineering container container-2.zip: in
/// `$KEF_CONTAINERS`, else `shared/containers` beside the repository;
/// `None` (with a message) where it is absent.
pub fn container_2() -> Option<std::path::PathBuf> {
    let dir = std::env::var_os("KEF_CONTAINERS")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/containers"));
    let path = dir.join("container-2.zip");
    if path.is_file() {
        Some(path)
    } else {
        println!("skipped: {} is absent (set KEF_CONTAINERS)", path.display());
        None
    }
}

/// The instruments' example file `name` ([`topographies`]), or `None`
/// (with a message) where it is absent.
pub fn instrument_file(name: &str) -> Option<std::path::PathBuf> {
    let path = topographies()?.join(name);
    if path.is_file() {
        Some(path)
    } else {
        println!("skipped: {} is absent", path.display());
        None
    }
}
