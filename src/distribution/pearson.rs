//! The Pearson system (MODEL.md §9): the density of a skewness and
//! kurtosis, by type.

use super::density::Density;
use super::family::{DistributionFamily, Parameters};
use super::gaussian::Gaussian;
use super::shape::{End, Form, PowerTails};
use super::{DistributionError, Shape};
use crate::bound::{Bound, End as Limit};
use crate::checks::{check, check_in, ParamError};
use crate::quadrature::{Rule, NODES};
use crate::special::atan2;

/// Kurtosis accepted by the Pearson family, at most (beyond it the tails
/// are too heavy for the model's integrals to be meaningful).
pub const PEARSON_KURTOSIS_MAX: f64 = 100.0;
/// |Skewness| accepted by the Pearson family, at most.
pub const PEARSON_SKEWNESS_MAX: f64 = 5.0;
/// The Pearson family's skewness: [-5, 5].
pub static PEARSON_SKEWNESS: Bound = Bound::new(Limit::Closed(-PEARSON_SKEWNESS_MAX), Limit::Closed(PEARSON_SKEWNESS_MAX));
/// The Pearson family's kurtosis: at most 100 (and above Sk² + 1).
pub static PEARSON_KURTOSIS: Bound = Bound::at_most(PEARSON_KURTOSIS_MAX).unit("(not excess: 3 for a Gaussian)");

/// The Pearson system from skewness Sk and kurtosis K (not excess: 3 for
/// a Gaussian), admissible where K > Sk² + 1
/// ([`HeightDistribution::Pearson`](super::HeightDistribution::Pearson)).
/// Pearson(0, 3) is the Gaussian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pearson {
    /// Skewness Sk (ISO 25178 Ssk).
    pub skewness: f64,
    /// Kurtosis K, not excess (ISO 25178 Sku).
    pub kurtosis: f64,
}

impl Parameters for Pearson {
    fn validate(&self) -> Result<(), ParamError> {
        let Pearson { skewness, kurtosis } = *self;
        check_in("skewness", skewness, &PEARSON_SKEWNESS)?;
        check_in("kurtosis", kurtosis, &PEARSON_KURTOSIS)?;
        check(
            "kurtosis",
            kurtosis,
            "> skewness² + 1 (the Pearson bound; kurtosis is not excess: 3 for a Gaussian)",
            |v| v > skewness * skewness + 1.0,
        )
    }

    fn skewness(&self) -> f64 {
        self.skewness
    }

    fn kurtosis(&self) -> f64 {
        self.kurtosis
    }

    /// Pearson(0, 3) exactly.
    fn is_gaussian(&self) -> bool {
        self.skewness == 0.0 && self.kurtosis == 3.0
    }

    fn stored(&self) -> Option<[f64; 2]> {
        Some([self.skewness, self.kurtosis])
    }

    /// The Gaussian's for Pearson(0, 3); else the fit, normalised by
    /// quadrature.
    fn density(&self) -> Density {
        if self.is_gaussian() {
            return Gaussian.density();
        }
        let p = fit(self.skewness, self.kurtosis);
        let form = PearsonForm {
            coeffs: p.coeffs,
            ty: p.ty,
            shape: p.shape,
        };
        let mut d = Density::plain(Shape::Pearson(form), p.lo, p.hi, p.mode);
        d.ln_norm = -d.integrate(|_| 1.0).ln();
        d
    }
}

impl DistributionFamily for Pearson {
    type Form = PearsonForm;

    /// Skewness and kurtosis, 0 and 3 where left out.
    fn from_arguments(
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        _: Option<&[f64]>,
    ) -> Result<Pearson, DistributionError> {
        let d = Pearson {
            skewness: skewness.unwrap_or(0.0),
            kurtosis: kurtosis.unwrap_or(3.0),
        };
        d.validate()?;
        Ok(d)
    }

    /// The Pearson density of both moments.
    fn from_moments(skewness: f64, kurtosis: f64) -> Option<Result<Pearson, ParamError>> {
        let d = Pearson { skewness, kurtosis };
        Some(d.validate().map(|()| d))
    }

