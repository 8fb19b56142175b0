//! The literature's statements on non-Gaussian asperity heights (MODEL.md
//! §9, "Statements from the literature"), computed from this model with
//! the default β = 0.04, ν = 0.3, ε* = 0.004, each with the range of
//! (ψ, θ, F*) where it holds.
//!
//! The statements come from abstracts of papers on other models (the CEB
//! and GW-type extensions of Tayebi & Polycarpou 2004 and of the Weibull
//! paper, J. Tribol. 2004, doi 10.1115/1.1739406); nothing here expects
//! this model to reproduce them, the rows say where it does.

use super::fits::holds_where;
use super::{sig, stretches, PaperError, Statement, Verdict};
use crate::{Constants, HeightDistribution, Model};

/// The ψ of the scans.
pub const NONGAUSSIAN_PSIS: [f64; 4] = [0.5, 1.0, 2.0, 4.0];
/// The θ of statement 1's grid.
pub const NONGAUSSIAN_THETAS: [f64; 3] = [1e-4, 1e-3, 3e-3];
/// The loads of statement 1's grid.
pub const NONGAUSSIAN_LOADS: [f64; 4] = [1e-4, 1e-3, 1e-2, 0.05];
/// θ of the load scans (statements 2 and 3).
pub const NONGAUSSIAN_THETA: f64 = 1e-3;
/// The loads scanned by statements 2 and 3: the paper's figure range.
pub const NONGAUSSIAN_F_STAR: (f64, f64) = crate::F_STAR_RANGE;

fn model(psi: f64, theta: f64, d: HeightDistribution) -> Result<Model, PaperError> {
    Ok(Model::new(Constants::default().distribution(d).at(psi, theta)?)?)
}

/// μ at `f`; NaN where it is undefined (a criterion on it then fails).
fn mu(m: &Model, f: f64) -> Result<f64, PaperError> {
    Ok(m.at_f_star(f)?.mu.unwrap_or(f64::NAN))
}

/// μ(Sk = 0.5, K = 5)/μ(Gaussian) at (ψ, θ, F*).
pub fn tayebi_ratio(psi: f64, theta: f64, f_star: f64) -> Result<f64, PaperError> {
    let p = model(psi, theta, HeightDistribution::pearson(0.5, 5.0)?)?;
    let g = model(psi, theta, HeightDistribution::GAUSSIAN)?;
    Ok(mu(&p, f_star)? / mu(&g, f_star)?)
}

/// d ln μ / d ln F* by a central difference (step 1e-3 in ln F*).
fn log_slope(m: &Model, f: f64) -> Result<f64, PaperError> {
    let k = 1e-3f64.exp();
    Ok((mu(m, f * k)? / mu(m, f / k)?).ln() / (2e-3))
}

