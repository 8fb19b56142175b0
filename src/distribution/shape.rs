//! The forms a standardised density's logarithm takes ([`Shape`], one
//! variant per family or Pearson type) and the ends of its support
//! ([`End`]): what the families build and [`Density`](super::Density)
//! evaluates. A leaf of `distribution/`.

use super::empirical::Kde;
use crate::quadrature::Rule;
use std::sync::Arc;

/// The power tails of a density (types IV, VII): see [`Density::power_tails`](super::Density::power_tails).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PowerTails {
    /// The real part of the complex singularities.
    pub centre: f64,
    /// Their distance from the real axis.
    pub half_width: f64,
    /// `q` in `g ~ |x − centre|^−q` (> 5 for every admissible pair).
    pub exponent: f64,
}

/// A finite end of a density's support: `g(x) ~ |x − at|^power` next to it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct End {
    pub at: f64,
    pub power: f64,
    /// Widest panel the Gauss–Jacobi rule may take at this end (where the
    /// rest of the density is not analytic at the end: Weibull's `e^(−w^k)`).
    pub jacobi_width: f64,
}

/// An end with `power` below this gets a Gauss–Jacobi rule with that very
/// weight (the 12-point rules integrate `t^power·t^k`, k < 24, to 1e-13 up
/// to here). Above it, next to the normal point, graded panels from a tiny
/// first one: many more nodes (a type I/II end of power 3.5 cost 5× the
/// Gaussian's solve that way, against 1.6× with its rule).
pub(crate) const JACOBI_POWER_MAX: f64 = 64.0;

impl End {
    /// The Gauss–Jacobi rule with this end's weight `t^power`, if the end
    /// takes one (`power` < [`JACOBI_POWER_MAX`]).
    pub(crate) fn jacobi_rule(&self) -> Option<Rule> {
        (self.power < JACOBI_POWER_MAX).then(|| Rule::jacobi(self.power))
    }

    /// Whether a panel of `width` (standardised units) reaching this end
    /// takes its Gauss–Jacobi rule.
    pub(crate) fn takes_jacobi(&self, width: f64) -> bool {
        self.power < JACOBI_POWER_MAX && width <= self.jacobi_width
    }
}

#[derive(Debug, Clone)]
pub(crate) enum Shape {
    Normal,
    /// Types I, II, VI: `−c_a·ln(1 − x/r_a) − c_b·ln(1 − x/r_b)`, or
    /// where that cancels (roots close together, near type V) the same as
    /// `−e·ln(B(x)/B0) − f·G(x)` with `G = ∫₀^x dt/B(t)` ([`Stable`]).
    TwoRoots {
        ra: f64,
        rb: f64,
        ca: f64,
        cb: f64,
        stable: Option<Stable>,
    },
    /// Near the normal point every closed form cancels: `−∫₀^x (A1t +
    /// A0)/B(t) dt` by Gauss–Legendre (the roots of B are ≥ NEAR_NORMAL
    /// away, so the rule is exact to rounding).
    NearNormal,
    /// Type III: `c1·x + c2·ln(1 + x/e₀)` with the end at `−e₀`.
    Gamma {
        c1: f64,
        c2: f64,
        inv_e0: f64,
    },
    /// Type V: `cv1·ln(1 − x/r) + cv2·(1/(x − r) + 1/r)`.
    TypeV {
        r: f64,
        cv1: f64,
        cv2: f64,
    },
    /// Types IV, VII.
    Complex {
        b0: f64,
        b1: f64,
        b2: f64,
        w: f64,
        c4a: f64,
        c4b: f64,
    },
    Weibull {
        k: f64,
        mu: f64,
        sd: f64,
    },
    Kde(Arc<Kde>),
}

/// `ln g = −e·ln(B(x)/B0) − f·G(x)`, `G(x) = ln(1 + x·k/(B0·(1 − x/r_b)))/k`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Stable {
    pub(super) e: f64,
    pub(super) f: f64,
    pub(super) k: f64,
    pub(super) b: [f64; 3],
    pub(super) rb: f64,
}
