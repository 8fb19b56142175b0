//! The ISO 16610 Gaussian filters (`topography::filter`) against the
//! independent NumPy reference `tools/filter_reference.py`
//! (tests/data/filter/reference.json), the transmission of sines, a
//! brute-force normalised convolution with missing points, constants, the
//! direct and FFT convolutions against each other, and the refusals.
use ke_friction::topography::{
    gaussian_lowpass, gaussian_lowpass_using, l_filter, s_filter, Convolution, FilterError, Topography,
};
use ke_friction::{Classify, ErrorKind};
use serde_json::Value;
use std::f64::consts::{LN_2, PI};

const METHODS: [Convolution; 3] = [Convolution::Auto, Convolution::Direct, Convolution::Fft];

fn alpha() -> f64 {
    (LN_2 / PI).sqrt()
}

/// The discrete weights w_k = s(kΔ), |k| ≤ ⌊λ/Δ⌋, from the definition.
fn weights(lambda: f64, delta: f64) -> Vec<(i64, f64)> {
    let reach = (lambda / delta + 1e-9 * (lambda / delta).max(1.0)).floor() as i64;
    let a = alpha() * lambda;
    (-reach..=reach)
        .map(|k| (k, (-PI * (k as f64 * delta / a).powi(2)).exp() / a))
        .collect()
}

/// The discrete amplitude transmission Σ w_k cos(2πkΔ/L)/Σ w_k.
fn transmission(lambda: f64, delta: f64, wavelength: f64) -> f64 {
    let w = weights(lambda, delta);
    let num: f64 = w
        .iter()
        .map(|&(k, w)| w * (2.0 * PI * k as f64 * delta / wavelength).cos())
        .sum();
    let den: f64 = w.iter().map(|&(_, w)| w).sum();
    num / den
}

/// The brute-force normalised convolution over the valid points of the
/// two-dimensional window.
fn brute(t: &Topography, lambda: f64) -> Vec<f64> {
    let (nx, ny) = (t.nx() as i64, t.ny() as i64);
    let wx = weights(lambda, t.dx());
    let wy = t.dy().map_or(vec![(0, 1.0)], |dy| weights(lambda, dy));
    let z = t.heights();
    let mut out = vec![f64::NAN; z.len()];
    for j in 0..ny {
        for i in 0..nx {
            // Sums of height differences from the centre point: the same
            // quotient, without the rounding of a large mean height.
            let centre = z[(j * nx + i) as usize];
            if centre.is_nan() {
                continue;
            }
            let (mut num, mut den) = (0.0, 0.0);
            for &(l, wl) in &wy {
                for &(k, wk) in &wx {
                    let (ii, jj) = (i + k, j + l);
                    if (0..nx).contains(&ii) && (0..ny).contains(&jj) {
                        let h = z[(jj * nx + ii) as usize];
                        if !h.is_nan() {
                            num += wk * wl * (h - centre);
                            den += wk * wl;
                        }
                    }
                }
            }
            out[(j * nx + i) as usize] = centre + num / den;
        }
    }
    out
}

/// max |a − b| over the points valid in both, after checking that the
/// same points are missing.
fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let mut worst = 0.0f64;
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert_eq!(x.is_nan(), y.is_nan(), "missing at {k}: {x} vs {y}");
        if !x.is_nan() {
            worst = worst.max((x - y).abs());
        }
    }
    worst
}

fn range(z: &[f64]) -> f64 {
    let valid = z.iter().filter(|h| !h.is_nan());
    valid.clone().fold(f64::NEG_INFINITY, |a, &b| a.max(b)) - valid.fold(f64::INFINITY, |a, &b| a.min(b))
}

fn uniform(k: u64) -> f64 {
    let mut z = k.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    ((z ^ (z >> 31)) >> 11) as f64 * 2f64.powi(-53)
}

/// A rough map with a fraction `missing` of its points missing.
fn rough(nx: usize, ny: usize, dx: f64, dy: f64, missing: f64) -> Topography {
    let z = (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            if uniform(2 * k as u64 + 1) < missing {
                f64::NAN
            } else {
                1e-3 + 1e-7 * ((0.31 * i + 0.17 * j).sin() + 0.5 * (0.05 * i - 0.08 * j).cos())
                    + 2e-8 * (uniform(2 * k as u64) - 0.5)
            }
        })
        .collect();
    Topography::map(z, nx, ny, dx, dy).unwrap()
}

// ---------------------------------------------------------------------------
// The NumPy reference.

