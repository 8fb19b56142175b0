//! Issue 46's numerics through `kefric`: an unbounded scan, an empty
//! filter band, scale-dependent statistics of too few points, the Weibull
//! density at Sk = 2, negative numbers as flag values.
use crate::common::TempDir;
use crate::support::{assert_bad_input, kefric, stderr};

/// A 64² .npy map (and a 1×4096 one), dx = 1 µm.
fn maps(dir: &TempDir) -> (String, String) {
    let write = |name: &str, shape: &[usize], z: Vec<f64>| {
        let bytes: Vec<u8> = z.iter().flat_map(|v| v.to_le_bytes()).collect();
        std::fs::write(dir.join(name), crate::npy::npy("<f8", false, shape, &bytes)).unwrap();
        dir.arg(name)
    };
    let n = 64;
    let z = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            1e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin() + (x * 0.13 - y * 0.41).cos())
        })
        .collect();
    let row = (0..4096).map(|i| 1e-7 * (i as f64 * 0.1).sin()).collect();
    (write("map.npy", &[n, n], z), write("row.npy", &[1, 4096], row))
}

#[test]
fn an_unbounded_scan_is_refused_naming_from_and_to() {
    let dir = TempDir::new("h46-scan");
    let (map, _) = maps(&dir);
    for (from, to) in [("1e-300", "1e300"), ("4.9e-324", "1e-5")] {
        let o = kefric(&["surface", &map, "--dx", "1e-6", "--scan", "--from", from, "--to", to]);
        assert_bad_input(&o, "--from/--to");
        assert!(stderr(&o).contains("decades"), "{}", stderr(&o));
    }
}

#[test]
fn an_l_filter_not_longer_than_the_s_filter_is_refused() {
    let dir = TempDir::new("h46-band");
    let (map, _) = maps(&dir);
    let o = kefric(&[
        "surface",
        &map,
        "--dx",
        "1e-6",
        "--lambda-s",
        "1e-5",
        "--lambda-c",
        "5e-6",
    ]);
    assert_bad_input(&o, "lambda_c = 5e-6 m with lambda_s = 1e-5 m is out of range");
}

#[test]
fn scale_dependent_statistics_of_too_few_points_are_refused() {
    let dir = TempDir::new("h46-scale");
    let (_, row) = maps(&dir);
    let o = kefric(&["surface", &row, "--dx", "1e-6", "--scale-dependent"]);
    assert_bad_input(&o, "ny = 1 is out of range: at least 5 points");
    std::fs::write(dir.join("short.txt"), "1e-7\n2e-7\n-1e-7\n").unwrap();
    let o = kefric(&["surface", &dir.arg("short.txt"), "--dx", "1e-6", "--scale-dependent"]);
    assert_bad_input(&o, "nx = 3 is out of range: at least 5 points");
}

/// F* at h* = 5.77 of the exponential heights (Weibull Sk = 2):
/// tools/nongaussian_reference.py's -0.019703042447467716 (it was NaN),
/// and the same as at Sk = 1.9999999 to the printed digits.
#[test]
fn weibull_at_skewness_two_is_finite() {
    let run = |sk: &str| {
        let o = kefric(&[
            "eval",
            "--psi",
            "1",
            "--theta",
            "10",
            "--distribution",
            "weibull",
            "--skewness",
            sk,
            "--h-star",
            "5.77",
            "--json",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        String::from_utf8(o.stdout).unwrap()
    };
    let at_two = run("2");
    assert!(!at_two.contains("NaN"), "{at_two}");
    let v: serde_json::Value = serde_json::from_str(at_two.lines().next().unwrap()).unwrap();
    let f = v
        .pointer("/f_star")
        .or_else(|| v.pointer("/0/f_star"))
        .and_then(|f| f.as_f64());
    let f = f.unwrap_or_else(|| panic!("no f_star in {at_two}"));
    assert!((f / -0.019703042447467716 - 1.0).abs() < 1e-9, "{f}");
}

#[test]
fn negative_numbers_are_flag_values() {
    for args in [
        &[
            "eval",
            "--psi",
            "1",
            "--theta",
            "10",
            "--distribution",
            "weibull",
            "--skewness",
            "-1",
            "--h-star",
            "1",
        ][..],
        &["eval", "--psi", "1", "--theta", "10", "--h-star", "-0.5"][..],
    ] {
        let o = kefric(args);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("unexpected argument"), "{}", stderr(&o));
    }
    // A negative value out of range is the flag's own error.
    let o = kefric(&["eval", "--psi", "-1", "--theta", "10", "--h-star", "1"]);
    assert_bad_input(&o, "--psi");
}

/// A Pearson density near its bound (K = Sk² + 1.01) makes μ(F*) jump:
/// the law fails at the first cell count whose 40 halvings miss by more
/// than finer cells could mend (16 cells per octave), saying where, not
/// after every finer build (it took 4.7 s, release).
#[test]
fn a_law_whose_mu_jumps_fails_at_the_first_cell_count() {
    let o = kefric(&[
        "law",
        "--psi",
        "1",
        "--theta",
        "1e-3",
        "--hardness",
        "1e9",
        "--pressure",
        "1e5:1e7",
        "--distribution",
        "pearson",
        "--skewness",
        "5",
        "--kurtosis",
        "26.01",
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("--pressure") && err.contains("at F* = 0.00146"), "{err}");
    assert!(
        err.contains("with 16 cells per octave") && err.contains("jumps"),
        "{err}"
    );
}
