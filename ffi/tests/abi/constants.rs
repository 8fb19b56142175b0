//! The model constants handle: defaults, setters checked at once, names,
//! and the `_with` functions that take it.

use super::{assert_failed, assert_says, last_error, refused};
use kefriction::*;
use std::ffi::{CStr, CString};
use std::ptr::{null, null_mut};

/// μ by the core itself at ψ = 1, θ = 0.001 with `constants`, for the C
/// calls to match.
/// kef_model_mu_with of `constants` (NULL: the defaults) at ψ = 1,
/// θ = 0.001 and `f_star`, which must answer.
///
/// # Safety
/// `constants` is a live handle or NULL.
unsafe fn mu_at(constants: *const kef_constants, f_star: f64) -> f64 {
    let mut mu = f64::NAN;
    // SAFETY: by the contract, and a local double.
    let code = unsafe { kef_model_mu_with(constants, 1.0, 0.001, f_star, &mut mu) };
    assert_eq!(code, KEF_OK, "{}", last_error());
    mu
}

fn core_mu(constants: ke_friction::Constants, f_star: f64) -> f64 {
    let params = constants.at(1.0, 0.001).unwrap();
    ke_friction::Model::new(params)
        .unwrap()
        .at_f_star(f_star)
        .unwrap()
        .mu
        .unwrap()
}

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
        let printed = mu_at(c, 0.01);
        assert_ne!(printed, base);
        assert_eq!(kef_constants_set_model(c, ceb.as_ptr()), KEF_OK);
        assert_eq!(name(kef_constants_model(c)), "ceb");
        let ceb_mu = mu_at(c, 0.01);
        assert_ne!(ceb_mu, base);
        let expected = core_mu(
            ke_friction::Constants::default()
                .fit(ke_friction::Fit::AsPrinted)
                .kind(ke_friction::ModelKind::CebType),
            0.01,
        );
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
        assert_failed(
            kef_constants_set_beta(c, 0.01),
            KEF_ERR_DOMAIN,
            "beta = 0.01 is out of range",
        );
        assert_eq!(kef_constants_beta(c), 0.04);
        assert_failed(kef_constants_set_beta(c, f64::NAN), KEF_ERR_ARGUMENT, "beta = NaN");
        assert_failed(kef_constants_set_nu(c, 0.5), KEF_ERR_DOMAIN, "nu = 0.5");
        assert_failed(
            kef_constants_set_eps_star(c, f64::INFINITY),
            KEF_ERR_ARGUMENT,
            "eps_star = inf",
        );
        assert_eq!(kef_constants_eps_star(c), 0.004);

        assert_eq!(kef_constants_set_fit(c, bad.as_ptr()), KEF_ERR_ARGUMENT);
        assert_eq!(
            last_error(),
            "fit 'AsPrinted' is unknown: must be one of consistent, as-printed"
        );
        assert_eq!(name(kef_constants_fit(c)), "consistent");
        assert_eq!(kef_constants_set_model(c, bad.as_ptr()), KEF_ERR_ARGUMENT);
        // The names of the core's registry (LAWS), not a list here.
        let laws = <ke_friction::ModelKind as ke_friction::Named>::names().join(", ");
        assert_eq!(
            last_error(),
            format!("model 'AsPrinted' is unknown: must be one of {laws}")
        );
        refused(kef_constants_set_model(c, null()), "name is NULL");
        refused(kef_constants_set_beta(null_mut(), 0.05), "constants is NULL");

        // Parameter errors of the _with functions.
        let mut mu = 7.0;
        assert_failed(
            kef_model_mu_with(c, -1.0, 0.001, 0.01, &mut mu),
            KEF_ERR_DOMAIN,
            "psi = -1 is out of range",
        );
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

/// The distribution of `c` as (family, skewness, kurtosis).
///
/// # Safety
/// `c` is NULL or a live handle.
unsafe fn distribution_of(c: *const kef_constants) -> (i32, f64, f64) {
    let (mut family, mut sk, mut k) = (-9, f64::NAN, f64::NAN);
    // SAFETY: the caller's handle, local outputs.
    assert_eq!(
        unsafe { kef_constants_distribution(c, &mut family, &mut sk, &mut k) },
        KEF_OK
    );
    (family, sk, k)
}

