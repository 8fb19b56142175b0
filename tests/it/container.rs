//! contact.engineering containers (issue 50): reading, the combined 1-D
//! PSD against SurfaceTopography's (references from
//! `tools/container_check.py --write` in tests/data/container/), the
//! spectral moments, and hostile containers.
//!
//! container-2.zip: `$KEF_CONTAINERS`, else `../shared/containers` beside
//! the repository (skipped if absent).

use std::io::Write;
use std::path::PathBuf;

use ke_friction::topography::container::{
    combined_psd, combined_scale_dependent, measurement_psd, measurement_scale_dependent, read_container,
    read_container_bytes, roughness_from_moments, spectral_moments, ContainerError, ContainerOptions, Heights,
    COMBINED_POINTS_PER_DECADE,
};
use ke_friction::topography::{Psd, ReadOptions};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/container");

fn reference(name: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(format!("{DATA}/{name}.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn floats(v: &serde_json::Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

/// Reads `path` and checks its measurements' grids and sizes and the
/// combined PSD against SurfaceTopography's, 1e-9 relative.
fn check_against_reference(path: &std::path::Path, name: &str) {
    let surfaces = read_container(path, &ContainerOptions::default()).unwrap();
    assert_eq!(surfaces.len(), 1);
    let r = reference(name);
    let ms = &surfaces[0].measurements;
    let rm = r["measurements"].as_array().unwrap();
    assert_eq!(ms.len(), rm.len());
    for (m, r) in ms.iter().zip(rm) {
        let grid: Vec<usize> = r["nb_grid_pts"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap() as usize)
            .collect();
        let (nx, ny) = m.grid();
        assert_eq!(nx, grid[0], "{}", m.name);
        assert_eq!(ny, grid.get(1).copied().unwrap_or(1), "{}", m.name);
        let sizes = floats(&r["physical_sizes"]);
        let (sx, sy) = m.size();
        assert!((sx / sizes[0] - 1.0).abs() < 1e-9, "{}: {sx} vs {}", m.name, sizes[0]);
        if let Some(sy) = sy {
            assert!((sy / sizes[1] - 1.0).abs() < 1e-9);
        }
    }
    let spectra: Vec<_> = ms.iter().map(measurement_psd).collect();
    let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE).unwrap();
    let (rq, rc) = (floats(&r["combined"]["q"]), floats(&r["combined"]["c"]));
    assert_eq!(combined.psd.q.len(), rq.len(), "bins");
    for k in 0..rq.len() {
        assert!((combined.psd.q[k] / rq[k] - 1.0).abs() <= 1e-9, "q[{k}]");
        assert!(
            (combined.psd.c[k] / rc[k] - 1.0).abs() <= 1e-9,
            "C[{k}]: {} vs {}",
            combined.psd.c[k],
            rc[k]
        );
        assert!(!combined.contributors[k].is_empty());
    }
    // The moments of the whole combined band: SurfaceTopography's
    // container c1d_moment(0, 2, 4).
    let tau = 2.0 * std::f64::consts::PI;
    let q = &combined.psd.q;
    let m = spectral_moments(&combined.psd, tau / q[q.len() - 1], tau / q[0]).unwrap();
    let rm = floats(&r["moments"]);
    for (got, want) in [m.m0, m.m2, m.m4].into_iter().zip(rm) {
        assert!((got / want - 1.0).abs() <= 1e-9, "{got} vs {want}");
    }
}

#[test]
fn synthetic_container_matches_surface_topography() {
    check_against_reference(&PathBuf::from(format!("{DATA}/synthetic.zip")), "synthetic");
    // Its third measurement is a nonuniform x z profile cut by its tip
    // radius (40 nm): fewer reliable wavevectors than the full spectrum.
    let s = read_container(format!("{DATA}/synthetic.zip").as_ref(), &ContainerOptions::default()).unwrap();
    let m = &s[0].measurements[2];
    assert!(matches!(m.heights, Heights::Nonuniform { .. }));
    assert_eq!(m.tip_radius, Some(40e-9));
    let p = measurement_psd(m);
    assert!(p.cutoff.is_some());
    // The .npy map is indexed [x, y] in a container: 64 x 64 either way,
    // its height scale 2 applied.
    assert_eq!(s[0].measurements[1].height_scale, 2.0);
}

/// The combined scale-dependent slope and curvature (mean squares) of the
/// container at `path` against SurfaceTopography's container
/// `scale_dependent_statistical_property`, 1e-9 relative at every distance
/// (NaN where it has NaN); returns the largest relative difference.
fn check_scale_dependent(path: &std::path::Path, name: &str) -> f64 {
    let s = read_container(path, &ContainerOptions::default()).unwrap();
    let r = reference(name);
    let mut worst = 0.0f64;
    for (kind, order) in [("slope", 1), ("curvature", 2)] {
        let got = combined_scale_dependent(&s[0].measurements, order, 10).unwrap();
        let d = floats(&r[kind]["d"]);
        let v: Vec<f64> = r[kind]["v"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap_or(f64::NAN))
            .collect();
        assert_eq!(got.distance.len(), d.len(), "{kind}");
        for k in 0..d.len() {
            assert!((got.distance[k] / d[k] - 1.0).abs() <= 1e-9, "{kind} d[{k}]");
            if v[k].is_nan() {
                assert!(got.mean_square[k].is_nan(), "{kind} v[{k}]");
            } else {
                let e = (got.mean_square[k] / v[k] - 1.0).abs();
                worst = worst.max(e);
                assert!(
                    e <= 1e-9,
                    "{kind} v[{k}] at {}: {} vs {}",
                    d[k],
                    got.mean_square[k],
                    v[k]
                );
            }
        }
    }
    worst
}

/// The synthetic container without its nonuniform profile: the combined
/// PSD and the combined scale-dependent slope and curvature.
#[test]
fn uniform_container_scale_dependent_matches_surface_topography() {
    let path = PathBuf::from(format!("{DATA}/uniform.zip"));
    check_against_reference(&path, "uniform");
    check_scale_dependent(&path, "uniform");
}

/// With its nonuniform profile (tip radius 40 nm: its cut-off from its own
/// interpolated derivatives): the combined scale-dependent statistics, the
/// nonuniform profile contributing at the lengths of its band.
#[test]
fn synthetic_container_scale_dependent_matches_surface_topography() {
    let path = PathBuf::from(format!("{DATA}/synthetic.zip"));
    check_scale_dependent(&path, "synthetic");
    let s = read_container(&path, &ContainerOptions::default()).unwrap();
    let m = &s[0].measurements[2];
    let own = measurement_scale_dependent(m, 1, 10);
    assert!(!own.distance.is_empty(), "the nonuniform profile contributes");
    assert!(own.cutoff.is_some(), "its tip radius cuts it");
    let combined = combined_scale_dependent(&s[0].measurements, 1, 10).unwrap();
    assert!(combined.contributors.iter().any(|c| c.contains(&2)));
}

#[test]
fn container_2_matches_surface_topography() {
    let Some(path) = crate::common::container_2() else {
        return;
    };
    check_against_reference(&path, "container-2");
    let s = read_container(&path, &ContainerOptions::default()).unwrap();
    let ms = &s[0].measurements;
    assert_eq!(ms[0].unit.as_deref(), Some("nm"));
    assert!(matches!(ms[0].heights, Heights::Nonuniform { .. }));
    assert_eq!(ms[1].grid(), (512, 512));
    assert_eq!(ms[2].grid(), (3001, 1));
    assert_eq!(ms[2].measurement_date.as_deref(), Some("2016-03-05"));
    // The scale-dependent statistics, the nonuniform TEM profile included.
    let worst = check_scale_dependent(&path, "container-2");
    println!("container-2: scale-dependent mean squares within {worst:.1e} of SurfaceTopography's");
    let tem = measurement_scale_dependent(&ms[0], 1, 10);
    assert!(tem.distance.len() >= 10, "the TEM profile contributes");
}

/// A power law C = q^-3 (H = 1) sampled densely: the moments of a band
/// against the closed forms (1/π)∫qⁿ q⁻³ dq.
#[test]
fn spectral_moments_of_a_power_law() {
    let q: Vec<f64> = (0..4001).map(|i| 10f64.powf(3.0 + i as f64 / 1000.0)).collect();
    let c: Vec<f64> = q.iter().map(|q| q.powi(-3)).collect();
    let psd = Psd { q, c };
    let (ls, lc) = (2.0 * std::f64::consts::PI / 1e6, 2.0 * std::f64::consts::PI / 1e4);
    let m = spectral_moments(&psd, ls, lc).unwrap();
    let pi = std::f64::consts::PI;
    let m0 = (1e-8 - 1e-12) / 2.0 / pi;
    let m2 = (1e6f64 / 1e4).ln() / pi;
    let m4 = (1e12 - 1e8) / 2.0 / pi;
    assert!((m.m0 / m0 - 1.0).abs() < 1e-5, "{} vs {m0}", m.m0);
    assert!((m.m2 / m2 - 1.0).abs() < 1e-5, "{} vs {m2}", m.m2);
    assert!((m.m4 / m4 - 1.0).abs() < 1e-5, "{} vs {m4}", m.m4);
    let r = roughness_from_moments(&m).unwrap();
    assert!((r.sigma - m.m0.sqrt()).abs() < 1e-20);
    assert!((r.alpha - m.m0 * m.m4 / (m.m2 * m.m2)).abs() < 1e-9 * r.alpha);
    assert!(r.eta > 0.0 && r.radius > 0.0 && r.beta > 0.0);
    // A band outside the spectrum, or inverted: none.
    assert!(spectral_moments(&psd, 1.0, 2.0).is_none());
    assert!(spectral_moments(&psd, lc, ls).is_none());
}

fn zip_of(members: &[(&str, &[u8])]) -> Vec<u8> {
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    for (name, bytes) in members {
        w.start_file(*name, opts).unwrap();
        w.write_all(bytes).unwrap();
    }
    w.finish().unwrap().into_inner()
}

const PROFILE: &[u8] = b"1\n2\n3\n2\n1\n0\n1\n2\n";

fn meta(entry: &str) -> String {
    format!("surfaces:\n- topographies:\n  - datafile:\n      original: p.txt\n{entry}")
}

fn read(bytes: &[u8]) -> Result<usize, String> {
    read_container_bytes(bytes, "c.zip", &ContainerOptions::default())
        .map(|s| s[0].measurements.len())
        .map_err(|e| e.to_string())
}

#[test]
fn a_plain_container_reads() {
    let m = meta("    unit: um\n    size: [8.0]\n    detrend_mode: center\n");
    let z = zip_of(&[("meta.yml", m.as_bytes()), ("p.txt", PROFILE)]);
    let s = read_container_bytes(&z, "c.zip", &ContainerOptions::default()).unwrap();
    let Heights::Uniform(t) = &s[0].measurements[0].heights else {
        panic!()
    };
    assert!((t.dx() - 1e-6).abs() < 1e-18);
    let mean: f64 = t.heights().iter().sum::<f64>() / 8.0;
    assert!(mean.abs() < 1e-18);
    assert!((t.heights()[0] - (1.0 - 1.5) * 1e-6).abs() < 1e-18);
}

#[test]
fn hostile_containers_give_clear_errors() {
    // A missing data file.
    let m = meta("    unit: um\n    size: [8.0]\n");
    let e = read(&zip_of(&[("meta.yml", m.as_bytes())])).unwrap_err();
    assert!(
        e.contains("p.txt is not in the archive") && e.contains("topographies[0]"),
        "{e}"
    );
    // Lying meta.yml: no size for a file that gives none; a map's two
    // sizes for a profile; an unknown unit; a bad detrend mode; no
    // `surfaces`.
    for (entry, says) in [
        ("    unit: um\n", "size: missing"),
        ("    unit: um\n    size: [8.0, 8.0]\n", "2 values for a profile"),
        ("    unit: furlong\n    size: [8.0]\n", "unit = \"furlong\""),
        (
            "    unit: um\n    size: [8.0]\n    detrend_mode: wobble\n",
            "detrend_mode",
        ),
        ("    unit: um\n    size: [-8.0]\n", "size = -8"),
        (
            "    unit: um\n    size: [8.0]\n    height_scale: .inf\n",
            "height_scale",
        ),
    ] {
        let m = meta(entry);
        let e = read(&zip_of(&[("meta.yml", m.as_bytes()), ("p.txt", PROFILE)])).unwrap_err();
        assert!(e.contains(says), "{entry}: {e}");
    }
    let e = read(&zip_of(&[("meta.yml", b"versions: 1\n")])).unwrap_err();
    assert!(e.contains("no `surfaces` list"), "{e}");
    // Only a squeezed NetCDF file, missing or not NetCDF: refused, naming
    // it.
    let m = "surfaces:\n- topographies:\n  - datafile:\n      squeezed-netcdf: s.nc\n";
    let e = read(&zip_of(&[("meta.yml", m.as_bytes())])).unwrap_err();
    assert!(e.contains("s.nc") && e.contains("not in the archive"), "{e}");
    let e = read(&zip_of(&[("meta.yml", m.as_bytes()), ("s.nc", PROFILE)])).unwrap_err();
    assert!(e.contains("s.nc") && e.contains("not a NetCDF-3 file"), "{e}");
    // Deep YAML, and aliases.
    let deep = format!("surfaces: {}{}\n", "[".repeat(10_000), "]".repeat(10_000));
    let e = read(&zip_of(&[("meta.yml", deep.as_bytes())])).unwrap_err();
    assert!(e.contains("nested deeper"), "{e}");
    let alias = "a: &x [1]\nsurfaces: *x\n";
    assert!(read(&zip_of(&[("meta.yml", alias.as_bytes())]))
        .unwrap_err()
        .contains("aliases"));
    // A zip bomb member: 8 MiB of zeros, over a 1 MiB bound.
    let zeros = vec![b'0'; 8 << 20];
    let m = meta("    unit: um\n    size: [8.0]\n");
    let z = zip_of(&[("meta.yml", m.as_bytes()), ("p.txt", &zeros)]);
    assert!(z.len() < 1 << 20);
    let options = ContainerOptions {
        read: ReadOptions {
            max_bytes: 1 << 20,
            ..ReadOptions::default()
        },
        ..ContainerOptions::default()
    };
    let e = read_container_bytes(&z, "c.zip", &options).unwrap_err();
    assert!(matches!(e, ContainerError::Archive { .. }));
    assert!(
        e.to_string().contains("p.txt") && e.to_string().contains("over the limit"),
        "{e}"
    );
    // An x z profile with a missing x.
    let m = meta("    unit: um\n");
    let e = read(&zip_of(&[
        ("meta.yml", m.as_bytes()),
        ("p.txt", b"0 1\nnan 2\n2 3\n3 1\n"),
    ]))
    .unwrap_err();
    assert!(e.contains("missing (NaN) x"), "{e}");
    // index.json (JSON is YAML) is read like meta.yml.
    let j = br#"{"surfaces": [{"topographies": [{"datafile": {"original": "p.txt"}, "unit": "um", "size": [8.0]}]}]}"#;
    assert_eq!(read(&zip_of(&[("index.json", j), ("p.txt", PROFILE)])), Ok(1));
    // Not a zip, a zip without metadata.
    assert!(read(b"hello").unwrap_err().contains("not a readable zip"));
    assert!(read(&zip_of(&[("p.txt", PROFILE)]))
        .unwrap_err()
        .contains("neither meta.yml nor index.json"));
}

/// Mutated containers (bytes of the archive flipped or cut; lines of its
/// meta.yml dropped, duplicated or garbled) give a container or an error,
/// never a panic; a spectrum taken of what reads is finite.
#[test]
fn mutated_containers_do_not_panic() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(50);
    let zip = std::fs::read(format!("{DATA}/synthetic.zip")).unwrap();
    let mut archive = zip::ZipArchive::new(std::io::Cursor::new(&zip[..])).unwrap();
    let mut members = Vec::new();
    for i in 0..archive.len() {
        let mut f = archive.by_index(i).unwrap();
        let mut bytes = Vec::new();
        std::io::Read::read_to_end(&mut f, &mut bytes).unwrap();
        members.push((f.name().to_string(), bytes));
    }
    let check = |bytes: &[u8]| {
        if let Ok(surfaces) = read_container_bytes(bytes, "m.zip", &ContainerOptions::default()) {
            for s in &surfaces {
                let spectra: Vec<_> = s.measurements.iter().map(measurement_psd).collect();
                if let Some(c) = combined_psd(&spectra, 10) {
                    assert!(c.psd.q.iter().all(|q| q.is_finite() && *q > 0.0));
                }
            }
        }
    };
    for _ in 0..40 {
        let mut bytes = zip.clone();
        match rng.gen_range(0..3) {
            0 => bytes.truncate(rng.gen_range(0..zip.len())),
            _ => {
                for _ in 0..rng.gen_range(1..8) {
                    let k = rng.gen_range(0..bytes.len());
                    bytes[k] = rng.gen();
                }
            }
        }
        check(&bytes);
    }
    let meta = &members.iter().find(|(n, _)| n == "meta.yml").unwrap().1;
    let lines: Vec<&str> = std::str::from_utf8(meta).unwrap().lines().collect();
    for _ in 0..80 {
        let mut l: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
        for _ in 0..rng.gen_range(1..4) {
            let k = rng.gen_range(0..l.len());
            match rng.gen_range(0..4) {
                0 => {
                    l.remove(k);
                }
                1 => l.insert(k, l[k].clone()),
                2 => l[k] = l[k].replace(['1', '2', '5'], ["-1", "0", "1e400"][rng.gen_range(0..3)]),
                _ => l[k] = l[k].replace(':', ["", " [", " {", ": &a x\n*a"][rng.gen_range(0..4)]),
            }
            if l.is_empty() {
                break;
            }
        }
        let text = l.join("\n");
        let mut entries: Vec<(&str, &[u8])> = members
            .iter()
            .filter(|(n, _)| n != "meta.yml")
            .map(|(n, b)| (n.as_str(), &b[..]))
            .collect();
        entries.push(("meta.yml", text.as_bytes()));
        check(&zip_of(&entries));
    }
}

mod analysis {
    use super::*;
    use ke_friction::topography::container::{container_analysis, container_scan, measurement_spectra, Band, Resolved};
    use ke_friction::topography::{StatsOptions, Surface, SurfaceModel};
    use ke_friction::{Load, Materials, Model, Params};

    const MATERIALS: Materials = Materials::from_array([70e9, 0.33, 200e9, 0.31, 1e9, 0.5, 0.4e-9]);

    /// μ of the whole band equals μ computed by hand from the same
    /// moments (σ = √m0, η, R from m2, m4: Params::from_physical), with the
    /// heights of the measurement resolving λc; the band is the union of
    /// the reliable ranges and rests on every measurement.
    fn check_whole_band(path: &std::path::Path) {
        let s = read_container(path, &ContainerOptions::default()).unwrap();
        let ms = &s[0].measurements;
        let spectra = measurement_spectra(ms);
        let loads = [Load::Pressure(1e6), Load::Force { force: 1.0, area: 1e-6 }];
        let how = SurfaceModel::new(MATERIALS);
        let a = container_analysis(ms, &spectra, None, COMBINED_POINTS_PER_DECADE, &how, &loads).unwrap();
        let resolved = Resolved::of(&spectra);
        let lo = resolved
            .ranges
            .iter()
            .flatten()
            .map(|r| r.0)
            .fold(f64::INFINITY, f64::min);
        let hi = resolved.ranges.iter().flatten().map(|r| r.1).fold(0.0, f64::max);
        assert_eq!((a.band.lambda_s, a.band.lambda_c), (lo, hi));
        let with_data: Vec<usize> = (0..ms.len()).filter(|&i| spectra[i].psd.is_some()).collect();
        assert_eq!(a.measurements, with_data);
        // By hand.
        let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE).unwrap();
        let m = spectral_moments(&combined.psd, lo, hi).unwrap();
        assert_eq!((a.moments.m0, a.moments.m2, a.moments.m4), (m.m0, m.m2, m.m4));
        let r = roughness_from_moments(&m).unwrap();
        let physical = MATERIALS.with_roughness(m.m0.sqrt(), r.radius, r.eta);
        let Heights::Uniform(t) = &ms[a.heights_from].heights else {
            panic!("uniform heights")
        };
        let (nx, _) = ms[a.heights_from].grid();
        assert!(
            (nx as f64 * t.dx() / hi - 1.0).abs() < 0.5,
            "the heights come from the longest scan"
        );
        let surface = Surface::new(t.clone(), StatsOptions::default()).unwrap();
        let params = Params::from_physical(&physical)
            .unwrap()
            .distribution(surface.distribution(None).unwrap());
        assert_eq!(a.model, params);
        let model = Model::new(params).unwrap();
        for (load, f) in loads.iter().zip(&a.frictions) {
            let want = load.friction(&model, &physical).unwrap();
            assert_eq!(f.mu, want.mu);
            assert!(f.mu > 0.0);
        }
        // The record serialises with its warnings as {kind, message}.
        let v = serde_json::to_value(&a).unwrap();
        assert!(v["roughness"]["beta"].as_f64().unwrap() > 0.0);
        assert!(v["warnings"].is_array());
    }

    /// The scan over λs spans the union band from the smallest reliable
    /// scale towards λc, each row naming the measurements whose reliable
    /// range overlaps its band; rows over several measurements carry the
    /// spread of μ across them (min ≤ max, μ ≥ 0).
    fn check_scan(path: &std::path::Path) {
        let s = read_container(path, &ContainerOptions::default()).unwrap();
        let ms = &s[0].measurements;
        let spectra = measurement_spectra(ms);
        let resolved = Resolved::of(&spectra);
        let band = resolved.default_band().unwrap();
        let how = SurfaceModel::new(MATERIALS);
        let loads = [Load::Pressure(1e6)];
        let rows = container_scan(ms, &spectra, None, 5, &how, &loads).unwrap();
        assert_eq!(rows[0].band.lambda_s, band.lambda_s);
        let last = rows.last().unwrap().band.lambda_s;
        assert!(last < band.lambda_c && last * 10f64.powf(1.0 / 5.0) >= band.lambda_c * (1.0 - 1e-12));
        let decades = (band.lambda_c / band.lambda_s).log10();
        assert_eq!(rows.len(), (decades * 5.0).ceil() as usize);
        let mut spreads = 0;
        for row in &rows {
            assert_eq!(row.band.lambda_c, band.lambda_c);
            let want: Vec<usize> = resolved
                .ranges
                .iter()
                .enumerate()
                .filter(|(_, r)| r.is_some_and(|r| r.0 < band.lambda_c && r.1 > row.band.lambda_s))
                .map(|(i, _)| i)
                .collect();
            assert_eq!(row.measurements, want);
            assert!(!row.measurements.is_empty());
            if let Some(spread) = &row.spread {
                assert!(row.measurements.len() >= 2);
                assert!(
                    spread[0].0 <= spread[0].1 && spread[0].0 >= 0.0,
                    "{spread:?} {:?}",
                    row.band
                );
                spreads += 1;
            }
        }
        // The first row rests on the whole band: the same μ as the analysis.
        let a = container_analysis(ms, &spectra, Some(band), COMBINED_POINTS_PER_DECADE, &how, &loads).unwrap();
        assert_eq!(rows[0].result.as_ref().unwrap().frictions[0].mu, a.frictions[0].mu);
        assert!(spreads > 0, "some band rests on two or more measurements");
        // Rows carry serialisable records and errors.
        let v = serde_json::to_value(&rows).unwrap();
        assert_eq!(v.as_array().unwrap().len(), rows.len());
    }

    #[test]
    fn uniform_container_mu_from_the_whole_band() {
        let path = PathBuf::from(format!("{DATA}/uniform.zip"));
        check_whole_band(&path);
        check_scan(&path);
    }

    #[test]
    fn container_2_mu_from_the_whole_band() {
        if let Some(path) = crate::common::container_2() {
            check_whole_band(&path);
            check_scan(&path);
        }
    }

    /// A band that is not one is a clear error naming it.
    #[test]
    fn a_bad_band_is_refused() {
        let path = PathBuf::from(format!("{DATA}/uniform.zip"));
        let s = read_container(&path, &ContainerOptions::default()).unwrap();
        let ms = &s[0].measurements;
        let spectra = measurement_spectra(ms);
        let how = SurfaceModel::new(MATERIALS);
        for band in [
            Band {
                lambda_s: 1e-6,
                lambda_c: 1e-7,
            },
            Band {
                lambda_s: f64::NAN,
                lambda_c: 1e-3,
            },
            Band {
                lambda_s: 1e-3,
                lambda_c: 2e-3,
            },
        ] {
            let e = container_analysis(ms, &spectra, Some(band), 10, &how, &[]).unwrap_err();
            assert!(e.to_string().starts_with("band"), "{e}");
        }
        assert!(container_scan(ms, &spectra, Some(f64::INFINITY), 10, &how, &[]).is_err());
    }
}

