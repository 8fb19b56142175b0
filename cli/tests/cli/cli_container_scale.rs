//! `kefric surface CONTAINER --scale-dependent` (issue 50): the combined
//! scale-dependent rms slope and curvature equal to SurfaceTopography's
//! container `scale_dependent_statistical_property` (the reference of
//! tools/container_check.py in tests/data/container/), nonuniform
//! profiles included.

use crate::support::{bad_input_problem, kefric, stderr};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/container");

#[test]
fn container_scale_dependent_json_and_csv_match_surface_topography() {
    let zip = format!("{DATA}/synthetic.zip");
    let o = kefric(&["surface", &zip, "--scale-dependent", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let text = std::fs::read_to_string(format!("{DATA}/synthetic.json")).unwrap();
    let r: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut lengths = std::collections::BTreeSet::new();
    for kind in ["slope", "curvature"] {
        let c = &doc["combined"][kind];
        let (d, rms) = (c["distance"].as_array().unwrap(), c["rms"].as_array().unwrap());
        let (rd, rv) = (r[kind]["d"].as_array().unwrap(), r[kind]["v"].as_array().unwrap());
        assert_eq!(d.len(), rd.len(), "{kind}");
        for k in 0..d.len() {
            let (d, rd) = (d[k].as_f64().unwrap(), rd[k].as_f64().unwrap());
            assert!((d / rd - 1.0).abs() <= 1e-9, "{kind} distance {k}");
            lengths.insert(format!("{:.6e}", d));
            match (rms[k].as_f64(), rv[k].as_f64()) {
                (Some(v), Some(want)) => assert!((v * v / want - 1.0).abs() <= 1e-9, "{kind} at {d}: {v}² vs {want}"),
                (None, None) => {}
                (got, want) => panic!("{kind} at {d}: {got:?} vs {want:?}"),
            }
        }
        // Each length names the measurements it rests on.
        assert!(c["rests_on"].as_array().unwrap().iter().all(|r| r.is_array()));
    }
    // The nonuniform profile (the third) has its own curve and takes part.
    let ms = doc["measurements"].as_array().unwrap();
    assert_eq!(ms.len(), 3);
    assert!(!ms[2]["slope"]["distance"].as_array().unwrap().is_empty());
    assert!(ms[2]["scale_cutoff"].as_f64().is_some(), "its tip radius cuts it");
    let name = ms[2]["name"].as_str().unwrap();
    let rests = doc["combined"]["slope"]["rests_on"].as_array().unwrap();
    assert!(rests.iter().any(|r| r.as_array().unwrap().iter().any(|n| n == name)));
    // CSV: a header, then one row a length of either grid.
    let o = kefric(&["surface", &zip, "--scale-dependent", "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let mut lines = out.lines();
    assert_eq!(
        lines.next(),
        Some("distance,rms_slope,rms_curvature,slope_from,curvature_from")
    );
    assert_eq!(lines.count(), lengths.len());
}

#[test]
fn container_scale_dependent_refuses_a_band() {
    let zip = format!("{DATA}/synthetic.zip");
    let o = kefric(&["surface", &zip, "--scale-dependent", "--lambda-c", "1e-6"]);
    let why = bad_input_problem(
        o.status.code(),
        &String::from_utf8_lossy(&o.stdout),
        &stderr(&o),
        "--lambda-c",
    );
    assert!(why.is_none(), "{why:?}");
}

/// A container SurfaceTopography wrote (its measurements `squeezed-netcdf`
/// NetCDF-3 files only): `--psd` and `--scale-dependent` as
/// SurfaceTopography reads it back.
#[test]
fn squeezed_netcdf_container_reads_in_the_cli() {
    let zip = format!("{DATA}/squeezed.zip");
    let text = std::fs::read_to_string(format!("{DATA}/squeezed.json")).unwrap();
    let r: serde_json::Value = serde_json::from_str(&text).unwrap();
    let o = kefric(&["surface", &zip, "--psd", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let ms = doc["measurements"].as_array().unwrap();
    assert_eq!(ms.len(), 2);
    assert!(ms.iter().all(|m| m["file"].as_str().unwrap().ends_with(".nc")));
    let (c, rc) = (
        doc["combined"]["c"].as_array().unwrap(),
        r["combined"]["c"].as_array().unwrap(),
    );
    assert_eq!(c.len(), rc.len());
    for (a, b) in c.iter().zip(rc) {
        assert!((a.as_f64().unwrap() / b.as_f64().unwrap() - 1.0).abs() <= 1e-9);
    }
    let o = kefric(&["surface", &zip, "--scale-dependent", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let d = doc["combined"]["slope"]["distance"].as_array().unwrap();
    assert_eq!(d.len(), r["slope"]["d"].as_array().unwrap().len());
}
