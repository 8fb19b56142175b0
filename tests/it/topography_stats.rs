//! Surface statistics (MODEL.md §10, `Topography::stats` and `combine`)
//! against the independent NumPy reference `tools/surface_reference.py`
//! (tests/data/surface_reference.json), a band-limited periodic surface
//! whose spectral moments are known exactly, a brute-force computation of
//! the masked case, and the refusals.
use crate::common::assert_rel;
use ke_friction::topography::{
    combine, Derivative, Detrend, StatsError, StatsOptions, SurfaceStats, Topography, Warning, HEIGHT_MAX,
    PRECISION_MIN, SIGMA_MIN,
};
use serde_json::Value;
use std::f64::consts::PI;

/// Agreement with the float64 NumPy reference and with exact values.
const REL: f64 = 1e-12;

/// Asserts that `got`'s statistics `names` (their record names) are
/// `want`'s to `tol` relative; `what` names the case.
fn assert_stats(what: &str, got: &SurfaceStats, want: &SurfaceStats, names: &[&str], tol: f64) {
    let (got, want) = (serde_json::to_value(got).unwrap(), serde_json::to_value(want).unwrap());
    for name in names {
        let value = |v: &serde_json::Value| v[*name].as_f64().unwrap_or_else(|| panic!("{what}: no {name}"));
        assert_rel(&format!("{what} {name}"), value(&got), value(&want), tol);
    }
}

// ---------------------------------------------------------------------------
// The synthetic surfaces of tools/surface_reference.py (see its docstring).

fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

fn uniform(seed: u64, k: u64) -> f64 {
    (splitmix64((seed << 32) + k) >> 11) as f64 * 2f64.powi(-53)
}

/// A synthetic surface of `tools/surface_reference.py` (also the
/// end-to-end test's, `surface_friction.rs`).
pub(crate) fn synthetic(nx: usize, ny: usize, seed: u64, missing: f64) -> Vec<f64> {
    (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            let u = uniform(seed, k as u64) - 0.5;
            let z = 1e-3 + 2e-8 * i - 1e-8 * j
                + 1e-7 * ((0.21 * i + 0.13 * j + 0.5).sin() + 0.6 * (0.047 * i - 0.09 * j).cos())
                + 3e-8 * (u + 0.8 * u * u);
            if missing > 0.0 && uniform(seed + 1, k as u64) < missing {
                f64::NAN
            } else {
                z
            }
        })
        .collect()
}

fn reference() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/surface_reference.json");
    let text = std::fs::read_to_string(path).expect("tests/data/surface_reference.json");
    serde_json::from_str(&text).expect("valid JSON")
}

fn options(detrend: &str, derivative: &str) -> StatsOptions {
    StatsOptions {
        detrend: match detrend {
            "plane" => Detrend::Plane,
            "line" => Detrend::Line,
            "mean" => Detrend::Mean,
            other => panic!("detrend {other}"),
        },
        derivative: match derivative {
            "fd" => Derivative::FiniteDifference,
            "spectral" => Derivative::Spectral,
            other => panic!("derivative {other}"),
        },
        ..StatsOptions::default()
    }
}

fn case_stats(case: &Value) -> SurfaceStats {
    let nx = case["nx"].as_u64().unwrap() as usize;
    let dx = case["dx"].as_f64().unwrap();
    let seed = case["seed"].as_u64().unwrap();
    let missing = case["missing"].as_f64().unwrap();
    let t = match case["ny"].as_u64() {
        Some(ny) => {
            let ny = ny as usize;
            Topography::map(
                synthetic(nx, ny, seed, missing),
                nx,
                ny,
                dx,
                case["dy"].as_f64().unwrap(),
            )
            .unwrap()
        }
        None => Topography::profile(synthetic(nx, 1, seed, missing), dx).unwrap(),
    };
    let o = options(case["detrend"].as_str().unwrap(), case["derivative"].as_str().unwrap());
    t.stats(&o).unwrap()
}

