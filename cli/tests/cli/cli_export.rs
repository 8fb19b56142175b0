//! `kefric export`: the arrays written to .npz and .npy, and bad input.

use crate::common::TempDir;
use crate::support::{assert_bad_input, kefric, stderr};
use ke_friction::Table;
use ndarray::{Array0, Array1, Array3};
use ndarray_npy::{read_npy, NpzReader};
use std::path::Path;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

const NAMES: [&str; 22] = [
    "beta",
    "eps_star",
    "f_star",
    "grid_f_star",
    "grid_fs_star",
    "grid_h_star",
    "grid_mu",
    "grid_p_star",
    "grid_psi",
    "grid_q_star",
    "grid_theta",
    "h_star",
    "interpolant",
    "knots_f_star",
    "knots_psi",
    "knots_theta",
    "metadata",
    "mu",
    "nu",
    "psi",
    "spline_ln_mu",
    "theta",
];

#[test]
fn export_npz_and_npy_hold_the_table_and_its_grid() {
    let tmp = TempDir::new("ok");
    let npz = tmp.join("t.npz");
    let o = kefric(&["export", "--quiet", "--npz", s(&npz)]);
    assert!(o.status.success(), "{}", stderr(&o));
    // A missing directory is created, with its parents.
    let npy = tmp.join("out/arrays");
    let o = kefric(&["export", "--quiet", "--npy", s(&npy)]);
    assert!(o.status.success(), "{}", stderr(&o));
    // No temporary files are left behind.
    assert_eq!(tmp.names(""), ["out", "t.npz"]);
    let npy_names = tmp.names("out/arrays");
    let want: Vec<String> = NAMES.iter().map(|n| format!("{n}.npy")).collect();
    assert_eq!(npy_names, want);

    let mut z = NpzReader::new(std::fs::File::open(&npz).unwrap()).unwrap();
    let mut names = z.names().unwrap();
    names.sort();
    assert_eq!(names, NAMES);

    let table = Table::embedded();
    // The self-description: JSON bytes naming the model, fit and constants.
    let meta: Array1<u8> = z.by_name("metadata").unwrap();
    let meta: serde_json::Value = serde_json::from_slice(meta.as_slice().unwrap()).unwrap();
    assert_eq!(meta["model"], "ke");
    assert_eq!(meta["fit"], "consistent");
    assert_eq!(meta["tolerance"].as_f64(), Some(table.info().tolerance));
    assert_eq!(
        meta["accuracy"]["max_rel"].as_f64(),
        Some(table.info().accuracy.max_rel)
    );
    assert_eq!(
        meta["format_version"].as_u64(),
        Some(table.info().format_version.into())
    );
    // The table's record under the same names as `kefric info --json`.
    let o = kefric(&["info", "--json"]);
    let info: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(meta, info);
    let interpolant: Array1<u8> = z.by_name("interpolant").unwrap();
    let interpolant: serde_json::Value = serde_json::from_slice(interpolant.as_slice().unwrap()).unwrap();
    assert_eq!(interpolant["quantity"], "ln(mu)");
    let coords: Vec<&str> = (0..3)
        .map(|k| interpolant["axes"][k]["coordinate"].as_str().unwrap())
        .collect();
    assert_eq!(coords, ["ln(psi)", "sqrt(theta)", "ln(f_star)"]);
    let spline: Array3<f64> = z.by_name("spline_ln_mu").unwrap();
    let shape: Vec<usize> = table.axes().iter().map(|a| a.nodes + 2).collect();
    assert_eq!(spline.shape(), shape.as_slice());
    let d = table.domain();
    let spec = &table.info().build;
    let [np, nt, nf] = spec.nodes;
    let g = spec.ghosts;
    let (h_lo, h_hi, h_nodes) = spec.h_star;
    let psi: Array1<f64> = z.by_name("psi").unwrap();
    let theta: Array1<f64> = z.by_name("theta").unwrap();
    let f_star: Array1<f64> = z.by_name("f_star").unwrap();
    assert_eq!((psi.len(), theta.len(), f_star.len()), (np, nt, nf));
    // The nodes inside the domain, ends included exactly.
    assert_eq!((psi[0], psi[np - 1]), d.psi);
    assert_eq!((theta[0], theta[nt - 1]), d.theta);
    assert_eq!((f_star[0], f_star[nf - 1]), d.f_star);
    for (k, v) in [&psi, &theta, &f_star].into_iter().enumerate() {
        let offset = if k == 1 { 0 } else { g };
        for (i, &x) in v.iter().enumerate() {
            let node = table.axes()[k].value(i + offset);
            assert!((x - node).abs() <= 1e-14 * node, "axis {k} node {i}: {x} vs {node}");
        }
    }

    // mu and h_star are the table's lookups at the nodes, bit for bit.
    let mu: Array3<f64> = z.by_name("mu").unwrap();
    let h_star: Array3<f64> = z.by_name("h_star").unwrap();
    assert_eq!(mu.shape(), [np, nt, nf]);
    assert_eq!(h_star.shape(), [np, nt, nf]);
    for ((i, j, k), &m) in mu.indexed_iter() {
        let (p, t, f) = (psi[i], theta[j], f_star[k]);
        assert_eq!(m, table.mu(p, t, f).unwrap(), "mu at {i},{j},{k}");
        assert_eq!(h_star[[i, j, k]], table.h_star(p, t, f).unwrap());
    }

    // The integration grid: ghost nodes included, μ NaN exactly where F* ≤ 0.
    let grid_psi: Array1<f64> = z.by_name("grid_psi").unwrap();
    let grid_theta: Array1<f64> = z.by_name("grid_theta").unwrap();
    let grid_h: Array1<f64> = z.by_name("grid_h_star").unwrap();
    let shape = [np + 2 * g, nt + g, h_nodes];
    assert_eq!([grid_psi.len(), grid_theta.len(), grid_h.len()], shape);
    assert_eq!((grid_h[0], grid_h[shape[2] - 1]), (h_lo, h_hi));
    assert_eq!(grid_psi[g], d.psi.0);
    let grid_mu: Array3<f64> = z.by_name("grid_mu").unwrap();
    let grid_f: Array3<f64> = z.by_name("grid_f_star").unwrap();
    for name in ["grid_p_star", "grid_fs_star", "grid_q_star"] {
        let a: Array3<f64> = z.by_name(name).unwrap();
        assert_eq!(a.shape(), shape, "{name}");
        assert!(a.iter().all(|v| v.is_finite()), "{name}");
    }
    assert_eq!(grid_mu.shape(), shape);
    assert_eq!(grid_f.shape(), shape);
    for (m, f) in grid_mu.iter().zip(&grid_f) {
        assert_eq!(m.is_nan(), *f <= 0.0, "mu {m}, F* {f}");
    }
    assert!(grid_f.iter().any(|&f| f <= 0.0) && grid_f.iter().any(|&f| f > 0.0));
    // A grid node against the model.
    let (i, j, k) = (g + 5, 7, 60);
    let model = ke_friction::Model::new(ke_friction::Params::new(grid_psi[i], grid_theta[j])).unwrap();
    let c = model.at_h_star(grid_h[k]).unwrap();
    assert_eq!(grid_f[[i, j, k]], c.f_star);
    assert_eq!(grid_mu[[i, j, k]], c.mu.unwrap());

    // The model constants.
    for (name, want) in [
        ("beta", d.constants.beta),
        ("nu", d.constants.nu),
        ("eps_star", d.constants.eps_star),
    ] {
        let a: Array0<f64> = z.by_name(name).unwrap();
        assert_eq!(a.into_scalar(), want, "{name}");
    }

    // The .npy files hold the same arrays.
    let mu_npy: Array3<f64> = read_npy(npy.join("mu.npy")).unwrap();
    assert_eq!(mu_npy, mu);
    let grid_mu_npy: Array3<f64> = read_npy(npy.join("grid_mu.npy")).unwrap();
    assert!(grid_mu_npy
        .iter()
        .zip(&grid_mu)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
    let nu_npy: Array0<f64> = read_npy(npy.join("nu.npy")).unwrap();
    assert_eq!(nu_npy.into_scalar(), d.constants.nu);

    // Exporting again replaces the files; an explicit --table gives the same arrays.
    let table_file = tmp.join("default.kft");
    std::fs::write(&table_file, Table::embedded_bytes()).unwrap();
    let o = kefric(&["export", "--quiet", "--table", s(&table_file), "--npy", s(&npy)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(tmp.names("out/arrays"), want);
    let again: Array3<f64> = read_npy(npy.join("mu.npy")).unwrap();
    assert_eq!(again, mu);
}

#[test]
fn export_bad_input_exits_2_with_one_line() {
    let tmp = TempDir::new("bad");
    let npz = tmp.join("t.npz");
    let npz = s(&npz);

    let missing = tmp.join("missing.kft");
    let o = kefric(&["export", "--table", s(&missing), "--npz", npz]);
    assert_bad_input(&o, "--table");

    let mut bytes = Table::embedded_bytes().to_vec();
    let mid = bytes.len() / 2;
    bytes[mid] ^= 0x40;
    let corrupt = tmp.join("corrupt.kft");
    std::fs::write(&corrupt, &bytes).unwrap();
    let o = kefric(&["export", "--table", s(&corrupt), "--npz", npz]);
    assert_bad_input(&o, "--table");
    let truncated = tmp.join("truncated.kft");
    std::fs::write(&truncated, &Table::embedded_bytes()[..100]).unwrap();
    let o = kefric(&["export", "--table", s(&truncated), "--npz", npz]);
    assert_bad_input(&o, "--table");

    // A directory as --npz, a missing parent directory, a file as --npy.
    let o = kefric(&["export", "--npz", s(&tmp.0)]);
    assert_bad_input(&o, "--npz");
    let orphan = tmp.join("no/such/dir/t.npz");
    let o = kefric(&["export", "--npz", s(&orphan)]);
    assert_bad_input(&o, "--npz");
    let file = tmp.join("file");
    std::fs::write(&file, b"x").unwrap();
    let o = kefric(&["export", "--npy", s(&file)]);
    assert_bad_input(&o, "--npy");

    // Exactly one of --npz and --npy.
    let dir = tmp.join("d");
    let o = kefric(&["export", "--npz", npz, "--npy", s(&dir)]);
    assert_bad_input(&o, "--npz");
    let o = kefric(&["export"]);
    assert_bad_input(&o, "--npz");

    // Nothing was written.
    assert_eq!(tmp.names(""), ["corrupt.kft", "file", "truncated.kft"]);
}

#[test]
fn a_ceb_tables_export_says_so() {
    let tmp = TempDir::new("ceb");
    let table = tmp.join("ceb.kft");
    let mut args = crate::support::SMALL_BUILD.to_vec();
    args.extend(["--model", "ceb", "--fit", "as-printed", "--out", s(&table)]);
    let o = kefric(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let npz = tmp.join("ceb.npz");
    let o = kefric(&["export", "--quiet", "--table", s(&table), "--npz", s(&npz)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut z = NpzReader::new(std::fs::File::open(&npz).unwrap()).unwrap();
    let meta: Array1<u8> = z.by_name("metadata").unwrap();
    let meta: serde_json::Value = serde_json::from_slice(meta.as_slice().unwrap()).unwrap();
    assert_eq!(meta["model"], "ceb");
    assert_eq!(meta["fit"], "as-printed");
    assert_eq!(meta["tolerance"].as_f64(), Some(1.0));
}
