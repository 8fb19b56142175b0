//! The batch forms: NaN mode, slopes into two arrays, the Stop contract
//! across the chunks of the slope batches, and NULL pointers.

use super::{assert_failed, assert_says, refused};
use ke_friction::Table;
use kefriction::*;
use std::ptr::{null, null_mut};

/// `n` valid table queries (ψ, θ, F*), varied.
fn queries(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let psi = (0..n).map(|i| 0.5 + (i % 75) as f64 * 0.1).collect();
    let theta = (0..n).map(|i| (i % 11) as f64 * 1e-3).collect();
    let f = (0..n).map(|i| 1e-5 * 1.01f64.powi((i % 900) as i32)).collect();
    (psi, theta, f)
}

/// kef_table_mu_with_slope_batch (`nan`: its `_nan` form) of the first
/// `n` queries into `mu` and `slope`: its code and, with `nan`, its count
/// of NaN elements.
///
/// # Safety
/// `t` is a live table.
unsafe fn slope_batch(
    t: *const kef_table,
    n: usize,
    (psi, theta, f): (&[f64], &[f64], &[f64]),
    mu: &mut [f64],
    slope: &mut [f64],
    nan: bool,
) -> (std::ffi::c_int, Option<usize>) {
    assert!([psi.len(), theta.len(), f.len(), mu.len(), slope.len()]
        .iter()
        .all(|&len| len >= n));
    let (p, th, fs, m, sl) = (
        psi.as_ptr(),
        theta.as_ptr(),
        f.as_ptr(),
        mu.as_mut_ptr(),
        slope.as_mut_ptr(),
    );
    let mut n_nan = usize::MAX;
    // SAFETY: `t` by the contract; slices of `n` values at least.
    unsafe {
        if nan {
            (
                kef_table_mu_with_slope_batch_nan(t, n, p, th, fs, m, sl, &mut n_nan),
                Some(n_nan),
            )
        } else {
            (kef_table_mu_with_slope_batch(t, n, p, th, fs, m, sl), None)
        }
    }
}

