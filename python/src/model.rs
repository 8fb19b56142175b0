//! `ModelCore`: the model by direct integration, and the parameters of
//! physical inputs.

use crate::convert::{record, same_len, slice, slice_mut};
use crate::distribution::DistributionCore;
use crate::error::{raise, value_error, Failure};
use crate::parallel::{cut, MODEL_WORK};
use ke_friction::{Classify, Constants, ErrorKind, Fit, Materials, Model, ModelKind, Named, Params};
use numpy::{PyReadonlyArray1, PyReadwriteArray1};
use pyo3::prelude::*;

/// The model by direct integration.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct ModelCore(pub Model);

#[pymethods]
impl ModelCore {
    /// The model at (ψ, θ); each constant left out (None) is the core's
    /// default (`Constants::default()`, see `DEFAULTS`; the Gaussian for
    /// `distribution`, which the Python layer resolves from its arguments).
    #[new]
    #[pyo3(signature = (psi, theta, beta=None, nu=None, eps_star=None, fit=None, model=None, distribution=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        psi: f64,
        theta: f64,
        beta: Option<f64>,
        nu: Option<f64>,
        eps_star: Option<f64>,
        fit: Option<&str>,
        model: Option<&str>,
        distribution: Option<PyRef<'_, DistributionCore>>,
    ) -> PyResult<ModelCore> {
        let mut c = Constants::default();
        if let Some(fit) = fit {
            c.fit = Fit::parse(fit).map_err(value_error)?;
        }
        if let Some(model) = model {
            c.kind = ModelKind::parse(model).map_err(value_error)?;
        }
        c.beta = beta.unwrap_or(c.beta);
        c.nu = nu.unwrap_or(c.nu);
        c.eps_star = eps_star.unwrap_or(c.eps_star);
        if let Some(d) = distribution {
            c.distribution = d.dist.clone();
        }
        Model::new(c.unchecked_at(psi, theta)).map(ModelCore).map_err(raise)
    }

    /// The contacts at `x` (F* if `at_f_star`, else h*) into the seven
    /// output arrays (h*, d*, P*, Fs*, Q*, F*, μ); returns how many points
    /// are NaN (with `nan`: a point the model cannot answer, but for an
    /// internal error, which raises), or raises the first bad point's
    /// error with its index as the exception's `index`. `threads` as
    /// `TableCore.mu_into`.
    #[allow(clippy::too_many_arguments)]
    fn contacts_into(
        &self,
        py: Python<'_>,
        x: PyReadonlyArray1<'_, f64>,
        at_f_star: bool,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<usize> {
        let x = slice("x", &x)?;
        let out = slice_mut("out", &mut out)?;
        same_len(7 * x.len(), &[("out", out.len())])?;
        let model = &self.0;
        py.detach(|| {
            MODEL_WORK.run(
                x.len(),
                threads,
                |chunks| cut(out, 7, chunks),
                |_| (),
                |chunk, out| {
                    let mut bad = 0;
                    let start = chunk.start;
                    for (i, (&v, row)) in x[chunk].iter().zip(out.chunks_exact_mut(7)).enumerate() {
                        let c = if at_f_star {
                            model.at_f_star(v)
                        } else {
                            model.at_h_star(v)
                        };
                        match c {
                            Ok(c) => row.copy_from_slice(&[
                                c.h_star,
                                c.d_star,
                                c.p_star,
                                c.fs_star,
                                c.q_star,
                                c.f_star,
                                c.mu.unwrap_or(f64::NAN),
                            ]),
                            Err(e) if nan && e.kind() != ErrorKind::Internal => {
                                row.fill(f64::NAN);
                                bad += 1;
                            }
                            Err(e) => return Err(Failure::at(start + i, &e)),
                        }
                    }
                    Ok(bad)
                },
            )
        })
        .map_err(|failure| failure.into_pyerr(py))
    }

    /// The model's parameters: the core's `Params` record (psi, theta,
    /// beta, nu, eps_star, fit, model, distribution, skewness, kurtosis,
    /// and heights, their number, for an empirical density).
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        record(py, serde_json::to_string(self.0.params()))
    }
}

/// The model's parameters of SI inputs ([`Params::from_physical`]): the
/// materials (in `Materials::FIELDS`' order, `_core.MATERIALS`) on a
/// surface of roughness `sigma`, `radius`, `density`; the core's `Params`
/// record, as `kefric params --json` prints it.
#[pyfunction]
pub fn params_from_physical<'py>(
    py: Python<'py>,
    materials: [f64; 7],
    sigma: f64,
    radius: f64,
    density: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let phys = Materials::from_array(materials).with_roughness(sigma, radius, density);
    let p = Params::from_physical(&phys).map_err(raise)?;
    record(py, serde_json::to_string(&p))
}

/// The core's default constants (`Constants::default()`: beta, nu,
/// eps_star, fit, model, distribution, skewness, kurtosis), for
/// `_core.DEFAULTS`.
pub fn defaults(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    record(py, serde_json::to_string(&Constants::default()))
}

/// The plausibility warnings (the core's `Warnings`, one summary a kind:
/// its worst warning's record with `count` and `of`) of the contacts in
/// `rows`, 7 columns a contact as `ModelCore.contacts_into` writes them
/// (h*, d*, P*, Fs*, Q*, F*, μ; a row of NaN, a point without a result,
/// is skipped; μ NaN is none).
#[pyfunction]
pub fn contact_warnings<'py>(py: Python<'py>, rows: PyReadonlyArray1<'py, f64>) -> PyResult<Bound<'py, PyAny>> {
    let rows = slice("rows", &rows)?;
    let mut warnings = ke_friction::Warnings::new();
    for r in rows.chunks_exact(7) {
        if r[0].is_nan() {
            continue;
        }
        warnings.note(ke_friction::Warning::of_point(
            r[5],
            r[0],
            r[6].is_finite().then_some(r[6]),
        ));
    }
    if warnings.is_empty() {
        // The common case, without a JSON round trip (4.5 us → ~0.3 us a call).
        return Ok(pyo3::types::PyList::empty(py).into_any());
    }
    let summaries: Vec<ke_friction::Summary<'_>> = warnings.summaries().collect();
    crate::convert::record(py, serde_json::to_string(&summaries))
}