/// The §9 literature statements: (1) high kurtosis with positive skewness
/// lowers μ (one row over a (ψ, θ, F*) grid); (2) for high kurtosis μ
/// decreases as F* decreases (one row per ψ); (3) negative skewness raises
/// μ, more so at light loads (one row per ψ for Pearson(−0.5, 3.375), one
/// for Weibull(−0.5) at ψ = 1). Takes about a second in release.
pub fn nongaussian_statements() -> Result<Vec<Statement>, PaperError> {
    let mut rows = Vec::new();

    // (1) Tayebi & Polycarpou: high K, positive Sk → lower μ.
    let mut fails = Vec::new();
    let (mut lo, mut hi) = ((f64::INFINITY, (0.0, 0.0, 0.0)), (0.0f64, (0.0, 0.0, 0.0)));
    let mut n = 0;
    for psi in NONGAUSSIAN_PSIS {
        for theta in NONGAUSSIAN_THETAS {
            let p = model(psi, theta, HeightDistribution::pearson(0.5, 5.0)?)?;
            let g = model(psi, theta, HeightDistribution::GAUSSIAN)?;
            for f in NONGAUSSIAN_LOADS {
                let r = mu(&p, f)? / mu(&g, f)?;
                n += 1;
                if r < lo.0 {
                    lo = (r, (psi, theta, f));
                }
                if r > hi.0 {
                    hi = (r, (psi, theta, f));
                }
                if r.is_nan() || r >= 1.0 {
                    fails.push(format!("{} at (ψ, θ, F*) = ({psi}, {theta}, {f})", sig(r, 4)));
                }
            }
        }
    }
    let at = |(psi, theta, f): (f64, f64, f64)| format!("(ψ, θ, F*) = ({psi}, {theta}, {f})");
    rows.push(Statement {
        paper: "Tayebi & Polycarpou 2004: surfaces with high kurtosis and positive skewness have a lower static friction coefficient than the Gaussian case",
        model_md: "—",
        computed: format!(
            "μ(Sk = 0.5, K = 5)/μ(Gaussian) = {} … {} over {n} points ({} at {}, {} at {}); {}",
            sig(lo.0, 3),
            sig(hi.0, 3),
            sig(lo.0, 3),
            at(lo.1),
            sig(hi.0, 3),
            at(hi.1),
            if fails.is_empty() {
                "below 1 at every point".to_string()
            } else {
                format!("not below 1 at {} points: {}", fails.len(), fails.join("; "))
            }
        ),
        value: hi.0,
        verdict: if fails.is_empty() {
            Verdict::Agrees
        } else if fails.len() == n {
            Verdict::Differs
        } else {
            Verdict::Partly
        },
        criterion: "μ(Sk = 0.5, K = 5)/μ(Gaussian) < 1 at every (ψ, θ, F*) of ψ ∈ {0.5, 1, 2, 4}, θ ∈ {1e-4, 1e-3, 3e-3}, F* ∈ {1e-4, 1e-3, 1e-2, 0.05}",
        note: "",
        holds_for: None,
    });

    // (2) Tayebi & Polycarpou: for high K, μ decreases as F* decreases.
    for psi in NONGAUSSIAN_PSIS {
        let p = model(psi, NONGAUSSIAN_THETA, HeightDistribution::pearson(0.0, 8.0)?)?;
        let g = model(psi, NONGAUSSIAN_THETA, HeightDistribution::GAUSSIAN)?;
        let c = holds_where(NONGAUSSIAN_F_STAR, |f| log_slope(&p, f), |s| s > 0.0)?;
        let gs = log_slope(&g, 1e-4)?;
        rows.push(Statement {
            paper: match psi {
                _ if psi == 0.5 => "Tayebi & Polycarpou 2004: for high kurtosis the static friction coefficient decreases with decreasing external force (the Gaussian's increases); Sk = 0, K = 8, θ = 0.001, ψ = 0.5",
                _ if psi == 1.0 => "the same at ψ = 1",
                _ if psi == 2.0 => "the same at ψ = 2",
                _ => "the same at ψ = 4",
            },
            model_md: "—",
            computed: format!(
                "d ln μ/d ln F* = {} at F* = {} … {} at F* = {}; > 0 {}; Gaussian: {} at F* = 1e-4",
                sig(c.ends.0, 3),
                sig(c.range.0, 2),
                sig(c.ends.1, 3),
                sig(c.range.1, 2),
                if c.everywhere() {
                    "everywhere".to_string()
                } else if c.nowhere() {
                    "nowhere".to_string()
                } else {
                    format!("only for {}", stretches(&c))
                },
                sig(gs, 3)
            ),
            value: c.ends.0,
            verdict: Verdict::over(&c),
            criterion: "dμ/dF* > 0 (central difference in ln F*) at every load of 1e-5 ≤ F* ≤ 0.1, 20 per decade",
            note: "",
            holds_for: Some(c),
        });
    }

    // (3) Weibull paper: negative Sk → higher μ, magnified at lower load.
    let negs: [(f64, HeightDistribution, &'static str); 5] = [
        (0.5, HeightDistribution::pearson(-0.5, 3.375)?, "The Weibull extension of CEB (J. Tribol. 2004, doi 10.1115/1.1739406): surfaces with negative skewness have a higher static friction coefficient than the Gaussian case, magnified at lower loads; Pearson Sk = −0.5, K = 3.375, θ = 0.001, ψ = 0.5"),
        (1.0, HeightDistribution::pearson(-0.5, 3.375)?, "the same at ψ = 1"),
        (2.0, HeightDistribution::pearson(-0.5, 3.375)?, "the same at ψ = 2"),
        (4.0, HeightDistribution::pearson(-0.5, 3.375)?, "the same at ψ = 4"),
        (1.0, HeightDistribution::weibull(-0.5)?, "the same with Weibull heights, Sk = −0.5, ψ = 1"),
    ];
    for (psi, d, paper) in negs {
        rows.push(higher_than_gaussian(psi, d, paper)?);
    }

    // (4) Chilamakuri & Bhushan: negative skewness and/or K < 3 give
    // severe friction (a high μ at light loads).
    let severe: [(f64, HeightDistribution, &'static str); 8] = [
        (0.5, HeightDistribution::pearson(0.0, 2.5)?, "Chilamakuri & Bhushan 1998: a kurtosis below 3 gives severe friction (a higher static friction coefficient than the Gaussian case, the more so at light loads); Pearson Sk = 0, K = 2.5, θ = 0.001, ψ = 0.5"),
        (1.0, HeightDistribution::pearson(0.0, 2.5)?, "the same at ψ = 1"),
        (2.0, HeightDistribution::pearson(0.0, 2.5)?, "the same at ψ = 2"),
        (4.0, HeightDistribution::pearson(0.0, 2.5)?, "the same at ψ = 4"),
        (0.5, HeightDistribution::pearson(-0.5, 2.5)?, "Chilamakuri & Bhushan 1998: negative skewness with a kurtosis below 3, the same; Pearson Sk = −0.5, K = 2.5, θ = 0.001, ψ = 0.5"),
        (1.0, HeightDistribution::pearson(-0.5, 2.5)?, "the same at ψ = 1"),
        (2.0, HeightDistribution::pearson(-0.5, 2.5)?, "the same at ψ = 2"),
        (4.0, HeightDistribution::pearson(-0.5, 2.5)?, "the same at ψ = 4"),
    ];
    for (psi, d, paper) in severe {
        rows.push(higher_than_gaussian(psi, d, paper)?);
    }
    Ok(rows)
}

/// A statement that the heights `d` give a higher μ than the Gaussian's at
/// (ψ, θ = 0.001), more so at lighter loads: where μ/μ_Gaussian > 1 over
/// 1e-5 ≤ F* ≤ 0.1, and whether it is larger at F* = 1e-4 than at 0.05.
fn higher_than_gaussian(psi: f64, d: HeightDistribution, paper: &'static str) -> Result<Statement, PaperError> {
    let p = model(psi, NONGAUSSIAN_THETA, d)?;
    let g = model(psi, NONGAUSSIAN_THETA, HeightDistribution::GAUSSIAN)?;
    let ratio = |f: f64| -> Result<f64, PaperError> { Ok(mu(&p, f)? / mu(&g, f)?) };
    let c = holds_where(NONGAUSSIAN_F_STAR, ratio, |r| r > 1.0)?;
    let (r_light, r_heavy) = (ratio(1e-4)?, ratio(0.05)?);
    let magnified = r_light > r_heavy;
    Ok(Statement {
        paper,
        model_md: "—",
        computed: format!(
            "μ/μ_Gaussian = {} at F* = 1e-4, {} at F* = 0.05 ({}); > 1 {}",
            sig(r_light, 4),
            sig(r_heavy, 4),
            if magnified { "larger at the lighter load" } else { "not larger at the lighter load" },
            if c.everywhere() {
                format!("over all of F* in [{}, {}]", sig(c.range.0, 2), sig(c.range.1, 2))
            } else if c.nowhere() {
                "nowhere".to_string()
            } else {
                format!("only for {}, below 1 elsewhere", stretches(&c))
            }
        ),
        value: r_light,
        verdict: match Verdict::over(&c) {
            Verdict::Agrees if !magnified => Verdict::Partly,
            v => v,
        },
        criterion: "μ/μ_Gaussian > 1 at every load of 1e-5 ≤ F* ≤ 0.1 (20 per decade), and larger at F* = 1e-4 than at F* = 0.05",
        note: "",
        holds_for: Some(c),
    })
}
