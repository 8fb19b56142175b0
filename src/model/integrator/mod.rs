//! The integrals' machinery, the same for every contact law: the
//! density of asperity heights, the panels and their Gauss rules.
//!
//! Every integral is taken in `x = (z* − d*)/ω_c*`, split at the regime
//! boundaries (the single-asperity laws jump there) and then into panels on
//! which the Gaussian changes by a bounded factor. Each panel gets a
//! [`NODES`]-point Gauss rule; the panel that
//! starts at the contact point `x = 0` gets a Gauss–Jacobi rule with the
//! exact weight `x^b`, and the panels of the non-contact adhesion integral
//! grow geometrically away from `z* = d*`, where its integrand varies on
//! the scale ε*. Tails below `e^−TAIL` of the integrand's largest Gaussian
//! factor are cut; the power tails of Pearson types IV and VII are
//! integrated out to infinity in one panel, in `1/(z* − c)` ([`TailRule`]).
//! No allocation, no recursion: a fixed amount of arithmetic per panel.
//!
//! The height densities φ* are in `density.rs`, the panels, the elastic
//! regime's nodes and the non-contact adhesion in `panels.rs`. The laws
//! (`../laws/`) integrate their own elastic regime with these; the
//! surface (`../surface.rs`) sums the regimes.
//!
//! [`NODES`]: crate::quadrature::NODES
//! [`TailRule`]: density::TailRule

mod density;
mod panels;

use super::asperity::{adhesion, HERTZ};
use crate::gw::sigma_s_ratio;
use crate::params::Params;
use crate::quadrature::Rule;
use density::{Gauss, General};

pub(crate) use density::{Heights, Phi, PhiVisitor, Window};
pub(crate) use panels::{add_node, elastic_node, EndSide};

/// What the integrals need that depends only on the parameters and not
/// on the contact law: the height density and the scales (the "plan";
/// MODEL.md §2).
#[derive(Debug, Clone)]
pub(crate) struct Integrator {
    /// σ_s/σ.
    s: f64,
    /// The density of asperity heights φ*.
    pub(super) heights: Heights,
    /// ω_c* = s/ψ².
    pub(crate) omega: f64,
    eps: f64,
    /// `a·r^c` of the three contact adhesion rows.
    pub(crate) adh_coef: [f64; 3],
    pub(crate) rules: &'static Rules,
}

/// The Gauss rules, the same for every model: computed once per process.
#[derive(Debug)]
pub(crate) struct Rules {
    gl: Rule,
    /// Gauss–Jacobi rules for `x^1.5`, `x^0.298` (first panels).
    gj_load: Rule,
    gj_adh: Rule,
    /// Gauss–Jacobi rule for `(1 − x)^½` (CEB-type, at x = 1), which is
    /// also the weight `x^0.5` of the Hertz load's slope.
    pub(crate) gj_half: Rule,
    /// Gauss–Jacobi rule for `x^−0.702`, the elastic adhesion's slope.
    gj_adh_slope: Rule,
}

impl Rules {
    fn get() -> &'static Rules {
        static RULES: std::sync::OnceLock<Rules> = std::sync::OnceLock::new();
        RULES.get_or_init(|| Rules {
            gl: Rule::legendre(),
            gj_load: Rule::jacobi(HERTZ.1),
            gj_adh: Rule::jacobi(adhesion::ELASTIC.1),
            gj_half: Rule::jacobi(0.5),
            gj_adh_slope: Rule::jacobi(adhesion::ELASTIC.1 - 1.0),
        })
    }
}

/// The integrals at one separation: P*, Fs*, their d*-derivatives and Q*
/// (what [`Integrals::evaluate`](crate::model::integrals::Integrals::evaluate) returns, with their prefactors), or the raw
/// integrals of one regime while they are summed (without).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Sums {
    /// P*.
    pub p: f64,
    /// ∂P*/∂d*.
    pub dp: f64,
    /// Fs*.
    pub fs: f64,
    /// ∂Fs*/∂d*.
    pub dfs: f64,
    /// Q* (0 unless asked for).
    pub q: f64,
}

impl Integrator {
    /// Plans the law-independent part of the integrals for valid
    /// parameters.
    pub fn new(p: &Params) -> Integrator {
        let pi = core::f64::consts::PI;
        let s = sigma_s_ratio(p.constants.beta);
        let omega = s / (p.psi * p.psi);
        let r = p.constants.eps_star / omega;
        let gauss = Gauss {
            s,
            inv_s2: 1.0 / (s * s),
            norm: 1.0 / (s * (2.0 * pi).sqrt()),
        };
        let heights = if p.constants.distribution.is_gaussian() {
            Heights::Gauss(gauss)
        } else {
            // Model::new validated the constants.
            let g = p.constants.distribution.validated_density();
            Heights::General(std::sync::Arc::new(General::new(g, s)))
        };
        Integrator {
            s,
            heights,
            omega,
            eps: p.constants.eps_star,
            adh_coef: adhesion::ROWS.map(|(a, _, c)| a * r.powf(c)),
            rules: Rules::get(),
        }
    }

