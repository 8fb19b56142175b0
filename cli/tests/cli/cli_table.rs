//! `kefric lookup`, `kefric verify` and `kefric build` on small inputs.
use crate::common::TempDir;
use crate::support::{kefric, SMALL_BUILD};

#[test]
fn lookup_json_gives_mu_and_its_slope_from_the_embedded_table() {
    let o = kefric(&["lookup", "--psi", "1", "--theta", "0.001", "--f-star", "0.01", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(|k| k.as_str()).collect();
    assert_eq!(keys, ["dmu_df_star", "f_star", "h_star", "mu", "psi", "theta"]);
    // MODEL.md §7: μ = 0.52521087083 at ψ = 1, θ = 0.001, F* = 0.01; the table is good to 1e-4.
    let mu = v["mu"].as_f64().unwrap();
    assert!((mu / 0.52521087083 - 1.0).abs() < 1e-4, "{mu}");
    let table = ke_friction::Table::embedded();
    let (m, s) = table.mu_with_slope(1.0, 0.001, 0.01).unwrap();
    assert_eq!(mu, m);
    assert_eq!(v["dmu_df_star"].as_f64().unwrap(), s);
    assert_eq!(v["h_star"].as_f64().unwrap(), table.h_star(1.0, 0.001, 0.01).unwrap());
    assert!(s < 0.0, "μ falls with F*");
}

#[test]
fn verify_passes_on_the_embedded_table_and_a_small_build_round_trips() {
    let o = kefric(&["verify", "--samples", "200", "--quiet"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("ok: within the table's tolerance"));
    // Where the f32 kernel runs, its deviation is reported (and small).
    let fast = out.lines().find(|l| l.starts_with("fast f32 kernel:"));
    assert_eq!(fast.is_some(), ke_friction::Table::embedded().fast_kernel(), "{out}");
    if let Some(line) = fast {
        let dev: f64 = line.split_whitespace().find_map(|w| w.parse().ok()).unwrap();
        assert!(dev > 0.0 && dev <= 3e-6, "{line}");
    }
    let dir = TempDir::new("cli-table");
    let path = dir.join("small.kft");
    let p = path.to_str().unwrap();
    let o = kefric(&[SMALL_BUILD, &["--out", p]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let t = ke_friction::Table::load(&path).unwrap();
    assert_eq!(t.info().build.nodes, [9, 9, 9]);
    assert!(t.info().accuracy.max_rel <= 0.5);
    let o = kefric(&["verify", "--table", p, "--samples", "200", "--quiet"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // A table that cannot meet a tolerance is not written, and says why (exit 1).
    let strict = dir.join("strict.kft");
    let o = kefric(&[
        "build",
        "--nodes",
        "9,9,9",
        "--samples",
        "200",
        "--tolerance",
        "1e-9",
        "--quiet",
        "--out",
        strict.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("misses its tolerance"));
    assert!(!strict.exists());
}
