//! What the paper reports (Kogut & Etsion 2004), checked against this model:
//! the table of MODEL.md §7 ("What the paper reports, to check against") and
//! the CEB-type comparison of MODEL.md §8 (last paragraph).
//!
//! Each test names the statement, its source, the value MODEL.md gives for
//! this model and the tolerance. Numbers measured when these tests were
//! written are quoted in the comments ("measured").
//!
//! The quantities are computed by `ke_friction::paper`, the same
//! functions `kefric validate` uses for `docs/validation.md`; how the
//! power-law exponents are fitted (301 points equally spaced in h* over
//! 0 ≤ h* ≤ 3, F* ≤ 0.1, ordinary least squares in log–log coordinates) and
//! which alternatives do not reproduce MODEL.md's numbers is documented
//! there.
use crate::common::rel;
use ke_friction::paper::fits::{
    adhesion_ratio_at, adhesion_ratio_crossing, exponent_n, extremes_over_h, friction_peak, ke_over_ceb,
    max_adhesion_ratio, power_m, MIN_FIT_POINTS, SWEEP_POINTS,
};
use ke_friction::paper::CEB_LOADS;
use ke_friction::{Model, Params};

fn model(psi: f64, theta: f64) -> Model {
    Model::new(Params::new(psi, theta)).unwrap()
}

/// The fits use the 301-point sweep and need more than 250 points with
/// F* ≤ 0.1 (ψ = 2 is the case where some are dropped).
#[test]
fn fits_use_more_than_250_of_the_301_points() {
    assert_eq!(SWEEP_POINTS, 301);
    assert_eq!(MIN_FIT_POINTS, 251);
    let fit = power_m(&model(2.0, 0.003)).unwrap();
    assert!(fit.points > 250 && fit.points < 301, "points = {}", fit.points);
    assert_eq!(power_m(&model(0.5, 0.003)).unwrap().points, 301);
}

/// Paper (Fig. 4): Q* ≈ C·F*^m with m = 0.86 at ψ = 0.5, θ = 0.003.
/// MODEL.md §7: this model gives 0.84 with the default ε* = 0.004.
/// Tolerance ±0.01. Measured 0.8410.
#[test]
fn power_m_is_0_84_at_psi_0_5_theta_0_003() {
    let m = power_m(&model(0.5, 0.003)).unwrap().exponent;
    assert!((m - 0.84).abs() <= 0.01, "m = {m}");
}

/// MODEL.md §7: with ε* = 0.01 the model gives the paper's m = 0.86
/// (ψ = 0.5, θ = 0.003). Tolerance ±0.01. Measured 0.8564.
#[test]
fn power_m_is_0_86_at_psi_0_5_theta_0_003_with_eps_star_0_01() {
    let model = Model::new(Params::new(0.5, 0.003).eps_star(0.01)).unwrap();
    let m = power_m(&model).unwrap().exponent;
    assert!((m - 0.86).abs() <= 0.01, "m = {m}");
}

/// Paper: n between 0.09 and 0.13 (θ = 0.001); experiment 0.102 at
/// ψ = 0.67 and 0.130 at ψ = 1.01. MODEL.md §6 item 1 and §7: this model
/// gives 0.112 at ψ = 0.67. Tolerance ±0.003. Measured 0.1122.
#[test]
fn exponent_n_is_0_112_at_psi_0_67_theta_0_001() {
    let n = exponent_n(&model(0.67, 0.001)).unwrap().exponent;
    assert!((n - 0.112).abs() <= 0.003, "n = {n}");
}

/// As above, at ψ = 1.01: MODEL.md gives 0.127. Tolerance ±0.003.
/// Measured 0.1276.
#[test]
fn exponent_n_is_0_127_at_psi_1_01_theta_0_001() {
    let n = exponent_n(&model(1.01, 0.001)).unwrap().exponent;
    assert!((n - 0.127).abs() <= 0.003, "n = {n}");
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
        let r = max_adhesion_ratio(&model(psi, 0.003)).value;
        assert!(r < 0.11, "ψ = {psi}: max Fs*/P* = {r}");
        if r > worst.1 {
            worst = (psi, r);
        }
    }
    assert_eq!(worst.0, 2.0, "largest Fs*/P* not at ψ = 2: {worst:?}");
    assert!((worst.1 - 0.104).abs() <= 0.002, "max Fs*/P* = {}", worst.1);
    // Below ψ = 2 the bound does not hold (the paper states it for ψ ≥ 2).
    assert!(max_adhesion_ratio(&model(1.5, 0.003)).value > 0.11);
    assert!(max_adhesion_ratio(&model(1.0, 0.003)).value > 0.11);
}

