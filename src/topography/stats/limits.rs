//! The diagnosis of heights at f64's limits: too large, too small, or
//! varying at the rounding level of their offset.

use super::sums::Sum;
use super::{StatsError, HEIGHT_MAX, PRECISION_MIN, SIGMA_MIN};
use crate::topography::Topography;

impl Topography {
    /// The real cause of a failure that heights at the limits of f64 bring
    /// about (a scan of the heights, on the failure path only): heights
    /// beyond [`HEIGHT_MAX`] ([`StatsError::Overflow`]), a variation
    /// below [`SIGMA_MIN`] ([`StatsError::Underflow`]) or at the rounding
    /// level of the offset ([`StatsError::Precision`]); other failures,
    /// and those the heights do not explain, are returned as they are.
    pub(super) fn diagnose(&self, e: StatsError) -> StatsError {
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
