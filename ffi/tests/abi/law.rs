//! The friction law handle: the library's values through C, its
//! failures and codes, the clamped count, batches, threads, and the
//! message of a failing lookup formatted only when asked for.

use super::{assert_failed, assert_says, last_error, refused};
use ke_friction::{FrictionLaw, OnError, OutOfRange, Params};
use kefriction::*;
use std::ffi::c_char;
use std::ptr::{null, null_mut};

/// H of the tests, Pa.
const H: f64 = 1.2e9;

fn law(policy: std::ffi::c_int) -> *mut kef_law {
    // SAFETY: NULL constants are the defaults.
    let law = unsafe { kef_law_new(null(), 1.0, 0.001, H, 1e4, 1e8, policy) };
    assert!(!law.is_null(), "{}", last_error());
    law
}

#[test]
fn the_law_through_c_is_the_librarys() {
    let c = law(KEF_LAW_ERROR);
    let rust = FrictionLaw::new(Params::new(1.0, 0.001), H, Some((1e4, 1e8)), OutOfRange::Error).unwrap();
    // SAFETY (every call): a live law or NULL, local doubles and arrays of
    // the length given.
    unsafe {
        for p in [1e4, 3.7e5, 2e6, 9.9e7, 1e8] {
            let (mut mu, mut d, mut only) = (0.0, 0.0, 0.0);
            assert_eq!(kef_law_mu_and_derivative(c, p, &mut mu, &mut d), KEF_OK);
            assert_eq!(kef_law_mu(c, p, &mut only), KEF_OK);
            assert_eq!((mu, d), rust.mu_and_derivative(p).unwrap());
            assert_eq!(only, mu);
        }
        let (mut lo, mut hi, mut h) = (0.0, 0.0, 0.0);
        assert_eq!(kef_law_range(c, &mut lo, &mut hi, &mut h), KEF_OK);
        assert_eq!((lo, hi, h), (1e4, 1e8, H));
        assert!(kef_law_max_error(c) <= 1e-6);
        assert!(kef_law_max_error(null()).is_nan());
        // The failures: the core's classification, the output untouched.
        for (p, code, text) in [
            (0.0, KEF_ERR_NO_MU, "pressure = 0 Pa is an open contact"),
            (-5.0, KEF_ERR_NO_MU, "pressure = -5 Pa is an open contact"),
            (f64::NAN, KEF_ERR_ARGUMENT, "pressure = NaN Pa is not a number"),
            (f64::INFINITY, KEF_ERR_ARGUMENT, "pressure = inf Pa is not finite"),
            (
                2e8,
                KEF_ERR_DOMAIN,
                "pressure = 2e8 Pa is outside the law's range [10000, 1e8] Pa",
            ),
        ] {
            let mut out = 42.0;
            assert_eq!(kef_law_mu(c, p, &mut out), code, "{p}");
            assert_eq!(out, 42.0);
            assert!(last_error().starts_with(text), "{}", last_error());
        }
        let mut out = 0.0;
        refused(kef_law_mu(null(), 1e6, &mut out), "law is NULL");
        kef_law_free(c);
        kef_law_free(null_mut());
    }
}

