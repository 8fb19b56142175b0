//! Hardening: every subcommand of `kefric` over a long list of bad inputs.
//!
//! Each bad invocation must exit with status 2 and print exactly one line on
//! stderr that names the offending flag; status 101 or "panicked" anywhere
//! is a failure. `build` cases start from a large build (tens of seconds if
//! it ran), so a bad input that is not rejected up front shows up as a
//! timeout. All failures are collected and reported together.

use crate::support::{bad_input_problem, LONG_BUILD};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Longest a rejected invocation may take (a real build of the `build` base
/// options takes far longer).
const LIMIT: Duration = Duration::from_secs(10);

/// One bad invocation and the flag its message must name.
struct Case {
    args: Vec<String>,
    flag: String,
}

/// The outcome of one run: exit status (None if killed), stdout, stderr, time.
struct Run {
    status: Option<i32>,
    stdout: String,
    stderr: String,
    elapsed: Duration,
}

fn run(args: &[String], limit: Duration) -> Run {
    let started = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_kefric"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("kefric starts");
    // Drain the pipes on threads so that a chatty child cannot block.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let out = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut out, &mut s).ok();
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut err, &mut s).ok();
        s
    });
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait works") {
            break s.code();
        }
        if started.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    Run {
        status,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
        elapsed: started.elapsed(),
    }
}

/// What is wrong with this run as a rejection naming its flag (None if
/// nothing).
fn judge(case: &Case, r: &Run) -> Option<String> {
    let why = bad_input_problem(r.status, &r.stdout, &r.stderr, &case.flag)?;
    let killed = match r.status {
        None => format!(
            " (killed after {:.1} s: not rejected up front)",
            r.elapsed.as_secs_f64()
        ),
        Some(_) => String::new(),
    };
    Some(format!("kefric {:?}: {why}{killed}", case.args))
}

/// Runs every case (a few at a time) and fails listing all bad outcomes.
fn check_all(cases: Vec<Case>) {
    assert!(!cases.is_empty());
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(vec![]);
    std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                let r = run(&case.args, LIMIT);
                if let Some(f) = judge(case, &r) {
                    failures.lock().unwrap().push((i, f));
                }
            });
        }
    });
    let mut failures = failures.into_inner().unwrap();
    failures.sort();
    assert!(
        failures.is_empty(),
        "{} of {} bad invocations were not rejected properly:\n{}",
        failures.len(),
        cases.len(),
        failures.into_iter().map(|(_, f)| f).collect::<Vec<_>>().join("\n")
    );
}

/// `base` with `flag` set to `value` (replacing its value if present).
fn with(base: &[&str], flag: &str, value: &str) -> Vec<String> {
    let mut args: Vec<String> = base.iter().map(|s| s.to_string()).collect();
    match args.iter().position(|a| a == flag) {
        Some(i) => args[i + 1] = value.to_string(),
        None => {
            args.push(flag.to_string());
            args.push(value.to_string());
        }
    }
    args
}

/// `base` without `flag` (and its value).
fn without(base: &[&str], flag: &str) -> Vec<String> {
    let mut args: Vec<String> = base.iter().map(|s| s.to_string()).collect();
    if let Some(i) = args.iter().position(|a| a == flag) {
        args.drain(i..i + 2);
    }
    args
}

/// Cases setting `flag` to each of `values` in `base`.
fn cases(base: &[&str], flag: &str, values: &[&str]) -> Vec<Case> {
    values
        .iter()
        .map(|v| Case {
            args: with(base, flag, v),
            flag: flag.to_string(),
        })
        .collect()
}

fn case(args: Vec<String>, flag: &str) -> Case {
    Case {
        args,
        flag: flag.to_string(),
    }
}

/// Text that is not a finite number, for every numeric flag.
const NOT_A_NUMBER: &[&str] = &[
    "nan", "NaN", "-nan", "inf", "+inf", "-inf", "infinity", "1e309", "-1e400", "", " ", "abc", "1,5", "0x10", "1e",
    "--", "1..2", "one",
];

