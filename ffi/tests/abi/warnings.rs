//! The warnings of the C ABI: KEF_WARN_* are the core's kinds' bits; the
//! direct integration sets them for the result it returns, a failure sets
//! none; F* > 1 is KEF_ERR_DOMAIN (issue 37, case 1).

use super::*;
use ke_friction::{Named, WarningKind};

fn message(kind: std::ffi::c_int) -> String {
    // SAFETY: kef_warning_message never returns NULL; its text is NUL-terminated.
    unsafe { CStr::from_ptr(kef_warning_message(kind)) }
        .to_str()
        .unwrap()
        .to_string()
}

#[test]
fn the_c_bits_are_the_cores_kinds() {
    let c = [
        (KEF_WARN_F_STAR_BELOW_RANGE, "f_star_below_range"),
        (KEF_WARN_F_STAR_ABOVE_RANGE, "f_star_above_range"),
        (KEF_WARN_NEGATIVE_SEPARATION, "negative_separation"),
        (KEF_WARN_ADHESION_DOMINATED, "adhesion_dominated"),
        (KEF_WARN_FEW_ASPERITIES, "few_asperities"),
        (KEF_WARN_NON_PERIODIC, "non_periodic"),
        (KEF_WARN_LOW_BANDWIDTH, "low_bandwidth"),
        (KEF_WARN_ANISOTROPY, "anisotropy"),
        (KEF_WARN_INTERVAL_MISMATCH, "interval_mismatch"),
        (KEF_WARN_UNRELIABLE_SCALE, "unreliable_scale"),
        (KEF_WARN_PSI_DOMAIN, "psi_domain"),
        (KEF_WARN_THETA_DOMAIN, "theta_domain"),
        (KEF_WARN_BETA_DOMAIN, "beta_domain"),
        (KEF_WARN_SPIKES, "spikes"),
        (KEF_WARN_TAIL, "tail"),
    ];
    assert_eq!(c.len(), WarningKind::ALL.len(), "a C constant for every kind");
    for (bit, name) in c {
        let kind = WarningKind::parse(name).unwrap();
        assert_eq!(bit as u32, kind.bit(), "{name}");
    }
}

#[test]
fn direct_integration_sets_the_warnings_of_its_result() {
    // Threads have their own warnings: run on a fresh one.
    std::thread::spawn(|| {
        let mut mu = f64::NAN;
        // SAFETY: mu is writable.
        let rc = unsafe { kef_model_mu_with(null(), 1.0, 0.001, 0.01, &mut mu) };
        assert_eq!((rc, kef_warnings()), (KEF_OK, 0), "inside the paper's range");
        assert_eq!(message(KEF_WARN_F_STAR_BELOW_RANGE), "");
        // F* = 1e-7 with adhesion: below the range, and mu > 1.
        // SAFETY: as above.
        let rc = unsafe { kef_model_mu_with(null(), 0.85, 0.0013, 1e-7, &mut mu) };
        assert_eq!(rc, KEF_OK);
        assert!(mu > 1.0, "{mu}");
        assert_eq!(
            kef_warnings(),
            KEF_WARN_F_STAR_BELOW_RANGE | KEF_WARN_ADHESION_DOMINATED
        );
        assert!(message(KEF_WARN_F_STAR_BELOW_RANGE).starts_with("F* = 1e-7 is below the range"));
        assert!(message(KEF_WARN_ADHESION_DOMINATED).contains("adhesion dominates"));
        // The mask accumulates until cleared: F* = 0.5 adds above-range and h* < 0.
        // SAFETY: as above.
        assert_eq!(
            unsafe { kef_model_mu(1.0, 0.001, 0.04, 0.3, 0.004, 0.5, &mut mu) },
            KEF_OK
        );
        assert_eq!(
            kef_warnings(),
            KEF_WARN_F_STAR_BELOW_RANGE
                | KEF_WARN_ADHESION_DOMINATED
                | KEF_WARN_F_STAR_ABOVE_RANGE
                | KEF_WARN_NEGATIVE_SEPARATION
        );
        kef_clear_warnings();
        assert_eq!(kef_warnings(), 0);
        assert_eq!(message(KEF_WARN_NEGATIVE_SEPARATION), "");
        assert_eq!(message(3), "", "not one bit");
        // F* = 2: a pressure above the hardness, KEF_ERR_DOMAIN, mu untouched, no warning.
        let mut untouched = -1.0;
        // SAFETY: as above.
        let rc = unsafe { kef_model_mu_with(null(), 0.85, 0.0013, 2.0, &mut untouched) };
        assert_eq!((rc, untouched, kef_warnings()), (KEF_ERR_DOMAIN, -1.0, 0));
        assert!(
            last_error().contains("f_star = 2 is out of range: must be <= 1"),
            "{}",
            last_error()
        );
    })
    .join()
    .unwrap();
}

/// kef_params_from_physical sets the validity domain's bits for inputs it
/// returns outside the paper's ranges, with their messages; inside them
/// none (issue 48).
#[test]
fn params_from_physical_sets_the_validity_domain_bits() {
    std::thread::spawn(|| {
        let (mut psi, mut theta, mut beta, mut nu, mut eps) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut call = |sigma: f64, radius: f64, density: f64| {
            // SAFETY: the five outputs are distinct and writable.
            unsafe {
                kef_params_from_physical(
                    200e9, 0.3, 200e9, 0.3, 2e9, sigma, radius, density, 0.3, 0.4e-9, &mut psi, &mut theta, &mut beta,
                    &mut nu, &mut eps,
                )
            }
        };
        // sigma = 1 µm, R = 100 µm, eta = 4e8 /m²: beta = 0.04, theta = 1.5e-4, psi ~ 1.
        assert_eq!(call(1e-6, 100e-6, 4e8), KEF_OK);
        assert_eq!(
            kef_warnings(),
            0,
            "inside the domain: psi = {psi}, theta = {theta}, beta = {beta}"
        );
        // sigma = 10 nm: theta = 0.015 (> 0.01), beta = 4e-4 ... below the model's floor: refused.
        // sigma = 20 nm, R = 10 µm, eta = 1e12: beta = 0.2 (> 0.16), theta = 0.0075.
        assert_eq!(call(20e-9, 10e-6, 1e12), KEF_OK);
        assert_eq!(
            kef_warnings() & KEF_WARN_BETA_DOMAIN,
            KEF_WARN_BETA_DOMAIN,
            "beta = {beta}"
        );
        assert!(message(KEF_WARN_BETA_DOMAIN).starts_with("beta = 0.2 is outside in [0.02, 0.16]"));
        kef_clear_warnings();
        assert_eq!((kef_warnings(), message(KEF_WARN_BETA_DOMAIN)), (0, String::new()));
        // sigma = 5 µm, R = 5 µm: psi = (2E/(pi K H))·(sigma_s/R)^½ far above 8.
        assert_eq!(call(5e-6, 5e-6, 1.6e9), KEF_OK);
        assert_ne!(kef_warnings() & KEF_WARN_PSI_DOMAIN, 0, "psi = {psi}");
        assert!(message(KEF_WARN_PSI_DOMAIN).contains("unreasonably small"));
    })
    .join()
    .unwrap();
}