#[test]
fn clamp_counts_and_batches_follow_the_contract() {
    let c = law(KEF_LAW_CLAMP);
    // SAFETY: as above.
    unsafe {
        let p = [5e5, 1.0, -1.0, 1e10, f64::NAN, 2e6];
        let (mut mu, mut d) = ([7.0; 6], [7.0; 6]);
        assert_failed(
            kef_law_mu_and_derivative_batch(c, 6, p.as_ptr(), mu.as_mut_ptr(), d.as_mut_ptr()),
            KEF_ERR_NO_MU,
            "batch element 2: pressure = -1 Pa",
        );
        assert_eq!(&mu[2..], &[7.0; 4]);
        assert_eq!(d[1], 0.0, "clamped below p_min");
        let mut n_nan = 0;
        assert_eq!(
            kef_law_mu_and_derivative_batch_nan(c, 6, p.as_ptr(), mu.as_mut_ptr(), d.as_mut_ptr(), &mut n_nan),
            KEF_OK
        );
        assert_eq!(n_nan, 2);
        let rust = FrictionLaw::new(Params::new(1.0, 0.001), H, Some((1e4, 1e8)), OutOfRange::Clamp).unwrap();
        let (mut want_mu, mut want_d) = ([0.0; 6], [0.0; 6]);
        rust.mu_and_derivative_batch(&p, &mut want_mu, &mut want_d, OnError::Nan)
            .unwrap();
        for i in 0..6 {
            assert_eq!(mu[i].to_bits(), want_mu[i].to_bits(), "{i}");
            assert_eq!(d[i].to_bits(), want_d[i].to_bits(), "{i}");
        }
        let mut only = [0.0; 6];
        assert_eq!(
            kef_law_mu_batch_nan(c, 6, p.as_ptr(), only.as_mut_ptr(), &mut n_nan),
            KEF_OK
        );
        assert_eq!(only[5], mu[5]);
        assert_eq!(kef_law_mu_batch(c, 1, p.as_ptr(), only.as_mut_ptr()), KEF_OK);
        // Clamped: p = 1 and 1e10, in the three batches, then p[0] is not.
        let mut count = 0u64;
        assert_eq!(kef_law_clamped(c, 1, &mut count), KEF_OK);
        assert_eq!(count, 5, "1 in the stopped batch, 2 in each NaN batch");
        assert_eq!(kef_law_clamped(c, 0, &mut count), KEF_OK);
        assert_eq!(count, 0);
        // Aliasing and bad policies.
        assert_eq!(
            kef_law_mu_and_derivative_batch(c, 6, p.as_ptr(), mu.as_mut_ptr(), mu.as_mut_ptr()),
            KEF_ERR_ARGUMENT
        );
        assert!(last_error().contains("overlap"), "{}", last_error());
        assert!(kef_law_new(null(), 1.0, 0.001, H, 0.0, 0.0, 7).is_null());
        assert_says("policy = 7 is unknown");
        assert!(kef_law_new(null(), 1.0, 0.001, H, 1e8, 1e4, KEF_LAW_CLAMP).is_null());
        assert_says("pressure range [1e8, 10000] Pa is invalid");
        kef_law_free(c);
    }
}

/// kef_law_from_physical of `p`, the law's default range, clamped.
fn law_from_physical(p: &ke_friction::Physical) -> *mut kef_law {
    kef_law_from_physical(
        p.e1,
        p.nu1,
        p.e2,
        p.nu2,
        p.hardness,
        p.sigma,
        p.radius,
        p.density,
        p.delta_gamma,
        p.epsilon,
        0.0,
        0.0,
        KEF_LAW_CLAMP,
    )
}

/// kef_law_from_surface of the file `path` with `family` (NULL: the
/// default) and `m`, the law's default range, clamped.
///
/// # Safety
/// `path` and `family` are NULL or NUL-terminated strings.
unsafe fn law_from_surface(path: *const c_char, family: *const c_char, m: &ke_friction::Materials) -> *mut kef_law {
    // SAFETY: by the caller's contract, and doubles.
    unsafe {
        kef_law_from_surface(
            path,
            family,
            m.e1,
            m.nu1,
            m.e2,
            m.nu2,
            m.hardness,
            m.delta_gamma,
            m.epsilon,
            0.0,
            0.0,
            KEF_LAW_CLAMP,
        )
    }
}

#[test]
fn a_law_from_physical_inputs_is_the_librarys_default_range_included() {
    let physical = ke_friction::Physical {
        e1: 70e9,
        nu1: 0.33,
        e2: 210e9,
        nu2: 0.3,
        hardness: 1e9,
        sigma: 100e-9,
        radius: 10e-6,
        density: 0.04 / (10e-6 * 100e-9),
        delta_gamma: 0.3,
        epsilon: 0.4e-9,
    };
    // SAFETY: a live law and local doubles.
    unsafe {
        let c = law_from_physical(&physical);
        assert!(!c.is_null(), "{}", last_error());
        let rust = FrictionLaw::from_physical(&physical, None, OutOfRange::Clamp).unwrap();
        let (mut lo, mut hi, mut h) = (0.0, 0.0, 0.0);
        assert_eq!(kef_law_range(c, &mut lo, &mut hi, &mut h), KEF_OK);
        assert_eq!((lo, hi, h), (1e4, 1e8, 1e9));
        let mut mu = 0.0;
        assert_eq!(kef_law_mu(c, 3e6, &mut mu), KEF_OK);
        assert_eq!(mu, rust.mu(3e6).unwrap());
        kef_law_free(c);
        assert!(law_from_physical(&ke_friction::Physical {
            hardness: -1.0,
            ..physical
        })
        .is_null());
        assert_says("hardness = -1");
    }
}

