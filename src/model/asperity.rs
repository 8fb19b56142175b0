//! Single-asperity laws (Table 1 of the paper, corrected per MODEL.md §6),
//! and the CEB-type tangential capacity of MODEL.md §8.
//!
//! `x = ω/ω_c` is an asperity's interference over the critical interference.

/// Upper end of the fully elastic regime.
pub const X_ELASTIC: f64 = 1.0;
/// Upper end of the 1st elastic-plastic regime.
pub const X_EP1: f64 = 6.0;
/// Start of the fully plastic regime.
pub const X_PLASTIC: f64 = 110.0;

/// Root of [`mu_ep`]: a preloaded asperity beyond it carries no tangential
/// load (MODEL.md §6, item 2). 30-digit value from mpmath's `findroot`.
pub const X0: f64 = 4.294_625_761_688_717;

/// Contact load `P̄/P̄_c = a·x^b` per regime (MODEL.md §3).
pub mod load {
    /// Fully elastic: `x^1.5`.
    pub const ELASTIC: (f64, f64) = (1.0, 1.5);
    /// 1st elastic-plastic: `1.03·x^1.425`.
    pub const EP1: (f64, f64) = (1.03, 1.425);
    /// 2nd elastic-plastic: `1.40·x^1.263`.
    pub const EP2: (f64, f64) = (1.40, 1.263);
}

/// Adhesion of a contacting asperity, `F̄_s/F̄_s0 = a·x^b·r^c` (MODEL.md §3).
pub mod adhesion {
    /// Fully elastic: `0.98·x^0.298·r^−0.29`.
    pub const ELASTIC: (f64, f64, f64) = (0.98, 0.298, -0.29);
    /// 1st elastic-plastic: `0.79·x^0.356·r^−0.321`.
    pub const EP1: (f64, f64, f64) = (0.79, 0.356, -0.321);
    /// 2nd elastic-plastic: `1.19·x^0.093·r^−0.332`.
    pub const EP2: (f64, f64, f64) = (1.19, 0.093, -0.332);
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

/// Adhesion of a non-contacting asperity, `F̄_s/F̄_s0 = (4/3)(u^−2 − ¼u^−8)`
/// with `u` the gap over ε plus one (MODEL.md §3).
#[inline]
pub fn adhesion_noncontact(u: f64) -> f64 {
    let u2 = 1.0 / (u * u);
    let u8 = (u2 * u2) * (u2 * u2);
    (4.0 / 3.0) * (u2 - 0.25 * u8)
}

/// d/du of [`adhesion_noncontact`]: `(4/3)(−2u^−3 + 2u^−9)`.
#[inline]
pub fn adhesion_noncontact_slope(u: f64) -> f64 {
    let u3 = 1.0 / (u * u * u);
    (8.0 / 3.0) * (u3 * u3 * u3 - u3)
}

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