/// A scratch directory with a regular file, a directory, and a few bad tables.
struct Scratch {
    dir: PathBuf,
}

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("hardening-cli-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("a_dir")).unwrap();
        std::fs::write(dir.join("a_file"), b"not a directory").unwrap();
        std::fs::write(dir.join("empty.kft"), b"").unwrap();
        std::fs::write(dir.join("text.kft"), b"hello, I am not a table\n").unwrap();
        let good = ke_friction::Table::embedded_bytes();
        std::fs::write(dir.join("truncated.kft"), &good[..good.len() / 3]).unwrap();
        let mut flipped = good.to_vec();
        let mid = flipped.len() / 2;
        flipped[mid] ^= 0x01;
        std::fs::write(dir.join("flipped.kft"), &flipped).unwrap();
        let mut trailing = good.to_vec();
        trailing.push(0);
        std::fs::write(dir.join("trailing.kft"), &trailing).unwrap();
        Scratch { dir }
    }

    fn path(&self, name: &str) -> String {
        self.dir.join(name).display().to_string()
    }

    /// Table paths that must all be rejected.
    fn bad_tables(&self) -> Vec<String> {
        let mut v: Vec<String> = [
            "missing.kft",
            "a_dir",
            "a_file/x.kft",
            "a_file",
            "empty.kft",
            "text.kft",
            "truncated.kft",
            "flipped.kft",
            "trailing.kft",
        ]
        .iter()
        .map(|n| self.path(n))
        .collect();
        v.push(String::new());
        v
    }

    /// Output paths that cannot be written: under a regular file, under a
    /// missing directory, or an existing directory.
    fn bad_outputs(&self, ext: &str) -> Vec<String> {
        vec![
            self.path(&format!("a_file/out.{ext}")),
            self.path(&format!("no_such_dir/out.{ext}")),
            self.path(&format!("no_such_dir/deeper/out.{ext}")),
            self.path("a_dir"),
            format!("{}/", self.path("a_dir")),
            String::new(),
        ]
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

#[test]
fn eval_rejects_bad_input() {
    let base = &["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01"];
    let mut all = vec![];
    for flag in ["--psi", "--theta", "--beta", "--nu", "--eps-star", "--f-star"] {
        all.extend(cases(base, flag, NOT_A_NUMBER));
        all.extend(cases(base, flag, &["1e308", "-1e308", "-1"]));
    }
    all.extend(cases(base, "--psi", &["0", "-0", "1e-320", "1e-4", "2000", "8:0.5"]));
    all.extend(cases(base, "--theta", &["-1e-300", "2000", "0:1"]));
    all.extend(cases(base, "--beta", &["0", "0.019", "0.01927", "101"]));
    all.extend(cases(base, "--nu", &["0.5", "0.50001", "1", "-0.001"]));
    all.extend(cases(base, "--eps-star", &["0", "1e-12", "101"]));
    all.extend(cases(base, "--fit", &["", "bogus", "Consistent", "1"]));
    all.extend(cases(base, "--model", &["", "bogus", "KE", "2"]));
    // F*: one value or START:STOP:COUNT (logarithmic, so every point > 0).
    all.extend(cases(
        base,
        "--f-star",
        &[
            "0",
            "-0",
            "1e6",
            "0.1:1e-5:0",
            "1e-5:0.1:0",
            "1e-5:0.1:-1",
            "1e-5:0.1:1.5",
            "1e-5:0.1:1e9",
            "1e-5:0.1:2000000",
            "1e-5:0.1:",
            "0:0.1:5",
            "-1:0.1:5",
            "1e-5:0:5",
            "1e-5:nan:5",
            "1e-5:inf:5",
            "1e-5:1e308:3",
            "8:0.5",
            "1:2:3:4",
            "::",
            ":",
            "a:b:c",
        ],
    ));
    let h_base = &["eval", "--psi", "1", "--theta", "0.001", "--h-star", "1"];
    all.extend(cases(h_base, "--h-star", NOT_A_NUMBER));
    all.extend(cases(
        h_base,
        "--h-star",
        &[
            "1e308", "-1e308", "1e7", "-1e7", "0:1e7:3", "-1e7:0:3", "3:0:0", "0:3:0", "0:3:-1", "0:3:x", "0:3:",
            "0:3:1e9", "nan:3:5", "0:inf:5", "1:2", "1:2:3:4", "::",
        ],
    ));
    // Missing, conflicting, repeated and unknown flags.
    all.push(case(without(base, "--psi"), "--psi"));
    all.push(case(without(base, "--theta"), "--theta"));
    all.push(case(without(base, "--f-star"), "--f-star"));
    all.push(case(with(base, "--h-star", "1"), "--h-star"));
    all.push(case(
        with(
            &["eval", "--psi", "1", "--psi", "2", "--theta", "0"],
            "--f-star",
            "0.01",
        ),
        "--psi",
    ));
    all.push(case(with(base, "--bogus", "1"), "--bogus"));
    all.push(case(vec!["eval".into(), "--psi".into()], "--psi"));
    check_all(all);
}

#[test]
fn eval_accepts_a_descending_sweep() {
    // START:STOP:COUNT is a sweep, not an interval: descending is allowed.
    let r = run(
        &with(&["eval", "--psi", "1", "--theta", "0.001"], "--h-star", "3:0:4"),
        LIMIT,
    );
    assert_eq!(r.status, Some(0), "{}", r.stderr);
    assert_eq!(r.stdout.lines().count(), 2 + 4, "{}", r.stdout);
}

#[test]
fn build_rejects_bad_input_before_any_work() {
    let scratch = Scratch::new("build");
    let out = scratch.path("out.kft");
    // A build that would take tens of seconds: a bad option must be caught first.
    let base_owned: Vec<&str> = LONG_BUILD.iter().copied().chain(["--out", out.as_str()]).collect();
    let base = &base_owned[..];
    let mut all = vec![];
    // Ranges LO:HI.
    let range_junk = ["", "abc", "1", "1:2:3", ":", "0.5:", ":8", "a:b", "1,2"];
    all.extend(cases(
        base,
        "--psi",
        &[
            "nan:8",
            "0.5:nan",
            "inf:8",
            "-inf:8",
            "0.5:inf",
            "0.5:1e308",
            "1e308:1e308",
            "0:8",
            "-0:8",
            "-1:8",
            "-8:-1",
            "8:0.5",
            "1:1",
            "1e-320:1",
            "1e-4:1",
            "0.5:2000",
            "0.0011:1",
        ],
    ));
    all.extend(cases(base, "--psi", &range_junk));
    all.extend(cases(
        base,
        "--theta",
        &[
            "nan:0.01",
            "0:nan",
            "-1:0.01",
            "-1e-300:0.01",
            "0.01:0",
            "0:0",
            "0:1e308",
            "0:2000",
            "0:999.9",
            "0:inf",
        ],
    ));
    all.extend(cases(base, "--theta", &range_junk));
    all.extend(cases(
        base,
        "--f-star",
        &[
            "0:0.1",
            "-1:0.1",
            "0.1:1e-5",
            "0.1:0.1",
            "1e-5:1e308",
            "1e-5:1000",
            "1e-5:99.9",
            "1e-5:inf",
            "nan:0.1",
        ],
    ));
    all.extend(cases(base, "--f-star", &range_junk));
    all.extend(cases(
        base,
        "--nodes",
        &[
            "4,9,9",
            "9,4,9",
            "9,9,4",
            "0,9,9",
            "-1,9,9",
            "9,9",
            "9,9,9,9",
            "a,b,c",
            "",
            "5000,9,9",
            "4096,4096,4096",
            "1000,1000,9",
            "1e3,9,9",
            "9.5,9,9",
            "9,,9",
            "99999999999999999999,9,9",
        ],
    ));
    all.extend(cases(
        base,
        "--h-star",
        &[
            "3:0:5",
            "0:0:5",
            "0:4:1",
            "0:4:0",
            "0:4:-1",
            "nan:4:5",
            "0:inf:5",
            "-1e308:4:5",
            "0:1e308:5",
            "-1e7:4:5",
            "0:1e7:5",
            "0:4:1e9",
            "0:4:200000",
            "",
            "abc",
            "0:4",
            "0:4:5:6",
        ],
    ));
    all.extend(cases(base, "--ghosts", &["-1", "9", "100", "abc", "", "1e3", "1.5"]));
    for flag in ["--beta", "--nu", "--eps-star", "--tolerance"] {
        all.extend(cases(base, flag, NOT_A_NUMBER));
        all.extend(cases(base, flag, &["1e308", "-1e308", "-1"]));
    }
    all.extend(cases(base, "--beta", &["0", "0.019", "101"]));
    all.extend(cases(base, "--nu", &["0.5", "1"]));
    all.extend(cases(base, "--eps-star", &["0", "1e-12", "101"]));
    all.extend(cases(base, "--tolerance", &["0", "2"]));
    all.extend(cases(
        base,
        "--samples",
        &["0", "1", "-1", "1e9", "abc", "", "100000000", "2.5"],
    ));
    all.extend(cases(
        base,
        "--seed",
        &["-1", "abc", "", "1e308", "18446744073709551616"],
    ));
    all.extend(cases(base, "--precision", &["f16", "", "F32"]));
    all.extend(cases(base, "--fit", &["bogus", ""]));
    all.extend(cases(base, "--model", &["bogus", ""]));
    for o in scratch.bad_outputs("kft") {
        all.push(case(with(base, "--out", &o), "--out"));
    }
    all.push(case(with(base, "--bogus", "1"), "--bogus"));
    check_all(all);
    assert!(!Path::new(&out).exists(), "a rejected build wrote {out}");
}

#[test]
fn verify_rejects_bad_input() {
    let scratch = Scratch::new("verify");
    let base = &["verify", "--quiet", "--samples", "10"];
    let mut all = vec![];
    all.extend(cases(
        base,
        "--samples",
        &["0", "1", "-1", "abc", "", "1e9", "100000000", "nan", "2.5"],
    ));
    all.extend(cases(
        base,
        "--seed",
        &["-1", "abc", "", "1e308", "18446744073709551616", "nan"],
    ));
    for t in scratch.bad_tables() {
        all.push(case(with(base, "--table", &t), "--table"));
    }
    all.push(case(with(base, "--bogus", "1"), "--bogus"));
    check_all(all);
}

#[test]
fn lookup_rejects_bad_input() {
    let scratch = Scratch::new("lookup");
    let base = &["lookup", "--psi", "1", "--theta", "0.001", "--f-star", "0.01"];
    let mut all = vec![];
    for flag in ["--psi", "--theta", "--f-star"] {
        all.extend(cases(base, flag, NOT_A_NUMBER));
        all.extend(cases(base, flag, &["1e308", "-1e308", "-1", "100"]));
    }
    all.extend(cases(base, "--psi", &["1e-320"]));
    all.extend(cases(base, "--f-star", &["1e-320"]));
    // Outside the default table's domain ψ 0.5–8, θ 0–0.01, F* 1e-5–0.1.
    all.extend(cases(base, "--psi", &["0", "0.49999", "8.00001"]));
    all.extend(cases(base, "--theta", &["-1e-300", "0.0100001"]));
    all.extend(cases(base, "--f-star", &["0", "9.9999e-6", "0.100001"]));
    for t in scratch.bad_tables() {
        all.push(case(with(base, "--table", &t), "--table"));
    }
    all.push(case(without(base, "--psi"), "--psi"));
    all.push(case(without(base, "--f-star"), "--f-star"));
    all.push(case(with(base, "--bogus", "1"), "--bogus"));
    check_all(all);
}

#[test]
fn export_rejects_bad_input() {
    let scratch = Scratch::new("export");
    let npz = scratch.path("out.npz");
    let base = &["export", "--quiet", "--npz", npz.as_str()];
    let mut all = vec![];
    for t in scratch.bad_tables() {
        all.push(case(with(base, "--table", &t), "--table"));
    }
    for o in scratch.bad_outputs("npz") {
        all.push(case(with(base, "--npz", &o), "--npz"));
    }
    let npy_base = &["export", "--quiet", "--npy", "x"];
    for o in [
        scratch.path("a_file"),
        scratch.path("a_file/sub"),
        "/".to_string(),
        "..".to_string(),
        String::new(),
    ] {
        all.push(case(with(npy_base, "--npy", &o), "--npy"));
    }
    all.push(case(vec!["export".into(), "--quiet".into()], "--npz"));
    all.push(case(with(base, "--npy", &scratch.path("npy_dir")), "--npy"));
    all.push(case(with(base, "--bogus", "1"), "--bogus"));
    check_all(all);
    assert!(!Path::new(&npz).exists(), "a rejected export wrote {npz}");
}

/// `plot` and `validate` are covered only if this build has them.
fn has_subcommand(name: &str) -> bool {
    run(&[name.to_string(), "--help".to_string()], LIMIT).status == Some(0)
}

#[test]
fn plot_rejects_bad_input() {
    if !has_subcommand("plot") {
        eprintln!("kefric plot is not available: skipped");
        return;
    }
    let scratch = Scratch::new("plot");
    let png = scratch.path("out.png");
    let svg = scratch.path("out.svg");
    let mut all = vec![];
    let fig = &["plot", "fig3", "--out", png.as_str()];
    for o in scratch.bad_outputs("png") {
        all.push(case(with(fig, "--out", &o), "--out"));
    }
    all.push(case(with(fig, "--out", &scratch.path("out.txt")), "--out"));
    let curve = &["plot", "curve", "--psi", "1", "--theta", "0.001", "--out", svg.as_str()];
    for flag in ["--psi", "--theta", "--beta", "--nu", "--eps-star"] {
        all.extend(cases(curve, flag, NOT_A_NUMBER));
        all.extend(cases(curve, flag, &["1e308", "-1"]));
    }
    all.extend(cases(curve, "--psi", &["0"]));
    for t in scratch.bad_tables().into_iter().filter(|t| !t.is_empty()) {
        all.push(case(with(curve, "--table", &t), "--table"));
    }
    let map = &["plot", "table-error", "--out", svg.as_str()];
    all.extend(cases(map, "--theta", NOT_A_NUMBER));
    all.extend(cases(map, "--theta", &["1e308", "-1"]));
    for t in scratch.bad_tables() {
        all.push(case(with(map, "--table", &t), "--table"));
    }
    let every = &["plot", "all", "--out-dir", "x"];
    for o in [
        scratch.path("a_file"),
        scratch.path("a_file/x"),
        "/".to_string(),
        String::new(),
    ] {
        all.push(case(with(every, "--out-dir", &o), "--out-dir"));
    }
    check_all(all);
    assert!(!Path::new(&png).exists() && !Path::new(&svg).exists());
}

#[test]
fn validate_rejects_unknown_flags() {
    if !has_subcommand("validate") {
        eprintln!("kefric validate is not available: skipped");
        return;
    }
    check_all(vec![case(vec!["validate".into(), "--bogus".into()], "--bogus")]);
}
