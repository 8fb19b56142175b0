//! Properties the model must have for any parameters (MODEL.md §4–§6),
//! checked over random parameter sets drawn with a fixed seed, plus the
//! edge cases of the public API (undefined μ, invalid inputs).
//!
//! Random sets: ψ log-uniform in [0.5, 8] (the paper's range), θ = 0 with
//! probability 1/4, otherwise log-uniform in [1e-4, 1e-2], h* uniform in
//! [0, 3].
use crate::common::rel;
use ke_friction::{EvalError, Fit, Model, ModelKind, Params};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const CASES: usize = 200;
const KINDS: [ModelKind; 2] = [ModelKind::KogutEtsion, ModelKind::CebType];

fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

fn log_uniform(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    (rng.gen_range(lo.ln()..hi.ln())).exp()
}

/// A random (ψ, θ).
fn random_params(rng: &mut ChaCha8Rng) -> (f64, f64) {
    let psi = log_uniform(rng, 0.5, 8.0);
    let theta = if rng.gen_bool(0.25) {
        0.0
    } else {
        log_uniform(rng, 1e-4, 1e-2)
    };
    (psi, theta)
}

fn model(psi: f64, theta: f64, kind: ModelKind) -> Model {
    Model::new(Params::new(psi, theta).kind(kind)).unwrap()
}

/// MODEL.md §5: F*(h*) decreases with h* as long as it is positive; P*
/// (a positive integrand over a shrinking range) always decreases.
/// Checked on h* = 0, 0.01, …, 3 for 200 random (ψ, θ) and both kinds:
/// strictly, P*(h + 0.01) < P*(h), and F*(h + 0.01) < F*(h) wherever F*(h) > 0.
#[test]
fn p_star_and_f_star_decrease_with_h_star_while_f_star_is_positive() {
    let mut rng = rng(1);
    let mut checked_f = 0;
    for _ in 0..CASES {
        let (psi, theta) = random_params(&mut rng);
        for kind in KINDS {
            let model = model(psi, theta, kind);
            let mut prev = model.at_h_star(0.0).unwrap();
            for i in 1..=300 {
                let c = model.at_h_star(f64::from(i) * 0.01).unwrap();
                let tag = format!("ψ={psi} θ={theta} {kind:?} h*={}", c.h_star);
                assert!(c.p_star < prev.p_star, "{tag}: P* {} ≥ {}", c.p_star, prev.p_star);
                if prev.f_star > 0.0 {
                    assert!(c.f_star < prev.f_star, "{tag}: F* {} ≥ {}", c.f_star, prev.f_star);
                    checked_f += 1;
                }
                prev = c;
            }
        }
    }
    assert!(checked_f > CASES * 2 * 250);
}

/// MODEL.md §4, §6 item 2 and §8: under Fit::Consistent every asperity's
/// tangential capacity is ≥ 0, so Q* ≥ 0, and μ = Q*/F* > 0 wherever
/// F* > 0. 200 random (ψ, θ, h*), both kinds.
#[test]
fn friction_is_nonnegative_and_mu_positive_under_the_consistent_fit() {
    let mut rng = rng(2);
    for _ in 0..CASES {
        let (psi, theta) = random_params(&mut rng);
        let h = rng.gen_range(0.0..3.0);
        for kind in KINDS {
            let m = Model::new(Params::new(psi, theta).kind(kind).fit(Fit::Consistent)).unwrap();
            let c = m.at_h_star(h).unwrap();
            assert!(c.q_star >= 0.0, "{c:?} ψ={psi} θ={theta} {kind:?}");
            if let Some(mu) = c.mu {
                assert!(mu > 0.0, "{c:?} ψ={psi} θ={theta} {kind:?}");
            }
        }
    }
}

/// MODEL.md §4: Fs* = 2πβθ·(…), so θ = 0 gives exactly no adhesion and
/// F* = P*. 200 random (ψ, h*), both kinds.
#[test]
fn zero_theta_gives_exactly_zero_adhesion() {
    let mut rng = rng(3);
    for _ in 0..CASES {
        let psi = log_uniform(&mut rng, 0.5, 8.0);
        let h = rng.gen_range(0.0..3.0);
        for kind in KINDS {
            let c = model(psi, 0.0, kind).at_h_star(h).unwrap();
            assert_eq!(c.fs_star, 0.0, "ψ={psi} h*={h} {kind:?}");
            assert_eq!(c.f_star, c.p_star, "ψ={psi} h*={h} {kind:?}");
        }
    }
}

