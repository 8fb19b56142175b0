//! The C ABI from Rust: every exported function, its failures and its
//! messages, threads, and the committed header.

mod aliasing;
mod batches;
mod constants;
mod fortran;
mod law;
mod queries;
mod warnings;

use kefriction::*;
use std::ffi::{c_char, CStr, CString};
use std::ptr::{null, null_mut};

fn last_error() -> String {
    // SAFETY: kef_last_error never returns NULL and its text is NUL-terminated.
    unsafe { CStr::from_ptr(kef_last_error()) }
        .to_str()
        .unwrap()
        .to_string()
}

/// Asserts that a call answered `code` = KEF_ERR_ARGUMENT with the
/// message `message` (kef_last_error).
#[track_caller]
fn refused(code: std::ffi::c_int, message: &str) {
    assert_eq!(code, KEF_ERR_ARGUMENT);
    assert_eq!(last_error(), message);
}

/// Asserts that a call answered `code` = `want` with a message starting
/// with `start` (kef_last_error).
#[track_caller]
fn assert_failed(code: std::ffi::c_int, want: std::ffi::c_int, start: &str) {
    assert_eq!(code, want);
    let message = last_error();
    assert!(message.starts_with(start), "{message}");
}

/// Asserts that the last error's message starts with `start`.
#[track_caller]
fn assert_says(start: &str) {
    let message = last_error();
    assert!(message.starts_with(start), "{message}");
}

/// A scratch directory under the target directory.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("ffi-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn c_path(p: &std::path::Path) -> CString {
    CString::new(p.to_str().unwrap()).unwrap()
}

/// The committed header declares the whole API. That it is exactly
/// cbindgen's output from ffi/src/lib.rs is checked by the package
/// ffi/header-check (`cargo run -p ke-friction-ffi-header-check`, a CI
/// stage), which keeps cbindgen out of the test build.
#[test]
fn the_header_declares_the_api() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let text = std::fs::read_to_string(format!("{dir}/include/kefriction.h")).unwrap();
    for name in [
        "kef_table_default",
        "kef_table_load",
        "kef_table_free",
        "kef_table_mu",
        "kef_table_mu_with_slope",
        "kef_table_mu_batch",
        "kef_curve_from_table",
        "kef_curve_from_model",
        "kef_curve_mu",
        "kef_curve_mu_with_slope",
        "kef_curve_mu_batch",
        "kef_curve_free",
        "kef_model_mu",
        "kef_last_error",
        "int kef_table_mu_batch_nan(",
        "int kef_table_mu_with_slope_batch(",
        "int kef_table_mu_with_slope_batch_nan(",
        "int kef_curve_mu_batch_nan(",
        "int kef_curve_mu_with_slope_batch(",
        "int kef_curve_mu_with_slope_batch_nan(",
        "size_t *n_nan",
        "kef_curve *kef_curve_from_model_with(const kef_constants *constants",
        "int kef_model_mu_with(const kef_constants *constants",
        "kef_constants *kef_constants_new(void);",
        "void kef_constants_free(kef_constants *constants);",
        "int kef_constants_set_beta(kef_constants *constants, double beta);",
        "int kef_constants_set_fit(kef_constants *constants, const char *name);",
        "int kef_constants_set_model(kef_constants *constants, const char *name);",
        "typedef struct kef_constants kef_constants;",
        "#define KEF_ERR_TABLE 4",
        "#define KEF_ERR_NO_MU 6",
        "stays valid until the thread exits",
        "extern \"C\"",
        "typedef struct kef_table kef_table;",
        "const char *kef_version(void);",
        "int kef_table_domain(const kef_table *table,",
        "int kef_table_h_star(const kef_table *table,",
        "int kef_table_h_star_batch(const kef_table *table,",
        "int kef_params_from_physical(double e1,",
        "#define KEF_DIST_GAUSSIAN 0",
        "#define KEF_DIST_PEARSON 1",
        "#define KEF_DIST_WEIBULL 2",
        "#define KEF_DIST_EMPIRICAL 3",
        "int kef_constants_set_distribution(kef_constants *constants,",
        "int kef_constants_set_heights(kef_constants *constants, const double *heights, size_t n);",
        "int kef_constants_distribution(const kef_constants *constants,",
        "typedef struct kef_law kef_law;",
        "#define KEF_LAW_CLAMP 0",
        "#define KEF_LAW_ERROR 1",
        "kef_law *kef_law_new(const kef_constants *constants,",
        "int kef_law_mu_and_derivative(const kef_law *law, double p, double *mu, double *dmu_dp);",
        "int kef_law_clamped(const kef_law *law, int reset, uint64_t *count);",
        "#include <stdint.h>",
    ] {
        assert!(text.contains(name), "the header lacks {name}");
    }
}

