//! Issue 46's numerics: hostile scan ranges, the Weibull density at its
//! largest skewness, an empty filter band, scale-dependent statistics of
//! too few points, and the memory the filters, spectra and scans hold.
use crate::common::rel;
use ke_friction::topography::{
    scale_dependent_curvature, scale_dependent_slope, scan, ScaleError, ScanError, ScanRange, StatsError, StatsOptions,
    Surface, Topography, SCAN_ROWS_MAX,
};
use ke_friction::{Constants, HeightDistribution, Model};

fn rough(n: usize) -> Topography {
    let heights = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            1e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin() + (x * 0.13 - y * 0.41).cos())
        })
        .collect();
    Topography::map(heights, n, n, 1e-6, 1e-6).unwrap()
}

/// A range spanning hundreds of decades (or one whose ratio overflows
/// f64, from the smallest subnormal) is refused naming the range, before
/// any row is allocated; the bound is SCAN_ROWS_MAX rows.
#[test]
fn scans_of_unbounded_ranges_are_refused() {
    let t = rough(32);
    for (from, to, per_decade) in [(1e-300, 1e300, 5), (4.9e-324, 1e-5, 5), (1e-6, 1e5, 100)] {
        let range = ScanRange { from, to, per_decade };
        let e = range.values().unwrap_err();
        assert!(matches!(e, ScanError::TooManyRows { .. }), "{e:?}");
        let text = e.to_string();
        assert!(
            text.contains("from and to must span at most") && text.contains("decades"),
            "{text}"
        );
        let e = scan(&t, &StatsOptions::default(), &range, None, |_, _| {}).unwrap_err();
        assert!(matches!(e, ScanError::TooManyRows { .. }), "{e:?}");
    }
    // The largest allowed: SCAN_ROWS_MAX rows exactly.
    let per_decade = 100;
    let decades = (SCAN_ROWS_MAX - 1) as f64 / per_decade as f64;
    let range = ScanRange {
        from: 1e-6,
        to: 1e-6 * 10f64.powf(decades),
        per_decade,
    };
    assert_eq!(range.values().unwrap().len(), SCAN_ROWS_MAX);
}

/// Sk = 2 is the Weibull shape k = 1, the exponential: its standardised
/// density is exp(−(x + 1)) for x ≥ −1 (closed form), and the model's P*,
/// Fs*, Q*, F* match `tools/nongaussian_reference.py` (mpmath, 30 digits):
/// `Model(psi, theta, make_density('weibull', 2, None)).evaluate(h)`, and
/// `solve_mu(1.0, 0.001, 'weibull', 2, None, 0.1, dps=20)` for μ at F* = 0.1.
/// It used to give NaN (0·ln 0 at the end of the support).
#[test]
fn weibull_at_skewness_two_is_the_exponential() {
    let d = HeightDistribution::weibull(2.0).unwrap();
    let density = d.density().unwrap();
    for x in [-1.0, -0.999, -0.5, 0.0, 1.0, 3.0, 10.0] {
        let want = (-(x + 1.0f64)).exp();
        assert!(
            rel(density.pdf(x), want) < 1e-12,
            "g({x}) = {} against {want}",
            density.pdf(x)
        );
    }
    let model = |psi: f64, theta: f64| {
        Model::new(Constants::default().distribution(d.clone()).at(psi, theta).unwrap()).unwrap()
    };
    for (psi, theta, h, p, fs, q, f) in [
        (
            1.0,
            10.0,
            1.0,
            0.023747150465581058,
            4.582103707605554,
            0.007649998539954576,
            -4.558356557139973,
        ),
        (
            1.0,
            10.0,
            5.77,
            0.00010262865567887468,
            0.019805671103146591,
            3.306119053057854e-5,
            -0.019703042447467716,
        ),
        (
            1.0,
            1e-3,
            1.0,
            0.023747150465581058,
            0.00045821037076055538,
            0.007649998539954576,
            0.023288940094820502,
        ),
    ] {
        let c = model(psi, theta).at_h_star(h).unwrap();
        for (name, got, want) in [
            ("P*", c.p_star, p),
            ("Fs*", c.fs_star, fs),
            ("Q*", c.q_star, q),
            ("F*", c.f_star, f),
        ] {
            assert!(
                rel(got, want) < 1e-9,
                "psi {psi} theta {theta} h* {h}: {name} {got} against {want}"
            );
        }
    }
    let c = model(1.0, 1e-3).at_f_star(0.1).unwrap();
    assert!(rel(c.h_star, -0.34315270050603275) < 1e-9, "h* {}", c.h_star);
    assert!(rel(c.mu.unwrap(), 0.2834770774566933) < 1e-9, "mu {:?}", c.mu);
}

