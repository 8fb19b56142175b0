//! `Curve`: μ(F*) for one surface pair, against direct integration, across
//! its cell boundaries, in batches, from a table, and with bad input.
use crate::common::rel;
use ke_friction::{Curve, CurveError, Fit, LookupError, Model, Params, Table, CURVE_ACCURACY};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The default table's range of loads, the curves' range here.
const RANGE: (f64, f64) = (1e-5, 0.1);

/// Surfaces at both ends of the default ψ range, without and with the
/// most adhesion, and one with non-default β, ν, ε*.
fn surfaces() -> Vec<(&'static str, Params)> {
    vec![
        ("psi 0.5, theta 0", Params::new(0.5, 0.0)),
        ("psi 8, theta 0.01", Params::new(8.0, 0.01)),
        ("psi 0.5, theta 0.01", Params::new(0.5, 0.01)),
        ("psi 1, theta 0.001", Params::new(1.0, 0.001)),
        (
            "psi 2, theta 0.003, beta 0.1, nu 0.25, eps* 0.01",
            Params::new(2.0, 0.003).beta(0.1).nu(0.25).eps_star(0.01),
        ),
    ]
}

/// Loads log-uniform over the range (seeded).
fn loads(n: usize, seed: u64) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (lo, hi) = RANGE;
    (0..n).map(|_| lo * (hi / lo).powf(rng.gen::<f64>())).collect()
}

/// The cells' interior ends (t = 0 of a cell) inside the range.
fn cell_starts(curve: &Curve) -> Vec<f64> {
    let cells_per_octave = (curve.cells() as f64 / (RANGE.1 / RANGE.0).log2()).round() as u32;
    let k = cells_per_octave.next_power_of_two().trailing_zeros();
    let shift = 52 - k;
    let (lo, hi) = curve.range();
    let mut out = vec![];
    let mut j = (lo.to_bits() >> shift) + 1;
    loop {
        let x = f64::from_bits(j << shift);
        if x >= hi {
            return out;
        }
        out.push(x);
        j += 1;
    }
}

#[test]
fn curves_from_the_model_match_direct_integration_to_1e_6_at_random_loads_and_midpoints() {
    for (what, params) in surfaces() {
        let model = Model::new(params).unwrap();
        let curve = Curve::from_model(&model, RANGE.0, RANGE.1).unwrap();
        assert!(
            curve.max_error() <= CURVE_ACCURACY,
            "{what}: recorded {}",
            curve.max_error()
        );
        let starts = cell_starts(&curve);
        let midpoints = starts.windows(2).map(|w| 0.5 * (w[0] + w[1]));
        let mut worst = 0.0f64;
        for f in loads(150, 11).into_iter().chain(midpoints) {
            let exact = model.at_f_star(f).unwrap().mu.unwrap();
            worst = worst.max(rel(curve.mu(f).unwrap(), exact));
        }
        assert!(worst <= CURVE_ACCURACY, "{what}: max relative error {worst:e}");
    }
}

#[test]
fn the_slope_matches_a_central_difference_of_direct_integration() {
    // dμ/dF* against (μ(F(1+ε)) − μ(F(1−ε)))/(2εF) with ε = 1e-4, whose own
    // error is about ε²·|μ'''|F²/6 relative: well below the 1e-4 asked.
    for (what, params) in surfaces() {
        let model = Model::new(params).unwrap();
        let curve = Curve::from_model(&model, RANGE.0, RANGE.1).unwrap();
        let mu = |f: f64| model.at_f_star(f).unwrap().mu.unwrap();
        for f in loads(20, 12) {
            let eps = 1e-4;
            let fd = (mu(f * (1.0 + eps)) - mu(f * (1.0 - eps))) / (2.0 * eps * f);
            let (_, slope) = curve.mu_with_slope(f).unwrap();
            // Relative to the slope's own scale, μ/F*.
            let scale = mu(f) / f;
            assert!(
                (slope - fd).abs() <= 1e-4 * scale,
                "{what} at F* = {f:e}: slope {slope:e}, difference {fd:e}"
            );
        }
    }
}

