//! `ContainerCore`: one surface of a contact.engineering container (its
//! measurements, read and detrended as SurfaceTopography reads them), the
//! combined spectrum, μ from the whole band and the scan over λs, as
//! `kefric surface CONTAINER` computes them (the core's
//! `topography::container`; its records are the CLI's `--json`).

use crate::convert::record;
use crate::error::{raise, value_error};
use crate::surface::request_error;
use ke_friction::topography::container::{
    combined_psd, container_analysis, container_scan, measurement_spectra, read_container, read_container_bytes,
    ContainerRecord, ContainerSurface, MeasurementPsd, MeasurementRecord, Resolved, ScanRecord,
};
use ke_friction::topography::{LambdaS, LoadInputs, SurfaceRequest, MAX_POINTS};
use ke_friction::{Family, Fit, ModelKind, Named, Warnings};
use numpy::PyArray1;
use pyo3::prelude::*;
use std::path::PathBuf;

/// One surface of a container, its measurements' reliable spectra taken.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct ContainerCore {
    /// The container's name in messages (its path, or the name given with
    /// its bytes).
    name: String,
    /// The names of the container's surfaces (None where unnamed).
    surfaces: Vec<Option<String>>,
    /// The surface chosen.
    surface: ContainerSurface,
    /// Its measurements' reliable spectra, in their order.
    spectra: Vec<MeasurementPsd>,
}

/// `(q, c)` as NumPy arrays.
type Arrays<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

/// The request of the Python keywords (the core checks them; its errors
/// name the keywords).
#[allow(clippy::too_many_arguments)]
fn request(
    materials: Option<[f64; 7]>,
    distribution: Option<&str>,
    fit: &str,
    model: &str,
    force: Option<Vec<f64>>,
    area: Option<f64>,
    pressure: Option<Vec<f64>>,
    lambda_s: Option<f64>,
    lambda_c: Option<f64>,
) -> PyResult<SurfaceRequest> {
    Ok(SurfaceRequest {
        materials: materials.map_or([None; 7], |m| m.map(Some)),
        distribution: distribution.map(Family::parse).transpose().map_err(value_error)?,
        fit: Fit::parse(fit).map_err(value_error)?,
        model: ModelKind::parse(model).map_err(value_error)?,
        loads: LoadInputs { force, area, pressure },
        lambda_s: lambda_s.map(LambdaS::Metres),
        lambda_c,
        ..SurfaceRequest::default()
    })
}

