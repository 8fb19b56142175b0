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

mod density;
mod empirical;
mod pearson;
mod shape;
mod weibull;

pub use density::Density;
pub use empirical::{Empirical, KDE_CENTRES};
pub use pearson::PearsonType;
pub(crate) use shape::{End, PowerTails, JACOBI_POWER_MAX};

use crate::checks::{check, ParamError};
use crate::num::Shortest;

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

/// A family of asperity-height distributions: the shape of a
/// [`HeightDistribution`] without its parameters
/// ([`HeightDistribution::family_kind`]). Its names are the record name
/// `distribution` (JSON, the NumPy export, the bindings).
///
/// Its [`code`](Family::code) is the variant's value here: a table file's
/// header stores it and the C ABI's `KEF_DIST_*` constants are it (never
/// reuse one).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Family {
    /// [`HeightDistribution::Gaussian`].
    Gaussian = 0,
    /// [`HeightDistribution::Pearson`].
    Pearson = 1,
    /// [`HeightDistribution::Weibull`].
    Weibull = 2,
    /// [`HeightDistribution::Empirical`].
    Empirical = 3,
}

impl Family {
    /// The family's code: a table file's and the C ABI's (`KEF_DIST_*`).
    pub const fn code(self) -> u8 {
        self as u8
    }

    /// The family of a code, if any.
    pub fn from_code(code: u8) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.code() == code)
    }
}

crate::named!(
    Family,
    "distribution",
    [
        Gaussian = "gaussian",
        Pearson = "pearson",
        Weibull = "weibull",
        Empirical = "empirical"
    ]
);

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
    /// Every family name, as [`family`](Self::family) spells it (the
    /// names of [`Family::ALL`]).
    pub const FAMILIES: [&'static str; Family::ALL.len()] = {
        let mut names = [""; Family::ALL.len()];
        let mut i = 0;
        while i < names.len() {
            names[i] = Family::ALL[i].name();
            i += 1;
        }
        names
    };

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
            (Some(f), _) => match Family::from_name(f) {
                Some(family) => family,
                None => {
                    return conflict(
                        "distribution",
                        format!(
                            "must be one of {} (not {f:?})",
                            <Family as crate::Named>::names().join(", ")
                        ),
                    )
                }
            },
            (None, Some(_)) => Family::Empirical,
            (None, None) if skewness.is_some() || kurtosis.is_some() => Family::Pearson,
            (None, None) => Family::Gaussian,
        };
        if family != Family::Empirical && heights.is_some() {
            return conflict(
                "heights",
                format!("only with the empirical distribution (not {family})"),
            );
        }
        let d = match family {
            Family::Gaussian => {
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
            Family::Pearson => HeightDistribution::pearson(skewness.unwrap_or(0.0), kurtosis.unwrap_or(3.0))?,
            Family::Weibull => {
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
            Family::Empirical => {
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

    /// The distribution of `family` with `skewness` and `kurtosis`, not
    /// validated (a table file's or a C caller's values: `validate`
    /// follows): the Gaussian ignores both, Weibull the kurtosis; `None`
    /// for the empirical family, which its heights make.
    pub fn of_family(family: Family, skewness: f64, kurtosis: f64) -> Option<HeightDistribution> {
        Some(match family {
            Family::Gaussian => HeightDistribution::Gaussian,
            Family::Pearson => HeightDistribution::Pearson { skewness, kurtosis },
            Family::Weibull => HeightDistribution::Weibull { skewness },
            Family::Empirical => return None,
        })
    }

    /// The family's record name: `"gaussian"`, `"pearson"`, `"weibull"` or
    /// `"empirical"` (the name of [`family_kind`](Self::family_kind)).
    pub fn family(&self) -> &'static str {
        self.family_kind().name()
    }

    /// The family ([`Family`]). Pearson(0, 3) is [`Family::Pearson`]
    /// here, though it equals the Gaussian.
    ///
    /// ```
    /// use ke_friction::{Family, HeightDistribution, Named};
    /// assert_eq!(HeightDistribution::weibull(0.5)?.family_kind(), Family::Weibull);
    /// assert_eq!(Family::parse("pearson")?.name(), "pearson");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn family_kind(&self) -> Family {
        match self {
            HeightDistribution::Gaussian => Family::Gaussian,
            HeightDistribution::Pearson { .. } => Family::Pearson,
            HeightDistribution::Weibull { .. } => Family::Weibull,
            HeightDistribution::Empirical(_) => Family::Empirical,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Named;

    #[test]
    fn family_names_are_the_record_names() {
        assert_eq!(HeightDistribution::FAMILIES.to_vec(), Family::names());
        for (d, name) in [
            (HeightDistribution::Gaussian, "gaussian"),
            (HeightDistribution::pearson(0.0, 3.0).unwrap(), "pearson"),
            (HeightDistribution::weibull(0.0).unwrap(), "weibull"),
        ] {
            assert_eq!(d.family(), name);
            assert_eq!(Family::parse(name), Ok(d.family_kind()));
        }
        assert_eq!(
            Family::parse("normal").unwrap_err().to_string(),
            "distribution 'normal' is unknown: must be one of gaussian, pearson, weibull, empirical"
        );
    }
}