fn heights(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|h| h.as_f64().unwrap_or(f64::NAN))
        .collect()
}

#[test]
fn matches_the_numpy_reference() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/filter/reference.json")).unwrap();
    let fixture: Value = serde_json::from_str(&text).unwrap();
    let mut checked = 0;
    for case in fixture["cases"].as_array().unwrap() {
        let z = heights(&case["heights"]);
        let nx = case["nx"].as_u64().unwrap() as usize;
        let dx = case["dx"].as_f64().unwrap();
        let t = match case["dy"].as_f64() {
            Some(dy) => Topography::map(z.clone(), nx, case["ny"].as_u64().unwrap() as usize, dx, dy).unwrap(),
            None => Topography::profile(z.clone(), dx).unwrap(),
        };
        for lp in case["lowpass"].as_array().unwrap() {
            let lambda = lp["lambda"].as_f64().unwrap();
            let want = heights(&lp["heights"]);
            let span = range(&want);
            for method in METHODS {
                let got = gaussian_lowpass_using(&t, lambda, method).unwrap();
                let err = max_diff(got.heights(), &want) / span;
                assert!(err <= 1e-12, "{} lambda {lambda} {method:?}: {err:e}", case["name"]);
                checked += 1;
            }
            let auto = gaussian_lowpass(&t, lambda).unwrap();
            assert_eq!(
                max_diff(
                    auto.heights(),
                    gaussian_lowpass_using(&t, lambda, Convolution::Auto).unwrap().heights()
                ),
                0.0
            );
            assert_eq!(max_diff(s_filter(&t, lambda).unwrap().heights(), auto.heights()), 0.0);
            let rough: Vec<f64> = z.iter().zip(&want).map(|(z, g)| z - g).collect();
            let got = l_filter(&t, lambda).unwrap();
            assert_eq!(
                (got.nx(), got.ny(), got.dx(), got.dy()),
                (t.nx(), t.ny(), t.dx(), t.dy())
            );
            assert!(
                max_diff(got.heights(), &rough) <= 1e-12 * span,
                "{} l_filter {lambda}",
                case["name"]
            );
        }
    }
    assert_eq!(checked, 15);
}

// ---------------------------------------------------------------------------
// Sines.

#[test]
fn a_sine_is_transmitted_as_the_weights_say() {
    let (n, dx, lambda) = (1500, 1e-6, 25e-6);
    let reach = 25;
    for wavelength in [lambda, 0.6 * lambda, 1.7 * lambda, 4.0 * lambda, 10.0 * lambda] {
        let z: Vec<f64> = (0..n)
            .map(|i| (2.0 * PI * i as f64 * dx / wavelength + 0.3).cos())
            .collect();
        let t = Topography::profile(z.clone(), dx).unwrap();
        let discrete = transmission(lambda, dx, wavelength);
        let continuous = (-PI * (alpha() * lambda / wavelength).powi(2)).exp();
        assert!(
            (discrete - continuous).abs() <= 1e-6,
            "L = {wavelength}: {discrete} vs {continuous}"
        );
        if wavelength == lambda {
            assert!((discrete - 0.5).abs() <= 1e-6, "50 % at the cut-off: {discrete}");
        }
        for method in METHODS {
            let g = gaussian_lowpass_using(&t, lambda, method).unwrap();
            let worst = (reach..n - reach)
                .map(|i| (g.heights()[i] - discrete * z[i]).abs())
                .fold(0.0, f64::max);
            assert!(worst <= 1e-12, "L = {wavelength} {method:?}: {worst:e}");
        }
    }
}

#[test]
fn a_map_sine_with_dx_not_dy_is_transmitted_along_each_axis() {
    let (nx, ny, dx, dy, lambda) = (120, 90, 1e-6, 1.6e-6, 20e-6);
    let (lx, ly) = (27e-6, 41e-6);
    let z: Vec<f64> = (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            (2.0 * PI * i * dx / lx).cos() * (2.0 * PI * j * dy / ly + 0.7).cos()
        })
        .collect();
    let t = Topography::map(z.clone(), nx, ny, dx, dy).unwrap();
    let expected = transmission(lambda, dx, lx) * transmission(lambda, dy, ly);
    let continuous = (-PI * (alpha() * lambda / lx).powi(2)).exp() * (-PI * (alpha() * lambda / ly).powi(2)).exp();
    assert!((expected - continuous).abs() <= 1e-6, "{expected} vs {continuous}");
    let (kx, ky) = (20, 12);
    for method in METHODS {
        let g = gaussian_lowpass_using(&t, lambda, method).unwrap();
        let mut worst = 0.0f64;
        for j in ky..ny - ky {
            for i in kx..nx - kx {
                worst = worst.max((g.heights()[j * nx + i] - expected * z[j * nx + i]).abs());
            }
        }
        assert!(worst <= 1e-12, "{method:?}: {worst:e}");
        // Near the edges too, against the brute force.
        assert!(max_diff(g.heights(), &brute(&t, lambda)) <= 1e-12, "{method:?}");
    }
}