/// λc ≤ λs is an empty band: refused naming both, by the statistics, the
/// band's heights and a surface; a scan's rows at λs ≥ λc say why.
#[test]
fn an_l_filter_not_longer_than_the_s_filter_is_refused() {
    let t = rough(64);
    for (lambda_s, lambda_c) in [(1e-5, 5e-6), (1e-5, 1e-5)] {
        let options = StatsOptions {
            lambda_s: Some(lambda_s),
            lambda_c: Some(lambda_c),
            ..StatsOptions::default()
        };
        let e = t.stats(&options).unwrap_err();
        assert!(matches!(e, StatsError::EmptyBand { .. }), "{e:?}");
        let text = e.to_string();
        assert!(text.contains("lambda_c") && text.contains("lambda_s"), "{text}");
        assert!(t.band_heights(&options).is_err());
        assert!(Surface::new(t.clone(), options).is_err());
    }
    let options = StatsOptions {
        lambda_c: Some(2e-5),
        ..StatsOptions::default()
    };
    let range = ScanRange {
        from: 4e-6,
        to: 4e-5,
        per_decade: 5,
    };
    let rows = scan(&t, &options, &range, None, |_, _| {}).unwrap();
    for row in rows {
        match row.surface {
            Ok(_) => assert!(row.lambda_s < 2e-5, "{}", row.lambda_s),
            Err(e) => {
                assert!(row.lambda_s >= 2e-5, "{}: {e}", row.lambda_s);
                assert!(matches!(e, StatsError::EmptyBand { .. }), "{e:?}");
            }
        }
    }
}

/// A direction of fewer than 4 + order points keeps fewer than 4
/// derivative values at every stencil: refused naming it, not rows of NaN.
#[test]
fn scale_dependent_statistics_of_too_few_points_are_refused() {
    let row = Topography::map(
        (0..4096).map(|i| (i as f64 * 0.1).sin() * 1e-7).collect(),
        4096,
        1,
        1e-6,
        1e-6,
    )
    .unwrap();
    let e = scale_dependent_slope(&row, &[1e-6, 1e-5]).unwrap_err();
    assert!(
        matches!(
            e,
            ScaleError::TooFewPoints {
                name: "ny",
                count: 1,
                min: 5,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(
        e.to_string().contains("ny = 1 is out of range: at least 5 points"),
        "{e}"
    );
    for n in [2, 3, 4, 5] {
        let p = Topography::profile((0..n).map(|i| i as f64 * 1e-7).collect(), 1e-6).unwrap();
        let slope = scale_dependent_slope(&p, &[1e-6]);
        assert_eq!(slope.is_err(), n < 5, "slope of {n} points: {slope:?}");
        let curvature = scale_dependent_curvature(&p, &[2e-6]);
        assert!(
            matches!(curvature, Err(ScaleError::TooFewPoints { name: "nx", min: 6, .. })),
            "curvature of {n} points: {curvature:?}"
        );
    }
    // The fewest accepted give numbers at the shortest stencil.
    let p = Topography::profile((0..5).map(|i| (i as f64).powi(2) * 1e-7).collect(), 1e-6).unwrap();
    assert!(scale_dependent_slope(&p, &[1e-6]).unwrap()[0].x.is_finite());
}