#[test]
fn the_heights_distribution_reaches_the_model() {
    let c = kef_constants_new();
    // SAFETY (every call): a live handle or NULL, local doubles.
    unsafe {
        assert_eq!(distribution_of(c), (KEF_DIST_GAUSSIAN, 0.0, 3.0));
        assert_eq!(distribution_of(null()), (KEF_DIST_GAUSSIAN, 0.0, 3.0));
        let gauss = mu_at(c, 1e-4);
        assert!((gauss - 0.7567111956).abs() < 1e-9, "{gauss}");

        // Pearson(0, 8) and Pearson(-0.5, 3.375): the reference values.
        for (sk, k, want) in [(0.0, 8.0, 0.2529016383), (-0.5, 3.375, 1.004869931)] {
            assert_eq!(
                kef_constants_set_distribution(c, KEF_DIST_PEARSON, sk, k),
                KEF_OK,
                "{}",
                last_error()
            );
            assert_eq!(distribution_of(c), (KEF_DIST_PEARSON, sk, k));
            let mu = mu_at(c, 1e-4);
            assert!((mu - want).abs() < 1e-9, "Pearson({sk}, {k}): {mu}");
            // A curve of the same constants agrees.
            let curve = kef_curve_from_model_with(c, 1.0, 0.001, 1e-5, 1e-3);
            assert!(!curve.is_null(), "{}", last_error());
            let mut from_curve = 0.0;
            assert_eq!(kef_curve_mu(curve, 1e-4, &mut from_curve), KEF_OK);
            assert!((from_curve / mu - 1.0).abs() < 1e-6, "{from_curve} {mu}");
            kef_curve_free(curve);
        }
        // Pearson(0, 3) is the Gaussian, to the bit.
        assert_eq!(kef_constants_set_distribution(c, KEF_DIST_PEARSON, 0.0, 3.0), KEF_OK);
        let normal = mu_at(c, 1e-4);
        assert_eq!(normal, gauss);

        // Weibull: the kurtosis argument is ignored; the getter gives the
        // one the skewness implies.
        assert_eq!(
            kef_constants_set_distribution(c, KEF_DIST_WEIBULL, 0.0, f64::NAN),
            KEF_OK,
            "{}",
            last_error()
        );
        let (family, sk, k) = distribution_of(c);
        assert_eq!((family, sk), (KEF_DIST_WEIBULL, 0.0));
        assert!((k - 2.717).abs() < 1e-3, "{k}");
        let expected = core_mu(
            ke_friction::Constants::default().distribution(ke_friction::HeightDistribution::weibull(0.0).unwrap()),
            1e-4,
        );
        let weibull = mu_at(c, 1e-4);
        assert_eq!(weibull, expected);

        // The Gaussian ignores both numbers.
        assert_eq!(
            kef_constants_set_distribution(c, KEF_DIST_GAUSSIAN, 9.0, f64::NAN),
            KEF_OK
        );
        assert_eq!(distribution_of(c), (KEF_DIST_GAUSSIAN, 0.0, 3.0));
        kef_constants_free(c);
    }
}