    /// The fraction of the asperities in contact at separation `d` (d*):
    /// ∫ φ* over z* > d* (MODEL.md §4's number of contacts over η·A_n);
    /// for the Gaussian ½·erfc(d*/(s√2)).
    pub fn contact_fraction(&self, d: f64) -> f64 {
        match &self.heights {
            Heights::Gauss(g) => 0.5 * libm::erfc(d / (g.s * core::f64::consts::SQRT_2)),
            Heights::General(h) => h.fraction_above(d),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    /// The fraction of summits above d* (the count of contacts' factor):
    /// for general densities (Pearson types I, IV, VI and Weibull), against
    /// a plain trapezoid of the pdf over the standardised heights above
    /// d*/s (200,000 steps): within 1e-7 (the density's own quadrature, ~
    /// 30 times fewer density evaluations than a midpoint rule that held
    /// 1e-4).
    #[test]
    fn the_fraction_of_summits_in_contact_matches_the_density() {
        use crate::HeightDistribution as H;
        for dist in [
            H::pearson(0.6, 4.0).unwrap(),
            H::pearson(0.3, 2.6).unwrap(),
            H::pearson(-0.5, 5.0).unwrap(),
            H::weibull(0.5).unwrap(),
        ] {
            let p = Params::new(1.0, 0.001).distribution(dist.clone());
            let grid = Integrator::new(&p);
            let density = p.constants.distribution.density().unwrap();
            let s = sigma_s_ratio(p.constants.beta);
            let (lo, hi) = density.support();
            for d in [-1.0, 0.0, 0.8, 2.0, 3.5] {
                let (a, b) = ((d / s).max(lo), hi.min(40.0));
                if a >= b {
                    // Above the support: no summit.
                    assert_eq!(grid.contact_fraction(d), 0.0, "{dist:?}, d* = {d}");
                    continue;
                }
                let n = 200_000;
                let h = (b - a) / n as f64;
                let mut sum = 0.5 * (density.pdf(a) + density.pdf(b));
                for k in 1..n {
                    sum += density.pdf(a + k as f64 * h);
                }
                let want = sum * h;
                let got = grid.contact_fraction(d);
                assert!((got / want - 1.0).abs() < 1e-7, "{dist:?}, d* = {d}: {got} vs {want}");
            }
        }
    }

    impl Integrator {
        /// `I^b[xa, xc]` (MODEL.md §4) with the same panels and rules as the
        /// model's own integrals.
        fn moment(&self, d: f64, b: f64, xa: f64, xc: f64) -> f64 {
            let Heights::Gauss(h) = &self.heights else {
                panic!("a Gaussian surface")
            };
            let win = h.window(d);
            let rule = Rule::jacobi(b);
            let mut sum = 0.0;
            self.panels(h, d, win, xa, xc, |p| {
                if p.first && xa == 0.0 {
                    self.jacobi_panel(h, d, &rule, b, p.x1, |_, w, _| sum += w);
                } else {
                    self.legendre_panel(h, d, p, |x, w, _| sum += x.powf(b) * w);
                }
            });
            sum
        }
    }

    /// MODEL.md §5: `I^b[0,∞)` in closed form through the parabolic cylinder
    /// function (values from `tools/reference.py`, mpmath `pcfd`), and the
    /// pieces `I^b[0,1]`, `I^b[1,∞)` from 30-digit quadrature.
    #[test]
    fn moments_match_the_closed_form_semi_infinite_integrals() {
        let doc: Value = serde_json::from_str(include_str!("../../../tests/data/reference_points.json")).unwrap();
        let mut n = 0;
        for p in doc["points"].as_array().unwrap() {
            if p["kind"] != "closed_form" {
                continue;
            }
            let f = |k: &str| p[k].as_f64().unwrap();
            let grid = Integrator::new(&Params::new(f("psi"), 0.0).beta(f("beta")));
            let (b, d) = (f("b"), f("d_star"));
            let lower = grid.moment(d, b, 0.0, 1.0);
            let upper = grid.moment(d, b, 1.0, f64::INFINITY);
            let whole = grid.moment(d, b, 0.0, f64::INFINITY);
            for (what, got, want) in [
                ("I[0,1]", lower, f("i_0_1")),
                ("I[1,inf)", upper, f("i_1_inf")),
                ("I[0,inf)", whole, f("i_0_inf")),
                ("I[0,1]+I[1,inf)", lower + upper, f("i_0_inf")),
            ] {
                let rel = ((got - want) / want).abs();
                assert!(rel < 1e-12, "b = {b}, d* = {d}: {what} = {got:e} vs {want:e} ({rel:e})");
            }
            n += 1;
        }
        assert!(n >= 6);
    }
}
