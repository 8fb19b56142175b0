//! Surface statistics (MODEL.md §10): σ, Sk, K, the spectral moments m0,
//! m2, m4 and the Greenwood–Williamson parameters derived from them (α, η,
//! R, β, σ_s, y_s), and the equivalent surface of two rough surfaces.
//!
//! The default (finite-difference) path makes two passes over the heights
//! and allocates nothing of the map's size: the first pass gathers the sums
//! of the least-squares plane fit, the second computes, in one sweep of
//! three rows at a time, the central moments of the detrended heights and
//! the first and second differences along x and y. The plane enters the
//! first differences only as a constant (its slope per sample), subtracted
//! in the loop; it does not enter the second differences. Sums run in short
//! blocks of four lanes and the block sums are added with Neumaier's
//! compensated summation, so that the results agree with a float64 NumPy
//! reference (`tools/surface_reference.py`) to about 1e-13 relative.

use super::Topography;
use crate::{ErrorKind, Shortest};
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::f64::consts::PI;
use std::fmt;

/// 16/π − 3√3 + 1 = 0.89680576…: α must exceed it (σ_s real, MODEL.md §10).
const ALPHA_MIN: f64 = 16.0 / PI - 3.0 * 1.732_050_807_568_877_2 + 1.0;
/// Fewest points along a direction (x, and y for a map).
const MIN_ALONG: usize = 16;
/// Fewest valid (non-missing) points.
const MIN_VALID: usize = 100;
/// Fewest valid first or second differences along a direction.
const MIN_DIFFERENCES: usize = 16;
/// Below this bandwidth α the surface is not an isotropic Gaussian one.
const ALPHA_GAUSSIAN: f64 = 1.5;
/// The isotropy band of m20/m02 and m40/m04.
const ISOTROPY: (f64, f64) = (0.8, 1.25);
/// Sampling intervals of two surfaces differing by more than this
/// (relative) are reported by [`combine`].
const INTERVAL_TOLERANCE: f64 = 0.01;
/// The largest |height| (metres) whose fourth power the moments can hold:
/// Σr⁴ over up to 2²⁸ points of detrended heights up to 2·1e75 stays
/// below f64::MAX (1.8e308), and so do m0·m4 and the kurtosis.
pub const HEIGHT_MAX: f64 = 1e75;
/// The smallest σ (metres) of the detrended heights whose fourth powers
/// stay normal f64 numbers (σ⁴ = 1e-300 > f64::MIN_POSITIVE = 2.2e-308):
/// below it m0, μ4 and the kurtosis underflow (squares of heights below
/// ~1e-154 m are 0 outright).
pub const SIGMA_MIN: f64 = 1e-75;
/// The rms of the heights about their mean, relative to their mean
/// |height|, at or below which any roughness is lost to rounding against
/// the offset (f64 keeps 16 digits; a sum of squares a few fewer).
pub const PRECISION_MIN: f64 = 1e-12;

/// How the heights are detrended before their statistics are taken.
///
/// Every fit is a least-squares fit over the valid (non-missing) points
/// only. The plane (or line) changes the first differences only by its
/// constant slope and leaves the second differences unchanged.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Detrend {
    /// The least-squares plane z = a + b·x + c·y for a map; for a profile
    /// (no y) this is the least-squares line z = a + b·x. The default.
    #[default]
    Plane,
    /// The least-squares line z = a + b·x: for a profile the same as
    /// [`Detrend::Plane`]; for a map a single tilt along x fitted over the
    /// whole map (no tilt along y is removed, and rows are not levelled
    /// one by one).
    Line,
    /// The mean height only (z = a): no tilt removed. The choice for
    /// periodic data analysed with [`Derivative::Spectral`].
    Mean,
}

/// How the slope and curvature moments m2, m4 are estimated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Derivative {
    /// Non-periodic finite differences (MODEL.md §10, the default):
    /// m20 = mean(((z\[i+1\] − z\[i\])/Δx)²) over every adjacent pair along x
    /// whose two points are valid, m40 = mean(((z\[i+1\] − 2z\[i\] + z\[i−1\])/Δx²)²)
    /// over every interior triple of valid points; m02, m04 the same along
    /// y with Δy. For a profile these equal SurfaceTopography's Rdq²,
    /// Rddq²; for a map it averages over rows trimmed at the edges (see
    /// `tools/surface_topography_check.py`).
    #[default]
    FiniteDifference,
    /// Periodic spectral moments: the detrended heights are taken as one
    /// period in each direction and m20 = Σ (2π·f_x)²·|Z|²/N², m40 =
    /// Σ (2π·f_x)⁴·|Z|²/N² (and m02, m04 with f_y) over the discrete
    /// Fourier transform Z of the N heights, the Nyquist term dropped.
    /// Exact for band-limited periodic data; refuses missing points. Use
    /// it with [`Detrend::Mean`]: a fitted plane makes periodic data
    /// non-periodic.
    Spectral,
}

crate::named!(Detrend, "detrend", [Plane = "plane", Line = "line", Mean = "mean"]);
crate::named!(
    Derivative,
    "derivative",
    [FiniteDifference = "fd", Spectral = "spectral"]
);

/// Options of [`Topography::stats`]: the band the surface is looked at
/// and how it is detrended and differentiated.
///
/// The pipeline is ISO 25178-3's, in its order: S-filter (λs, the
/// Gaussian of ISO 16610-61, removes wavelengths shorter than λs) →
/// F-operation ([`Detrend`]) → L-filter (λc: the roughness is z − G_λc\[z\],
/// removing wavelengths longer than λc) → statistics.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StatsOptions {
    /// How the heights are detrended (default: the least-squares plane,
    /// or line for a profile).
    pub detrend: Detrend,
    /// How m2 and m4 are estimated (default: finite differences).
    pub derivative: Derivative,
    /// The S-filter's nesting index λs (m), or `None` for no S-filter.
    pub lambda_s: Option<f64>,
    /// The L-filter's nesting index λc (m), or `None` for no L-filter.
    pub lambda_c: Option<f64>,
}

/// Something to know about a result that is still returned.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// α < 1.5: not an isotropic Gaussian surface (α ≥ 1.5 for one), so
    /// the relations of MODEL.md §10 are approximate.
    LowBandwidth {
        /// The bandwidth α.
        alpha: f64,
    },
    /// A ratio m20/m02 or m40/m04 outside 0.8–1.25: the surface is
    /// anisotropic, and the relations assume isotropy.
    Anisotropy {
        /// `"m20/m02"` or `"m40/m04"`.
        ratio: &'static str,
        /// Its value.
        value: f64,
    },
    /// [`combine`]: the two surfaces were sampled at intervals differing by
    /// more than 1 %, so their m2, m4 belong to different bands.
    IntervalMismatch {
        /// `"dx"` or `"dy"`.
        name: &'static str,
        /// The interval of the first surface (metres).
        first: f64,
        /// The interval of the second surface (metres).
        second: f64,
    },
    /// The shortest scale the statistics see (λs, or 2·max(dx, dy)
    /// without an S-filter) is below the instrument's reliability cut-off:
    /// m2, m4 and so β and ψ come from scales the instrument distorts.
    Unreliable {
        /// The shortest scale the statistics see (metres).
        scale: f64,
        /// The reliability cut-off (metres).
        cutoff: f64,
    },
}

