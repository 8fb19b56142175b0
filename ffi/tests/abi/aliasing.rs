//! Outputs that alias each other or an input: KEF_ERR_ARGUMENT naming the
//! two parameters, nothing written (two `&mut` to one place would be
//! undefined behaviour in Rust); inputs may alias each other.

use super::last_error;
use super::queries::ALUMINIUM_ON_STEEL;
use kefriction::*;

const OVERLAP: &str = "outputs must not alias each other or the inputs";

fn expect_overlap(code: i32, first: &str, second: &str) {
    assert_eq!(code, KEF_ERR_ARGUMENT, "{}", last_error());
    assert_eq!(last_error(), format!("{first} and {second} overlap: {OVERLAP}"));
}

#[test]
fn parameters_from_physical_refuse_one_place_for_two_outputs() {
    let x = ALUMINIUM_ON_STEEL;
    // (psi, theta, beta, nu, eps_star) into the cells `at` of `out`.
    let call = |out: &mut [f64; 5], at: [usize; 5]| {
        let base = out.as_mut_ptr();
        // SAFETY: every index is < 5: pointers into a local array.
        let [psi, theta, beta, nu, eps_star] = at.map(|i| unsafe { base.add(i) });
        // SAFETY: local doubles (aliased on purpose: the call must refuse).
        unsafe {
            kef_params_from_physical(
                x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9], psi, theta, beta, nu, eps_star,
            )
        }
    };
    for (at, first, second) in [
        ([0, 0, 2, 3, 4], "psi", "theta"),
        ([0, 1, 2, 3, 2], "beta", "eps_star"),
        ([0, 1, 2, 1, 4], "theta", "nu"),
    ] {
        let mut out = [9.0; 5];
        expect_overlap(call(&mut out, at), first, second);
        assert_eq!(out, [9.0; 5], "{at:?}: nothing written");
    }
    let mut out = [9.0; 5];
    assert_eq!(call(&mut out, [0, 1, 2, 3, 4]), KEF_OK, "{}", last_error());
    assert!(out.iter().all(|&v| v != 9.0));
}

#[test]
fn pairs_of_outputs_must_be_distinct() {
    let t = kef_table_default();
    let mut v = 9.0;
    let p: *mut f64 = &mut v;
    // SAFETY: the default table; one local double, passed twice on purpose.
    unsafe {
        expect_overlap(kef_table_mu_with_slope(t, 1.0, 0.001, 0.01, p, p), "mu", "dmu_df_star");
        let mut d = [9.0; 6];
        let q = d.as_mut_ptr();
        expect_overlap(
            kef_table_domain(t, q, q.add(1), q.add(2), q.add(3), q.add(4), q.add(1)),
            "psi_max",
            "f_star_max",
        );
        assert_eq!(d, [9.0; 6]);
        let c = kef_curve_from_table(t, 1.0, 0.001);
        assert!(!c.is_null(), "{}", last_error());
        expect_overlap(kef_curve_range(c, p, p), "f_star_min", "f_star_max");
        expect_overlap(kef_curve_mu_with_slope(c, 0.01, p, p), "mu", "dmu_df_star");
        kef_curve_free(c);
        let mut family = 7;
        expect_overlap(
            kef_constants_distribution(std::ptr::null(), &mut family, p, p),
            "skewness",
            "kurtosis",
        );
        assert_eq!(family, 7);
        // An int output over a double one.
        expect_overlap(
            kef_constants_distribution(std::ptr::null(), p.cast(), p, std::ptr::null_mut()),
            "family",
            "skewness",
        );
    }
    assert_eq!(v, 9.0, "nothing written");
}

#[test]
fn batch_outputs_must_not_overlap_the_inputs_or_each_other() {
    let t = kef_table_default();
    let psi = [1.0; 4];
    let theta = [0.001; 4];
    let mut f = [0.01, 0.02, 0.03, 0.04];
    let fp = f.as_mut_ptr();
    let mut n_nan = 9usize;
    // SAFETY: the default table, local arrays of 4 (overlapping on purpose).
    unsafe {
        // In place, and shifted by one element.
        expect_overlap(
            kef_table_mu_batch(t, 4, psi.as_ptr(), theta.as_ptr(), fp, fp),
            "f_star",
            "mu",
        );
        expect_overlap(
            kef_table_mu_batch(t, 3, psi.as_ptr(), theta.as_ptr(), fp, fp.add(1)),
            "f_star",
            "mu",
        );
        expect_overlap(
            kef_table_h_star_batch(t, 4, psi.as_ptr(), fp, theta.as_ptr(), fp),
            "theta",
            "h_star",
        );
        let mut mu = [9.0; 4];
        let m = mu.as_mut_ptr();
        expect_overlap(
            kef_table_mu_with_slope_batch(t, 4, psi.as_ptr(), theta.as_ptr(), fp, m, m.add(3)),
            "mu",
            "dmu_df_star",
        );
        // The count over the last element of the results.
        expect_overlap(
            kef_table_mu_batch_nan(t, 4, psi.as_ptr(), theta.as_ptr(), fp, m, m.add(3).cast()),
            "mu",
            "n_nan",
        );
        let c = kef_curve_from_table(t, 1.0, 0.001);
        assert!(!c.is_null(), "{}", last_error());
        expect_overlap(kef_curve_mu_batch(c, 4, fp, fp), "f_star", "mu");
        expect_overlap(kef_curve_mu_batch_nan(c, 4, fp, m, fp.cast()), "f_star", "n_nan");
        expect_overlap(
            kef_curve_mu_with_slope_batch_nan(c, 4, fp, m, m, &mut n_nan),
            "mu",
            "dmu_df_star",
        );
        assert_eq!((mu, n_nan), ([9.0; 4], 9), "nothing written");
        // Adjacent arrays do not overlap; no array with n = 0.
        let mut both = [9.0; 8];
        let b = both.as_mut_ptr();
        assert_eq!(
            kef_curve_mu_with_slope_batch(c, 4, fp, b, b.add(4)),
            KEF_OK,
            "{}",
            last_error()
        );
        assert_eq!(kef_curve_mu_batch(c, 0, fp, fp), KEF_OK, "{}", last_error());
        kef_curve_free(c);
        // Inputs may alias each other: θ and F* from one array.
        let shared = [0.005; 4];
        assert_eq!(
            kef_table_mu_batch(t, 4, psi.as_ptr(), shared.as_ptr(), shared.as_ptr(), m),
            KEF_OK,
            "{}",
            last_error()
        );
    }
    assert_eq!(f, [0.01, 0.02, 0.03, 0.04], "the inputs untouched");
    assert!(mu_written(&f));
}

/// A lookup still works on the inputs after the refused calls.
fn mu_written(f: &[f64; 4]) -> bool {
    let mut mu = [0.0; 4];
    let (psi, theta) = ([1.0; 4], [0.001; 4]);
    // SAFETY: the default table, distinct local arrays of 4.
    let code = unsafe {
        kef_table_mu_batch(
            kef_table_default(),
            4,
            psi.as_ptr(),
            theta.as_ptr(),
            f.as_ptr(),
            mu.as_mut_ptr(),
        )
    };
    code == KEF_OK && mu.iter().all(|&m| m > 0.0)
}