/// SurfaceTopography's own container (`write_containers` of uniform.zip):
/// every measurement a `squeezed-netcdf` NetCDF-3 (64-bit offset) file,
/// its pipeline already applied; index.json beside meta.yml. The combined
/// PSD, moments and scale-dependent statistics against SurfaceTopography
/// reading it back, 1e-9 relative.
#[test]
fn squeezed_netcdf_container_matches_surface_topography() {
    let path = PathBuf::from(format!("{DATA}/squeezed.zip"));
    check_against_reference(&path, "squeezed");
    check_scale_dependent(&path, "squeezed");
    let s = read_container(&path, &ContainerOptions::default()).unwrap();
    for m in &s[0].measurements {
        assert!(m.data_file.ends_with(".nc"), "{}", m.data_file);
        // Squeezed: the metadata's detrend_mode (center) is not applied
        // again.
        assert_eq!(m.detrend, ke_friction::topography::container::DetrendMode::None);
    }
    assert_eq!(s[0].measurements[1].grid(), (64, 64));
}

/// The nonuniform profile of synthetic.zip as SurfaceTopography squeezes
/// it (its NetCDF file: dimension n, positions x, the tip radius in the
/// `json` attribute): the same positions, heights and tip radius as read
/// from the original x z text and detrended here.
#[test]
fn squeezed_nonuniform_profile_equals_the_original() {
    let opts = ContainerOptions::default();
    let squeezed = read_container(format!("{DATA}/squeezed-nonuniform.zip").as_ref(), &opts).unwrap();
    let original = read_container(format!("{DATA}/synthetic.zip").as_ref(), &opts).unwrap();
    let (a, b) = (&squeezed[0].measurements[0], &original[0].measurements[2]);
    let (Heights::Nonuniform { x: xa, z: za }, Heights::Nonuniform { x: xb, z: zb }) = (&a.heights, &b.heights) else {
        panic!("both nonuniform")
    };
    assert_eq!(xa.len(), xb.len());
    let scale = zb.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..xa.len() {
        assert!((xa[k] - xb[k]).abs() <= 1e-12 * xb[xb.len() - 1], "x[{k}]");
        assert!((za[k] - zb[k]).abs() <= 1e-9 * scale, "z[{k}]: {} vs {}", za[k], zb[k]);
    }
    assert_eq!(a.tip_radius, Some(40e-9), "from the NetCDF file's json attribute");
    let (ca, cb) = (measurement_psd(a).cutoff.unwrap(), measurement_psd(b).cutoff.unwrap());
    assert!((ca / cb - 1.0).abs() < 1e-9, "tip cut-off {ca} vs {cb}");
}

