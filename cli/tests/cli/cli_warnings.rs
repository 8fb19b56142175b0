//! The plausibility warnings and the domain error of F* > 1 (issue 37's
//! cases 1–4), loads in newtons and pascals, and the one number format.
use crate::cli_surface::{MATERIALS, MATERIAL_FLAGS};
use crate::common::TempDir;
use crate::support::{assert_stderr_has, kefric, stderr};
use ke_friction::topography::{write_x3p, StatsOptions, Surface, Topography};
use ke_friction::{Load, Model};
use serde_json::Value;

/// A map whose waves do not fit it (not periodic: its edges jump), dx = 1 µm.
fn rough(n: usize) -> Vec<f64> {
    (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            let w = (x * 0.31).sin()
                + (y * 0.23).cos()
                + 0.7 * (x * 0.17 - y * 0.29).sin()
                + 0.5 * (x * 0.41 + y * 0.37).cos();
            0.2e-6 * w
        })
        .collect()
}

/// A periodic map of the same kind: whole periods along x and y.
fn periodic(n: usize) -> Vec<f64> {
    let t = 2.0 * std::f64::consts::PI / n as f64;
    (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            let w = (6.0 * x * t).sin()
                + (5.0 * y * t).cos()
                + 0.7 * (3.0 * x * t - 7.0 * y * t).sin()
                + 0.5 * (9.0 * x * t + 8.0 * y * t).cos();
            0.2e-6 * w
        })
        .collect()
}

fn write(dir: &TempDir, name: &str, z: Vec<f64>, n: usize) -> String {
    let t = Topography::map(z, n, n, 1e-6, 1e-6).unwrap();
    write_x3p(&t, &dir.join(name), 'D').unwrap();
    dir.arg(name)
}

