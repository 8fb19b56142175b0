//! The model constants handle: defaults, setters checked at once, names,
//! and the `_with` functions that take it.

use super::last_error;
use kefriction::*;
use std::ffi::{CStr, CString};
use std::ptr::{null, null_mut};

fn name(p: *const std::ffi::c_char) -> String {
    assert!(!p.is_null());
    // SAFETY: a static NUL-terminated name.
    unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_string()
}

#[test]
fn the_handle_round_trips_and_changes_the_model() {
    let c = kef_constants_new();
    assert!(!c.is_null());
    let fit = CString::new("as-printed").unwrap();
    let ceb = CString::new("ceb").unwrap();
    // SAFETY (every call): a live handle or NULL, local doubles, C strings.
    unsafe {
        let defaults = ke_friction::Constants::default();
        assert_eq!(kef_constants_beta(c), defaults.beta);
        assert_eq!(kef_constants_nu(c), defaults.nu);
        assert_eq!(kef_constants_eps_star(c), defaults.eps_star);
        assert_eq!(name(kef_constants_fit(c)), "consistent");
        assert_eq!(name(kef_constants_model(c)), "ke");
        assert_eq!(kef_constants_beta(null()), defaults.beta);
        assert_eq!(name(kef_constants_model(null())), "ke");

        // NULL and a fresh handle are the defaults, and the old function.
        let (mut base, mut fresh, mut old) = (0.0, 0.0, 0.0);
        assert_eq!(kef_model_mu_with(null(), 1.0, 0.001, 0.01, &mut base), KEF_OK);
        assert_eq!(kef_model_mu_with(c, 1.0, 0.001, 0.01, &mut fresh), KEF_OK);
        assert_eq!(kef_model_mu(1.0, 0.001, 0.04, 0.3, 0.004, 0.01, &mut old), KEF_OK);
        assert_eq!((base, fresh), (old, old));
        assert!((base - 0.52521087083).abs() < 1e-10, "{base}");

        assert_eq!(kef_constants_set_fit(c, fit.as_ptr()), KEF_OK);
        assert_eq!(name(kef_constants_fit(c)), "as-printed");
        let mut printed = 0.0;
        assert_eq!(kef_model_mu_with(c, 1.0, 0.001, 0.01, &mut printed), KEF_OK);
        assert_ne!(printed, base);
        assert_eq!(kef_constants_set_model(c, ceb.as_ptr()), KEF_OK);
        assert_eq!(name(kef_constants_model(c)), "ceb");
        let mut ceb_mu = 0.0;
        assert_eq!(kef_model_mu_with(c, 1.0, 0.001, 0.01, &mut ceb_mu), KEF_OK);
        assert_ne!(ceb_mu, base);
        let expected = ke_friction::Model::new(
            ke_friction::Constants::default()
                .fit(ke_friction::Fit::AsPrinted)
                .kind(ke_friction::Kind::CebType)
                .at(1.0, 0.001)
                .unwrap(),
        )
        .unwrap()
        .at_f_star(0.01)
        .unwrap()
        .mu
        .unwrap();
        assert_eq!(ceb_mu, expected);

        assert_eq!(kef_constants_set_beta(c, 0.05), KEF_OK);
        assert_eq!(kef_constants_set_nu(c, 0.25), KEF_OK);
        assert_eq!(kef_constants_set_eps_star(c, 0.003), KEF_OK);
        assert_eq!(
            (kef_constants_beta(c), kef_constants_nu(c), kef_constants_eps_star(c)),
            (0.05, 0.25, 0.003)
        );

        // A curve from the model with the same constants agrees.
        let curve = kef_curve_from_model_with(c, 1.0, 0.001, 1e-3, 1e-2);
        assert!(!curve.is_null(), "{}", last_error());
        let (mut from_curve, mut direct) = (0.0, 0.0);
        assert_eq!(kef_curve_mu(curve, 5e-3, &mut from_curve), KEF_OK);
        assert_eq!(kef_model_mu_with(c, 1.0, 0.001, 5e-3, &mut direct), KEF_OK);
        assert!((from_curve / direct - 1.0).abs() < 1e-6, "{from_curve} {direct}");
        kef_curve_free(curve);
        let curve = kef_curve_from_model_with(null(), 1.0, 0.001, 1e-3, 1e-2);
        assert!(!curve.is_null());
        kef_curve_free(curve);
        kef_constants_free(c);
        kef_constants_free(null_mut());
    }
}

#[test]
fn setters_check_at_once_and_keep_the_handle_on_failure() {
    let c = kef_constants_new();
    let bad = CString::new("AsPrinted").unwrap();
    // SAFETY: a live handle or NULL, C strings.
    unsafe {
        assert_eq!(kef_constants_set_beta(c, 0.01), KEF_ERR_DOMAIN);
        assert!(
            last_error().starts_with("beta = 0.01 is out of range"),
            "{}",
            last_error()
        );
        assert_eq!(kef_constants_beta(c), 0.04);
        assert_eq!(kef_constants_set_beta(c, f64::NAN), KEF_ERR_ARGUMENT);
        assert!(last_error().starts_with("beta = NaN"), "{}", last_error());
        assert_eq!(kef_constants_set_nu(c, 0.5), KEF_ERR_DOMAIN);
        assert!(last_error().starts_with("nu = 0.5"), "{}", last_error());
        assert_eq!(kef_constants_set_eps_star(c, f64::INFINITY), KEF_ERR_ARGUMENT);
        assert!(last_error().starts_with("eps_star = inf"), "{}", last_error());
        assert_eq!(kef_constants_eps_star(c), 0.004);

        assert_eq!(kef_constants_set_fit(c, bad.as_ptr()), KEF_ERR_ARGUMENT);
        assert_eq!(
            last_error(),
            "fit \"AsPrinted\" is unknown: must be \"consistent\" or \"as-printed\""
        );
        assert_eq!(name(kef_constants_fit(c)), "consistent");
        assert_eq!(kef_constants_set_model(c, bad.as_ptr()), KEF_ERR_ARGUMENT);
        assert_eq!(
            last_error(),
            "model \"AsPrinted\" is unknown: must be \"ke\" or \"ceb\""
        );
        assert_eq!(kef_constants_set_model(c, null()), KEF_ERR_ARGUMENT);
        assert_eq!(last_error(), "name is NULL");
        assert_eq!(kef_constants_set_beta(null_mut(), 0.05), KEF_ERR_ARGUMENT);
        assert_eq!(last_error(), "constants is NULL");

        // Parameter errors of the _with functions.
        let mut mu = 7.0;
        assert_eq!(kef_model_mu_with(c, -1.0, 0.001, 0.01, &mut mu), KEF_ERR_DOMAIN);
        assert!(last_error().starts_with("psi = -1 is out of range"), "{}", last_error());
        assert_eq!(kef_model_mu_with(c, 1.0, 0.001, 0.01, null_mut()), KEF_ERR_ARGUMENT);
        assert_eq!(mu, 7.0);
        // No positive μ in the range (the printed fit at ψ = 4): NULL with
        // the core's message.
        let fit = CString::new("as-printed").unwrap();
        assert_eq!(kef_constants_set_fit(c, fit.as_ptr()), KEF_OK);
        assert!(kef_curve_from_model_with(c, 4.0, 0.001, 1e-4, 1e-2).is_null());
        assert!(
            last_error().contains("no positive friction coefficient"),
            "{}",
            last_error()
        );
        kef_constants_free(c);
    }
}
