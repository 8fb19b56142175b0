//! `kefric eval`: output formats, ranges and bad input.
use crate::support::{kefric, stderr};

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
    // MODEL.md §7: h* = 1.4692414618, μ = 0.52521087083.
    assert!((v["h_star"].as_f64().unwrap() - 1.4692414618).abs() < 1e-10);
    assert!((v["mu"].as_f64().unwrap() / 0.52521087083 - 1.0).abs() < 1e-10);
    // 17 significant digits.
    assert!(text.contains("\"mu\":5.252108708"), "{text}");
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