impl Warning {
    /// A short snake_case name of the warning: `"low_bandwidth"`,
    /// `"anisotropy"` or `"interval_mismatch"`.
    pub const fn kind(&self) -> &'static str {
        match self {
            Warning::LowBandwidth { .. } => "low_bandwidth",
            Warning::Anisotropy { .. } => "anisotropy",
            Warning::IntervalMismatch { .. } => "interval_mismatch",
            Warning::Unreliable { .. } => "unreliable_scale",
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::LowBandwidth { alpha } => write!(
                f,
                "the bandwidth alpha = {alpha} is below 1.5: this is not an isotropic Gaussian surface, \
                 so the summit density, radius and beta are approximate"
            ),
            Warning::Anisotropy { ratio, value } => write!(
                f,
                "{ratio} = {value} is outside 0.8-1.25: the surface is anisotropic, \
                 and the relations assume an isotropic surface"
            ),
            Warning::IntervalMismatch { name, first, second } => write!(
                f,
                "the two surfaces have {name} = {first} m and {second} m (differing by more than 1 %): \
                 their slope and curvature moments belong to different bands; the result keeps the first's"
            ),
            Warning::Unreliable { scale, cutoff } => write!(
                f,
                "the shortest scale analysed, {scale:e} m, is below the instrument's reliability cut-off \
                 {cutoff:e} m: beta, R, eta and psi come from distorted scales; filter with --lambda-s {cutoff:e} \
                 (or auto)"
            ),
        }
    }
}

/// A warning is recorded as `{"kind": "...", "message": "...", ...}` with
/// its values (`alpha`, `ratio` and `value`, or `name`, `first` and
/// `second`).
impl Serialize for Warning {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("kind", self.kind())?;
        map.serialize_entry("message", &self.to_string())?;
        match self {
            Warning::LowBandwidth { alpha } => map.serialize_entry("alpha", alpha)?,
            Warning::Anisotropy { ratio, value } => {
                map.serialize_entry("ratio", ratio)?;
                map.serialize_entry("value", value)?;
            }
            Warning::Unreliable { scale, cutoff } => {
                map.serialize_entry("scale", scale)?;
                map.serialize_entry("cutoff", cutoff)?;
            }
            Warning::IntervalMismatch { name, first, second } => {
                map.serialize_entry("name", name)?;
                map.serialize_entry("first", first)?;
                map.serialize_entry("second", second)?;
            }
        }
        map.end()
    }
}

/// Why the statistics of a surface cannot be taken.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum StatsError {
    /// A filter's nesting index is out of range (see [`super::FilterError`]).
    #[error(transparent)]
    Filter(#[from] super::FilterError),
    /// The filtered heights do not make a topography.
    #[error(transparent)]
    Topography(#[from] super::TopographyError),
    /// Fewer than 16 points along a direction.
    #[error("{name} = {count} is out of range: at least 16 points are needed along {direction}")]
    TooFewPoints {
        /// `"nx"` or `"ny"`.
        name: &'static str,
        /// `"x"` or `"y"`.
        direction: &'static str,
        /// Points along that direction.
        count: usize,
    },
    /// Fewer than 100 valid (non-missing) points.
    #[error("{valid} valid points is out of range: at least 100 are needed ({missing} missing)")]
    TooFewValid {
        /// Valid points.
        valid: usize,
        /// Missing points.
        missing: usize,
    },
    /// Fewer than 16 valid first or second differences along a direction
    /// (too many missing points in between).
    #[error("{count} valid differences for {name} is out of range: at least 16 are needed (too many missing points)")]
    TooFewDifferences {
        /// `"m20"`, `"m40"`, `"m02"` or `"m04"`.
        name: &'static str,
        /// Valid differences.
        count: usize,
    },
    /// The valid points lie on one line, so the plane (or line) fit is
    /// undetermined.
    #[error("the valid points lie on one line: the {detrend:?} fit is undetermined (use Detrend::Mean)")]
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
    /// α ≤ 0.8968 (β ≤ 0.01928): σ_s would be imaginary.
    #[error(
        "alpha = {alpha} is out of range: must be > 0.8968 (beta = {beta} must be > 0.01928), \
         else sigma_s is imaginary"
    )]
    Bandwidth {
        /// The bandwidth α = m0·m4/m2².
        alpha: f64,
        /// β = α^½/(16√(3π)).
        beta: f64,
    },
    /// Spectral moments of a surface with missing points.
    #[error("{missing} missing points: the spectral estimate needs every point (use Derivative::FiniteDifference)")]
    MissingPoints {
        /// Missing points.
        missing: usize,
    },
    /// [`combine`] of a profile with a map, or a [`super::Surface::join`]
    /// of surfaces that are not two single ones taken alike.
    #[error("cannot combine these surfaces: both must be profiles or both maps, single surfaces, with the same detrending and derivative")]
    Mismatch,
    /// Heights so large that their squares or fourth powers overflow f64
    /// (|height| must be below [`HEIGHT_MAX`]).
    #[error(
        "the largest |height| = {} m is out of range: must be below {} m, \
         else the heights' squares and fourth powers (m0, m4, kurtosis) overflow f64",
        Shortest::rounded(*max_abs),
        Shortest(*bound)
    )]
    Overflow {
        /// The largest |height| found (metres).
        max_abs: f64,
        /// The bound, [`HEIGHT_MAX`] (metres).
        bound: f64,
    },
    /// Heights so small that their squares and fourth powers underflow
    /// f64 (σ must be at least [`SIGMA_MIN`]).
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
        /// The bound, [`SIGMA_MIN`] (metres).
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
        /// The bound, [`PRECISION_MIN`].
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

