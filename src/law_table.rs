//! Solver-ready tables of a [`FrictionLaw`]: rows (p, μ, dμ/dp) at
//! log-spaced pressures, and the measured worst relative error of linear
//! interpolation between them — what tabulated-curve inputs read (MOOSE's
//! `PiecewiseLinear`, LS-DYNA curves, COMSOL interpolation functions all
//! interpolate linearly in p between rows).
//!
//! The rows are either as many as asked for ([`LawTable::with_rows`]) or
//! the fewest that meet a tolerance ([`LawTable::for_tolerance`]). The
//! error is measured against the law itself (its curve, within
//! [`FrictionLaw::max_error`] of the model) at [`INTERIOR_POINTS`] points
//! inside every interval, the midpoint among them.
//!
//! ```
//! use ke_friction::{FrictionLaw, LawTable, OutOfRange, Params};
//! let law = FrictionLaw::new(Params::new(1.0, 0.001), 1e9, Some((1e4, 1e8)), OutOfRange::Error)?;
//! let table = LawTable::for_tolerance(&law, 1e4, 1e8, 1e-3)?;
//! assert!(table.interpolation_error <= 1e-3);
//! assert_eq!(table.rows.first().unwrap().pressure, 1e4);
//! assert_eq!(table.rows.last().unwrap().pressure, 1e8);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::bound::{Bound, End};
use crate::{Classify, ErrorKind, FrictionLaw, PressureError, Shortest};

/// The default tolerance of [`LawTable::for_tolerance`] (`kefric law`
/// without `--rows`): the worst relative error of linear interpolation.
pub const LAW_TABLE_TOLERANCE: f64 = 1e-3;

/// The tolerances a table can be asked for: not below the law's own
/// accuracy ([`crate::CURVE_ACCURACY`], 1e-6), below 1 (a relative error).
pub const LAW_TABLE_TOLERANCE_RANGE: (f64, f64) = (1e-6, 0.5);

/// The most rows a table has (the rows are its size in memory: 24 bytes
/// each).
pub const LAW_TABLE_MAX_ROWS: usize = 1_000_000;

/// The rows a table may be asked for ([`LawTable::with_rows`]): from 2 to
/// [`LAW_TABLE_MAX_ROWS`].
pub static LAW_ROWS: Bound = Bound::whole(2, LAW_TABLE_MAX_ROWS);

/// The tolerances a table may be asked for ([`LawTable::for_tolerance`]):
/// [`LAW_TABLE_TOLERANCE_RANGE`].
pub static LAW_TOLERANCE: Bound = Bound::new(
    End::Closed(LAW_TABLE_TOLERANCE_RANGE.0),
    End::Closed(LAW_TABLE_TOLERANCE_RANGE.1),
);

/// The points inside every interval where the interpolation error is
/// measured: at `k/(INTERIOR_POINTS + 1)` of the interval, k = 1 …
/// (the midpoint is the fourth). The error of linear interpolation is a
/// near-parabola over a short interval: sampling it at eighths finds its
/// peak to within 2 %.
pub const INTERIOR_POINTS: usize = 7;

/// One row: the pressure (Pa), μ and dμ/dp (1/Pa) there.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LawRow {
    /// The contact pressure p, Pa.
    pub pressure: f64,
    /// The friction coefficient μ(p).
    pub mu: f64,
    /// dμ/dp, 1/Pa.
    pub dmu_dp: f64,
}

/// The rows of a law at log-spaced pressures and how well linear
/// interpolation between them follows the law.
#[derive(Debug, Clone, PartialEq)]
pub struct LawTable {
    /// The rows, the first at the lowest pressure and the last at the
    /// highest, log-spaced.
    pub rows: Vec<LawRow>,
    /// The worst relative error |μ_linear − μ(p)| / μ(p) of linear
    /// interpolation in p between consecutive rows, measured at
    /// [`INTERIOR_POINTS`] points of every interval.
    pub interpolation_error: f64,
}