// ---------------------------------------------------------------------------
// Missing points, constants, the two convolutions.

#[test]
fn missing_points_stay_missing_and_neighbours_use_valid_points_only() {
    let t = rough(37, 29, 1e-6, 1.3e-6, 0.15);
    for lambda in [2.6e-6, 7.9e-6, 29e-6] {
        let want = brute(&t, lambda);
        let span = range(t.heights());
        for method in METHODS {
            let g = gaussian_lowpass_using(&t, lambda, method).unwrap();
            for (z, g) in t.heights().iter().zip(g.heights()) {
                assert_eq!(z.is_nan(), g.is_nan());
            }
            let err = max_diff(g.heights(), &want) / span;
            assert!(err <= 1e-12, "lambda {lambda} {method:?}: {err:e}");
        }
        let r = l_filter(&t, lambda).unwrap();
        let rough: Vec<f64> = t.heights().iter().zip(&want).map(|(z, g)| z - g).collect();
        assert!(max_diff(r.heights(), &rough) <= 1e-12 * span);
    }
    // A profile too.
    let row = t.heights()[..37].to_vec();
    let p = Topography::profile(row, 1e-6).unwrap();
    for method in METHODS {
        let g = gaussian_lowpass_using(&p, 9e-6, method).unwrap();
        assert!(max_diff(g.heights(), &brute(&p, 9e-6)) <= 1e-12 * range(p.heights()));
    }
}

#[test]
fn a_constant_stays_constant_including_the_edges() {
    for c in [1.234_567_890_123e-6, -3.0, 7e-3] {
        let missing = rough(41, 33, 1e-6, 1.5e-6, 0.2);
        let z: Vec<f64> = missing
            .heights()
            .iter()
            .map(|h| if h.is_nan() { f64::NAN } else { c })
            .collect();
        let map = Topography::map(z, 41, 33, 1e-6, 1.5e-6).unwrap();
        let full = Topography::map(vec![c; 41 * 33], 41, 33, 1e-6, 1.5e-6).unwrap();
        let profile = Topography::profile(vec![c; 300], 1e-6).unwrap();
        for (t, lambda) in [
            (&map, 3e-6),
            (&map, 40e-6),
            (&full, 11e-6),
            (&profile, 5e-6),
            (&profile, 290e-6),
        ] {
            for method in METHODS {
                let g = gaussian_lowpass_using(t, lambda, method).unwrap();
                for (z, g) in t.heights().iter().zip(g.heights()) {
                    assert_eq!(z.is_nan(), g.is_nan());
                    if !z.is_nan() {
                        assert!(
                            (g - c).abs() <= 1e-15 * c.abs(),
                            "{g} vs {c} ({method:?}, lambda {lambda})"
                        );
                    }
                }
            }
            let r = l_filter(t, lambda).unwrap();
            assert!(r.heights().iter().all(|r| r.is_nan() || r.abs() <= 1e-15 * c.abs()));
        }
    }
}

#[test]
fn direct_and_fft_convolutions_agree() {
    for (t, missing) in [
        (rough(300, 200, 1e-6, 1.4e-6, 0.0), false),
        (rough(257, 131, 1e-6, 0.8e-6, 0.1), true),
    ] {
        let span = range(t.heights());
        let scan = (t.nx() as f64 * t.dx()).min(t.ny() as f64 * t.dy().unwrap());
        for lambda in [2.0 * 1.4e-6, 25e-6, scan / 5.0, scan] {
            let a = gaussian_lowpass_using(&t, lambda, Convolution::Direct).unwrap();
            let b = gaussian_lowpass_using(&t, lambda, Convolution::Fft).unwrap();
            let err = max_diff(a.heights(), b.heights()) / span;
            assert!(err <= 1e-12, "missing {missing}, lambda {lambda}: {err:e}");
        }
    }
    let p = Topography::profile(rough(5000, 1, 1e-6, 1e-6, 0.01).heights().to_vec(), 1e-6).unwrap();
    for lambda in [3e-6, 100e-6, 4999e-6] {
        let a = gaussian_lowpass_using(&p, lambda, Convolution::Direct).unwrap();
        let b = gaussian_lowpass_using(&p, lambda, Convolution::Fft).unwrap();
        assert!(
            max_diff(a.heights(), b.heights()) <= 1e-12 * range(p.heights()),
            "profile lambda {lambda}"
        );
    }
}