/// MODEL.md §4: θ enters only through Fs*, linearly. Fs*(2θ) = 2·Fs*(θ)
/// to 1e-14 relative; P* and Q* at θ and 2θ equal those at θ = 0 to 1e-15
/// relative (measured: bit-identical). 200 random (ψ, θ > 0, h*), both kinds.
#[test]
fn adhesion_is_linear_in_theta_and_p_star_q_star_do_not_depend_on_it() {
    let mut rng = rng(4);
    for _ in 0..CASES {
        let psi = log_uniform(&mut rng, 0.5, 8.0);
        let theta = log_uniform(&mut rng, 1e-4, 1e-2);
        let h = rng.gen_range(0.0..3.0);
        for kind in KINDS {
            let c0 = model(psi, 0.0, kind).at_h_star(h).unwrap();
            let c1 = model(psi, theta, kind).at_h_star(h).unwrap();
            let c2 = model(psi, 2.0 * theta, kind).at_h_star(h).unwrap();
            let tag = format!("ψ={psi} θ={theta} h*={h} {kind:?}");
            assert!(c1.fs_star > 0.0, "{tag}");
            assert!(rel(c2.fs_star, 2.0 * c1.fs_star) <= 1e-14, "{tag}: {c1:?} {c2:?}");
            for c in [c1, c2] {
                assert!(rel(c.p_star, c0.p_star) <= 1e-15, "{tag}: P* {c:?} {c0:?}");
                assert!(rel(c.q_star, c0.q_star) <= 1e-15, "{tag}: Q* {c:?} {c0:?}");
            }
        }
    }
}

/// MODEL.md §5: for F* > 0 there is exactly one h* on the decreasing
/// branch, so at_f_star(at_h_star(h).f_star) returns h, to 1e-10 absolute.
/// 200 random (ψ, θ, h*), both kinds (cases with F* ≤ 0 would be skipped;
/// with this seed there are none), plus the approach to the zero of F* at
/// ψ = 0.5, θ = 0.01 (h* → 2.32199…, F* down to ~3e-9). Measured error
/// ≤ 1.8e-15.
#[test]
fn at_f_star_inverts_at_h_star() {
    let check = |model: &Model, h: f64, tag: &str| {
        let c = model.at_h_star(h).unwrap();
        if c.f_star <= 0.0 {
            return false;
        }
        let back = model.at_f_star(c.f_star).unwrap();
        let tag = format!("{tag} h*={h} F*={:e}", c.f_star);
        assert!((back.h_star - h).abs() <= 1e-10, "{tag}: got h* = {}", back.h_star);
        assert!(rel(back.f_star, c.f_star) <= 1e-9, "{tag}: {back:?}");
        true
    };
    let mut rng = rng(5);
    let mut done = 0;
    for _ in 0..CASES {
        let (psi, theta) = random_params(&mut rng);
        let h = rng.gen_range(0.0..3.0);
        for kind in KINDS {
            let tag = format!("ψ={psi} θ={theta} {kind:?}");
            if check(&model(psi, theta, kind), h, &tag) {
                done += 1;
            }
        }
    }
    assert!(done > CASES, "only {done} cases with F* > 0");
    for kind in KINDS {
        let model = model(0.5, 0.01, kind);
        for h in [2.0, 2.2, 2.3, 2.32, 2.3219, 2.32199] {
            let tag = format!("ψ=0.5 θ=0.01 {kind:?}");
            assert!(check(&model, h, &tag), "{tag}: F* ≤ 0 at h* = {h}");
        }
    }
}

/// MODEL.md §6, last paragraph: the literal printed Eq. 18 (Fit::AsPrinted)
/// gives a negative Q* for ψ ≳ 2. At ψ = 2, θ = 0, h* = 0.5 this crate gives
/// Q* = −2.2238780074e-4 (μ = −2.7895852307e-3), and the independent
/// 30-digit mpmath oracle (`tools/reference.py point ke as-printed 2 0 0.5`)
/// gives Q* = −2.22387800737759e-4: checked to 1e-9 relative. The consistent
/// fit gives Q* = +2.8009985629e-3 (MODEL.md §7); P* is the same for both.
#[test]
fn as_printed_fit_gives_negative_friction_at_psi_2() {
    let printed = Model::new(Params::new(2.0, 0.0).fit(Fit::AsPrinted)).unwrap();
    let consistent = Model::new(Params::new(2.0, 0.0).fit(Fit::Consistent)).unwrap();
    let p = printed.at_h_star(0.5).unwrap();
    let c = consistent.at_h_star(0.5).unwrap();
    assert!(p.q_star < 0.0, "{p:?}");
    assert!(p.mu.unwrap() < 0.0, "{p:?}");
    assert!(rel(p.q_star, -2.22387800737759e-4) <= 1e-9, "{p:?}");
    assert!(rel(p.mu.unwrap(), -2.78958523068443e-3) <= 1e-9, "{p:?}");
    assert!(rel(c.q_star, 2.8009985629e-3) <= 1e-9, "{c:?}");
    assert_eq!(p.p_star, c.p_star);
    assert_eq!(p.f_star, c.f_star);
}