    fn from_stored(skewness: f64, kurtosis: f64) -> Option<Pearson> {
        Some(Pearson { skewness, kurtosis })
    }
}

impl Density {
    /// The Pearson type, for a Pearson density (the Gaussian is
    /// [`PearsonType::Normal`]).
    pub fn pearson_type(&self) -> Option<PearsonType> {
        match &self.shape {
            Shape::Gaussian(_) => Some(PearsonType::Normal),
            Shape::Pearson(p) => Some(p.ty),
            _ => None,
        }
    }
}

/// The type of a Pearson density (MODEL.md §9).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PearsonType {
    /// The normal distribution (Sk = 0, K = 3).
    Normal,
    /// Beta: bounded support (B2 < 0, Sk ≠ 0).
    I,
    /// Symmetric beta (B2 < 0, Sk = 0).
    II,
    /// Gamma: a half-line (B2 = 0).
    III,
    /// Unbounded, skewed (B2 > 0, D < 0).
    IV,
    /// Inverse gamma: a half-line (B2 > 0, D = 0).
    V,
    /// Beta prime: a half-line (B2 > 0, D > 0).
    VI,
    /// Student's t (B2 > 0, Sk = 0).
    VII,
}

impl PearsonType {
    /// The type's name: `"0"` (normal), `"I"`, …, `"VII"`.
    pub fn name(self) -> &'static str {
        match self {
            PearsonType::Normal => "0",
            PearsonType::I => "I",
            PearsonType::II => "II",
            PearsonType::III => "III",
            PearsonType::IV => "IV",
            PearsonType::V => "V",
            PearsonType::VI => "VI",
            PearsonType::VII => "VII",
        }
    }
}

/// Roots of B(x) at least this far from 0 make a Pearson density "near
/// normal" ([`PearsonShape::NearNormal`]).
const NEAR_NORMAL: f64 = 1000.0;

/// A Pearson density's form: its coefficients, type and the closed form
/// of its logarithm.
#[derive(Debug, Clone)]
pub(crate) struct PearsonForm {
    /// `(A1, A0, B0, B1, B2)`: `g'/g = −(A1·x + A0)/(B0 + B1·x + B2·x²)`.
    coeffs: [f64; 5],
    ty: PearsonType,
    shape: PearsonShape,
}

/// The closed forms of a Pearson density's logarithm, by type.
#[derive(Debug, Clone)]
enum PearsonShape {
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
    Gamma { c1: f64, c2: f64, inv_e0: f64 },
    /// Type V: `cv1·ln(1 − x/r) + cv2·(1/(x − r) + 1/r)`.
    TypeV { r: f64, cv1: f64, cv2: f64 },
    /// Types IV, VII.
    Complex {
        b0: f64,
        b1: f64,
        b2: f64,
        w: f64,
        c4a: f64,
        c4b: f64,
    },
}

/// `ln g = −e·ln(B(x)/B0) − f·G(x)`, `G(x) = ln(1 + x·k/(B0·(1 − x/r_b)))/k`.
#[derive(Debug, Clone, Copy)]
struct Stable {
    e: f64,
    f: f64,
    k: f64,
    b: [f64; 3],
    rb: f64,
}

impl Form for PearsonForm {
    #[inline(always)]
    fn ln(&self, x: f64) -> f64 {
        match &self.shape {
            PearsonShape::TwoRoots { stable: Some(st), .. } => {
                let [b0, b1, b2] = st.b;
                let g = (x * st.k / (b0 * (1.0 - x / st.rb))).ln_1p() / st.k;
                -st.e * ((b1 * x + b2 * x * x) / b0).ln_1p() - st.f * g
            }
            PearsonShape::TwoRoots { ra, rb, ca, cb, .. } => -ca * (-x / ra).ln_1p() - cb * (-x / rb).ln_1p(),
            PearsonShape::NearNormal => near_normal_ln(self.coeffs, x),
            PearsonShape::Gamma { c1, c2, inv_e0 } => c1 * x + c2 * (x * inv_e0).ln_1p(),
            PearsonShape::TypeV { r, cv1, cv2 } => cv1 * (-x / r).ln_1p() + cv2 * (1.0 / (x - r) + 1.0 / r),
            PearsonShape::Complex {
                b0,
                b1,
                b2,
                w,
                c4a,
                c4b,
            } => {
                // ln(1 + u), not ln_1p(u): the density is exp of this, so
                // only its absolute error matters (≤ 2^-53, the rounding
                // of 1 + u), and ln costs a third of ln_1p.
                let ln = c4a * (1.0 + (b1 * x + b2 * x * x) / b0).ln();
                if *c4b == 0.0 {
                    // Type VII (Sk = 0): no arctangent term; a third of
                    // the work per node.
                    return ln;
                }
                // atan2(2B2x/w, 1 + uv) with both arguments times w²: no
                // cancellation when w is small (near type V).
                let y = 2.0 * b2 * x * w;
                let xx = w * w + (2.0 * b2 * x + b1) * b1;
                ln + c4b * atan2(y, xx)
            }
        }
    }

