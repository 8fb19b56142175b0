//! The rough surface: Gaussian asperity heights and the integrals of
//! MODEL.md §4 (Kogut–Etsion) and §8 (CEB-type).
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
//! The height densities φ* are in `density.rs`, the integrals in
//! `integrals.rs`.
//!
//! [`NODES`]: crate::quadrature::NODES
//! [`TailRule`]: density::TailRule

mod density;
mod integrals;

use super::asperity::{adhesion, load};
use super::laws::{ContactLaw, Law};
use crate::distribution::Density;
use crate::gw::sigma_s_ratio;
use crate::params::{hardness_coefficient, Params};
use crate::quadrature::Rule;
use density::{Gauss, General, Heights};

pub(super) use density::{Phi, Window};
pub(super) use integrals::{elastic_node, EndSide};

/// Everything the integrals need that depends only on the parameters
/// (the "plan"; MODEL.md §2).
#[derive(Debug, Clone)]
pub(crate) struct Surface {
    /// The planned single-asperity law.
    law: Law,
    /// σ_s/σ.
    s: f64,
    /// The density of asperity heights φ*.
    heights: Heights,
    /// ω_c* = s/ψ².
    pub(super) omega: f64,
    /// y_s* = h* − d*.
    pub ys: f64,
    eps: f64,
    /// (2/3)πβKω_c*, in front of P* and Q*.
    load_pref: f64,
    /// 2πβθ, in front of Fs*.
    adh_pref: f64,
    /// `a·r^c` of the three contact adhesion rows.
    adh_coef: [f64; 3],
    pub(super) rules: &'static Rules,
}

/// The Gauss rules, the same for every model: computed once per process.
#[derive(Debug)]
pub(super) struct Rules {
    gl: Rule,
    /// Gauss–Jacobi rules for `x^1.5`, `x^0.298` (first panels).
    gj_load: Rule,
    gj_adh: Rule,
    /// Gauss–Jacobi rule for `(1 − x)^½` (CEB-type, at x = 1), which is
    /// also the weight `x^0.5` of the Hertz load's slope.
    pub(super) gj_half: Rule,
    /// Gauss–Jacobi rule for `x^−0.702`, the elastic adhesion's slope.
    gj_adh_slope: Rule,
}

impl Rules {
    fn get() -> &'static Rules {
        static RULES: std::sync::OnceLock<Rules> = std::sync::OnceLock::new();
        RULES.get_or_init(|| Rules {
            gl: Rule::legendre(),
            gj_load: Rule::jacobi(load::ELASTIC.1),
            gj_adh: Rule::jacobi(adhesion::ELASTIC.1),
            gj_half: Rule::jacobi(0.5),
            gj_adh_slope: Rule::jacobi(adhesion::ELASTIC.1 - 1.0),
        })
    }
}

/// The integrals at one separation: P*, Fs*, their d*-derivatives and Q*
/// (what [`Surface::evaluate`] returns, with their prefactors), or the raw
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

impl Surface {
    /// The fraction of the asperities in contact at separation `d` (d*):
    /// ∫ φ* over z* > d* (MODEL.md §4's number of contacts over η·A_n);
    /// for the Gaussian ½·erfc(d*/(s√2)).
    pub fn contact_fraction(&self, d: f64) -> f64 {
        match &self.heights {
            Heights::Gauss(g) => 0.5 * libm::erfc(d / (g.s * core::f64::consts::SQRT_2)),
            Heights::General(h) => h.fraction_above(d),
        }
    }