/// Every field of `got` against the reference record `want`.
fn compare(what: &str, got: &SurfaceStats, want: &Value, tol: f64) {
    let got = serde_json::to_value(got).unwrap();
    for key in [
        "points",
        "missing",
        "nx",
        "ny",
        "dx",
        "dy",
        "sigma",
        "skewness",
        "kurtosis",
        "m20",
        "m02",
        "m40",
        "m04",
        "m2",
        "m4",
        "alpha",
        "eta",
        "radius",
        "beta",
        "sigma_s",
        "y_s",
        "anisotropy_m2",
        "anisotropy_m4",
    ] {
        let (g, w) = (&got[key], &want[key]);
        match (g.as_f64(), w.as_f64()) {
            // Sk is a difference of large terms and may be near 0: its
            // error is absolute (relative to 1, the scale of Sk).
            (Some(g), Some(w)) if key == "skewness" => {
                assert!((g - w).abs() <= tol, "{what}: skewness: got {g:e}, want {w:e}")
            }
            (Some(g), Some(w)) => assert_rel(&format!("{what}: {key}"), g, w, tol),
            _ => assert_eq!(g, w, "{what}: {key}"),
        }
    }
}

#[test]
fn agrees_with_the_numpy_reference() {
    let doc = reference();
    let cases = doc["cases"].as_array().unwrap();
    assert!(cases.len() >= 10);
    for case in cases {
        let name = case["name"].as_str().unwrap();
        compare(name, &case_stats(case), &case["stats"], REL);
    }
}

#[test]
fn combinations_agree_with_the_numpy_reference() {
    let doc = reference();
    let cases = doc["cases"].as_array().unwrap();
    let find = |name: &str| case_stats(cases.iter().find(|c| c["name"] == name).unwrap());
    for combo in doc["combinations"].as_array().unwrap() {
        let (a, b) = (combo["first"].as_str().unwrap(), combo["second"].as_str().unwrap());
        let got = combine(&find(a), &find(b)).unwrap();
        compare(&format!("{a} + {b}"), &got, &combo["stats"], REL);
    }
}

#[test]
fn record_fields_and_warnings() {
    let doc = reference();
    let case = &doc["cases"][0];
    let stats = case_stats(case);
    let json = serde_json::to_value(&stats).unwrap();
    let keys: Vec<&str> = json.as_object().unwrap().keys().map(String::as_str).collect();
    for key in [
        "points", "sigma", "kurtosis", "m02", "alpha", "eta", "radius", "beta", "sigma_s", "y_s", "warnings",
    ] {
        assert!(keys.contains(&key), "{key} missing from {keys:?}");
    }
    // map_plane is anisotropic (m20/m02 ≈ 3.8): warned, with a message.
    assert!(stats.anisotropy_m2.unwrap() > 1.25);
    assert!(stats
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::Anisotropy { ratio: "m20/m02", .. })));
    let w = &json["warnings"][0];
    assert_eq!(w["kind"], "anisotropy");
    assert!(w["message"].as_str().unwrap().contains("m20/m02"));
}

// ---------------------------------------------------------------------------
// A band-limited periodic surface: exact spectral moments.

/// (amplitude, p, q, phase): A·cos(2π(p·i/nx + q·j/ny) + φ).
const WAVES: [(f64, f64, f64, f64); 5] = [
    (1.0e-6, 3.0, 1.0, 0.3),
    (0.5e-6, 7.0, -4.0, 1.1),
    (0.3e-6, 12.0, 9.0, -0.7),
    (0.2e-6, 1.0, 15.0, 2.0),
    (0.1e-6, 25.0, -20.0, 0.4),
];

fn band_limited(nx: usize, ny: usize, waves: &[(f64, f64, f64, f64)]) -> Vec<f64> {
    (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            2e-4 + waves
                .iter()
                .map(|&(a, p, q, phi)| a * (2.0 * PI * (p * i / nx as f64 + q * j / ny as f64) + phi).cos())
                .sum::<f64>()
        })
        .collect()
}

/// m0, m20, m40, m02, m04 of the waves, exactly.
fn exact_moments(waves: &[(f64, f64, f64, f64)], lx: f64, ly: f64) -> [f64; 5] {
    let mut m = [0.0; 5];
    for &(a, p, q, _) in waves {
        let (kx, ky) = (2.0 * PI * p / lx, 2.0 * PI * q / ly);
        let e = 0.5 * a * a;
        m[0] += e;
        m[1] += e * kx.powi(2);
        m[2] += e * kx.powi(4);
        m[3] += e * ky.powi(2);
        m[4] += e * ky.powi(4);
    }
    m
}