    #[inline]
    fn dln(&self, x: f64) -> f64 {
        let [a1, a0, b0, b1, b2] = self.coeffs;
        -(a1 * x + a0) / (b0 + x * (b1 + x * b2))
    }

    fn ln_at_end(&self, e: End, upper: bool, dist: f64, x: f64) -> f64 {
        match self.shape {
            PearsonShape::TwoRoots { ra, rb, ca, cb, .. } => {
                let term = |r: f64, c: f64| {
                    if r == e.at {
                        -c * (dist / r.abs()).ln()
                    } else {
                        -c * (-x / r).ln_1p()
                    }
                };
                term(ra, ca) + term(rb, cb)
            }
            PearsonShape::Gamma { c1, c2, inv_e0 } => c1 * x + c2 * (dist * inv_e0.abs()).ln(),
            PearsonShape::TypeV { r, cv1, cv2 } => {
                let xr = if upper { -dist } else { dist };
                cv1 * (dist / r.abs()).ln() + cv2 * (1.0 / xr + 1.0 / r)
            }
            _ => self.ln(x),
        }
    }

    /// Types IV and VII: `g ~ |x − centre|^−exponent` on both sides, with g
    /// analytic in `1/(x − centre)` out to infinity (its only
    /// singularities are the complex roots of B(x), `centre ± i·half_width`).
    fn power_tails(&self) -> Option<PowerTails> {
        match self.shape {
            PearsonShape::Complex { b1, b2, w, c4a, .. } => Some(PowerTails {
                centre: -b1 / (2.0 * b2),
                half_width: w / (2.0 * b2.abs()),
                exponent: -2.0 * c4a,
            }),
            _ => None,
        }
    }
}

/// `−∫₀^x (A1t + A0)/B(t) dt` by Gauss–Legendre ([`PearsonShape::NearNormal`]);
/// out of line: its twelve nodes would make every other form's call
/// spill registers.
#[inline(never)]
fn near_normal_ln([a1, a0, b0, b1, b2]: [f64; 5], x: f64) -> f64 {
    let r = Rule::shared_legendre();
    -x * (0..NODES)
        .map(|i| {
            let t = x * r.t[i];
            r.w[i] * (a1 * t + a0) / (b0 + t * (b1 + t * b2))
        })
        .sum::<f64>()
}

/// A Pearson density's parts.
struct Fitted {
    /// `(A1, A0, B0, B1, B2)`.
    coeffs: [f64; 5],
    ty: PearsonType,
    shape: PearsonShape,
    lo: Option<End>,
    hi: Option<End>,
    mode: f64,
}