#[test]
fn mu_and_its_slope_are_continuous_across_cell_boundaries() {
    let model = Model::new(Params::new(1.0, 0.003)).unwrap();
    let curve = Curve::from_model(&model, RANGE.0, RANGE.1).unwrap();
    let starts = cell_starts(&curve);
    assert!(starts.len() > 100, "{} cell boundaries", starts.len());
    for x in starts {
        // The last double of the cell below, and the first of the cell above.
        let below = f64::from_bits(x.to_bits() - 1);
        let (m0, s0) = curve.mu_with_slope(below).unwrap();
        let (m1, s1) = curve.mu_with_slope(x).unwrap();
        assert!(rel(m0, m1) <= 1e-13, "mu jumps at F* = {x:e}: {m0} vs {m1}");
        assert!(rel(s0, s1) <= 1e-9, "slope jumps at F* = {x:e}: {s0} vs {s1}");
    }
}

#[test]
fn batches_are_the_single_lookups_bit_for_bit() {
    let curve = Curve::from_model(&Model::new(Params::new(2.0, 0.001)).unwrap(), RANGE.0, RANGE.1).unwrap();
    let mut f = loads(1000, 13);
    f.extend([RANGE.0, RANGE.1]);
    let mut mu = vec![0.0; f.len()];
    let mut both = vec![(0.0, 0.0); f.len()];
    curve.mu_batch(&f, &mut mu).unwrap();
    curve.mu_with_slope_batch(&f, &mut both).unwrap();
    for (i, &x) in f.iter().enumerate() {
        assert_eq!(mu[i].to_bits(), curve.mu(x).unwrap().to_bits());
        let (m, s) = curve.mu_with_slope(x).unwrap();
        assert_eq!((both[i].0.to_bits(), both[i].1.to_bits()), (m.to_bits(), s.to_bits()));
        assert_eq!(m.to_bits(), mu[i].to_bits());
    }
}

#[test]
fn a_table_curve_is_within_the_table_s_tolerance_plus_its_own_error() {
    let table = Table::embedded();
    let tolerance = table.info().tolerance;
    for (psi, theta) in [(0.5, 0.0), (8.0, 0.01), (1.0, 0.001), (3.3, 0.0047)] {
        let curve = table.curve(psi, theta).unwrap();
        assert_eq!(curve.range(), table.domain().f_star);
        assert!(curve.max_error() <= CURVE_ACCURACY, "recorded {}", curve.max_error());
        let model = Model::new(Params::new(psi, theta)).unwrap();
        for f in loads(60, 14) {
            let got = curve.mu(f).unwrap();
            // Against the table's exact interpolant: what the curve adds.
            let interpolant = table.mu_portable(psi, theta, f).unwrap();
            assert!(rel(got, interpolant) <= curve.max_error() * 1.5 + 1e-12, "F* = {f:e}");
            // Against direct integration: the table's error plus that.
            let exact = model.at_f_star(f).unwrap().mu.unwrap();
            assert!(rel(got, exact) <= tolerance + curve.max_error(), "F* = {f:e}");
        }
    }
}

#[test]
fn loads_outside_the_range_are_errors_naming_the_value_and_the_range() {
    let curve = Table::embedded().curve(1.0, 0.001).unwrap();
    let subnormal = f64::MIN_POSITIVE / 4.0;
    for bad in [
        f64::NAN,
        -f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        -0.01,
        subnormal,
        9.99e-6,
        0.1000001,
        1e300,
    ] {
        for e in [curve.mu(bad).unwrap_err(), curve.mu_with_slope(bad).unwrap_err()] {
            match e {
                LookupError::OutOfDomain { name, value, lo, hi } => {
                    assert_eq!(name, "f_star");
                    assert!(value.to_bits() == bad.to_bits(), "{value} vs {bad}");
                    assert_eq!((lo, hi), RANGE);
                }
                other => panic!("{bad}: {other:?}"),
            }
        }
    }
    // The ends themselves are inside.
    assert!(curve.mu(RANGE.0).is_ok() && curve.mu(RANGE.1).is_ok());
}

