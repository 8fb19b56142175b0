//! Hardening: `kefric build` is deterministic across thread counts, and an
//! interrupted or failed build never damages the file at its output path.

use crate::common::TempDir;
use crate::support::{LONG_BUILD, SMALL_BUILD};
use ke_friction::Table;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn kefric(args: &[&str], threads: Option<usize>) -> std::process::Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_kefric"));
    cmd.args(args);
    if let Some(n) = threads {
        cmd.env("RAYON_NUM_THREADS", n.to_string());
    }
    cmd.output().expect("kefric runs")
}

fn build_small(out: &Path, threads: usize) -> Vec<u8> {
    let out_s = out.display().to_string();
    let mut args = SMALL_BUILD.to_vec();
    args.extend(["--out", out_s.as_str()]);
    let o = kefric(&args, Some(threads));
    assert!(
        o.status.success(),
        "{threads} threads: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains(&format!("on {threads} threads")), "{stdout}");
    std::fs::read(out).unwrap()
}

#[test]
fn builds_on_one_and_two_threads_are_byte_identical() {
    let dir = TempDir::new("threads");
    let one = build_small(&dir.0.join("one.kft"), 1);
    let two = build_small(&dir.0.join("two.kft"), 2);
    let four = build_small(&dir.0.join("four.kft"), 4);
    assert!(one == two, "1 and 2 threads differ");
    assert!(one == four, "1 and 4 threads differ");
    // A valid table, and exactly the files asked for (no temporary left).
    let t = Table::from_bytes(&one).expect("the build decodes");
    assert_eq!(t.info().build.nodes, [9, 9, 9]);
    assert_eq!(dir.names(""), ["four.kft", "one.kft", "two.kft"]);
}

/// Temporary files `write_atomic` may leave behind when killed.
fn is_temporary(name: &str, target: &str) -> bool {
    name.strip_prefix(&format!(".{target}.tmp-"))
        .is_some_and(|pid| !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit()))
}

/// A scratch directory holding a valid table (the embedded one) at
/// `table.kft`, its path, and the path as an argument.
fn with_previous_table(name: &str) -> (TempDir, std::path::PathBuf, String) {
    let dir = TempDir::new(name);
    let out = dir.join("table.kft");
    std::fs::write(&out, Table::embedded_bytes()).unwrap();
    let arg = dir.arg("table.kft");
    (dir, out, arg)
}

#[test]
fn an_interrupted_build_leaves_the_previous_file_intact() {
    let (dir, out, out_s) = with_previous_table("kill");
    let previous = Table::embedded_bytes();
    // Larger than the default build: several seconds at least.
    let mut child = Command::new(env!("CARGO_BIN_EXE_kefric"))
        .args(LONG_BUILD)
        .args(["--out", out_s.as_str()])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("kefric starts");
    let started = Instant::now();
    std::thread::sleep(Duration::from_millis(500));
    let still_running = child.try_wait().unwrap().is_none();
    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert!(
        still_running,
        "the build ended within {:?} ({status:?}): the test did not interrupt anything",
        started.elapsed()
    );
    let now = std::fs::read(&out).expect("the previous file is still there");
    assert!(now == previous, "the previous file at the output path was changed");
    let mut temporaries = vec![];
    for name in dir.names("") {
        if name == "table.kft" {
            continue;
        }
        assert!(
            is_temporary(&name, "table.kft"),
            "unexpected file {name} after the kill"
        );
        temporaries.push(name);
    }
    for name in temporaries {
        std::fs::remove_file(dir.0.join(name)).unwrap();
    }
}

#[test]
fn a_failed_build_leaves_the_previous_file_intact() {
    let (dir, out, out_s) = with_previous_table("fail");
    let previous = Table::embedded_bytes();
    // Misses its tolerance after doing all the work: status 1, nothing written.
    let mut args: Vec<&str> = SMALL_BUILD.iter().map(|a| if *a == "1" { "1e-9" } else { a }).collect();
    args.extend(["--out", out_s.as_str()]);
    let o = kefric(&args, None);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("tolerance"), "{err}");
    assert!(
        std::fs::read(&out).unwrap() == previous,
        "the previous file was changed"
    );
    assert_eq!(dir.names(""), ["table.kft"]);
    // Rejected input: status 2, nothing written either.
    let mut args = SMALL_BUILD.to_vec();
    args.extend(["--out", out_s.as_str(), "--psi", "8:0.5"]);
    let o = kefric(&args, None);
    assert_eq!(o.status.code(), Some(2));
    assert!(std::fs::read(&out).unwrap() == previous);
    assert_eq!(dir.names(""), ["table.kft"]);
}

#[test]
fn a_successful_build_replaces_the_previous_file_whole() {
    let dir = TempDir::new("replace");
    let out = dir.0.join("table.kft");
    let old = b"an old, invalid table".to_vec();
    std::fs::write(&out, &old).unwrap();
    // A reader that opened the old file keeps seeing all of it: the new file
    // is renamed over the old one, not written into it.
    let mut reader = std::fs::File::open(&out).unwrap();
    let bytes = build_small(&out, 2);
    assert!(Table::from_bytes(&bytes).is_ok());
    let mut seen = vec![];
    std::io::Read::read_to_end(&mut reader, &mut seen).unwrap();
    assert!(seen == old, "the old file was rewritten in place, not replaced");
    assert_eq!(dir.names(""), ["table.kft"]);
}
