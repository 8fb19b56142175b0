//! `kefric eval`: output formats, ranges and bad input.
use crate::support::{assert_stderr_has, kefric, stderr};

#[test]
fn eval_json_at_f_star_matches_model_md() {
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let v: serde_json::Value = serde_json::from_str(text.trim()).unwrap();
    for key in [
        "psi", "theta", "beta", "nu", "eps_star", "h_star", "d_star", "p_star", "fs_star", "q_star", "f_star", "mu",
    ] {
        assert!(v.get(key).is_some(), "key {key} missing in {text}");
    }
    assert_eq!(v["fit"], "consistent");
    assert_eq!(v["model"], "ke");
    // MODEL.md §7: h* = 1.4692414618, μ = 0.52521087083.
    assert!((v["h_star"].as_f64().unwrap() - 1.4692414618).abs() < 1e-10);
    assert!((v["mu"].as_f64().unwrap() / 0.52521087083 - 1.0).abs() < 1e-10);
    // Shortest round-trip form, still exact: the text parses back to the
    // very f64 the library computes.
    let raw = |key: &str| -> f64 {
        let at = text.find(&format!("\"{key}\":")).unwrap() + key.len() + 3;
        let end = text[at..].find([',', '}']).unwrap();
        text[at..at + end].parse().unwrap()
    };
    let model = ke_friction::Model::new(ke_friction::Params::new(1.0, 0.001)).unwrap();
    let c = model.at_f_star(0.01).unwrap();
    assert_eq!(raw("mu"), c.mu.unwrap());
    assert_eq!(raw("h_star"), c.h_star);
    assert_eq!(
        (v["psi"].as_f64(), v["theta"].as_f64()),
        (Some(1.0), Some(0.001)),
        "{text}"
    );
    assert!(
        text.trim_end().ends_with('}') && text.find("\"psi\"") < text.find("\"mu\""),
        "{text}"
    );
}

