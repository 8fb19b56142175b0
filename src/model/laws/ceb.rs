//! The CEB-type single-asperity law (MODEL.md §8): Hertz load with the
//! tangential capacity `μ_CEB(x)` of an elastic asperity below x = 1
//! (Eriten et al. 2010), the volume-conserving load `1.5(2x − 1)` above,
//! no friction beyond first yield; the Kogut–Etsion adhesion throughout.

use super::{jumps_of, ContactLaw, Jump, LoadLaw, Regime};
use crate::model::asperity::{X_ELASTIC, X_EP1, X_PLASTIC};
use crate::model::integrator::{elastic_node, EndSide, Integrator, Phi, Sums, Window};
use crate::params::Constants;

/// Depth of first yield on the axis, in contact radii (ν = 0.3).
const ZETA: f64 = 0.48;

/// The CEB-type tangential capacity `μ_CEB(x)` of an elastic asperity
/// (MODEL.md §8; Eriten et al. 2010 for ν = 0.3), split into its two
/// branches so that the surface integrals can treat each one's endpoint
/// behaviour exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CebCapacity {
    /// `0.2045/(K|c1|)`: `μ1 = a1·(1/x − 1)^½`.
    a1: f64,
    c3: f64,
    c4: f64,
    /// `c5 = c5_const − c5_inv/x`.
    c5_const: f64,
    c5_inv: f64,
    /// `μ2(x)·x^1.5 = m15·x^1.5 + x·(d1·x + d0)^½/(2c3)`, with
    /// `m15 = −c4/(2c3)`, `d1 = c4² − 4c3·c5_const`, `d0 = 4c3·c5_inv`.
    m15: f64,
    d1: f64,
    d0: f64,
    inv_2c3: f64,
    /// Where the branches cross: `μ2` below, `μ1` above.
    pub x_cross: f64,
}

impl CebCapacity {
    /// The capacity for Poisson's ratio `nu` (K = 0.454 + 0.41ν).
    pub fn new(nu: f64) -> CebCapacity {
        let k = crate::params::hardness_coefficient(nu);
        let c1 = -1.0 + 1.5 * ZETA * (1.0 / ZETA).atan() - ZETA * ZETA / (2.0 * (1.0 + ZETA * ZETA));
        let pi = core::f64::consts::PI;
        let c3 = (9.0 * pi * pi / 16.0) * (2.0 - nu / 2.0 + 7.0 * nu * nu / 8.0);
        let c4 = (9.0 * pi / 4.0) * (1.0 - 2.0 * nu) * (1.0 - nu / 2.0);
        let c5_const = 1.5 * (1.0 - 2.0 * nu) * (1.0 - 2.0 * nu);
        let c5_inv = 0.56 / (k * k);
        let inv_2c3 = 1.0 / (2.0 * c3);
        let mut cap = CebCapacity {
            a1: 0.2045 / (k * c1.abs()),
            c3,
            c4,
            c5_const,
            c5_inv,
            m15: -c4 * inv_2c3,
            d1: c4 * c4 - 4.0 * c3 * c5_const,
            d0: 4.0 * c3 * c5_inv,
            inv_2c3,
            x_cross: 1.0,
        };
        // μ1 − μ2 goes from + (μ1 > μ2 near 0) to − (μ1(1) = 0 < μ2(1)):
        // bisect to the last bit.
        let (mut lo, mut hi) = (1e-6, 1.0);
        while hi - lo > 1e-16 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if cap.mu1(mid) > cap.mu2(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        cap.x_cross = 0.5 * (lo + hi);
        cap
    }

    /// Surface-yield branch `μ1(x) = a1·(1/x − 1)^½`.
    pub fn mu1(&self, x: f64) -> f64 {
        self.a1 * (1.0 / x - 1.0).max(0.0).sqrt()
    }

    /// Axis-yield branch `μ2(x) = (−c4 + (c4² − 4c3c5)^½)/(2c3)`.
    pub fn mu2(&self, x: f64) -> f64 {
        let c5 = self.c5_const - self.c5_inv / x;
        (-self.c4 + (self.c4 * self.c4 - 4.0 * self.c3 * c5).sqrt()) / (2.0 * self.c3)
    }

    /// `μ_CEB(x) = min(μ1, μ2)` on `0 < x < 1`, else 0.
    pub fn mu(&self, x: f64) -> f64 {
        if x > 0.0 && x < 1.0 {
            self.mu1(x).min(self.mu2(x))
        } else {
            0.0
        }
    }

    /// `μ2(x)·x^1.5 = m15·x^1.5 + x·g(x)` with `g` analytic on [0, 1]:
    /// this is `m15`. The split leaves a Gauss–Jacobi rule only the
    /// `x^1.5` part to integrate, and an analytic remainder.
    pub fn mu2_power_coefficient(&self) -> f64 {
        self.m15
    }

    /// The analytic remainder `g(x)` of [`mu2_power_coefficient`](Self::mu2_power_coefficient).
    pub fn mu2_remainder(&self, x: f64) -> f64 {
        (self.d1 * x + self.d0).sqrt() * self.inv_2c3
    }

    /// `μ1(x)·x^1.5 = a1·x·(1 − x)^½`: returns `a1·x`, the analytic factor
    /// in front of the `(1 − x)^½` endpoint behaviour at `x = 1`.
    pub fn mu1_factor(&self, x: f64) -> f64 {
        self.a1 * x
    }
}

/// The volume-conserving load `1.5(2x − 1)` above first yield.
const VOLUME: LoadLaw = LoadLaw::Affine(1.5, 2.0, -1.0);

/// The regimes above x = 1: one load law, the adhesion rows of the
/// Kogut–Etsion regimes, no friction.
const REGIMES: [Regime; 3] = [
    Regime::plain(X_ELASTIC, X_EP1, 1.0, VOLUME, Some(1)),
    Regime::plain(X_EP1, X_PLASTIC, 1.0, VOLUME, Some(2)),
    Regime::plain(X_PLASTIC, f64::INFINITY, 1.0, VOLUME, None),
];

/// The CEB-type law, planned for one Poisson's ratio.
#[derive(Debug, Clone)]
pub struct CebType {
    cap: CebCapacity,
    jumps: [Jump; 3],
}

impl CebType {
    /// The law for `c.nu` (the [`Fit`](crate::Fit) does not apply).
    pub fn new(c: &Constants) -> CebType {
        CebType {
            cap: CebCapacity::new(c.nu),
            jumps: jumps_of(&REGIMES),
        }
    }
}

impl ContactLaw for CebType {
    fn regimes(&self) -> &[Regime] {
        &REGIMES
    }