#[test]
fn extreme_heights_stay_finite() {
    for (a, b) in [(-1.7e308, 1.7e308), (1e-310, 3e-310), (-f64::MAX, f64::MAX)] {
        let z: Vec<f64> = (0..24 * 20).map(|k| if uniform(k) < 0.5 { a } else { b }).collect();
        let t = Topography::map(z, 24, 20, 1e-6, 1e-6).unwrap();
        for method in METHODS {
            let g = gaussian_lowpass_using(&t, 6e-6, method).unwrap();
            assert!(
                g.heights().iter().all(|h| h.is_finite() && *h >= a && *h <= b),
                "{a} {b} {method:?}"
            );
            let want = brute(&t, 6e-6);
            // The brute force's sums of differences overflow at ±f64::MAX.
            if b < 1e308 {
                assert!(max_diff(g.heights(), &want) <= 1e-12 * (b - a), "{a} {b} {method:?}");
            }
        }
    }
}

#[test]
fn an_all_missing_map_stays_missing() {
    let t = Topography::map(vec![f64::NAN; 20 * 20], 20, 20, 1e-6, 1e-6).unwrap();
    assert!(gaussian_lowpass(&t, 5e-6).unwrap().heights().iter().all(|h| h.is_nan()));
    assert!(l_filter(&t, 5e-6).unwrap().heights().iter().all(|h| h.is_nan()));
}

// ---------------------------------------------------------------------------
// Refusals.

#[test]
fn refusals_name_the_numbers() {
    let map = rough(40, 30, 1e-6, 1.5e-6, 0.0);
    let profile = Topography::profile(vec![0.0; 100], 2e-6).unwrap();
    for lambda in [f64::NAN, f64::INFINITY, -1e-6, 0.0] {
        let e = gaussian_lowpass(&map, lambda).unwrap_err();
        assert!(
            matches!(e, FilterError::Cutoff { lambda: l } if l == lambda || l.is_nan() && lambda.is_nan()),
            "{e:?}"
        );
        assert!(e.to_string().contains(&format!("{lambda:e}")), "{e}");
        let kind = if lambda.is_finite() {
            ErrorKind::Domain
        } else {
            ErrorKind::Argument
        };
        assert_eq!(e.kind(), kind, "{lambda}");
    }
    let e = s_filter(&map, 2.9e-6).unwrap_err();
    assert_eq!(
        e,
        FilterError::TooShort {
            lambda: 2.9e-6,
            min: 3e-6
        }
    );
    assert_eq!(e.kind(), ErrorKind::Domain);
    let msg = e.to_string();
    assert!(msg.contains("2.9e-6") && msg.contains("3e-6"), "{msg}");
    assert!(s_filter(&map, 3e-6).is_ok());

    let e = l_filter(&map, 40.5e-6).unwrap_err();
    let (sx, sy) = (40.0 * 1e-6, 30.0 * 1.5e-6);
    assert_eq!(
        e,
        FilterError::TooLong {
            lambda: 40.5e-6,
            size_x: sx,
            size_y: Some(sy)
        }
    );
    let msg = e.to_string();
    for number in [40.5e-6, sx, sy] {
        assert!(msg.contains(&format!("{number:e}")), "{msg} lacks {number}");
    }
    assert!(l_filter(&map, sx).is_ok());
    // The shorter extent decides (here y).
    let tall = rough(30, 40, 1.5e-6, 1e-6, 0.0);
    assert!(matches!(l_filter(&tall, 40.5e-6), Err(FilterError::TooLong { .. })));
    assert!(l_filter(&tall, 39.9e-6).is_ok());

    let e = l_filter(&profile, 201e-6).unwrap_err();
    assert_eq!(
        e,
        FilterError::TooLong {
            lambda: 201e-6,
            size_x: 100.0 * 2e-6,
            size_y: None
        }
    );
    assert!(e.to_string().contains(&format!("{:e}", 100.0 * 2e-6)));
    let e = s_filter(&profile, 3e-6).unwrap_err();
    assert_eq!(
        e,
        FilterError::TooShort {
            lambda: 3e-6,
            min: 4e-6
        }
    );
}