/// The statistics of a surface and the model's inputs derived from them
/// (MODEL.md §10), in SI units. The field names are the JSON record's.
///
/// m2, m4 come from the shortest wavelengths in the data: α, β, R and η
/// depend on the sampling intervals (always reported with them) and on
/// any filtering, and compare only at the same band.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct SurfaceStats {
    /// Valid (non-missing) points.
    pub points: usize,
    /// Missing points.
    pub missing: usize,
    /// Points along x.
    pub nx: usize,
    /// Points along y (1 for a profile).
    pub ny: usize,
    /// Sampling interval along x (m).
    pub dx: f64,
    /// Sampling interval along y (m); `None` for a profile.
    pub dy: Option<f64>,
    /// The scan size along x, nx·dx (m).
    pub size_x: f64,
    /// The scan size along y, ny·dy (m); `None` for a profile.
    pub size_y: Option<f64>,
    /// The S-filter's nesting index λs (m); `None` if not applied.
    pub lambda_s: Option<f64>,
    /// The L-filter's nesting index λc (m); `None` if not applied.
    pub lambda_c: Option<f64>,
    /// σ (Sq): root-mean-square of the detrended heights (m).
    pub sigma: f64,
    /// Sk (Ssk): skewness of the detrended heights (dimensionless).
    pub skewness: f64,
    /// K (Sku): kurtosis of the detrended heights, not excess (3 for a
    /// Gaussian; dimensionless).
    pub kurtosis: f64,
    /// m20: mean square slope along x (dimensionless).
    pub m20: f64,
    /// m02: mean square slope along y (dimensionless); `None` for a profile.
    pub m02: Option<f64>,
    /// m40: mean square curvature along x (1/m²).
    pub m40: f64,
    /// m04: mean square curvature along y (1/m²); `None` for a profile.
    pub m04: Option<f64>,
    /// m2: m20 for a profile, (m20 + m02)/2 for a map (dimensionless).
    pub m2: f64,
    /// m4: m40 for a profile, (m40 + m04)/2 for a map (1/m²).
    pub m4: f64,
    /// α = m0·m4/m2², the bandwidth, with m0 = σ² (dimensionless).
    pub alpha: f64,
    /// η = m4/(6π√3·m2), the summit density (1/m²).
    pub eta: f64,
    /// R = 0.375·(π/m4)^½, the mean summit radius (m).
    pub radius: f64,
    /// β = ηRσ = α^½/(16√(3π)) (dimensionless).
    pub beta: f64,
    /// σ_s = σ·(1 − 0.8968/α)^½, the standard deviation of the summit
    /// heights (m), with 0.8968 = 16/π − 3√3 + 1.
    pub sigma_s: f64,
    /// y_s = 4·(m0/(πα))^½, the mean summit height above the mean plane (m).
    pub y_s: f64,
    /// m20/m02 (dimensionless, 1 if isotropic); `None` for a profile.
    pub anisotropy_m2: Option<f64>,
    /// m40/m04 (dimensionless, 1 if isotropic); `None` for a profile.
    pub anisotropy_m4: Option<f64>,
    /// What to know about these values.
    pub warnings: Vec<Warning>,
}

impl Topography {
    /// The statistics of the surface (MODEL.md §10): detrended as
    /// `options.detrend` says, m2 and m4 estimated as `options.derivative`
    /// says, missing (NaN) points left out of every sum (and every
    /// difference that touches one).
    ///
    /// Refused: fewer than 16 points along x (or y, for a map), fewer than
    /// 100 valid points or 16 valid differences along a direction, constant
    /// heights, and α ≤ 0.8968; warned: α < 1.5 and anisotropy. Heights
    /// f64 cannot take the moments of are refused with the cause: beyond
    /// [`HEIGHT_MAX`] in magnitude ([`StatsError::Overflow`]), σ below
    /// [`SIGMA_MIN`] ([`StatsError::Underflow`]), a variation at the
    /// rounding level of the offset ([`StatsError::Precision`]).
    ///
    /// ```
    /// use ke_friction::topography::{StatsOptions, Topography};
    /// let n = 64;
    /// let dx = 1e-6;
    /// let heights: Vec<f64> = (0..n * n)
    ///     .map(|k| {
    ///         let (x, y) = ((k % n) as f64, (k / n) as f64);
    ///         1e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin())
    ///     })
    ///     .collect();
    /// let surface = Topography::map(heights, n, n, dx, dx)?;
    /// let stats = surface.stats(&StatsOptions::default())?;
    /// assert!(stats.sigma > 0.0 && stats.alpha > 1.0);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn stats(&self, options: &StatsOptions) -> Result<SurfaceStats, StatsError> {
        let mut stats = match self.band(options)? {
            Some((band, detrend)) => {
                let plain = StatsOptions {
                    detrend,
                    lambda_s: None,
                    lambda_c: None,
                    ..*options
                };
                band.stats_of(&plain).map_err(|e| band.diagnose(e))?
            }
            None => self.stats_of(options).map_err(|e| self.diagnose(e))?,
        };
        stats.lambda_s = options.lambda_s;
        stats.lambda_c = options.lambda_c;
        Ok(stats)
    }

    /// The surface in the band `options` states, and the detrending left
    /// for the statistics to do: S-filter (λs), then the F-operation and
    /// the L-filter (λc) if there is one (the roughness, detrended: the
    /// statistics only take its mean out). `None` without filters.
    fn band(&self, options: &StatsOptions) -> Result<Option<(Topography, Detrend)>, StatsError> {
        if options.lambda_s.is_none() && options.lambda_c.is_none() {
            return Ok(None);
        }
        let s = match options.lambda_s {
            Some(lambda) => super::s_filter(self, lambda)?,
            None => self.clone(),
        };
        let Some(lambda) = options.lambda_c else {
            return Ok(Some((s, options.detrend)));
        };
        let heights = s.detrended(options.detrend)?;
        let detrended = Topography::new(heights, s.nx, s.ny, s.dx, s.dy)?;
        Ok(Some((super::l_filter(&detrended, lambda)?, Detrend::Mean)))
    }

    /// The heights the statistics see: in the band `options` states
    /// (filtered as [`Topography::stats`] does) and detrended, missing
    /// points NaN. What an empirical height density is built from.
    pub fn band_heights(&self, options: &StatsOptions) -> Result<Vec<f64>, StatsError> {
        match self.band(options)? {
            Some((band, detrend)) => band.detrended(detrend),
            None => self.detrended(options.detrend),
        }
    }

    /// [`Topography::stats`], its failures not yet diagnosed.
    fn stats_of(&self, options: &StatsOptions) -> Result<SurfaceStats, StatsError> {
        let (nx, ny) = (self.nx, self.ny);
        if nx < MIN_ALONG {
            return Err(StatsError::TooFewPoints {
                name: "nx",
                direction: "x",
                count: nx,
            });
        }
        if !self.is_profile() && ny < MIN_ALONG {
            return Err(StatsError::TooFewPoints {
                name: "ny",
                direction: "y",
                count: ny,
            });
        }
        let Some(z0) = self.heights.iter().copied().find(|h| !h.is_nan()) else {
            return Err(StatsError::TooFewValid {
                valid: 0,
                missing: self.heights.len(),
            });
        };
        let fit = dispatch::fit_sums(self, z0);
        let points = fit.n.value() as usize;
        let missing = self.heights.len() - points;
        if points < MIN_VALID {
            return Err(StatsError::TooFewValid { valid: points, missing });
        }
        let detrend = match options.detrend {
            Detrend::Plane if self.is_profile() => Detrend::Line,
            other => other,
        };
        let plane = fit.solve(detrend)?;

        let sums = match options.derivative {
            Derivative::FiniteDifference => {
                if missing == 0 {
                    dispatch::sweep::<false>(self, z0, &plane)
                } else {
                    dispatch::sweep::<true>(self, z0, &plane)
                }
            }
            Derivative::Spectral => {
                if missing > 0 {
                    return Err(StatsError::MissingPoints { missing });
                }
                spectral(self, z0, &plane)
            }
        };

        // Central moments of the detrended heights (their mean is 0 to
        // rounding; it is removed all the same).
        let n = points as f64;
        let mean = sums.moments[0].value() / n;
        let s2 = sums.moments[1].value() / n;
        let s3 = sums.moments[2].value() / n;
        let s4 = sums.moments[3].value() / n;
        let mu2 = s2 - mean * mean;
        let mu3 = s3 - 3.0 * mean * s2 + 2.0 * mean * mean * mean;
        let mu4 = s4 - 4.0 * mean * s3 + 6.0 * mean * mean * s2 - 3.0 * mean * mean * mean * mean;
        let m0 = mu2;
        let sigma = m0.max(0.0).sqrt();
        if !m0.is_finite() {
            return Err(StatsError::OutOfRange { name: "m0", value: m0 });
        }
        // Constant: σ at the rounding level of the heights (a plane, after
        // a plane fit, leaves residuals of a few ulps).
        if sigma <= 1e-13 * fit.scale || m0 <= 0.0 {
            return Err(StatsError::Constant { sigma });
        }
        // σ⁴ below f64's normal range: μ4 and the kurtosis lose their digits
        // (the largest |height| is filled in by `diagnose`).
        if sigma < SIGMA_MIN {
            return Err(StatsError::Underflow {
                sigma,
                max_abs: f64::NAN,
                bound: SIGMA_MIN,
            });
        }
        let skewness = mu3 / (m0 * sigma);
        let kurtosis = mu4 / (m0 * m0);
        finite("skewness", skewness)?;
        positive("kurtosis", kurtosis)?;

        let (m20, m40, m02, m04) = sums.derivatives(self)?;
        SurfaceStats::from_moments(
            (points, missing, nx, ny, self.dx, self.dy),
            [m0, skewness, kurtosis],
            (m20, m02, m40, m04),
        )
    }
}

