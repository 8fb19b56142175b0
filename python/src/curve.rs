//! `CurveCore`: μ(F*) of one surface pair.

use crate::convert::{on_error, same_len, slice, slice_mut};
use crate::error::{raise, Failure};
use crate::model::ModelCore;
use crate::parallel::{curve_batch, cut_pairs, CURVE_WORK};
use ke_friction::Curve;
use numpy::{PyReadonlyArray1, PyReadwriteArray1};
use pyo3::prelude::*;

/// μ(F*) of one surface pair.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct CurveCore(pub Curve);

#[pymethods]
impl CurveCore {
    #[staticmethod]
    fn from_model(model: &ModelCore, f_star_min: f64, f_star_max: f64) -> PyResult<CurveCore> {
        Curve::from_model(&model.0, f_star_min, f_star_max)
            .map(CurveCore)
            .map_err(raise)
    }

    fn range(&self) -> (f64, f64) {
        self.0.range()
    }

    fn max_error(&self) -> f64 {
        self.0.max_error()
    }

    fn mu_scalar(&self, f_star: f64) -> PyResult<f64> {
        self.0.mu(f_star).map_err(raise)
    }

    fn mu_with_slope_scalar(&self, f_star: f64) -> PyResult<(f64, f64)> {
        self.0.mu_with_slope(f_star).map_err(raise)
    }

    /// μ into `out` by the core's batch; returns how many elements are
    /// NaN, or raises as `TableCore.mu_into`.
    fn mu_into(
        &self,
        py: Python<'_>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let (curve, on_error) = (&self.0, on_error(nan));
        curve_batch(py, "f_star", &f_star, &mut out, threads, |start, f, out| {
            curve
                .mu_batch_with(f, out, on_error)
                .map_err(|e| Failure::of_batch(e, start))
        })
    }

    /// μ and dμ/dF* into `mu` and `slope`; as `mu_into`.
    fn mu_with_slope_into(
        &self,
        py: Python<'_>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut mu: PyReadwriteArray1<'_, f64>,
        mut slope: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let f = slice("f_star", &f_star)?;
        let (mu, slope) = (slice_mut("mu", &mut mu)?, slice_mut("slope", &mut slope)?);
        let n = mu.len();
        same_len(n, &[("f_star", f.len()), ("slope", slope.len())])?;
        let (curve, on_error) = (&self.0, on_error(nan));
        py.detach(|| {
            CURVE_WORK.run(
                n,
                threads,
                |chunks| cut_pairs(mu, slope, chunks),
                |_| (),
                |chunk, (mu, slope)| {
                    let start = chunk.start;
                    curve
                        .mu_with_slope_into(&f[chunk], mu, slope, on_error)
                        .map_err(|e| Failure::of_batch(e, start))
                },
            )
        })
        .map_err(|failure| failure.into_pyerr(py))
    }
}
