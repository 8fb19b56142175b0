//! `SurfaceCore`: a measured rough surface (or the equivalent surface of
//! two), its statistics, height distribution and model inputs (MODEL.md
//! §10), as `kefric surface` computes them.

use crate::convert::{record, slice};
use crate::distribution::DistributionCore;
use crate::error::{exception, raise, read_error, value_error};
use crate::model::ModelCore;
use ke_friction::topography::{
    read_file, Derivative, Detrend, ReadOptions, StatsOptions, Surface, Topography, MAX_POINTS,
};
use ke_friction::{Classify, Load, Materials};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use std::path::PathBuf;

/// The detrending called `name` (the core's names).
fn detrend_of(name: &str) -> PyResult<Detrend> {
    Detrend::from_name(name).ok_or_else(|| {
        let names: Vec<String> = Detrend::ALL.iter().map(|d| format!("{:?}", d.name())).collect();
        value_error(format!("detrend = {name:?}: must be one of {}", names.join(", ")))
    })
}

/// The derivative estimate called `name` (the core's names).
fn derivative_of(name: &str) -> PyResult<Derivative> {
    Derivative::from_name(name).ok_or_else(|| {
        let names: Vec<String> = Derivative::ALL.iter().map(|d| format!("{:?}", d.name())).collect();
        value_error(format!("derivative = {name:?}: must be one of {}", names.join(", ")))
    })
}

/// The statistics' options of the Python keywords.
fn options(detrend: &str, derivative: &str) -> PyResult<StatsOptions> {
    Ok(StatsOptions {
        detrend: detrend_of(detrend)?,
        derivative: derivative_of(derivative)?,
        lambda_s: None,
        lambda_c: None,
    })
}

/// The topography of `heights` (row-major, `ny` rows of `nx`): a profile
/// without `dy`, else a map.
fn topography(heights: Vec<f64>, nx: usize, ny: usize, dx: f64, dy: Option<f64>) -> PyResult<Topography> {
    match dy {
        None if ny == 1 => Topography::profile(heights, dx),
        None => return Err(value_error(format!("a map of {ny} rows needs dy"))),
        Some(dy) => Topography::map(heights, nx, ny, dx, dy),
    }
    .map_err(raise)
}

/// The materials of `Surface.model`'s keywords, in the order e1, nu1, e2,
/// nu2, hardness, delta_gamma, epsilon.
fn materials((e1, nu1, e2, nu2, hardness, delta_gamma, epsilon): (f64, f64, f64, f64, f64, f64, f64)) -> Materials {
    Materials {
        e1,
        nu1,
        e2,
        nu2,
        hardness,
        delta_gamma,
        epsilon,
    }
}

/// A measured surface: one topography, or the equivalent surface of two.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct SurfaceCore(Surface);

#[pymethods]
impl SurfaceCore {
    /// The surface of one topography (`parts` of one) or of two pressed
    /// together: each part `(heights, nx, ny, dx, dy)`, heights row-major
    /// in metres (NaN = missing), `dy` None for a profile.
    #[staticmethod]
    #[allow(clippy::type_complexity)]
    fn new(
        py: Python<'_>,
        parts: Vec<(PyReadonlyArray1<'_, f64>, usize, usize, f64, Option<f64>)>,
        detrend: &str,
        derivative: &str,
    ) -> PyResult<SurfaceCore> {
        let options = options(detrend, derivative)?;
        let mut topographies = Vec::with_capacity(parts.len());
        for (heights, nx, ny, dx, dy) in &parts {
            let heights = slice("heights", heights)?.into_owned();
            topographies.push(topography(heights, *nx, *ny, *dx, *dy)?);
        }
        let surface = py.detach(|| match <[Topography; 1]>::try_from(topographies) {
            Ok([one]) => Ok(Surface::new(one, options)),
            Err(v) => match <[Topography; 2]>::try_from(v) {
                Ok([a, b]) => Ok(Surface::pair(a, b, options)),
                Err(v) => Err(v.len()),
            },
        });
        match surface {
            Ok(s) => s.map(SurfaceCore).map_err(raise),
            Err(n) => Err(value_error(format!("a surface has one or two parts, not {n}"))),
        }
    }

    /// The surface in the file `path` (X3P, `.npy` or text), by the core's
    /// reader: `dx`, `dy` in metres for files that give none, `z_unit`
    /// metres per unit of `.npy` and text heights, `xy_unit` of the x, y
    /// columns of text (both finite and > 0), `max_points` the most points
    /// the surface may have (None: the core's `MAX_POINTS`). A file that
    /// cannot be read is an `OSError`, a bad one or one over `max_points`
    /// a `ValueError`, heights that cannot be allocated a `MemoryError`;
    /// all name the file.
    #[staticmethod]
    #[pyo3(signature = (path, dx, dy, z_unit, xy_unit, detrend, derivative, max_points=None))]
    #[allow(clippy::too_many_arguments)]
    fn read(
        py: Python<'_>,
        path: PathBuf,
        dx: Option<f64>,
        dy: Option<f64>,
        z_unit: f64,
        xy_unit: f64,
        detrend: &str,
        derivative: &str,
        max_points: Option<u64>,
    ) -> PyResult<SurfaceCore> {
        let options = options(detrend, derivative)?;
        let read = ReadOptions {
            dx,
            dy,
            z_unit,
            xy_unit,
            max_points: max_points.unwrap_or(MAX_POINTS),
            ..ReadOptions::default()
        };
        let topography = py.detach(|| read_file(&path, &read)).map_err(read_error)?;
        py.detach(|| Surface::new(topography, options))
            .map(SurfaceCore)
            .map_err(|e| exception(e.kind(), format!("{}: {e}", path.display())))
    }

    /// Two surfaces pressed together: the equivalent surface of the
    /// topographies of `a` and `b` (one each), statistics taken with
    /// `detrend` and `derivative`.
    #[staticmethod]
    fn pair(
        py: Python<'_>,
        a: &SurfaceCore,
        b: &SurfaceCore,
        detrend: &str,
        derivative: &str,
    ) -> PyResult<SurfaceCore> {
        let options = options(detrend, derivative)?;
        let one = |s: &SurfaceCore, name: &str| match s.0.parts() {
            [(t, _)] => Ok(t.clone()),
            _ => Err(value_error(format!(
                "{name} is a pair already: give two single surfaces"
            ))),
        };
        let (ta, tb) = (one(a, "a")?, one(b, "b")?);
        py.detach(|| {
            if a.0.options() == options && b.0.options() == options {
                // Their statistics are taken already.
                Surface::join(a.0.clone(), b.0.clone())
            } else {
                Surface::pair(ta, tb, options)
            }
        })
        .map(SurfaceCore)
        .map_err(raise)
    }

    /// The statistics: the core's `SurfaceStats` record (what `kefric
    /// surface --json` prints as "surface").
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        record(py, serde_json::to_string(self.0.stats()))
    }