impl Topography {
    /// The real cause of a failure that heights at the limits of f64 bring
    /// about (a scan of the heights, on the failure path only): heights
    /// beyond [`HEIGHT_MAX`] ([`StatsError::Overflow`]), a variation
    /// below [`SIGMA_MIN`] ([`StatsError::Underflow`]) or at the rounding
    /// level of the offset ([`StatsError::Precision`]); other failures,
    /// and those the heights do not explain, are returned as they are.
    fn diagnose(&self, e: StatsError) -> StatsError {
        let sigma = match e {
            StatsError::Constant { sigma } | StatsError::Underflow { sigma, .. } => sigma,
            StatsError::OutOfRange { .. } | StatsError::NotFinite { .. } => f64::NAN,
            StatsError::Bandwidth { alpha, .. } if !alpha.is_finite() => f64::NAN,
            _ => return e,
        };
        let Some(scan) = Scan::of(&self.heights) else {
            return e;
        };
        let constant = matches!(e, StatsError::Constant { .. });
        let lost = scan.relative <= PRECISION_MIN && (scan.relative > 0.0 || scan.max_abs > HEIGHT_MAX);
        if constant && lost {
            return StatsError::Precision {
                sigma,
                rms: scan.rms,
                mean_abs: scan.mean_abs,
                relative: scan.relative,
                bound: PRECISION_MIN,
            };
        }
        if scan.max_abs > HEIGHT_MAX {
            return StatsError::Overflow {
                max_abs: scan.max_abs,
                bound: HEIGHT_MAX,
            };
        }
        let tiny = scan.relative > 0.0 && scan.rms < SIGMA_MIN;
        if tiny || matches!(e, StatsError::Underflow { .. }) {
            return StatsError::Underflow {
                sigma: if sigma.is_nan() { scan.rms } else { sigma },
                max_abs: scan.max_abs,
                bound: SIGMA_MIN,
            };
        }
        e
    }

    /// The heights less their least-squares plane, line or mean (as
    /// `detrend` says, fitted over the valid points; a profile's plane is
    /// its line), row-major, missing points still NaN: the heights whose
    /// moments [`Topography::stats`] takes, for an empirical density.
    pub fn detrended(&self, detrend: Detrend) -> Result<Vec<f64>, StatsError> {
        let Some(z0) = self.heights.iter().copied().find(|h| !h.is_nan()) else {
            return Err(StatsError::TooFewValid {
                valid: 0,
                missing: self.heights.len(),
            });
        };
        let detrend = match detrend {
            Detrend::Plane if self.is_profile() => Detrend::Line,
            other => other,
        };
        let plane = dispatch::fit_sums(self, z0).solve(detrend)?;
        let (u_of, v_of) = (centred(self.nx), centred(self.ny));
        let lin: Vec<f64> = (0..self.nx).map(|i| plane.b * u_of(i)).collect();
        let mut out = Vec::with_capacity(self.heights.len());
        for (j, row) in self.heights.chunks_exact(self.nx).enumerate() {
            let p = plane.a + plane.c * v_of(j);
            out.extend(row.iter().zip(&lin).map(|(&z, &l)| (z - z0) - (p + l)));
        }
        Ok(out)
    }
}

impl SurfaceStats {
    /// The record of measured (or combined) moments: m2, m4 (a map's
    /// averages over x and y), the anisotropy ratios, the quantities of
    /// MODEL.md §10 that follow from m0, m2, m4, and the warnings.
    fn from_moments(
        (points, missing, nx, ny, dx, dy): (usize, usize, usize, usize, f64, Option<f64>),
        [m0, skewness, kurtosis]: [f64; 3],
        (m20, m02, m40, m04): (f64, Option<f64>, f64, Option<f64>),
    ) -> Result<SurfaceStats, StatsError> {
        let (m2, m4) = match (m02, m04) {
            (Some(m02), Some(m04)) => (0.5 * (m20 + m02), 0.5 * (m40 + m04)),
            _ => (m20, m40),
        };
        let derived = Derived::new(m0, m2, m4)?;
        let mut stats = SurfaceStats {
            points,
            missing,
            nx,
            ny,
            dx,
            dy,
            size_x: nx as f64 * dx,
            size_y: dy.map(|dy| ny as f64 * dy),
            lambda_s: None,
            lambda_c: None,
            sigma: m0.sqrt(),
            skewness,
            kurtosis,
            m20,
            m02,
            m40,
            m04,
            m2,
            m4,
            alpha: derived.alpha,
            eta: derived.eta,
            radius: derived.radius,
            beta: derived.beta,
            sigma_s: derived.sigma_s,
            y_s: derived.y_s,
            anisotropy_m2: m02.map(|m02| m20 / m02),
            anisotropy_m4: m04.map(|m04| m40 / m04),
            warnings: Vec::new(),
        };
        stats.warn();
        Ok(stats)
    }

