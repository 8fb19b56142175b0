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
mod family;
mod shape;

pub use density::Density;
pub(crate) use shape::{End, Form, FormVisitor, PowerTails, JACOBI_POWER_MAX};

use crate::checks::ParamError;
use crate::num::Shortest;
use family::{DistributionFamily, Parameters};

/// Writes, from one line a family (`Variant = code, "name" =>
/// module::Type`, with the variant's docs, and first a `#[cfg(..)]` for a
/// family built only so: the test-only uniform), the family's module,
/// [`HeightDistribution`] (one variant holding the family's parameters,
/// `Type`), [`Family`] with its codes and its names (`named!`, which takes
/// the `#[cfg]` too), the density's forms (`Shape`, one variant holding
/// the family's [`Form`], dispatched by a `match`: no dynamic call where
/// the model integrates), and the calls from a distribution or a family
/// to the family's [`Parameters`] and [`DistributionFamily`].
macro_rules! families {
    ($( $(#[cfg($cfg:meta)])? $(#[doc = $doc:literal])* $variant:ident = $code:literal, $name:literal => $module:ident :: $ty:ident ),+ $(,)?) => {
        $( $(#[cfg($cfg)])? mod $module; $(#[cfg($cfg)])? pub use $module::*; )+

        /// The shape of the asperity heights' distribution: one of the model
        /// constants ([`Constants::distribution`](crate::Constants::distribution)).
        /// Each variant holds its family's parameters.
        ///
        /// Its record names (JSON, the NumPy export, the bindings) are
        /// `distribution` ([`family`](Self::family)), `skewness` and `kurtosis`.
        ///
        /// Equality is as distributions: Pearson(0, 3) equals the Gaussian.
        #[derive(Debug, Clone)]
        #[non_exhaustive]
        pub enum HeightDistribution {
            $( $(#[cfg($cfg)])? $(#[doc = $doc])* $variant($ty), )+
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
            $( $(#[cfg($cfg)])? #[doc = concat!("[`HeightDistribution::", stringify!($variant), "`].")] $variant = $code, )+
        }

        impl Family {
            /// Whether the family is made of measured heights.
            fn takes_heights(self) -> bool {
                match self { $( $(#[cfg($cfg)])? Family::$variant => <$ty as DistributionFamily>::TAKES_HEIGHTS, )+ }
            }

            /// The family's distribution of a front end's arguments.
            fn distribution_of(
                self,
                skewness: Option<f64>,
                kurtosis: Option<f64>,
                heights: Option<&[f64]>,
            ) -> Result<HeightDistribution, DistributionError> {
                Ok(match self {
                    $( $(#[cfg($cfg)])? Family::$variant => HeightDistribution::$variant(<$ty>::from_arguments(skewness, kurtosis, heights)?), )+
                })
            }

            /// The family's distribution of measured moments, if they make it.
            fn moments_distribution(self, skewness: f64, kurtosis: f64) -> Option<Result<HeightDistribution, ParamError>> {
                match self {
                    $( $(#[cfg($cfg)])? Family::$variant => <$ty>::from_moments(skewness, kurtosis).map(|d| d.map(HeightDistribution::$variant)), )+
                }
            }

            /// The family's distribution of stored values, if it has one.
            fn stored_distribution(self, skewness: f64, kurtosis: f64) -> Option<HeightDistribution> {
                match self {
                    $( $(#[cfg($cfg)])? Family::$variant => <$ty>::from_stored(skewness, kurtosis).map(HeightDistribution::$variant), )+
                }
            }
        }

        crate::named!(Family, "distribution", [ $( $(#[cfg($cfg)])? $variant = $name ),+ ]);

        /// The forms of a [`Density`]'s logarithm, one a family.
        #[derive(Debug, Clone)]
        pub(crate) enum Shape {
            $( $(#[cfg($cfg)])? $variant(<$ty as DistributionFamily>::Form), )+
        }

        impl Form for Shape {
            #[inline]
            fn ln(&self, x: f64) -> f64 {
                match self { $( $(#[cfg($cfg)])? Shape::$variant(f) => f.ln(x), )+ }
            }
            #[inline]
            fn dln(&self, x: f64) -> f64 {
                match self { $( $(#[cfg($cfg)])? Shape::$variant(f) => f.dln(x), )+ }
            }
            #[inline]
            fn ln_at_end(&self, end: End, upper: bool, dist: f64, x: f64) -> f64 {
                match self { $( $(#[cfg($cfg)])? Shape::$variant(f) => f.ln_at_end(end, upper, dist, x), )+ }
            }
            fn tails(&self, mode: f64) -> (f64, f64) {
                match self { $( $(#[cfg($cfg)])? Shape::$variant(f) => f.tails(mode), )+ }
            }
            fn smoothness_scale(&self) -> f64 {
                match self { $( $(#[cfg($cfg)])? Shape::$variant(f) => f.smoothness_scale(), )+ }
            }
            fn power_tails(&self) -> Option<PowerTails> {
                match self { $( $(#[cfg($cfg)])? Shape::$variant(f) => f.power_tails(), )+ }
            }
        }

        impl Density {
            /// `visitor` called with the density's form.
            #[inline(always)]
            pub(crate) fn visit_form<V: FormVisitor>(&self, visitor: V) -> V::Out {
                match &self.shape { $( $(#[cfg($cfg)])? Shape::$variant(f) => visitor.visit(f), )+ }
            }
        }

        impl HeightDistribution {
            /// The family's parameters.
            fn parameters(&self) -> &dyn Parameters {
                match self { $( $(#[cfg($cfg)])? HeightDistribution::$variant(p) => p, )+ }
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
                match self { $( $(#[cfg($cfg)])? HeightDistribution::$variant(_) => Family::$variant, )+ }
            }

            /// The same family and parameters.
            fn same_parameters(&self, other: &HeightDistribution) -> bool {
                match (self, other) {
                    $( $(#[cfg($cfg)])? (HeightDistribution::$variant(a), HeightDistribution::$variant(b)) => a == b, )+
                    _ => false,
                }
            }
        }
    };
}

families! {
    /// The paper's Gaussian (skewness 0, kurtosis 3):
    /// [`HeightDistribution::GAUSSIAN`].
    Gaussian = 0, "gaussian" => gaussian::Gaussian,
    /// The Pearson system from skewness Sk and kurtosis K (not excess: 3
    /// for a Gaussian), admissible where K > Sk² + 1
    /// ([`HeightDistribution::pearson`]). Pearson(0, 3) is the Gaussian.
    Pearson = 1, "pearson" => pearson::Pearson,
    /// A standardised Weibull distribution with skewness Sk in
    /// (−1.1395, 2] ([`HeightDistribution::weibull`]); its kurtosis
    /// follows from Sk (2.717 at Sk = 0).
    Weibull = 2, "weibull" => weibull::Weibull,
    /// A kernel density of measured heights ([`Empirical`],
    /// [`HeightDistribution::empirical`]).
    Empirical = 3, "empirical" => empirical::Empirical,
    #[cfg(test)]
    /// A test-only family: the uniform density, what adding a family takes.
    Uniform = 4, "uniform" => uniform::Uniform,
}

impl Default for HeightDistribution {
    /// The Gaussian.
    fn default() -> HeightDistribution {
        HeightDistribution::GAUSSIAN
    }
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

    /// The paper's Gaussian (the default).
    pub const GAUSSIAN: HeightDistribution = HeightDistribution::Gaussian(Gaussian);

    /// The Pearson distribution with skewness `skewness` and kurtosis
    /// `kurtosis` (not excess), validated: K > Sk² + 1, |Sk| ≤ 5, K ≤ 100.
    pub fn pearson(skewness: f64, kurtosis: f64) -> Result<HeightDistribution, ParamError> {
        let d = HeightDistribution::Pearson(Pearson { skewness, kurtosis });
        d.validate()?;
        Ok(d)
    }

    /// The standardised Weibull distribution with skewness `skewness`, validated.
    pub fn weibull(skewness: f64) -> Result<HeightDistribution, ParamError> {
        let d = HeightDistribution::Weibull(Weibull { skewness });
        d.validate()?;
        Ok(d)
    }

    /// The empirical density of measured `heights` ([`Empirical::new`]).
    pub fn empirical(heights: &[f64]) -> Result<HeightDistribution, ParamError> {
        Ok(HeightDistribution::Empirical(Empirical::new(heights)?))
    }

    /// The distribution a front end's arguments ask for, by one set of
    /// rules for every front end (CLI flags, Python keywords): `family` if
    /// given (a front end parses its name with [`Named::parse`](crate::Named::parse)), else empirical with
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
    /// assert_eq!(D::from_arguments(Some(ke_friction::Family::Gaussian), None, Some(8.0), None).unwrap_err().name(), "kurtosis");
    /// # Ok::<(), ke_friction::DistributionError>(())
    /// ```
    pub fn from_arguments(
        family: Option<Family>,
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        heights: Option<&[f64]>,
    ) -> Result<HeightDistribution, DistributionError> {
        let conflict = |name: &'static str, reason: String| Err(DistributionError::Conflict { name, reason });
        let family = match (family, heights) {
            (Some(family), _) => family,
            (None, Some(_)) => Family::Empirical,
            (None, None) if skewness.is_some() || kurtosis.is_some() => Family::Pearson,
            (None, None) => Family::Gaussian,
        };
        if heights.is_some() && !family.takes_heights() {
            let with: Vec<&str> = Family::ALL
                .into_iter()
                .filter(|f| f.takes_heights())
                .map(Family::name)
                .collect();
            return conflict(
                "heights",
                format!("only with the {} distribution (not {family})", with.join(" or ")),
            );
        }
        family.distribution_of(skewness, kurtosis, heights)
    }

    /// The distribution of `family` with `skewness` and `kurtosis`, not
    /// validated (a table file's or a C caller's values: `validate`
    /// follows): the Gaussian ignores both, Weibull the kurtosis; `None`
    /// for the empirical family, which its heights make.
    pub fn of_family(family: Family, skewness: f64, kurtosis: f64) -> Option<HeightDistribution> {
        family.stored_distribution(skewness, kurtosis)
    }

    /// The distribution of `family` fitted to measured heights' `skewness`
    /// and `kurtosis` (a surface's), validated: the Gaussian ignores both,
    /// Weibull the kurtosis; `None` for the empirical family, which the
    /// heights themselves make.
    pub fn of_moments(family: Family, skewness: f64, kurtosis: f64) -> Option<Result<HeightDistribution, ParamError>> {
        family.moments_distribution(skewness, kurtosis)
    }

    /// The skewness and kurtosis a table file stores for the distribution
    /// (which [`of_family`](Self::of_family) reads back; Weibull's
    /// kurtosis is stored as 0); `None` for an empirical density, which
    /// tables do not hold.
    pub fn stored(&self) -> Option<[f64; 2]> {
        self.parameters().stored()
    }

    /// The family's record name: `"gaussian"`, `"pearson"`, `"weibull"` or
    /// `"empirical"` (the name of [`family_kind`](Self::family_kind)).
    pub fn family(&self) -> &'static str {
        self.family_kind().name()
    }

    /// Whether the model treats this distribution as the paper's Gaussian
    /// (the Gaussian itself, or Pearson(0, 3) exactly).
    pub fn is_gaussian(&self) -> bool {
        self.parameters().is_gaussian()
    }

    /// The skewness of the distribution.
    pub fn skewness(&self) -> f64 {
        self.parameters().skewness()
    }

    /// The kurtosis (not excess) of the distribution; for Weibull, the one
    /// its skewness implies.
    pub fn kurtosis(&self) -> f64 {
        self.parameters().kurtosis()
    }

    /// Checks the parameters (MODEL.md §9), naming the bound.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.parameters().validate()
    }

    /// The standardised density g (mean 0, variance 1), or why the
    /// distribution is not valid ([`validate`](Self::validate)).
    pub fn density(&self) -> Result<Density, ParamError> {
        self.validate()?;
        Ok(self.validated_density())
    }

    /// The density of a distribution that validated.
    pub(crate) fn validated_density(&self) -> Density {
        self.parameters().density()
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
        if let Some(n) = self.parameters().heights() {
            write!(f, "{n} heights, ")?;
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
        if self.is_gaussian() || other.is_gaussian() {
            return self.is_gaussian() && other.is_gaussian();
        }
        self.same_parameters(other)
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
        if let Some(n) = self.parameters().heights() {
            m.serialize_entry("heights", &n)?;
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
            (HeightDistribution::GAUSSIAN, "gaussian"),
            (HeightDistribution::pearson(0.0, 3.0).unwrap(), "pearson"),
            (HeightDistribution::weibull(0.0).unwrap(), "weibull"),
        ] {
            assert_eq!(d.family(), name);
            assert_eq!(Family::parse(name), Ok(d.family_kind()));
        }
        // The registry's names (the test-only uniform family is one of
        // them in the unit tests), not a list here.
        assert_eq!(
            Family::parse("normal").unwrap_err().to_string(),
            format!(
                "distribution 'normal' is unknown: must be one of {}",
                Family::names().join(", ")
            )
        );
        assert!(Family::names().ends_with(&["uniform"]));
    }
}
