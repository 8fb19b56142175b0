//! The library's version, a table's domain, h* from a table (one point and
//! a batch), and the parameters from physical quantities.

use super::{assert_failed, last_error, refused};
use kefriction::*;
use std::ffi::CStr;
use std::ptr::{null, null_mut};

#[test]
fn the_version_is_the_crates() {
    let v = kef_version();
    assert!(!v.is_null());
    assert_eq!(v, kef_version(), "a static string");
    // SAFETY: a static NUL-terminated string.
    let text = unsafe { CStr::from_ptr(v) }.to_str().unwrap();
    assert_eq!(text, env!("CARGO_PKG_VERSION"));
    assert_eq!(text.split('.').count(), 3, "{text}");
}

#[test]
fn the_domain_is_the_tables_and_bounds_its_lookups() {
    let t = kef_table_default();
    let d = ke_friction::Table::embedded().domain();
    let mut r = [f64::NAN; 6];
    let [a, b, c, e, f, g] = r.each_mut().map(|x| x as *mut f64);
    // SAFETY (every call): a live table or NULL, local doubles or NULL.
    unsafe {
        assert_eq!(kef_table_domain(t, a, b, c, e, f, g), KEF_OK);
        assert_eq!(r, [d.psi.0, d.psi.1, d.theta.0, d.theta.1, d.f_star.0, d.f_star.1]);
        assert_eq!(r, [0.5, 8.0, 0.0, 0.01, 1e-5, 0.1]);
        let mut mu = 0.0;
        // The corners are inside; a step past any end is KEF_ERR_DOMAIN.
        assert_eq!(kef_table_mu(t, r[0], r[2], r[4], &mut mu), KEF_OK);
        assert_eq!(kef_table_mu(t, r[1], r[3], r[5], &mut mu), KEF_OK);
        assert_eq!(kef_table_mu(t, r[1] * 1.01, r[3], r[5], &mut mu), KEF_ERR_DOMAIN);
        assert_eq!(kef_table_mu(t, r[0], r[2], r[5] * 1.01, &mut mu), KEF_ERR_DOMAIN);

        let mut untouched = [7.0; 6];
        let [a, b, c, e, f, _] = untouched.each_mut().map(|x| x as *mut f64);
        refused(kef_table_domain(t, a, b, c, e, f, null_mut()), "f_star_max is NULL");
        assert_eq!(untouched, [7.0; 6]);
        let [a, b, c, e, f, g] = untouched.each_mut().map(|x| x as *mut f64);
        refused(kef_table_domain(null(), a, b, c, e, f, g), "table is NULL");
        assert_eq!(untouched, [7.0; 6]);
    }
}

#[test]
fn h_star_from_the_table_point_and_batch() {
    let t = kef_table_default();
    let table = ke_friction::Table::embedded();
    // SAFETY (every call): a live table or NULL, local doubles and arrays
    // of the length given, NULL only where n is 0 or to test it.
    unsafe {
        let mut h = -1.0;
        assert_eq!(kef_table_h_star(t, 1.0, 0.001, 0.01, &mut h), KEF_OK);
        assert_eq!(h, table.h_star(1.0, 0.001, 0.01).unwrap());
        let mut heavier = -1.0;
        assert_eq!(kef_table_h_star(t, 1.0, 0.001, 0.05, &mut heavier), KEF_OK);
        assert!(heavier < h, "a larger load, a smaller separation: {heavier} {h}");
        // Within the table's accuracy of direct integration.
        let exact = ke_friction::Model::new(ke_friction::Params::new(1.0, 0.001))
            .unwrap()
            .at_f_star(0.01)
            .unwrap()
            .h_star;
        assert!((h / exact - 1.0).abs() < 1e-3, "{h} {exact}");

        let mut out = 5.0;
        assert_eq!(kef_table_h_star(t, 9.0, 0.001, 0.01, &mut out), KEF_ERR_DOMAIN);
        assert!(
            last_error().contains("psi = 9 is outside the range [0.5, 8]"),
            "{}",
            last_error()
        );
        assert_eq!(kef_table_h_star(t, 1.0, f64::NAN, 0.01, &mut out), KEF_ERR_ARGUMENT);
        assert!(last_error().contains("theta = NaN"), "{}", last_error());
        assert_eq!(out, 5.0);
        refused(kef_table_h_star(t, 1.0, 0.001, 0.01, null_mut()), "h_star is NULL");
        refused(kef_table_h_star(null(), 1.0, 0.001, 0.01, &mut out), "table is NULL");

        let psi = [1.0, 2.0, 4.0, 1.0, 1.0];
        let theta = [0.001, 0.003, 0.0, 0.001, 0.001];
        let f = [1e-4, 1e-2, 0.1, 0.2, 1e-2];
        let mut hs = [-1.0; 5];
        assert_eq!(
            kef_table_h_star_batch(t, 3, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), hs.as_mut_ptr()),
            KEF_OK
        );
        for i in 0..3 {
            assert_eq!(hs[i], table.h_star(psi[i], theta[i], f[i]).unwrap());
        }
        let mut hs = [-1.0; 5];
        assert_failed(
            kef_table_h_star_batch(t, 5, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), hs.as_mut_ptr()),
            KEF_ERR_DOMAIN,
            "batch element 3: f_star = 0.2 is outside the range",
        );
        assert!(hs[..3].iter().all(|&h| h > 0.0), "{hs:?}");
        assert_eq!(hs[3..], [-1.0; 2]);
        let nan = [1e-2, f64::NAN];
        assert_failed(
            kef_table_h_star_batch(t, 2, psi.as_ptr(), theta.as_ptr(), nan.as_ptr(), hs.as_mut_ptr()),
            KEF_ERR_ARGUMENT,
            "batch element 1: f_star = NaN",
        );
        assert_eq!(kef_table_h_star_batch(t, 0, null(), null(), null(), null_mut()), KEF_OK);
        refused(
            kef_table_h_star_batch(t, 2, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), null_mut()),
            "h_star is NULL",
        );
    }
}