/// The standardised Pearson density with skewness `sk` and kurtosis `k`
/// (validated): its type, shape, ends and mode (MODEL.md §9).
fn fit(sk: f64, k: f64) -> Fitted {
    let s2 = sk * sk;
    let a1 = 10.0 * k - 12.0 * s2 - 18.0;
    let a0 = sk * (k + 3.0);
    let (b0, b1, b2) = (4.0 * k - 3.0 * s2, a0, 2.0 * k - 3.0 * s2 - 6.0);
    let disc = b1 * b1 - 4.0 * b0 * b2;
    let tiny = 8.0 * f64::EPSILON;
    let (ty, shape, lo, hi) = if b2.abs() <= tiny * b0 {
        // Gamma: B(x) = B0 + B1·x, the end at −B0/B1.
        let c1 = -a1 / b1;
        let c2 = -(a0 - a1 * b0 / b1) / b1;
        let e = End {
            at: -b0 / b1,
            power: c2,
            jacobi_width: f64::INFINITY,
        };
        let (lo, hi) = if b1 > 0.0 { (Some(e), None) } else { (None, Some(e)) };
        let shape = PearsonShape::Gamma {
            c1,
            c2,
            inv_e0: b1 / b0,
        };
        (PearsonType::III, shape, lo, hi)
    } else if b2 < 0.0 || disc > tiny * b0 * b0 {
        let sq = disc.sqrt();
        let q = if b1 != 0.0 {
            -(b1 + sq.copysign(b1)) / 2.0
        } else {
            -sq / 2.0
        };
        let (ra, rb) = (q / b2, b0 / q);
        let ca = (a1 * ra + a0) / (b2 * (ra - rb));
        let cb = (a1 * rb + a0) / (b2 * (rb - ra));
        let end = |r: f64, c: f64| End {
            at: r,
            power: -c,
            jacobi_width: f64::INFINITY,
        };
        // Condition of the two closed forms: the size of their terms
        // per unit x; the stable form where the roots nearly coincide.
        let k = sq * (sq + b1.abs()) / (2.0 * q);
        let (e, f) = (a1 / (2.0 * b2), a0 - a1 * b1 / (2.0 * b2));
        let plain = (ca / ra).abs() + (cb / rb).abs();
        let alt = (e.abs() * (b1.abs() + b2.abs()) + f.abs()) / b0;
        let stable = (alt < plain).then_some(Stable {
            e,
            f,
            k,
            b: [b0, b1, b2],
            rb,
        });
        let shape = PearsonShape::TwoRoots { ra, rb, ca, cb, stable };
        if b2 < 0.0 {
            let (lo, hi) = if ra < rb {
                (end(ra, ca), end(rb, cb))
            } else {
                (end(rb, cb), end(ra, ca))
            };
            let ty = if sk == 0.0 { PearsonType::II } else { PearsonType::I };
            (ty, shape, Some(lo), Some(hi))
        } else {
            // Both roots on one side of 0: the nearer one ends the support.
            let (near, c) = if ra.abs() < rb.abs() { (ra, ca) } else { (rb, cb) };
            let e = end(near, c);
            let (lo, hi) = if near < 0.0 { (Some(e), None) } else { (None, Some(e)) };
            (PearsonType::VI, shape, lo, hi)
        }
    } else if disc.abs() <= tiny * b0 * b0 {
        let r = -b1 / (2.0 * b2);
        let e = End {
            at: r,
            power: f64::INFINITY,
            jacobi_width: f64::INFINITY,
        };
        let (lo, hi) = if r < 0.0 { (Some(e), None) } else { (None, Some(e)) };
        let shape = PearsonShape::TypeV {
            r,
            cv1: -a1 / b2,
            cv2: (a1 * r + a0) / b2,
        };
        (PearsonType::V, shape, lo, hi)
    } else {
        let w = (-disc).sqrt();
        let shape = PearsonShape::Complex {
            b0,
            b1,
            b2,
            w,
            c4a: -a1 / (2.0 * b2),
            c4b: -(a0 - a1 * b1 / (2.0 * b2)) * 2.0 / w,
        };
        let ty = if sk == 0.0 { PearsonType::VII } else { PearsonType::IV };
        (ty, shape, None, None)
    };
    // Near the normal point: every root of B far away.
    let nearest = match (b2.abs() <= tiny * b0, disc < 0.0) {
        (true, _) => (b0 / b1).abs(),
        (false, true) => (b0 / b2).abs().sqrt(),
        (false, false) => {
            let q = if b1 != 0.0 {
                -(b1 + disc.sqrt().copysign(b1)) / 2.0
            } else {
                -disc.sqrt() / 2.0
            };
            (q / b2).abs().min((b0 / q).abs())
        }
    };
    let shape = if nearest >= NEAR_NORMAL {
        PearsonShape::NearNormal
    } else {
        shape
    };
    // The mode: where A1·x + A0 = 0, or the end where g is unbounded.
    let stationary = -a0 / a1;
    let inside = |x: f64| lo.is_none_or(|e| x > e.at) && hi.is_none_or(|e| x < e.at);
    let mode = if a1 > 0.0 && inside(stationary) {
        stationary
    } else {
        [lo, hi]
            .into_iter()
            .flatten()
            .filter(|e| e.power < 0.0)
            .min_by(|a, b| a.power.total_cmp(&b.power))
            .map_or(0.0, |e| e.at)
    };
    Fitted {
        coeffs: [a1, a0, b0, b1, b2],
        ty,
        shape,
        lo,
        hi,
        mode,
    }
}

