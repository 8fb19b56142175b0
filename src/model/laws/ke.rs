//! The Kogut–Etsion single-asperity law (Table 1 of the paper, corrected
//! per MODEL.md §6; MODEL.md §3–4): Hertz below x = 1, two elastic-plastic
//! power laws, fully plastic beyond x = 110; the friction rows
//! `0.52·x^0.982` (elastic) and `1.03·x^1.425·μ_ep(x)` (1st elastic-plastic).

use super::{jumps_of, ContactLaw, FrictionRow, Jump, LoadLaw, Regime};
use crate::model::asperity::{X_ELASTIC, X_EP1, X_PLASTIC};
use crate::model::integrator::{elastic_node, Integrator, Phi, Sums, Window};
use crate::params::{hardness_coefficient, Constants, Fit};
use crate::quadrature::Rule;

/// Root of [`mu_ep`]: a preloaded asperity beyond it carries no tangential
/// load (MODEL.md §6, item 2). 30-digit value from mpmath's `findroot`.
pub const X0: f64 = 4.294_625_761_688_717;

/// Contact load `P̄/P̄_c = a·x^b` per regime (MODEL.md §3).
pub mod load {
    /// Fully elastic: `x^1.5` (Hertz, every law's: [`HERTZ`](crate::model::asperity::HERTZ)).
    pub const ELASTIC: (f64, f64) = crate::model::asperity::HERTZ;
    /// 1st elastic-plastic: `1.03·x^1.425`.
    pub const EP1: (f64, f64) = (1.03, 1.425);
    /// 2nd elastic-plastic: `1.40·x^1.263`.
    pub const EP2: (f64, f64) = (1.40, 1.263);
}

/// Elastic friction row `Q̄_max/P̄_c = 0.52·x^0.982` (MODEL.md §3).
pub const FRICTION_ELASTIC: (f64, f64) = (0.52, 0.982);

/// Single-asperity static friction coefficient in the 1st elastic-plastic
/// regime, `μ_ep(x) = 0.85 − 0.40x + 0.09x² − 0.01x³` (Kogut & Etsion 2003;
/// MODEL.md §3).
#[inline]
pub fn mu_ep(x: f64) -> f64 {
    0.85 + x * (-0.40 + x * (0.09 - 0.01 * x))
}

/// The Gauss–Jacobi rule for `x^0.982` (the elastic friction row's first
/// panel), computed once per process.
fn friction_rule() -> &'static Rule {
    static RULE: std::sync::OnceLock<Rule> = std::sync::OnceLock::new();
    RULE.get_or_init(|| Rule::jacobi(FRICTION_ELASTIC.1))
}

/// The Kogut–Etsion law, planned for one set of constants.
#[derive(Debug, Clone)]
pub struct KogutEtsion {
    regimes: [Regime; 3],
    jumps: [Jump; 3],
    friction_rule: &'static Rule,
}

impl KogutEtsion {
    /// The law for `c.nu` (the fully plastic load 3/K) and `c.fit` (the
    /// 1st elastic-plastic friction row: `1.03`, clipped at x₀, or the
    /// printed `0.52`, unclipped up to x = 6).
    pub fn new(c: &Constants) -> KogutEtsion {
        let k = hardness_coefficient(c.nu);
        let (q_ep, to) = match c.fit {
            Fit::Consistent => (load::EP1.0, X0),
            Fit::AsPrinted => (FRICTION_ELASTIC.0, X_EP1),
        };
        let regimes = [
            Regime {
                xa: X_ELASTIC,
                xc: X_EP1,
                coef: load::EP1.0,
                load: LoadLaw::Power(load::EP1.1),
                adhesion: Some(1),
                friction: Some(FrictionRow { coef: q_ep, to }),
                split: Some(X0),
            },
            Regime::plain(X_EP1, X_PLASTIC, load::EP2.0, LoadLaw::Power(load::EP2.1), Some(2)),
            Regime::plain(X_PLASTIC, f64::INFINITY, 3.0 / k, LoadLaw::Linear, None),
        ];
        KogutEtsion {
            regimes,
            jumps: jumps_of(&regimes),
            friction_rule: friction_rule(),
        }
    }
}

impl ContactLaw for KogutEtsion {
    fn regimes(&self) -> &[Regime] {
        &self.regimes
    }

    fn jumps(&self) -> &[Jump] {
        &self.jumps
    }

    #[inline(always)]
    fn mu(&self, x: f64) -> f64 {
        mu_ep(x)
    }

    /// Hertz load, adhesion row 0 and the friction row `0.52·x^0.982`
    /// (Gauss–Jacobi with that weight on the first panel).
    fn elastic<H: Phi>(&self, s: &Integrator, h: &H, d: f64, win: Window, adh: bool, want_q: bool) -> Sums {
        let mut acc = Sums::default();
        let b_fric = FRICTION_ELASTIC.1;
        s.panels(h, d, win, 0.0, X_ELASTIC, |p| {
            if p.first {
                s.elastic_first_panel(h, d, p.x1, adh, &mut acc);
                if want_q {
                    s.jacobi_panel(h, d, self.friction_rule, b_fric, p.x1, |_, w, _| acc.q += w);
                }
            } else {
                s.legendre_panel(h, d, p, |x, w, dw| {
                    let lx = x.ln();
                    elastic_node::<H>(&mut acc, x, lx, w, dw, adh);
                    if want_q {
                        acc.q += (b_fric * lx).exp() * w;
                    }
                });
            }
        });
        acc.q *= FRICTION_ELASTIC.0;
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn x0_is_the_root_of_mu_ep() {
        assert!(mu_ep(X0).abs() < 1e-15);
        assert!(mu_ep(X0 - 1e-6) > 0.0 && mu_ep(X0 + 1e-6) < 0.0);
    }

    #[test]
    fn mu_ep_continues_the_elastic_coefficient() {
        // MODEL.md §6: 0.530 vs 0.52 at x = 1.
        assert!((mu_ep(1.0) - 0.53).abs() < 1e-12);
    }
}