#[test]
fn table_lookups_match_the_library_and_fail_cleanly() {
    let t = kef_table_default();
    let table = ke_friction::Table::embedded();
    let (mut mu, mut slope) = (-1.0, -1.0);
    // SAFETY (every call in these tests): the pointers are live tables or
    // curves, NULL, or point to local doubles.
    unsafe {
        assert_eq!(kef_table_mu(t, 1.0, 0.001, 0.01, &mut mu), KEF_OK);
        assert_eq!(mu, table.mu(1.0, 0.001, 0.01).unwrap());
        assert_eq!(
            kef_table_mu_with_slope(t, 1.0, 0.001, 0.01, &mut mu, &mut slope),
            KEF_OK
        );
        assert_eq!((mu, slope), table.mu_with_slope(1.0, 0.001, 0.01).unwrap());
        // Out of the domain: KEF_ERR_DOMAIN; NaN, ±∞: KEF_ERR_ARGUMENT (the
        // core's classification); the message names the argument and the
        // range, the output stays untouched.
        for (psi, theta, f, code, name) in [
            (
                9.0,
                0.001,
                0.01,
                KEF_ERR_DOMAIN,
                "psi = 9 is outside the range [0.5, 8]",
            ),
            (1.0, f64::NAN, 0.01, KEF_ERR_ARGUMENT, "theta = NaN"),
            (1.0, 0.001, f64::INFINITY, KEF_ERR_ARGUMENT, "f_star = inf"),
            (1.0, 0.001, f64::NEG_INFINITY, KEF_ERR_ARGUMENT, "f_star = -inf"),
            (
                1.0,
                0.001,
                0.0,
                KEF_ERR_DOMAIN,
                "f_star = 0 is outside the range [1e-5, 0.1]",
            ),
        ] {
            let mut out = 42.0;
            assert_eq!(kef_table_mu(t, psi, theta, f, &mut out), code);
            assert_eq!(out, 42.0);
            assert!(last_error().contains(name), "{}", last_error());
            let mut s = 42.0;
            assert_eq!(kef_table_mu_with_slope(t, psi, theta, f, &mut out, &mut s), code);
            assert_eq!((out, s), (42.0, 42.0));
        }
        // NULL pointers.
        assert_eq!(kef_table_mu(null(), 1.0, 0.001, 0.01, &mut mu), KEF_ERR_ARGUMENT);
        assert_eq!(last_error(), "table is NULL");
        assert_eq!(kef_table_mu(t, 1.0, 0.001, 0.01, null_mut()), KEF_ERR_ARGUMENT);
        assert_eq!(last_error(), "mu is NULL");
        assert_eq!(
            kef_table_mu_with_slope(t, 1.0, 0.001, 0.01, &mut mu, null_mut()),
            KEF_ERR_ARGUMENT
        );
        assert_eq!(last_error(), "dmu_df_star is NULL");
        // Freeing NULL and the default table does nothing.
        kef_table_free(null_mut());
        kef_table_free(t.cast_mut());
        assert_eq!(kef_table_mu(kef_table_default(), 1.0, 0.001, 0.01, &mut mu), KEF_OK);
    }
}

#[test]
fn batches_name_the_first_bad_element_and_write_nothing_from_it() {
    let t = kef_table_default();
    let psi = [1.0, 2.0, 3.0, 9.0, 1.0, 1.0];
    let theta = [0.001; 6];
    let f = [1e-4, 1e-3, 1e-2, 1e-2, 0.2, 1e-2];
    let mut mu = [-1.0; 6];
    // SAFETY: slices of length 6 (or fewer, as n says); NULL only for n = 0.
    unsafe {
        assert_failed(
            kef_table_mu_batch(t, 6, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), mu.as_mut_ptr()),
            KEF_ERR_DOMAIN,
            "batch element 3: psi = 9",
        );
        let table = ke_friction::Table::embedded();
        for i in 0..3 {
            assert_eq!(mu[i], table.mu(psi[i], theta[i], f[i]).unwrap());
        }
        assert_eq!(&mu[3..], &[-1.0; 3]);
        let mut all = [0.0; 3];
        assert_eq!(
            kef_table_mu_batch(t, 3, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), all.as_mut_ptr()),
            KEF_OK
        );
        assert_eq!(all, mu[..3]);
        assert_eq!(kef_table_mu_batch(t, 0, null(), null(), null(), null_mut()), KEF_OK);
        assert_eq!(
            kef_table_mu_batch(t, 2, psi.as_ptr(), null(), f.as_ptr(), mu.as_mut_ptr()),
            KEF_ERR_ARGUMENT
        );
        assert_eq!(last_error(), "theta is NULL");

        let c = kef_curve_from_table(t, 1.0, 0.001);
        assert!(!c.is_null());
        let loads = [1e-4, 1e-3, f64::NAN, 1e-2];
        let mut out = [-1.0; 4];
        assert_failed(
            kef_curve_mu_batch(c, 4, loads.as_ptr(), out.as_mut_ptr()),
            KEF_ERR_ARGUMENT,
            "batch element 2: f_star = NaN",
        );
        assert!(out[0] > 0.0 && out[1] > 0.0 && out[2] == -1.0 && out[3] == -1.0);
        assert_eq!(kef_curve_mu_batch(c, 2, loads.as_ptr(), out.as_mut_ptr()), KEF_OK);
        assert_eq!(kef_curve_mu_batch(c, 1, null(), out.as_mut_ptr()), KEF_ERR_ARGUMENT);
        kef_curve_free(c);
    }
}

