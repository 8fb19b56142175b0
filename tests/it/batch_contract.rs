//! The one batch contract (`OnError`) of every batch function, on the fast
//! and the portable table kernels and on curves: with `Stop`, at the first
//! bad element `i` the output holds the results before `i`, is untouched
//! from `i`, and the error names `i`; with `Nan`, NaN exactly at the bad
//! elements, every other element bit for bit the single lookup, and the
//! count of NaN returned.

use crate::forge::Spec;
use ke_friction::{Classify, Curve, LookupError, OnError, Table};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Queries of `n` with bad ones (NaN, beyond each end) at random places.
fn queries(t: &Table, n: usize, bad: usize, rng: &mut ChaCha8Rng) -> ([Vec<f64>; 3], Vec<usize>) {
    let r = t.domain().ranges();
    let mut q: [Vec<f64>; 3] =
        core::array::from_fn(|k| (0..n).map(|_| r[k].0 + (r[k].1 - r[k].0) * rng.gen::<f64>()).collect());
    let mut where_bad: Vec<usize> = (0..bad).map(|_| rng.gen_range(0..n)).collect();
    where_bad.sort_unstable();
    where_bad.dedup();
    for (j, &i) in where_bad.iter().enumerate() {
        let k = j % 3;
        q[k][i] = [f64::NAN, r[k].1 * 2.0 + 1.0, -1.0][j % 3];
    }
    (q, where_bad)
}

fn tables() -> Vec<(&'static str, Table)> {
    vec![
        ("default (fast kernel where the CPU has it)", Table::embedded().clone()),
        (
            "f64 (portable kernel)",
            Table::from_bytes(&Spec::uniform(-0.7, false).encode()).unwrap(),
        ),
    ]
}

#[test]
fn table_batches_keep_the_contract() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for (name, t) in tables() {
        for (n, bad) in [(1, 1), (7, 1), (8, 1), (37, 3), (200, 9), (1000, 0)] {
            let ([p, th, f], bad_at) = queries(&t, n, bad, &mut rng);
            let single: Vec<Result<(f64, f64), LookupError>> =
                (0..n).map(|i| t.mu_with_slope(p[i], th[i], f[i])).collect();
            // Stop: the prefix, an untouched tail, the first bad index.
            let sentinel = -12345.0;
            let mut out = vec![sentinel; n];
            let r = t.mu_batch_with(&p, &th, &f, &mut out, OnError::Stop);
            let mut pairs = vec![(sentinel, sentinel); n];
            let rs = t.mu_with_slope_batch_with(&p, &th, &f, &mut pairs, OnError::Stop);
            match bad_at.first() {
                Some(&i) => {
                    for (e, what) in [(r.unwrap_err(), "mu"), (rs.unwrap_err(), "slope")] {
                        assert_eq!(e.index(), Some(i), "{name} n={n} {what}: {e}");
                        assert!(e.to_string().starts_with(&format!("batch element {i}:")), "{e}");
                    }
                    assert!(out[i..].iter().all(|&v| v == sentinel), "{name}: tail written");
                    assert!(
                        pairs[i..].iter().all(|&v| v == (sentinel, sentinel)),
                        "{name}: tail written"
                    );
                    for k in 0..i {
                        assert_eq!(out[k].to_bits(), single[k].unwrap().0.to_bits(), "{name}: element {k}");
                        assert_eq!(pairs[k], single[k].unwrap(), "{name}: element {k}");
                    }
                }
                None => assert_eq!((r, rs), (Ok(0), Ok(0))),
            }
            // Nan: NaN exactly at the bad elements.
            let mut out = vec![sentinel; n];
            let n_nan = t.mu_batch_with(&p, &th, &f, &mut out, OnError::Nan).unwrap();
            let n_nan_slope = t
                .mu_with_slope_batch_with(&p, &th, &f, &mut pairs, OnError::Nan)
                .unwrap();
            assert_eq!((n_nan, n_nan_slope), (bad_at.len(), bad_at.len()), "{name}");
            for k in 0..n {
                match single[k] {
                    Ok((mu, s)) => {
                        assert_eq!(out[k].to_bits(), mu.to_bits(), "{name}: {k}");
                        assert_eq!(pairs[k], (mu, s), "{name}: {k}");
                    }
                    Err(_) => assert!(
                        out[k].is_nan() && pairs[k].0.is_nan() && pairs[k].1.is_nan(),
                        "{name}: {k}"
                    ),
                }
            }
        }
    }
}