/// Paper: at ψ = 1 (θ = 0.003), Fs*/P* < 0.1 for F* > 0.01. MODEL.md §7:
/// the ratio crosses 0.1 at F* ≈ 0.009. Found by bisection in ln F*;
/// tolerance ±0.001. Measured 0.009092.
#[test]
fn adhesion_ratio_crosses_0_1_at_f_star_0_009_for_psi_1() {
    let model = model(1.0, 0.003);
    let excess = |f: f64| adhesion_ratio_at(&model, f).unwrap() - 0.1;
    let (lo, hi) = (1e-4_f64, 0.05_f64);
    assert!(excess(lo) > 0.0 && excess(hi) < 0.0, "no sign change");
    let b = adhesion_ratio_crossing(&model, 0.1, (lo, hi)).unwrap();
    assert!(b.hi / b.lo - 1.0 < 1e-9);
    assert!((b.lo - 0.009).abs() <= 0.001, "crossing at F* = {}", b.lo);
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
    let (min, max) = extremes_over_h(&model(8.0, 0.003), f64::INFINITY, |c| c.q_star / c.f_star).unwrap();
    assert!(rel(min.value, 1.8e-5) <= 0.1, "min Q*/F* = {:e}", min.value);
    assert!(rel(max.value, 1.2e-3) <= 0.1, "max Q*/F* = {:e}", max.value);
    assert_eq!(min.h_star, 0.0, "minimum not at h* = 0");
    assert_eq!(max.h_star, 3.0, "maximum not at h* = 3");
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
    let m = power_m(&model).unwrap().exponent;
    assert!((m - 0.62).abs() <= 0.01, "m = {m}");
    assert!((m - 0.82).abs() >= 0.15, "m = {m} is close to the paper's 0.82");

    // Golden-section search for the maximum of Q*(h*) on [0, 1.5].
    let q = |h: f64| model.at_h_star(h).unwrap().q_star;
    let peak = friction_peak(&model, (0.0, 1.5)).unwrap();
    // An interior maximum: Q* is lower at both ends of the paper's h* range.
    assert!(peak.h_star > 0.1 && peak.h_star < 1.4, "{peak:?}");
    assert!(q(0.0) < peak.q_star && q(3.0) < peak.q_star);
    assert!((peak.f_star - 0.07).abs() <= 0.01, "Q* peaks at {peak:?}");
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
    let loads = CEB_LOADS;
    assert_eq!(loads, [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 5e-2]);
    let r05 = ke_over_ceb(0.5, 0.003, &loads).unwrap();
    let r1 = ke_over_ceb(1.0, 0.003, &loads).unwrap();
    let r2 = ke_over_ceb(2.0, 0.003, &loads).unwrap();
    for (i, &f) in loads.iter().enumerate() {
        assert!((1.45..=1.85).contains(&r05[i]), "ψ = 0.5, F* = {f}: {}", r05[i]);
        assert!((2.0..=9.0).contains(&r1[i]), "ψ = 1, F* = {f}: {}", r1[i]);
        if (1e-3..=1e-2).contains(&f) {
            assert!((2.8..=4.6).contains(&r1[i]), "ψ = 1, F* = {f}: {}", r1[i]);
        }
        assert!(r2[i] >= 9.5, "ψ = 2, F* = {f}: {}", r2[i]);
        if f >= 3e-4 {
            assert!(r2[i] >= 10.0, "ψ = 2, F* = {f}: {}", r2[i]);
        }
        assert!(r05[i] < r1[i] && r1[i] < r2[i], "not increasing with ψ at F* = {f}");
        if i > 0 {
            for r in [&r05, &r1, &r2] {
                assert!(r[i] > r[i - 1], "not increasing with F* at {f}: {r:?}");
            }
        }
    }
}

/// `paper::statements` (what `kefric validate` prints) reports the
/// verdicts MODEL.md §7 leads one to expect: the two known differences
/// (m at ψ = 0.5 with the default ε*, and m = 0.62 instead of 0.82 at
/// ψ = 2) and n at ψ = 2, which follows from the latter (n ≈ 1 − m); and,
/// now that the CEB-type rows test MODEL.md §8's factors over the plotted
/// loads rather than only "below", two of them hold over part of the range
/// only (ψ = 0.5: 1.54–1.72×, ψ = 1: 2.49–10.7×).
#[test]
fn statements_differ_from_the_paper_only_where_model_md_says_so() {
    use ke_friction::paper::{statements, Verdict};
    let rows = statements().unwrap();
    let with = |v: Verdict| -> Vec<&str> { rows.iter().filter(|r| r.verdict == v).map(|r| r.paper).collect() };
    let differ = with(Verdict::Differs);
    assert_eq!(differ.len(), 3, "{differ:#?}");
    assert!(differ[0].contains("m = 0.86 at ψ = 0.5"), "{differ:#?}");
    assert!(differ[1].contains("ψ = 0.5 and ψ = 2"), "{differ:#?}");
    assert!(differ[2].contains("m = 0.82 at ψ = 2"), "{differ:#?}");
    let partly = with(Verdict::Partly);
    assert_eq!(partly.len(), 2, "{partly:#?}");
    assert!(partly[0].contains("even at ψ = 0.5"), "{partly:#?}");
    assert!(partly[1].contains("at ψ = 1"), "{partly:#?}");
    assert_eq!(with(Verdict::Agrees).len(), 7);
}