#[test]
fn curves_from_tables_and_from_the_model() {
    // SAFETY: live handles and local doubles.
    unsafe {
        let t = kef_table_default();
        let c = kef_curve_from_table(t, 2.0, 0.003);
        assert!(!c.is_null());
        let (mut mu, mut s, mut lo, mut hi) = (0.0, 0.0, 0.0, 0.0);
        assert_eq!(kef_curve_mu(c, 0.01, &mut mu), KEF_OK);
        let exact = ke_friction::Model::new(ke_friction::Params::new(2.0, 0.003))
            .unwrap()
            .at_f_star(0.01)
            .unwrap()
            .mu
            .unwrap();
        assert!((mu / exact - 1.0).abs() < 1e-4, "{mu} {exact}");
        assert_eq!(kef_curve_mu_with_slope(c, 0.01, &mut mu, &mut s), KEF_OK);
        assert!(s < 0.0);
        assert_eq!(kef_curve_range(c, &mut lo, &mut hi), KEF_OK);
        assert_eq!((lo, hi), (1e-5, 0.1));
        let mut out = 7.0;
        assert_eq!(kef_curve_mu(c, 0.5, &mut out), KEF_ERR_DOMAIN);
        assert_eq!(out, 7.0);
        assert!(last_error().contains("f_star = 0.5"), "{}", last_error());
        assert_eq!(kef_curve_mu(c, 0.01, null_mut()), KEF_ERR_ARGUMENT);
        assert_eq!(kef_curve_mu(null(), 0.01, &mut out), KEF_ERR_ARGUMENT);
        assert_eq!(last_error(), "curve is NULL");
        kef_curve_free(c);
        kef_curve_free(null_mut());

        assert!(kef_curve_from_table(t, 9.0, 0.003).is_null());
        assert!(last_error().contains("psi = 9"), "{}", last_error());
        assert!(kef_curve_from_table(null(), 1.0, 0.003).is_null());
        assert_eq!(last_error(), "table is NULL");

        let m = kef_curve_from_model(1.0, 0.001, 0.04, 0.3, 0.004, 1e-4, 1e-2);
        assert!(!m.is_null());
        assert_eq!(kef_curve_mu(m, 0.01, &mut mu), KEF_OK);
        assert!((mu / 0.52521087083 - 1.0).abs() < 1e-6, "{mu}");
        kef_curve_free(m);
        assert!(kef_curve_from_model(-1.0, 0.001, 0.04, 0.3, 0.004, 1e-4, 1e-2).is_null());
        assert_says("psi = -1 is out of range");
        assert!(kef_curve_from_model(1.0, 0.001, 0.04, 0.3, 0.004, 1e-2, 1e-4).is_null());
        assert!(last_error().contains("f_star_min < f_star_max"), "{}", last_error());
        assert!(kef_curve_from_model(1.0, 0.001, 0.04, 0.3, 0.004, f64::NAN, 1e-2).is_null());
    }
}

