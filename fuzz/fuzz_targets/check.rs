//! The invariant every table that loads must keep (src/table/format.rs):
//! every in-domain query answers with a finite μ > 0, a finite slope and a
//! finite h*, the same bits from single and batch lookups, the fast kernel
//! within f32 rounding of the portable one; out-of-domain queries are
//! errors. Never a panic (libFuzzer reports one as a crash), never a read
//! outside the arrays (AddressSanitizer reports one).

use ke_friction::Table;

/// In-domain queries: the corners and edges of the domain (where cells
/// are clamped) and the points at fractions `fractions` of each range.
pub fn queries(t: &Table, fractions: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let r = t.domain().ranges();
    let at = |k: usize, u: f64| {
        let (lo, hi) = r[k];
        let u = if u.is_finite() { u.abs().fract() } else { 0.5 };
        (lo + (hi - lo) * u).clamp(lo, hi)
    };
    let mut q = vec![];
    for a in [0.0, 1.0] {
        for b in [0.0, 1.0] {
            for c in [0.0, 1.0] {
                q.push([
                    if a == 0.0 { r[0].0 } else { r[0].1 },
                    if b == 0.0 { r[1].0 } else { r[1].1 },
                    if c == 0.0 { r[2].0 } else { r[2].1 },
                ]);
            }
        }
    }
    q.extend(fractions.iter().map(|f| [at(0, f[0]), at(1, f[1]), at(2, f[2])]));
    q
}

/// Checks the invariant at `queries`; `max_coef` bounds |ln μ| coefficients
/// (for the fast kernel's tolerance).
pub fn check(t: &Table, queries: &[[f64; 3]], max_coef: f64) {
    let n = queries.len();
    let col = |k: usize| queries.iter().map(|q| q[k]).collect::<Vec<f64>>();
    let (psi, theta, f_star) = (col(0), col(1), col(2));
    let mut batch = vec![0.0; n];
    t.mu_batch(&psi, &theta, &f_star, &mut batch).expect("in-domain batch");
    let mut batch_slope = vec![(0.0, 0.0); n];
    t.mu_with_slope_batch(&psi, &theta, &f_star, &mut batch_slope)
        .expect("in-domain slope batch");
    // f32 sums and f32 cell coordinates (see the tests' bound in
    // tests/it/crafted_tables.rs and src/table/avx2.rs).
    let tolerance = 1e-5 + 2e-3 * max_coef;
    for (i, &[p, th, f]) in queries.iter().enumerate() {
        let mu = t.mu(p, th, f).expect("in-domain mu");
        let exact = t.mu_portable(p, th, f).expect("in-domain mu_portable");
        assert!(mu.is_finite() && mu > 0.0, "mu({p}, {th}, {f}) = {mu}");
        assert!(
            exact.is_finite() && exact > 0.0,
            "mu_portable({p}, {th}, {f}) = {exact}"
        );
        assert!(
            (mu.ln() - exact.ln()).abs() <= tolerance,
            "kernels differ at ({p}, {th}, {f}): {mu} vs {exact}"
        );
        assert_eq!(batch[i].to_bits(), mu.to_bits(), "batch vs single at {i}");
        let (m, s) = t.mu_with_slope(p, th, f).expect("in-domain slope");
        assert!(m.to_bits() == mu.to_bits() && s.is_finite(), "mu_with_slope ({m}, {s})");
        assert_eq!(batch_slope[i], (m, s), "slope batch vs single at {i}");
        let (pm, ps) = t.mu_with_slope_portable(p, th, f).expect("in-domain portable slope");
        assert!(
            pm.to_bits() == exact.to_bits() && ps.is_finite(),
            "portable slope ({pm}, {ps})"
        );
        let h = t.h_star(p, th, f).expect("in-domain h*");
        assert!(h.is_finite(), "h* = {h}");
    }
    // Outside the domain: errors, in single and batch lookups.
    let d = t.domain();
    let (p, th) = (d.psi.0, d.theta.0);
    for f in [f64::NAN, d.f_star.0 * 0.5, d.f_star.1 * 2.0 + 1.0, f64::INFINITY] {
        assert!(t.mu(p, th, f).is_err() && t.mu_portable(p, th, f).is_err() && t.h_star(p, th, f).is_err());
    }
    let mut out = [0.0; 3];
    assert!(t
        .mu_batch(&[p; 3], &[th; 3], &[d.f_star.0, f64::NAN, d.f_star.1], &mut out)
        .is_err());
}
