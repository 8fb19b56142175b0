//! What a family of height distributions supplies (one file per family:
//! `gaussian.rs`, `pearson.rs`, `weibull.rs`, `empirical.rs`, and one
//! line in `families!` of `distribution/mod.rs`).

use super::density::Density;
use super::shape::Form;
use super::DistributionError;
use crate::checks::ParamError;

/// A family's parameters as a [`HeightDistribution`](super::HeightDistribution)
/// holds them: the questions every front end asks of a distribution.
pub(crate) trait Parameters {
    /// Checks the parameters (MODEL.md §9), naming the bound.
    fn validate(&self) -> Result<(), ParamError>;

    /// The skewness.
    fn skewness(&self) -> f64;

    /// The kurtosis (not excess).
    fn kurtosis(&self) -> f64;

    /// Whether the model treats it as the paper's Gaussian.
    fn is_gaussian(&self) -> bool {
        false
    }

    /// How many measured heights it was made of, if it was.
    fn heights(&self) -> Option<usize> {
        None
    }

    /// The skewness and kurtosis a table file stores for it (and
    /// [`DistributionFamily::from_stored`] reads back); `None` if tables
    /// do not hold the family.
    fn stored(&self) -> Option<[f64; 2]>;

    /// The standardised density (mean 0, variance 1), once validated.
    fn density(&self) -> Density;
}

/// A family of height distributions: its parameters and how a front end's
/// arguments or a table's values make them.
pub(crate) trait DistributionFamily: Parameters + Sized {
    /// The form of its density's logarithm.
    type Form: Form;

    /// Whether the family is made of measured heights (the only one a
    /// front end's `heights` may go to).
    const TAKES_HEIGHTS: bool = false;

    /// The family's parameters from a front end's arguments, validated,
    /// each error naming its argument (the rules of
    /// [`HeightDistribution::from_arguments`](super::HeightDistribution::from_arguments)).
    fn from_arguments(
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        heights: Option<&[f64]>,
    ) -> Result<Self, DistributionError>;

    /// The parameters of stored values ([`Parameters::stored`]), not
    /// validated; `None` if the family cannot be made from them.
    fn from_stored(skewness: f64, kurtosis: f64) -> Option<Self>;

    /// The family's distribution of measured heights' skewness and
    /// kurtosis (a surface's), validated; `None` if moments do not make
    /// it (the empirical family takes the heights themselves).
    fn from_moments(skewness: f64, kurtosis: f64) -> Option<Result<Self, ParamError>>;
}