/// A NetCDF-3 classic file: dimensions `dims`, one variable `heights`
/// over `var_dims` (f64, big-endian), `unit` "nm" on it; `lie` rewrites
/// the header before the data.
fn netcdf(dims: &[(&str, u32)], var_dims: &[u32], heights: &[f64], lie: impl Fn(&mut Vec<u8>)) -> Vec<u8> {
    fn name(out: &mut Vec<u8>, s: &str) {
        out.extend((s.len() as u32).to_be_bytes());
        out.extend(s.as_bytes());
        out.extend(std::iter::repeat_n(0u8, (4 - s.len() % 4) % 4));
    }
    let mut h = b"CDF\x01".to_vec();
    h.extend(0u32.to_be_bytes());
    h.extend(10u32.to_be_bytes());
    h.extend((dims.len() as u32).to_be_bytes());
    for (n, len) in dims {
        name(&mut h, n);
        h.extend(len.to_be_bytes());
    }
    h.extend([0u8; 8]);
    h.extend(11u32.to_be_bytes());
    h.extend(1u32.to_be_bytes());
    name(&mut h, "heights");
    h.extend((var_dims.len() as u32).to_be_bytes());
    for d in var_dims {
        h.extend(d.to_be_bytes());
    }
    h.extend(12u32.to_be_bytes());
    h.extend(1u32.to_be_bytes());
    name(&mut h, "unit");
    h.extend(2u32.to_be_bytes());
    h.extend(2u32.to_be_bytes());
    h.extend(b"nm\0\0");
    h.extend(6u32.to_be_bytes());
    h.extend((8 * heights.len() as u32).to_be_bytes());
    let begin = h.len() as u32 + 4;
    h.extend(begin.to_be_bytes());
    for v in heights {
        h.extend(v.to_be_bytes());
    }
    lie(&mut h);
    h
}

