//! The scale-dependent rms slope and curvature and the tip-radius
//! reliability cut-off (`topography::scale`, Sanner et al. 2022, doi
//! 10.1016/j.apsadv.2021.100190) against closed forms: the discrete slope
//! and curvature of sines, planes and paraboloids (with the linear
//! interpolation's exact error at fractional scale factors), the trimmed
//! edges, the root of the tip criterion, and the refusals. The comparison
//! with SurfaceTopography itself is `tools/scale_check.py`.
use ke_friction::topography::{
    scale_dependent_curvature, scale_dependent_slope, tip_reliability_cutoff, ScaleError, Topography,
};
use ke_friction::{Classify, ErrorKind};
use std::f64::consts::{PI, SQRT_2};

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

fn sine(n: usize, dx: f64, amplitude: f64, wavelength: f64) -> Vec<f64> {
    (0..n)
        .map(|i| amplitude * (2.0 * PI * i as f64 * dx / wavelength).sin() + 1e-6)
        .collect()
}

/// Upwind slope of A·sin(2πx/L) at distance d: 2A·sin(πd/L)/d·cos(…), rms
/// over whole half-periods 2A·sin(πd/L)/(d·√2).
#[test]
fn sine_slope_is_the_discrete_identity() {
    // dx a power of two: d/dx is exactly m (the trimmed edge is ⌈d/dx⌉).
    let dx = 0.5f64.powi(21);
    let (a, l) = (0.3e-6, 20.0 * dx); // 20 points a wavelength
    for m in [1usize, 2, 3, 5, 7, 13, 19, 31] {
        let d = m as f64 * dx;
        // 200 points kept (the last m trimmed): 10 whole wavelengths.
        let t = Topography::profile(sine(200 + m, dx, a, l), dx).unwrap();
        let row = scale_dependent_slope(&t, &[d]).unwrap()[0];
        let want = 2.0 * a * (PI * d / l).sin().abs() / d / SQRT_2;
        assert!(close(row.x, want, 1e-11), "m = {m}: {} vs {want}", row.x);
        assert_eq!(row.y, None);
        assert_eq!(row.distance, d);
    }
}

/// Central curvature of A·sin(2πx/L) with step a = d/2:
/// −4A·sin²(πa/L)/a²·sin(…), rms 4A·sin²(πa/L)/(a²·√2).
#[test]
fn sine_curvature_is_the_discrete_identity() {
    let dx = 0.5f64.powi(21);
    let (amp, l) = (0.3e-6, 20.0 * dx);
    for m in [1usize, 2, 3, 4, 9, 15] {
        let d = 2.0 * m as f64 * dx;
        let step = m as f64 * dx;
        // 200 points kept (m trimmed at each end).
        let t = Topography::profile(sine(200 + 2 * m, dx, amp, l), dx).unwrap();
        let row = scale_dependent_curvature(&t, &[d]).unwrap()[0];
        let want = 4.0 * amp * (PI * step / l).sin().powi(2) / (step * step) / SQRT_2;
        assert!(close(row.x, want, 1e-10), "m = {m}: {} vs {want}", row.x);
    }
}

/// A sine along x of a map (dx ≠ dy): the same rms slope along x at
/// every row, none along y.
#[test]
fn map_sine_along_x_has_no_slope_along_y() {
    let dx = 0.5f64.powi(21);
    let (dy, a, l) = (0.8e-6, 0.3e-6, 20.0 * dx);
    let m = 4;
    let (nx, ny) = (200 + m, 30);
    let row: Vec<f64> = sine(nx, dx, a, l);
    let h: Vec<f64> = (0..ny).flat_map(|_| row.iter().copied()).collect();
    let t = Topography::map(h, nx, ny, dx, dy).unwrap();
    let d = m as f64 * dx;
    let r = scale_dependent_slope(&t, &[d]).unwrap()[0];
    let want = 2.0 * a * (PI * d / l).sin() / d / SQRT_2;
    assert!(close(r.x, want, 1e-11), "{} vs {want}", r.x);
    // Along y the rows are equal: zero but for the rounding of the
    // interpolation between rows (fractional s_y).
    assert!(r.y.unwrap() < 1e-12 * r.x, "{r:?}");
}