#[pymethods]
impl ContainerCore {
    /// The container at `path`, or of the bytes `data` called `name`:
    /// its surface number `surface`; `tip_radius` or `resolution` (m,
    /// the resolution first) for the measurements whose metadata gives
    /// neither; `max_points` each measurement's limit (None: the
    /// library's). OSError if the file cannot be read, ValueError for a
    /// container that is not one, is damaged, or whose metadata or data
    /// files are bad (naming the member or field).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (path=None, data=None, name=None, surface=0, tip_radius=None, resolution=None,
                        max_points=None))]
    fn read(
        py: Python<'_>,
        path: Option<PathBuf>,
        data: Option<&[u8]>,
        name: Option<String>,
        surface: usize,
        tip_radius: Option<f64>,
        resolution: Option<f64>,
        max_points: Option<u64>,
    ) -> PyResult<ContainerCore> {
        let request = SurfaceRequest {
            tip_radius,
            resolution,
            max_points: max_points.unwrap_or(MAX_POINTS),
            ..SurfaceRequest::default()
        };
        let options = request.container_options().map_err(request_error)?;
        let (name, surfaces) = match (path, data) {
            (Some(path), None) => {
                let name = path.display().to_string();
                let surfaces = py.detach(|| read_container(&path, &options)).map_err(raise)?;
                (name, surfaces)
            }
            (None, Some(data)) => {
                let name = name.unwrap_or_else(|| "the container".to_string());
                let surfaces = py
                    .detach(|| read_container_bytes(data, &name, &options))
                    .map_err(raise)?;
                (name, surfaces)
            }
            _ => return Err(value_error("give a path or the data (bytes), not both")),
        };
        let names: Vec<Option<String>> = surfaces.iter().map(|s| s.name.clone()).collect();
        let count = surfaces.len();
        let Some(chosen) = surfaces.into_iter().nth(surface) else {
            return Err(value_error(format!(
                "surface = {surface} is out of range: the container {name} has {count} surface{} (0 to {})",
                if count == 1 { "" } else { "s" },
                count.saturating_sub(1)
            )));
        };
        let spectra = py.detach(|| measurement_spectra(&chosen.measurements));
        Ok(ContainerCore {
            name,
            surfaces: names,
            surface: chosen,
            spectra,
        })
    }

    /// The container's name in messages.
    fn name(&self) -> &str {
        &self.name
    }

    /// The names of the container's surfaces (None where unnamed).
    fn surfaces(&self) -> Vec<Option<String>> {
        self.surfaces.clone()
    }

    /// The measurements' records (the core's `MeasurementRecord`, as
    /// `kefric surface CONTAINER --json` prints them).
    fn measurements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let records = MeasurementRecord::all(&self.surface, &self.spectra);
        record(py, serde_json::to_string(&records))
    }

    /// `(combined, own)`: the combined spectrum `(q, c, contributors)` at
    /// `per_decade` bins a decade (None if no measurement has a reliable
    /// spectrum) and each measurement's own reliable spectrum `(q, c)`
    /// (None where it has none).
    #[allow(clippy::type_complexity)]
    fn psd<'py>(
        &self,
        py: Python<'py>,
        per_decade: u32,
    ) -> PyResult<(
        Option<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>, Vec<Vec<usize>>)>,
        Vec<Option<Arrays<'py>>>,
    )> {
        if !(1..=1000).contains(&per_decade) {
            return Err(value_error(format!(
                "nb_points_per_decade = {per_decade} is out of range: 1 to 1000"
            )));
        }
        let combined = py.detach(|| combined_psd(&self.spectra, per_decade));
        let combined = combined.map(|c| {
            (
                PyArray1::from_vec(py, c.psd.q),
                PyArray1::from_vec(py, c.psd.c),
                c.contributors,
            )
        });
        let own = self
            .spectra
            .iter()
            .map(|s| {
                s.psd
                    .as_ref()
                    .map(|p| (PyArray1::from_slice(py, &p.q), PyArray1::from_slice(py, &p.c)))
            })
            .collect();
        Ok((combined, own))
    }

    /// μ from the whole band (the band `lambda_s`..`lambda_c`, m, where
    /// given) with `materials` (the seven, in `Materials::FIELDS`' order),
    /// the height model, fit and model, at the loads (`force` on `area`,
    /// or `pressure`; none: the model's inputs alone): `{"record": the
    /// core's `ContainerRecord`, "warnings": one summary a kind}`.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (materials, distribution, fit, model, force, area, pressure, lambda_s, lambda_c))]
    fn friction<'py>(
        &self,
        py: Python<'py>,
        materials: [f64; 7],
        distribution: Option<&str>,
        fit: &str,
        model: &str,
        force: Option<Vec<f64>>,
        area: Option<f64>,
        pressure: Option<Vec<f64>>,
        lambda_s: Option<f64>,
        lambda_c: Option<f64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let request = request(
            Some(materials),
            distribution,
            fit,
            model,
            force,
            area,
            pressure,
            lambda_s,
            lambda_c,
        )?;
        let (materials, loads) = request.container_model().map_err(request_error)?;
        let band = request
            .container_band(&Resolved::of(&self.spectra))
            .map_err(request_error)?;
        let how = request.model_of(materials);
        let a = py
            .detach(|| {
                container_analysis(
                    &self.surface.measurements,
                    &self.spectra,
                    band,
                    ke_friction::topography::container::COMBINED_POINTS_PER_DECADE,
                    &how,
                    &loads,
                )
            })
            .map_err(|e| request_error(request.container_failure(&e, &self.name)))?;
        let mut warnings = Warnings::new();
        warnings.extend(a.warnings.iter().cloned());
        let doc = ContainerRecord::new(&self.surface, &self.spectra, &a);
        let out = serde_json::json!({
            "record": serde_json::to_value(&doc).map_err(value_error)?,
            "warnings": serde_json::to_value(warnings.summaries().collect::<Vec<_>>()).map_err(value_error)?,
        });
        record(py, serde_json::to_string(&out))
    }

    /// The scan over λs from the smallest reliable scale of any
    /// measurement towards `lambda_c` (m; None: the largest scale any
    /// resolves), `per_decade` a decade, with the materials (and
    /// optionally one load) as `friction`'s: `{"rows": the core's
    /// `ScanRecord` of each row, "warnings": the rows' summaries}`.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (materials, distribution, fit, model, force, area, pressure, lambda_c, per_decade))]
    fn scan<'py>(
        &self,
        py: Python<'py>,
        materials: [f64; 7],
        distribution: Option<&str>,
        fit: &str,
        model: &str,
        force: Option<Vec<f64>>,
        area: Option<f64>,
        pressure: Option<Vec<f64>>,
        lambda_c: Option<f64>,
        per_decade: u32,
    ) -> PyResult<Bound<'py, PyAny>> {
        if !ke_friction::topography::PER_DECADE.contains(f64::from(per_decade)) {
            return Err(value_error(format!(
                "per_decade = {per_decade} is out of range: must be {}",
                ke_friction::topography::PER_DECADE.range()
            )));
        }
        let request = request(
            Some(materials),
            distribution,
            fit,
            model,
            force,
            area,
            pressure,
            None,
            lambda_c,
        )?;
        let (materials, loads) = request.container_model().map_err(request_error)?;
        // The band's end checked as for `friction` (> 0, finite).
        request
            .container_band(&Resolved::of(&self.spectra))
            .map_err(request_error)?;
        let how = request.model_of(materials);
        let rows = py
            .detach(|| {
                container_scan(
                    &self.surface.measurements,
                    &self.spectra,
                    lambda_c,
                    per_decade,
                    &how,
                    &loads,
                )
            })
            .map_err(|e| request_error(request.container_failure(&e, &self.name)))?;
        let mut warnings = Warnings::new();
        for row in &rows {
            if let Ok(a) = &row.result {
                warnings.note(a.warnings.iter().cloned());
            }
        }
        let records: Vec<ScanRecord<'_>> = rows.iter().map(|r| ScanRecord::new(&self.surface, r)).collect();
        let out = serde_json::json!({
            "rows": serde_json::to_value(&records).map_err(value_error)?,
            "warnings": serde_json::to_value(warnings.summaries().collect::<Vec<_>>()).map_err(value_error)?,
        });
        record(py, serde_json::to_string(&out))
    }
}
