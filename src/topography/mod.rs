//! Measured surfaces (MODEL.md §10): height maps and profiles read from
//! files (ISO 25178-72 X3P, `.npy`, text), their statistics, their power
//! spectral density, the ISO 16610 Gaussian filters (S-filter, L-filter),
//! the scale-dependent rms slope and curvature and the tip-radius
//! reliability cut-off (Sanner et al. 2022), and the equivalent surface of two rough surfaces.
//!
//! Feature `topography` (the CLI and the Python package enable it; the
//! light runtime does not).

pub mod container;
mod evaluate;
mod filter;
mod metadata;
mod psd;
mod read;
mod record;
mod request;
mod scale;
mod scan;
mod stats;
mod surface;
mod write;

pub use evaluate::{EvaluateError, Evaluation, SurfaceModel};
pub use filter::{gaussian_lowpass, gaussian_lowpass_using, l_filter, s_filter, Convolution, FilterError};
pub use metadata::Metadata;
pub use psd::{
    complete_part, psd_all, psd_area, psd_profile_x, psd_profile_y, Psd, PsdError, Rectangle, Window, PSD_POINTS,
};
pub use read::{read_bytes, read_file, Channel, Format, ReadError, ReadOptions, MAX_BYTES, MAX_POINTS};
pub use record::{FrictionRecord, Frictions, SurfaceRecord};
pub use request::{
    band_ends, evaluate_failure, reliability_needed, Analysis, BandEnd, Checked, Cutoff, Field, LambdaS, LoadInputs,
    Message, Outcome, Part, RequestError, Sensitivity, Source, SurfaceRequest, SENSITIVITY_FAMILIES, WITH_MATERIALS,
};
pub use scale::{
    default_distances, scale_dependent_curvature, scale_dependent_slope, tip_reliability_cutoff, ScaleError, ScaleRow,
    DISTANCES_PER_DECADE, TIP_SAFETY_FACTOR,
};
pub use scan::{scan, ScanError, ScanRange, ScanRow, PER_DECADE, SCAN_ROWS_MAX};
pub use stats::{
    combine, Derivative, Detrend, HeightTail, StatsError, StatsOptions, SurfaceStats, Warning, DIFFERENCES, HEIGHT_MAX,
    POINTS_ALONG, PRECISION_MIN, SIGMA_MIN, TAIL_SAMPLE, VALID_POINTS,
};
pub use surface::Surface;
pub use write::write_x3p;

use std::sync::Arc;

/// A measured height map (or profile) on a regular grid, in SI units.
///
/// Heights are stored row-major: `ny` rows of `nx` points, a row running
/// along x (rows = y, as in NumPy and X3P). A profile has `ny == 1` and no
/// `dy`. Missing points (NaN in the file, or masked invalid by the
/// instrument) are NaN here: kept as missing, never filled.
///
/// Two topographies are equal when their grids and heights are (the
/// [`Metadata`] describes, it is not compared).
///
/// A clone shares the heights (they are immutable, behind an [`Arc`]): a
/// scan's rows and a surface's parts hold no copy of them.
#[derive(Debug, Clone)]
pub struct Topography {
    heights: Arc<Vec<f64>>,
    nx: usize,
    ny: usize,
    dx: f64,
    dy: Option<f64>,
    metadata: Metadata,
}

/// Why a [`Topography`] cannot be made from the given heights.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TopographyError {
    /// The number of heights is not `nx·ny`, or a size is zero.
    #[error("{len} heights do not make a {nx} x {ny} grid")]
    Shape {
        /// Heights given.
        len: usize,
        /// Points along x.
        nx: usize,
        /// Points along y.
        ny: usize,
    },
    /// A sampling interval is not finite and > 0.
    #[error("{name} = {value} is out of range: must be > 0 and finite (metres)")]
    Interval {
        /// `"dx"` or `"dy"`.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A height is infinite (missing points are NaN).
    #[error("height at index {index} is infinite (missing points are NaN)")]
    Infinite {
        /// Row-major index of the point.
        index: usize,
    },
}

/// Heights that do not make a topography: the caller's argument (a
/// non-finite interval or height is [`ErrorKind::Argument`](crate::ErrorKind::Argument),
/// a finite interval out of range [`ErrorKind::Domain`](crate::ErrorKind::Domain)).
impl crate::Classify for TopographyError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            TopographyError::Interval { value, .. } => crate::ErrorKind::of_value(*value),
            _ => crate::ErrorKind::Argument,
        }
    }
}

impl PartialEq for Topography {
    fn eq(&self, other: &Topography) -> bool {
        (self.nx, self.ny, self.dx, self.dy) == (other.nx, other.ny, other.dx, other.dy)
            && self.heights == other.heights
    }
}

impl Topography {
    /// A map of `ny` rows of `nx` heights (metres, row-major, NaN =
    /// missing) with sampling intervals `dx`, `dy` (metres).
    pub fn map(heights: Vec<f64>, nx: usize, ny: usize, dx: f64, dy: f64) -> Result<Topography, TopographyError> {
        Topography::new(heights, nx, ny, dx, Some(dy))
    }

    /// A profile of heights (metres, NaN = missing) sampled every `dx` metres.
    pub fn profile(heights: Vec<f64>, dx: f64) -> Result<Topography, TopographyError> {
        let nx = heights.len();
        Topography::new(heights, nx, 1, dx, None)
    }

    fn new(heights: Vec<f64>, nx: usize, ny: usize, dx: f64, dy: Option<f64>) -> Result<Topography, TopographyError> {
        if nx == 0 || ny == 0 || nx.checked_mul(ny) != Some(heights.len()) {
            return Err(TopographyError::Shape {
                len: heights.len(),
                nx,
                ny,
            });
        }
        for (name, value) in [("dx", Some(dx)), ("dy", dy)] {
            if let Some(value) = value {
                if !(value.is_finite() && value > 0.0) {
                    return Err(TopographyError::Interval { name, value });
                }
            }
        }
        if let Some(index) = heights.iter().position(|h| h.is_infinite()) {
            return Err(TopographyError::Infinite { index });
        }
        Ok(Topography {
            heights: Arc::new(heights),
            nx,
            ny,
            dx,
            dy,
            metadata: Metadata::default(),
        })
    }

    /// What the file said about the measurement (empty for a topography
    /// made from heights).
    pub fn metadata(&self) -> &Metadata {
        &self.metadata
    }

    /// The topography with `metadata` in place of its own.
    pub fn with_metadata(mut self, metadata: Metadata) -> Topography {
        self.metadata = metadata;
        self
    }

    /// The heights, row-major (metres, NaN = missing).
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// Points along x.
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Points along y (1 for a profile).
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// Sampling interval along x (metres).
    pub fn dx(&self) -> f64 {
        self.dx
    }

    /// Sampling interval along y (metres); `None` for a profile.
    pub fn dy(&self) -> Option<f64> {
        self.dy
    }

    /// Whether this is a profile (one row, no `dy`).
    pub fn is_profile(&self) -> bool {
        self.dy.is_none()
    }
}