#[test]
fn a_bad_distribution_is_refused_with_its_bound_and_the_handle_kept() {
    let c = kef_constants_new();
    // SAFETY (every call): a live handle or NULL, local arrays.
    unsafe {
        assert_eq!(kef_constants_set_distribution(c, KEF_DIST_PEARSON, 0.5, 8.0), KEF_OK);
        // K <= Sk² + 1: the Pearson bound.
        assert_failed(
            kef_constants_set_distribution(c, KEF_DIST_PEARSON, 0.5, 1.2),
            KEF_ERR_DOMAIN,
            "kurtosis = 1.2 is out of range: must be > skewness² + 1",
        );
        assert_eq!(distribution_of(c), (KEF_DIST_PEARSON, 0.5, 8.0));
        assert_failed(
            kef_constants_set_distribution(c, KEF_DIST_PEARSON, 6.0, 50.0),
            KEF_ERR_DOMAIN,
            "skewness = 6 is out of range: must be in [-5, 5]",
        );
        assert_failed(
            kef_constants_set_distribution(c, KEF_DIST_PEARSON, 0.0, 101.0),
            KEF_ERR_DOMAIN,
            "kurtosis = 101 is out of range: must be <= 100",
        );
        // An unknown code, and the empirical family's, which its heights set.
        assert_eq!(kef_constants_set_distribution(c, 7, 0.0, 3.0), KEF_ERR_ARGUMENT);
        // The settable families of the core's registry, each once.
        let message = last_error();
        assert!(message.starts_with("family 7 is unknown: must be "), "{message}");
        for family in ke_friction::Family::ALL
            .into_iter()
            .filter(|f| *f != ke_friction::Family::Empirical)
        {
            let mentions = message.matches(&format!("({})", family.code())).count()
                + message.matches(&format!("({}, ", family.code())).count();
            assert_eq!(mentions, 1, "{family}: {message}");
        }
        for constant in ["KEF_DIST_GAUSSIAN (0)", "KEF_DIST_PEARSON (1)", "KEF_DIST_WEIBULL (2)"] {
            assert!(message.contains(constant), "{message}");
        }
        assert_eq!(
            kef_constants_set_distribution(c, KEF_DIST_EMPIRICAL, 0.0, 3.0),
            KEF_ERR_ARGUMENT
        );
        assert_eq!(
            last_error(),
            "family 3 (KEF_DIST_EMPIRICAL) is set by kef_constants_set_heights"
        );
        assert_eq!(distribution_of(c), (KEF_DIST_PEARSON, 0.5, 8.0));
        assert_failed(
            kef_constants_set_distribution(c, KEF_DIST_PEARSON, f64::NAN, 3.0),
            KEF_ERR_ARGUMENT,
            "skewness = NaN",
        );
        assert_failed(
            kef_constants_set_distribution(c, KEF_DIST_WEIBULL, 2.5, 0.0),
            KEF_ERR_DOMAIN,
            "skewness = 2.5 is out of range: must be in (-1.1395, 2]",
        );
        assert_failed(
            kef_constants_set_distribution(c, 7, 0.0, 3.0),
            KEF_ERR_ARGUMENT,
            "family 7 is unknown",
        );
        assert_eq!(
            kef_constants_set_distribution(c, KEF_DIST_EMPIRICAL, 0.0, 3.0),
            KEF_ERR_ARGUMENT
        );
        assert!(last_error().contains("kef_constants_set_heights"), "{}", last_error());
        refused(
            kef_constants_set_distribution(null_mut(), KEF_DIST_PEARSON, 0.0, 8.0),
            "constants is NULL",
        );
        assert_eq!(distribution_of(c), (KEF_DIST_PEARSON, 0.5, 8.0));

        // Heights: NULL with n > 0, too few, constant, infinite.
        refused(kef_constants_set_heights(c, null(), 200), "heights is NULL");
        assert_failed(
            kef_constants_set_heights(c, null(), 0),
            KEF_ERR_DOMAIN,
            "heights = 0 is out of range",
        );
        let few: Vec<f64> = (0..99).map(f64::from).collect();
        assert_eq!(kef_constants_set_heights(c, few.as_ptr(), few.len()), KEF_ERR_DOMAIN);
        assert!(last_error().contains("at least 100 finite values"), "{}", last_error());
        let flat = vec![2.5; 500];
        assert_eq!(kef_constants_set_heights(c, flat.as_ptr(), flat.len()), KEF_ERR_DOMAIN);
        assert!(last_error().contains("constant"), "{}", last_error());
        let mut inf: Vec<f64> = (0..500).map(|i| f64::from(i).sin()).collect();
        inf[7] = f64::INFINITY;
        assert_failed(
            kef_constants_set_heights(c, inf.as_ptr(), inf.len()),
            KEF_ERR_ARGUMENT,
            "heights = inf",
        );
        assert_eq!(distribution_of(c), (KEF_DIST_PEARSON, 0.5, 8.0));

        // NULL outputs of the getter.
        let (mut family, mut sk) = (-9, 0.0);
        refused(
            kef_constants_distribution(c, &mut family, &mut sk, null_mut()),
            "kurtosis is NULL",
        );
        assert_eq!(family, -9);
        kef_constants_free(c);
    }
}