    /// The shortest scale the statistics see: λs, or without an S-filter
    /// the shortest wavelength sampled, 2·max(dx, dy).
    pub fn shortest_scale(&self) -> f64 {
        self.lambda_s.unwrap_or(2.0 * self.dx.max(self.dy.unwrap_or(0.0)))
    }

    /// Adds [`Warning::Unreliable`] if the shortest scale analysed is below
    /// the instrument's reliability cut-off `cutoff` (m); true if it did.
    pub fn check_reliability(&mut self, cutoff: f64) -> bool {
        let scale = self.shortest_scale();
        let unreliable = scale < cutoff * (1.0 - 1e-12);
        if unreliable {
            self.warnings.push(Warning::Unreliable { scale, cutoff });
        }
        unreliable
    }

    /// Adds the warnings that follow from α and the anisotropy ratios.
    fn warn(&mut self) {
        if self.alpha < ALPHA_GAUSSIAN {
            self.warnings.push(Warning::LowBandwidth { alpha: self.alpha });
        }
        for (ratio, value) in [("m20/m02", self.anisotropy_m2), ("m40/m04", self.anisotropy_m4)] {
            if let Some(value) = value {
                if !(ISOTROPY.0..=ISOTROPY.1).contains(&value) {
                    self.warnings.push(Warning::Anisotropy { ratio, value });
                }
            }
        }
    }
}

/// The equivalent surface of two independent rough surfaces pressed
/// together, against a flat (the composite of Greenwood & Tripp): the sum
/// of their heights, each measured from its own mean plane toward the
/// other surface.
///
/// Variances and slope and curvature moments add, and so do the third and
/// fourth cumulants:
///
/// - m0 = σ² = σa² + σb²; m20, m02, m40, m04, m2 and m4 add likewise;
/// - Sk·σ³ = Ska·σa³ + Skb·σb³;
/// - (K − 3)·σ⁴ = (Ka − 3)·σa⁴ + (Kb − 3)·σb⁴;
///
/// and α, η, R, β, σ_s, y_s follow from m0, m2, m4 as for one surface
/// (refused if α ≤ 0.8968). The result keeps the points, sizes and sampling
/// intervals of `a`: both surfaces should be sampled alike (same band),
/// and a warning is added if dx (or dy) differ by more than 1 %. Both must
/// be profiles or both maps.
pub fn combine(a: &SurfaceStats, b: &SurfaceStats) -> Result<SurfaceStats, StatsError> {
    let add = |x: Option<f64>, y: Option<f64>| -> Result<Option<f64>, StatsError> {
        match (x, y) {
            (Some(x), Some(y)) => Ok(Some(x + y)),
            (None, None) => Ok(None),
            _ => Err(StatsError::Mismatch),
        }
    };
    let dy = add(a.dy, b.dy).map(|_| a.dy)?;
    let m02 = add(a.m02, b.m02)?;
    let m04 = add(a.m04, b.m04)?;
    let (va, vb) = (a.sigma * a.sigma, b.sigma * b.sigma);
    let m0 = va + vb;
    positive("m0", m0)?;
    let sigma = m0.sqrt();
    let skewness = (a.skewness * va * a.sigma + b.skewness * vb * b.sigma) / (m0 * sigma);
    let kurtosis = 3.0 + ((a.kurtosis - 3.0) * va * va + (b.kurtosis - 3.0) * vb * vb) / (m0 * m0);
    finite("skewness", skewness)?;
    positive("kurtosis", kurtosis)?;
    let mut stats = SurfaceStats::from_moments(
        (a.points, a.missing, a.nx, a.ny, a.dx, dy),
        [m0, skewness, kurtosis],
        (a.m20 + b.m20, m02, a.m40 + b.m40, m04),
    )?;
    (stats.lambda_s, stats.lambda_c) = (a.lambda_s, a.lambda_c);
    for (name, first, second) in [("dx", Some(a.dx), Some(b.dx)), ("dy", a.dy, b.dy)] {
        if let (Some(first), Some(second)) = (first, second) {
            if (first - second).abs() > INTERVAL_TOLERANCE * first.abs().max(second.abs()) {
                stats.warnings.push(Warning::IntervalMismatch { name, first, second });
            }
        }
    }
    Ok(stats)
}

fn finite(name: &'static str, value: f64) -> Result<f64, StatsError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(StatsError::NotFinite { name, value })
    }
}

fn positive(name: &'static str, value: f64) -> Result<f64, StatsError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(StatsError::OutOfRange { name, value })
    }
}

/// The scale of the valid heights, computed relative to the largest
/// |height| (so that neither overflows nor underflows).
struct Scan {
    /// The largest |height| (metres).
    max_abs: f64,
    /// The mean |height| (metres).
    mean_abs: f64,
    /// The rms of the heights about their mean (metres; 0 if it underflows).
    rms: f64,
    /// `rms / mean_abs`, computed from the scaled heights.
    relative: f64,
}

impl Scan {
    /// The scan of `heights` (NaN = missing), or `None` if none is valid
    /// or all are 0.
    fn of(heights: &[f64]) -> Option<Scan> {
        let valid = || heights.iter().copied().filter(|z| !z.is_nan());
        let max_abs = valid().fold(0.0f64, |m, z| m.max(z.abs()));
        if !(max_abs > 0.0 && max_abs.is_finite()) {
            return None;
        }
        let n = valid().count() as f64;
        let (mut sum, mut sum_abs) = (Sum::default(), Sum::default());
        for z in valid() {
            sum.add(z / max_abs);
            sum_abs.add(z.abs() / max_abs);
        }
        let (mean, mean_abs) = (sum.value() / n, sum_abs.value() / n);
        let mut squares = Sum::default();
        for z in valid() {
            squares.add((z / max_abs - mean).powi(2));
        }
        let rms = (squares.value() / n).sqrt();
        Some(Scan {
            max_abs,
            mean_abs: mean_abs * max_abs,
            rms: rms * max_abs,
            relative: rms / mean_abs,
        })
    }
}

/// α, η, R, β, σ_s, y_s from m0, m2, m4 (MODEL.md §10).
struct Derived {
    alpha: f64,
    eta: f64,
    radius: f64,
    beta: f64,
    sigma_s: f64,
    y_s: f64,
}

