//! Asperity-height distributions (MODEL.md §9): the Gaussian of the paper,
//! the Pearson system from skewness and kurtosis, Weibull, and an empirical
//! density from measured heights.
//!
//! Every distribution is a *standardised* density g (mean 0, variance 1);
//! the model scales it by σ_s (MODEL.md §9: `φ*(z*) = g(z*/s)/s`), so that
//! applying a surface's skewness and kurtosis to its asperity heights is a
//! modelling assumption, the one the literature's extensions make.
//!
//! ```
//! use ke_friction::HeightDistribution;
//! let peaked = HeightDistribution::pearson(0.0, 8.0)?;
//! let g = peaked.density()?;
//! let [mass, mean, var, sk, k] = g.moments();
//! assert!((mass - 1.0).abs() < 1e-12 && mean.abs() < 1e-12 && (var - 1.0).abs() < 1e-12);
//! assert!(sk.abs() < 1e-12 && (k - 8.0).abs() < 1e-9);
//! assert!(HeightDistribution::pearson(0.5, 1.2).is_err()); // K ≤ Sk² + 1
//! # Ok::<(), ke_friction::ParamError>(())
//! ```

use crate::model::quadrature::{Rule, NODES};
use crate::num::Shortest;
use crate::params::{check, ParamError};
use std::sync::Arc;

/// The shape of the asperity heights' distribution: one of the model
/// constants ([`Constants::distribution`](crate::Constants::distribution)).
///
/// Its record names (JSON, the NumPy export, the bindings) are
/// `distribution` ([`family`](Self::family)), `skewness` and `kurtosis`.
///
/// Equality is as distributions: Pearson(0, 3) equals the Gaussian.
#[derive(Debug, Clone, Default)]
#[non_exhaustive]
pub enum HeightDistribution {
    /// The paper's Gaussian (skewness 0, kurtosis 3).
    #[default]
    Gaussian,
    /// The Pearson system from skewness Sk and kurtosis K (not excess: 3
    /// for a Gaussian), admissible where K > Sk² + 1. Pearson(0, 3) is the
    /// Gaussian.
    Pearson {
        /// Skewness Sk (ISO 25178 Ssk).
        skewness: f64,
        /// Kurtosis K, not excess (ISO 25178 Sku).
        kurtosis: f64,
    },
    /// A standardised Weibull distribution with skewness Sk in
    /// (−1.1395, 2]; its kurtosis follows from Sk (2.717 at Sk = 0).
    Weibull {
        /// Skewness Sk.
        skewness: f64,
    },
    /// A kernel density of measured heights ([`Empirical`]).
    Empirical(Empirical),
}

/// Bounds of the Weibull skewness (MODEL.md §9): Sk in (WEIBULL_SKEWNESS_MIN, WEIBULL_SKEWNESS_MAX].
pub const WEIBULL_SKEWNESS_MIN: f64 = -1.1395;
/// Upper bound of the Weibull skewness.
pub const WEIBULL_SKEWNESS_MAX: f64 = 2.0;
/// Fewest finite heights an [`Empirical`] density accepts.
pub const EMPIRICAL_MIN_HEIGHTS: usize = 100;
/// Kurtosis accepted by the Pearson family, at most (beyond it the tails
/// are too heavy for the model's integrals to be meaningful).
pub const PEARSON_KURTOSIS_MAX: f64 = 100.0;
/// |Skewness| accepted by the Pearson family, at most.
pub const PEARSON_SKEWNESS_MAX: f64 = 5.0;