#[test]
fn measured_heights_give_an_empirical_density_and_are_copied() {
    // Deterministic pseudo-random heights, NaN (missing points) among them.
    let mut state = 7u64;
    let mut heights: Vec<f64> = (0..4000)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let u = ((state >> 11) as f64 + 0.5) / 9007199254740992.0;
            // Exponential-ish heights: skewed.
            -u.ln()
        })
        .collect();
    heights[10] = f64::NAN;
    let c = kef_constants_new();
    // SAFETY (every call): a live handle, a local array of `len` doubles.
    unsafe {
        assert_eq!(
            kef_constants_set_heights(c, heights.as_ptr(), heights.len()),
            KEF_OK,
            "{}",
            last_error()
        );
        let want = ke_friction::HeightDistribution::empirical(&heights).unwrap();
        let (family, sk, k) = distribution_of(c);
        assert_eq!((family, sk, k), (KEF_DIST_EMPIRICAL, want.skewness(), want.kurtosis()));
        assert!(sk > 1.0, "{sk}");
        let mu = mu_at(c, 1e-4);
        // Changing (and dropping) the caller's array changes nothing.
        heights.iter_mut().for_each(|h| *h = 0.0);
        drop(heights);
        let again = mu_at(c, 1e-4);
        assert_eq!(again, mu);
        let expected = core_mu(ke_friction::Constants::default().distribution(want), 1e-4);
        assert_eq!(mu, expected);
        kef_constants_free(c);
    }
}

/// The issue-38 case: ψ, θ of a measured surface whose β is 0.117 and
/// whose heights are Pearson, looked up in the default table. The plain
/// lookup cannot know; kef_table_mu_with refuses, naming β and both values,
/// and answers kef_table_mu's value for the table's own constants.
#[test]
fn a_lookup_with_the_constants_refuses_a_table_built_for_others() {
    let (t, c) = (kef_table_default(), kef_constants_new());
    // SAFETY: live handles, local doubles and arrays of the length given.
    unsafe {
        let (mut plain, mut checked) = (0.0, 0.0);
        assert_eq!(kef_table_mu(t, 1.0, 0.001, 2e-4, &mut plain), KEF_OK);
        assert_eq!(kef_table_mu_with(t, c, 1.0, 0.001, 2e-4, &mut checked), KEF_OK);
        assert_eq!(kef_table_mu_with(t, null(), 1.0, 0.001, 2e-4, &mut checked), KEF_OK);
        assert_eq!(plain, checked);
        assert_eq!(kef_constants_set_beta(c, 0.117), KEF_OK);
        assert_eq!(kef_constants_set_distribution(c, KEF_DIST_PEARSON, 0.3, 3.5), KEF_OK);
        let mut out = 42.0;
        assert_eq!(kef_table_mu_with(t, c, 1.0, 0.001, 2e-4, &mut out), KEF_ERR_DOMAIN);
        assert_eq!(out, 42.0);
        assert_says("beta = 0.117, but the table holds beta = 0.04");
        assert_eq!(kef_constants_set_beta(c, 0.04), KEF_OK);
        assert_failed(
            kef_table_mu_with(t, c, 1.0, 0.001, 2e-4, &mut out),
            KEF_ERR_DOMAIN,
            "distribution = pearson (skewness 0.3, kurtosis 3.5), but the table holds distribution = gaussian",
        );
        let (psi, theta, f) = ([1.0, 2.0], [0.001, 0.002], [1e-3, 1e-2]);
        let mut mu = [7.0; 2];
        assert_eq!(
            kef_table_mu_batch_with(t, c, 2, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), mu.as_mut_ptr()),
            KEF_ERR_DOMAIN
        );
        assert_eq!(mu, [7.0; 2]);
        assert_eq!(
            kef_table_mu_batch_with(t, null(), 2, psi.as_ptr(), theta.as_ptr(), f.as_ptr(), mu.as_mut_ptr()),
            KEF_OK
        );
        assert_eq!(kef_table_mu(t, 2.0, 0.002, 1e-2, &mut plain), KEF_OK);
        assert_eq!(mu[1], plain);
        kef_constants_free(c);
    }
}