impl Derived {
    fn new(m0: f64, m2: f64, m4: f64) -> Result<Derived, StatsError> {
        positive("m0", m0)?;
        positive("m2", m2)?;
        finite("m4", m4)?;
        let alpha = m0 * m4 / (m2 * m2);
        let beta = alpha.max(0.0).sqrt() / (16.0 * (3.0 * PI).sqrt());
        if !(alpha > ALPHA_MIN && alpha.is_finite()) {
            return Err(StatsError::Bandwidth { alpha, beta });
        }
        let derived = Derived {
            alpha,
            eta: m4 / (6.0 * PI * 3f64.sqrt() * m2),
            radius: 0.375 * (PI / m4).sqrt(),
            beta,
            sigma_s: m0.sqrt() * (1.0 - ALPHA_MIN / alpha).sqrt(),
            y_s: 4.0 * (m0 / (PI * alpha)).sqrt(),
        };
        positive("eta", derived.eta)?;
        positive("radius", derived.radius)?;
        positive("sigma_s", derived.sigma_s)?;
        positive("y_s", derived.y_s)?;
        Ok(derived)
    }
}

// ---------------------------------------------------------------------------
// Summation.

/// Lanes of the inner loops (independent partial sums, vectorised).
const LANES: usize = 4;
/// Points per block: lane sums are folded into the compensated totals
/// after each block, so no plain running sum grows beyond BLOCK/LANES terms.
const BLOCK: usize = 512;

/// Neumaier's compensated sum.
#[derive(Debug, Clone, Copy, Default)]
struct Sum {
    sum: f64,
    comp: f64,
}

impl Sum {
    #[inline]
    fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.comp += (self.sum - t) + x;
        } else {
            self.comp += (x - t) + self.sum;
        }
        self.sum = t;
    }

    fn value(&self) -> f64 {
        self.sum + self.comp
    }
}

/// `(value, 1)` for a valid value, `(0, 0)` for a missing one (NaN); with
/// `MASKED == false` every value is valid.
#[inline(always)]
fn mask<const MASKED: bool>(x: f64) -> (f64, f64) {
    if MASKED && x.is_nan() {
        (0.0, 0.0)
    } else {
        (x, 1.0)
    }
}

/// Sums `K` quantities over the points of `M` slices of the same length,
/// `kernel` giving the `K` terms from the `M` values at one index: four
/// lanes (a chunk of four indices at a time, vectorised), folded into
/// compensated totals every [`BLOCK`] indices.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lanes by index: the shape that vectorises
fn sum_slices<const M: usize, const K: usize>(
    inputs: [&[f64]; M],
    totals: &mut [Sum; K],
    kernel: impl Fn([f64; M]) -> [f64; K],
) {
    let len = inputs.iter().map(|s| s.len()).min().unwrap_or(0);
    let mut start = 0;
    while start < len {
        let end = (start + BLOCK).min(len);
        let block = inputs.map(|s| &s[start..end]);
        let n = end - start;
        let full = n - n % LANES;
        let mut lanes = [[0.0f64; LANES]; K];
        let mut c = 0;
        while c < full {
            let chunk = block.map(|s| &s[c..c + LANES]);
            for l in 0..LANES {
                let terms = kernel(std::array::from_fn(|m| chunk[m][l]));
                for k in 0..K {
                    lanes[k][l] += terms[k];
                }
            }
            c += LANES;
        }
        for i in full..n {
            let terms = kernel(std::array::from_fn(|m| block[m][i]));
            for k in 0..K {
                lanes[k][0] += terms[k];
            }
        }
        for k in 0..K {
            totals[k].add((lanes[k][0] + lanes[k][2]) + (lanes[k][1] + lanes[k][3]));
        }
        start = end;
    }
}

/// The two passes compiled twice: for any x86-64 CPU (SSE2), and for one
/// with AVX2 (wider vectors), chosen at run time. The code and the order of
/// every operation are the same (no fused multiply-adds), so the results are
/// the same bit for bit.
mod dispatch {
    use super::{FitSums, Plane, Sweep, Topography};

    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    fn avx2() -> bool {
        std::is_x86_feature_detected!("avx2")
    }

    /// [`super::fit_sums`].
    pub(super) fn fit_sums(t: &Topography, z0: f64) -> FitSums {
        #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
        if avx2() {
            // SAFETY: the CPU supports AVX2 (just detected).
            return unsafe { fit_sums_avx2(t, z0) };
        }
        super::fit_sums(t, z0)
    }

    /// [`super::sweep`].
    pub(super) fn sweep<const MASKED: bool>(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
        #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
        if avx2() {
            // SAFETY: the CPU supports AVX2 (just detected).
            return unsafe { sweep_avx2::<MASKED>(t, z0, plane) };
        }
        super::sweep::<MASKED>(t, z0, plane)
    }

    /// [`super::fit_sums`] with AVX2.
    ///
    /// # Safety
    /// The CPU must support AVX2.
    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    #[target_feature(enable = "avx2")]
    unsafe fn fit_sums_avx2(t: &Topography, z0: f64) -> FitSums {
        super::fit_sums(t, z0)
    }

    /// [`super::sweep`] with AVX2.
    ///
    /// # Safety
    /// The CPU must support AVX2.
    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    #[target_feature(enable = "avx2")]
    unsafe fn sweep_avx2<const MASKED: bool>(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
        super::sweep::<MASKED>(t, z0, plane)
    }
}

// ---------------------------------------------------------------------------
// Pass 1: the sums of the least-squares fit.

/// Sums over the valid points, with u = i − (nx − 1)/2 and v = j − (ny −
/// 1)/2 the centred sample indices and z' = z − z0.
#[derive(Default)]
struct FitSums {
    n: Sum,
    su: Sum,
    sv: Sum,
    suu: Sum,
    svv: Sum,
    suv: Sum,
    sz: Sum,
    suz: Sum,
    svz: Sum,
    /// |z0| + rms(z − z0) (metres): the scale of the rounding of the
    /// detrended heights.
    scale: f64,
}

/// The fitted trend z − z0 = a + b·u + c·v (per sample index).
struct Plane {
    a: f64,
    b: f64,
    c: f64,
}

fn centred(n: usize) -> impl Fn(usize) -> f64 {
    let centre = 0.5 * (n as f64 - 1.0);
    move |i| i as f64 - centre
}

#[inline(always)]
fn fit_sums(t: &Topography, z0: f64) -> FitSums {
    let (nx, ny) = (t.nx, t.ny);
    let u_of = centred(nx);
    let v_of = centred(ny);
    let u: Vec<f64> = (0..nx).map(&u_of).collect();
    let mut fit = FitSums::default();
    let mut szz = Sum::default();
    for (j, row) in t.heights.chunks_exact(nx).enumerate() {
        let v = v_of(j);
        let mut row_sums = [Sum::default(); 6];
        sum_slices([row, &u], &mut row_sums, |[z, u]| {
            let (z, w) = mask::<true>(z - z0);
            let uw = u * w;
            [w, uw, uw * u, z, uw * z, z * z]
        });
        let [n, su, suu, sz, suz, zz] = row_sums.map(|s| s.value());
        fit.n.add(n);
        fit.su.add(su);
        fit.suu.add(suu);
        fit.sz.add(sz);
        fit.suz.add(suz);
        fit.sv.add(v * n);
        fit.svv.add(v * v * n);
        fit.suv.add(v * su);
        fit.svz.add(v * sz);
        szz.add(zz);
    }
    let n = fit.n.value();
    fit.scale = z0.abs() + if n > 0.0 { (szz.value() / n).sqrt() } else { 0.0 };
    fit
}