impl HeightDistribution {
    /// Every family name, as [`family`](Self::family) spells it.
    pub const FAMILIES: [&'static str; 4] = ["gaussian", "pearson", "weibull", "empirical"];

    /// The Pearson distribution with skewness `skewness` and kurtosis
    /// `kurtosis` (not excess), validated: K > Sk² + 1, |Sk| ≤ 5, K ≤ 100.
    pub fn pearson(skewness: f64, kurtosis: f64) -> Result<HeightDistribution, ParamError> {
        let d = HeightDistribution::Pearson { skewness, kurtosis };
        d.validate()?;
        Ok(d)
    }

    /// The standardised Weibull distribution with skewness `skewness`, validated.
    pub fn weibull(skewness: f64) -> Result<HeightDistribution, ParamError> {
        let d = HeightDistribution::Weibull { skewness };
        d.validate()?;
        Ok(d)
    }

    /// The empirical density of measured `heights` ([`Empirical::new`]).
    pub fn empirical(heights: &[f64]) -> Result<HeightDistribution, ParamError> {
        Ok(HeightDistribution::Empirical(Empirical::new(heights)?))
    }

    /// The distribution a front end's arguments ask for, by one set of
    /// rules for every front end (CLI flags, Python keywords): `family` if
    /// given (one of [`FAMILIES`](Self::FAMILIES)), else empirical with
    /// `heights`, else Pearson with `skewness` or `kurtosis` (left out: 0
    /// and 3), else the Gaussian. Weibull takes `skewness` alone (a
    /// `kurtosis` only if it is the one the skewness implies); the
    /// Gaussian only skewness 0 and kurtosis 3; `heights` only the
    /// empirical family, which takes nothing else. Every error names the
    /// argument ([`DistributionError::name`]).
    ///
    /// ```
    /// use ke_friction::HeightDistribution as D;
    /// assert_eq!(D::from_arguments(None, None, Some(8.0), None)?, D::pearson(0.0, 8.0)?);
    /// assert_eq!(D::from_arguments(Some("gaussian"), None, Some(8.0), None).unwrap_err().name(), "kurtosis");
    /// # Ok::<(), ke_friction::DistributionError>(())
    /// ```
    pub fn from_arguments(
        family: Option<&str>,
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        heights: Option<&[f64]>,
    ) -> Result<HeightDistribution, DistributionError> {
        let conflict = |name: &'static str, reason: String| Err(DistributionError::Conflict { name, reason });
        let family = match (family, heights) {
            (Some(f), _) => f,
            (None, Some(_)) => "empirical",
            (None, None) if skewness.is_some() || kurtosis.is_some() => "pearson",
            (None, None) => "gaussian",
        };
        if !HeightDistribution::FAMILIES.contains(&family) {
            return conflict(
                "distribution",
                format!("must be gaussian, pearson, weibull or empirical (not {family:?})"),
            );
        }
        if family != "empirical" && heights.is_some() {
            return conflict(
                "heights",
                format!("only with the empirical distribution (not {family})"),
            );
        }
        let d = match family {
            "gaussian" => {
                for (name, value, normal) in [("skewness", skewness, 0.0), ("kurtosis", kurtosis, 3.0)] {
                    if value.is_some_and(|v| v != normal) {
                        return conflict(
                            name,
                            "the gaussian distribution has skewness 0 and kurtosis 3 (ask for pearson)".into(),
                        );
                    }
                }
                HeightDistribution::Gaussian
            }
            "pearson" => HeightDistribution::pearson(skewness.unwrap_or(0.0), kurtosis.unwrap_or(3.0))?,
            "weibull" => {
                let d = HeightDistribution::weibull(skewness.unwrap_or(0.0))?;
                if let Some(k) = kurtosis {
                    let implied = d.kurtosis();
                    if k != implied {
                        return conflict(
                            "kurtosis",
                            format!(
                                "= {}: not with weibull, whose kurtosis follows from the skewness ({})",
                                Shortest(k),
                                Shortest(implied)
                            ),
                        );
                    }
                }
                d
            }
            _ => {
                if let Some(name) = [("skewness", skewness), ("kurtosis", kurtosis)]
                    .into_iter()
                    .find_map(|(name, v)| v.map(|_| name))
                {
                    return conflict(
                        name,
                        "not with an empirical density (the heights give its shape)".into(),
                    );
                }
                let Some(heights) = heights else {
                    return conflict("heights", "the empirical distribution needs measured heights".into());
                };
                HeightDistribution::empirical(heights)?
            }
        };
        Ok(d)
    }

    /// The family's record name: `"gaussian"`, `"pearson"`, `"weibull"` or `"empirical"`.
    pub fn family(&self) -> &'static str {
        match self {
            HeightDistribution::Gaussian => "gaussian",
            HeightDistribution::Pearson { .. } => "pearson",
            HeightDistribution::Weibull { .. } => "weibull",
            HeightDistribution::Empirical(_) => "empirical",
        }
    }

    /// Whether the model treats this distribution as the paper's Gaussian
    /// (the Gaussian itself, or Pearson(0, 3) exactly).
    pub fn is_gaussian(&self) -> bool {
        match self {
            HeightDistribution::Gaussian => true,
            HeightDistribution::Pearson { skewness, kurtosis } => *skewness == 0.0 && *kurtosis == 3.0,
            _ => false,
        }
    }

    /// The skewness of the distribution.
    pub fn skewness(&self) -> f64 {
        match self {
            HeightDistribution::Gaussian => 0.0,
            HeightDistribution::Pearson { skewness, .. } | HeightDistribution::Weibull { skewness } => *skewness,
            HeightDistribution::Empirical(e) => e.0.skewness,
        }
    }

    /// The kurtosis (not excess) of the distribution; for Weibull, the one
    /// its skewness implies.
    pub fn kurtosis(&self) -> f64 {
        match self {
            HeightDistribution::Gaussian => 3.0,
            HeightDistribution::Pearson { kurtosis, .. } => *kurtosis,
            HeightDistribution::Weibull { .. } => self.density().map_or(f64::NAN, |d| d.moments()[4]),
            HeightDistribution::Empirical(e) => e.0.kurtosis,
        }
    }

    /// Checks the parameters (MODEL.md §9), naming the bound.
    pub fn validate(&self) -> Result<(), ParamError> {
        match *self {
            HeightDistribution::Gaussian | HeightDistribution::Empirical(_) => Ok(()),
            HeightDistribution::Pearson { skewness, kurtosis } => {
                check("skewness", skewness, "in [-5, 5]", |v| v.abs() <= PEARSON_SKEWNESS_MAX)?;
                check("kurtosis", kurtosis, "<= 100 (not excess: 3 for a Gaussian)", |v| {
                    v <= PEARSON_KURTOSIS_MAX
                })?;
                check(
                    "kurtosis",
                    kurtosis,
                    "> skewness² + 1 (the Pearson bound; kurtosis is not excess: 3 for a Gaussian)",
                    |v| v > skewness * skewness + 1.0,
                )
            }
            HeightDistribution::Weibull { skewness } => {
                check("skewness", skewness, "in (-1.1395, 2] (the Weibull family)", |v| {
                    v > WEIBULL_SKEWNESS_MIN && v <= WEIBULL_SKEWNESS_MAX
                })
            }
        }
    }

    /// The standardised density g (mean 0, variance 1), or why the
    /// distribution is not valid ([`validate`](Self::validate)).
    pub fn density(&self) -> Result<Density, ParamError> {
        self.validate()?;
        Ok(Density::new(self))
    }
}