/// A plane: its slopes at every distance, fractional scale factors too
/// (linear interpolation is exact for it).
#[test]
fn plane_slope_is_exact_at_every_distance() {
    let (nx, ny, dx, dy) = (50, 40, 1e-6, 1.7e-6);
    let (sx, sy) = (0.03, -0.2);
    let h = (0..ny)
        .flat_map(|j| (0..nx).map(move |i| sx * i as f64 * dx + sy * j as f64 * dy + 5e-6))
        .collect();
    let t = Topography::map(h, nx, ny, dx, dy).unwrap();
    let ds = [1e-6, 1.3e-6, 2.5e-6, 7.77e-6, 20e-6];
    for r in scale_dependent_slope(&t, &ds).unwrap() {
        assert!(close(r.x, sx.abs(), 1e-9), "{r:?}");
        assert!(close(r.y.unwrap(), sy.abs(), 1e-9), "{r:?}");
    }
}

/// A paraboloid x²/(2Rx) + y²/(2Ry): curvature 1/R exactly at integer
/// scale factors s = d/(2Δ); at fractional ones the linear interpolation
/// adds exactly f(1 − f)/s² (f the fraction of s), the same at every point.
#[test]
fn paraboloid_curvature_is_exact() {
    let (nx, ny, dx, dy) = (80, 60, 1e-6, 0.6e-6);
    let (rx, ry) = (2e-3, 5e-4);
    let h = (0..ny)
        .flat_map(|j| {
            (0..nx).map(move |i| {
                let (x, y) = (i as f64 * dx - 30e-6, j as f64 * dy - 10e-6);
                x * x / (2.0 * rx) + y * y / (2.0 * ry)
            })
        })
        .collect();
    let t = Topography::map(h, nx, ny, dx, dy).unwrap();
    let ds = [2e-6, 4e-6, 6e-6, 3e-6, 5e-6, 7.3e-6, 12e-6];
    for r in scale_dependent_curvature(&t, &ds).unwrap() {
        for (got, radius, delta) in [(r.x, rx, dx), (r.y.unwrap(), ry, dy)] {
            let s: f64 = r.distance / (2.0 * delta);
            let f = s - s.floor();
            let want = (1.0 + f * (1.0 - f) / (s * s)) / radius;
            assert!(close(got, want, 1e-6), "d = {}: {got} vs {want}", r.distance);
        }
    }
}

/// Fewer than 4 points left after trimming: NaN, as SurfaceTopography.
#[test]
fn too_few_points_give_nan() {
    let dx = 0.5; // exact scale factors
    let t = Topography::profile((0..10).map(|i| (i * i) as f64 * 1e-3).collect(), dx).unwrap();
    let rows = scale_dependent_slope(&t, &[3.0, 3.5]).unwrap();
    assert!(rows[0].x.is_finite()); // s = 6: 4 kept
    assert!(rows[1].x.is_nan()); // s = 7: 3 kept
    let rows = scale_dependent_curvature(&t, &[3.0, 4.0]).unwrap();
    assert!(rows[0].x.is_finite()); // s = 3: 4 kept
    assert!(rows[1].x.is_nan()); // s = 4: 2 kept
}

