//! What a family's density supplies to [`Density`](super::Density): the
//! form its logarithm takes ([`Form`], one type per family) and the ends
//! of its support ([`End`]). A leaf of `distribution/`.

use crate::quadrature::Rule;

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

/// The logarithm of a family's standardised density, up to its
/// normalising constant: what [`Density`](super::Density) evaluates, one
/// type per family (the family's [`DistributionFamily::Form`](super::family::DistributionFamily::Form)),
/// dispatched without a dynamic call (`Shape`, written by `families!`).
pub(crate) trait Form {
    /// ln g(x) − ln_norm inside the support.
    fn ln(&self, x: f64) -> f64;

    /// g'(x)/g(x) inside the support.
    fn dln(&self, x: f64) -> f64;

    /// ln g(x) − ln_norm at distance `dist ≥ 0` inside the support from its
    /// finite end `end` (`upper`: the support's upper end), at `x` (`end.at
    /// ∓ dist`): from the distance itself where rounding `x` would lose it.
    fn ln_at_end(&self, end: End, upper: bool, dist: f64, x: f64) -> f64 {
        let _ = (end, upper, dist);
        self.ln(x)
    }

    /// Below the first and above the second, g only falls away from its
    /// mass (`mode`, for a unimodal density).
    fn tails(&self, mode: f64) -> (f64, f64) {
        (mode, mode)
    }

    /// The scale on which g may change shape without its log-slope
    /// showing it (unlimited unless said).
    fn smoothness_scale(&self) -> f64 {
        f64::INFINITY
    }

    /// The power tails of the density, if it has them.
    fn power_tails(&self) -> Option<PowerTails> {
        None
    }
}

/// A computation generic over a density's form, called with the form
/// itself ([`Density::visit_form`](super::Density::visit_form)): the model
/// dispatches on the family once per integral, not once per node.
pub(crate) trait FormVisitor {
    /// What the computation returns.
    type Out;
    /// The computation with the form `form`.
    fn visit<F: Form>(self, form: &F) -> Self::Out;
}