/// A failing lookup's message is formatted by kef_last_error: the
/// pointer from an earlier call holds it once kef_last_error is called,
/// and a later failure of another kind replaces it.
#[test]
fn a_lookups_message_is_formatted_when_asked_for() {
    let c = law(KEF_LAW_ERROR);
    // SAFETY: a live law, local doubles; kef_last_error's buffer lives as
    // long as the thread.
    unsafe {
        let early = kef_last_error();
        let mut mu = 0.0;
        assert_eq!(kef_law_mu(c, -2.0, &mut mu), KEF_ERR_NO_MU);
        let now = kef_last_error();
        assert_eq!(now, early, "one buffer per thread");
        let text = std::ffi::CStr::from_ptr(early).to_str().unwrap();
        assert!(text.starts_with("pressure = -2 Pa"), "{text}");
        // A table lookup's too, and then a constructor's (formatted at once).
        assert_failed(
            kef_table_mu(kef_table_default(), 1.0, 0.001, 0.5, &mut mu),
            KEF_ERR_DOMAIN,
            "f_star = 0.5",
        );
        assert_eq!(kef_law_mu(c, -3.0, &mut mu), KEF_ERR_NO_MU);
        assert!(kef_law_new(null(), -1.0, 0.001, H, 0.0, 0.0, KEF_LAW_CLAMP).is_null());
        assert_says("psi = -1");
        kef_law_free(c);
    }
}

#[test]
fn one_law_serves_many_threads_and_counts_their_clamps() {
    let c = law(KEF_LAW_CLAMP) as usize;
    let rust = FrictionLaw::new(Params::new(1.0, 0.001), H, Some((1e4, 1e8)), OutOfRange::Clamp).unwrap();
    std::thread::scope(|s| {
        for k in 0..4 {
            let rust = &rust;
            s.spawn(move || {
                for i in 0..1000 {
                    let p = 1e4 * 1.01f64.powi(i + 50 * k);
                    let (mut mu, mut d) = (0.0, 0.0);
                    // SAFETY: the law stays alive until the scope ends.
                    let code = unsafe { kef_law_mu_and_derivative(c as *const kef_law, p, &mut mu, &mut d) };
                    assert_eq!(code, KEF_OK);
                    assert_eq!((mu, d), rust.mu_and_derivative(p).unwrap());
                }
            });
        }
    });
    let clamped: u64 = (0..4)
        .map(|k| (0..1000).filter(|i| 1e4 * 1.01f64.powi(i + 50 * k) > 1e8).count() as u64)
        .sum();
    let mut count = 0;
    // SAFETY: every thread is done with it.
    unsafe {
        assert_eq!(kef_law_clamped(c as *const kef_law, 0, &mut count), KEF_OK);
        kef_law_free(c as *mut kef_law);
    }
    assert!(clamped > 0);
    assert_eq!(count, clamped);
}

