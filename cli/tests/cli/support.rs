//! Running the `kefric` binary built for the tests, and what its
//! rejection of bad input must look like.

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

/// Asserts that the run's stderr contains `text` (and shows it if not).
#[track_caller]
pub fn assert_stderr_has(o: &std::process::Output, text: &str) {
    let e = stderr(o);
    assert!(e.contains(text), "{text:?} not in stderr: {e}");
}

/// Runs `kefric` with `feed` writing its stdin (on a thread of its own,
/// so that a program that stops reading cannot block the test).
pub fn kefric_fed(args: &[&str], feed: impl FnOnce(std::process::ChildStdin) + Send + 'static) -> std::process::Output {
    use std::process::Stdio;
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kefric"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("kefric runs");
    let stdin = child.stdin.take().expect("a piped stdin");
    let writer = std::thread::spawn(move || feed(stdin));
    let o = child.wait_with_output().expect("kefric ends");
    writer.join().expect("the writer ends");
    o
}

/// Runs `kefric` with `input` on its stdin.
pub fn kefric_stdin(args: &[&str], input: &[u8]) -> std::process::Output {
    use std::io::Write;
    let input = input.to_vec();
    kefric_fed(args, move |mut stdin| {
        let _ = stdin.write_all(&input);
    })
}