impl FitSums {
    fn solve(&self, detrend: Detrend) -> Result<Plane, StatsError> {
        let n = self.n.value();
        let (su, sv, sz) = (self.su.value(), self.sv.value(), self.sz.value());
        let cuu = self.suu.value() - su * su / n;
        let cvv = self.svv.value() - sv * sv / n;
        let cuv = self.suv.value() - su * sv / n;
        let cuz = self.suz.value() - su * sz / n;
        let cvz = self.svz.value() - sv * sz / n;
        let (b, c) = match detrend {
            Detrend::Mean => (0.0, 0.0),
            Detrend::Line => {
                if cuu.is_nan() || cuu <= 0.0 {
                    return Err(StatsError::Undetermined { detrend });
                }
                (cuz / cuu, 0.0)
            }
            Detrend::Plane => {
                let det = cuu * cvv - cuv * cuv;
                if det.is_nan() || det <= 1e-12 * cuu * cvv {
                    return Err(StatsError::Undetermined { detrend });
                }
                ((cuz * cvv - cvz * cuv) / det, (cvz * cuu - cuz * cuv) / det)
            }
        };
        Ok(Plane {
            a: (sz - b * su - c * sv) / n,
            b,
            c,
        })
    }
}

// ---------------------------------------------------------------------------
// Pass 2: moments of the detrended heights and the differences.

/// The sums of the second pass.
#[derive(Default)]
struct Sweep {
    /// Σr, Σr², Σr³, Σr⁴ of the detrended heights r.
    moments: [Sum; 4],
    /// Σ d², Σ e², count(d), count(e) along x: d the first differences of
    /// the detrended heights, e the second differences.
    x: [Sum; 4],
    /// The same along y (zero for a profile).
    y: [Sum; 4],
    /// Spectral moments instead: m20, m40, m02, m04 directly.
    spectral: Option<[f64; 4]>,
}

impl Sweep {
    /// m20, m40, and for a map m02, m04.
    fn derivatives(&self, t: &Topography) -> Result<(f64, f64, Option<f64>, Option<f64>), StatsError> {
        if let Some([m20, m40, m02, m04]) = self.spectral {
            positive("m20", m20)?;
            finite("m40", m40)?;
            return Ok(match t.dy {
                Some(_) => (m20, m40, Some(positive("m02", m02)?), Some(finite("m04", m04)?)),
                None => (m20, m40, None, None),
            });
        }
        let (m20, m40) = moments_of(&self.x, t.dx, "m20", "m40")?;
        match t.dy {
            Some(dy) => {
                let (m02, m04) = moments_of(&self.y, dy, "m02", "m04")?;
                Ok((m20, m40, Some(m02), Some(m04)))
            }
            None => Ok((m20, m40, None, None)),
        }
    }
}

/// The mean squares of the first and second differences along one
/// direction, over the sampling interval h squared and to the fourth.
fn moments_of(sums: &[Sum; 4], h: f64, m2: &'static str, m4: &'static str) -> Result<(f64, f64), StatsError> {
    let [d2, e2, nd, ne] = sums.map(|s| s.value());
    for (name, count) in [(m2, nd), (m4, ne)] {
        if count < MIN_DIFFERENCES as f64 {
            return Err(StatsError::TooFewDifferences {
                name,
                count: count as usize,
            });
        }
    }
    let h2 = h * h;
    let m2v = positive(m2, d2 / nd / h2)?;
    let m4v = finite(m4, e2 / ne / (h2 * h2))?;
    Ok((m2v, m4v))
}

/// The second pass: every row once, with its neighbours above and below.
#[inline(always)]
fn sweep<const MASKED: bool>(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
    let (nx, ny) = (t.nx, t.ny);
    let u_of = centred(nx);
    let v_of = centred(ny);
    // The plane's x part, b·u, for one row (a row's worth, not a map's).
    let lin: Vec<f64> = (0..nx).map(|i| plane.b * u_of(i)).collect();
    let mut out = Sweep::default();
    let rows: Vec<&[f64]> = t.heights.chunks_exact(nx).collect();
    for (j, &row) in rows.iter().enumerate() {
        // Moments of r = (z − z0) − (a + c·v + b·u).
        let p = plane.a + plane.c * v_of(j);
        sum_slices([row, &lin], &mut out.moments, |[z, l]| {
            let (r, _) = mask::<MASKED>((z - z0) - (p + l));
            let r2 = r * r;
            [r, r2, r2 * r, r2 * r2]
        });
        // Along x: first differences (less the plane's slope b) and
        // second differences, centred at i + 1.
        differences::<MASKED>(&mut out.x, row, plane.b);
        // Along y: between this row and the one before, and centred on
        // this row.
        if j >= 1 {
            let prev = rows[j - 1];
            if let Some(&next) = rows.get(j + 1) {
                let mut s = [Sum::default(); 4];
                sum_slices([prev, row, next], &mut s, |[z0, z1, z2]| {
                    let (d, wd) = mask::<MASKED>((z1 - z0) - plane.c);
                    let (e, we) = mask::<MASKED>((z2 - z1) - (z1 - z0));
                    [d * d, e * e, wd, we]
                });
                for (total, s) in out.y.iter_mut().zip(&s) {
                    total.add(s.value());
                }
            } else {
                let mut s = [Sum::default(); 2];
                sum_slices([prev, row], &mut s, |[z0, z1]| {
                    let (d, wd) = mask::<MASKED>((z1 - z0) - plane.c);
                    [d * d, wd]
                });
                out.y[0].add(s[0].value());
                out.y[2].add(s[1].value());
            }
        }
    }
    out
}

/// First and second differences along a line `z` of n ≥ 3 points: Σd²,
/// Σe² and their counts added to `totals`, d = (z\[i+1\] − z\[i\]) − slope,
/// e = (z\[i+2\] − z\[i+1\]) − (z\[i+1\] − z\[i\]) (differences of neighbours
/// first: exact for heights with a large offset).
#[inline(always)]
fn differences<const MASKED: bool>(totals: &mut [Sum; 4], z: &[f64], slope: f64) {
    let n = z.len();
    if n < 3 {
        return;
    }
    let mut s = [Sum::default(); 4];
    sum_slices([&z[..n - 2], &z[1..n - 1], &z[2..]], &mut s, |[z0, z1, z2]| {
        let (d, wd) = mask::<MASKED>((z1 - z0) - slope);
        let (e, we) = mask::<MASKED>((z2 - z1) - (z1 - z0));
        [d * d, e * e, wd, we]
    });
    // The last pair.
    let (d, wd) = mask::<MASKED>((z[n - 1] - z[n - 2]) - slope);
    s[0].add(d * d);
    s[2].add(wd);
    for (total, s) in totals.iter_mut().zip(&s) {
        total.add(s.value());
    }
}

