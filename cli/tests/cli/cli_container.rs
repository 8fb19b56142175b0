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