#[test]
fn a_distribution_is_chosen_by_its_record_name_as_by_its_code() {
    let (by_name, by_code) = (kef_constants_new(), kef_constants_new());
    // SAFETY (every call): live handles or NULL, NUL-terminated strings.
    unsafe {
        for (name, code) in [
            ("pearson", KEF_DIST_PEARSON),
            ("weibull", KEF_DIST_WEIBULL),
            ("gaussian", KEF_DIST_GAUSSIAN),
        ] {
            let name = CString::new(name).unwrap();
            assert_eq!(
                kef_constants_set_distribution_named(by_name, name.as_ptr(), 0.2, 4.0),
                KEF_OK,
                "{}",
                last_error()
            );
            assert_eq!(kef_constants_set_distribution(by_code, code, 0.2, 4.0), KEF_OK);
            let (mut a, mut b) = (0.0, 0.0);
            assert_eq!(kef_model_mu_with(by_name, 1.0, 0.001, 1e-4, &mut a), KEF_OK);
            assert_eq!(kef_model_mu_with(by_code, 1.0, 0.001, 1e-4, &mut b), KEF_OK);
            assert_eq!(a.to_bits(), b.to_bits(), "{name:?}");
        }
        // An unknown name: the core's message with every name; NULL refused.
        let bad = CString::new("lognormal").unwrap();
        assert_eq!(
            kef_constants_set_distribution_named(by_name, bad.as_ptr(), 0.0, 3.0),
            KEF_ERR_ARGUMENT
        );
        let families = <ke_friction::Family as ke_friction::Named>::names().join(", ");
        assert_eq!(
            last_error(),
            format!("distribution 'lognormal' is unknown: must be one of {families}")
        );
        assert_eq!(
            kef_constants_set_distribution_named(by_name, null(), 0.0, 3.0),
            KEF_ERR_ARGUMENT
        );
        // "empirical" is by kef_constants_set_heights.
        let empirical = CString::new("empirical").unwrap();
        assert_eq!(
            kef_constants_set_distribution_named(by_name, empirical.as_ptr(), 0.0, 3.0),
            KEF_ERR_ARGUMENT
        );
        assert!(last_error().contains("kef_constants_set_heights"), "{}", last_error());
        kef_constants_free(by_name);
        kef_constants_free(by_code);
    }
}

/// A curve from a table for a surface pair's constants: the table's own
/// (or NULL) give kef_curve_from_table's curve; others give NULL, the
/// message naming β and both values.
#[test]
fn a_curve_from_a_table_with_the_constants_refuses_other_constants() {
    let (t, c) = (kef_table_default(), kef_constants_new());
    // SAFETY: live handles and local doubles.
    unsafe {
        let plain = kef_curve_from_table(t, 1.0, 0.001);
        for constants in [c as *const kef_constants, null()] {
            let checked = kef_curve_from_table_with(t, constants, 1.0, 0.001);
            assert!(!checked.is_null(), "{}", last_error());
            for f in [1e-4, 2e-3, 5e-2] {
                let (mut a, mut b) = (0.0, 0.0);
                assert_eq!(kef_curve_mu(plain, f, &mut a), KEF_OK);
                assert_eq!(kef_curve_mu(checked, f, &mut b), KEF_OK);
                assert_eq!(a, b);
            }
            kef_curve_free(checked);
        }
        assert_eq!(kef_constants_set_beta(c, 0.117), KEF_OK);
        assert!(kef_curve_from_table_with(t, c, 1.0, 0.001).is_null());
        assert_says("beta = 0.117, but the table holds beta = 0.04");
        kef_curve_free(plain);
        kef_constants_free(c);
    }
}