// ---------------------------------------------------------------------------
// The spectral path.

// The FFTs of the spectral moments: the `realfft` crate (over `rustfft`).
use realfft::{num_complex::Complex, RealFftPlanner};

/// Moments of the heights as in [`sweep`], m2 and m4 from the discrete
/// Fourier transforms of the rows and the columns of the detrended heights
/// (no missing points): the mean over rows of the per-row moments equals
/// the 2-D spectral sum Σ (2π·f_x)^p·|Z|²/N² by Parseval's theorem along y.
///
/// The transforms are the `realfft` crate's (real input, the half spectrum
/// k = 0..=N/2; over `rustfft`).
fn spectral(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
    let (nx, ny) = (t.nx, t.ny);
    let mut out = sweep_moments_only(t, z0, plane);
    let u_of = centred(nx);
    let v_of = centred(ny);
    let residual = |i: usize, j: usize, z: f64| (z - z0) - (plane.a + plane.c * v_of(j) + plane.b * u_of(i));

    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(nx);
    let mut buf = fft.make_input_vec();
    let mut spectrum = fft.make_output_vec();
    let mut scratch = fft.make_scratch_vec();
    let (mut m20, mut m40) = (Sum::default(), Sum::default());
    for (j, row) in t.heights.chunks_exact(nx).enumerate() {
        for (i, (b, &z)) in buf.iter_mut().zip(row).enumerate() {
            *b = residual(i, j, z);
        }
        fft.process_with_scratch(&mut buf, &mut spectrum, &mut scratch)
            .expect("buffers of the plan's lengths");
        let (s2, s4) = line_moments(&spectrum, nx, t.dx);
        m20.add(s2);
        m40.add(s4);
    }
    let mut result = [m20.value() / ny as f64, m40.value() / ny as f64, 0.0, 0.0];

    if let Some(dy) = t.dy {
        // Columns, gathered a few at a time (one cache line of each row).
        const COLUMNS: usize = 8;
        let fft = planner.plan_fft_forward(ny);
        let mut spectrum = fft.make_output_vec();
        let mut scratch = fft.make_scratch_vec();
        let mut cols = vec![fft.make_input_vec(); COLUMNS];
        let (mut m02, mut m04) = (Sum::default(), Sum::default());
        let mut i0 = 0;
        while i0 < nx {
            let width = COLUMNS.min(nx - i0);
            for (j, row) in t.heights.chunks_exact(nx).enumerate() {
                for (k, col) in cols.iter_mut().take(width).enumerate() {
                    let i = i0 + k;
                    col[j] = residual(i, j, row[i]);
                }
            }
            for col in cols.iter_mut().take(width) {
                fft.process_with_scratch(col, &mut spectrum, &mut scratch)
                    .expect("buffers of the plan's lengths");
                let (s2, s4) = line_moments(&spectrum, ny, dy);
                m02.add(s2);
                m04.add(s4);
            }
            i0 += width;
        }
        result[2] = m02.value() / nx as f64;
        result[3] = m04.value() / nx as f64;
    }
    out.spectral = Some(result);
    out
}

/// Σ (2π·f_k)²·|X_k|²/N² and Σ (2π·f_k)⁴·|X_k|²/N² over the transform X
/// of one real line of N points spaced h, the Nyquist term (k = N/2, N
/// even) dropped; `half` is the half spectrum X_0..X_{N/2} of the line
/// (X_{N−k} = conj X_k counts each 0 < k < N/2 twice).
fn line_moments(half: &[Complex<f64>], n: usize, h: f64) -> (f64, f64) {
    let (mut s2, mut s4) = (Sum::default(), Sum::default());
    let scale = 2.0 * PI / (n as f64 * h);
    for (k, xk) in half.iter().enumerate().skip(1) {
        if 2 * k >= n {
            continue;
        }
        let w = (scale * k as f64).powi(2);
        let p = 2.0 * xk.norm_sqr();
        s2.add(w * p);
        s4.add(w * w * p);
    }
    let n2 = (n as f64) * (n as f64);
    (s2.value() / n2, s4.value() / n2)
}

/// The moments of the detrended heights alone (no missing points).
fn sweep_moments_only(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
    let nx = t.nx;
    let u_of = centred(nx);
    let v_of = centred(t.ny);
    let lin: Vec<f64> = (0..nx).map(|i| plane.b * u_of(i)).collect();
    let mut out = Sweep::default();
    for (j, row) in t.heights.chunks_exact(nx).enumerate() {
        let p = plane.a + plane.c * v_of(j);
        sum_slices([row, &lin], &mut out.moments, |[z, l]| {
            let r = (z - z0) - (p + l);
            let r2 = r * r;
            [r, r2, r2 * r, r2 * r2]
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `line_moments` of the `realfft` half spectrum against the sums of
    /// a direct DFT over every k (both halves).
    #[test]
    fn line_moments_match_a_direct_dft() {
        let h = 0.7;
        for n in [2usize, 3, 8, 16, 17, 30, 100, 128, 243] {
            let x: Vec<f64> = (0..n).map(|j| (j as f64 * 0.37).sin() + 0.1 * j as f64).collect();
            let (mut w2, mut w4) = (0.0, 0.0);
            for k in 1..n {
                if 2 * k == n {
                    continue;
                }
                let (mut re, mut im) = (0.0, 0.0);
                for (j, v) in x.iter().enumerate() {
                    let (s, c) = (2.0 * PI * ((j * k) % n) as f64 / n as f64).sin_cos();
                    re += v * c;
                    im -= v * s;
                }
                let f = 2.0 * PI * k.min(n - k) as f64 / (n as f64 * h);
                let p = (re * re + im * im) / (n * n) as f64;
                w2 += f * f * p;
                w4 += f.powi(4) * p;
            }
            let fft = RealFftPlanner::<f64>::new().plan_fft_forward(n);
            let (mut input, mut half) = (x.clone(), fft.make_output_vec());
            fft.process(&mut input, &mut half).unwrap();
            let (g2, g4) = line_moments(&half, n, h);
            let scale = w2.abs().max(1e-300);
            assert!((g2 - w2).abs() <= 1e-12 * scale, "n = {n}: {g2} vs {w2}");
            assert!((g4 - w4).abs() <= 1e-12 * w4.abs().max(1e-300), "n = {n}: {g4} vs {w4}");
        }
    }

    #[test]
    fn alpha_min_is_the_constant() {
        assert!((ALPHA_MIN - 0.896_805_76).abs() < 1e-8);
        assert!((ALPHA_MIN - (16.0 / PI - 3.0 * 3f64.sqrt() + 1.0)).abs() < 1e-15);
    }
}