fn squeezed_meta(size: &str) -> String {
    format!("surfaces:\n- topographies:\n  - datafile: {{squeezed-netcdf: m.nc}}\n    unit: um\n    size: {size}\n")
}

/// NetCDF files written here (classic format): a profile and a map read
/// with the file's unit and the metadata's size, the map's [x][y] order
/// kept; hostile ones refused with the member named.
#[test]
fn netcdf_members_read_or_refused_naming_the_file() {
    let h: Vec<f64> = (0..6).map(|i| f64::from(i * i)).collect();
    let nc = netcdf(&[("x", 6)], &[0], &h, |_| {});
    let z = zip_of(&[("meta.yml", squeezed_meta("[3.0]").as_bytes()), ("m.nc", &nc)]);
    let s = read_container_bytes(&z, "c.zip", &ContainerOptions::default()).unwrap();
    let Heights::Uniform(t) = &s[0].measurements[0].heights else {
        panic!()
    };
    // The file's unit (nm) for the heights and the size (its own unit too,
    // as SurfaceTopography does): 3 nm over 6 points.
    assert_eq!(t.nx(), 6);
    assert!((t.dx() - 0.5e-9).abs() < 1e-24);
    assert!((t.heights()[5] - 25e-9).abs() < 1e-20, "not detrended: squeezed");
    // A map stored [x][y] (3 × 2): h[x=i][y=j] = 10 i + j.
    let m: Vec<f64> = (0..3)
        .flat_map(|i| (0..2).map(move |j| f64::from(10 * i + j)))
        .collect();
    let nc = netcdf(&[("x", 3), ("y", 2)], &[0, 1], &m, |_| {});
    let z = zip_of(&[("meta.yml", squeezed_meta("[3.0, 2.0]").as_bytes()), ("m.nc", &nc)]);
    let s = read_container_bytes(&z, "c.zip", &ContainerOptions::default()).unwrap();
    let Heights::Uniform(t) = &s[0].measurements[0].heights else {
        panic!()
    };
    assert_eq!((t.nx(), t.ny()), (3, 2));
    // Row j = 1, column i = 2: 21 nm.
    assert!((t.heights()[3 + 2] - 21e-9).abs() < 1e-20);
    // Hostile files: each refused, naming m.nc.
    let hostile: Vec<(&str, Vec<u8>)> = vec![
        ("truncated", nc[..nc.len() - 5].to_vec()),
        ("CDF-5", netcdf(&[("x", 6)], &[0], &h, |b| b[3] = 5)),
        ("not NetCDF", b"hello".to_vec()),
        (
            "a billion dimensions",
            netcdf(&[("x", 6)], &[0], &h, |b| {
                b[12..16].copy_from_slice(&1_000_000_000u32.to_be_bytes())
            }),
        ),
        ("a huge dimension", netcdf(&[("x", 4_000_000_000)], &[0], &h, |_| {})),
        ("a record dimension", netcdf(&[("x", 0)], &[0], &h, |_| {})),
        ("a dimension id out of range", netcdf(&[("x", 6)], &[7], &h, |_| {})),
        ("heights over (x, x)", netcdf(&[("x", 6)], &[0, 0], &h, |_| {})),
    ];
    for (what, nc) in hostile {
        let z = zip_of(&[("meta.yml", squeezed_meta("[3.0]").as_bytes()), ("m.nc", &nc)]);
        let e = read(&z).expect_err(what);
        assert!(e.contains("m.nc"), "{what}: {e}");
        assert!(!e.contains('\n'), "{what}: one line: {e}");
    }
}
