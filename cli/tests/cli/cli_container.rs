//! `kefric surface CONTAINER --psd` (issue 50): each measurement's
//! spectrum and the combined one, equal to SurfaceTopography's (the
//! reference of tools/container_check.py in tests/data/container/).

use crate::support::{bad_input_problem, kefric, stderr};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/container");

#[test]
fn container_psd_json_carries_the_combined_spectrum() {
    let zip = format!("{DATA}/synthetic.zip");
    let o = kefric(&["surface", &zip, "--psd", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let ms = doc["measurements"].as_array().unwrap();
    assert_eq!(ms.len(), 3);
    assert_eq!(ms[0]["ny"], 1);
    assert_eq!((ms[1]["nx"].as_u64(), ms[1]["ny"].as_u64()), (Some(64), Some(64)));
    let text = std::fs::read_to_string(format!("{DATA}/synthetic.json")).unwrap();
    let r: serde_json::Value = serde_json::from_str(&text).unwrap();
    let (q, c) = (
        doc["combined"]["q"].as_array().unwrap(),
        doc["combined"]["c"].as_array().unwrap(),
    );
    let (rq, rc) = (
        r["combined"]["q"].as_array().unwrap(),
        r["combined"]["c"].as_array().unwrap(),
    );
    assert_eq!(q.len(), rq.len());
    for k in 0..q.len() {
        let rel =
            |a: &serde_json::Value, b: &serde_json::Value| (a.as_f64().unwrap() / b.as_f64().unwrap() - 1.0).abs();
        assert!(rel(&q[k], &rq[k]) <= 1e-9 && rel(&c[k], &rc[k]) <= 1e-9, "bin {k}");
    }
    // CSV: one row a point, the combined ones last.
    let o = kefric(&["surface", &zip, "--psd", "--csv"]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.starts_with("measurement,q,c\n"));
    assert_eq!(out.lines().filter(|l| l.starts_with("combined,")).count(), rq.len());
}

#[test]
fn container_psd_rejects_a_bad_tip_radius_and_a_bad_container() {
    let zip = format!("{DATA}/synthetic.zip");
    let o = kefric(&["surface", &zip, "--psd", "--tip-radius", "0"]);
    let why = bad_input_problem(
        o.status.code(),
        &String::from_utf8_lossy(&o.stdout),
        &stderr(&o),
        "--tip-radius",
    );
    assert!(why.is_none(), "{why:?}");
    // A container whose data file is missing: exit 2, one line naming it.
    let dir = std::env::temp_dir().join(format!("kefric-container-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("missing.zip");
    {
        use std::io::Write;
        let mut w = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
        w.start_file("meta.yml", zip::write::SimpleFileOptions::default())
            .unwrap();
        w.write_all(b"surfaces:\n- topographies:\n  - datafile: {original: gone.txt}\n    unit: nm\n")
            .unwrap();
        w.finish().unwrap();
    }
    let o = kefric(&["surface", path.to_str().unwrap(), "--psd"]);
    let why = bad_input_problem(
        o.status.code(),
        &String::from_utf8_lossy(&o.stdout),
        &stderr(&o),
        "gone.txt",
    );
    assert!(why.is_none(), "{why:?}");
    std::fs::remove_dir_all(&dir).ok();
}

use crate::cli_surface::MATERIAL_FLAGS as MATERIALS;

fn args<'a>(zip: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut a = vec!["surface", zip];
    a.extend(MATERIALS);
    a.extend(extra);
    a
}

/// `surface CONTAINER` with materials and a load: μ from the whole band,
/// equal to the library's `container_analysis` (same record), with the
/// measurements' list, the combined moments and roughness, the model and
/// the friction; the text names μ and the band.
#[test]
fn container_mu_json_and_text() {
    use ke_friction::topography::container::{
        container_analysis, measurement_spectra, read_container, ContainerOptions, COMBINED_POINTS_PER_DECADE,
    };
    use ke_friction::topography::SurfaceModel;
    use ke_friction::{Load, Materials};
    let zip = format!("{DATA}/uniform.zip");
    let o = kefric(&args(&zip, &["--pressure", "1e6", "--json"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let s = read_container(zip.as_ref(), &ContainerOptions::default()).unwrap();
    let ms = &s[0].measurements;
    let spectra = measurement_spectra(ms);
    let materials = Materials::from_array([70e9, 0.33, 200e9, 0.31, 1e9, 0.5, 0.4e-9]);
    let a = container_analysis(
        ms,
        &spectra,
        None,
        COMBINED_POINTS_PER_DECADE,
        &SurfaceModel::new(materials),
        &[Load::Pressure(1e6)],
    )
    .unwrap();
    assert_eq!(doc["friction"][0]["mu"].as_f64(), Some(a.frictions[0].mu));
    assert_eq!(doc["combined"]["moments"]["m2"].as_f64(), Some(a.moments.m2));
    assert_eq!(doc["combined"]["roughness"]["beta"].as_f64(), Some(a.roughness.beta));
    assert_eq!(doc["combined"]["band"]["lambda_c"].as_f64(), Some(a.band.lambda_c));
    assert_eq!(doc["measurements"].as_array().unwrap().len(), ms.len());
    for m in doc["measurements"].as_array().unwrap() {
        for key in ["file", "name", "unit", "nx", "ny", "dx", "size", "reliable"] {
            assert!(m.get(key).is_some(), "{key}");
        }
    }
    assert_eq!(doc["combined"]["rests_on"].as_array().unwrap().len(), ms.len());
    assert!(doc["model"]["psi"].as_f64().unwrap() > 0.0);
    let o = kefric(&args(&zip, &["--pressure", "1e6"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains(&format!("mu {}", ke_friction::Shortest::sig(a.frictions[0].mu))),
        "{text}"
    );
    assert!(text.contains("band: λs"));
}

/// `surface CONTAINER --scan`: rows from the smallest reliable scale, each
/// naming its measurements (CSV and JSON agree), the spread where two or
/// more overlap.
#[test]
fn container_scan_rows_name_their_measurements() {
    let zip = format!("{DATA}/uniform.zip");
    let o = kefric(&args(&zip, &["--pressure", "1e6", "--scan", "--json"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = doc["rows"].as_array().unwrap();
    assert!(rows.len() > 2);
    let smallest = doc["measurements"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|m| m["reliable"]["lambda_min"].as_f64())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(rows[0]["lambda_s"].as_f64(), Some(smallest));
    assert!(rows.iter().all(|r| !r["measurements"].as_array().unwrap().is_empty()));
    assert!(rows
        .iter()
        .any(|r| r["spread"].is_array() && r["measurements"].as_array().unwrap().len() >= 2));
    let o = kefric(&args(&zip, &["--pressure", "1e6", "--scan", "--csv"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let mut lines = out.lines();
    assert!(lines.next().unwrap().starts_with("lambda_s,lambda_c,measurements,"));
    assert_eq!(lines.count(), rows.len());
}

/// Bad inputs: exit 2, one line naming the flag.
#[test]
fn container_mu_rejects_bad_inputs() {
    let zip = format!("{DATA}/uniform.zip");
    for (extra, flag) in [
        (
            vec!["--pressure", "1e6", "--lambda-s", "1", "--lambda-c", "1e-3"],
            "--lambda-s",
        ),
        (vec!["--pressure", "1e6", "--lambda-c", "-1"], "--lambda-c"),
        (vec!["--pressure", "1e6", "--scan", "--per-decade", "0"], "--per-decade"),
        (vec!["--pressure", "1e6", "--scan", "--from", "1e-6"], "--from"),
        (vec!["--pressure", "1e6", "--dx", "1e-6"], "--dx"),
    ] {
        let o = kefric(&args(&zip, &extra));
        let why = bad_input_problem(o.status.code(), &String::from_utf8_lossy(&o.stdout), &stderr(&o), flag);
        assert!(why.is_none(), "{extra:?}: {why:?}");
    }
    // No materials: the message names them.
    let o = kefric(&["surface", &zip, "--pressure", "1e6"]);
    let why = bad_input_problem(
        o.status.code(),
        &String::from_utf8_lossy(&o.stdout),
        &stderr(&o),
        "--e1",
    );
    assert!(why.is_none(), "{why:?}");
}
