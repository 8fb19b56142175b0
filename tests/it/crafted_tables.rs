//! Crafted table files (a hostile author's, with valid checksums, from the
//! independent encoder in `tests/forge.rs`): each is refused at load with
//! an error naming the bad field, or loads and answers correctly from
//! every kernel. Issue 23's regression tests.

use crate::forge::{crafted, Spec};
use ke_friction::{Table, TableError};

/// In-domain queries: the corners, the edges' midpoints and a grid inside.
fn queries(t: &Table) -> Vec<[f64; 3]> {
    let r = t.domain().ranges();
    let at = |k: usize, u: f64| {
        let (lo, hi) = r[k];
        if u >= 1.0 {
            hi
        } else {
            lo + (hi - lo) * u
        }
    };
    let us = [0.0, 1e-12, 0.013, 0.25, 0.5, 0.77, 0.999_999, 1.0];
    let mut q = vec![];
    for &a in &us {
        for &b in &us {
            for &c in &us {
                q.push([at(0, a), at(1, b), at(2, c)]);
            }
        }
    }
    q
}

/// Every query of a table with uniform ln μ coefficients `c`: μ = e^c
/// (the weights sum to one), h* = 1, slope finite; single and batch the
/// same bits; the fast kernel within f32 rounding of the portable one.
fn answers_uniform(name: &str, t: &Table, c: f64) {
    let expect = c.exp();
    let q = queries(t);
    let (psi, theta, f): (Vec<f64>, Vec<f64>, Vec<f64>) = (
        q.iter().map(|x| x[0]).collect(),
        q.iter().map(|x| x[1]).collect(),
        q.iter().map(|x| x[2]).collect(),
    );
    let mut batch = vec![0.0; q.len()];
    t.mu_batch(&psi, &theta, &f, &mut batch)
        .unwrap_or_else(|e| panic!("{name}: batch {e}"));
    let mut batch_slope = vec![(0.0, 0.0); q.len()];
    t.mu_with_slope_batch(&psi, &theta, &f, &mut batch_slope)
        .unwrap_or_else(|e| panic!("{name}: slope batch {e}"));
    for (i, &[p, th, fs]) in q.iter().enumerate() {
        let exact = t.mu_portable(p, th, fs).unwrap();
        assert!(
            exact.is_finite() && exact > 0.0 && (exact / expect - 1.0).abs() <= 1e-12,
            "{name}: portable mu({p}, {th}, {fs}) = {exact}, expected {expect}"
        );
        let fast = t.mu(p, th, fs).unwrap();
        assert!(
            fast > 0.0 && (fast / expect - 1.0).abs() <= 2e-6 * (1.0 + c.abs()),
            "{name}: mu({p}, {th}, {fs}) = {fast}, expected {expect}"
        );
        assert_eq!(batch[i].to_bits(), fast.to_bits(), "{name}: batch vs single at {i}");
        let (m, s) = t.mu_with_slope(p, th, fs).unwrap();
        assert_eq!(m.to_bits(), fast.to_bits(), "{name}: mu_with_slope's mu");
        assert!(s.is_finite(), "{name}: slope {s}");
        assert_eq!(batch_slope[i], (m, s), "{name}: slope batch vs single at {i}");
        let (pm, ps) = t.mu_with_slope_portable(p, th, fs).unwrap();
        assert!(
            pm.to_bits() == exact.to_bits() && ps.is_finite(),
            "{name}: portable slope"
        );
        let h = t.h_star(p, th, fs).unwrap();
        assert!((h - 1.0).abs() <= 1e-12, "{name}: h* = {h}");
    }
    let curve = t.curve(1.0, 0.001).unwrap_or_else(|e| panic!("{name}: curve {e}"));
    let m = curve.mu(0.01).unwrap();
    assert!(
        (m / expect - 1.0).abs() <= 1e-9,
        "{name}: curve mu {m}, expected {expect}"
    );
}

#[test]
fn the_encoder_writes_tables_the_library_reads() {
    for f32 in [true, false] {
        let spec = Spec::uniform(0.5f64.ln(), f32);
        let t = Table::from_bytes(&spec.encode()).expect("a valid forged table");
        answers_uniform("uniform 0.5", &t, spec.stored(0.5f64.ln()));
    }
}

#[test]
fn every_crafted_file_is_refused_naming_its_field_or_answers_correctly() {
    for (name, spec, refused) in crafted() {
        let bytes = spec.encode();
        let result = std::panic::catch_unwind(|| Table::from_bytes(&bytes))
            .unwrap_or_else(|_| panic!("{name}: Table::from_bytes panicked"));
        match (refused, result) {
            (Some(field), Err(e)) => {
                assert!(matches!(e, TableError::Inconsistent(_)), "{name}: {e:?}");
                assert!(e.to_string().contains(field), "{name}: '{e}' does not name {field}");
            }
            (Some(field), Ok(_)) => panic!("{name}: loaded, but must be refused for {field}"),
            (None, Err(e)) => panic!("{name}: refused ({e}) but is representable"),
            (None, Ok(t)) => {
                let c = spec.stored(spec.ln_mu[0]);
                // The fast f32 kernel only where its exponential reaches.
                assert!(!t.fast_kernel() || c.abs() <= 86.0, "{name}: fast kernel at ln mu {c}");
                answers_uniform(name, &t, c)
            }
        }
    }
}

#[test]
fn a_table_at_the_exponentials_limits_answers_at_its_extremes() {
    // Alternating ±86 (f32) and ±650 (f64, F* bounded away from 0 so the
    // slope stays finite): every blend is within the coefficients' range.
    for (f32, c) in [(true, 86.0), (false, 600.0)] {
        let mut s = Spec::uniform(0.0, f32);
        if !f32 {
            s.axes[2] = crate::forge::Axis::over(crate::forge::LOG, 1e-3, 0.1, 9);
        }
        for (i, v) in s.ln_mu.iter_mut().enumerate() {
            *v = if (i * 7919) % 3 == 0 { c } else { -c };
        }
        let t = Table::from_bytes(&s.encode()).unwrap_or_else(|e| panic!("±{c}: {e}"));
        for [p, th, fs] in queries(&t) {
            for (mu, slope) in [
                t.mu_with_slope(p, th, fs).unwrap(),
                t.mu_with_slope_portable(p, th, fs).unwrap(),
            ] {
                assert!(
                    mu.is_finite() && mu > 0.0 && slope.is_finite(),
                    "±{c}: ({mu}, {slope}) at ({p}, {th}, {fs})"
                );
                let ln = mu.ln();
                assert!(ln.abs() <= c * (1.0 + 1e-6) + 1e-3, "±{c}: ln mu {ln}");
            }
        }
    }
}

#[test]
fn queries_outside_the_domain_and_nan_are_errors_on_crafted_tables() {
    let t = Table::from_bytes(&Spec::uniform(0.0, true).encode()).unwrap();
    let (lo, hi) = t.domain().f_star;
    for f in [f64::NAN, lo * 0.999, hi * 1.001, f64::INFINITY, -1.0] {
        assert!(
            t.mu(1.0, 0.001, f).is_err() && t.mu_portable(1.0, 0.001, f).is_err() && t.h_star(1.0, 0.001, f).is_err()
        );
        let mut out = [0.0; 9];
        let mut f_star = [0.01; 9];
        f_star[5] = f;
        let e = t.mu_batch(&[1.0; 9], &[0.001; 9], &f_star, &mut out).unwrap_err();
        assert!(e.to_string().contains("element 5"), "{e}");
    }
}