/// Why a front end's arguments do not make a distribution
/// ([`HeightDistribution::from_arguments`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DistributionError {
    /// A value out of its range (the family's bounds).
    #[error(transparent)]
    Value(#[from] ParamError),
    /// Arguments that do not go together, or a missing or unknown one.
    #[error("{name}{}{reason}", if reason.starts_with('=') { " " } else { ": " })]
    Conflict {
        /// The argument at fault: `distribution`, `skewness`, `kurtosis` or `heights`.
        name: &'static str,
        /// Why.
        reason: String,
    },
}

impl DistributionError {
    /// The argument at fault (a front end spells it as its flag or keyword).
    pub fn name(&self) -> &'static str {
        match self {
            DistributionError::Value(e) => e.name,
            DistributionError::Conflict { name, .. } => name,
        }
    }
}

/// The value's kind, else [`ErrorKind::Argument`](crate::ErrorKind::Argument).
impl crate::Classify for DistributionError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            DistributionError::Value(e) => e.kind(),
            DistributionError::Conflict { .. } => crate::ErrorKind::Argument,
        }
    }
}

impl std::fmt::Display for HeightDistribution {
    /// `gaussian`, `pearson (skewness 0.5, kurtosis 3.375)`, `weibull
    /// (skewness 0, kurtosis 2.717)` or `empirical (20000 heights, skewness …,
    /// kurtosis …)`: how every front end names it in text.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.is_gaussian() {
            return f.write_str("gaussian");
        }
        write!(f, "{} (", self.family())?;
        if let HeightDistribution::Empirical(e) = self {
            write!(f, "{} heights, ", e.len())?;
        }
        write!(
            f,
            "skewness {}, kurtosis {})",
            Shortest::rounded(self.skewness()),
            Shortest::rounded(self.kurtosis())
        )
    }
}

impl PartialEq for HeightDistribution {
    /// The same distribution: the same family and parameters, or both the
    /// Gaussian (Pearson(0, 3) is the Gaussian).
    fn eq(&self, other: &HeightDistribution) -> bool {
        use HeightDistribution::*;
        match (self, other) {
            _ if self.is_gaussian() || other.is_gaussian() => self.is_gaussian() && other.is_gaussian(),
            (
                Pearson {
                    skewness: a,
                    kurtosis: k,
                },
                Pearson {
                    skewness: b,
                    kurtosis: l,
                },
            ) => a == b && k == l,
            (Weibull { skewness: a }, Weibull { skewness: b }) => a == b,
            (Empirical(a), Empirical(b)) => a == b,
            _ => false,
        }
    }
}

impl serde::Serialize for HeightDistribution {
    /// As `{"distribution": family, "skewness": Sk, "kurtosis": K}` (and
    /// `"heights": n` for an empirical density), flattened into the
    /// records that hold it.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("distribution", self.family())?;
        m.serialize_entry("skewness", &self.skewness())?;
        m.serialize_entry("kurtosis", &self.kurtosis())?;
        if let HeightDistribution::Empirical(e) = self {
            m.serialize_entry("heights", &e.0.n)?;
        }
        m.end()
    }
}

/// An empirical density of measured heights (MODEL.md §9): the heights are
/// standardised, binned onto at most [`KDE_CENTRES`] evenly spaced centres
/// (no more than four per kernel width) and smoothed by a
/// Gaussian kernel of Silverman's bandwidth `h = 1.06·n^(−1/5)`, then
/// rescaled so that the density has mean 0 and variance 1 exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Empirical(Arc<Kde>);

/// Most bin centres of an [`Empirical`] density.
pub const KDE_CENTRES: usize = 2000;

#[derive(Debug, PartialEq)]
struct Kde {
    /// Heights given (finite ones).
    n: usize,
    /// Skewness and kurtosis of the heights.
    skewness: f64,
    kurtosis: f64,
    /// Standardised centres (mean 0, and variance `1 − h²` with the
    /// weights), and their weights (sum 1).
    centres: Vec<f64>,
    weights: Vec<f64>,
    /// Kernel width, in standardised units.
    h: f64,
}

/// Kernels further than this many widths away are left out (e^−40.5).
const KDE_REACH: f64 = 9.0;

impl Kde {
    /// The kernel density of weighted `atoms` (x, weight; weights summing
    /// to `total`) lying in `lo..=hi`, with kernel width `h0`: linear binning
    /// onto evenly spaced centres, about four per kernel width (binning
    /// then changes the density by ~1e-3 of itself) and at most
    /// [`KDE_CENTRES`], then standardised so that the smoothed density has
    /// mean 0 and variance (of the centres) + h² = 1.
    fn binned(
        n: usize,
        [skewness, kurtosis]: [f64; 2],
        (lo, hi): (f64, f64),
        h0: f64,
        atoms: impl Iterator<Item = (f64, f64)>,
        total: f64,
    ) -> Kde {
        let m = (((hi - lo) / (0.25 * h0)).ceil() as usize + 1).clamp(16, KDE_CENTRES);
        let step = (hi - lo) / (m - 1) as f64;
        let mut weights = vec![0.0; m];
        for (x, w) in atoms {
            let t = (x - lo) / step;
            let i = (t.floor().max(0.0) as usize).min(m - 2);
            let f = (t - i as f64).clamp(0.0, 1.0);
            weights[i] += w * (1.0 - f);
            weights[i + 1] += w * f;
        }
        weights.iter_mut().for_each(|w| *w /= total);
        let centres: Vec<f64> = (0..m).map(|i| lo + step * i as f64).collect();
        let cm: f64 = centres.iter().zip(&weights).map(|(c, w)| c * w).sum();
        let cv: f64 = centres.iter().zip(&weights).map(|(c, w)| (c - cm) * (c - cm) * w).sum();
        let scale = 1.0 / (cv + h0 * h0).sqrt();
        Kde {
            n,
            skewness,
            kurtosis,
            centres: centres.into_iter().map(|c| (c - cm) * scale).collect(),
            weights,
            h: h0 * scale,
        }
    }
}