/// Why a table cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LawTableError {
    /// The pressures are not inside the law's range, or not in order.
    #[error("pressure range [{}, {}] Pa is invalid: it must be positive and increasing, within the law's range [{}, {}] Pa", Shortest(*.lo), Shortest(*.hi), Shortest(*.law_lo), Shortest(*.law_hi))]
    Range {
        /// The lowest pressure asked for.
        lo: f64,
        /// The highest.
        hi: f64,
        /// The law's lowest pressure.
        law_lo: f64,
        /// The law's highest.
        law_hi: f64,
    },
    /// The number of rows is out of range.
    #[error("rows = {rows} is out of range: must be {}", LAW_ROWS.range())]
    Rows {
        /// The rows asked for.
        rows: usize,
    },
    /// The tolerance is out of range.
    #[error("tolerance = {} is out of range: must be {}", Shortest(*.tolerance), LAW_TOLERANCE.range())]
    Tolerance {
        /// The tolerance asked for.
        tolerance: f64,
    },
    /// No number of rows up to the maximum meets the tolerance.
    #[error("no table of up to {LAW_TABLE_MAX_ROWS} rows interpolates within {}: the best has {}", Shortest(*.tolerance), Shortest(*.error))]
    Unreachable {
        /// The tolerance asked for.
        tolerance: f64,
        /// The error at the maximum number of rows.
        error: f64,
    },
    /// The law has no μ at a pressure of the range (a bug: the range is
    /// checked to lie within the law's).
    #[error(transparent)]
    Pressure(#[from] PressureError),
}

impl Classify for LawTableError {
    fn kind(&self) -> ErrorKind {
        match self {
            LawTableError::Range { lo, hi, .. } => ErrorKind::of_value(lo + hi),
            LawTableError::Rows { .. } => ErrorKind::Domain,
            LawTableError::Tolerance { tolerance } => ErrorKind::of_value(*tolerance),
            LawTableError::Unreachable { .. } => ErrorKind::Tolerance,
            LawTableError::Pressure(_) => ErrorKind::Internal,
        }
    }
}

/// The `i`-th of `n` log-spaced pressures from `lo` to `hi`, both ends
/// exact (so that rounding cannot step outside the law's range).
fn pressure(lo: f64, hi: f64, i: usize, n: usize) -> f64 {
    if i == 0 {
        lo
    } else if i + 1 == n {
        hi
    } else {
        (lo * (hi / lo).powf(i as f64 / (n - 1) as f64)).clamp(lo, hi)
    }
}

/// Checks the pressure range against the law's.
fn check_range(law: &FrictionLaw, lo: f64, hi: f64) -> Result<(), LawTableError> {
    let (law_lo, law_hi) = law.range();
    if lo.is_finite() && hi.is_finite() && law_lo <= lo && lo < hi && hi <= law_hi {
        Ok(())
    } else {
        Err(LawTableError::Range { lo, hi, law_lo, law_hi })
    }
}

/// The worst relative error of linear interpolation between `n`
/// log-spaced rows from `lo` to `hi` (evaluated as it goes: nothing is
/// allocated).
fn interpolation_error(law: &FrictionLaw, lo: f64, hi: f64, n: usize) -> Result<f64, PressureError> {
    let mut worst = 0.0f64;
    let (mut p0, mut mu0) = (lo, law.mu(lo)?);
    for i in 1..n {
        let p1 = pressure(lo, hi, i, n);
        let mu1 = law.mu(p1)?;
        for k in 1..=INTERIOR_POINTS {
            let t = k as f64 / (INTERIOR_POINTS + 1) as f64;
            let p = p0 + (p1 - p0) * t;
            let exact = law.mu(p)?;
            let linear = mu0 + (mu1 - mu0) * t;
            worst = worst.max((linear - exact).abs() / exact.abs());
        }
        (p0, mu0) = (p1, mu1);
    }
    Ok(worst)
}

impl LawTable {
    /// `rows` rows of `law` at log-spaced pressures from `lo` to `hi` (Pa;
    /// within the law's range), with their measured interpolation error.
    pub fn with_rows(law: &FrictionLaw, lo: f64, hi: f64, rows: usize) -> Result<LawTable, LawTableError> {
        check_range(law, lo, hi)?;
        if !LAW_ROWS.contains(rows as f64) {
            return Err(LawTableError::Rows { rows });
        }
        let rows = (0..rows)
            .map(|i| {
                let p = pressure(lo, hi, i, rows);
                let (mu, dmu_dp) = law.mu_and_derivative(p)?;
                Ok(LawRow {
                    pressure: p,
                    mu,
                    dmu_dp,
                })
            })
            .collect::<Result<Vec<_>, PressureError>>()?;
        let interpolation_error = interpolation_error(law, lo, hi, rows.len())?;
        Ok(LawTable {
            rows,
            interpolation_error,
        })
    }