    /// Plans the integrals for valid parameters.
    pub fn new(p: &Params) -> Surface {
        let pi = core::f64::consts::PI;
        let s = sigma_s_ratio(p.constants.beta);
        let k = hardness_coefficient(p.constants.nu);
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
            let g = Density::new(&p.constants.distribution);
            Heights::General(std::sync::Arc::new(General::new(g, s)))
        };
        Surface {
            law: Law::new(&p.constants),
            s,
            heights,
            omega,
            ys: 1.0 / (4.0 * 3f64.sqrt() * pi * p.constants.beta),
            eps: p.constants.eps_star,
            load_pref: (2.0 / 3.0) * pi * p.constants.beta * k * omega,
            adh_pref: 2.0 * pi * p.constants.beta * p.theta,
            adh_coef: adhesion::ROWS.map(|(a, _, c)| a * r.powf(c)),
            rules: Rules::get(),
        }
    }

    /// P*, Fs* (with their d*-derivatives) and, if `want_q`, Q* at `d`:
    /// one `match` on the law, then static calls.
    pub fn evaluate(&self, d: f64, want_q: bool) -> Sums {
        match &self.law {
            Law::Ke(law) => self.evaluate_law(law, d, want_q),
            Law::Ceb(law) => self.evaluate_law(law, d, want_q),
        }
    }

    /// [`evaluate`](Self::evaluate) with the law `law`.
    #[inline(always)]
    pub(super) fn evaluate_law<L: ContactLaw>(&self, law: &L, d: f64, want_q: bool) -> Sums {
        match &self.heights {
            Heights::Gauss(h) => self.evaluate_with(law, h, d, want_q),
            Heights::General(h) => self.evaluate_with(law, &**h, d, want_q),
        }
    }

    #[inline(always)]
    fn evaluate_with<L: ContactLaw, H: Phi>(&self, law: &L, h: &H, d: f64, want_q: bool) -> Sums {
        let win = h.window(d);
        let mut c = self.contact(law, h, d, win, want_q);
        if self.adh_pref != 0.0 {
            let (j, dj) = self.noncontact(h, d);
            c.fs += j;
            c.dfs += dj;
        }
        Sums {
            p: self.load_pref * c.p,
            dp: self.load_pref * c.dp,
            fs: self.adh_pref * c.fs,
            dfs: self.adh_pref * c.dfs,
            q: self.load_pref * c.q,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Constants;
    use serde_json::Value;

    /// The fraction of summits above d* (the count of contacts' factor):
    /// for a general density, against a plain trapezoid of its pdf over
    /// the standardised heights above d*/s (200,000 steps): within 1e-3,
    /// ample for a warning at "fewer than 10".
    #[test]
    fn the_fraction_of_summits_in_contact_matches_the_density() {
        let p = Params::new(1.0, 0.001).distribution(crate::HeightDistribution::pearson(0.6, 4.0).unwrap());
        let surface = Surface::new(&p);
        let density = p.constants.distribution.density().unwrap();
        let s = sigma_s_ratio(p.constants.beta);
        let (_, hi) = density.support();
        for d in [-1.0, 0.0, 0.8, 2.0, 3.5] {
            let (a, b) = (d / s, hi.min(40.0));
            let n = 200_000;
            let h = (b - a) / n as f64;
            let mut sum = 0.5 * (density.pdf(a) + density.pdf(b));
            for k in 1..n {
                sum += density.pdf(a + k as f64 * h);
            }
            let want = sum * h;
            let got = surface.contact_fraction(d);
            assert!((got / want - 1.0).abs() < 1e-3, "d* = {d}: {got} vs {want}");
        }
    }

    impl Surface {
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
            let surface = Surface::new(&Params::new(f("psi"), 0.0).beta(f("beta")));
            let (b, d) = (f("b"), f("d_star"));
            let lower = surface.moment(d, b, 0.0, 1.0);
            let upper = surface.moment(d, b, 1.0, f64::INFINITY);
            let whole = surface.moment(d, b, 0.0, f64::INFINITY);
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

    /// The test-only Hertz law (x^1.5 at every interference, no plastic
    /// regime) through the same integrals: P* matches the closed form
    /// `(2/3)πβKω_c*·I^1.5[0,∞)` (MODEL.md §5), and, where every contact
    /// is elastic (ψ small), the Kogut–Etsion model; with a bounded Pearson
    /// density (K = 2.5) too: the general path, with the jumps.
    #[test]
    fn a_test_only_hertz_law_goes_through_the_same_integrals() {
        use crate::model::laws::hertz::Hertz;
        let doc: Value = serde_json::from_str(include_str!("../../../tests/data/reference_points.json")).unwrap();
        let p = doc["points"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["kind"] == "closed_form" && p["b"] == 1.5)
            .expect("a closed form for b = 1.5");
        let f = |k: &str| p[k].as_f64().unwrap();
        let surface = Surface::new(&Params::new(f("psi"), 0.0).beta(f("beta")));
        let s = surface.evaluate_law(&Hertz::new(), f("d_star"), true);
        let want = surface.load_pref * f("i_0_inf");
        assert!(s.p.is_finite() && s.p > 0.0 && s.dp < 0.0, "{s:?}");
        assert!(((s.p - want) / want).abs() < 1e-12, "P* = {:e} vs {want:e}", s.p);
        assert_eq!((s.fs, s.q), (0.0, 0.0));

        let gaussian = Constants::default();
        let pearson = Constants::default().distribution(crate::HeightDistribution::pearson(0.0, 2.5).unwrap());
        for c in [gaussian, pearson] {
            let params = c.at(0.1, 0.003).unwrap();
            let surface = Surface::new(&params);
            for d in [0.5, 1.0, 2.0] {
                let hertz = surface.evaluate_law(&Hertz::new(), d, true);
                let ke = surface.evaluate(d, true);
                assert!(hertz.p.is_finite() && hertz.p > 0.0, "{hertz:?}");
                for (what, a, b) in [
                    ("P*", hertz.p, ke.p),
                    ("dP*", hertz.dp, ke.dp),
                    ("Fs*", hertz.fs, ke.fs),
                    ("dFs*", hertz.dfs, ke.dfs),
                ] {
                    assert!(((a - b) / b).abs() < 1e-9, "d* = {d}: {what} {a:e} vs {b:e}");
                }
            }
        }
    }
}