const SPECTRAL: StatsOptions = StatsOptions {
    detrend: Detrend::Mean,
    derivative: Derivative::Spectral,
    lambda_s: None,
    lambda_c: None,
};

#[test]
fn spectral_moments_of_a_band_limited_surface_are_exact() {
    // 64 × 48: a power-of-two length along x, another along y (and the other way
    // round); Δx ≠ Δy.
    for (nx, ny) in [(64, 48), (56, 64), (64, 64)] {
        let (dx, dy) = (0.7e-6, 1.3e-6);
        let t = Topography::map(band_limited(nx, ny, &WAVES), nx, ny, dx, dy).unwrap();
        let s = t.stats(&SPECTRAL).unwrap();
        let [m0, m20, m40, m02, m04] = exact_moments(&WAVES, nx as f64 * dx, ny as f64 * dy);
        let what = format!("{nx}x{ny}");
        assert_rel(&format!("{what} m0"), s.sigma * s.sigma, m0, REL);
        assert_rel(&format!("{what} m20"), s.m20, m20, REL);
        assert_rel(&format!("{what} m40"), s.m40, m40, REL);
        assert_rel(&format!("{what} m02"), s.m02.unwrap(), m02, REL);
        assert_rel(&format!("{what} m04"), s.m04.unwrap(), m04, REL);
        assert_rel(&format!("{what} m2"), s.m2, 0.5 * (m20 + m02), REL);
        assert_rel(&format!("{what} m4"), s.m4, 0.5 * (m40 + m04), REL);
        let m2 = 0.5 * (m20 + m02);
        let m4 = 0.5 * (m40 + m04);
        let alpha = m0 * m4 / (m2 * m2);
        assert_rel(&format!("{what} alpha"), s.alpha, alpha, REL);
        assert_rel(
            &format!("{what} beta"),
            s.beta,
            alpha.sqrt() / (16.0 * (3.0 * PI).sqrt()),
            REL,
        );
        assert_rel(&format!("{what} eta"), s.eta, m4 / (6.0 * PI * 3f64.sqrt() * m2), REL);
        assert_rel(&format!("{what} R"), s.radius, 0.375 * (PI / m4).sqrt(), REL);
        let c = 16.0 / PI - 3.0 * 3f64.sqrt() + 1.0;
        assert_rel(
            &format!("{what} sigma_s"),
            s.sigma_s,
            m0.sqrt() * (1.0 - c / alpha).sqrt(),
            REL,
        );
        assert_rel(&format!("{what} y_s"), s.y_s, 4.0 * (m0 / (PI * alpha)).sqrt(), REL);
    }
    // A profile of 1000 points (not a power of two).
    let waves: Vec<_> = WAVES.iter().map(|&(a, p, _, phi)| (a, 4.0 * p, 0.0, phi)).collect();
    let (n, dx) = (1000, 2e-7);
    let t = Topography::profile(band_limited(n, 1, &waves), dx).unwrap();
    let s = t.stats(&SPECTRAL).unwrap();
    let [m0, m20, m40, _, _] = exact_moments(&waves, n as f64 * dx, 1.0);
    assert_rel("profile m0", s.sigma * s.sigma, m0, REL);
    assert_rel("profile m2", s.m2, m20, REL);
    assert_rel("profile m4", s.m4, m40, REL);
    assert_eq!((s.m02, s.m04, s.dy, s.ny), (None, None, None, 1));
}

