//! What the paper reports (Kogut & Etsion 2004), checked against this model:
//! the table of MODEL.md §7 ("What the paper reports, to check against") and
//! the CEB-type comparison of MODEL.md §8 (last paragraph).
//!
//! Each test names the statement, its source, the value MODEL.md gives for
//! this model and the tolerance. Numbers measured when these tests were
//! written are quoted in the comments ("measured").
//!
//! ## How the power-law exponents are fitted
//!
//! The paper's exponents m (Q* ≈ C·F*^m) and n (μ ∝ F*^−n) are least-squares
//! slopes in log–log coordinates. The slope depends on how the points are
//! sampled, so it is defined once, in [`loglog_slope_over_h`]:
//!
//! * 301 points equally spaced in h* over 0 ≤ h* ≤ 3 (the paper's range of
//!   separations, MODEL.md §1), i.e. h* = 0, 0.01, …, 3;
//! * points with F* > 0.1 dropped (the paper's range of loads, MODEL.md §1;
//!   this only matters at ψ = 2, where F*(h* = 0) = 0.13);
//! * ordinary least squares of ln y on ln F*, every point weighted equally.
//!
//! This definition reproduces every number MODEL.md §7 quotes: m = 0.841
//! (ψ = 0.5), 0.856 (ψ = 0.5, ε* = 0.01), 0.619 (ψ = 2), n = 0.1122
//! (ψ = 0.67) and 0.1276 (ψ = 1.01). Alternatives that do *not* reproduce
//! the n values of MODEL.md §6 item 1: points equally spaced in ln F* over the
//! same h* range give n = 0.106 / 0.118; over the F* range of the paper's
//! figures, 1e-5 ≤ F* ≤ 0.1, n = 0.096 / 0.094; over 1e-4 ≤ F* ≤ 0.1,
//! n = 0.116 / 0.118. At ψ = 2 keeping F* > 0.1 (h* near 0) gives m = 0.573
//! instead of 0.62.
mod common;
use common::rel;
use ke_friction::{Contact, Kind, Model, Params};

fn model(psi: f64, theta: f64) -> Model {
    Model::new(Params::new(psi, theta)).unwrap()
}

/// The contact at each of the 301 separations h* = 0, 0.01, …, 3.
fn sweep_h(model: &Model) -> Vec<Contact> {
    (0..=300)
        .map(|i| model.at_h_star(3.0 * f64::from(i) / 300.0).unwrap())
        .collect()
}