    fn jumps(&self) -> &[Jump] {
        &self.jumps
    }

    /// The elastic regime: `Q̄ = μ_CEB·P̄`, with the branch `μ2` below the
    /// crossing `xc` and `μ1` (which vanishes like `(1 − x)^½` at x = 1)
    /// above it.
    fn elastic<H: Phi>(&self, s: &Integrator, h: &H, d: f64, win: Window, adh: bool, want_q: bool) -> Sums {
        let ceb = &self.cap;
        let xc = ceb.x_cross;
        let mut acc = Sums::default();
        let m15 = ceb.mu2_power_coefficient();
        s.panels(h, d, win, 0.0, xc, |p| {
            if p.first {
                s.elastic_first_panel(h, d, p.x1, adh, &mut acc);
                if want_q {
                    // acc.p is so far just ∫₀^x1 x^1.5 φ*, the first panel's load.
                    acc.q += m15 * acc.p;
                    s.legendre_panel(h, d, p, |x, w, _| acc.q += x * ceb.mu2_remainder(x) * w);
                }
            } else {
                s.legendre_panel(h, d, p, |x, w, dw| {
                    let load = elastic_node::<H>(&mut acc, x, x.ln(), w, dw, adh);
                    if want_q {
                        acc.q += (m15 * load + x * ceb.mu2_remainder(x)) * w;
                    }
                });
            }
        });
        s.panels(h, d, win, xc, X_ELASTIC, |p| {
            let last = p.last && p.at_end == EndSide::None;
            s.legendre_panel(h, d, p, |x, w, dw| {
                elastic_node::<H>(&mut acc, x, x.ln(), w, dw, adh);
                if want_q && !last {
                    acc.q += ceb.mu1_factor(x) * (1.0 - x).sqrt() * w;
                }
            });
            if want_q && last {
                // (1 − x)^½ at x = 1: the mirrored Gauss–Jacobi rule.
                let width = X_ELASTIC - p.x0;
                let scale = s.omega * width.powf(1.5);
                for (t, wt) in s.rules.gj_half.t.iter().zip(&s.rules.gj_half.w) {
                    let x = X_ELASTIC - width * t;
                    acc.q += scale * wt * h.phi(d + s.omega * x) * ceb.mu1_factor(x);
                }
            }
        });
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ceb_capacity_matches_model_md_section_8() {
        // MODEL.md §8: μ_CEB = 1.1372 at x = 0.1, 0.43946 at 0.5, 0.28193 at 0.951;
        // branches cross at 0.951169.
        let cap = CebCapacity::new(0.3);
        assert!((cap.mu(0.1) - 1.1372).abs() < 5e-5);
        assert!((cap.mu(0.5) - 0.43946).abs() < 5e-6);
        assert!((cap.mu(0.951) - 0.28193).abs() < 5e-6);
        assert!((cap.x_cross - 0.951169).abs() < 5e-7);
        for x in [0.05, 0.3, 0.9, 0.96, 0.999] {
            let (m15, g) = (cap.mu2_power_coefficient(), cap.mu2_remainder(x));
            let direct = cap.mu2(x) * x.powf(1.5);
            assert!((m15 * x.powf(1.5) + x * g - direct).abs() < 1e-13 * direct.abs().max(1.0));
            let d1 = cap.mu1(x) * x.powf(1.5);
            assert!((cap.mu1_factor(x) * (1.0 - x).sqrt() - d1).abs() < 1e-14);
        }
    }
}
