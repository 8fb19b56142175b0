//! `kefric surface` at a stated scale: the ISO 16610 filters (--lambda-s,
//! --lambda-c), μ against λs (--scan), the power spectrum (--psd) and the
//! instrument's reliability cut-off; against the library called directly
//! and against the single command.
use crate::common::TempDir;
use crate::support::{assert_bad_input, assert_stderr_has, kefric, stderr};
use ke_friction::topography::{write_x3p, StatsOptions, Surface, Topography};
use serde_json::Value;

use crate::cli_surface::MATERIAL_FLAGS as MATERIALS;

/// A rough map: waves from 4 µm to 150 µm, dx = 1 µm, dy = 1.5 µm.
fn map(dir: &TempDir) -> (String, Topography) {
    let (nx, ny) = (160, 120);
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let waves: Vec<(f64, f64, f64, f64)> = (0..40)
        .map(|k| {
            let wavelength = 4e-6 * (150.0f64 / 4.0).powf(k as f64 / 39.0);
            let angle = std::f64::consts::TAU * next();
            (
                wavelength,
                angle,
                std::f64::consts::TAU * next(),
                1e-7 * (wavelength / 4e-6).powf(0.8),
            )
        })
        .collect();
    let z = (0..nx * ny)
        .map(|k| {
            let (x, y) = ((k % nx) as f64 * 1e-6, (k / nx) as f64 * 1.5e-6);
            waves
                .iter()
                .map(|&(l, a, p, amp)| amp * (std::f64::consts::TAU / l * (x * a.cos() + y * a.sin()) + p).sin())
                .sum::<f64>()
        })
        .collect();
    let t = Topography::map(z, nx, ny, 1e-6, 1.5e-6).unwrap();
    let path = dir.join("map.x3p");
    write_x3p(&t, &path, 'D').unwrap();
    (dir.arg("map.x3p"), t)
}

