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
//!
//! The submodules: `error` (what is reported; the warnings are the
//! core's, `crate::Warning`), `band` (the
//! filters before the statistics), `sums` (the fit sums, the detrending and
//! the finite-difference sweeps), `spectral` (the spectral moments),
//! `derived` (the Greenwood–Williamson quantities from m0, m2, m4),
//! `composite` (the equivalent surface of two, [`combine`]) and `limits`
//! (heights at f64's limits).

mod band;
mod composite;
mod derived;
mod error;
mod limits;
mod spectral;
mod sums;
mod tail;

pub use crate::warning::Warning;
pub use composite::combine;
pub use error::StatsError;
pub use tail::{HeightTail, TAIL_SAMPLE};

use super::Topography;
use crate::bound::Bound;
use derived::Derived;
use sums::dispatch;

/// Fewest points along a direction (x, and y for a map).
const MIN_ALONG: usize = 16;
/// The points along a direction the statistics take: at least 16 (`MIN_ALONG`).
pub static POINTS_ALONG: Bound = Bound::whole(MIN_ALONG, usize::MAX);
/// Fewest valid (non-missing) points.
const MIN_VALID: usize = 100;
/// The valid (non-missing) points the statistics take: at least 100 (`MIN_VALID`).
pub static VALID_POINTS: Bound = Bound::whole(MIN_VALID, usize::MAX);
/// Fewest valid first or second differences along a direction.
const MIN_DIFFERENCES: usize = 16;
/// The valid first or second differences along a direction the
/// statistics take: at least 16 (`MIN_DIFFERENCES`).
pub static DIFFERENCES: Bound = Bound::whole(MIN_DIFFERENCES, usize::MAX);
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

impl StatsOptions {
    /// Whether the options make a band: with both filters, λc must be
    /// longer than λs ([`StatsError::EmptyBand`] otherwise). Each filter's
    /// own range is checked against the surface when it is applied.
    pub fn check(&self) -> Result<(), StatsError> {
        match (self.lambda_s, self.lambda_c) {
            // NaN fails the filter's own check, naming it.
            (Some(lambda_s), Some(lambda_c)) if lambda_c <= lambda_s => {
                Err(StatsError::EmptyBand { lambda_s, lambda_c })
            }
            _ => Ok(()),
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
    /// The highest measured heights and the spikes ([`HeightTail`]);
    /// `None` for the equivalent surface of two (its heights are not
    /// summed point by point). Not part of the record.
    #[serde(skip)]
    pub tail: Option<HeightTail>,
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
    /// [`Topography::stats`], its failures not yet diagnosed.
    fn stats_of(&self, options: &StatsOptions) -> Result<SurfaceStats, StatsError> {
        let (nx, ny) = (self.nx, self.ny);
        if !POINTS_ALONG.contains(nx as f64) {
            return Err(StatsError::TooFewPoints {
                name: "nx",
                direction: "x",
                count: nx,
            });
        }
        if !self.is_profile() && !POINTS_ALONG.contains(ny as f64) {
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
        if !VALID_POINTS.contains(points as f64) {
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
                spectral::spectral(self, z0, &plane)
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
        let mut stats = SurfaceStats::from_moments(
            (points, missing, nx, ny, self.dx, self.dy),
            [m0, skewness, kurtosis],
            (m20, m02, m40, m04),
        )?;
        let tail = HeightTail::of(self, z0, &plane, mean, sigma);
        stats
            .warnings
            .extend(Warning::of_spikes(kurtosis, tail.beyond(), points));
        stats.tail = Some(tail);
        if options.derivative == Derivative::Spectral {
            let mismatch = spectral::edge_mismatch(self, z0, &plane);
            if mismatch > sigma {
                stats.warnings.push(Warning::NonPeriodic { mismatch, sigma });
            }
        }
        Ok(stats)
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
            tail: None,
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
