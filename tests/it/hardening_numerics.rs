//! Hardening: properties of direct integration over the whole valid
//! parameter space (fixed seeds): finite outputs everywhere, μ defined
//! exactly where F* > 0, and `at_f_star` converging to the requested F*.

use ke_friction::{Contact, EvalError, Fit, Model, ModelKind, Params};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The lowest β taken here: 0.1 % above the model's floor β_min (σ_s
/// real, [`ke_friction::BETA_MIN`]), where σ_s/σ is smallest.
const BETA_LOW: f64 = ke_friction::BETA_MIN * 1.001;

/// Log-uniform in [lo, hi].
fn log_uniform(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    (rng.gen_range(lo.ln()..=hi.ln())).exp().clamp(lo, hi)
}

/// Random parameters over the ranges: ψ 0.05–50 (log), θ 0–1 (a
/// tenth exactly 0, the rest half uniform, half log-uniform down to 1e-6),
/// ε* 1e-6–1 (log), β `BETA_LOW`–1 (log), ν in [0, 0.5), both fits,
/// both models.
fn random_params(rng: &mut ChaCha8Rng) -> Params {
    let theta = match rng.gen_range(0..10) {
        0 => 0.0,
        1..=5 => log_uniform(rng, 1e-6, 1.0),
        _ => rng.gen_range(0.0..=1.0),
    };
    let nu = if rng.gen_bool(0.1) {
        0.0
    } else {
        rng.gen_range(0.0..0.5)
    };
    Params::new(log_uniform(rng, 0.05, 50.0), theta)
        .beta(log_uniform(rng, BETA_LOW, 1.0))
        .nu(nu)
        .eps_star(log_uniform(rng, 1e-6, 1.0))
        .fit(if rng.gen_bool(0.5) {
            Fit::Consistent
        } else {
            Fit::AsPrinted
        })
        .kind(if rng.gen_bool(0.5) {
            ModelKind::KogutEtsion
        } else {
            ModelKind::CebType
        })
}

/// Every corner of the ranges, with all fits and models.
fn corner_params() -> Vec<Params> {
    let mut v = vec![];
    for psi in [0.05, 50.0] {
        for theta in [0.0, 1e-6, 1.0] {
            for beta in [BETA_LOW, 1.0] {
                for nu in [0.0, 0.4999] {
                    for eps in [1e-6, 1.0] {
                        for fit in [Fit::Consistent, Fit::AsPrinted] {
                            for kind in [ModelKind::KogutEtsion, ModelKind::CebType] {
                                v.push(
                                    Params::new(psi, theta)
                                        .beta(beta)
                                        .nu(nu)
                                        .eps_star(eps)
                                        .fit(fit)
                                        .kind(kind),
                                );
                            }
                        }
                    }
                }
            }
        }
    }
    v
}

/// What is wrong with a contact from `at_h_star` (None if nothing).
fn check_contact(model: &Model, c: &Contact) -> Option<String> {
    let fields = [c.h_star, c.d_star, c.p_star, c.fs_star, c.q_star, c.f_star];
    if fields.iter().any(|v| !v.is_finite()) {
        return Some(format!("non-finite field: {c:?}"));
    }
    if c.p_star < 0.0 || c.fs_star < 0.0 {
        return Some(format!("negative P* or Fs*: {c:?}"));
    }
    if (c.f_star - (c.p_star - c.fs_star)).abs() > 4.0 * f64::EPSILON * (c.p_star + c.fs_star) {
        return Some(format!("F* != P* - Fs*: {c:?}"));
    }
    if (c.d_star - (c.h_star - model.y_s())).abs() > 4.0 * f64::EPSILON * c.h_star.abs().max(1.0) {
        return Some(format!("d* != h* - y_s*: {c:?}"));
    }
    match c.mu {
        Some(mu) if c.f_star <= 0.0 => Some(format!("mu = {mu} where F* <= 0: {c:?}")),
        Some(mu) if !mu.is_finite() => Some(format!("non-finite mu: {c:?}")),
        None if c.f_star > 0.0 => Some(format!("no mu where F* > 0: {c:?}")),
        _ => None,
    }
}

/// The accuracy to which `at_f_star(f)` can reproduce f: F* = P* − Fs* is a
/// difference, computed to about 1e-13 of P* + Fs* (the integrals'
/// accuracy, which also bounds their roughness in h*); where the two nearly
/// cancel (strong adhesion, small F*) no root finder can do better than that.
fn f_tolerance(f: f64, c: &Contact) -> f64 {
    1e-10 * f + 1e-12 * (c.p_star + c.fs_star)
}

/// Runs `f` on a thread and fails if it takes longer than `secs` (a
/// performance regression then fails instead of hanging the suite).
fn within<T: Send + 'static>(secs: u64, what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)));
    });
    match rx.recv_timeout(std::time::Duration::from_secs(secs)) {
        Ok(Ok(v)) => v,
        Ok(Err(panic)) => std::panic::resume_unwind(panic),
        Err(_) => panic!("{what} took more than {secs} s"),
    }
}