    /// The parts' own statistics records (one, or two for a pair).
    fn parts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let parts: Vec<_> = self.0.parts().iter().map(|(_, s)| s).collect();
        record(py, serde_json::to_string(&parts))
    }

    /// Whether this is the equivalent surface of two.
    fn is_pair(&self) -> bool {
        self.0.parts().len() == 2
    }

    /// The parts' topographies, `(heights, nx, ny, dx, dy)` each: heights
    /// row-major (metres, NaN = missing), `dy` None for a profile.
    #[allow(clippy::type_complexity)]
    fn topographies<'py>(&self, py: Python<'py>) -> Vec<(Bound<'py, PyArray1<f64>>, usize, usize, f64, Option<f64>)> {
        self.0
            .parts()
            .iter()
            .map(|(t, _)| (PyArray1::from_slice(py, t.heights()), t.nx(), t.ny(), t.dx(), t.dy()))
            .collect()
    }

    /// `(detrend, derivative)`, by the Python keywords' names.
    fn options(&self) -> (&'static str, &'static str) {
        let o = self.0.options();
        (o.detrend.name(), o.derivative.name())
    }

    /// The height distribution of `family` (None: pearson), the core's
    /// `Surface::distribution`.
    #[pyo3(signature = (family=None))]
    fn distribution(&self, py: Python<'_>, family: Option<&str>) -> PyResult<DistributionCore> {
        py.detach(|| self.0.distribution(family))
            .map(DistributionCore::of)
            .map_err(raise)
    }

    /// What the empirical density of the surface is made from: each
    /// part's detrended heights (NaN = missing) and standard deviation σ
    /// (`DistributionCore.empirical` of the one, or
    /// `DistributionCore.empirical_sum` of the two, rebuilds it).
    fn empirical_parts<'py>(&self, py: Python<'py>) -> PyResult<Vec<(Bound<'py, PyArray1<f64>>, f64)>> {
        let detrend = self.0.options().detrend;
        let mut out = Vec::with_capacity(2);
        for (t, s) in self.0.parts() {
            let heights = py.detach(|| t.detrended(detrend)).map_err(raise)?;
            out.push((PyArray1::from_vec(py, heights), s.sigma));
        }
        Ok(out)
    }

    /// The model's parameters of `materials` on this surface with the
    /// distribution `family`, fit and model (`Params` record, as `kefric
    /// surface --json` prints as "model").
    fn params<'py>(
        &self,
        py: Python<'py>,
        materials: (f64, f64, f64, f64, f64, f64, f64),
        distribution: &DistributionCore,
    ) -> PyResult<Bound<'py, PyAny>> {
        let p = self
            .0
            .params(&self::materials(materials), distribution.dist.clone())
            .map_err(raise)?;
        record(py, serde_json::to_string(&p))
    }

    /// The friction of a load (a `force` on an `area`, or a `pressure`)
    /// on `model`, made from `materials` on this surface: the core's
    /// `Friction` record.
    #[pyo3(signature = (model, materials, force, area, pressure))]
    fn friction<'py>(
        &self,
        py: Python<'py>,
        model: &ModelCore,
        materials: (f64, f64, f64, f64, f64, f64, f64),
        force: Option<f64>,
        area: Option<f64>,
        pressure: Option<f64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let load = match (force, area, pressure) {
            (Some(force), Some(area), None) => Load::Force { force, area },
            (None, None, Some(p)) => Load::Pressure(p),
            _ => return Err(value_error("give force with area, or pressure alone")),
        };
        let physical = self.0.physical(&self::materials(materials));
        let friction = py.detach(|| load.friction(&model.0, &physical)).map_err(raise)?;
        record(py, serde_json::to_string(&friction))
    }
}