#[cfg(test)]
mod tests {
    use crate::distribution::HeightDistribution;

    /// Every Pearson type: ∫g = 1, mean 0, variance 1 and the stated Sk, K.
    #[test]
    fn densities_have_their_moments() {
        let cases: &[(f64, f64)] = &[
            (0.0, 3.0),
            (0.3, 3.2),
            (0.0, 2.0),
            (0.0, 1.5),
            (0.8, 2.5),
            (-0.8, 2.5),
            (0.5, 2.0),
            (0.8, 3.96),
            (-0.8, 3.96),
            (0.5, 3.375),
            (-0.5, 3.375),
            (0.0, 8.0),
            (0.0, 4.0),
            (0.5, 8.0),
            (-0.8, 8.0),
            (0.8, 5.0),
            (0.2, 3.0),
            (1e-7, 3.0),
            (0.0, 3.000001),
            (0.0, 2.999999),
            (0.5, 3.375 + 1e-9),
            (0.5, 3.375 - 1e-9),
        ];
        // Near type V: K where D = B1² − 4B0B2 = 0, and just off it.
        let type_v = |sk: f64| {
            // Sk²(K+3)² = 4(4K − 3Sk²)(2K − 3Sk² − 6), by bisection on D
            // between the gamma line and K = 100.
            let s2 = sk * sk;
            let d = |k: f64| {
                let b1 = sk * (k + 3.0);
                b1 * b1 - 4.0 * (4.0 * k - 3.0 * s2) * (2.0 * k - 3.0 * s2 - 6.0)
            };
            let (mut lo, mut hi) = (1.5 * s2 + 3.0 + 1e-9, 100.0);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if (d(mid) > 0.0) == (d(lo) > 0.0) {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            lo
        };
        let near_v: Vec<(f64, f64)> = [0.3, 0.5, -0.8]
            .iter()
            .flat_map(|&sk| {
                let k = type_v(sk);
                [
                    (sk, k),
                    (sk, k * (1.0 + 1e-7)),
                    (sk, k * (1.0 - 1e-7)),
                    (sk, k * (1.0 + 1e-3)),
                    (sk, k * (1.0 - 1e-3)),
                ]
            })
            .collect();
        for &(sk, k) in cases.iter().chain(&near_v) {
            let g = HeightDistribution::pearson(sk, k).unwrap().density().unwrap();
            let [m0, mean, var, s, kk] = g.moments();
            eprintln!(
                "({sk}, {k}) {:?}: {m0:.3e} {mean:.3e} {var:.3e} {s:.3e} {kk:.3e} supp {:?} mode {}",
                g.pearson_type(),
                g.support(),
                g.mode()
            );
            let tol = if k > 4.5 { 1e-7 } else { 1e-11 };
            assert!((m0 - 1.0).abs() < 1e-12, "({sk}, {k}) mass {m0}");
            assert!(mean.abs() < 1e-11, "({sk}, {k}) mean {mean}");
            assert!((var - 1.0).abs() < 1e-11, "({sk}, {k}) var {var}");
            assert!((s - sk).abs() < 1e-10, "({sk}, {k}) skew {s}");
            assert!((kk - k).abs() < tol * k, "({sk}, {k}) kurt {kk}");
        }
    }
}