#[test]
fn finite_differences_of_a_band_limited_surface() {
    // Along x the non-periodic differences of a periodic surface: the mean
    // over the nx − 1 pairs of each row; compare with the exact discrete
    // values of a single wave along x, 2 sin(πp/nx)/Δx per unit amplitude,
    // over whole periods (pairs wrap except the last one).
    let (nx, ny, dx, dy) = (128, 32, 1e-6, 2e-6);
    let waves = [(1e-6, 4.0, 0.0, 0.0)];
    let t = Topography::map(band_limited(nx, ny, &waves), nx, ny, dx, dy).unwrap();
    let o = StatsOptions {
        detrend: Detrend::Mean,
        derivative: Derivative::FiniteDifference,
        lambda_s: None,
        lambda_c: None,
    };
    // The surface is constant along y: m02 = 0 is refused.
    assert!(matches!(t.stats(&o), Err(StatsError::OutOfRange { name: "m02", .. })));
    // A profile: brute force.
    let t = Topography::profile(band_limited(nx, 1, &waves), dx).unwrap();
    let s = t.stats(&o).unwrap();
    let z = t.heights();
    let d: Vec<f64> = z.windows(2).map(|w| ((w[1] - w[0]) / dx).powi(2)).collect();
    let e: Vec<f64> = z
        .windows(3)
        .map(|w| ((w[2] - 2.0 * w[1] + w[0]) / (dx * dx)).powi(2))
        .collect();
    assert_rel("m20", s.m20, d.iter().sum::<f64>() / d.len() as f64, 1e-12);
    assert_rel("m40", s.m40, e.iter().sum::<f64>() / e.len() as f64, 1e-12);
    // One wave: α = 1 to within the edge effects, so a warning.
    assert!((s.alpha - 1.0).abs() < 0.05, "alpha = {}", s.alpha);
    assert!(s.warnings.iter().any(|w| matches!(w, Warning::LowBandwidth { .. })));
}

// ---------------------------------------------------------------------------
// Missing points: a brute-force computation.

/// The statistics the straightforward way: a detrended copy of the map,
/// two-pass moments, explicit loops over the differences.
fn brute_force(z: &[f64], nx: usize, ny: usize, dx: f64, dy: f64) -> [f64; 8] {
    let at = |i: usize, j: usize| z[j * nx + i];
    let valid: Vec<(usize, usize)> = (0..ny)
        .flat_map(|j| (0..nx).map(move |i| (i, j)))
        .filter(|&(i, j)| !at(i, j).is_nan())
        .collect();
    // Normal equations of z = a + b·x + c·y (x, y in metres), with the
    // mean height removed first; Gaussian elimination.
    let n = valid.len() as f64;
    let zm = valid.iter().map(|&(i, j)| at(i, j)).sum::<f64>() / n;
    let xm = valid.iter().map(|&(i, _)| i as f64 * dx).sum::<f64>() / n;
    let ym = valid.iter().map(|&(_, j)| j as f64 * dy).sum::<f64>() / n;
    let mut m = [[0.0; 3]; 2];
    for &(i, j) in &valid {
        let (x, y, h) = (i as f64 * dx - xm, j as f64 * dy - ym, at(i, j) - zm);
        m[0][0] += x * x;
        m[0][1] += x * y;
        m[1][1] += y * y;
        m[0][2] += x * h;
        m[1][2] += y * h;
    }
    let det = m[0][0] * m[1][1] - m[0][1] * m[0][1];
    let b = (m[0][2] * m[1][1] - m[1][2] * m[0][1]) / det;
    let c = (m[1][2] * m[0][0] - m[0][2] * m[0][1]) / det;
    let r = |i: usize, j: usize| (at(i, j) - zm) - b * (i as f64 * dx - xm) - c * (j as f64 * dy - ym);
    let rs: Vec<f64> = valid.iter().map(|&(i, j)| r(i, j)).collect();
    let mean = rs.iter().sum::<f64>() / n;
    let mom = |p: i32| rs.iter().map(|x| (x - mean).powi(p)).sum::<f64>() / n;
    let (m2, m3, m4) = (mom(2), mom(3), mom(4));
    let mean_sq = |v: Vec<f64>| v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64;
    let mut d20 = Vec::new();
    let mut d40 = Vec::new();
    let mut d02 = Vec::new();
    let mut d04 = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            if i + 1 < nx && !(at(i, j).is_nan() || at(i + 1, j).is_nan()) {
                d20.push((r(i + 1, j) - r(i, j)) / dx);
            }
            if i + 2 < nx && !(at(i, j).is_nan() || at(i + 1, j).is_nan() || at(i + 2, j).is_nan()) {
                d40.push((r(i + 2, j) - 2.0 * r(i + 1, j) + r(i, j)) / (dx * dx));
            }
            if j + 1 < ny && !(at(i, j).is_nan() || at(i, j + 1).is_nan()) {
                d02.push((r(i, j + 1) - r(i, j)) / dy);
            }
            if j + 2 < ny && !(at(i, j).is_nan() || at(i, j + 1).is_nan() || at(i, j + 2).is_nan()) {
                d04.push((r(i, j + 2) - 2.0 * r(i, j + 1) + r(i, j)) / (dy * dy));
            }
        }
    }
    [
        m2.sqrt(),
        m3 / m2.powf(1.5),
        m4 / (m2 * m2),
        mean_sq(d20),
        mean_sq(d40),
        mean_sq(d02),
        mean_sq(d04),
        valid.len() as f64,
    ]
}

