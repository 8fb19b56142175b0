//! The Weibull family (MODEL.md §9): the standardised Weibull density of a
//! skewness.

use super::density::Density;
use super::family::{DistributionFamily, Parameters};
use super::shape::{End, Form};
use super::{DistributionError, Shape};
use crate::bound::{self, Bound};
use crate::checks::{check_in, ParamError};
use crate::num::Shortest;
use crate::special::ln_gamma;

/// Bounds of the Weibull skewness (MODEL.md §9): Sk in (WEIBULL_SKEWNESS_MIN, WEIBULL_SKEWNESS_MAX].
pub const WEIBULL_SKEWNESS_MIN: f64 = -1.1395;
/// Upper bound of the Weibull skewness.
pub const WEIBULL_SKEWNESS_MAX: f64 = 2.0;

/// The Weibull family's skewness: (WEIBULL_SKEWNESS_MIN, WEIBULL_SKEWNESS_MAX].
pub static WEIBULL_SKEWNESS: Bound =
    Bound::new(bound::End::Open(WEIBULL_SKEWNESS_MIN), bound::End::Closed(WEIBULL_SKEWNESS_MAX))
        .unit("(the Weibull family)");

/// A standardised Weibull distribution with skewness Sk in (−1.1395, 2]
/// ([`HeightDistribution::Weibull`](super::HeightDistribution::Weibull));
/// its kurtosis follows from Sk (2.717 at Sk = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weibull {
    /// Skewness Sk.
    pub skewness: f64,
}

impl Parameters for Weibull {
    fn validate(&self) -> Result<(), ParamError> {
        check_in("skewness", self.skewness, &WEIBULL_SKEWNESS)
    }

    fn skewness(&self) -> f64 {
        self.skewness
    }

    /// The kurtosis its skewness implies.
    fn kurtosis(&self) -> f64 {
        match self.validate() {
            Ok(()) => self.density().moments()[4],
            Err(_) => f64::NAN,
        }
    }

    /// The skewness, and 0 for the kurtosis (which follows from it).
    fn stored(&self) -> Option<[f64; 2]> {
        Some([self.skewness, 0.0])
    }

    /// k by a secant search on the skewness by quadrature, from the
    /// Γ-function estimate.
    fn density(&self) -> Density {
        let sk = self.skewness;
        if sk == WEIBULL_SKEWNESS_MAX {
            // k = 1 exactly: the exponential, whose skewness is 2 (a
            // search could land on k a rounding below 1, where the
            // density's end would be a pole).
            return of_shape(1.0);
        }
        let skew_of = |ln_k: f64| {
            let d = of_shape(ln_k.exp());
            (d.integrate(|x| x * x * x), d)
        };
        let mut a = weibull_shape(sk).unwrap_or(f64::NAN).ln();
        let (mut fa, mut best) = skew_of(a);
        let mut b = a + 1e-3;
        for _ in 0..30 {
            let (fb, d) = skew_of(b);
            best = d;
            if fb == sk || fb == fa {
                break;
            }
            let next = b - (fb - sk) * (b - a) / (fb - fa);
            (a, fa) = (b, fb);
            b = next;
            if (b - a).abs() <= 1e-15 * b.abs().max(1.0) {
                best = skew_of(b).1;
                break;
            }
        }
        best
    }
}

impl DistributionFamily for Weibull {
    type Form = WeibullForm;

    /// The skewness (0 if left out); a kurtosis only if it is the one the
    /// skewness implies.
    fn from_arguments(
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        _: Option<&[f64]>,
    ) -> Result<Weibull, DistributionError> {
        let d = Weibull {
            skewness: skewness.unwrap_or(0.0),
        };
        d.validate()?;
        if let Some(k) = kurtosis {
            let implied = d.kurtosis();
            if k != implied {
                return Err(DistributionError::Conflict {
                    name: "kurtosis",
                    reason: format!(
                        "= {}: not with weibull, whose kurtosis follows from the skewness ({})",
                        Shortest(k),
                        Shortest(implied)
                    ),
                });
            }
        }
        Ok(d)
    }

    /// The Weibull density of the skewness (its kurtosis follows).
    fn from_moments(skewness: f64, _: f64) -> Option<Result<Weibull, ParamError>> {
        let d = Weibull { skewness };
        Some(d.validate().map(|()| d))
    }

    fn from_stored(skewness: f64, _: f64) -> Option<Weibull> {
        Some(Weibull { skewness })
    }
}

/// `ln(sd·k) + (k − 1)·ln w − w^k` with `w = mu + sd·x`: Weibull(k)
/// standardised.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WeibullForm {
    k: f64,
    mu: f64,
    sd: f64,
}

impl Form for WeibullForm {
    #[inline]
    fn ln(&self, x: f64) -> f64 {
        let Self { k, mu, sd } = *self;
        let w = mu + sd * x;
        (sd * k).ln() + power_ln(k, w) - w.powf(k)
    }

