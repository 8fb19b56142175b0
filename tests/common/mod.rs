//! Shared tolerances and helpers for the integration tests.
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

/// Runs the `kefric` binary built for the tests.
pub fn kefric(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kefric"))
        .args(args)
        .output()
        .expect("kefric runs")
}

/// A process's stderr as text.
pub fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
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

/// `kefric build` of a small table (a fraction of a second); any tolerance.
pub const SMALL_BUILD: &[&str] = &[
    "build",
    "--nodes",
    "9,9,9",
    "--h-star",
    "0:4:21",
    "--samples",
    "200",
    "--tolerance",
    "1",
    "--quiet",
];

/// `kefric build` of a table larger than the default: several seconds at
/// least, long enough to interrupt or to show that bad input is caught first.
pub const LONG_BUILD: &[&str] = &["build", "--nodes", "65,65,65", "--samples", "200000", "--quiet"];

/// What is wrong with a run as the rejection of bad input naming `needle`
/// (the flag), or `None`: it must exit with status 2 (`None`: it did not
/// exit), print exactly one line on stderr containing `needle`, print
/// nothing on stdout, and not panic.
pub fn bad_input_problem(status: Option<i32>, stdout: &str, stderr: &str, needle: &str) -> Option<String> {
    let mut why = vec![];
    match status {
        Some(2) => {}
        Some(s) => why.push(format!("exit status {s}, want 2")),
        None => why.push("did not exit".to_string()),
    }
    if stderr.contains("panicked") || stdout.contains("panicked") {
        why.push("panicked".into());
    }
    let lines = stderr.trim_end().lines().count();
    if lines != 1 {
        why.push(format!("{lines} lines on stderr, want 1"));
    } else if !stderr.contains(needle) {
        why.push(format!("message does not name {needle}"));
    }
    if !stdout.is_empty() {
        why.push(format!("stdout not empty: {stdout:?}"));
    }
    (!why.is_empty()).then(|| format!("{}; stderr: {stderr:?}", why.join("; ")))
}

/// Asserts what bad input must give (see [`bad_input_problem`]).
#[track_caller]
pub fn assert_bad_input(o: &std::process::Output, needle: &str) {
    let out = String::from_utf8_lossy(&o.stdout);
    if let Some(why) = bad_input_problem(o.status.code(), &out, &stderr(o), needle) {
        panic!("{why}");
    }
}