    /// The fewest log-spaced rows of `law` from `lo` to `hi` (Pa) whose
    /// linear interpolation is within `tolerance` (relative, in
    /// [`LAW_TABLE_TOLERANCE_RANGE`]) of the law: doubling the rows until
    /// the error is met, then bisecting.
    pub fn for_tolerance(law: &FrictionLaw, lo: f64, hi: f64, tolerance: f64) -> Result<LawTable, LawTableError> {
        check_range(law, lo, hi)?;
        if !LAW_TOLERANCE.contains(tolerance) {
            return Err(LawTableError::Tolerance { tolerance });
        }
        let meets = |n: usize| interpolation_error(law, lo, hi, n).map(|e| (e <= tolerance, e));
        let mut n = 2;
        loop {
            let (ok, error) = meets(n)?;
            if ok {
                break;
            }
            if n == LAW_TABLE_MAX_ROWS {
                return Err(LawTableError::Unreachable { tolerance, error });
            }
            n = (2 * n).min(LAW_TABLE_MAX_ROWS);
        }
        // n meets the tolerance; the smallest that does lies in (n/2, n]
        // (the error falls as 1/n² once the rows resolve μ's curvature).
        let (mut fails, mut holds) = (n / 2, n);
        while holds - fails > 1 {
            let mid = fails + (holds - fails) / 2;
            if meets(mid)?.0 {
                holds = mid;
            } else {
                fails = mid;
            }
        }
        LawTable::with_rows(law, lo, hi, holds)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{OutOfRange, Params};

    fn law() -> FrictionLaw {
        FrictionLaw::new(Params::new(1.0, 0.001), 1e9, Some((1e4, 1e8)), OutOfRange::Error).unwrap()
    }

    #[test]
    fn the_rows_chosen_are_the_fewest_that_meet_the_tolerance() {
        let law = law();
        for tolerance in [1e-2, 1e-3, 1e-4] {
            let t = LawTable::for_tolerance(&law, 1e4, 1e8, tolerance).unwrap();
            assert!(t.interpolation_error <= tolerance);
            let fewer = LawTable::with_rows(&law, 1e4, 1e8, t.rows.len() - 1).unwrap();
            assert!(
                fewer.interpolation_error > tolerance,
                "{tolerance}: {} rows",
                t.rows.len()
            );
        }
    }

    #[test]
    fn rows_are_the_law_at_log_spaced_pressures() {
        let law = law();
        let t = LawTable::with_rows(&law, 1e5, 1e7, 5).unwrap();
        let p: Vec<f64> = t.rows.iter().map(|r| r.pressure).collect();
        for (got, want) in p.iter().zip([1e5, 10f64.powf(5.5), 1e6, 10f64.powf(6.5), 1e7]) {
            assert!((got / want - 1.0).abs() < 1e-15, "{got} vs {want}");
        }
        for r in &t.rows {
            assert_eq!((r.mu, r.dmu_dp), law.mu_and_derivative(r.pressure).unwrap());
        }
    }

    #[test]
    fn bad_requests_name_what_is_wrong() {
        let law = law();
        let range = LawTable::with_rows(&law, 1e3, 1e8, 10).unwrap_err();
        assert!(matches!(range, LawTableError::Range { .. }) && range.kind() == ErrorKind::Domain);
        let nan = LawTable::with_rows(&law, f64::NAN, 1e8, 10).unwrap_err();
        assert_eq!(nan.kind(), ErrorKind::Argument);
        for rows in [0, 1, LAW_TABLE_MAX_ROWS + 1] {
            let e = LawTable::with_rows(&law, 1e4, 1e8, rows).unwrap_err();
            assert_eq!(e, LawTableError::Rows { rows });
        }
        for tolerance in [0.0, 1e-7, 0.6, f64::NAN] {
            let e = LawTable::for_tolerance(&law, 1e4, 1e8, tolerance).unwrap_err();
            assert!(e.to_string().starts_with("tolerance = "), "{e}");
        }
    }
}