#[test]
fn missing_points_match_a_brute_force_computation() {
    let (nx, ny, dx, dy) = (41, 37, 0.4e-6, 0.9e-6);
    // Remove the large offset (the brute force is plain arithmetic), keep
    // the tilt; 10 % missing, and a missing row and column.
    let mut z: Vec<f64> = synthetic(nx, ny, 21, 0.1).iter().map(|h| h - 1e-3).collect();
    for i in 0..nx {
        z[5 * nx + i] = f64::NAN;
    }
    for j in 0..ny {
        z[j * nx + 30] = f64::NAN;
    }
    let t = Topography::map(z.clone(), nx, ny, dx, dy).unwrap();
    let s = t.stats(&StatsOptions::default()).unwrap();
    let [sigma, sk, k, m20, m40, m02, m04, points] = brute_force(&z, nx, ny, dx, dy);
    assert_eq!(s.points as f64, points);
    assert_eq!(s.points + s.missing, nx * ny);
    let tol = 1e-11;
    assert_rel("sigma", s.sigma, sigma, tol);
    assert_rel("skewness", s.skewness, sk, tol);
    assert_rel("kurtosis", s.kurtosis, k, tol);
    assert_rel("m20", s.m20, m20, tol);
    assert_rel("m40", s.m40, m40, tol);
    assert_rel("m02", s.m02.unwrap(), m02, tol);
    assert_rel("m04", s.m04.unwrap(), m04, tol);
}

#[test]
fn missing_points_at_the_ends_of_a_profile_are_left_out() {
    // Leading and trailing NaN: the same statistics as the profile without
    // them (line and mean detrending).
    let z = synthetic(600, 1, 4, 0.0);
    let mut masked = z.clone();
    for (i, h) in masked.iter_mut().enumerate() {
        if !(37..600 - 11).contains(&i) {
            *h = f64::NAN;
        }
    }
    let full = Topography::profile(z[37..600 - 11].to_vec(), 1e-7).unwrap();
    let masked = Topography::profile(masked, 1e-7).unwrap();
    for detrend in [Detrend::Plane, Detrend::Line, Detrend::Mean] {
        let o = StatsOptions {
            detrend,
            ..StatsOptions::default()
        };
        let (a, b) = (full.stats(&o).unwrap(), masked.stats(&o).unwrap());
        assert_eq!((b.points, b.missing, b.nx), (600 - 48, 48, 600));
        let names = ["sigma", "skewness", "kurtosis", "m2", "m4", "beta"];
        assert_stats(&format!("{detrend:?}"), &b, &a, &names, 1e-12);
    }
}

// ---------------------------------------------------------------------------
// Intervals, profiles and maps.

#[test]
fn each_direction_has_its_own_interval() {
    let (nx, ny) = (48, 40);
    let z = synthetic(nx, ny, 2, 0.0);
    let a = Topography::map(z.clone(), nx, ny, 1e-6, 1e-6).unwrap();
    let b = Topography::map(z, nx, ny, 1e-6, 2.5e-6).unwrap();
    let o = StatsOptions::default();
    let (a, b) = (a.stats(&o).unwrap(), b.stats(&o).unwrap());
    assert_rel("m20", b.m20, a.m20, 1e-14);
    assert_rel("m40", b.m40, a.m40, 1e-14);
    assert_rel("m02", b.m02.unwrap(), a.m02.unwrap() / 2.5f64.powi(2), 1e-14);
    assert_rel("m04", b.m04.unwrap(), a.m04.unwrap() / 2.5f64.powi(4), 1e-14);
    assert_rel("sigma", b.sigma, a.sigma, 1e-14);
    assert_eq!((b.dx, b.dy), (1e-6, Some(2.5e-6)));
}