#[test]
fn a_props_list_gives_one_shared_law_built_once() {
    let props = [1.5, 0.002, 1.1e9, 1e5, 1e8, 0.05, 0.32, 0.005];
    // SAFETY: arrays of the length given; the shared law is never freed
    // (kef_law_free ignores it).
    unsafe {
        let a = kef_law_from_props(8, props.as_ptr());
        assert!(!a.is_null(), "{}", last_error());
        let threads: Vec<usize> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..4)
                .map(|_| s.spawn(|| kef_law_from_props(8, props.as_ptr()) as usize))
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        });
        assert!(threads.iter().all(|&t| t == a as usize), "one law per props list");
        kef_law_free(a.cast_mut());
        let constants = ke_friction::Constants::default().beta(0.05).nu(0.32).eps_star(0.005);
        let rust = FrictionLaw::new(
            constants.at(1.5, 0.002).unwrap(),
            1.1e9,
            Some((1e5, 1e8)),
            OutOfRange::Clamp,
        )
        .unwrap();
        let mut mu = 0.0;
        assert_eq!(kef_law_mu(a, 1e9, &mut mu), KEF_OK, "clamped, not an error");
        assert_eq!(mu, rust.mu(1e8).unwrap());
        // Three values: the default range and constants.
        let short = kef_law_from_props(3, props.as_ptr());
        let (mut lo, mut hi, mut h) = (0.0, 0.0, 0.0);
        assert_eq!(kef_law_range(short, &mut lo, &mut hi, &mut h), KEF_OK);
        assert_eq!((lo, hi), (1e-5 * 1.1e9, 0.1 * 1.1e9));
        for n in [0, 2, 4, 9] {
            assert!(kef_law_from_props(n, props.as_ptr()).is_null());
            assert_says(&format!("n_props = {n}: must be 3"));
        }
        let bad = [1.0, 0.001, -5.0];
        assert!(kef_law_from_props(3, bad.as_ptr()).is_null());
        assert_says("hardness = -5");
        assert!(kef_law_from_props(3, null()).is_null());
        assert_eq!(last_error(), "props is NULL");
    }
}

/// A measured surface (an X3P file of the library's writer) to the law
/// through C: the law the library builds from the same file with
/// `kefric surface`'s defaults; a missing file and an unknown family are
/// refused, naming them.
#[test]
fn a_law_from_a_measured_surface_is_the_librarys() {
    use ke_friction::topography::{read_file, write_x3p, ReadOptions, StatsOptions, Surface, Topography};
    let n = 128;
    let heights: Vec<f64> = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            2e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin() + (x * 0.13 - y * 0.41).cos())
        })
        .collect();
    let dir = super::scratch("law-surface");
    let path = dir.join("rough.x3p");
    write_x3p(&Topography::map(heights, n, n, 1e-6, 1e-6).unwrap(), &path, 'D').unwrap();
    // The README's aluminium pin on a nickel-coated disk.
    let materials = ke_friction::Materials::from_array([70e9, 0.33, 200e9, 0.31, 1e9, 0.5, 0.4e-9]);
    let surface = Surface::new(
        read_file(&path, &ReadOptions::default()).unwrap(),
        StatsOptions::default(),
    )
    .unwrap();
    let rust = FrictionLaw::from_surface(&surface, &materials, None, None, OutOfRange::Clamp).unwrap();
    let c_path = super::c_path(&path);
    // SAFETY: NUL-terminated strings, a live law, local doubles.
    unsafe {
        let from = |family: *const c_char| law_from_surface(c_path.as_ptr(), family, &materials);
        let gaussian = FrictionLaw::from_surface(
            &surface,
            &materials,
            Some(ke_friction::Family::Gaussian),
            None,
            OutOfRange::Clamp,
        )
        .unwrap();
        for (family, rust) in [
            (null(), &rust),
            (c"".as_ptr(), &rust),
            (c"gaussian".as_ptr(), &gaussian),
        ] {
            let law = from(family);
            assert!(!law.is_null(), "{}", last_error());
            let (mut mu, mut d) = (0.0, 0.0);
            assert_eq!(kef_law_mu_and_derivative(law, 1e6, &mut mu, &mut d), KEF_OK);
            assert_eq!((mu, d), rust.mu_and_derivative(1e6).unwrap());
            kef_law_free(law);
        }
        assert!(from(c"lognormal".as_ptr()).is_null());
        assert!(last_error().contains("lognormal"), "{}", last_error());
        let missing = super::c_path(&dir.join("missing.x3p"));
        assert!(law_from_surface(missing.as_ptr(), null(), &materials).is_null());
        assert!(last_error().contains("missing.x3p"), "{}", last_error());
    }
}