/// Contact::mu is None exactly when F* ≤ 0 (MODEL.md §4: μ is defined only
/// where F* > 0). The known case: ψ = 0.5, θ = 0.01, h* = 4 has
/// F* = −1.91e-6 (adhesion outweighs the load; F* crosses zero at
/// h* ≈ 2.322 there). Then 200 random (ψ log-uniform in [0.5, 1.5], θ
/// log-uniform in [1e-3, 1e-2], h* uniform in [0, 6], so that both cases
/// occur), both kinds, counting both outcomes (measured: 342 defined, 58
/// undefined).
#[test]
fn mu_is_none_exactly_when_f_star_is_not_positive() {
    let c = model(0.5, 0.01, ModelKind::KogutEtsion).at_h_star(4.0).unwrap();
    assert!(c.f_star < 0.0 && c.f_star > -1e-5, "{c:?}");
    assert_eq!(c.mu, None);
    assert!(c.q_star > 0.0, "Q* is still defined: {c:?}");
    let c = model(0.5, 0.01, ModelKind::KogutEtsion).at_h_star(2.0).unwrap();
    assert!(c.f_star > 0.0 && c.mu.unwrap() > 0.0, "{c:?}");

    // F* ≤ 0 needs small ψ and large θ: the sweep is biased there.
    let mut rng = rng(7);
    let (mut defined, mut undefined) = (0, 0);
    for _ in 0..CASES {
        let psi = log_uniform(&mut rng, 0.5, 1.5);
        let theta = log_uniform(&mut rng, 1e-3, 1e-2);
        let h = rng.gen_range(0.0..6.0);
        for kind in KINDS {
            let c = model(psi, theta, kind).at_h_star(h).unwrap();
            assert_eq!(c.mu.is_none(), c.f_star <= 0.0, "{c:?}");
            if let Some(mu) = c.mu {
                assert_eq!(mu, c.q_star / c.f_star, "{c:?}");
                defined += 1;
            } else {
                undefined += 1;
            }
        }
    }
    assert!(
        defined > 100 && undefined > 20,
        "defined {defined}, undefined {undefined}"
    );
}

/// Invalid inputs are errors, never NaN results: h* NaN/±∞; F* zero (both
/// signs), negative, NaN, +∞; ψ NaN (ParamError names "psi").
#[test]
fn invalid_inputs_are_rejected() {
    let err = Model::new(Params::new(f64::NAN, 0.001)).unwrap_err();
    assert_eq!(err.name, "psi");
    for kind in KINDS {
        let model = model(1.0, 0.001, kind);
        for h in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert!(
                matches!(model.at_h_star(h), Err(EvalError::HStar(_))),
                "h* = {h}: {:?}",
                model.at_h_star(h)
            );
        }
        for f in [0.0, -0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(
                matches!(model.at_f_star(f), Err(EvalError::FStar(_))),
                "F* = {f}: {:?}",
                model.at_f_star(f)
            );
        }
    }
}

/// MODEL.md §5: μ is a smooth (C^∞) function of the load although the
/// single-asperity laws have jumps. On 401 points equally spaced in ln F*
/// over [1e-5, 0.1] (step Δ = 0.023), the second differences of ln μ stay
/// below 5·Δ² (curvature ≤ 5; measured ≤ 1.45) and the third differences
/// below 1e-4 (measured ≤ 2.5e-5): a jump of relative size 5e-5 in μ, or a
/// kink of 0.004 in the slope d ln μ / d ln F*, would fail the test.
/// Fixed cases across ψ and θ, both kinds, plus 12 random (ψ, θ).
#[test]
fn mu_is_smooth_in_f_star() {
    let mut cases = vec![
        (0.5, 0.0, ModelKind::KogutEtsion),
        (0.5, 0.01, ModelKind::KogutEtsion),
        (1.0, 0.003, ModelKind::KogutEtsion),
        (2.0, 0.003, ModelKind::KogutEtsion),
        (8.0, 0.0001, ModelKind::KogutEtsion),
        (8.0, 0.01, ModelKind::KogutEtsion),
        (1.0, 0.003, ModelKind::CebType),
        (4.0, 0.0, ModelKind::CebType),
    ];
    let mut rng = rng(9);
    for i in 0..12 {
        let (psi, theta) = random_params(&mut rng);
        cases.push((psi, theta, KINDS[i % 2]));
    }
    let n = 400;
    let (lo, hi) = (1e-5_f64.ln(), 0.1_f64.ln());
    let step = (hi - lo) / f64::from(n);
    for (psi, theta, kind) in cases {
        let model = model(psi, theta, kind);
        let ln_mu: Vec<f64> = (0..=n)
            .map(|i| {
                let f = (lo + step * f64::from(i)).exp();
                model.at_f_star(f).unwrap().mu.unwrap().ln()
            })
            .collect();
        let d2: Vec<f64> = ln_mu.windows(3).map(|w| w[2] - 2.0 * w[1] + w[0]).collect();
        let d3: Vec<f64> = d2.windows(2).map(|w| w[1] - w[0]).collect();
        let tag = format!("ψ={psi} θ={theta} {kind:?}");
        let max2 = d2.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
        let max3 = d3.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
        assert!(max2 <= 5.0 * step * step, "{tag}: max |Δ² ln μ| = {max2:e}");
        assert!(max3 <= 1e-4, "{tag}: max |Δ³ ln μ| = {max3:e}");
    }
}
