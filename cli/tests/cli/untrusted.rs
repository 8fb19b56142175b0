//! Issue 23 through the program: crafted table files, output that cannot
//! be written, special files as outputs, unbounded inputs, text from files.

use crate::common::TempDir;
use crate::forge::{crafted, Spec};
use crate::support::{assert_bad_input, assert_stderr_has, kefric, kefric_fed, stderr};
use std::io::Write;
use std::process::Command;

/// Runs kefric with stdout sent to /dev/full.
fn to_full(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kefric"))
        .args(args)
        .stdout(std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap())
        .output()
        .unwrap()
}

#[test]
fn output_that_cannot_be_written_is_one_error_line_and_exit_1() {
    let params = [&["params"][..], &crate::cli_tools::SI[..]].concat();
    let cases: &[&[&str]] = &[
        &["info"],
        &["info", "--json"],
        &["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01"],
        &["lookup", "--psi", "1", "--theta", "0.001", "--f-star", "0.01"],
        &params,
        &["validate"],
        &["--help"],
    ];
    for args in cases {
        let o = to_full(args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert_eq!(err.trim(), "error: stdout: No space left on device", "{args:?}");
    }
}

#[test]
fn crafted_tables_are_refused_naming_the_field_or_answer() {
    let tmp = TempDir::new("crafted");
    for (i, (name, spec, refused)) in crafted().into_iter().enumerate() {
        let path = tmp.join(&format!("{i}.kft"));
        std::fs::write(&path, spec.encode()).unwrap();
        let p = path.to_str().unwrap();
        let o = kefric(&[
            "lookup", "--table", p, "--psi", "2", "--theta", "0.001", "--f-star", "0.001", "--json",
        ]);
        match refused {
            Some(field) => {
                assert_bad_input(&o, "--table");
                assert!(stderr(&o).contains(field), "{name}: {}", stderr(&o));
            }
            None => {
                assert!(o.status.success(), "{name}: {}", stderr(&o));
                let out: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
                let mu = out["mu"].as_f64().unwrap();
                let want = spec.stored(spec.ln_mu[0]).exp();
                assert!(
                    (mu / want - 1.0).abs() <= 2e-6 * (1.0 + want.ln().abs()),
                    "{name}: {mu} vs {want}"
                );
            }
        }
    }
}

#[test]
fn text_from_a_table_is_printed_escaped() {
    let tmp = TempDir::new("escape");
    let mut spec = Spec::uniform(0.0, true);
    spec.generator = "ok\n\x1b[32mverdict: OK\x1b[0m\r\u{202e}".into();
    let path = tmp.join("t.kft");
    std::fs::write(&path, spec.encode()).unwrap();
    for json in [false, true] {
        let mut args = vec!["info", "--table", path.to_str().unwrap()];
        if json {
            args.push("--json");
        }
        let o = kefric(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let out = String::from_utf8(o.stdout).unwrap();
        assert!(!out.chars().any(|c| c.is_control() && c != '\n'), "{out:?}");
        assert!(
            !out.contains('\u{202e}') && !out.lines().any(|l| l.starts_with("verdict")),
            "{out}"
        );
        assert!(out.contains(r"\u{1b}[32mverdict: OK"), "{out}");
    }
}

#[test]
fn special_files_are_refused_as_outputs_and_symlinks_followed() {
    let o = kefric(&["export", "--npz", "/dev/full", "--quiet"]);
    assert_bad_input(&o, "--npz");
    assert_stderr_has(&o, "not a regular file");
    let tmp = TempDir::new("links");
    std::fs::write(tmp.join("real.npz"), b"old").unwrap();
    std::os::unix::fs::symlink("real.npz", tmp.join("link.npz")).unwrap();
    let o = kefric(&["export", "--npz", &tmp.arg("link.npz"), "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::symlink_metadata(tmp.join("link.npz"))
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::metadata(tmp.join("real.npz")).unwrap().len() > 1000);
    assert_eq!(tmp.names(""), ["link.npz", "real.npz"], "no temporary file left");
    let fifo = tmp.join("fifo.kft");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let mut args = crate::support::SMALL_BUILD.to_vec();
    args.extend(["--out", fifo.to_str().unwrap()]);
    let o = kefric(&args);
    assert_bad_input(&o, "--out");
}

#[test]
fn unbounded_inputs_end_with_an_error() {
    let o = kefric(&["info", "--table", "/dev/urandom"]);
    assert_bad_input(&o, "--table");
    // A 3 MiB line; the program stops reading after 1 MiB.
    let o = kefric_fed(&["lookup", "--csv"], |mut stdin| {
        let chunk = vec![b'1'; 1 << 16];
        for _ in 0..48 {
            if stdin.write_all(&chunk).is_err() {
                break;
            }
        }
    });
    assert_eq!(o.status.code(), Some(2));
    assert_stderr_has(&o, "--csv: line 1: longer than 1048576 bytes");
}

#[test]
fn a_ghost_node_without_mu_is_named_as_the_cause() {
    let tmp = TempDir::new("ghost");
    let o = kefric(&[
        "build",
        "--f-star",
        "1e-4:1e-1",
        "--nodes",
        "5,5,5",
        "--quiet",
        "--out",
        &tmp.arg("t.kft"),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("ghost node beyond the F* range") && err.contains("more F* nodes"),
        "{err}"
    );
    assert!(tmp.names("").is_empty());
}

#[test]
fn a_table_error_names_the_file_once() {
    let tmp = TempDir::new("once");
    let missing = tmp.arg("missing.kft");
    std::fs::write(tmp.join("bad.kft"), b"KEFRICTB\x01\x00\x00\x00junk").unwrap();
    for path in [missing, tmp.arg("bad.kft")] {
        let o = kefric(&[
            "lookup", "--table", &path, "--psi", "1", "--theta", "0", "--f-star", "0.01",
        ]);
        assert_bad_input(&o, "--table");
        assert_eq!(stderr(&o).matches(path.as_str()).count(), 1, "{}", stderr(&o));
    }
}