#[test]
fn a_map_is_its_rows_in_x() {
    // Mean detrending leaves the differences alone: m20, m40 of a map are
    // the means of its rows' (same number of pairs per row).
    let (nx, ny, dx) = (120, 24, 0.3e-6);
    let z = synthetic(nx, ny, 8, 0.0);
    let o = StatsOptions {
        detrend: Detrend::Mean,
        ..StatsOptions::default()
    };
    let map = Topography::map(z.clone(), nx, ny, dx, dx).unwrap().stats(&o).unwrap();
    let rows: Vec<SurfaceStats> = z
        .chunks(nx)
        .map(|row| Topography::profile(row.to_vec(), dx).unwrap().stats(&o).unwrap())
        .collect();
    let mean = |f: fn(&SurfaceStats) -> f64| rows.iter().map(f).sum::<f64>() / ny as f64;
    assert_rel("m20", map.m20, mean(|s| s.m20), 1e-13);
    assert_rel("m40", map.m40, mean(|s| s.m40), 1e-13);
    let row = &rows[0];
    assert_eq!((row.ny, row.dy, row.m02, row.m04), (1, None, None, None));
    assert_eq!((row.anisotropy_m2, row.anisotropy_m4), (None, None));
    assert_eq!(row.m2, row.m20);
    assert_rel("map m2", map.m2, 0.5 * (map.m20 + map.m02.unwrap()), 1e-15);
}

// ---------------------------------------------------------------------------
// Two surfaces.

#[test]
fn the_sum_of_two_surfaces() {
    // Two band-limited surfaces with disjoint wave vectors: their sum's
    // spectral moments are the sums, exactly.
    let (nx, ny, dx, dy) = (64, 64, 1e-6, 1.5e-6);
    let first = &WAVES[..3];
    let second = &WAVES[3..];
    let stats = |waves: &[(f64, f64, f64, f64)]| {
        Topography::map(band_limited(nx, ny, waves), nx, ny, dx, dy)
            .unwrap()
            .stats(&SPECTRAL)
            .unwrap()
    };
    let (a, b, both) = (stats(first), stats(second), stats(&WAVES));
    let sum = combine(&a, &b).unwrap();
    let names = [
        "sigma", "m20", "m02", "m40", "m04", "m2", "m4", "alpha", "eta", "radius", "beta", "sigma_s", "y_s",
    ];
    assert_stats("pair", &sum, &both, &names, REL);
    // Cumulants add.
    let (va, vb) = (a.sigma.powi(2), b.sigma.powi(2));
    let v = va + vb;
    assert_rel(
        "skewness",
        sum.skewness * v.powf(1.5),
        a.skewness * va.powf(1.5) + b.skewness * vb.powf(1.5),
        1e-13,
    );
    assert_rel(
        "excess kurtosis",
        (sum.kurtosis - 3.0) * v * v,
        (a.kurtosis - 3.0) * va * va + (b.kurtosis - 3.0) * vb * vb,
        1e-12,
    );
    // Intervals of the first; a mismatch over 1 % is reported.
    assert!(!sum
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::IntervalMismatch { .. })));
    let c = Topography::map(band_limited(nx, ny, second), nx, ny, 1.02 * dx, dy)
        .unwrap()
        .stats(&SPECTRAL)
        .unwrap();
    let mixed = combine(&a, &c).unwrap();
    assert_eq!(mixed.dx, a.dx);
    assert!(mixed
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::IntervalMismatch { name: "dx", .. })));
    // A profile and a map do not combine.
    let profile = Topography::profile(synthetic(500, 1, 3, 0.0), 1e-7)
        .unwrap()
        .stats(&StatsOptions::default())
        .unwrap();
    assert_eq!(combine(&a, &profile), Err(StatsError::Mismatch));
    assert!(combine(&profile, &profile).is_ok());
}

// ---------------------------------------------------------------------------
// Refusals.