/// Least-squares slope of `ys` on `xs`.
fn slope(xs: &[f64], ys: &[f64]) -> f64 {
    let n = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxy: f64 = xs.iter().zip(ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// The slope of ln y against ln F* (module docs: equally spaced h* in
/// [0, 3], F* ≤ 0.1, ordinary least squares).
fn loglog_slope_over_h(model: &Model, y: impl Fn(&Contact) -> f64) -> f64 {
    let (mut ln_f, mut ln_y) = (Vec::new(), Vec::new());
    for c in sweep_h(model) {
        if c.f_star <= 0.1 {
            assert!(c.f_star > 0.0, "F* ≤ 0 at h* = {}", c.h_star);
            ln_f.push(c.f_star.ln());
            ln_y.push(y(&c).ln());
        }
    }
    assert!(
        ln_f.len() > 250,
        "too few points with F* ≤ 0.1: {}",
        ln_f.len()
    );
    slope(&ln_f, &ln_y)
}

/// m in Q* ≈ C·F*^m.
fn power_m(model: &Model) -> f64 {
    loglog_slope_over_h(model, |c| c.q_star)
}

/// n in μ ∝ F*^−n.
fn exponent_n(model: &Model) -> f64 {
    -loglog_slope_over_h(model, |c| c.mu.unwrap())
}

/// Paper (Fig. 4): Q* ≈ C·F*^m with m = 0.86 at ψ = 0.5, θ = 0.003.
/// MODEL.md §7: this model gives 0.84 with the default ε* = 0.004.
/// Tolerance ±0.01. Measured 0.8410.
#[test]
fn power_m_is_0_84_at_psi_0_5_theta_0_003() {
    let m = power_m(&model(0.5, 0.003));
    assert!((m - 0.84).abs() <= 0.01, "m = {m}");
}

/// MODEL.md §7: with ε* = 0.01 the model gives the paper's m = 0.86
/// (ψ = 0.5, θ = 0.003). Tolerance ±0.01. Measured 0.8564.
#[test]
fn power_m_is_0_86_at_psi_0_5_theta_0_003_with_eps_star_0_01() {
    let model = Model::new(Params::new(0.5, 0.003).eps_star(0.01)).unwrap();
    let m = power_m(&model);
    assert!((m - 0.86).abs() <= 0.01, "m = {m}");
}

/// Paper: n between 0.09 and 0.13 (θ = 0.001); experiment 0.102 at
/// ψ = 0.67 and 0.130 at ψ = 1.01. MODEL.md §6 item 1 and §7: this model
/// gives 0.112 at ψ = 0.67. Tolerance ±0.003. Measured 0.1122.
#[test]
fn exponent_n_is_0_112_at_psi_0_67_theta_0_001() {
    let n = exponent_n(&model(0.67, 0.001));
    assert!((n - 0.112).abs() <= 0.003, "n = {n}");
}

/// As above, at ψ = 1.01: MODEL.md gives 0.127. Tolerance ±0.003.
/// Measured 0.1276.
#[test]
fn exponent_n_is_0_127_at_psi_1_01_theta_0_001() {
    let n = exponent_n(&model(1.01, 0.001));
    assert!((n - 0.127).abs() <= 0.003, "n = {n}");
}

/// Largest Fs*/P* over h* = 0, 0.01, …, 3.
fn max_adhesion_ratio(model: &Model) -> f64 {
    sweep_h(model)
        .iter()
        .map(|c| c.fs_star / c.p_star)
        .fold(0.0, f64::max)
}

/// Paper: Fs*/P* < 0.11 over the whole range for ψ ≥ 2 (θ = 0.003).
/// MODEL.md §6 item 3 and §7: the maximum is 0.104, at ψ = 2 (at h* = 3).
/// Tolerance ±0.002 on the maximum. Measured 0.10381 at ψ = 2, falling with
/// ψ to 0.0309 at ψ = 8; and, so that ψ ≥ 2 is the boundary that matters,
/// 0.135 at ψ = 1.5 and 0.200 at ψ = 1.
#[test]
fn adhesion_ratio_stays_below_0_11_for_psi_from_2_and_peaks_at_0_104() {
    let mut worst = (0.0, 0.0);
    for psi in [2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0] {
        let r = max_adhesion_ratio(&model(psi, 0.003));
        assert!(r < 0.11, "ψ = {psi}: max Fs*/P* = {r}");
        if r > worst.1 {
            worst = (psi, r);
        }
    }
    assert_eq!(worst.0, 2.0, "largest Fs*/P* not at ψ = 2: {worst:?}");
    assert!((worst.1 - 0.104).abs() <= 0.002, "max Fs*/P* = {}", worst.1);
    // Below ψ = 2 the bound does not hold (the paper states it for ψ ≥ 2).
    assert!(max_adhesion_ratio(&model(1.5, 0.003)) > 0.11);
    assert!(max_adhesion_ratio(&model(1.0, 0.003)) > 0.11);
}

/// Paper: at ψ = 1 (θ = 0.003), Fs*/P* < 0.1 for F* > 0.01. MODEL.md §7:
/// the ratio crosses 0.1 at F* ≈ 0.009. Found by bisection in ln F*;
/// tolerance ±0.001. Measured 0.009092.
#[test]
fn adhesion_ratio_crosses_0_1_at_f_star_0_009_for_psi_1() {
    let model = model(1.0, 0.003);
    let excess = |f: f64| {
        let c = model.at_f_star(f).unwrap();
        c.fs_star / c.p_star - 0.1
    };
    let (mut lo, mut hi) = (1e-4_f64, 0.05_f64);
    assert!(excess(lo) > 0.0 && excess(hi) < 0.0, "no sign change");
    for _ in 0..60 {
        let mid = (lo * hi).sqrt();
        if excess(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    assert!(hi / lo - 1.0 < 1e-9);
    assert!((lo - 0.009).abs() <= 0.001, "crossing at F* = {lo}");
    // The paper's statement itself, at a few loads above 0.01.
    for f in [0.0101, 0.02, 0.05, 0.1] {
        assert!(excess(f) < 0.0, "Fs*/P* ≥ 0.1 at F* = {f}");
    }
}

/// Paper: at ψ = 8, Q* is three to four orders of magnitude below F*.
/// MODEL.md §7: Q*/F* ≈ 1.8e-5 … 1.2e-3 over 0 ≤ h* ≤ 3. Checked at
/// θ = 0.003 (the θ of the paper's ψ-comparisons; Q*/F* barely depends on θ
/// at ψ = 8: 1.816e-5 … 1.190e-3 at θ = 0). Tolerance 10% on the minimum
/// (at h* = 0) and the maximum (at h* = 3). Measured 1.8230e-5 and 1.2276e-3.
#[test]
fn friction_to_load_ratio_spans_1_8e_5_to_1_2e_3_at_psi_8() {
    let ratios: Vec<f64> = sweep_h(&model(8.0, 0.003))
        .iter()
        .map(|c| c.q_star / c.f_star)
        .collect();
    let min = ratios.iter().copied().fold(f64::INFINITY, f64::min);
    let max = ratios.iter().copied().fold(0.0, f64::max);
    assert!(rel(min, 1.8e-5) <= 0.1, "min Q*/F* = {min:e}");
    assert!(rel(max, 1.2e-3) <= 0.1, "max Q*/F* = {max:e}");
    assert_eq!(min, ratios[0], "minimum not at h* = 0");
    assert_eq!(max, ratios[300], "maximum not at h* = 3");
}

/// Paper: m = 0.82 at ψ = 2. NOT reproduced: MODEL.md §7 says this model
/// gives 0.62, and Q* peaks near F* ≈ 0.07, inside the paper's load range,
/// so no single power law fits. This test documents the known difference:
/// m = 0.62 ± 0.01 (measured 0.6190; θ = 0.003, fit as in the module docs),
/// at least 0.15 away from the paper's 0.82; and the peak of Q*(h*) lies at
/// F* = 0.07 ± 0.01 (measured F* = 0.0654, h* = 0.635, Q* = 2.832e-3).
#[test]
fn psi_2_gives_m_0_62_not_the_papers_0_82_and_q_peaks_near_f_star_0_07() {
    let model = model(2.0, 0.003);
    let m = power_m(&model);
    assert!((m - 0.62).abs() <= 0.01, "m = {m}");
    assert!(
        (m - 0.82).abs() >= 0.15,
        "m = {m} is close to the paper's 0.82"
    );

    // Golden-section search for the maximum of Q*(h*) on [0, 1.5].
    let q = |h: f64| model.at_h_star(h).unwrap().q_star;
    let g = (5.0_f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (0.0, 1.5);
    for _ in 0..80 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if q(x1) < q(x2) {
            a = x1;
        } else {
            b = x2;
        }
    }
    let peak = model.at_h_star(0.5 * (a + b)).unwrap();
    // An interior maximum: Q* is lower at both ends of the paper's h* range.
    assert!(peak.h_star > 0.1 && peak.h_star < 1.4, "{peak:?}");
    assert!(q(0.0) < peak.q_star && q(3.0) < peak.q_star);
    assert!((peak.f_star - 0.07).abs() <= 0.01, "Q* peaks at {peak:?}");
}

/// μ_KE / μ_CEB at the given loads (θ = 0.003).
fn ke_over_ceb(psi: f64, loads: &[f64]) -> Vec<f64> {
    let ke = model(psi, 0.003);
    let ceb = Model::new(Params::new(psi, 0.003).kind(Kind::CebType)).unwrap();
    loads
        .iter()
        .map(|&f| ke.at_f_star(f).unwrap().mu.unwrap() / ceb.at_f_star(f).unwrap().mu.unwrap())
        .collect()
}

/// Paper (Fig. 5, dashed lines) and MODEL.md §8: the CEB-type μ lies below
/// Kogut–Etsion's by about 1.5× at ψ = 0.5, 3–4× at ψ = 1 and 10× or more
/// at ψ = 2 (θ = 0.003). Measured μ_KE/μ_CEB at
/// F* = 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 5e-2:
///
/// | ψ   | ratios |
/// |-----|--------|
/// | 0.5 | 1.540 1.549 1.563 1.581 1.616 1.691 1.789 |
/// | 1   | 2.366 2.577 2.924 3.429 4.431 6.436 8.331 |
/// | 2   | 9.805 10.58 11.63 12.83 14.56 16.74 18.10 |
///
/// So the ratio grows with the load; "3–4×" at ψ = 1 holds only for
/// 1e-3 ≲ F* ≲ 1e-2, and "10× or more" at ψ = 2 holds from F* ≈ 1.2e-4 up
/// (9.8 at 1e-4). Bands asserted: ψ = 0.5 in [1.45, 1.85] everywhere;
/// ψ = 1 in [2.8, 4.6] for 1e-3 ≤ F* ≤ 1e-2 and in [2, 9] everywhere;
/// ψ = 2 ≥ 9.5 everywhere and ≥ 10 from 3e-4; the ratio increases with ψ
/// and with F*.
#[test]
fn ceb_type_mu_is_1_5x_3_to_4x_and_10x_below_ke_at_psi_0_5_1_2() {
    let loads = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 5e-2];
    let r05 = ke_over_ceb(0.5, &loads);
    let r1 = ke_over_ceb(1.0, &loads);
    let r2 = ke_over_ceb(2.0, &loads);
    for (i, &f) in loads.iter().enumerate() {
        assert!(
            (1.45..=1.85).contains(&r05[i]),
            "ψ = 0.5, F* = {f}: {}",
            r05[i]
        );
        assert!((2.0..=9.0).contains(&r1[i]), "ψ = 1, F* = {f}: {}", r1[i]);
        if (1e-3..=1e-2).contains(&f) {
            assert!((2.8..=4.6).contains(&r1[i]), "ψ = 1, F* = {f}: {}", r1[i]);
        }
        assert!(r2[i] >= 9.5, "ψ = 2, F* = {f}: {}", r2[i]);
        if f >= 3e-4 {
            assert!(r2[i] >= 10.0, "ψ = 2, F* = {f}: {}", r2[i]);
        }
        assert!(
            r05[i] < r1[i] && r1[i] < r2[i],
            "not increasing with ψ at F* = {f}"
        );
        if i > 0 {
            for r in [&r05, &r1, &r2] {
                assert!(r[i] > r[i - 1], "not increasing with F* at {f}: {r:?}");
            }
        }
    }
}
