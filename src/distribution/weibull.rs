//! The Weibull family (MODEL.md §9): the standardised Weibull density of a
//! skewness.

use super::density::Density;
use super::shape::{End, Shape};
use super::{WEIBULL_SKEWNESS_MAX, WEIBULL_SKEWNESS_MIN};
use crate::special::ln_gamma;

impl Density {
    /// The standardised Weibull density with shape `k`; its standard
    /// deviation by quadrature (`Γ(1 + 2/k) − Γ(1 + 1/k)²` cancels for large k).
    fn weibull_of_shape(k: f64) -> Density {
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
            Density::plain(Shape::Weibull { k, mu, sd }, Some(lo), None, mode)
        };
        let rough = make(sd);
        let var = rough.integrate(|x| x * x) - rough.integrate(|x| x).powi(2);
        make(sd * var.sqrt())
    }

    /// The standardised Weibull density with skewness `sk`: k by a secant
    /// search on the skewness by quadrature, from the Γ-function estimate.
    pub(super) fn weibull(sk: f64) -> Density {
        let skew_of = |ln_k: f64| {
            let d = Density::weibull_of_shape(ln_k.exp());
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
            let d = HeightDistribution::weibull(sk).unwrap();
            let [m0, mean, var, s, kk] = d.density().unwrap().moments();
            eprintln!("weibull {sk}: {m0:.3e} {mean:.3e} {var:.3e} {s:.3e} {kk:.3e}");
            assert!((m0 - 1.0).abs() < 1e-12 && mean.abs() < 1e-11 && (var - 1.0).abs() < 1e-11);
            assert!((s - sk).abs() < 1e-10 && (kk - d.kurtosis()).abs() < 1e-10);
        }
    }
}