#[test]
fn refusals_name_the_value() {
    let o = StatsOptions::default();
    let refused = |t: Result<Topography, _>| t.unwrap().stats(&o).unwrap_err();
    // The direction's name and count of a TooFewPoints refusal.
    let too_few = |e: &StatsError| match e {
        StatsError::TooFewPoints { name, count, .. } => Some((*name, *count)),
        _ => None,
    };
    // Fewer than 16 points along a direction.
    let e = refused(Topography::profile(synthetic(15, 1, 1, 0.0), 1e-6));
    assert_eq!(too_few(&e), Some(("nx", 15)), "{e}");
    assert!(e.to_string().contains("nx = 15"), "{e}");
    let e = refused(Topography::map(synthetic(100, 15, 1, 0.0), 100, 15, 1e-6, 1e-6));
    assert_eq!(too_few(&e), Some(("ny", 15)), "{e}");
    // Fewer than 100 valid points.
    let e = refused(Topography::profile(synthetic(99, 1, 1, 0.0), 1e-6));
    assert!(matches!(e, StatsError::TooFewValid { valid: 99, .. }), "{e}");
    let e = Topography::map(vec![f64::NAN; 400], 20, 20, 1e-6, 1e-6)
        .unwrap()
        .stats(&o)
        .unwrap_err();
    assert!(matches!(e, StatsError::TooFewValid { valid: 0, missing: 400 }), "{e}");
    // Too many missing points between: every other point.
    let z: Vec<f64> = synthetic(400, 1, 1, 0.0)
        .iter()
        .enumerate()
        .map(|(i, &h)| if i % 2 == 0 { h } else { f64::NAN })
        .collect();
    let e = refused(Topography::profile(z, 1e-6));
    assert!(
        matches!(e, StatsError::TooFewDifferences { name: "m20", count: 0 }),
        "{e}"
    );
    // Constant data, and an exact plane (constant after detrending).
    let e = Topography::profile(vec![2.5e-6; 200], 1e-6)
        .unwrap()
        .stats(&o)
        .unwrap_err();
    assert!(matches!(e, StatsError::Constant { .. }), "{e}");
    let plane: Vec<f64> = (0..40 * 30)
        .map(|k| 1e-3 + 3e-7 * (k % 40) as f64 - 2e-7 * (k / 40) as f64)
        .collect();
    let e = refused(Topography::map(plane, 40, 30, 1e-6, 1e-6));
    assert!(matches!(e, StatsError::Constant { .. }), "{e}");
    // α ≤ 0.8968: a ramp with a little noise, only its mean removed.
    let ramp: Vec<f64> = (0..200)
        .map(|i| 1e-6 * i as f64 + 1e-9 * (uniform(3, i) - 0.5))
        .collect();
    let mean_only = StatsOptions {
        detrend: Detrend::Mean,
        ..o
    };
    let e = Topography::profile(ramp, 1e-6).unwrap().stats(&mean_only).unwrap_err();
    match e {
        StatsError::Bandwidth { alpha, beta } => {
            assert!(alpha < 0.8968, "{alpha}");
            assert_rel("beta", beta, alpha.sqrt() / (16.0 * (3.0 * PI).sqrt()), 1e-14);
        }
        other => panic!("{other}"),
    }
    assert!(
        e.to_string().contains("alpha = ") && e.to_string().contains("0.8968"),
        "{e}"
    );
    // The spectral estimate refuses missing points.
    let e = Topography::map(synthetic(32, 32, 1, 0.05), 32, 32, 1e-6, 1e-6)
        .unwrap()
        .stats(&SPECTRAL)
        .unwrap_err();
    assert!(matches!(e, StatsError::MissingPoints { .. }), "{e}");
    // Every point on one column: the plane is undetermined.
    let column: Vec<f64> = (0..32 * 32)
        .map(|k| if k % 32 == 3 { uniform(1, k as u64) } else { f64::NAN })
        .collect();
    assert!(Topography::map(column, 32, 32, 1e-6, 1e-6).unwrap().stats(&o).is_err());
}

#[test]
fn extreme_inputs_are_refused_not_panicked_on() {
    let o = StatsOptions::default();
    let base = synthetic(64, 64, 6, 0.0);
    for (scale, dx) in [
        (1e200, 1.0),
        (1e-200, 1.0),
        (1.0, 1e-300),
        (1.0, 1e300),
        (1e300, 1e-300),
    ] {
        let z: Vec<f64> = base.iter().map(|h| (h - 1e-3) * scale).collect();
        let t = Topography::map(z, 64, 64, dx, dx).unwrap();
        for derivative in [Derivative::FiniteDifference, Derivative::Spectral] {
            if let Ok(s) = t.stats(&StatsOptions { derivative, ..o }) {
                for v in [s.sigma, s.m2, s.m4, s.alpha, s.beta, s.eta, s.radius, s.sigma_s, s.y_s] {
                    assert!(v.is_finite() && v > 0.0, "scale {scale}, dx {dx}: {s:?}");
                }
            }
        }
    }
}

