//! Several measurements of one surface in the CLI (issue 50): `plot
//! surface CONTAINER --psd/--scan`, `surface --measurements FILE@KEY=VALUE
//! ...` (loose files, the same as a container of them), the measurements
//! named in text and CSV, and hostile containers (one line, exit 2).

use crate::cli_surface::MATERIAL_FLAGS as MATERIALS;
use crate::common::TempDir;
use crate::support::{assert_bad_input, kefric, stderr};
use std::io::{Read, Write};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/container");
const PNG_MAGIC: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// The members of the container `name` of tests/data/container, unzipped
/// into `dir`.
fn unzip(name: &str, dir: &TempDir) {
    let file = std::fs::File::open(format!("{DATA}/{name}")).unwrap();
    let mut z = zip::ZipArchive::new(file).unwrap();
    for i in 0..z.len() {
        let mut f = z.by_index(i).unwrap();
        let mut bytes = Vec::new();
        f.read_to_end(&mut bytes).unwrap();
        std::fs::write(dir.join(f.name()), bytes).unwrap();
    }
}

/// A zip of `members` at `path`.
fn write_zip(path: &std::path::Path, members: &[(&str, &[u8])]) {
    let mut w = zip::ZipWriter::new(std::fs::File::create(path).unwrap());
    let opts = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    for (name, bytes) in members {
        w.start_file(*name, opts).unwrap();
        w.write_all(bytes).unwrap();
    }
    w.finish().unwrap();
}

