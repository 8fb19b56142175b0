//! `FrictionLawCore`: μ(p) and dμ/dp of the contact pressure, in SI.

use crate::convert::{on_error, same_len, slice, slice_mut};
use crate::error::{raise, value_error, Failure};
use crate::model::ModelCore;
use crate::parallel::{curve_batch, cut_pairs, CURVE_WORK};
use ke_friction::{law_notes, FrictionLaw, LawFormat, LawTable, Named, OutOfRange, PressureError, StressUnit};
use numpy::{PyReadonlyArray1, PyReadwriteArray1};
use pyo3::prelude::*;

/// μ(p) of one surface pair on a material of hardness H.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct FrictionLawCore(pub FrictionLaw);

/// A batch's failure at `start` + its element's index, with the element's
/// own message (the Python layer adds the index in the array's shape).
fn failure(e: PressureError, start: usize) -> Failure {
    let index = start + e.index().unwrap_or(0);
    match e {
        PressureError::Pressure { value, lo, hi, .. } => Failure::at(
            index,
            &PressureError::Pressure {
                index: None,
                value,
                lo,
                hi,
            },
        ),
        e => Failure::at(index, &e),
    }
}

#[pymethods]
impl FrictionLawCore {
    /// The law of `model`'s parameters on hardness `hardness` (Pa), over
    /// [`lo`, `hi`] (Pa; both None: the default range), `policy` outside it.
    #[new]
    #[pyo3(signature = (model, hardness, lo, hi, policy))]
    fn new(model: &ModelCore, hardness: f64, lo: Option<f64>, hi: Option<f64>, policy: &str) -> PyResult<Self> {
        let policy = OutOfRange::parse(policy).map_err(value_error)?;
        let range = match (lo, hi) {
            (Some(lo), Some(hi)) => Some((lo, hi)),
            (None, None) => None,
            _ => return Err(value_error("pressure_range: give both ends or neither")),
        };
        FrictionLaw::new(model.0.params().clone(), hardness, range, policy)
            .map(FrictionLawCore)
            .map_err(raise)
    }

    fn hardness(&self) -> f64 {
        self.0.hardness()
    }

    fn range(&self) -> (f64, f64) {
        self.0.range()
    }

    fn policy(&self) -> &'static str {
        self.0.policy().name()
    }

    fn max_error(&self) -> f64 {
        self.0.max_error()
    }

    fn clamped(&self) -> u64 {
        self.0.clamped()
    }

    fn reset_clamped(&self) -> u64 {
        self.0.reset_clamped()
    }

    fn mu_scalar(&self, p: f64) -> PyResult<f64> {
        self.0.mu(p).map_err(raise)
    }

    fn mu_and_derivative_scalar(&self, p: f64) -> PyResult<(f64, f64)> {
        self.0.mu_and_derivative(p).map_err(raise)
    }

    /// μ into `out` by the core's batch; returns how many elements are
    /// NaN, or raises the first bad element's error with its flat index.
    fn mu_into(
        &self,
        py: Python<'_>,
        pressure: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let (law, on_error) = (&self.0, on_error(nan));
        curve_batch(py, "pressure", &pressure, &mut out, threads, |start, p, out| {
            law.mu_batch(p, out, on_error).map_err(|e| failure(e, start))
        })
    }

    /// μ and dμ/dp into `mu` and `dmu_dp`; as `mu_into`.
    fn mu_and_derivative_into(
        &self,
        py: Python<'_>,
        pressure: PyReadonlyArray1<'_, f64>,
        mut mu: PyReadwriteArray1<'_, f64>,
        mut dmu_dp: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let p = slice("pressure", &pressure)?;
        let (mu, dmu_dp) = (slice_mut("mu", &mut mu)?, slice_mut("dmu_dp", &mut dmu_dp)?);
        let n = mu.len();
        same_len(n, &[("pressure", p.len()), ("dmu_dp", dmu_dp.len())])?;
        let (law, on_error) = (&self.0, on_error(nan));
        py.detach(|| {
            CURVE_WORK.run(
                n,
                threads,
                |chunks| cut_pairs(mu, dmu_dp, chunks),
                |_| (),
                |chunk, (mu, dmu_dp)| {
                    let start = chunk.start;
                    law.mu_and_derivative_batch(&p[chunk], mu, dmu_dp, on_error)
                        .map_err(|e| failure(e, start))
                },
            )
        })
        .map_err(|failure| failure.into_pyerr(py))
    }

    /// The rows (p, μ, dμ/dp, flat) of a solver-ready table from `lo` to
    /// `hi` (`rows` of them, or the fewest within `tolerance`) and its
    /// measured interpolation error ([`LawTable`]).
    fn table(&self, py: Python<'_>, lo: f64, hi: f64, rows: Option<i64>, tolerance: f64) -> PyResult<(Vec<f64>, f64)> {
        let table = self.make_table(py, lo, hi, rows, tolerance)?;
        let flat = table.rows.iter().flat_map(|r| [r.pressure, r.mu, r.dmu_dp]).collect();
        Ok((flat, table.interpolation_error))
    }

    /// The same table as text in `format` ([`LawFormat`]'s names), the
    /// pressures in `stress_unit` ([`StressUnit`]'s), with the core's notes
    /// (CSV: none; its names line and rows only).
    // The arguments are `FrictionLaw.table`'s, one for one.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (lo, hi, rows, tolerance, format, stress_unit))]
    fn table_text(
        &self,
        py: Python<'_>,
        lo: f64,
        hi: f64,
        rows: Option<i64>,
        tolerance: f64,
        format: &str,
        stress_unit: &str,
    ) -> PyResult<String> {
        let format = LawFormat::parse(format).map_err(value_error)?;
        let unit = StressUnit::parse(stress_unit).map_err(value_error)?;
        let table = self.make_table(py, lo, hi, rows, tolerance)?;
        let law = &self.0;
        let notes = law_notes(
            law,
            &table,
            unit,
            rows.is_none().then_some(tolerance),
            &[law.params().describe()],
        );
        Ok(table.to_format(format, unit, &notes))
    }
}

impl FrictionLawCore {
    /// The table of `rows` rows, or the fewest within `tolerance`.
    fn make_table(&self, py: Python<'_>, lo: f64, hi: f64, rows: Option<i64>, tolerance: f64) -> PyResult<LawTable> {
        let rows = rows
            .map(|n| {
                usize::try_from(n).map_err(|_| {
                    value_error(format!(
                        "rows = {n} is out of range: must be {}",
                        ke_friction::bounds::LAW_ROWS.range()
                    ))
                })
            })
            .transpose()?;
        let law = &self.0;
        let table = py
            .detach(|| match rows {
                Some(n) => LawTable::with_rows(law, lo, hi, n),
                None => LawTable::for_tolerance(law, lo, hi, tolerance),
            })
            .map_err(raise)?;
        Ok(table)
    }
}