fn args<'a>(head: &[&'a str], tail: &[&'a str]) -> Vec<&'a str> {
    let mut all = head.to_vec();
    all.extend_from_slice(MATERIAL_FLAGS);
    all.extend_from_slice(tail);
    all
}

/// Case 1: a load far below the paper's range warns (F* and, on a small
/// area, too few asperities); a pressure above the hardness is refused
/// (exit 2) by `surface`, `eval` and `eval --surface`, not answered μ = 0.
#[test]
fn absurd_loads_warn_or_are_refused() {
    let dir = TempDir::new("warn-loads");
    let file = write(&dir, "rough.x3p", rough(128), 128);
    let o = kefric(&args(&["surface", &file], &["--force", "1e-6", "--area", "1e-4"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("warning: F* = 1e-11 is below the range the paper covers (1e-5 <= F* <= 0.1)"),
        "{err}"
    );
    assert!(err.contains("warning: about "), "{err}");
    assert!(
        err.contains("asperities are in contact on the nominal area (fewer than 10)"),
        "{err}"
    );
    // The JSON record carries them too, by kind.
    let o = kefric(&args(
        &["surface", &file],
        &["--force", "1e-6", "--area", "1e-4", "--json"],
    ));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let kinds: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["kind"].as_str().unwrap())
        .collect();
    assert!(
        kinds.contains(&"f_star_below_range") && kinds.contains(&"few_asperities"),
        "{kinds:?}"
    );
    assert_eq!(v["warnings"][0]["count"], 1);
    // 1e6 N on 1 cm² against 1 GPa: F* = 10.
    for cmd in [
        args(&["surface", &file], &["--force", "1e6", "--area", "1e-4"]),
        args(&["eval", "--surface", &file], &["--force", "1e6", "--area", "1e-4"]),
    ] {
        let o = kefric(&cmd);
        assert_eq!(o.status.code(), Some(2), "{cmd:?}: {}", stderr(&o));
        assert_stderr_has(&o, "f_star = 10 is out of range: must be <= 1");
        assert!(
            o.stdout.is_empty() || !String::from_utf8_lossy(&o.stdout).contains("mu "),
            "no answer"
        );
    }
    let o = kefric(&["eval", "--psi", "0.85", "--theta", "0.0013", "--f-star", "1e4"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_stderr_has(&o, "f_star = 10000 is out of range: must be <= 1");
    // μ > 1 at a light load: adhesion-dominated, said so.
    let o = kefric(&["eval", "--psi", "0.85", "--theta", "0.0013", "--f-star", "1e-7"]);
    assert!(o.status.success());
    assert_stderr_has(&o, "> 1 at F* = 1e-7: adhesion dominates");
}

/// Case 2: `plot surface` gives the warnings `surface` gives for the same
/// file and flags.
#[test]
fn plot_surface_warns_as_surface_does() {
    let dir = TempDir::new("warn-plot");
    let file = write(&dir, "rough.x3p", rough(128), 128);
    let out = dir.arg("s.png");
    let flags = ["--derivative", "spectral"];
    let s = kefric(&args(&["surface", &file], &flags));
    let mut plot = args(&["plot", "surface", &file], &flags);
    plot.extend(["--out", &out]);
    let p = kefric(&plot);
    assert!(s.status.success() && p.status.success(), "{}", stderr(&p));
    let warnings = |o: &std::process::Output| -> Vec<String> {
        stderr(o)
            .lines()
            .filter(|l| l.starts_with("warning:"))
            .map(String::from)
            .collect()
    };
    assert!(!warnings(&s).is_empty());
    for w in warnings(&s) {
        assert!(warnings(&p).contains(&w), "plot misses {w}: {:?}", warnings(&p));
    }
}

/// Case 3: spectral derivatives on a map that is not periodic warn; on a
/// periodic map they do not (and agree with finite differences there
/// better than on the non-periodic one).
#[test]
fn spectral_derivatives_warn_on_a_non_periodic_map() {
    let dir = TempDir::new("warn-spectral");
    let n = 128;
    let kinds = |file: &str, derivative: &str| -> (Vec<String>, f64) {
        let o = kefric(&["surface", file, "--derivative", derivative, "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        let k = v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["kind"].as_str().unwrap().to_string())
            .collect();
        (k, v["surface"]["m4"].as_f64().unwrap())
    };
    let rough = write(&dir, "rough.x3p", rough(n), n);
    let (k, m4_spectral) = kinds(&rough, "spectral");
    assert!(k.contains(&"non_periodic".to_string()), "{k:?}");
    let (k, m4_fd) = kinds(&rough, "fd");
    assert!(!k.contains(&"non_periodic".to_string()), "{k:?}");
    assert!(
        m4_spectral / m4_fd > 2.0,
        "the edge jump inflates m4: {m4_spectral} vs {m4_fd}"
    );
    let periodic = write(&dir, "periodic.x3p", periodic(n), n);
    let (k, _) = kinds(&periodic, "spectral");
    assert!(!k.contains(&"non_periodic".to_string()), "{k:?}");
    let o = kefric(&["surface", &rough, "--derivative", "spectral"]);
    assert_stderr_has(&o, "warning: derivative = spectral on a surface that is not periodic");
}

/// Case 4: loads in newtons and pascals: `surface --force START:STOP:COUNT`
/// (log-spaced), `--pressure` ranges, `eval --surface --force`, each row
/// the library's μ at that load; `plot surface --force` draws.
#[test]
fn force_and_pressure_ranges_give_one_row_a_load() {
    let dir = TempDir::new("warn-ranges");
    let file = write(&dir, "rough.x3p", rough(128), 128);
    let o = kefric(&args(
        &["surface", &file],
        &["--force", "0.1:100:7", "--area", "1e-5", "--json"],
    ));
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["friction"].as_array().unwrap();
    assert_eq!(rows.len(), 7);
    // The library's μ at each load (log-spaced: 0.1, 0.316…, …, 100 N).
    let t = Topography::map(rough(128), 128, 128, 1e-6, 1e-6).unwrap();
    let surface = Surface::new(t, StatsOptions::default()).unwrap();
    let model = Model::new(surface.params(&MATERIALS, surface.distribution(None).unwrap()).unwrap()).unwrap();
    for (k, row) in rows.iter().enumerate() {
        let force = 0.1 * 1000f64.powf(k as f64 / 6.0);
        assert!((row["force"].as_f64().unwrap() / force - 1.0).abs() < 1e-12, "{row}");
        let load = Load::Force {
            force: row["force"].as_f64().unwrap(),
            area: 1e-5,
        };
        let f = load.friction(&model, &surface.physical(&MATERIALS)).unwrap();
        assert_eq!(row["mu"].as_f64(), Some(f.mu), "{row}");
        assert!(
            (row["f_star"].as_f64().unwrap() / (force / 1e-5 / 1e9) - 1.0).abs() < 1e-9,
            "{row}"
        );
    }
    // One load in text: the single-load block; a range: a table of rows.
    let o = kefric(&args(&["surface", &file], &["--pressure", "1e4:1e6:3"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("p (Pa)"), "{text}");
    assert_eq!(
        text.lines().filter(|l| l.trim_start().starts_with("10000 ")).count(),
        1,
        "{text}"
    );
    // eval --surface with a force range: the same μ as surface's rows.
    let o = kefric(&args(
        &["eval", "--surface", &file],
        &["--force", "0.1:100:7", "--area", "1e-5", "--json"],
    ));
    assert!(o.status.success(), "{}", stderr(&o));
    let eval_rows: Vec<Value> = String::from_utf8_lossy(&o.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(eval_rows.len(), 7);
    for (a, b) in eval_rows.iter().zip(rows) {
        assert_eq!(a["mu"], b["mu"]);
    }
    // Dimensionless inputs have no hardness: a load in newtons is refused.
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--force", "1", "--area", "1"]);
    assert_eq!(o.status.code(), Some(2));
    assert_stderr_has(&o, "--force: a load in SI units needs the hardness");
    let out = dir.arg("n.png");
    let o = kefric(&args(
        &["plot", "surface", &file],
        &["--force", "0.1:100:7", "--area", "1e-5", "--out", &out],
    ));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::metadata(dir.join("n.png")).unwrap().len() > 1000);
    // One load: the default F* range in newtons, widened to hold it
    // (issue 49: it was refused), the load marked on the curves.
    let svg = dir.arg("one.svg");
    let o = kefric(&args(
        &["plot", "surface", &file],
        &["--force", "10", "--area", "1e-5", "--out", &svg],
    ));
    assert!(o.status.success(), "{}", stderr(&o));
    let drawn = std::fs::read_to_string(dir.join("one.svg")).unwrap();
    assert!(drawn.contains("the load: F (N) = 10"), "the load is not marked");
    let o = kefric(&args(
        &["plot", "surface", &file],
        &["--force", "10:1:3", "--area", "1e-5", "--out", &out],
    ));
    assert_eq!(o.status.code(), Some(2));
    assert_stderr_has(&o, "--force: the plot needs a range");
    // 10 N on 1e-5 m² is 1e6 Pa in the record, as --pressure 1e6 (not
    // 999999.9999999999), and gives the same μ.
    let o = kefric(&args(
        &["surface", &file],
        &["--force", "10", "--area", "1e-5", "--json"],
    ));
    let text = String::from_utf8_lossy(&o.stdout).to_string();
    assert!(text.contains("\"pressure\":1000000.0"), "{text}");
    let by_force: Value = serde_json::from_str(&text).unwrap();
    let o = kefric(&args(&["surface", &file], &["--pressure", "1e6", "--json"]));
    let by_pressure: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(by_force["friction"]["mu"], by_pressure["friction"]["mu"]);
}

/// A plot's warnings count every load drawn of every fit (60 loads × the
/// fits), not the range's two ends (issue 49: "2 of 2 results").
#[test]
fn plot_warnings_count_the_loads_drawn() {
    let dir = TempDir::new("warn-plot-count");
    let file = write(&dir, "rough.x3p", rough(128), 128);
    let out = dir.arg("s.png");
    let o = kefric(&args(
        &["plot", "surface", &file],
        &["--f-star", "1e-7:0.1", "--out", &out],
    ));
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let fits = 3 - err.matches("note: no ").count();
    let total = format!("of {} results", fits * ke_friction::figures::DISTRIBUTIONS_LOADS);
    let counted: Vec<&str> = err.lines().filter(|l| l.contains(" results; the worst")).collect();
    assert!(!counted.is_empty(), "{err}");
    for line in counted {
        assert!(line.contains(&total), "{line}: not {total}");
    }
}

/// One number format: 6 significant digits in text (`eval`'s μ is
/// `0.525211`, not `5.25211e-1`), every digit in JSON.
#[test]
fn text_has_six_significant_digits_and_json_every_digit() {
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01"]);
    let text = String::from_utf8_lossy(&o.stdout);
    let row = text.lines().last().unwrap();
    assert_eq!(row.split_whitespace().last(), Some("0.525211"), "{text}");
    assert!(!row.contains("e-1") && !row.contains("e0"), "{row}");
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01", "--json"]);
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let mu = v["mu"].as_f64().unwrap();
    let exact = Model::new(ke_friction::Params::new(1.0, 0.001))
        .unwrap()
        .at_f_star(0.01)
        .unwrap()
        .mu
        .unwrap();
    assert_eq!(mu, exact);
}

/// Steel on steel ([`crate::cli_tools::SI`] without the roughness, which
/// the surface gives) and a contact area.
fn steel() -> Vec<&'static str> {
    let roughness = ["--sigma", "--radius", "--density"];
    let mut args: Vec<&str> = crate::cli_tools::SI
        .chunks(2)
        .filter(|pair| !roughness.contains(&pair[0]))
        .flatten()
        .copied()
        .collect();
    args.extend(["--area", "1e-5"]);
    args
}

/// Issue 48: the validity domain on di-1, spikes on sur-2 (whose default
/// is the empirical density: Pearson refuses its skewness), the tail of
/// plu-1's Pearson density at 0.01 N; on stderr and in --json.
#[test]
fn validity_spikes_and_tail_warnings_on_the_instruments_files() {
    let instrument = |name| crate::common::instrument_file(name).map(|p| p.display().to_string());
    let run = |file: &str, extra: &[&str]| {
        let mut args = vec!["surface", file];
        args.extend(steel());
        args.extend(extra);
        let o = crate::support::kefric(&args);
        assert!(o.status.success(), "{args:?}: {}", crate::support::stderr(&o));
        crate::support::stderr(&o)
    };
    if let Some(f) = instrument("di-1.di") {
        let err = run(&f, &["--force", "1"]);
        assert!(err.contains("warning: psi = 209."), "{err}");
        assert!(err.contains("warning: beta = 0.548"), "{err}");
    }
    if let Some(f) = instrument("sur-2.sur") {
        let err = run(&f, &["--force", "1"]);
        assert!(err.contains("warning: the heights have spikes: kurtosis 811"), "{err}");
    }
    if let Some(f) = instrument("plu-1.plu") {
        let err = run(&f, &["--force", "0.01", "--distribution", "pearson"]);
        assert!(
            err.contains("the contact lies on an extrapolated tail: h* = 16.09"),
            "{err}"
        );
        assert!(err.contains("0 measured points above the separation"), "{err}");
        let mut args = vec![
            "surface",
            f.as_str(),
            "--json",
            "--force",
            "0.01",
            "--distribution",
            "pearson",
        ];
        args.extend(steel());
        let o = crate::support::kefric(&args);
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let tail = v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .find(|w| w["kind"] == "tail")
            .unwrap();
        assert_eq!(tail["above"], 0);
        assert!(tail["max_height"].as_f64().unwrap() < 4.0);
        // The default (empirical here) has measured heights above its contact.
        let err = run(&f, &["--force", "0.01"]);
        assert!(!err.contains("extrapolated tail"), "{err}");
    }
}

/// `law --surface` reads the surface once: its anisotropy warning is
/// printed once (issue 49: twice).
#[test]
fn law_of_a_surface_warns_once() {
    let dir = TempDir::new("warn-law");
    let n = 128;
    // Rougher along x than along y: m20/m02 far outside the isotropy band.
    let z: Vec<f64> = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            0.2e-6 * ((x * 0.31).sin() + 0.7 * (x * 0.53).cos() + 0.2 * (y * 0.07).sin())
        })
        .collect();
    let file = write(&dir, "aniso.x3p", z, n);
    let o = kefric(&args(&["law", "--surface", &file], &["--pressure", "1e5:1e7"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(err.matches("anisotrop").count(), 1, "{err}");
}
