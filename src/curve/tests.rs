//! The curve's unit tests (beside its private cells and kernels).

use super::*;

#[test]
fn the_cell_coordinate_is_exact_and_cells_are_uniform_within_an_octave() {
    // 16 cells per octave: 0.1 = 1.6·2⁻⁴ lies in cell 9 of its octave,
    // at t = 0.6, since 16·0.6 = 9.6.
    let shift = 52 - 4;
    let bits = 0.1f64.to_bits();
    let t = f64::from_bits(((bits << 4) & MANTISSA) | ONE) - 1.0;
    let x0 = f64::from_bits((bits >> shift) << shift);
    let width = f64::from_bits(((bits >> shift) + 1) << shift) - x0;
    assert_eq!(x0, 1.5625 * 0.0625);
    assert_eq!(width, 0.0625 / 16.0);
    assert!((x0 + t * width - 0.1).abs() <= 1e-17);
}

/// μ = 1 + |F* − F₀|^0.3 (a J-shaped density's end meeting a regime
/// boundary looks like this): the cells around F₀ are split, the curve
/// meets the accuracy close to F₀ too, and batches give bit for bit
/// what single lookups give, in split cells as elsewhere.
#[test]
fn a_power_law_cusp_is_met_by_splitting_its_cells() {
    let f0 = 0.0123;
    let mu = |f: f64| 1.0 + (f - f0).abs().powf(0.3);
    let slope = |f: f64| {
        if f == f0 {
            0.0
        } else {
            0.3 * (f - f0).abs().powf(-0.7) * (f - f0).signum()
        }
    };
    let node = |f: f64| Ok((mu(f), slope(f)));
    let exact = |f: f64| Ok(mu(f));
    let curve = Curve::refined(1e-3, 0.1, &node, &exact, CURVE_ACCURACY).unwrap();
    assert!(
        !curve.splits.is_empty() && curve.splits.len() <= SPLIT_CELLS,
        "{curve:?}"
    );
    assert!(curve.cell_bits < MAX_CELL_BITS, "{curve:?}");
    assert!(curve.max_error() <= CURVE_ACCURACY);
    let mut rng = SplitMix64(3);
    let loads: Vec<f64> = (0..4000)
        .map(|i| match i % 2 {
            0 => f0 * (1.0 + 1e-3 * (2.0 * rng.unit() - 1.0)),
            _ => 1e-3 * 100f64.powf(rng.unit()),
        })
        .collect();
    let mut worst = 0.0f64;
    for &f in &loads {
        worst = worst.max(((curve.mu(f).unwrap() - mu(f)) / mu(f)).abs());
        let (m, d) = curve.mu_with_slope(f).unwrap();
        assert_eq!(m, curve.mu(f).unwrap());
        assert!(d.is_finite(), "slope at {f}");
    }
    // Between the sampled points of the pieces a little more than the
    // contract; near the cusp itself the pieces are 2^-30 of a cell.
    assert!(worst <= 1e-5, "{worst:e}");
    let mut batch = vec![0.0; loads.len()];
    curve.mu_batch(&loads, &mut batch).unwrap();
    for (f, b) in loads.iter().zip(&batch) {
        assert_eq!(b.to_bits(), curve.mu(*f).unwrap().to_bits(), "F* = {f}");
    }
}

/// A jump in μ cannot be met by any cubic pieces: the error names it.
#[test]
fn a_jump_is_refused_naming_the_load() {
    let node = |f: f64| Ok((if f < 0.02 { 1.0 } else { 1.1 }, 0.0));
    let exact = |f: f64| Ok(node(f)?.0);
    match Curve::refined(1e-3, 0.1, &node, &exact, CURVE_ACCURACY) {
        Err(CurveError::Accuracy { f_star, max_error, .. }) => {
            assert!(
                (f_star / 0.02 - 1.0).abs() < 1e-6 && max_error > CURVE_ACCURACY,
                "{f_star}"
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_hermite_cubic_reproduces_a_cubic_on_a_cut_cell() {
    let p = |x: f64| 2.0 - 3.0 * x + 0.5 * x * x - 0.25 * x * x * x;
    let dp = |x: f64| -3.0 + x - 0.75 * x * x;
    let (x0, width, a, b) = (1.0, 0.5, 1.1, 1.4);
    let c = hermite_in_t(a, b, x0, width, (p(a), dp(a)), (p(b), dp(b)));
    for t in [0.2, 0.35, 0.5, 0.8] {
        let x = x0 + t * width;
        assert!((cubic(&c, t) - p(x)).abs() < 1e-13, "t = {t}");
        assert!((cubic_slope(&c, t) / width - dp(x)).abs() < 1e-12, "t = {t}");
    }
}