#[test]
fn curve_batches_keep_the_contract() {
    let curve: Curve = Table::embedded().curve(1.0, 0.001).unwrap();
    let (lo, hi) = curve.range();
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    for (n, bad) in [(1, 1), (5, 1), (64, 5), (1000, 0)] {
        let mut f: Vec<f64> = (0..n).map(|_| lo + (hi - lo) * rng.gen::<f64>()).collect();
        let mut bad_at: Vec<usize> = (0..bad).map(|_| rng.gen_range(0..n)).collect();
        bad_at.sort_unstable();
        bad_at.dedup();
        for (j, &i) in bad_at.iter().enumerate() {
            f[i] = [f64::NAN, hi * 2.0, lo / 2.0][j % 3];
        }
        let mut out = vec![-1.0; n];
        let mut pairs = vec![(-1.0, -1.0); n];
        let r = curve.mu_batch_with(&f, &mut out, OnError::Stop);
        let rs = curve.mu_with_slope_batch_with(&f, &mut pairs, OnError::Stop);
        if let Some(&i) = bad_at.first() {
            assert_eq!(r.unwrap_err().index(), Some(i));
            assert_eq!(rs.unwrap_err().index(), Some(i));
            assert!(out[i..].iter().all(|&v| v == -1.0) && pairs[i..].iter().all(|&v| v == (-1.0, -1.0)));
        }
        let n_nan = curve.mu_batch_with(&f, &mut out, OnError::Nan).unwrap();
        assert_eq!(n_nan, bad_at.len());
        assert_eq!(
            curve.mu_with_slope_batch_with(&f, &mut pairs, OnError::Nan).unwrap(),
            bad_at.len()
        );
        for k in 0..n {
            match curve.mu_with_slope(f[k]) {
                Ok((mu, s)) => assert!(out[k].to_bits() == mu.to_bits() && pairs[k] == (mu, s), "{k}"),
                Err(_) => assert!(out[k].is_nan() && pairs[k].0.is_nan()),
            }
        }
    }
}

#[test]
fn a_split_batch_reports_the_index_in_the_whole() {
    let t = Table::embedded();
    let mut f = vec![0.01; 100];
    f[73] = f64::NAN;
    let mut out = vec![0.0; 100];
    let piece = 64..100;
    let e = t
        .mu_batch(&[1.0; 36], &[0.001; 36], &f[piece.clone()], &mut out[piece.clone()])
        .unwrap_err()
        .shifted(piece.start);
    assert_eq!(e.index(), Some(73));
    assert_eq!(e.kind(), ke_friction::ErrorKind::Argument);
}

#[test]
fn pairs_into_two_arrays_are_the_pairs_batch_across_buffer_boundaries() {
    let mut rng = ChaCha8Rng::seed_from_u64(35);
    for (name, t) in tables() {
        // 700 elements: three stack buffers of 256, bad ones in each.
        let ([p, th, f], bad) = queries(&t, 700, 9, &mut rng);
        let mut pairs = vec![(0.0, 0.0); 700];
        let want = t
            .mu_with_slope_batch_with(&p, &th, &f, &mut pairs, OnError::Nan)
            .unwrap();
        let (mut mu, mut slope) = (vec![7.0; 700], vec![7.0; 700]);
        let got = t
            .mu_with_slope_into(&p, &th, &f, &mut mu, &mut slope, OnError::Nan)
            .unwrap();
        assert_eq!(got, want, "{name}");
        for i in 0..700 {
            assert_eq!(mu[i].to_bits(), pairs[i].0.to_bits(), "{name} mu[{i}]");
            assert_eq!(slope[i].to_bits(), pairs[i].1.to_bits(), "{name} slope[{i}]");
        }
        // Stop: written before the first bad element, untouched from it.
        let (mut mu, mut slope) = (vec![7.0; 700], vec![7.0; 700]);
        let e = t
            .mu_with_slope_into(&p, &th, &f, &mut mu, &mut slope, OnError::Stop)
            .unwrap_err();
        assert_eq!(e.index(), Some(bad[0]), "{name}");
        assert!(mu[bad[0]..].iter().chain(&slope[bad[0]..]).all(|&v| v == 7.0), "{name}");
        assert_eq!(mu[..bad[0]], pairs.iter().map(|p| p.0).collect::<Vec<_>>()[..bad[0]]);
        // A slope array of another length is refused, nothing written.
        let (mut mu, mut slope) = (vec![7.0; 700], vec![7.0; 699]);
        let e = t
            .mu_with_slope_into(&p, &th, &f, &mut mu, &mut slope, OnError::Nan)
            .unwrap_err();
        assert!(matches!(e, LookupError::LengthMismatch { out: 699, .. }), "{e}");
        assert!(mu.iter().all(|&v| v == 7.0));
    }
    // A curve: the same.
    let t = Table::embedded();
    let c = t.curve(1.0, 0.001).unwrap();
    let (lo, hi) = c.range();
    let f: Vec<f64> = (0..600)
        .map(|i| {
            if i == 300 {
                hi * 2.0
            } else {
                lo + (hi - lo) * i as f64 / 600.0
            }
        })
        .collect();
    let mut pairs = vec![(0.0, 0.0); 600];
    c.mu_with_slope_batch_with(&f, &mut pairs, OnError::Nan).unwrap();
    let (mut mu, mut slope) = (vec![0.0; 600], vec![0.0; 600]);
    assert_eq!(c.mu_with_slope_into(&f, &mut mu, &mut slope, OnError::Nan).unwrap(), 1);
    assert!(mu[300].is_nan() && slope[300].is_nan());
    for i in (0..600).filter(|&i| i != 300) {
        assert_eq!(
            (mu[i].to_bits(), slope[i].to_bits()),
            (pairs[i].0.to_bits(), pairs[i].1.to_bits())
        );
    }
    let e = c
        .mu_with_slope_into(&f, &mut mu, &mut slope, OnError::Stop)
        .unwrap_err();
    assert_eq!(e.index(), Some(300));
    let e = c
        .mu_with_slope_into(&f, &mut mu, &mut slope[..5], OnError::Nan)
        .unwrap_err();
    assert!(matches!(e, LookupError::CurveLengthMismatch { out: 5, .. }), "{e}");
}