/// The cut-off of a finely sampled sine solves the criterion: the
/// sharpest discrete curvature at the stencil length λ,
/// 4A·sin²(πλ/2L)/(λ/2)², equals f/R; none for a sharp tip, the whole
/// length for a blunt one.
#[test]
fn tip_cutoff_of_a_sine_solves_the_criterion() {
    let (dx, a, l) = (0.05e-6, 0.5e-6, 10e-6); // 200 points a wavelength
    let n = 2000;
    let t = Topography::profile(sine(n, dx, a, l), dx).unwrap();
    let curvature = |lambda: f64| {
        let step = lambda / 2.0;
        4.0 * a * (PI * step / l).sin().powi(2) / (step * step)
    };
    let peak = a * (2.0 * PI / l).powi(2);
    // f/R below the peak curvature: cut off where the discrete one falls to it.
    for ratio in [0.2, 0.5, 0.8] {
        let radius = 0.5 / (ratio * peak);
        let cut = tip_reliability_cutoff(&t, radius, 0.5).unwrap().unwrap();
        assert!(close(curvature(cut), ratio * peak, 1e-3), "ratio {ratio}: λ = {cut}");
    }
    assert_eq!(tip_reliability_cutoff(&t, 0.5 / (2.0 * peak), 0.5).unwrap(), None);
    let blunt = tip_reliability_cutoff(&t, 1e3, 0.5).unwrap();
    assert_eq!(blunt, Some(n as f64 * dx));
}

#[test]
fn missing_points_and_bad_arguments_are_refused() {
    let mut h = sine(100, 1e-6, 1e-7, 1e-5);
    h[17] = f64::NAN;
    h[18] = f64::NAN;
    let t = Topography::profile(h, 1e-6).unwrap();
    for e in [
        scale_dependent_slope(&t, &[2e-6]).unwrap_err(),
        scale_dependent_curvature(&t, &[2e-6]).unwrap_err(),
        tip_reliability_cutoff(&t, 1e-6, 0.5).unwrap_err(),
    ] {
        assert_eq!(e, ScaleError::MissingPoints { missing: 2 });
        assert_eq!(e.kind(), ErrorKind::Argument);
        assert!(e.to_string().contains("missing"), "{e}");
    }
    let t = Topography::profile(sine(100, 1e-6, 1e-7, 1e-5), 1e-6).unwrap();
    for d in [0.0, -1e-6, f64::NAN, f64::INFINITY] {
        let e = scale_dependent_slope(&t, &[1e-6, d]).unwrap_err();
        assert!(matches!(e, ScaleError::Distance { .. }), "{e}");
        assert_eq!(e.kind(), ErrorKind::Argument);
    }
    for r in [0.0, -1.0, f64::NAN] {
        let e = tip_reliability_cutoff(&t, r, 0.5).unwrap_err();
        assert!(matches!(e, ScaleError::TipRadius { .. }), "{e}");
        assert_eq!(e.kind(), ErrorKind::Argument);
        let e = tip_reliability_cutoff(&t, 1e-6, r).unwrap_err();
        assert!(matches!(e, ScaleError::SafetyFactor { .. }), "{e}");
    }
    assert!(scale_dependent_slope(&t, &[]).unwrap().is_empty());
}

#[test]
fn default_distances_run_five_a_decade_from_the_shortest_stencil_to_half_the_scan() {
    use ke_friction::topography::{default_distances, Topography};
    // 200 x 100 points, dx = 1 µm, dy = 2 µm: shorter side 200 µm.
    let t = Topography::map(vec![0.0; 200 * 100], 200, 100, 1e-6, 2e-6).unwrap();
    for order in [1u32, 2] {
        let d = default_distances(&t, order);
        assert_eq!(d[0], f64::from(order) * 2e-6);
        assert!((*d.last().unwrap() / 100e-6 - 1.0).abs() < 1e-15);
        for w in d.windows(2).take(d.len() - 2) {
            assert!((w[1] / w[0] - 10f64.powf(0.2)).abs() < 1e-12);
        }
        assert!(d.windows(2).all(|w| w[1] > w[0]));
    }
    // A scan shorter than twice the stencil: the one shortest length.
    let t = Topography::profile(vec![0.0; 3], 1e-6).unwrap();
    assert_eq!(default_distances(&t, 2), vec![2e-6]);
}
