//! μ against the scale a surface is looked at: the statistics (and, in
//! the front ends, the model's inputs and μ) at a series of S-filter
//! nesting indices λs, log-spaced. Each row is exactly the single
//! evaluation at that λs: the same [`Surface::new`] with the same options
//! but λs.

use super::{StatsError, StatsOptions, Surface, Topography};
use crate::bound::Bound;

/// The most rows a scan may have: 1,000 (10 decades at 100 a decade, 200
/// at 5). Each row filters the whole surface, so the count is bounded.
pub const SCAN_ROWS_MAX: usize = 1000;

/// The values a decade a scan may take (a scan's rows are bounded by
/// [`SCAN_ROWS_MAX`] too).
pub static PER_DECADE: Bound = Bound::whole(1, 100);

/// The λs of a scan: from `from` to `to` (metres), `per_decade` a decade.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanRange {
    /// The smallest λs (m).
    pub from: f64,
    /// The largest λs (m).
    pub to: f64,
    /// Values a decade (at least 1).
    pub per_decade: usize,
}

/// Why a scan range is refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ScanError {
    /// `from`, `to` not finite, positive and increasing (`from ≤ to`).
    #[error("the scan from {from:e} m to {to:e} m is out of range: need 0 < from <= to, finite")]
    Range {
        /// The smallest λs.
        from: f64,
        /// The largest λs.
        to: f64,
    },
    /// No value a decade, or so many that the scan would be unbounded.
    #[error("{per_decade} values a decade is out of range: must be {}", PER_DECADE.range())]
    PerDecade {
        /// The values a decade asked for.
        per_decade: usize,
    },
    /// More rows than [`SCAN_ROWS_MAX`]: `from` to `to` spans too many
    /// decades at `per_decade` a decade.
    #[error(
        "the scan from {from:e} m to {to:e} m spans {decades:.3} decades, out of range: at {per_decade} a decade \
         from and to must span at most {:.3} decades (a scan has at most {max} rows)",
        (SCAN_ROWS_MAX - 1) as f64 / *per_decade as f64,
        max = SCAN_ROWS_MAX
    )]
    TooManyRows {
        /// The smallest λs.
        from: f64,
        /// The largest λs.
        to: f64,
        /// log10(to/from) (may be infinite when the ratio overflows).
        decades: f64,
        /// The values a decade asked for.
        per_decade: usize,
    },
}

/// A bad range is the caller's argument.
impl crate::Classify for ScanError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            ScanError::Range { from, to } => crate::ErrorKind::of_value(from + to),
            ScanError::PerDecade { .. } | ScanError::TooManyRows { .. } => crate::ErrorKind::Domain,
        }
    }
}

impl ScanRange {
    /// The default range of `t`: from the shortest wavelength sampled,
    /// 2·max(dx, dy), to a tenth of the scan size (the smaller side of a
    /// map), 5 values a decade.
    pub fn default_for(t: &Topography) -> ScanRange {
        let d = t.dx().max(t.dy().unwrap_or(0.0));
        let size = match t.dy() {
            Some(dy) => (t.nx() as f64 * t.dx()).min(t.ny() as f64 * dy),
            None => t.nx() as f64 * t.dx(),
        };
        ScanRange {
            from: 2.0 * d,
            to: (size / 10.0).max(2.0 * d),
            per_decade: 5,
        }
    }

    /// The λs values: log-spaced at `per_decade` a decade from `from`,
    /// ending exactly at `to` (the last step may be shorter).
    pub fn values(&self) -> Result<Vec<f64>, ScanError> {
        let ScanRange { from, to, per_decade } = *self;
        if !(from.is_finite() && to.is_finite() && from > 0.0 && from <= to) {
            return Err(ScanError::Range { from, to });
        }
        if !PER_DECADE.contains(per_decade as f64) {
            return Err(ScanError::PerDecade { per_decade });
        }
        // to/from may overflow to ∞ (from 4.9e-324): log10 of the two
        // separately stays finite.
        let decades = to.log10() - from.log10();
        let steps = (decades * per_decade as f64 - 1e-9).ceil().max(0.0);
        // steps + 1 values (the last is `to`).
        if steps.is_nan() || steps >= SCAN_ROWS_MAX as f64 {
            return Err(ScanError::TooManyRows {
                from,
                to,
                decades,
                per_decade,
            });
        }
        let steps = steps as usize;
        let mut values: Vec<f64> = (0..steps)
            .map(|k| from * 10f64.powf(k as f64 / per_decade as f64))
            .collect();
        values.push(to);
        Ok(values)
    }
}

/// One row of a scan: λs, whether it is at or above the instrument's
/// reliability cut-off (`None` if none is known), and the surface in that
/// band (or why there is none).
#[derive(Debug, Clone)]
pub struct ScanRow {
    /// The S-filter's nesting index (m).
    pub lambda_s: f64,
    /// λs ≥ the reliability cut-off; `None` when no cut-off is known.
    pub reliable: Option<bool>,
    /// The surface at that λs (its statistics record λs), or the failure.
    pub surface: Result<Surface, StatsError>,
}

/// The surface of `t` at each λs of `range` (the other options, λc
/// included, as `options` gives them); `cutoff` (m), the instrument's
/// reliability cut-off, marks the rows below it unreliable (and adds the
/// warning the single evaluation gives). `progress(done, total)` is
/// called after each row.
pub fn scan(
    t: &Topography,
    options: &StatsOptions,
    range: &ScanRange,
    cutoff: Option<f64>,
    mut progress: impl FnMut(usize, usize),
) -> Result<Vec<ScanRow>, ScanError> {
    let values = range.values()?;
    let total = values.len();
    let rows = values
        .into_iter()
        .enumerate()
        .map(|(k, lambda_s)| {
            let options = StatsOptions {
                lambda_s: Some(lambda_s),
                ..*options
            };
            let surface = Surface::new(t.clone(), options).map(|mut s| {
                if let Some(cutoff) = cutoff {
                    s.check_reliability(cutoff);
                }
                s
            });
            progress(k + 1, total);
            ScanRow {
                lambda_s,
                reliable: cutoff.map(|c| lambda_s >= c * (1.0 - 1e-12)),
                surface,
            }
        })
        .collect();
    Ok(rows)
}