/// Aluminium on steel, σ = 100 nm, R = 10 µm, β = 0.04, Δγ = 0.3 J/m²,
/// ε = 0.4 nm (the core's example).
pub(crate) const ALUMINIUM_ON_STEEL: [f64; 10] = [
    70e9,
    0.33,
    210e9,
    0.3,
    1.0e9,
    100e-9,
    10e-6,
    0.04 / (10e-6 * 100e-9),
    0.3,
    0.4e-9,
];

fn from_physical(x: [f64; 10], out: &mut [f64; 5]) -> i32 {
    let [psi, theta, beta, nu, eps_star] = out.each_mut().map(|x| x as *mut f64);
    // SAFETY: five local doubles.
    unsafe {
        kef_params_from_physical(
            x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9], psi, theta, beta, nu, eps_star,
        )
    }
}

#[test]
fn parameters_from_physical_quantities_are_the_cores() {
    let x = ALUMINIUM_ON_STEEL;
    let mut out = [f64::NAN; 5];
    assert_eq!(from_physical(x, &mut out), KEF_OK);
    let p = ke_friction::Params::from_physical(&ke_friction::Physical {
        e1: x[0],
        nu1: x[1],
        e2: x[2],
        nu2: x[3],
        hardness: x[4],
        sigma: x[5],
        radius: x[6],
        density: x[7],
        delta_gamma: x[8],
        epsilon: x[9],
    })
    .unwrap();
    assert_eq!(
        out,
        [p.psi, p.theta, p.constants.beta, p.constants.nu, p.constants.eps_star]
    );
    assert!((out[1] - 0.003).abs() < 1e-15, "theta = Δγ/(σH): {}", out[1]);
    assert!(
        (out[2] - 0.04).abs() < 1e-12 && (out[4] - 0.004).abs() < 1e-12,
        "{out:?}"
    );
    assert_eq!(out[3], 0.33);
    // The five feed kef_model_mu.
    let mut mu = 0.0;
    // SAFETY: a local double.
    assert_eq!(
        unsafe { kef_model_mu(out[0], out[1], out[2], out[3], out[4], 0.01, &mut mu) },
        KEF_OK,
        "{}",
        last_error()
    );
    assert!(mu > 0.0);

    // Failures: the message names the input and its range; nothing written.
    for (i, value, code, message) in [
        (0, -1.0, KEF_ERR_DOMAIN, "e1 = -1 is out of range: must be > 0 Pa"),
        (1, 0.5, KEF_ERR_DOMAIN, "nu1 = 0.5 is out of range"),
        (5, f64::NAN, KEF_ERR_ARGUMENT, "sigma = NaN"),
        (8, f64::INFINITY, KEF_ERR_ARGUMENT, "delta_gamma = inf"),
        (7, 1e9, KEF_ERR_DOMAIN, "beta (= density·radius·sigma)"),
    ] {
        let mut bad = x;
        bad[i] = value;
        let mut out = [9.0; 5];
        assert_eq!(from_physical(bad, &mut out), code, "input {i} = {value}");
        assert!(last_error().starts_with(message), "{}", last_error());
        assert_eq!(out, [9.0; 5]);
    }
    let mut out = [9.0; 5];
    let [psi, theta, beta, _, eps_star] = out.each_mut().map(|x| x as *mut f64);
    // SAFETY: local doubles, and one NULL.
    let code = unsafe {
        kef_params_from_physical(
            x[0],
            x[1],
            x[2],
            x[3],
            x[4],
            x[5],
            x[6],
            x[7],
            x[8],
            x[9],
            psi,
            theta,
            beta,
            null_mut(),
            eps_star,
        )
    };
    refused(code, "nu is NULL");
    assert_eq!(out, [9.0; 5]);
}