#[test]
fn nan_mode_marks_bad_points_and_counts_them() {
    let t = kef_table_default();
    let table = Table::embedded();
    let psi = [1.0, 2.0, 3.0, 4.0];
    let theta = [0.001; 4];
    let f = [1e-4, 1e-3, f64::NAN, 1e-2];
    let (mut mu, mut slope, mut n_nan) = ([-1.0; 4], [-1.0; 4], 99);
    // SAFETY (every call in this file): slices of length n, local outputs,
    // or NULL.
    unsafe {
        let code = kef_table_mu_batch_nan(
            t,
            4,
            psi.as_ptr(),
            theta.as_ptr(),
            f.as_ptr(),
            mu.as_mut_ptr(),
            &mut n_nan,
        );
        assert_eq!((code, n_nan), (KEF_OK, 1));
        assert!(mu[2].is_nan());
        for i in [0, 1, 3] {
            assert_eq!(mu[i], table.mu(psi[i], theta[i], f[i]).unwrap());
        }
        assert_eq!(
            slope_batch(t, 4, (&psi, &theta, &f), &mut mu, &mut slope, true),
            (KEF_OK, Some(1))
        );
        assert!(mu[2].is_nan() && slope[2].is_nan());
        for i in [0, 1, 3] {
            assert_eq!((mu[i], slope[i]), table.mu_with_slope(psi[i], theta[i], f[i]).unwrap());
        }
        // Out of the domain counts too; all good is 0.
        let far = [1e-4, 0.5, 1e-3, 1e-2];
        assert_eq!(
            kef_table_mu_batch_nan(
                t,
                4,
                psi.as_ptr(),
                theta.as_ptr(),
                far.as_ptr(),
                mu.as_mut_ptr(),
                &mut n_nan
            ),
            KEF_OK
        );
        assert_eq!(n_nan, 1);
        assert!(mu[1].is_nan() && mu[2] > 0.0);
        assert_eq!(
            kef_table_mu_batch_nan(
                t,
                2,
                psi.as_ptr(),
                theta.as_ptr(),
                f.as_ptr(),
                mu.as_mut_ptr(),
                &mut n_nan
            ),
            KEF_OK
        );
        assert_eq!(n_nan, 0);

        let c = kef_curve_from_table(t, 1.0, 0.001);
        let curve = table.curve(1.0, 0.001).unwrap();
        n_nan = 99;
        assert_eq!(
            kef_curve_mu_batch_nan(c, 4, f.as_ptr(), mu.as_mut_ptr(), &mut n_nan),
            KEF_OK
        );
        assert_eq!(n_nan, 1);
        assert!(mu[2].is_nan());
        for i in [0, 1, 3] {
            assert_eq!(mu[i], curve.mu(f[i]).unwrap());
        }
        n_nan = 99;
        let code = kef_curve_mu_with_slope_batch_nan(c, 4, f.as_ptr(), mu.as_mut_ptr(), slope.as_mut_ptr(), &mut n_nan);
        assert_eq!((code, n_nan), (KEF_OK, 1));
        assert!(mu[2].is_nan() && slope[2].is_nan());
        for i in [0, 1, 3] {
            assert_eq!((mu[i], slope[i]), curve.mu_with_slope(f[i]).unwrap());
        }

        // NULL: arrays only with n = 0; n_nan always required.
        assert_eq!(kef_curve_mu_batch_nan(c, 0, null(), null_mut(), &mut n_nan), KEF_OK);
        assert_eq!(n_nan, 0);
        assert_eq!(
            kef_table_mu_batch_nan(t, 0, null(), null(), null(), null_mut(), &mut n_nan),
            KEF_OK
        );
        refused(
            kef_curve_mu_batch_nan(c, 4, f.as_ptr(), mu.as_mut_ptr(), null_mut()),
            "n_nan is NULL",
        );
        refused(
            kef_table_mu_batch_nan(t, 4, psi.as_ptr(), null(), f.as_ptr(), mu.as_mut_ptr(), &mut n_nan),
            "theta is NULL",
        );
        refused(
            kef_curve_mu_with_slope_batch_nan(c, 4, f.as_ptr(), mu.as_mut_ptr(), null_mut(), &mut n_nan),
            "dmu_df_star is NULL",
        );
        refused(
            kef_curve_mu_batch_nan(null(), 0, null(), null_mut(), &mut n_nan),
            "curve is NULL",
        );
        kef_curve_free(c);
    }
}

#[test]
fn slope_batches_stop_at_the_first_bad_element_across_chunks() {
    let t = kef_table_default();
    let table = Table::embedded();
    let n = 700;
    let (psi, theta, mut f) = queries(n);
    f[300] = 0.5;
    f[650] = f64::NAN;
    let (mut mu, mut slope) = (vec![-1.0; n], vec![-1.0; n]);
    // SAFETY: vectors of length n.
    unsafe {
        let (code, _) = slope_batch(t, n, (&psi, &theta, &f), &mut mu, &mut slope, false);
        assert_failed(code, KEF_ERR_DOMAIN, "batch element 300: f_star = 0.5");
        for i in 0..300 {
            assert_eq!(
                (mu[i], slope[i]),
                table.mu_with_slope(psi[i], theta[i], f[i]).unwrap(),
                "{i}"
            );
        }
        assert!(mu[300..].iter().chain(&slope[300..]).all(|&v| v == -1.0));
        // The whole of a good batch, and the NaN count of the bad one.
        let (code, _) = slope_batch(t, 300, (&psi, &theta, &f), &mut mu, &mut slope, false);
        assert_eq!(code, KEF_OK);
        assert_eq!(
            slope_batch(t, n, (&psi, &theta, &f), &mut mu, &mut slope, true),
            (KEF_OK, Some(2))
        );
        assert!(mu[300].is_nan() && mu[650].is_nan() && mu[699] > 0.0);

        let c = kef_curve_from_table(t, 2.0, 0.003);
        let curve = table.curve(2.0, 0.003).unwrap();
        let (mut mu, mut slope) = (vec![-1.0; n], vec![-1.0; n]);
        let code = kef_curve_mu_with_slope_batch(c, n, f.as_ptr(), mu.as_mut_ptr(), slope.as_mut_ptr());
        assert_failed(code, KEF_ERR_DOMAIN, "batch element 300: f_star = 0.5");
        for i in 0..300 {
            assert_eq!((mu[i], slope[i]), curve.mu_with_slope(f[i]).unwrap(), "{i}");
        }
        assert!(mu[300..].iter().chain(&slope[300..]).all(|&v| v == -1.0));
        // A NaN is KEF_ERR_ARGUMENT (the core's classification).
        let code = kef_curve_mu_with_slope_batch(c, 350, f[301..].as_ptr(), mu.as_mut_ptr(), slope.as_mut_ptr());
        assert_failed(code, KEF_ERR_ARGUMENT, "batch element 349: f_star = NaN");
        assert_eq!(
            kef_curve_mu_with_slope_batch(c, 0, null(), null_mut(), null_mut()),
            KEF_OK
        );
        refused(
            kef_curve_mu_with_slope_batch(c, 1, f.as_ptr(), null_mut(), slope.as_mut_ptr()),
            "mu is NULL",
        );
        kef_curve_free(c);
    }
}