#[test]
fn the_model_by_direct_integration() {
    let mut mu = -1.0;
    // SAFETY: a local double, or NULL.
    unsafe {
        assert_eq!(kef_model_mu(1.0, 0.001, 0.04, 0.3, 0.004, 0.01, &mut mu), KEF_OK);
        // MODEL.md §7.
        assert!((mu - 0.52521087083).abs() < 1e-10, "{mu}");
        let mut out = 3.0;
        for (f, code) in [
            (0.0, KEF_ERR_DOMAIN),
            (-1.0, KEF_ERR_DOMAIN),
            (f64::NAN, KEF_ERR_ARGUMENT),
            (f64::INFINITY, KEF_ERR_ARGUMENT),
            (1e30, KEF_ERR_DOMAIN),
        ] {
            assert_eq!(kef_model_mu(1.0, 0.001, 0.04, 0.3, 0.004, f, &mut out), code, "{f}");
            assert_eq!(out, 3.0);
            assert!(last_error().contains("f_star"), "{}", last_error());
        }
        assert_failed(
            kef_model_mu(1.0, 0.001, 0.01, 0.3, 0.004, 0.01, &mut out),
            KEF_ERR_DOMAIN,
            "beta = 0.01 is out of range",
        );
        assert_failed(
            kef_model_mu(1.0, 0.001, f64::NAN, 0.3, 0.004, 0.01, &mut out),
            KEF_ERR_ARGUMENT,
            "beta = NaN",
        );
        assert_eq!(
            kef_model_mu(1.0, 0.001, 0.04, 0.3, 0.004, 0.01, null_mut()),
            KEF_ERR_ARGUMENT
        );
    }
}

#[test]
fn loading_tables_reports_missing_and_damaged_files() {
    let dir = scratch("load");
    // SAFETY: NUL-terminated paths and live handles.
    unsafe {
        let good = dir.join("good.kft");
        std::fs::write(&good, ke_friction::Table::embedded_bytes()).unwrap();
        let t = kef_table_load(c_path(&good).as_ptr());
        assert!(!t.is_null());
        let mut mu = 0.0;
        assert_eq!(kef_table_mu(t, 1.0, 0.001, 0.01, &mut mu), KEF_OK);
        kef_table_free(t);

        let missing = kef_table_load(c_path(&dir.join("missing.kft")).as_ptr());
        assert!(missing.is_null());
        assert!(last_error().contains("missing.kft"), "{}", last_error());
        let mut bytes = ke_friction::Table::embedded_bytes().to_vec();
        let mid = bytes.len() / 2;
        bytes[mid] ^= 0x10;
        let bad = dir.join("bad.kft");
        std::fs::write(&bad, &bytes).unwrap();
        assert!(kef_table_load(c_path(&bad).as_ptr()).is_null());
        assert!(last_error().contains("checksum"), "{}", last_error());
        assert!(kef_table_load(null::<c_char>()).is_null());
        assert_eq!(last_error(), "path is NULL");
    }
    // The codes: a missing file is KEF_ERR_IO, a damaged one KEF_ERR_TABLE
    // (checked through the message's source: the codes are not returned by
    // a NULL-returning function, so compare with what the library says).
    assert!(matches!(
        ke_friction::Table::load(dir.join("missing.kft")),
        Err(ke_friction::TableError::Io { .. })
    ));
}

#[test]
fn one_table_and_one_curve_serve_many_threads() {
    let t = kef_table_default() as usize;
    // SAFETY: a live table.
    let c = unsafe { kef_curve_from_table(t as *const kef_table, 1.0, 0.003) } as usize;
    let table = ke_friction::Table::embedded();
    let curve = table.curve(1.0, 0.003).unwrap();
    std::thread::scope(|s| {
        for k in 0..4 {
            let (table, curve) = (&table, &curve);
            s.spawn(move || {
                for i in 0..2000 {
                    let f = 1e-5 * 1.004f64.powi(i + 100 * k);
                    let psi = 0.5 + (i % 75) as f64 * 0.1;
                    let (mut a, mut b) = (0.0, 0.0);
                    // SAFETY: the table and curve stay alive until the scope ends.
                    unsafe {
                        assert_eq!(kef_table_mu(t as *const kef_table, psi, 0.003, f, &mut a), KEF_OK);
                        assert_eq!(kef_curve_mu(c as *const kef_curve, f, &mut b), KEF_OK);
                        // A failure here sets only this thread's message.
                        assert_eq!(
                            kef_curve_mu(c as *const kef_curve, 1.0 + k as f64, &mut b),
                            KEF_ERR_DOMAIN
                        );
                    }
                    assert_eq!(a, table.mu(psi, 0.003, f).unwrap());
                    assert_eq!(b, curve.mu(f).unwrap_or(b));
                    assert!(
                        last_error().contains(&format!("f_star = {}", 1 + k)),
                        "{}",
                        last_error()
                    );
                }
            });
        }
    });
    // SAFETY: every thread is done with it.
    unsafe { kef_curve_free(c as *mut kef_curve) };
}