#[test]
fn at_h_star_is_finite_and_mu_is_defined_exactly_where_f_star_is_positive() {
    let mut rng = ChaCha8Rng::seed_from_u64(2004);
    let mut failures = vec![];
    let (mut n, mut with_mu) = (0, 0);
    let mut sets: Vec<Params> = (0..12000).map(|_| random_params(&mut rng)).collect();
    sets.extend(corner_params());
    for p in sets {
        let model = Model::new(p.clone()).unwrap_or_else(|e| panic!("{p:?}: {e}"));
        let mut hs: Vec<f64> = (0..8).map(|_| rng.gen_range(-5.0..=10.0)).collect();
        hs.extend([-5.0, 0.0, 10.0]);
        for h in hs {
            match model.at_h_star(h) {
                Ok(c) => {
                    n += 1;
                    with_mu += c.mu.is_some() as usize;
                    if let Some(why) = check_contact(&model, &c) {
                        failures.push(format!("{p:?}, h* = {h}: {why}"));
                    }
                }
                Err(e) => failures.push(format!("{p:?}, h* = {h}: {e}")),
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {n} evaluations failed:\n{}",
        failures.len(),
        failures[..failures.len().min(20)].join("\n")
    );
    // Both cases occur (the property is not vacuous).
    assert!(with_mu > n / 10 && with_mu < n * 9 / 10, "{with_mu} of {n} have mu");
}

#[test]
fn at_f_star_converges_to_the_requested_force() {
    let mut rng = ChaCha8Rng::seed_from_u64(1609488);
    let mut failures = vec![];
    let (mut n, mut strict, mut worst) = (0, 0, (0.0f64, String::new()));
    let mut sets: Vec<Params> = (0..6000).map(|_| random_params(&mut rng)).collect();
    sets.extend(corner_params());
    for p in sets {
        let model = Model::new(p.clone()).unwrap();
        let mut fs: Vec<f64> = (0..4).map(|_| log_uniform(&mut rng, 1e-8, 1.0)).collect();
        fs.extend([1e-8, 1.0]);
        for f in fs {
            n += 1;
            match model.at_f_star(f) {
                Ok(c) => {
                    let err = (c.f_star - f).abs();
                    // Mild cancellation (P* + Fs* ≤ 10 F*): the 1e-10.
                    let mild = c.p_star + c.fs_star <= 10.0 * f;
                    strict += (err <= 1e-10 * f) as usize;
                    let tol = if mild { 1e-10 * f } else { f_tolerance(f, &c) };
                    if err / tol > worst.0 {
                        worst = (err / tol, format!("{p:?}, F* = {f}: {c:?}"));
                    }
                    if err > tol {
                        failures.push(format!("{p:?}, F* = {f}: F* = {:e} at the root: {c:?}", c.f_star));
                    } else if c.mu.is_none() || !c.mu.unwrap().is_finite() {
                        failures.push(format!("{p:?}, F* = {f}: no finite mu: {c:?}"));
                    } else if let Some(why) = check_contact(&model, &c) {
                        failures.push(format!("{p:?}, F* = {f}: {why}"));
                    } else if model.force(c.h_star).1.is_nan() || model.force(c.h_star).1 >= 0.0 {
                        failures.push(format!("{p:?}, F* = {f}: not on the decreasing branch: {c:?}"));
                    }
                }
                Err(e) => failures.push(format!("{p:?}, F* = {f}: {e:?}")),
            }
        }
    }
    eprintln!(
        "at_f_star: {n} solves, {strict} within 1e-10 relative; worst error / tolerance = {:.3} at {}",
        worst.0, worst.1
    );
    assert!(
        failures.is_empty(),
        "{} of {n} solves failed:\n{}",
        failures.len(),
        failures[..failures.len().min(20)].join("\n")
    );
    // Cancellation limits only a minority of the solves.
    assert!(strict * 2 > n, "only {strict} of {n} within 1e-10 relative");
}

/// The far-field adhesion: for d* ≫ s, P* = 0 and
/// Fs* = 2πβθ·(4/3)·(ε*/D)²·(1 + 3s²/D² + 15s⁴/D⁴ + …), D = d* + ε*.
/// The integration once grew like h*² (minutes at 1e5, hours at 1e6): a
/// watchdog turns that into a failure instead of a hang.
#[test]
fn far_separations_are_fast_and_match_the_asymptote() {
    let problems = within(10, "18 evaluations at far separations", || {
        let mut problems = vec![];
        for p in [
            Params::new(1.0, 0.001),
            Params::new(0.05, 1.0).beta(BETA_LOW).eps_star(1e-6),
            Params::new(50.0, 1e-6).beta(1.0).eps_star(1.0).kind(ModelKind::CebType),
        ] {
            let model = Model::new(p.clone()).unwrap();
            let s2 = 1.0 - 3.717e-4 / (p.constants.beta * p.constants.beta);
            for h in [100.0, 1e3, 1e4, 1e5, 1e6, -1e6 + 1.0] {
                let c = model.at_h_star(h).unwrap();
                if let Some(why) = check_contact(&model, &c) {
                    problems.push(format!("{p:?}, h* = {h}: {why}"));
                }
                if h < 0.0 {
                    if c.f_star.is_nan() || c.f_star <= 0.0 {
                        problems.push(format!("{p:?}, h* = {h}: F* <= 0: {c:?}"));
                    }
                    continue;
                }
                let dd = c.d_star + p.constants.eps_star;
                let (a, b) = (s2 / (dd * dd), 15.0 * s2 * s2 / dd.powi(4));
                let want = 2.0
                    * std::f64::consts::PI
                    * p.constants.beta
                    * p.theta
                    * (4.0 / 3.0)
                    * (p.constants.eps_star / dd).powi(2)
                    * (1.0 + 3.0 * a + b);
                let rel = (c.fs_star / want - 1.0).abs();
                if c.p_star != 0.0 || rel > 1e-9 {
                    problems.push(format!(
                        "{p:?}, h* = {h}: P* = {:e}, Fs* = {:e}, asymptote {want:e} ({rel:e})",
                        c.p_star, c.fs_star
                    ));
                }
            }
        }
        problems
    });
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Where F* ≤ 0 down to deep penetrations, the root search must walk far
/// enough (it once stepped by 1 and gave up at h* = −199).
#[test]
fn strong_adhesion_roots_lie_deep_and_are_found() {
    let p = Params::new(0.05, 1.0)
        .beta(BETA_LOW)
        .nu(0.49)
        .eps_star(1e-6)
        .kind(ModelKind::CebType);
    let model = Model::new(p).unwrap();
    for f in [1e-8, 1e-4, 0.01, 1.0] {
        let c = model.at_f_star(f).unwrap_or_else(|e| panic!("F* = {f}: {e:?}"));
        assert!(c.h_star < -200.0, "{c:?}");
        assert!((c.f_star - f).abs() <= f_tolerance(f, &c), "{c:?}");
    }
}

/// The bounds of the accepted parameters (ψ 1e-3–1e3, θ ≤ 1e3, β ≤ 100,
/// ε* 1e-9–100): outputs stay finite over the whole h* range, and F* is
/// either found or out of reach (never a failed search).
#[test]
fn the_limits_of_the_accepted_parameters_stay_finite() {
    within(20, "the limits of the parameters", the_limits);
    // Just outside: rejected, naming the parameter.
    for (p, name) in [
        (Params::new(0.99e-3, 0.0), "psi"),
        (Params::new(1.01e3, 0.0), "psi"),
        (Params::new(1.0, 1.01e3), "theta"),
        (Params::new(1.0, 0.0).beta(100.1), "beta"),
        (Params::new(1.0, 0.0).eps_star(0.99e-9), "eps_star"),
        (Params::new(1.0, 0.0).eps_star(100.1), "eps_star"),
        (Params::new(1e-320, 0.0), "psi"),
        (Params::new(1e308, 0.0), "psi"),
        (Params::new(1.0, 1e308), "theta"),
        (Params::new(1.0, 0.0).beta(1e308), "beta"),
        (Params::new(1.0, 0.0).eps_star(1e308), "eps_star"),
    ] {
        assert_eq!(Model::new(p.clone()).unwrap_err().name, name, "{p:?}");
    }
}

fn the_limits() {
    for psi in [1e-3, 1e3] {
        for theta in [0.0, 1e3] {
            for beta in [BETA_LOW, 100.0] {
                for eps in [1e-9, 100.0] {
                    for kind in [ModelKind::KogutEtsion, ModelKind::CebType] {
                        let p = Params::new(psi, theta).beta(beta).nu(0.3).eps_star(eps).kind(kind);
                        let model = Model::new(p.clone()).unwrap_or_else(|e| panic!("{p:?}: {e}"));
                        for h in [-1e6, -1e3, -5.0, 0.0, 3.0, 10.0, 1e3, 1e6] {
                            let c = model.at_h_star(h).unwrap();
                            assert!(check_contact(&model, &c).is_none(), "{p:?}, h* = {h}: {c:?}");
                        }
                        for f in [1e-8, 1.0] {
                            match model.at_f_star(f) {
                                Ok(c) => assert!((c.f_star - f).abs() <= f_tolerance(f, &c), "{p:?}: {c:?}"),
                                Err(EvalError::FStarTooLarge { .. }) => {}
                                Err(e) => panic!("{p:?}, F* = {f}: {e:?}"),
                            }
                        }
                    }
                }
            }
        }
    }
}