#[test]
fn stop_mode_leaves_the_tail_untouched() {
    let t = kef_table_default();
    let (psi, theta, mut f) = queries(10);
    f[6] = f64::NAN;
    let mut mu = [-1.0; 10];
    // SAFETY: arrays of length 10.
    unsafe {
        let code = kef_table_mu_batch(t, 10, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), mu.as_mut_ptr());
        assert_failed(code, KEF_ERR_ARGUMENT, "batch element 6: f_star = NaN");
        assert!(mu[..6].iter().all(|&m| m > 0.0));
        assert_eq!(&mu[6..], &[-1.0; 4]);
        let c = kef_curve_from_table(t, 1.0, 0.003);
        let mut mu = [-1.0; 10];
        assert_failed(
            kef_curve_mu_batch(c, 10, f.as_ptr(), mu.as_mut_ptr()),
            KEF_ERR_ARGUMENT,
            "batch element 6: ",
        );
        assert!(mu[..6].iter().all(|&m| m > 0.0));
        assert_eq!(&mu[6..], &[-1.0; 4]);
        kef_curve_free(c);
    }
}

#[test]
fn the_last_error_pointer_stays_valid_and_shows_the_message_formatted_last() {
    let t = kef_table_default();
    let p = kef_last_error();
    let mut mu = 0.0;
    // SAFETY: a live table, a local double; `p` is valid for the thread's life.
    unsafe {
        assert_eq!(kef_table_mu(t, 9.0, 0.001, 0.01, &mut mu), KEF_ERR_DOMAIN);
        assert_eq!(kef_last_error(), p);
        let first = std::ffi::CStr::from_ptr(p).to_str().unwrap().to_string();
        assert!(first.starts_with("psi = 9"), "{first}");
        assert_eq!(kef_table_mu(t, 1.0, 0.001, 0.5, &mut mu), KEF_ERR_DOMAIN);
        // A lookup's message is formatted when kef_last_error asks for it;
        // until then the buffer holds the one before.
        assert!(std::ffi::CStr::from_ptr(p).to_str().unwrap().starts_with("psi = 9"));
        assert_eq!(kef_last_error(), p);
        assert!(std::ffi::CStr::from_ptr(p)
            .to_str()
            .unwrap()
            .starts_with("f_star = 0.5"));
        // A message longer than the buffer is cut at a character boundary.
        let long = format!("/nonexistent/{}é.kft", "é".repeat(1500));
        let path = std::ffi::CString::new(long).unwrap();
        assert!(kef_table_load(path.as_ptr()).is_null());
        assert_eq!(kef_last_error(), p);
        let cut = std::ffi::CStr::from_ptr(p).to_bytes().len();
        assert!((1020..=1023).contains(&cut), "{cut}");
        assert_says("cannot read table /nonexistent/éé");
    }
}