    #[inline]
    fn dln(&self, x: f64) -> f64 {
        let Self { k, mu, sd } = *self;
        let w = mu + sd * x;
        let pole = if k == 1.0 { 0.0 } else { (k - 1.0) / w };
        sd * (pole - k * w.powf(k - 1.0))
    }

    fn ln_at_end(&self, _: End, _: bool, dist: f64, _: f64) -> f64 {
        let Self { k, sd, .. } = *self;
        let w = sd * dist;
        (sd * k).ln() + power_ln(k, w) - w.powf(k)
    }
}

/// (k − 1)·ln w, 0 for k = 1 (Sk = 2, the exponential: w⁰ = 1 at w = 0
/// too, where 0·ln 0 would be NaN).
#[inline]
fn power_ln(k: f64, w: f64) -> f64 {
    if k == 1.0 {
        0.0
    } else {
        (k - 1.0) * w.ln()
    }
}

/// The standardised Weibull density with shape `k`; its standard
/// deviation by quadrature (`Γ(1 + 2/k) − Γ(1 + 1/k)²` cancels for large k).
fn of_shape(k: f64) -> Density {
    let (mu, sd) = weibull_mean_sd(k);
    let make = |sd: f64| {
        let at = -mu / sd;
        let mode = if k > 1.0 {
            (((k - 1.0) / k).powf(1.0 / k) - mu) / sd
        } else {
            at
        };
        let lo = End {
            at,
            power: k - 1.0,
            jacobi_width: 1e-6f64.powf(1.0 / k) / sd,
        };
        Density::plain(Shape::Weibull(WeibullForm { k, mu, sd }), Some(lo), None, mode)
    };
    let rough = make(sd);
    let var = rough.integrate(|x| x * x) - rough.integrate(|x| x).powi(2);
    make(sd * var.sqrt())
}

fn weibull_mean_sd(k: f64) -> (f64, f64) {
    let g1 = ln_gamma(1.0 + 1.0 / k).exp();
    let g2 = ln_gamma(1.0 + 2.0 / k).exp();
    (g1, (g2 - g1 * g1).sqrt())
}

/// Skewness and kurtosis of Weibull(k).
fn weibull_moments(k: f64) -> (f64, f64) {
    let g = |j: f64| ln_gamma(1.0 + j / k).exp();
    let (g1, g2, g3, g4) = (g(1.0), g(2.0), g(3.0), g(4.0));
    let v = g2 - g1 * g1;
    let sk = (g3 - 3.0 * g1 * v - g1.powi(3)) / v.powf(1.5);
    let kurt = (g4 - 4.0 * g1 * g3 + 6.0 * g1 * g1 * g2 - 3.0 * g1.powi(4)) / (v * v);
    (sk, kurt)
}

/// The Weibull shape k with skewness `sk` (decreasing in k), by bisection
/// in ln k; `None` outside (−1.1395, 2].
pub(crate) fn weibull_shape(sk: f64) -> Option<f64> {
    if !(sk > WEIBULL_SKEWNESS_MIN && sk <= WEIBULL_SKEWNESS_MAX) {
        return None;
    }
    if sk == WEIBULL_SKEWNESS_MAX {
        // The exponential.
        return Some(1.0);
    }
    let (mut lo, mut hi) = (0.5f64.ln(), 1000f64.ln());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if weibull_moments(mid.exp()).0 > sk {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 4.0 * f64::EPSILON {
            break;
        }
    }
    Some((0.5 * (lo + hi)).exp())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distribution::HeightDistribution;

    #[test]
    fn weibull_shape_at_zero_skewness() {
        let k = weibull_shape(0.0).unwrap();
        assert!((k - 3.602_349_425_7).abs() < 1e-9, "{k}");
        assert!(weibull_shape(-1.2).is_none() && weibull_shape(2.1).is_none());
    }

    /// Weibull: ∫g = 1, mean 0, variance 1, the stated Sk and the implied K.
    #[test]
    fn densities_have_their_moments() {
        for sk in [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0] {
            // The variant, not `HeightDistribution::weibull`: the file stays a
            // template a new family copies under its own name (tools/scaffold_check.sh).
            let d = HeightDistribution::Weibull(Weibull { skewness: sk });
            d.validate().unwrap();
            let [m0, mean, var, s, kk] = d.density().unwrap().moments();
            eprintln!("weibull {sk}: {m0:.3e} {mean:.3e} {var:.3e} {s:.3e} {kk:.3e}");
            assert!((m0 - 1.0).abs() < 1e-12 && mean.abs() < 1e-11 && (var - 1.0).abs() < 1e-11);
            assert!((s - sk).abs() < 1e-10 && (kk - d.kurtosis()).abs() < 1e-10);
        }
    }
}