impl Empirical {
    /// The density of `heights` (any unit; NaN entries are skipped). At
    /// least [`EMPIRICAL_MIN_HEIGHTS`] finite heights, not all equal.
    pub fn new(heights: &[f64]) -> Result<Empirical, ParamError> {
        let finite = || heights.iter().copied().filter(|v| v.is_finite());
        let n = finite().count();
        check("heights", n as f64, "at least 100 finite values", |v| {
            v >= EMPIRICAL_MIN_HEIGHTS as f64
        })?;
        if let Some(bad) = heights.iter().find(|v| v.is_infinite()) {
            return Err(ParamError {
                name: "heights",
                value: *bad,
                range: "finite (NaN marks a missing point)",
            });
        }
        let nf = n as f64;
        let mean = finite().sum::<f64>() / nf;
        let [m2, m3, m4] = finite().fold([0.0; 3], |[a, b, c], v| {
            let d = v - mean;
            [a + d * d, b + d * d * d, c + d * d * d * d]
        });
        let (m2, m3, m4) = (m2 / nf, m3 / nf, m4 / nf);
        let sd = m2.sqrt();
        if !(sd > 1e-12 * mean.abs().max(f64::MIN_POSITIVE) && sd.is_finite()) {
            return Err(ParamError {
                name: "heights",
                value: sd,
                range: "a standard deviation > 0 (the heights are constant)",
            });
        }
        let (lo, hi) = finite().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            let x = (v - mean) / sd;
            (a.min(x), b.max(x))
        });
        let h0 = 1.06 * (n as f64).powf(-0.2);
        let atoms = finite().map(|v| ((v - mean) / sd, 1.0));
        let kde = Kde::binned(n, [m3 / (m2 * sd), m4 / (m2 * m2)], (lo, hi), h0, atoms, nf);
        Ok(Empirical(Arc::new(kde)))
    }

    /// The density of the sum of two independent heights, `sd`·X + `other_sd`·Y,
    /// with X of this density and Y of `other` (both standardised): the
    /// convolution of the two (MODEL.md §10, two rough surfaces). Their
    /// kernels combine into one Gaussian kernel; their bin centres are
    /// convolved and binned again (at most [`KDE_CENTRES`]); skewness and
    /// kurtosis follow from the cumulants, which add. [`Empirical::len`]
    /// of the sum is the smaller of the two counts.
    ///
    /// ```
    /// use ke_friction::HeightDistribution;
    /// let a: Vec<f64> = (0..2000).map(|i| ((i as f64) * 0.61).sin()).collect();
    /// let b: Vec<f64> = (0..3000).map(|i| ((i as f64) * 0.37).cos().powi(3)).collect();
    /// let (HeightDistribution::Empirical(x), HeightDistribution::Empirical(y)) =
    ///     (HeightDistribution::empirical(&a)?, HeightDistribution::empirical(&b)?) else { unreachable!() };
    /// let sum = x.sum(1.0, &y, 2.0)?;
    /// let d = HeightDistribution::Empirical(sum).density()?;
    /// let [mass, mean, var, _, _] = d.moments();
    /// assert!((mass - 1.0).abs() < 1e-9 && mean.abs() < 1e-9 && (var - 1.0).abs() < 1e-9);
    /// # Ok::<(), ke_friction::ParamError>(())
    /// ```
    pub fn sum(&self, sd: f64, other: &Empirical, other_sd: f64) -> Result<Empirical, ParamError> {
        let positive = |v: f64| v > 0.0;
        check("sd", sd, "> 0", positive)?;
        check("other_sd", other_sd, "> 0", positive)?;
        let (a, b) = (&*self.0, &*other.0);
        let total = sd.hypot(other_sd);
        let (wa, wb) = (sd / total, other_sd / total);
        let h0 = (wa * a.h).hypot(wb * b.h);
        let ends = |k: &Kde| (k.centres[0], k.centres[k.centres.len() - 1]);
        let ((alo, ahi), (blo, bhi)) = (ends(a), ends(b));
        let skewness = wa.powi(3) * a.skewness + wb.powi(3) * b.skewness;
        let kurtosis = 3.0 + wa.powi(4) * (a.kurtosis - 3.0) + wb.powi(4) * (b.kurtosis - 3.0);
        let atoms = a.centres.iter().zip(&a.weights).flat_map(|(&ca, &pa)| {
            b.centres
                .iter()
                .zip(&b.weights)
                .map(move |(&cb, &pb)| (wa * ca + wb * cb, pa * pb))
        });
        Ok(Empirical(Arc::new(Kde::binned(
            a.n.min(b.n),
            [skewness, kurtosis],
            (wa * alo + wb * blo, wa * ahi + wb * bhi),
            h0,
            atoms,
            1.0,
        ))))
    }

    /// Number of heights the density was built from.
    pub fn len(&self) -> usize {
        self.0.n
    }

    /// Always false: an empirical density has at least [`EMPIRICAL_MIN_HEIGHTS`] heights.
    pub fn is_empty(&self) -> bool {
        self.0.n == 0
    }

    /// Kernel width (Silverman's bandwidth, in units of the standardised heights).
    pub fn bandwidth(&self) -> f64 {
        self.0.h
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

/// The power tails of a density (types IV, VII): see [`Density::power_tails`].
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

/// `ln g = −e·ln(B(x)/B0) − f·G(x)`, `G(x) = ln(1 + x·k/(B0·(1 − x/r_b)))/k`.
#[derive(Debug, Clone, Copy)]
struct Stable {
    e: f64,
    f: f64,
    k: f64,
    b: [f64; 3],
    rb: f64,
}

/// Roots of B(x) at least this far from 0 make a Pearson density "near
/// normal" ([`Shape::NearNormal`]).
const NEAR_NORMAL: f64 = 1000.0;

#[derive(Debug, Clone)]
enum Shape {
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

/// A standardised density g (mean 0, variance 1) of a
/// [`HeightDistribution`]: its value, support, mode and moments.
#[derive(Debug, Clone)]
pub struct Density {
    shape: Shape,
    /// `(A1, A0, B0, B1, B2)` of a Pearson density.
    pearson: Option<([f64; 5], PearsonType)>,
    lo: Option<End>,
    hi: Option<End>,
    /// ln g(x) = ln_norm + shape(x).
    ln_norm: f64,
    mode: f64,
}

impl Density {
    /// The density of a distribution that validated.
    pub(crate) fn new(dist: &HeightDistribution) -> Density {
        let mut d = match dist {
            _ if dist.is_gaussian() => Density::plain(Shape::Normal, None, None, 0.0),
            HeightDistribution::Pearson { skewness, kurtosis } => Density::pearson(*skewness, *kurtosis),
            HeightDistribution::Weibull { skewness } => Density::weibull(*skewness),
            HeightDistribution::Empirical(e) => {
                let kde = &e.0;
                let mode = kde
                    .centres
                    .iter()
                    .copied()
                    .max_by(|a, b| kde_value(kde, *a).total_cmp(&kde_value(kde, *b)))
                    .unwrap_or(0.0);
                Density::plain(Shape::Kde(e.0.clone()), None, None, mode)
            }
            HeightDistribution::Gaussian => unreachable!("is_gaussian"),
        };
        d.ln_norm = match d.shape {
            Shape::Normal => -0.5 * (2.0 * core::f64::consts::PI).ln(),
            Shape::Kde(_) | Shape::Weibull { .. } => 0.0,
            _ => -d.integrate(|_| 1.0).ln(),
        };
        d
    }

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
    fn weibull(sk: f64) -> Density {
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

    fn plain(shape: Shape, lo: Option<End>, hi: Option<End>, mode: f64) -> Density {
        Density {
            shape,
            pearson: None,
            lo,
            hi,
            ln_norm: 0.0,
            mode,
        }
    }

    fn pearson(sk: f64, k: f64) -> Density {
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
        Density {
            shape,
            pearson: Some(([a1, a0, b0, b1, b2], ty)),
            lo,
            hi,
            ln_norm: 0.0,
            mode,
        }
    }

    /// The support `(lo, hi)` (infinite where unbounded).
    pub fn support(&self) -> (f64, f64) {
        (
            self.lo.map_or(f64::NEG_INFINITY, |e| e.at),
            self.hi.map_or(f64::INFINITY, |e| e.at),
        )
    }

    /// Where g is largest (for a J-shaped density, the end where it is unbounded).
    pub fn mode(&self) -> f64 {
        self.mode
    }

    /// Below the first and above the second, g only falls away from its
    /// mass: the mode for the unimodal families, the outermost kernel
    /// centres for an empirical density (whose outliers make it
    /// multimodal: a tail may not be cut at the first dip).
    pub(crate) fn tails(&self) -> (f64, f64) {
        match &self.shape {
            Shape::Kde(kde) => (kde.centres[0], kde.centres[kde.centres.len() - 1]),
            _ => (self.mode, self.mode),
        }
    }

    /// The Pearson type, for a Pearson density (the Gaussian is
    /// [`PearsonType::Normal`]).
    pub fn pearson_type(&self) -> Option<PearsonType> {
        match self.shape {
            Shape::Normal => Some(PearsonType::Normal),
            _ => self.pearson.map(|(_, t)| t),
        }
    }

    /// The power tails of a type IV or VII density: `g ~ |x − centre|^−exponent`
    /// on both sides, with g analytic in `1/(x − centre)` out to infinity
    /// (its only singularities are the complex roots of the Pearson
    /// quadratic B(x), `centre ± i·half_width`).
    pub(crate) fn power_tails(&self) -> Option<PowerTails> {
        match self.shape {
            Shape::Complex { b1, b2, w, c4a, .. } => Some(PowerTails {
                centre: -b1 / (2.0 * b2),
                half_width: w / (2.0 * b2.abs()),
                exponent: -2.0 * c4a,
            }),
            _ => None,
        }
    }

    pub(crate) fn lower_end(&self) -> Option<End> {
        self.lo
    }

    pub(crate) fn upper_end(&self) -> Option<End> {
        self.hi
    }

    /// The scale (in standardised units) on which g may change shape
    /// without its log-slope showing it: a kernel's width for an empirical
    /// density, else unlimited.
    pub(crate) fn smoothness_scale(&self) -> f64 {
        match &self.shape {
            Shape::Kde(kde) => kde.h,
            _ => f64::INFINITY,
        }
    }

    /// ln g(x); −∞ outside the support.
    pub fn ln_pdf(&self, x: f64) -> f64 {
        if let Some(e) = self.lo {
            if x <= e.at {
                return if x == e.at {
                    self.ln_pdf_at_end(e, 0.0)
                } else {
                    f64::NEG_INFINITY
                };
            }
        }
        if let Some(e) = self.hi {
            if x >= e.at {
                return if x == e.at {
                    self.ln_pdf_at_end(e, 0.0)
                } else {
                    f64::NEG_INFINITY
                };
            }
        }
        self.ln_norm + self.shape_ln(x)
    }

    /// g(x); 0 outside the support.
    pub fn pdf(&self, x: f64) -> f64 {
        self.ln_pdf(x).exp()
    }

    /// g'(x)/g(x) inside the support.
    pub fn dln_pdf(&self, x: f64) -> f64 {
        if let Some(([a1, a0, b0, b1, b2], _)) = self.pearson {
            return -(a1 * x + a0) / (b0 + x * (b1 + x * b2));
        }
        match &self.shape {
            Shape::Weibull { k, mu, sd } => {
                let w = mu + sd * x;
                sd * ((k - 1.0) / w - k * w.powf(k - 1.0))
            }
            Shape::Kde(kde) => {
                let (v, dv) = kde_value_slope(kde, x);
                dv / v
            }
            _ => -x,
        }
    }

    /// ln g at distance `dist ≥ 0` inside the support from its finite end
    /// `e`, computed from the distance itself (no rounding of `e.at ± dist`).
    pub(crate) fn ln_pdf_at_end(&self, e: End, dist: f64) -> f64 {
        let upper = self.hi == Some(e);
        let x = if upper { e.at - dist } else { e.at + dist };
        self.ln_norm
            + match self.shape {
                Shape::TwoRoots { ra, rb, ca, cb, .. } => {
                    let term = |r: f64, c: f64| {
                        if r == e.at {
                            -c * (dist / r.abs()).ln()
                        } else {
                            -c * (-x / r).ln_1p()
                        }
                    };
                    term(ra, ca) + term(rb, cb)
                }
                Shape::Gamma { c1, c2, inv_e0 } => c1 * x + c2 * (dist * inv_e0.abs()).ln(),
                Shape::TypeV { r, cv1, cv2 } => {
                    let xr = if upper { -dist } else { dist };
                    cv1 * (dist / r.abs()).ln() + cv2 * (1.0 / xr + 1.0 / r)
                }
                Shape::Weibull { k, mu: _, sd } => {
                    let w = sd * dist;
                    (sd * k).ln() + (k - 1.0) * w.ln() - w.powf(k)
                }
                _ => self.shape_ln(x),
            }
    }

    /// ln g(x) − ln_norm inside the support.
    fn shape_ln(&self, x: f64) -> f64 {
        match &self.shape {
            Shape::Normal => -0.5 * x * x,
            Shape::TwoRoots { stable: Some(st), .. } => {
                let [b0, b1, b2] = st.b;
                let g = (x * st.k / (b0 * (1.0 - x / st.rb))).ln_1p() / st.k;
                -st.e * ((b1 * x + b2 * x * x) / b0).ln_1p() - st.f * g
            }
            Shape::TwoRoots { ra, rb, ca, cb, .. } => -ca * (-x / ra).ln_1p() - cb * (-x / rb).ln_1p(),
            Shape::NearNormal => {
                let ([a1, a0, b0, b1, b2], _) = self.pearson.expect("a Pearson density");
                let r = Rule::shared_legendre();
                -x * (0..NODES)
                    .map(|i| {
                        let t = x * r.t[i];
                        r.w[i] * (a1 * t + a0) / (b0 + t * (b1 + t * b2))
                    })
                    .sum::<f64>()
            }
            Shape::Gamma { c1, c2, inv_e0 } => c1 * x + c2 * (x * inv_e0).ln_1p(),
            Shape::TypeV { r, cv1, cv2 } => cv1 * (-x / r).ln_1p() + cv2 * (1.0 / (x - r) + 1.0 / r),
            Shape::Complex {
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
            Shape::Weibull { k, mu, sd } => {
                let w = mu + sd * x;
                (sd * k).ln() + (k - 1.0) * w.ln() - w.powf(*k)
            }
            Shape::Kde(kde) => kde_value(kde, x).ln(),
        }
    }

    /// `[∫g, mean, variance, skewness, kurtosis]`, by the same quadrature
    /// the model uses (to about 1e-13 for densities with light tails).
    pub fn moments(&self) -> [f64; 5] {
        let m = |k: i32| self.integrate(|x| x.powi(k));
        let (m0, m1) = (m(0), m(1));
        let mean = m1 / m0;
        let c = |k: i32| self.integrate(|x| (x - mean).powi(k)) / m0;
        let var = c(2);
        [m0, mean, var, c(3) / var.powf(1.5), c(4) / (var * var)]
    }

    /// `∫ f(x)·g(x) dx` over the support, split at the mode, with
    /// Gauss–Jacobi panels at finite ends and geometric panels into the tails.
    pub(crate) fn integrate(&self, f: impl Fn(f64) -> f64) -> f64 {
        let (lo, hi) = self.support();
        let mut sum = 0.0;
        let mode = self.mode.clamp(lo, hi);
        let start = if mode > lo && mode < hi { mode } else { 0.0 };
        for dir in [-1.0, 1.0] {
            let end = if dir > 0.0 { self.hi } else { self.lo };
            march(self, start, dir, end, &mut |x0, x1, rule| {
                sum += panel_sum(self, x0, x1, rule, end, &f)
            });
        }
        sum
    }
}

/// How one panel is integrated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum PanelRule {
    /// Gauss–Legendre.
    Legendre,
    /// Gauss–Jacobi with the end's weight `|x − end|^power` at `x1`.
    JacobiEnd,
}

/// Walks from `x` in direction `dir` (±1) in panels until the support end
/// (`end`) or until the density has become negligible; calls `f(x0, x1,
/// rule)` (with `x0 < x1`).
fn march(g: &Density, x: f64, dir: f64, end: Option<End>, f: &mut impl FnMut(f64, f64, PanelRule)) {
    let peak = g.ln_pdf(g.mode).max(g.ln_pdf(x));
    let peak = if peak.is_finite() { peak } else { g.ln_pdf(x) };
    let mut x = x;
    for _ in 0..100_000 {
        let mut step = 8.0 / g.dln_pdf(x).abs().max(1e-300);
        step = step.max(1e-3 * (1.0 + x.abs()) * f64::EPSILON.sqrt());
        // Far out, panels grow with |x| (power tails) but stay within their
        // distance from 0 for the x^k weights.
        step = step.min(0.5 * (1.0 + x.abs())).min(g.smoothness_scale());
        if let Some(e) = end {
            let dist = (e.at - x) * dir;
            if dist <= 0.0 {
                return;
            }
            if step >= 0.5 * dist && e.takes_jacobi(dist) {
                let (a, b) = if dir > 0.0 { (x, e.at) } else { (e.at, x) };
                f(a, b, PanelRule::JacobiEnd);
                return;
            }
            step = step.min(0.5 * dist);
        }
        let x1 = x + dir * step;
        let (a, b) = if dir > 0.0 { (x, x1) } else { (x1, x) };
        f(a, b, PanelRule::Legendre);
        x = x1;
        // Negligible: the density times (1 + x²)² has fallen by e^−60.
        let ln_g = match end {
            Some(e) => g.ln_pdf_at_end(e, (e.at - x) * dir),
            None => g.ln_pdf(x),
        };
        if ln_g + 2.0 * (1.0 + x * x).ln() < peak - 60.0 || ln_g == f64::NEG_INFINITY {
            return;
        }
    }
}

/// One panel of [`Density::integrate`].
fn panel_sum(g: &Density, x0: f64, x1: f64, rule: PanelRule, end: Option<End>, f: &impl Fn(f64) -> f64) -> f64 {
    let width = x1 - x0;
    match rule {
        PanelRule::Legendre => {
            let r = Rule::shared_legendre();
            (0..NODES)
                .map(|i| {
                    let x = x0 + width * r.t[i];
                    width * r.w[i] * f(x) * g.pdf(x)
                })
                .sum()
        }
        PanelRule::JacobiEnd => {
            let Some(r) = end.and_then(|e| e.jacobi_rule().map(|r| (e, r))) else {
                return 0.0;
            };
            let (e, r) = r;
            let upper = e.at == x1;
            // ∫ |x − e|^p·(g/|x − e|^p) over the panel, in the distance t·width.
            (0..NODES)
                .map(|i| {
                    let dist = width * r.t[i];
                    let x = if upper { x1 - dist } else { x0 + dist };
                    let regular = g.ln_pdf_at_end(e, dist) - e.power * dist.ln();
                    width.powf(e.power + 1.0) * r.w[i] * f(x) * regular.exp()
                })
                .sum()
        }
    }
}

fn kde_value(kde: &Kde, x: f64) -> f64 {
    kde_value_slope(kde, x).0
}

/// The kernel density and its slope at `x`: the kernels within
/// [`KDE_REACH`] widths, by a recurrence from the nearest centre (the
/// centres are evenly spaced: two exponentials per call).
fn kde_value_slope(kde: &Kde, x: f64) -> (f64, f64) {
    let (h, c, w) = (kde.h, &kde.centres, &kde.weights);
    let n = c.len();
    let delta = (c[n - 1] - c[0]) / (n - 1) as f64;
    let inv_h2 = 1.0 / (h * h);
    let norm = 1.0 / (h * (2.0 * core::f64::consts::PI).sqrt());
    let reach = (KDE_REACH * h / delta).ceil() as isize;
    let j0 = ((x - c[0]) / delta)
        .round()
        .clamp(-(reach + 1) as f64, (n as isize + reach) as f64) as isize;
    let t = x - (c[0] + delta * j0 as f64);
    // Kernel j0 + m: exp(−(t − mδ)²/2h²) = base·r^m·q_m, q_m = exp(−m²δ²/2h²).
    let base = (-0.5 * t * t * inv_h2).exp();
    let r = (t * delta * inv_h2).exp();
    let q = (-0.5 * delta * delta * inv_h2).exp();
    let (mut v, mut dv) = (0.0, 0.0);
    let mut add = |j: isize, k: f64| {
        if (0..n as isize).contains(&j) {
            let j = j as usize;
            let term = w[j] * k;
            v += term;
            dv -= term * (x - c[j]) * inv_h2;
        }
    };
    add(j0, base);
    for (dir, ratio) in [(1isize, r), (-1, 1.0 / r)] {
        // k_m = base·ratio^m·q^(m²): k_(m+1) = k_m·ratio·q^(2m+1).
        let (mut k, mut qm) = (base, q);
        for m in 1..=reach {
            k *= ratio * qm;
            qm *= q * q;
            add(j0 + dir * m, k);
        }
    }
    (v * norm, dv * norm)
}

/// ln Γ(x) for x > 0 (Lanczos, g = 7, n = 9: about 1e-15 relative).
pub(crate) fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        let pi = core::f64::consts::PI;
        return (pi / (pi * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut a = C[0];
    let t = x + G + 0.5;
    for (i, c) in C.iter().enumerate().skip(1) {
        a += c / (x + i as f64);
    }
    0.5 * (2.0 * core::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + a.ln()
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

/// `atan2(y, x)` to about an ulp, at half the cost of the C library's
/// (which is correctly rounded, with a multi-precision fallback): FDLIBM's
/// `atan` (Sun Microsystems, 1993; error < 1 ulp) of `y/x`, plus ±π for
/// `x < 0`. The Pearson IV log-density takes one per node: there only the
/// absolute error (≲ 2e-16 here) matters.
fn atan2(y: f64, x: f64) -> f64 {
    use core::f64::consts::PI;
    if x > 0.0 {
        atan(y / x)
    } else if x < 0.0 {
        atan(y / x) + PI.copysign(y)
    } else {
        y.atan2(x) // x = ±0 or NaN
    }
}

/// FDLIBM's `s_atan.c`: `atan(x)` by reduction to |t| < 7/16 and an odd
/// polynomial of degree 23.
fn atan(x: f64) -> f64 {
    const HI: [f64; 4] = [
        0.4636476090008061,
        core::f64::consts::FRAC_PI_4,
        0.982793723247329,
        core::f64::consts::FRAC_PI_2,
    ];
    const LO: [f64; 4] = [
        2.2698777452961687e-17,
        3.061616997868383e-17,
        1.3903311031230998e-17,
        6.123233995736766e-17,
    ];
    const AT: [f64; 11] = [
        0.3333333333333293,
        -0.19999999999876483,
        0.14285714272503466,
        -0.11111110405462356,
        0.09090887133436507,
        -0.0769187620504483,
        0.06661073137387531,
        -0.058335701337905735,
        0.049768779946159324,
        -0.036531572744216916,
        0.016285820115365782,
    ];
    let a = x.abs();
    if a.is_nan() {
        return x;
    }
    if a >= 7.378_697_629_483_821e19 {
        // |x| ≥ 2^66: π/2 to the last bit.
        return (HI[3] + LO[3]).copysign(x);
    }
    let (id, t) = if a < 0.4375 {
        if a < 7.450580596923828e-09 {
            return x; // |x| < 2^−27
        }
        (None, x)
    } else if a < 1.1875 {
        if a < 0.6875 {
            (Some(0), (2.0 * a - 1.0) / (2.0 + a))
        } else {
            (Some(1), (a - 1.0) / (a + 1.0))
        }
    } else if a < 2.4375 {
        (Some(2), (a - 1.5) / (1.0 + 1.5 * a))
    } else {
        (Some(3), -1.0 / a)
    };
    let z = t * t;
    let w = z * z;
    let s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    let s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    match id {
        None => t - t * (s1 + s2),
        Some(i) => (HI[i] - ((t * (s1 + s2) - LO[i]) - t)).copysign(x),
    }
}

#[cfg(test)]
mod atan_tests {
    use super::*;

    /// Distance in ulps between two finite doubles of the same sign.
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    #[test]
    fn atan2_is_within_an_ulp_of_the_c_library() {
        // A deterministic spread over signs and 40 decades of y/x, plus
        // every branch point of the reduction and the axes.
        let mut rng = crate::rng::SplitMix64(25);
        // A magnitude in e^±46 and a random sign.
        let mut draw = || (rng.unit() * 92.0 - 46.0).exp().copysign(rng.unit() - 0.5);
        let mut worst = 0;
        for _ in 0..200_000 {
            let (y, x) = (draw(), draw());
            let (ours, libm) = (atan2(y, x), y.atan2(x));
            worst = worst.max(ulps(ours, libm));
        }
        for t in [0.4375, 0.6875, 1.1875, 2.4375, 7.45e-9, 1e-300, 1e20, 1e300] {
            for t in [t, t * (1.0 - f64::EPSILON), t * (1.0 + f64::EPSILON)] {
                for (y, x) in [(t, 1.0), (-t, 1.0), (t, -1.0), (-t, -1.0), (1.0, t), (1.0, -t)] {
                    worst = worst.max(ulps(atan2(y, x), y.atan2(x)));
                }
            }
        }
        assert!(worst <= 1, "worst {worst} ulps");
        for (y, x) in [
            (0.0, 0.0),
            (-0.0, 0.0),
            (1.0, 0.0),
            (-1.0, -0.0),
            (0.0, -1.0),
            (-0.0, -1.0),
        ] {
            assert_eq!(atan2(y, x).to_bits(), y.atan2(x).to_bits(), "atan2({y}, {x})");
        }
        assert!(atan2(f64::NAN, 1.0).is_nan() && atan2(1.0, f64::NAN).is_nan());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_gamma_matches_factorials_and_half_integers() {
        let mut f = 1.0f64;
        for n in 1..20 {
            f *= n as f64;
            assert!(
                (ln_gamma(n as f64 + 1.0) - f.ln()).abs() < 2e-14 * f.ln().max(1.0),
                "n = {n}"
            );
        }
        let sqrt_pi = core::f64::consts::PI.sqrt();
        assert!((ln_gamma(0.5) - sqrt_pi.ln()).abs() < 1e-15);
        assert!((ln_gamma(1.5) - (0.5 * sqrt_pi).ln()).abs() < 1e-15);
    }

    #[test]
    fn weibull_shape_at_zero_skewness() {
        let k = weibull_shape(0.0).unwrap();
        assert!((k - 3.602_349_425_7).abs() < 1e-9, "{k}");
        assert!(weibull_shape(-1.2).is_none() && weibull_shape(2.1).is_none());
    }
}

#[cfg(test)]
mod moment_tests {
    use super::*;

    /// Every Pearson type and Weibull: ∫g = 1, mean 0, variance 1 and the
    /// stated Sk, K.
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
        for sk in [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0] {
            let d = HeightDistribution::weibull(sk).unwrap();
            let [m0, mean, var, s, kk] = d.density().unwrap().moments();
            eprintln!("weibull {sk}: {m0:.3e} {mean:.3e} {var:.3e} {s:.3e} {kk:.3e}");
            assert!((m0 - 1.0).abs() < 1e-12 && mean.abs() < 1e-11 && (var - 1.0).abs() < 1e-11);
            assert!((s - sk).abs() < 1e-10 && (kk - d.kurtosis()).abs() < 1e-10);
        }
    }
}