#[test]
fn text_output_uses_the_flags_spellings_and_warns_outside_the_papers_range() {
    let o = kefric(&[
        "eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01", "--model", "ceb",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.starts_with(
            "# psi = 1, theta = 0.001, beta = 0.04, nu = 0.3, eps_star = 0.004, fit = consistent, model = ceb\n"
        ),
        "{out}"
    );
    assert!(
        o.stderr.is_empty(),
        "no warning inside the paper's range: {}",
        stderr(&o)
    );
    // F* = 5, a pressure five times the hardness: refused (exit 2).
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--f-star", "5"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_stderr_has(&o, "f_star = 5 is out of range: must be <= 1");
    // F* = 0.5 (h* < 0): an answer, exit 0, one warning line a kind.
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.5"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 2, "{err}");
    assert!(
        err.starts_with("warning: F* = 0.5 is above the range the paper covers"),
        "{err}"
    );
    assert!(err.contains("\nwarning: h* = -"), "{err}");
    // A sweep warns once a kind, counting the points and naming the worst.
    let o = kefric(&[
        "eval",
        "--psi",
        "1",
        "--theta",
        "0.001",
        "--f-star",
        "0.02:0.8:3",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("warning: 2 of 3 results; the worst: F* = 0.8 is above"),
        "{err}"
    );
    // lookup warns where h* < 0 or F* > 0.1 too; the default table stops at 0.1.
    let o = kefric(&["lookup", "--psi", "8", "--theta", "0", "--f-star", "0.1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let h: f64 = String::from_utf8_lossy(&o.stdout)
        .lines()
        .find_map(|l| l.strip_prefix("h* = "))
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(stderr(&o).contains("warning:"), h < 0.0, "h* = {h}: {}", stderr(&o));
}

#[test]
fn eval_ranges_give_one_row_per_point() {
    let o = kefric(&["eval", "--psi", "2", "--theta", "0", "--h-star", "0:3:7", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows: Vec<serde_json::Value> = String::from_utf8(o.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 7);
    assert_eq!(rows[3]["h_star"].as_f64().unwrap(), 1.5);
    assert_eq!(rows[6]["fs_star"].as_f64().unwrap(), 0.0);
    let o = kefric(&[
        "eval",
        "--psi",
        "2",
        "--theta",
        "0",
        "--f-star",
        "1e-4:1e-2:3",
        "--json",
    ]);
    let f: Vec<f64> = String::from_utf8(o.stdout)
        .unwrap()
        .lines()
        .map(|l| {
            serde_json::from_str::<serde_json::Value>(l).unwrap()["f_star"]
                .as_f64()
                .unwrap()
        })
        .collect();
    assert_eq!(f.len(), 3);
    assert!((f[1] / 1e-3 - 1.0).abs() < 1e-12, "logarithmic midpoint: {f:?}");
}

#[test]
fn eval_prints_null_mu_where_f_star_is_not_positive() {
    let o = kefric(&["eval", "--psi", "0.5", "--theta", "0.01", "--h-star", "5", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["f_star"].as_f64().unwrap() <= 0.0);
    assert!(v["mu"].is_null());
    let table = kefric(&["eval", "--psi", "0.5", "--theta", "0.01", "--h-star", "5"]);
    assert!(String::from_utf8_lossy(&table.stdout).contains("undefined"));
}

#[test]
fn eval_rejects_bad_input_with_status_2_and_one_line_naming_the_flag() {
    let cases: &[(&[&str], &str)] = &[
        (&["--psi", "-1", "--theta", "0", "--h-star", "1"], "--psi"),
        (&["--psi", "nan", "--theta", "0", "--h-star", "1"], "--psi"),
        (&["--psi", "1", "--theta", "-0.1", "--h-star", "1"], "--theta"),
        (
            &["--psi", "1", "--theta", "0", "--beta", "0.01", "--h-star", "1"],
            "--beta",
        ),
        (&["--psi", "1", "--theta", "0", "--nu", "0.5", "--h-star", "1"], "--nu"),
        (
            &["--psi", "1", "--theta", "0", "--eps-star", "0", "--h-star", "1"],
            "--eps-star",
        ),
        (&["--psi", "1", "--theta", "0", "--h-star", "inf"], "--h-star"),
        (&["--psi", "1", "--theta", "0", "--h-star", "0:1:0"], "--h-star"),
        (&["--psi", "1", "--theta", "0", "--h-star", "0:1"], "--h-star"),
        (&["--psi", "1", "--theta", "0", "--f-star", "-1"], "--f-star"),
        (&["--psi", "1", "--theta", "0", "--f-star", "0:0.1:3"], "--f-star"),
        (&["--psi", "1", "--theta", "0", "--f-star", "1e300"], "--f-star"),
        (&["--psi", "1", "--theta", "0"], "--h-star"),
        (
            &["--psi", "1", "--theta", "0", "--h-star", "1", "--f-star", "1"],
            "--f-star",
        ),
        (&["--psi", "x", "--theta", "0", "--h-star", "1"], "--psi"),
        (
            &["--psi", "1", "--theta", "0", "--h-star", "1", "--fit", "bogus"],
            "--fit",
        ),
    ];
    for (args, flag) in cases {
        let mut all = vec!["eval"];
        all.extend_from_slice(args);
        let o = kefric(&all);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{all:?}: not one line: {err}");
        assert!(err.contains(flag), "{all:?}: message does not name {flag}: {err}");
        assert!(!err.contains("panicked"), "{all:?}: {err}");
    }
}

#[test]
fn a_solved_f_star_of_0_1_plus_rounding_is_inside_the_papers_range() {
    // F* = 0.1 solves to 0.10000000000000002 here, and h* > 0: no warning.
    let o = kefric(&["eval", "--psi", "2", "--theta", "0.003", "--f-star", "1e-5:0.1:9"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
}

#[test]
fn plot_curve_takes_an_f_star_range() {
    let tmp = crate::common::TempDir::new("curve-range");
    let out = tmp.arg("c.svg");
    let o = kefric(&[
        "plot", "curve", "--psi", "1", "--theta", "0.003", "--f-star", "1e-4:0.5", "--out", &out,
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(svg.contains("<svg"));
    // The range reaches beyond the paper's: warned, as eval warns.
    assert_stderr_has(&o, "the worst: F* = 0.5 is above the range the paper covers");
    let o = kefric(&[
        "plot", "curve", "--psi", "1", "--theta", "0.003", "--f-star", "1e-4:2", "--out", &out,
    ]);
    crate::support::assert_bad_input(&o, "must be <= 1");
    let o = kefric(&[
        "plot", "curve", "--psi", "1", "--theta", "0.003", "--f-star", "0.5:0.1", "--out", &out,
    ]);
    crate::support::assert_bad_input(&o, "--f-star");
}