fn json(args: &[&str]) -> Value {
    let o = kefric(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

fn with(base: &[&str], extra: &[&str]) -> Vec<String> {
    base.iter().chain(extra).map(|s| s.to_string()).collect()
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

#[test]
fn filtered_statistics_are_the_librarys_and_record_the_band() {
    let dir = TempDir::new("scale-filtered");
    let (file, t) = map(&dir);
    let v = json(&["surface", &file, "--lambda-s", "5e-6", "--lambda-c", "80e-6", "--json"]);
    let s = &v["surface"];
    assert_eq!(s["lambda_s"], 5e-6);
    assert_eq!(s["lambda_c"], 80e-6);
    assert_eq!(s["size_x"].as_f64().unwrap(), 160.0 * 1e-6);
    assert_eq!(s["size_y"].as_f64().unwrap(), 120.0 * 1.5e-6);
    let options = StatsOptions {
        lambda_s: Some(5e-6),
        lambda_c: Some(80e-6),
        ..StatsOptions::default()
    };
    let lib = Surface::new(t.clone(), options).unwrap();
    for name in ["sigma", "skewness", "kurtosis", "m2", "m4", "beta", "radius", "eta"] {
        let want = serde_json::to_value(lib.stats()).unwrap()[name].as_f64().unwrap();
        assert_eq!(s[name].as_f64().unwrap(), want, "{name}");
    }
    // The band narrows the roughness: σ and m4 are below the unfiltered ones.
    let raw = Surface::new(t, StatsOptions::default()).unwrap();
    assert!(lib.stats().sigma < raw.stats().sigma && lib.stats().m4 < 0.5 * raw.stats().m4);
    // Every text output beside β and ψ states the band.
    let mut args = vec![
        "eval",
        "--surface",
        file.as_str(),
        "--f-star",
        "1e-3",
        "--lambda-s",
        "5e-6",
    ];
    args.extend(MATERIALS);
    let o = kefric(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("dy = 1.5e-6 m, lambda_s = 5e-6 m"), "{text}");
    // Unfiltered, the record says so.
    let v = json(&["surface", &file, "--json"]);
    assert!(v["surface"]["lambda_s"].is_null() && v["surface"]["lambda_c"].is_null());
}

#[test]
fn each_scan_row_is_the_single_command_at_that_lambda_s() {
    let dir = TempDir::new("scale-scan");
    let (file, _) = map(&dir);
    let load = ["--force", "10", "--area", "1e-5"];
    let base = with(&["surface", &file, "--json", "--lambda-c", "100e-6"], MATERIALS);
    let mut scan_args = strs(&base);
    scan_args.extend(load);
    scan_args.extend(["--scan", "--per-decade", "4"]);
    let scan = json(&scan_args);
    let rows = scan["rows"].as_array().unwrap();
    // From 2·max(dx, dy) = 3 µm to a tenth of the smaller side (16 µm).
    assert_eq!(rows[0]["lambda_s"], 3e-6);
    assert_eq!(rows.last().unwrap()["lambda_s"].as_f64().unwrap(), 16e-6);
    assert_eq!(rows.len(), 4);
    let mut mu = vec![];
    for row in rows {
        let lambda = row["lambda_s"].as_f64().unwrap();
        let lambda_s = format!("{lambda:e}");
        let mut args = strs(&base);
        args.extend(load);
        args.extend(["--lambda-s", &lambda_s, "--sensitivity", "off"]);
        let single = json(&args);
        for group in ["surface", "model", "friction"] {
            assert_eq!(row[group], single[group], "{group} at {lambda}");
        }
        mu.push(row["friction"]["mu"].as_f64().unwrap());
    }
    // μ moves with the scale (here it grows as short waves are filtered out).
    assert!(mu.windows(2).all(|w| w[1] != w[0]), "{mu:?}");
    // CSV: the same numbers, the record names as columns.
    let o = kefric(&strs(&with(
        &[
            "surface",
            &file,
            "--csv",
            "--lambda-c",
            "100e-6",
            "--scan",
            "--per-decade",
            "4",
        ],
        &[MATERIALS, &load[..]].concat(),
    )));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&header[..4], ["lambda_s", "reliable", "sigma", "skewness"]);
    let mu_col = header.iter().position(|&c| c == "mu").unwrap();
    for (line, want) in lines.zip(&mu) {
        let got: f64 = line.split(',').nth(mu_col).unwrap().parse().unwrap();
        assert_eq!(got, *want);
    }
}

#[test]
fn the_reliability_cut_off_marks_rows_and_warns() {
    let dir = TempDir::new("scale-reliability");
    let (file, _) = map(&dir);
    let scan = json(&["surface", &file, "--scan", "--resolution", "6e-6", "--json"]);
    for row in scan["rows"].as_array().unwrap() {
        let lambda = row["lambda_s"].as_f64().unwrap();
        assert_eq!(row["reliable"].as_bool().unwrap(), lambda >= 6e-6, "{lambda}");
    }
    // A single evaluation below the cut-off warns, naming both lengths.
    let o = kefric(&["surface", &file, "--resolution", "6e-6"]);
    assert!(o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("3e-6 m, is below the instrument's reliability cut-off 6e-6 m"),
        "{err}"
    );
    // At or above it, or filtered there with auto, no such warning.
    for extra in [&["--lambda-s", "6e-6"][..], &["--lambda-s", "auto"][..]] {
        let o = kefric(&[&["surface", &file, "--resolution", "6e-6", "--json"][..], extra].concat());
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(!stderr(&o).contains("reliability"), "{}", stderr(&o));
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["surface"]["lambda_s"], 6e-6);
    }
    // A tip that distorts no scale: auto is no filter, and says so naming
    // both flags (issue 49: it was silent).
    let o = kefric(&[
        "surface",
        &file,
        "--lambda-s",
        "auto",
        "--tip-radius",
        "10e-9",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["surface"]["lambda_s"], Value::Null);
    assert_stderr_has(
        &o,
        &format!("warning: {file}: --lambda-s auto: --tip-radius 1e-8 m distorts no scale of these data"),
    );
}

#[test]
fn the_psd_integrates_to_the_mean_square_height() {
    let dir = TempDir::new("scale-psd");
    let (file, t) = map(&dir);
    let v = json(&["surface", &file, "--psd", "--json"]);
    for name in ["x", "y", "area"] {
        let q = v[name]["q"].as_array().unwrap();
        assert_eq!(q.len(), v[name]["c"].as_array().unwrap().len(), "{name}");
        assert!(q.len() > 5, "{name}");
    }
    // Parseval along x: Σ C Δq / π over 0 < q < q_Nyquist is the mean
    // square of the (plane-detrended) rows about their means, but for the
    // Nyquist term.
    let q: Vec<f64> = v["x"]["q"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let c: Vec<f64> = v["x"]["c"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let dq = q[1] - q[0];
    let partial: f64 = c[1..].iter().sum::<f64>() * dq / std::f64::consts::PI;
    let z = t.detrended(ke_friction::topography::Detrend::Plane).unwrap();
    let rows: Vec<f64> = z
        .chunks(t.nx())
        .map(|row| {
            let mean = row.iter().sum::<f64>() / row.len() as f64;
            row.iter().map(|h| (h - mean) * (h - mean)).sum::<f64>() / row.len() as f64
        })
        .collect();
    let m0 = rows.iter().sum::<f64>() / rows.len() as f64;
    assert!((partial / m0 - 1.0).abs() < 0.01, "{partial} vs {m0}");
}

#[test]
fn bad_scales_are_refused_naming_the_numbers() {
    let dir = TempDir::new("scale-bad");
    let (file, _) = map(&dir);
    for (args, needle) in [
        (&["--lambda-s", "1e-6"][..], "at least 2·max(dx, dy) = 3e-6 m"),
        (&["--lambda-c", "1e-3"][..], "at most the scan size"),
        (&["--lambda-s", "auto"][..], "give --tip-radius or --resolution"),
        (&["--csv"][..], "--csv: with --scan, --psd or --scale-dependent"),
        (&["--scan", "--from", "1e-5", "--to", "1e-6"][..], "need 0 < from <= to"),
    ] {
        let o = kefric(&[&["surface", &file][..], args].concat());
        assert_bad_input(&o, needle);
    }
}

#[test]
fn plot_surface_draws_the_psd_and_the_scan() {
    let dir = TempDir::new("scale-plots");
    let (file, _) = map(&dir);
    for (what, extra) in [
        ("psd", &["--psd", "--lambda-s", "4e-6"][..]),
        (
            "scan",
            &["--scan", "--resolution", "5e-6", "--force", "10", "--area", "1e-5"][..],
        ),
    ] {
        let out = dir.arg(&format!("{what}.png"));
        let mut args = vec!["plot", "surface", file.as_str(), "--scale", "1", "--out", out.as_str()];
        args.extend(extra);
        if what == "scan" {
            args.extend(MATERIALS);
        }
        let o = kefric(&args);
        assert!(o.status.success(), "{what}: {}", stderr(&o));
        let png = std::fs::read(&out).unwrap();
        assert!(
            png.starts_with(b"\x89PNG") && png.len() > 10_000,
            "{what}: {} bytes",
            png.len()
        );
    }
    let out = dir.arg("two.png");
    let o = kefric(&["plot", "surface", &file, &file, "--psd", "--out", &out]);
    assert_bad_input(&o, "take one surface file");
}

#[test]
fn scale_dependent_slope_and_curvature_are_the_librarys_at_its_default_distances() {
    use ke_friction::topography::{default_distances, scale_dependent_curvature, scale_dependent_slope, Detrend};
    let dir = TempDir::new("scale-dependent");
    let (_, flat) = map(&dir);
    // Tilted: the rows are of the plane-detrended heights, as the
    // statistics' (issue 49: they were of the heights as read).
    let tilted: Vec<f64> = (0..flat.nx() * flat.ny())
        .map(|k| flat.heights()[k] + 0.5 * (k % flat.nx()) as f64 * 1e-6 - 0.3 * (k / flat.nx()) as f64 * 1.5e-6)
        .collect();
    let t = Topography::map(tilted, flat.nx(), flat.ny(), 1e-6, 1.5e-6).unwrap();
    write_x3p(&t, &dir.join("tilted.x3p"), 'D').unwrap();
    let file = dir.arg("tilted.x3p");
    let doc = json(&["surface", &file, "--scale-dependent", "--json"]);
    let detrended = t.detrended_topography(Detrend::Plane).unwrap();
    // From 2·max(dx, dy) as the help says: both orders have every row.
    let d = default_distances(&t, 2);
    assert_eq!(d[0], 2.0 * 1.5e-6);
    let got = |name: &str| -> Vec<Option<f64>> { doc[name].as_array().unwrap().iter().map(Value::as_f64).collect() };
    let distance: Vec<f64> = got("distance").into_iter().map(Option::unwrap).collect();
    assert_eq!(distance, d);
    let slope = scale_dependent_slope(&detrended, &d).unwrap();
    let curvature = scale_dependent_curvature(&detrended, &d).unwrap();
    for (k, (s, c)) in slope.iter().zip(&curvature).enumerate() {
        assert_eq!(got("slope_x")[k], Some(s.x));
        assert_eq!(got("slope_y")[k], s.y);
        assert_eq!(got("curvature_x")[k], Some(c.x), "no empty curvature");
        assert_eq!(got("curvature_y")[k], c.y);
    }
    // At one interval the rms slope of these heights is √m20 of the
    // statistics (`kefric surface --json`); of the tilted ones it is not.
    let stats = json(&["surface", &file, "--json"]);
    let m20 = stats["surface"]["m20"].as_f64().unwrap();
    let one = scale_dependent_slope(&detrended, &[1e-6]).unwrap()[0].x;
    let rel = (one - m20.sqrt()).abs() / m20.sqrt();
    // Not exact on a map: the stencils drop the last row too (7e-4 here).
    assert!(
        rel < 2e-3,
        "rms slope at dx {one} against sqrt(m20) {} ({rel:e})",
        m20.sqrt()
    );
    let raw = scale_dependent_slope(&t, &[1e-6]).unwrap()[0].x;
    assert!(
        (raw - m20.sqrt()).abs() / m20.sqrt() > 0.1,
        "the tilt shows: {raw} against {}",
        m20.sqrt()
    );
    // The slope falls with the scale on this self-affine map.
    assert!(slope.first().unwrap().x > 2.0 * slope.last().unwrap().x);
    // CSV: a header and one row a distance; the text adds the cut-off.
    let o = kefric(&["surface", &file, "--scale-dependent", "--csv"]);
    let csv = String::from_utf8(o.stdout).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("distance,slope_x,slope_y,curvature_x,curvature_y"));
    assert_eq!(lines.count(), d.len());
    let o = kefric(&["surface", &file, "--scale-dependent", "--tip-radius", "1e-9"]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("# reliability cut-off: "), "{text}");
    let o = kefric(&["surface", &file, "--scale-dependent", "--scan"]);
    assert_eq!(o.status.code(), Some(2));
}

/// Each scan row carries its warning kinds, the single command's at that
/// λs (JSON), as a text column and a CSV column; the summary comes once
/// per kind (issue 48, item 4).
#[test]
fn scan_rows_carry_the_single_commands_warnings() {
    let dir = TempDir::new("scale-scan-warnings");
    let (file, _) = map(&dir);
    // A light load on a small area: F* below the paper's range and few
    // asperities in every row.
    let load = ["--force", "1e-4", "--area", "1e-7"];
    let base = with(&["surface", &file, "--json"], MATERIALS);
    let mut scan_args = strs(&base);
    scan_args.extend(load);
    scan_args.extend(["--scan", "--per-decade", "3"]);
    let scan = json(&scan_args);
    let rows = scan["rows"].as_array().unwrap();
    let mut flagged = 0;
    for row in rows {
        let lambda_s = format!("{:e}", row["lambda_s"].as_f64().unwrap());
        let mut args = strs(&base);
        args.extend(load);
        args.extend(["--lambda-s", &lambda_s]);
        let single = json(&args);
        let want: Vec<&Value> = single["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| &w["kind"])
            .collect();
        let got: Vec<&Value> = row["warnings"].as_array().unwrap().iter().collect();
        assert_eq!(got, want, "at {lambda_s}");
        flagged += usize::from(!got.is_empty());
    }
    assert_eq!(flagged, rows.len(), "every row warns f_star_below_range");
    let summary = scan["warnings"].as_array().unwrap();
    let below: Vec<&Value> = summary.iter().filter(|w| w["kind"] == "f_star_below_range").collect();
    assert_eq!(below.len(), 1, "once per kind: {summary:?}");
    assert_eq!(
        (below[0]["count"].as_u64(), below[0]["of"].as_u64()),
        (Some(rows.len() as u64), Some(rows.len() as u64))
    );
    // Text: a last column of kinds; stderr: the summary once per kind.
    let text_base = with(&["surface", &file], MATERIALS);
    let mut args = strs(&text_base);
    args.extend(load);
    args.extend(["--scan", "--per-decade", "3"]);
    let o = kefric(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout.clone()).unwrap();
    let header = text.lines().nth(1).unwrap();
    assert!(header.trim_end().ends_with("warnings"), "{header}");
    for line in text.lines().skip(2).filter(|l| !l.starts_with('#')) {
        assert!(line.contains("f_star_below_range"), "{line}");
    }
    let err = stderr(&o);
    assert_eq!(err.matches("is below the range the paper covers").count(), 1, "{err}");
    // CSV: the kinds in a last column, joined by ';'.
    args.push("--csv");
    let o = kefric(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.lines().next().unwrap().ends_with(",error,warnings"));
    for line in text.lines().skip(1) {
        assert!(
            line.rsplit(',').next().unwrap().contains("f_star_below_range"),
            "{line}"
        );
    }
}

/// Missing points: `--psd` gives the spectra of the largest complete
/// rectangle and says so (issue 49: it refused; Python's psd() does the same).
#[test]
fn the_psd_of_a_map_with_missing_points_is_of_its_largest_complete_rectangle() {
    use ke_friction::topography::{complete_part, psd_all, Detrend, Window};
    let dir = TempDir::new("scale-psd-holes");
    let (_, t) = map(&dir);
    let mut z = t.heights().to_vec();
    for v in &mut z[..5 * t.nx()] {
        *v = f64::NAN; // rows 0-4
    }
    let holes = Topography::map(z, t.nx(), t.ny(), 1e-6, 1.5e-6).unwrap();
    write_x3p(&holes, &dir.join("holes.x3p"), 'D').unwrap();
    let file = dir.arg("holes.x3p");
    let o = kefric(&["surface", &file, "--psd", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_stderr_has(&o, &format!(
            "warning: --psd: {file}: 800 missing points: the power spectral density of the largest complete rectangle, 160 × 115 points from column 0, row 5 of 160 × 120"
        ));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let (part, _) = complete_part(&holes).unwrap();
    let want = psd_all(&part.detrended_topography(Detrend::Plane).unwrap(), Window::None).unwrap();
    for (name, p) in &want {
        let c: Vec<f64> = v[name]["c"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        assert_eq!(c, p.c, "{name}");
    }
}