/// Runs `kefric ARGS` and asserts success.
#[track_caller]
fn ok(args: &[&str]) -> String {
    let o = kefric(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    String::from_utf8(o.stdout).unwrap()
}

/// A written image: an SVG with drawn lines (its text returned), or a
/// PNG of the default size that is not blank (a blank page compresses to
/// a few kB).
#[track_caller]
fn image(path: &std::path::Path) -> String {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    if path.extension().is_some_and(|e| e == "png") {
        assert_eq!(bytes[..8], PNG_MAGIC);
        let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
        assert_eq!((be(16), be(20)), (2000, 1500));
        assert!(
            bytes.len() > 20_000,
            "{}: {} bytes, blank?",
            path.display(),
            bytes.len()
        );
        return String::new();
    }
    let svg = String::from_utf8(bytes).unwrap();
    assert!(svg.starts_with("<svg") || svg.contains("<svg"));
    let lines = svg.matches("<polyline").count() + svg.matches("<path").count();
    assert!(lines >= 5, "{} drawn lines", lines);
    svg
}

/// `plot surface CONTAINER --psd`: PNG and SVG written, each measurement
/// in the legend by name, and the combined curve; the SVG draws each
/// measurement's colour.
#[test]
fn plot_container_psd() {
    let dir = TempDir::new("plot-container-psd");
    let zip = format!("{DATA}/synthetic.zip");
    for name in ["psd.png", "psd.svg"] {
        let out = ok(&[
            "plot",
            "surface",
            &zip,
            "--psd",
            "--out",
            &dir.arg(name),
            "--scale",
            "2",
        ]);
        assert!(out.contains("wrote"), "{out}");
    }
    image(&dir.join("psd.png"));
    let svg = image(&dir.join("psd.svg"));
    for name in ["coarse.txt", "map.npy", "nonuniform.txt", "combined", "64 × 64 map"] {
        assert!(svg.contains(name), "{name} not in the SVG");
    }
    // The palette's first three colours (one a measurement) and black (the combined).
    for colour in ["#0072B2", "#D55E00", "#009E73", "#000000"] {
        assert!(svg.to_uppercase().contains(colour), "{colour} not drawn");
    }
    // The filters asked for are marked, as for one surface; a bad one is
    // refused naming it.
    let out = dir.arg("filters.svg");
    ok(&[
        "plot",
        "surface",
        &zip,
        "--psd",
        "--lambda-s",
        "auto",
        "--lambda-c",
        "1e-5",
        "--out",
        &out,
    ]);
    let svg = image(out.as_ref());
    assert!(svg.contains("2π/λs") && svg.contains("2π/λc"));
    let o = kefric(&["plot", "surface", &zip, "--psd", "--lambda-c", "-1", "--out", &out]);
    assert_bad_input(&o, "--lambda-c");
}

/// `plot surface CONTAINER --scan` with materials and a load: μ against λs,
/// the spread across measurements shaded (named in the legend), and the
/// measurements each λs rests on named; without materials: exit 2 naming
/// them; `--lambda-s` refused.
#[test]
fn plot_container_scan() {
    let dir = TempDir::new("plot-container-scan");
    let zip = format!("{DATA}/uniform.zip");
    for name in ["scan.png", "scan.svg"] {
        let mut args = vec!["plot", "surface", zip.as_str(), "--scan", "--pressure", "1e6"];
        args.extend(MATERIALS);
        let out = dir.arg(name);
        args.extend(["--out", out.as_str()]);
        ok(&args);
    }
    image(&dir.join("scan.png"));
    let svg = image(&dir.join("scan.svg"));
    for text in [
        "coarse.txt",
        "map.npy",
        "μ (combined spectrum)",
        "μ of each measurement alone",
        "the measurements each λs rests on",
    ] {
        assert!(svg.contains(text), "{text} not in the SVG");
    }
    assert!(svg.contains("<polygon"), "no shaded spread");
    let o = kefric(&["plot", "surface", &zip, "--scan", "--out", &dir.arg("x.png")]);
    assert_bad_input(&o, "--e1");
    let mut args = vec!["plot", "surface", zip.as_str(), "--scan", "--lambda-s", "1e-6"];
    args.extend(MATERIALS);
    let out = dir.arg("y.png");
    args.extend(["--out", out.as_str()]);
    assert_bad_input(&kefric(&args), "--lambda-s");
    // Neither --psd nor --scan: said so.
    let o = kefric(&["plot", "surface", &zip, "--out", &dir.arg("z.png")]);
    assert_bad_input(&o, "--psd or --scan");
    assert!(!dir.join("z.png").exists());
}

/// `--measurements` of the synthetic container's files with the settings
/// of its meta.yml: the same combined spectrum as a container of the same
/// files (built here: the text and nonuniform profiles; a `.npy` reads
/// rows = y loose, [x, y] in a container), CSV rows naming each file;
/// `plot surface --measurements` names them too.
#[test]
fn measurements_equal_the_container_of_the_same_files() {
    let dir = TempDir::new("measurements-equal");
    unzip("synthetic.zip", &dir);
    let meta = "surfaces:\n- topographies:\n  - datafile: {original: coarse.txt}\n    detrend_mode: height\n    size: [0.001]\n    unit: mm\n  - datafile: {original: nonuniform.txt}\n    detrend_mode: curvature\n    unit: mm\n    instrument: {parameters: {tip_radius: {value: 40, unit: nm}}}\n";
    let read = |name: &str| std::fs::read(dir.join(name)).unwrap();
    let (coarse, nonuniform) = (read("coarse.txt"), read("nonuniform.txt"));
    let zip = dir.arg("two.zip");
    write_zip(
        zip.as_ref(),
        &[
            ("meta.yml", meta.as_bytes()),
            ("coarse.txt", &coarse),
            ("nonuniform.txt", &nonuniform),
        ],
    );
    let a = dir.arg("coarse.txt") + "@unit=mm,size=0.001";
    let b = dir.arg("nonuniform.txt") + "@unit=mm,detrend_mode=curvature,tip_radius=40e-9";
    let loose: serde_json::Value =
        serde_json::from_str(&ok(&["surface", "--measurements", &a, &b, "--psd", "--json"])).unwrap();
    let container: serde_json::Value = serde_json::from_str(&ok(&["surface", &zip, "--psd", "--json"])).unwrap();
    assert!(!loose["combined"]["q"].as_array().unwrap().is_empty());
    let floats =
        |v: &serde_json::Value| -> Vec<f64> { v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect() };
    for key in ["q", "c"] {
        let (l, c) = (floats(&loose["combined"][key]), floats(&container["combined"][key]));
        assert_eq!(l.len(), c.len());
        for (x, y) in l.iter().zip(&c) {
            assert!((x / y - 1.0).abs() <= 1e-12, "{key}: {x} against {y}");
        }
    }
    assert_eq!(loose["files"][0].as_str(), Some(dir.arg("coarse.txt").as_str()));
    assert_eq!(loose["measurements"][1]["name"], "nonuniform.txt");
    let csv = ok(&["surface", "--measurements", &a, &b, "--psd", "--csv"]);
    for name in ["coarse.txt,", "nonuniform.txt,", "combined,"] {
        assert!(csv.lines().any(|l| l.starts_with(name)), "no {name} row");
    }
    // μ: the text names each measurement and what the band rests on.
    let mut args = vec!["surface", "--measurements", a.as_str(), b.as_str(), "--pressure", "1e6"];
    args.extend(MATERIALS);
    let text = ok(&args);
    assert!(
        text.contains("measurement coarse.txt") && text.contains("measurement nonuniform.txt"),
        "{text}"
    );
    assert!(text.contains("rests on"), "{text}");
    // The scan's CSV names the measurements of each row.
    args.extend(["--scan", "--csv"]);
    let csv = ok(&args);
    assert!(
        csv.lines()
            .skip(1)
            .all(|l| l.contains("coarse.txt") || l.contains("nonuniform.txt")),
        "{csv}"
    );
    // The plot of loose files.
    let out = dir.arg("loose.svg");
    ok(&["plot", "surface", "--measurements", &a, &b, "--psd", "--out", &out]);
    let svg = image(out.as_ref());
    assert!(svg.contains("coarse.txt") && svg.contains("nonuniform.txt"));
}

/// The container's own CSV and text name its measurements: `--psd --csv`
/// rows, `--scan --csv`'s `measurements` column, and the text of μ.
#[test]
fn container_csv_and_text_name_the_measurements() {
    let zip = format!("{DATA}/uniform.zip");
    let csv = ok(&["surface", &zip, "--psd", "--csv"]);
    for name in ["coarse.txt,", "map.npy,", "combined,"] {
        assert!(csv.lines().any(|l| l.starts_with(name)), "no {name} row");
    }
    let mut args = vec!["surface", zip.as_str(), "--pressure", "1e6"];
    args.extend(MATERIALS);
    let text = ok(&args);
    assert!(
        text.contains("measurement coarse.txt") && text.contains("measurement map.npy"),
        "{text}"
    );
    args.extend(["--scan", "--csv"]);
    let csv = ok(&args);
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert!(!rows.is_empty());
    assert!(rows.iter().all(|l| l
        .split(',')
        .nth(2)
        .is_some_and(|m| m.contains("coarse.txt") || m.contains("map.npy"))));
    assert!(rows.iter().any(|l| l
        .split(',')
        .nth(2)
        .is_some_and(|m| m.contains("coarse.txt") && m.contains("map.npy"))));
}

/// Bad `--measurements`: a missing file (named; exit 2 as any input file
/// that cannot be read), a bad setting (named), flags a measurement's
/// settings replace, FILE with --measurements; one file is a surface of one
/// measurement.
#[test]
fn measurements_errors() {
    let dir = TempDir::new("measurements-errors");
    unzip("synthetic.zip", &dir);
    let a = dir.arg("coarse.txt") + "@unit=mm,size=0.001";
    let gone = dir.arg("gone.txt");
    assert_bad_input(&kefric(&["surface", "--measurements", &a, &gone, "--psd"]), "gone.txt");
    let bad = dir.arg("coarse.txt") + "@unit=mm,size=0.001,colour=red";
    assert_bad_input(
        &kefric(&["surface", "--measurements", &bad, "--psd"]),
        "unknown setting \"colour\"",
    );
    // A column of heights gives no size.
    std::fs::write(dir.join("column.txt"), "1\n2\n3\n2\n1\n0\n1\n2\n").unwrap();
    let nosize = dir.arg("column.txt") + "@unit=mm";
    assert_bad_input(
        &kefric(&["surface", "--measurements", &nosize, "--psd"]),
        "size: missing",
    );
    for (flags, flag) in [
        (vec!["--dx", "1e-6"], "--dx"),
        (vec!["--channel", "1"], "--channel"),
        (vec!["--detrend", "line"], "--detrend"),
        (vec!["--z-unit", "nm"], "--z-unit"),
    ] {
        let mut args = vec!["surface", "--measurements", a.as_str(), "--psd"];
        args.extend(flags);
        assert_bad_input(&kefric(&args), flag);
    }
    let o = kefric(&["surface", &dir.arg("map.npy"), "--measurements", &a]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--measurements"));
    // One file: a surface of one measurement, its spectrum and the combined one.
    let csv = ok(&["surface", "--measurements", &a, "--psd", "--csv"]);
    assert!(csv.lines().any(|l| l.starts_with("coarse.txt,")));
    assert!(csv.lines().any(|l| l.starts_with("combined,")));
    // The combined scale-dependent statistics, as for a container.
    let scales = ok(&["surface", "--measurements", &a, "--scale-dependent", "--csv"]);
    assert!(
        scales.lines().next().unwrap().starts_with("distance,rms_slope"),
        "{scales}"
    );
    assert!(scales.lines().count() > 3, "{scales}");
}

/// Hostile containers through the CLI: a meta.yml that lies about a size,
/// a missing member, a member whose header declares more than the bound
/// once inflated (a zip bomb), deep YAML: one line naming the fault, exit
/// 2, for `surface` and `plot surface` alike.
#[test]
fn hostile_containers_give_one_line() {
    let dir = TempDir::new("hostile-containers");
    let profile = b"1\n2\n3\n2\n1\n0\n1\n2\n".as_slice();
    let entry =
        |rest: &str| format!("surfaces:\n- topographies:\n  - datafile: {{original: p.txt}}\n    unit: um\n{rest}");
    // (name, meta.yml, other members, what the message says)
    type Case<'a> = (&'a str, Vec<u8>, Vec<(&'a str, Vec<u8>)>, &'a str);
    let cases: Vec<Case> = vec![
        (
            "size",
            entry("    size: [8.0, 8.0]\n").into_bytes(),
            vec![("p.txt", profile.to_vec())],
            "size: 2 values for a profile",
        ),
        (
            "negative",
            entry("    size: [-8.0]\n").into_bytes(),
            vec![("p.txt", profile.to_vec())],
            "size = -8",
        ),
        (
            "missing",
            entry("    size: [8.0]\n").into_bytes(),
            vec![],
            "p.txt is not in the archive",
        ),
        (
            "deep",
            format!("surfaces: {}{}\n", "[".repeat(10_000), "]".repeat(10_000)).into_bytes(),
            vec![],
            "nested deeper",
        ),
    ];
    for (name, meta, members, says) in cases {
        let path = dir.join(&format!("{name}.zip"));
        let mut all: Vec<(&str, &[u8])> = vec![("meta.yml", &meta)];
        all.extend(members.iter().map(|(n, b)| (*n, b.as_slice())));
        write_zip(&path, &all);
        let p = path.to_str().unwrap();
        assert_bad_input(&kefric(&["surface", p, "--psd"]), says);
        assert_bad_input(
            &kefric(&["plot", "surface", p, "--psd", "--out", &dir.arg("x.svg")]),
            says,
        );
    }
    // A zip bomb's header: p.txt declares 3 GiB once inflated (over the
    // 2 GiB bound): refused before anything is inflated.
    let path = dir.join("bomb.zip");
    write_zip(
        &path,
        &[("meta.yml", entry("    size: [8.0]\n").as_bytes()), ("p.txt", profile)],
    );
    let mut bytes = std::fs::read(&path).unwrap();
    let declared = 3u32 << 30;
    let mut patched = 0;
    for at in 0..bytes.len() - 4 {
        let (offset, name_at) = match &bytes[at..at + 4] {
            b"PK\x03\x04" => (22, 30),
            b"PK\x01\x02" => (24, 46),
            _ => continue,
        };
        if bytes.get(at + name_at..at + name_at + 5) == Some(b"p.txt".as_slice()) {
            bytes[at + offset..at + offset + 4].copy_from_slice(&declared.to_le_bytes());
            patched += 1;
        }
    }
    assert_eq!(patched, 2, "the local and central headers of p.txt");
    std::fs::write(&path, bytes).unwrap();
    let p = path.to_str().unwrap();
    assert_bad_input(&kefric(&["surface", p, "--psd"]), "over the limit");
    assert_bad_input(&kefric(&["surface", p, "--psd"]), "p.txt");
}
