//! Why the statistics of a surface cannot be taken.

use super::Detrend;
use crate::{ErrorKind, Shortest};

/// Why the statistics of a surface cannot be taken.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum StatsError {
    /// A filter's nesting index is out of range (see
    /// [`FilterError`](crate::topography::FilterError)).
    #[error(transparent)]
    Filter(#[from] crate::topography::FilterError),
    /// The filtered heights do not make a topography.
    #[error(transparent)]
    Topography(#[from] crate::topography::TopographyError),
    /// The L-filter's nesting index λc is not longer than the S-filter's
    /// λs: the band between them would be empty.
    #[error(
        "lambda_c = {lambda_c:e} m with lambda_s = {lambda_s:e} m is out of range: \
         lambda_c must be > lambda_s (the band from lambda_s to lambda_c is empty)"
    )]
    EmptyBand {
        /// The S-filter's nesting index (m).
        lambda_s: f64,
        /// The L-filter's nesting index (m).
        lambda_c: f64,
    },
    /// Fewer points along a direction than [`POINTS_ALONG`](super::POINTS_ALONG).
    #[error("{name} = {count} is out of range: must be {} points along {direction}", super::POINTS_ALONG.range())]
    TooFewPoints {
        /// `"nx"` or `"ny"`.
        name: &'static str,
        /// `"x"` or `"y"`.
        direction: &'static str,
        /// Points along that direction.
        count: usize,
    },
    /// Fewer valid (non-missing) points than [`VALID_POINTS`](super::VALID_POINTS).
    #[error("{valid} valid points is out of range: must be {} ({missing} missing)", super::VALID_POINTS.range())]
    TooFewValid {
        /// Valid points.
        valid: usize,
        /// Missing points.
        missing: usize,
    },
    /// Fewer valid first or second differences along a direction than
    /// [`DIFFERENCES`](super::DIFFERENCES) (too many missing points in
    /// between).
    #[error("{count} valid differences for {name} is out of range: must be {} (too many missing points)", super::DIFFERENCES.range())]
    TooFewDifferences {
        /// `"m20"`, `"m40"`, `"m02"` or `"m04"`.
        name: &'static str,
        /// Valid differences.
        count: usize,
    },
    /// The valid points lie on one line, so the plane (or line) fit is
    /// undetermined.
    #[error("the valid points lie on one line: the {detrend} detrend's fit is undetermined (choose the detrend mean)")]
    Undetermined {
        /// The detrending asked for.
        detrend: Detrend,
    },
    /// The detrended heights are constant (σ = 0 to rounding).
    #[error("sigma = {sigma} m is out of range: the detrended heights are constant (no roughness), must be > 0")]
    Constant {
        /// σ of the detrended heights (metres).
        sigma: f64,
    },
    /// α outside [`ALPHA_ADMISSIBLE`](crate::bounds::ALPHA_ADMISSIBLE) (β outside
    /// [`BETA_ADMISSIBLE`](crate::bounds::BETA_ADMISSIBLE)): σ_s would be imaginary.
    #[error(
        "alpha = {alpha} is out of range: must be {} (beta = {beta} must be {}), else sigma_s is imaginary",
        crate::gw::ALPHA_ADMISSIBLE.range(),
        crate::params::BETA_ADMISSIBLE.range()
    )]
    Bandwidth {
        /// The bandwidth α = m0·m4/m2².
        alpha: f64,
        /// β = α^½/(16√(3π)).
        beta: f64,
    },
    /// Spectral moments of a surface with missing points.
    #[error("{missing} missing points: the spectral estimate needs every point (choose the derivative fd, finite differences)")]
    MissingPoints {
        /// Missing points.
        missing: usize,
    },
    /// [`combine`](super::combine()) of a profile with a map, or a
    /// [`Surface::join`](crate::topography::Surface::join) of surfaces that
    /// are not two single ones taken alike.
    #[error("cannot combine these surfaces: both must be profiles or both maps, single surfaces, with the same detrending and derivative")]
    Mismatch,
    /// Heights so large that their squares or fourth powers overflow f64
    /// (|height| must be below [`HEIGHT_MAX`](super::HEIGHT_MAX)).
    #[error(
        "the largest |height| = {} m is out of range: must be below {} m, \
         else the heights' squares and fourth powers (m0, m4, kurtosis) overflow f64",
        Shortest::rounded(*max_abs),
        Shortest(*bound)
    )]
    Overflow {
        /// The largest |height| found (metres).
        max_abs: f64,
        /// The bound, [`HEIGHT_MAX`](super::HEIGHT_MAX) (metres).
        bound: f64,
    },
    /// Heights so small that their squares and fourth powers underflow
    /// f64 (σ must be at least [`SIGMA_MIN`](super::SIGMA_MIN)).
    #[error(
        "sigma = {} m is out of range (largest |height| = {} m): must be >= {} m, \
         else the heights' squares and fourth powers (m0, m4, kurtosis) underflow f64",
        Shortest::rounded(*sigma),
        Shortest::rounded(*max_abs),
        Shortest(*bound)
    )]
    Underflow {
        /// σ of the detrended heights as computed (metres; 0 when the
        /// squares underflowed outright).
        sigma: f64,
        /// The largest |height| found (metres).
        max_abs: f64,
        /// The bound, [`SIGMA_MIN`](super::SIGMA_MIN) (metres).
        bound: f64,
    },
    /// The heights' variation is at the rounding level of their offset:
    /// any roughness was lost to rounding against the mean height.
    #[error(
        "sigma = {} m is out of range: the heights vary by rms {} m about a mean |height| of {} m, \
         a relative {} that must be > {}: any roughness was lost to rounding against the offset \
         (subtract it before the heights become f64)",
        Shortest::rounded(*sigma),
        Shortest::rounded(*rms),
        Shortest::rounded(*mean_abs),
        Shortest::rounded(*relative),
        Shortest(*bound)
    )]
    Precision {
        /// σ of the detrended heights (metres).
        sigma: f64,
        /// The rms of the heights about their mean (metres).
        rms: f64,
        /// Their mean |height| (metres).
        mean_abs: f64,
        /// `rms / mean_abs`.
        relative: f64,
        /// The bound, [`PRECISION_MIN`](super::PRECISION_MIN).
        bound: f64,
    },
    /// A result that is not finite (the skewness, m4: any finite value is
    /// valid, negative ones included).
    #[error("{name} = {value} is out of range: must be finite")]
    NotFinite {
        /// The quantity (`"skewness"`, `"m4"`, `"m40"`…).
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A result that is not finite and > 0 (heights or intervals so large
    /// or so small that the powers overflow or underflow, or a slope of 0).
    #[error("{name} = {value} is out of range: must be > 0 and finite")]
    OutOfRange {
        /// The quantity (`"m0"`, `"m2"`, `"m4"`, `"m20"`, `"kurtosis"`…).
        name: &'static str,
        /// Its value.
        value: f64,
    },
}

/// What kind of failure this is (see [`ErrorKind`]).
impl crate::Classify for StatsError {
    fn kind(&self) -> ErrorKind {
        match self {
            StatsError::OutOfRange { value, .. } | StatsError::NotFinite { value, .. } => ErrorKind::of_value(*value),
            StatsError::Bandwidth { alpha, .. } => ErrorKind::of_value(*alpha),
            StatsError::Mismatch | StatsError::MissingPoints { .. } => ErrorKind::Argument,
            StatsError::Filter(e) => e.kind(),
            StatsError::Topography(e) => e.kind(),
            _ => ErrorKind::Domain,
        }
    }
}