#[test]
fn bad_batches_name_the_element_or_the_lengths() {
    let curve = Table::embedded().curve(1.0, 0.001).unwrap();
    let mut out = [0.0; 3];
    let e = curve.mu_batch(&[0.01, f64::NAN, 0.02], &mut out).unwrap_err();
    assert!(
        matches!(
            e,
            LookupError::BatchElement {
                index: 1,
                name: "f_star",
                ..
            }
        ),
        "{e:?}"
    );
    assert_eq!(out[0], curve.mu(0.01).unwrap(), "written up to the bad element");
    let e = curve.mu_batch(&[0.01, 0.02], &mut out).unwrap_err();
    assert_eq!(e, LookupError::CurveLengthMismatch { f_star: 2, out: 3 });
    let mut pairs = [(0.0, 0.0); 1];
    let e = curve.mu_with_slope_batch(&[0.01, 0.02], &mut pairs).unwrap_err();
    assert_eq!(e, LookupError::CurveLengthMismatch { f_star: 2, out: 1 });
    // A bad load inside the second group of four (the AVX2 batch takes
    // loads four at a time): the error names it, the loads before it are
    // written, bit for bit the single lookups.
    let mut f = [0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.0, 0.008, 0.009, 0.01];
    let mut out = [-1.0; 10];
    let e = curve.mu_batch(&f, &mut out).unwrap_err();
    assert!(matches!(e, LookupError::BatchElement { index: 6, .. }), "{e:?}");
    for i in 0..6 {
        assert_eq!(out[i].to_bits(), curve.mu(f[i]).unwrap().to_bits(), "load {i}");
    }
    assert_eq!(out[6..], [-1.0; 4], "nothing written from the bad load on");
    f[6] = 0.007;
    curve.mu_batch(&f, &mut out).unwrap();
    assert_eq!(out[9].to_bits(), curve.mu(0.01).unwrap().to_bits());
    // Empty batches are fine.
    curve.mu_batch(&[], &mut []).unwrap();
}

#[test]
fn bad_ranges_and_loads_without_friction_are_curve_errors() {
    let model = Model::new(Params::new(1.0, 0.001)).unwrap();
    for (lo, hi) in [
        (0.1, 0.1),
        (0.1, 0.01),
        (0.0, 0.1),
        (-1e-3, 0.1),
        (f64::NAN, 0.1),
        (1e-5, f64::INFINITY),
        (f64::MIN_POSITIVE / 2.0, 0.1),
    ] {
        let e = Curve::from_model(&model, lo, hi).unwrap_err();
        assert!(matches!(e, CurveError::Range { .. }), "[{lo}, {hi}]: {e:?}");
    }
    assert!(matches!(
        Curve::from_model(&model, 1e-300, 1e300).unwrap_err(),
        CurveError::TooWide { .. }
    ));
    // The literal printed Eq. 18 gives a negative μ for ψ ≳ 2.
    let printed = Model::new(Params::new(4.0, 0.001).fit(Fit::AsPrinted)).unwrap();
    let e = Curve::from_model(&printed, 1e-5, 0.1).unwrap_err();
    assert!(matches!(e, CurveError::NoMu { .. }), "{e:?}");
    // A table curve outside the table's ψ.
    let e = Table::embedded().curve(20.0, 0.001).unwrap_err();
    assert!(
        matches!(e, CurveError::Lookup(LookupError::OutOfDomain { name: "psi", .. })),
        "{e:?}"
    );
}

#[test]
fn curves_are_send_sync_and_clone() {
    fn shareable<T: Send + Sync + Clone>() {}
    shareable::<Curve>();
    let curve = Table::embedded().curve(1.0, 0.001).unwrap();
    let copy = curve.clone();
    std::thread::scope(|s| {
        let h = s.spawn(|| curve.mu(0.01).unwrap());
        assert_eq!(h.join().unwrap(), copy.mu(0.01).unwrap());
    });
}

#[test]
fn a_range_ending_on_a_cell_boundary_looks_up_both_ends() {
    // 2⁻⁴ = 0.0625 starts a cell: the last cell is that one point.
    let model = Model::new(Params::new(1.5, 0.002)).unwrap();
    let curve = Curve::from_model(&model, 1e-4, 0.0625).unwrap();
    for f in [1e-4, 0.0625, 0.0625 * (1.0 - f64::EPSILON)] {
        let (exact, exact_slope) = model.mu_with_slope_at_f_star(f).unwrap();
        let (mu, slope) = curve.mu_with_slope(f).unwrap();
        assert!(rel(mu, exact) <= CURVE_ACCURACY, "F* = {f:e}: {mu} vs {exact}");
        assert!(
            rel(slope, exact_slope) <= 1e-3,
            "F* = {f:e}: slope {slope} vs {exact_slope}"
        );
    }
    assert!(curve.mu(0.0625 * (1.0 + f64::EPSILON)).is_err());
}