/// Heights at the limits of f64 are refused with the cause (overflow,
/// underflow, rounding against the offset), not called constant or given
/// a skewness "out of range".
#[test]
fn heights_at_the_limits_of_f64_name_the_cause() {
    let o = StatsOptions::default();
    let base = synthetic(64, 64, 6, 0.0);
    let stats = |f: &dyn Fn(f64) -> f64| {
        let z: Vec<f64> = base.iter().map(|&h| f(h - 1e-3)).collect();
        Topography::map(z, 64, 64, 1e-6, 1e-6).unwrap().stats(&o)
    };
    let max_abs = base.iter().map(|h| (h - 1e-3).abs()).fold(0.0, f64::max);
    // The error's message, which must hold each of `words`.
    let says = |e: &StatsError, words: &[&str]| {
        let text = e.to_string();
        for w in words {
            assert!(text.contains(w), "{w:?} not in {text}");
        }
        text
    };

    // Overflow: scaled to 1e150 (the fourth powers overflow, the skewness
    // was NaN) and to 1e200 (the squares overflow, it was "constant").
    for top in [1e76, 1e150, 1e200, 1e300] {
        let e = stats(&|h| h / max_abs * top).unwrap_err();
        match &e {
            StatsError::Overflow { max_abs, bound } => {
                assert_rel("max_abs", *max_abs, top, 1e-12);
                assert_eq!(*bound, HEIGHT_MAX);
            }
            other => panic!("top {top}: {other}"),
        }
        let text = says(&e, &["must be below 1e75 m", "overflow"]);
        assert!(!text.contains("constant") && !text.contains("NaN"), "{text}");
    }
    // ±1e150 exactly, alternating (a checkerboard).
    let z: Vec<f64> = (0..64 * 64)
        .map(|k| if (k % 64 + k / 64) % 2 == 0 { 1e150 } else { -1e150 })
        .collect();
    let e = Topography::map(z, 64, 64, 1e-6, 1e-6).unwrap().stats(&o).unwrap_err();
    assert!(matches!(e, StatsError::Overflow { max_abs: 1e150, .. }), "{e}");

    // Underflow: scaled by 1e-300 (the squares are 0) and to 1e-100 (the
    // fourth powers are).
    for scale in [1e-300, 1e-93] {
        let e = stats(&|h| h * scale).unwrap_err();
        match &e {
            StatsError::Underflow {
                sigma,
                max_abs: m,
                bound,
            } => {
                assert!(*sigma < SIGMA_MIN, "{e}");
                assert_rel("max_abs", *m, max_abs * scale, 1e-12);
                assert_eq!(*bound, SIGMA_MIN);
            }
            other => panic!("scale {scale}: {other}"),
        }
        says(&e, &["must be >= 1e-75 m", "underflow"]);
    }

    // Rounding against the offset: 1e300 + heights of 1e-7 m are all
    // 1e300; 1 m + heights of 1e-13 m keep a few digits of them only.
    for (offset, scale) in [(1e300, 1.0), (1.0, 1e-6)] {
        let e = stats(&|h| offset + h * scale).unwrap_err();
        match &e {
            StatsError::Precision {
                mean_abs,
                relative,
                bound,
                ..
            } => {
                assert_rel("mean_abs", *mean_abs, offset, 1e-9);
                assert!(*relative <= PRECISION_MIN, "{e}");
                assert_eq!(*bound, PRECISION_MIN);
            }
            other => panic!("offset {offset}: {other}"),
        }
        let text = e.to_string();
        assert!(text.contains("lost to rounding against the offset"), "{text}");
    }

    // Inside the bounds: heights up to 1e70 m, or with sigma down to
    // 1e-70 m, still have their statistics.
    for top in [1e70, 1e-68] {
        let s = stats(&|h| h / max_abs * top).unwrap();
        assert!(s.kurtosis.is_finite() && s.kurtosis > 1.0, "{s:?}");
    }

    // A non-finite skewness: any finite value is valid, negative ones too.
    let s = stats(&|h| h).unwrap();
    let mut nan = s.clone();
    nan.skewness = f64::NAN;
    let e = combine(&nan, &s).unwrap_err();
    assert!(matches!(e, StatsError::NotFinite { name: "skewness", .. }), "{e}");
    assert_eq!(e.to_string(), "skewness = NaN is out of range: must be finite");
}
