//! The Pearson system (MODEL.md §9): the density of a skewness and
//! kurtosis, by type.

use super::shape::{End, Shape, Stable};

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
/// normal" ([`Shape::NearNormal`]).
const NEAR_NORMAL: f64 = 1000.0;

/// A Pearson density's parts: what [`Density`](super::Density) holds of it.
pub(super) struct Fitted {
    /// `(A1, A0, B0, B1, B2)`.
    pub coeffs: [f64; 5],
    pub ty: PearsonType,
    pub shape: Shape,
    pub lo: Option<End>,
    pub hi: Option<End>,
    pub mode: f64,
}

/// The standardised Pearson density with skewness `sk` and kurtosis `k`
/// (validated): its type, shape, ends and mode (MODEL.md §9).
pub(super) fn fit(sk: f64, k: f64) -> Fitted {
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
        let shape = Shape::Gamma {
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
        let shape = Shape::TwoRoots { ra, rb, ca, cb, stable };
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
        let shape = Shape::TypeV {
            r,
            cv1: -a1 / b2,
            cv2: (a1 * r + a0) / b2,
        };
        (PearsonType::V, shape, lo, hi)
    } else {
        let w = (-disc).sqrt();
        let shape = Shape::Complex {
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
        Shape::NearNormal
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