/// The CEB-type row at ψ = 1 tests MODEL.md §8's "3–4×" (read off Fig. 5)
/// over the plotted loads, F* at h* = 3 (2.0e-4, where the CEB-type line
/// starts) to 0.073 (h* = 0 of the Kogut–Etsion line): the ratio runs from
/// 2.49 to 10.7, so it lies in [2.5, 4.5) (the band, rounded) for
/// 2.1e-4 ≤ F* ≤ 0.011 only, and the row says so instead of "agrees".
/// Measured ends 2.0967e-4 and 1.0592e-2; tolerance 1% on each.
#[test]
fn ceb_row_at_psi_1_holds_for_part_of_the_plotted_loads_and_says_which() {
    use ke_friction::paper::{statements, Verdict};
    let rows = statements().unwrap();
    let row = rows.iter().find(|r| r.paper.contains("the same at ψ = 1")).unwrap();
    assert_eq!(row.verdict, Verdict::Partly);
    assert_eq!(row.verdict.to_string(), "partly");
    let c = row.holds_for.as_ref().unwrap();
    assert_eq!(c.holds.len(), 1, "{c:?}");
    let (a, b) = c.holds[0];
    assert!(c.range.0 < a && b < c.range.1, "{c:?}");
    assert!(
        rel(a, 2.0967e-4) < 0.01 && rel(b, 1.0592e-2) < 0.01,
        "holds for [{a:e}, {b:e}]"
    );
    // Outside the stretch the ratio is outside the band, at both ends.
    let ((_, lo), (_, hi)) = c.extremes;
    assert!(lo < 2.5 && hi >= 4.5, "{lo} … {hi}");
    assert!(
        row.computed.contains("only for F* in [2.1e-4, 0.011]"),
        "{}",
        row.computed
    );
    assert!(row.computed.contains("2.49× at F* = 2.0e-4"), "{}", row.computed);
    // ψ = 2: ≥ 9.5 at every plotted load (measured 11.0 to 20.7).
    let row2 = rows.iter().find(|r| r.paper.contains("the same at ψ = 2")).unwrap();
    assert_eq!(row2.verdict, Verdict::Agrees);
    assert!(row2.holds_for.as_ref().unwrap().everywhere());
}

/// `holds_where` finds the stretch where a criterion holds and its ends:
/// y = log10 F* over [1e-5, 0.1] lies in [−3.5, −2) for
/// F* in [10^−3.5, 1e-2) (ends to the 1e-6 relative of the bisection); a
/// band nowhere met gives no stretch; one met everywhere the whole range.
#[test]
fn holds_where_finds_the_stretch_and_fails_outside_the_band() {
    use ke_friction::paper::fits::holds_where;
    use ke_friction::paper::Band;
    let y = |f: f64| Ok(f.log10());
    let band = Band { lo: -3.5, hi: -2.0 };
    let c = holds_where((1e-5, 0.1), y, |v| band.contains(v)).unwrap();
    assert_eq!(c.holds.len(), 1, "{c:?}");
    let (a, b) = c.holds[0];
    assert!(rel(a, 10f64.powf(-3.5)) < 2e-6 && rel(b, 1e-2) < 2e-6, "[{a:e}, {b:e}]");
    assert!(!c.everywhere() && !c.nowhere());
    assert!(!band.contains(-2.0) && !band.contains(-3.6) && band.contains(-3.5));
    let never = holds_where((1e-5, 0.1), y, |v| v > 0.0).unwrap();
    assert!(never.nowhere());
    let always = holds_where((1e-5, 0.1), y, |v| v < 0.0).unwrap();
    assert!(always.everywhere() && always.holds == vec![(1e-5, 0.1)]);
    // Two stretches: outside (−4, −2).
    let two = holds_where((1e-5, 0.1), y, |v| !(-4.0..-2.0).contains(&v)).unwrap();
    assert_eq!(two.holds.len(), 2, "{two:?}");
    assert!(rel(two.holds[0].1, 1e-4) < 2e-6 && rel(two.holds[1].0, 1e-2) < 2e-6);
}

/// The plotted loads are those of the figures' curves: at ψ = 1,
/// θ = 0.003 from F*(h* = 3) to F*(h* = 0) < 0.1; at ψ = 2 up to 0.1
/// (F*(h* = 0) = 0.13 there).
#[test]
fn plotted_loads_run_from_h_star_3_to_0_1_or_h_star_0() {
    use ke_friction::paper::fits::plotted_loads;
    let m1 = model(1.0, 0.003);
    let (lo, hi) = plotted_loads(&[&m1]).unwrap();
    assert_eq!(lo, m1.at_h_star(3.0).unwrap().f_star);
    assert_eq!(hi, m1.at_h_star(0.0).unwrap().f_star);
    assert!(hi < 0.1);
    let m2 = model(2.0, 0.003);
    assert_eq!(plotted_loads(&[&m2]).unwrap().1, 0.1);
}
