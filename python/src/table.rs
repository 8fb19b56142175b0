//! `TableCore`: a table of μ(ψ, θ, F*).

use crate::convert::{on_error, record, same_len, slice, slice_mut};
use crate::curve::CurveCore;
use crate::error::{raise, Failure};
use crate::parallel::{cut, cut_pairs, in_pieces, Inputs, TABLE_WORK};
use ke_friction::Table;
use numpy::{PyReadonlyArray1, PyReadwriteArray1};
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::borrow::Cow;

/// A table of μ(ψ, θ, F*), and the bytes it was decoded from (`None`
/// for the embedded default table), so that it pickles as it was made.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct TableCore {
    table: Cow<'static, Table>,
    bytes: Option<Vec<u8>>,
}

/// Readies `table` for `n` lookups by this thread (its coefficients read
/// through into this core's cache, see [`Table::prepare_batch`]), unless
/// an argument is one value for all (`repeats`: the queries then touch few
/// of them).
fn read_through(table: &Table, repeats: bool, n: usize) {
    if !repeats {
        table.prepare_batch(n);
    }
}

impl TableCore {
    /// The table of a file's contents, which it keeps.
    fn decoded(bytes: Vec<u8>) -> Result<TableCore, ke_friction::TableError> {
        Ok(TableCore {
            table: Cow::Owned(Table::from_bytes(&bytes)?),
            bytes: Some(bytes),
        })
    }
}

#[pymethods]
impl TableCore {
    #[staticmethod]
    fn default() -> TableCore {
        TableCore {
            table: Cow::Borrowed(Table::embedded()),
            bytes: None,
        }
    }

    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<TableCore> {
        // The read's errors name the path themselves.
        let bytes = Table::read_file(&path).map_err(raise)?;
        TableCore::decoded(bytes).map_err(|e| raise(e.in_file(&path)))
    }

    /// The table of a table file's contents (as `load` reads them).
    #[staticmethod]
    fn from_bytes(data: &[u8]) -> PyResult<TableCore> {
        TableCore::decoded(data.to_vec()).map_err(raise)
    }

    /// The contents of the table's file: the bytes it was decoded from
    /// (the embedded table's for the default one).
    fn to_bytes<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        PyBytes::new(py, self.bytes.as_deref().unwrap_or(Table::embedded_bytes()))
    }

    /// Whether this is the embedded default table (`default()`).
    fn is_default(&self) -> bool {
        self.bytes.is_none()
    }

    fn mu_scalar(&self, psi: f64, theta: f64, f_star: f64) -> PyResult<f64> {
        self.table.mu(psi, theta, f_star).map_err(raise)
    }

    fn mu_with_slope_scalar(&self, psi: f64, theta: f64, f_star: f64) -> PyResult<(f64, f64)> {
        self.table.mu_with_slope(psi, theta, f_star).map_err(raise)
    }

    /// μ into `out` by the core's batch (`OnError::Nan` if `nan`, else
    /// `OnError::Stop`); returns how many elements are NaN, or raises the
    /// first bad element's error with its flat index as the exception's
    /// `index`. Each input has `out`'s length or is one value for all.
    /// `threads`: the most threads to use, 0 for one per core (large
    /// arrays only, see [`TABLE_WORK`]).
    #[allow(clippy::too_many_arguments)]
    fn mu_into(
        &self,
        py: Python<'_>,
        psi: PyReadonlyArray1<'_, f64>,
        theta: PyReadonlyArray1<'_, f64>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let (p, t, f) = (slice("psi", &psi)?, slice("theta", &theta)?, slice("f_star", &f_star)?);
        let out = slice_mut("out", &mut out)?;
        let n = out.len();
        let inputs = Inputs::new(n, [("psi", &*p), ("theta", &*t), ("f_star", &*f)])?;
        let (table, on_error) = (&*self.table, on_error(nan));
        py.detach(|| {
            TABLE_WORK.run(
                n,
                threads,
                |chunks| cut(out, 1, chunks),
                |m| read_through(table, inputs.repeats, m),
                |chunk, out| {
                    let start = chunk.start;
                    in_pieces(chunk, inputs.piece(), |r| {
                        let o = &mut out[r.start - start..r.end - start];
                        let [p, t, f] = inputs.slices(r.clone());
                        table
                            .mu_batch_with(p, t, f, o, on_error)
                            .map_err(|e| Failure::of_batch(e, r.start))
                    })
                },
            )
        })
        .map_err(|failure| failure.into_pyerr(py))
    }

    /// μ and ∂μ/∂F* into `mu` and `slope`; as `mu_into`.
    #[allow(clippy::too_many_arguments)]
    fn mu_with_slope_into(
        &self,
        py: Python<'_>,
        psi: PyReadonlyArray1<'_, f64>,
        theta: PyReadonlyArray1<'_, f64>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut mu: PyReadwriteArray1<'_, f64>,
        mut slope: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let (p, t, f) = (slice("psi", &psi)?, slice("theta", &theta)?, slice("f_star", &f_star)?);
        let (mu, slope) = (slice_mut("mu", &mut mu)?, slice_mut("slope", &mut slope)?);
        let n = mu.len();
        same_len(n, &[("slope", slope.len())])?;
        let inputs = Inputs::new(n, [("psi", &*p), ("theta", &*t), ("f_star", &*f)])?;
        let (table, on_error) = (&*self.table, on_error(nan));
        py.detach(|| {
            TABLE_WORK.run(
                n,
                threads,
                |chunks| cut_pairs(mu, slope, chunks),
                |m| read_through(table, inputs.repeats, m),
                |chunk, (mu, slope)| {
                    let start = chunk.start;
                    in_pieces(chunk, inputs.piece(), |r| {
                        let k = r.start - start..r.end - start;
                        let [p, t, f] = inputs.slices(r.clone());
                        table
                            .mu_with_slope_into(p, t, f, &mut mu[k.clone()], &mut slope[k], on_error)
                            .map_err(|e| Failure::of_batch(e, r.start))
                    })
                },
            )
        })
        .map_err(|failure| failure.into_pyerr(py))
    }

    /// Refuses a model whose constants are not the table's (a
    /// `ValueError` naming the first that differs, with both values).
    fn check_constants(&self, model: PyRef<'_, crate::model::ModelCore>) -> PyResult<()> {
        self.table.check_constants(&model.0.params().constants).map_err(raise)
    }

    fn curve(&self, psi: f64, theta: f64) -> PyResult<CurveCore> {
        self.table.curve(psi, theta).map(CurveCore).map_err(raise)
    }

    /// The table's record, `TableInfo` as the core serialises it (the
    /// names of `kefric info --json` and of a NumPy export's `metadata`).
    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        record(py, serde_json::to_string(self.table.info()))
    }

    /// Whether lookups run the fast (AVX2) kernel on this CPU.
    fn fast_kernel(&self) -> bool {
        self.table.fast_kernel()
    }
}
