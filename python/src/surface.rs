//! `SurfaceCore`: a measured rough surface (or the equivalent surface of
//! two), its statistics, height distribution and model inputs (MODEL.md
//! §10), as `kefric surface` computes them.

use crate::convert::{record, slice};
use crate::distribution::DistributionCore;
use crate::error::{exception, raise, value_error};
use crate::model::ModelCore;
use ke_friction::topography::{
    complete_part, default_distances, psd_all, scale_dependent_curvature, scale_dependent_slope, scan,
    tip_reliability_cutoff, Channel, Cutoff, Derivative, Detrend, Field, FilterError, LambdaS, LoadInputs, Psd,
    Rectangle, RequestError, ScanRange, Source, StatsError, StatsOptions, Surface, SurfaceRequest, Topography, Window,
    MAX_POINTS,
};
use ke_friction::{Classify, Family, Load, Materials, Named};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use std::path::PathBuf;

/// The detrending called `name` (the core's names).
/// Metres per unit of a length unit's name or symbol (`"um"`, `"µm"`,
/// `"Å"`: the core's `LengthUnit::from_symbol`, the names `kefric surface
/// --z-unit` takes); ValueError listing the names otherwise.
#[pyfunction]
pub fn length_unit(name: &str) -> PyResult<f64> {
    ke_friction::LengthUnit::from_symbol(name)
        .map(ke_friction::LengthUnit::metres)
        .map_err(raise)
}

fn detrend_of(name: &str) -> PyResult<Detrend> {
    Detrend::parse(name).map_err(value_error)
}

/// The derivative estimate called `name` (the core's names).
fn derivative_of(name: &str) -> PyResult<Derivative> {
    Derivative::parse(name).map_err(value_error)
}

/// The statistics' options of the Python keywords (no filters).
fn options(detrend: &str, derivative: &str) -> PyResult<StatsOptions> {
    Ok(StatsOptions {
        detrend: detrend_of(detrend)?,
        derivative: derivative_of(derivative)?,
        lambda_s: None,
        lambda_c: None,
    })
}

/// The cut-off of a `resolution` (taking precedence) or a `tip_radius` on
/// `t`, as `kefric surface --resolution/--tip-radius` (the core's request).
fn cutoff_of(t: &Topography, tip_radius: Option<f64>, resolution: Option<f64>) -> PyResult<Cutoff> {
    let request = SurfaceRequest {
        tip_radius,
        resolution,
        ..SurfaceRequest::default()
    };
    request.check().map_err(request_error)?;
    request.cutoff(t, "the surface").map_err(request_error)
}

/// The S-filter's nesting index of the Python keywords: `lambda_s` metres,
/// or with `auto` the reliability cut-off (none if the instrument
/// distorts no scale; an error if nothing is known of it).
fn lambda_s_of(lambda_s: Option<f64>, auto: bool, cutoff: Cutoff) -> PyResult<Option<f64>> {
    let request = SurfaceRequest {
        lambda_s: if auto {
            Some(LambdaS::Auto)
        } else {
            lambda_s.map(LambdaS::Metres)
        },
        ..SurfaceRequest::default()
    };
    request
        .stats_options(cutoff, "the surface")
        .map(|o| o.lambda_s)
        .map_err(request_error)
}

/// A request's failure as Python names its inputs (the keywords): the
/// exception of its kind.
pub fn request_error(e: RequestError) -> PyErr {
    if e.out_of_memory {
        return pyo3::exceptions::PyMemoryError::new_err(e.message.to_string());
    }
    let message = if e.field == Field::File {
        e.message.to_string()
    } else {
        e.to_string()
    };
    exception(e.kind, message)
}

/// `lambda_s="auto"` with a `tip_radius` that distorts no scale of `file`:
/// a `UserWarning` (the core's `SurfaceRequest::auto_without_cutoff`, its
/// inputs by their keywords).
fn warn_auto_without_cutoff(
    py: Python<'_>,
    file: &str,
    auto: bool,
    cutoff: Cutoff,
    tip_radius: Option<f64>,
) -> PyResult<()> {
    let request = SurfaceRequest {
        lambda_s: auto.then_some(LambdaS::Auto),
        tip_radius,
        ..SurfaceRequest::default()
    };
    if let Some(note) = request.auto_without_cutoff(cutoff, file) {
        let message = std::ffi::CString::new(note.to_string()).unwrap_or_default();
        PyErr::warn(py, &py.get_type::<pyo3::exceptions::PyUserWarning>(), &message, 2)?;
    }
    Ok(())
}

/// The surface of `t` with `options`, its statistics checked against the
/// reliability `cutoff` (an unreliable-scale warning if below).
fn surface_of(t: Topography, options: StatsOptions, cutoff: Cutoff) -> Result<Surface, StatsError> {
    let mut surface = Surface::new(t, options)?;
    if let Some(c) = cutoff.value() {
        surface.check_reliability(c);
    }
    Ok(surface)
}

/// A power spectral density as `(q, c)` arrays.
fn psd_arrays<'py>(py: Python<'py>, p: Psd) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
    (PyArray1::from_vec(py, p.q), PyArray1::from_vec(py, p.c))
}

/// The window of the Python keyword (the core's names).
fn window_of(name: &str) -> PyResult<Window> {
    Window::parse(name).map_err(value_error)
}

/// The loads of `force` on `area`, or `pressure` (lists of one length,
/// broadcast by the caller), each checked by the core
/// (`Load::from_parts`); a row with neither is refused.
fn loads_of(force: &Option<Vec<f64>>, area: &Option<Vec<f64>>, pressure: &Option<Vec<f64>>) -> PyResult<Vec<Load>> {
    let n = force.as_ref().or(pressure.as_ref()).map_or(0, Vec::len);
    let at = |v: &Option<Vec<f64>>, k: usize| v.as_ref().and_then(|v| v.get(k).copied());
    (0..n)
        .map(|k| {
            Load::from_parts(at(force, k), at(area, k), at(pressure, k))
                .map_err(raise)?
                .ok_or_else(|| value_error("give force with area, or pressure alone"))
        })
        .collect()
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

/// The exception of statistics that cannot be taken with `options`: a
/// filter's refused nesting index names its keyword (`lambda_s: the
/// cut-off wavelength lambda = … m is out of range: must be at least … m`).
fn stats_error(e: StatsError, options: &StatsOptions, what: Option<&str>) -> PyErr {
    let name = match &e {
        StatsError::Filter(f) => {
            let lambda = match f {
                FilterError::Cutoff { lambda } | FilterError::TooShort { lambda, .. } => Some(*lambda),
                FilterError::TooLong { lambda, .. } => Some(*lambda),
                _ => None,
            };
            let same = |l: Option<f64>| {
                l.is_some() && (l == lambda || l.zip(lambda).is_some_and(|(a, b)| a.is_nan() && b.is_nan()))
            };
            if same(options.lambda_s) {
                Some("lambda_s")
            } else if same(options.lambda_c) {
                Some("lambda_c")
            } else {
                None
            }
        }
        _ => None,
    };
    let prefix = [what, name].into_iter().flatten().collect::<Vec<_>>().join(": ");
    if prefix.is_empty() {
        raise(e)
    } else {
        exception(e.kind(), format!("{prefix}: {e}"))
    }
}

/// A measured surface: one topography, or the equivalent surface of two;
/// and what is known of the instrument's reliability cut-off.
#[pyclass(frozen, module = "ke_friction._core")]
pub struct SurfaceCore {
    surface: Surface,
    cutoff: Cutoff,
    /// The tip radius the cut-off came from, if any (for `filtered`'s
    /// `lambda_s="auto"` warning when it distorts no scale).
    tip_radius: Option<f64>,
}

impl SurfaceCore {
    /// The surface of the parts `topographies`, each with its own cut-off,
    /// taken with `options`.
    fn build(
        py: Python<'_>,
        topographies: Vec<(Topography, Cutoff)>,
        options: StatsOptions,
        what: Option<&str>,
    ) -> PyResult<SurfaceCore> {
        let cutoff = match &topographies[..] {
            [(_, c)] => *c,
            [(_, a), (_, b)] if a == b => *a,
            _ => Cutoff::Unknown,
        };
        let n = topographies.len();
        let surface = py.detach(|| {
            let mut surfaces = Vec::with_capacity(n);
            for (t, c) in topographies {
                surfaces.push(surface_of(t, options, c)?);
            }
            match <[Surface; 1]>::try_from(surfaces) {
                Ok([one]) => Ok(Ok(one)),
                Err(v) => match <[Surface; 2]>::try_from(v) {
                    Ok([a, b]) => Ok(Surface::join(a, b).map_err(raise)),
                    Err(v) => Ok(Err(value_error(format!(
                        "a surface has one or two parts, not {}",
                        v.len()
                    )))),
                },
            }
        });
        match surface {
            Ok(Ok(surface)) => Ok(SurfaceCore {
                surface,
                cutoff,
                tip_radius: None,
            }),
            Ok(Err(e)) => Err(e),
            Err(e) => Err(stats_error(e, &options, what)),
        }
    }

    /// The one topography of a single surface (`what` names the
    /// operation in the error of a pair).
    fn single(&self, what: &str) -> PyResult<&Topography> {
        match self.surface.parts() {
            [(t, _)] => Ok(t),
            _ => Err(value_error(format!("{what}: of a single surface, not a pair"))),
        }
    }
}

#[pymethods]
impl SurfaceCore {
    /// The surface of one topography (`parts` of one) or of two pressed
    /// together: each part `(heights, nx, ny, dx, dy)`, heights row-major
    /// in metres (NaN = missing), `dy` None for a profile. `lambda_s`,
    /// `lambda_c`: the filters' nesting indices (m); `auto`: `lambda_s` is
    /// the reliability cut-off of `resolution` or `tip_radius` (each
    /// part's); `no_cutoff`: the cut-off is known to be none (a pickled
    /// surface's).
    #[staticmethod]
    #[allow(clippy::type_complexity, clippy::too_many_arguments)]
    #[pyo3(signature = (parts, detrend, derivative, lambda_s=None, lambda_c=None, auto=false, tip_radius=None,
                        resolution=None, no_cutoff=false))]
    fn new(
        py: Python<'_>,
        parts: Vec<(PyReadonlyArray1<'_, f64>, usize, usize, f64, Option<f64>)>,
        detrend: &str,
        derivative: &str,
        lambda_s: Option<f64>,
        lambda_c: Option<f64>,
        auto: bool,
        tip_radius: Option<f64>,
        resolution: Option<f64>,
        no_cutoff: bool,
    ) -> PyResult<SurfaceCore> {
        let base = options(detrend, derivative)?;
        if parts.is_empty() || parts.len() > 2 {
            return Err(value_error(format!(
                "a surface has one or two parts, not {}",
                parts.len()
            )));
        }
        let mut topographies = Vec::with_capacity(parts.len());
        let mut lambda = None;
        for (heights, nx, ny, dx, dy) in &parts {
            let heights = slice("heights", heights)?.into_owned();
            let t = topography(heights, *nx, *ny, *dx, *dy)?;
            let cutoff = if no_cutoff {
                Cutoff::Known(None)
            } else {
                py.detach(|| cutoff_of(&t, tip_radius, resolution))?
            };
            if !no_cutoff {
                warn_auto_without_cutoff(py, "heights", auto, cutoff, tip_radius)?;
            }
            lambda = Some(lambda_s_of(lambda_s, auto, cutoff)?);
            topographies.push((t, cutoff));
        }
        let options = StatsOptions {
            lambda_s: lambda.flatten(),
            lambda_c,
            ..base
        };
        let mut core = SurfaceCore::build(py, topographies, options, None)?;
        core.tip_radius = tip_radius;
        Ok(core)
    }

    /// The surface in the file `path` (X3P, `.npy`, text or an instrument's
    /// own format), by the core's
    /// reader: `dx`, `dy` in metres for files that give none, `z_unit`
    /// metres per unit of `.npy` and text heights, `xy_unit` of the x, y
    /// columns of text (both finite and > 0), `max_points` the most points
    /// the surface may have (None: the core's `MAX_POINTS`); `channel` the
    /// channel of a file with several (a name, or an index from 0, as
    /// text); the filters and the cut-off as in `new`. A file that
    /// cannot be read is an `OSError`, a bad one or one over `max_points`
    /// a `ValueError`, heights that cannot be allocated a `MemoryError`;
    /// all name the file.
    #[staticmethod]
    #[pyo3(signature = (path, dx, dy, z_unit, xy_unit, detrend, derivative, max_points=None, lambda_s=None,
                        lambda_c=None, auto=false, tip_radius=None, resolution=None, channel=None))]
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
        lambda_s: Option<f64>,
        lambda_c: Option<f64>,
        auto: bool,
        tip_radius: Option<f64>,
        resolution: Option<f64>,
        channel: Option<String>,
    ) -> PyResult<SurfaceCore> {
        let request = SurfaceRequest {
            dx,
            dy,
            z_unit,
            xy_unit,
            max_points: max_points.unwrap_or(MAX_POINTS),
            channel: channel.map(|c| c.parse::<Channel>().unwrap_or_else(|never| match never {})),
            detrend: detrend_of(detrend)?,
            derivative: derivative_of(derivative)?,
            lambda_s: if auto {
                Some(LambdaS::Auto)
            } else {
                lambda_s.map(LambdaS::Metres)
            },
            lambda_c,
            tip_radius,
            resolution,
            ..SurfaceRequest::default()
        };
        request.check().map_err(request_error)?;
        let topography = py.detach(|| request.read(Source::Path(&path))).map_err(request_error)?;
        let name = path.display().to_string();
        let cutoff = py
            .detach(|| request.cutoff(&topography, &name))
            .map_err(request_error)?;
        warn_auto_without_cutoff(py, &name, auto, cutoff, tip_radius)?;
        let options = request.stats_options(cutoff, &name).map_err(request_error)?;
        let mut core = SurfaceCore::build(py, vec![(topography, cutoff)], options, Some(&name))?;
        core.tip_radius = tip_radius;
        Ok(core)
    }

    /// Two surfaces pressed together: the equivalent surface of the
    /// topographies of `a` and `b` (one each), statistics taken with
    /// `detrend` and `derivative` and the filters the two share (a
    /// `ValueError` if they differ).
    #[staticmethod]
    fn pair(
        py: Python<'_>,
        a: &SurfaceCore,
        b: &SurfaceCore,
        detrend: &str,
        derivative: &str,
    ) -> PyResult<SurfaceCore> {
        let (oa, ob) = (a.surface.options(), b.surface.options());
        if (oa.lambda_s, oa.lambda_c) != (ob.lambda_s, ob.lambda_c) {
            return Err(value_error(format!(
                "the surfaces are filtered differently: lambda_s {:?} and {:?}, lambda_c {:?} and {:?}",
                oa.lambda_s, ob.lambda_s, oa.lambda_c, ob.lambda_c
            )));
        }
        let options = StatsOptions {
            lambda_s: oa.lambda_s,
            lambda_c: oa.lambda_c,
            ..options(detrend, derivative)?
        };
        let one = |s: &SurfaceCore, name: &str| match s.surface.parts() {
            [(t, _)] => Ok(t.clone()),
            _ => Err(value_error(format!(
                "{name} is a pair already: give two single surfaces"
            ))),
        };
        let (ta, tb) = (one(a, "a")?, one(b, "b")?);
        if oa == options && ob == options {
            // Their statistics are taken already.
            let cutoff = if a.cutoff == b.cutoff {
                a.cutoff
            } else {
                Cutoff::Unknown
            };
            let surface = py
                .detach(|| Surface::join(a.surface.clone(), b.surface.clone()))
                .map_err(raise)?;
            return Ok(SurfaceCore {
                surface,
                cutoff,
                tip_radius: None,
            });
        }
        SurfaceCore::build(py, vec![(ta, a.cutoff), (tb, b.cutoff)], options, None)
    }

    /// The same heights, detrending and derivative (and reliability
    /// cut-off) with the filters `lambda_s` (`auto`: the cut-off) and
    /// `lambda_c`.
    #[pyo3(signature = (lambda_s=None, lambda_c=None, auto=false))]
    fn filtered(
        &self,
        py: Python<'_>,
        lambda_s: Option<f64>,
        lambda_c: Option<f64>,
        auto: bool,
    ) -> PyResult<SurfaceCore> {
        // The warning `kefric surface --lambda-s auto` gives where the tip
        // distorts no scale (the core's note).
        warn_auto_without_cutoff(py, "the surface", auto, self.cutoff, self.tip_radius)?;
        let options = StatsOptions {
            lambda_s: lambda_s_of(lambda_s, auto, self.cutoff)?,
            lambda_c,
            ..self.surface.options()
        };
        let parts = self
            .surface
            .parts()
            .iter()
            .map(|(t, _)| (t.clone(), self.cutoff))
            .collect();
        let mut core = SurfaceCore::build(py, parts, options, None)?;
        core.tip_radius = self.tip_radius;
        Ok(core)
    }

    /// `(lambda_s, lambda_c)`: the filters' nesting indices (m), None
    /// where not applied.
    fn filters(&self) -> (Option<f64>, Option<f64>) {
        let o = self.surface.options();
        (o.lambda_s, o.lambda_c)
    }

    /// `(known, cutoff)`: whether the reliability cut-off is known, and
    /// the cut-off (m; None when known to be none).
    fn cutoff(&self) -> (bool, Option<f64>) {
        match self.cutoff {
            Cutoff::Unknown => (false, None),
            Cutoff::Known(c) => (true, c),
        }
    }

    /// The power spectral densities of the detrended, unfiltered heights
    /// (as `kefric surface --psd`): `[("x", q, c)]` of a profile, and
    /// `("y", …)`, `("area", …)` of a map; `window` "none" or "hann".
    #[allow(clippy::type_complexity)]
    fn psd<'py>(
        &self,
        py: Python<'py>,
        window: &str,
    ) -> PyResult<Vec<(&'static str, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>)>> {
        let window = window_of(window)?;
        let t = self.single("psd")?;
        let detrend = self.surface.options().detrend;
        let (spectra, rectangle) = py.detach(|| -> PyResult<(Vec<(&'static str, Psd)>, Option<Rectangle>)> {
            // Missing points: the largest complete rectangle, as kefric --psd.
            let (part, rectangle) = complete_part(t).map_err(raise)?;
            let detrended = part.detrended_topography(detrend).map_err(raise)?;
            let spectra = psd_all(&detrended, window).map_err(raise)?;
            Ok((spectra, rectangle))
        })?;
        if let Some(r) = rectangle {
            let message = std::ffi::CString::new(format!("psd: {r}")).unwrap_or_default();
            PyErr::warn(py, &py.get_type::<pyo3::exceptions::PyUserWarning>(), &message, 2)?;
        }
        Ok(spectra
            .into_iter()
            .map(|(name, p)| {
                let (q, c) = psd_arrays(py, p);
                (name, q, c)
            })
            .collect())
    }

    /// The surface at each S-filter nesting index λs from `from_` to `to`
    /// (None: the core's defaults), `per_decade` a decade (as `kefric
    /// surface --scan`), the other options this surface's. The cut-off:
    /// of `resolution` or `tip_radius`, else this surface's. Returns
    /// `(cutoff, rows)`, each row `(lambda_s, reliable, surface, error)`:
    /// `reliable` None without a cut-off, `surface` None with `error` the
    /// message where the statistics cannot be taken.
    #[allow(clippy::type_complexity, clippy::too_many_arguments)]
    #[pyo3(signature = (from_=None, to=None, per_decade=5, tip_radius=None, resolution=None))]
    fn scan(
        &self,
        py: Python<'_>,
        from_: Option<f64>,
        to: Option<f64>,
        per_decade: usize,
        tip_radius: Option<f64>,
        resolution: Option<f64>,
    ) -> PyResult<(
        Option<f64>,
        Vec<(f64, Option<bool>, Option<SurfaceCore>, Option<String>)>,
    )> {
        let t = self.single("scan")?;
        let cutoff = match py.detach(|| cutoff_of(t, tip_radius, resolution))? {
            Cutoff::Unknown => self.cutoff,
            known => known,
        };
        let default = ScanRange::default_for(t);
        let range = ScanRange {
            from: from_.unwrap_or(default.from),
            to: to.unwrap_or(default.to),
            per_decade,
        };
        let options = self.surface.options();
        let rows = py
            .detach(|| scan(t, &options, &range, cutoff.value(), |_, _| {}))
            .map_err(|e| exception(e.kind(), format!("scan: {e}")))?;
        Ok((
            cutoff.value(),
            rows.into_iter()
                .map(|row| match row.surface {
                    Ok(surface) => (
                        row.lambda_s,
                        row.reliable,
                        Some(SurfaceCore {
                            surface,
                            cutoff,
                            tip_radius: tip_radius.or(self.tip_radius),
                        }),
                        None,
                    ),
                    Err(e) => (row.lambda_s, row.reliable, None, Some(e.to_string())),
                })
                .collect(),
        ))
    }

    /// The core's default stencil lengths (m) of `order` (1 slope, 2
    /// curvature): `default_distances`.
    fn default_distances<'py>(&self, py: Python<'py>, order: u32) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let t = self.single("scale_dependent")?;
        Ok(PyArray1::from_vec(py, default_distances(t, order)))
    }

    /// The scale-dependent rms slope (`order` 1) or curvature (2) at each
    /// distance (m) of the detrended (as the statistics), unfiltered
    /// heights: `(x, y)`, `y` None for a profile.
    #[allow(clippy::type_complexity)]
    fn scale_dependent<'py>(
        &self,
        py: Python<'py>,
        distances: PyReadonlyArray1<'_, f64>,
        order: u8,
    ) -> PyResult<(Bound<'py, PyArray1<f64>>, Option<Bound<'py, PyArray1<f64>>>)> {
        let t = self.single("scale_dependent")?;
        let detrend = self.surface.options().detrend;
        let distances = slice("distances", &distances)?.into_owned();
        let rows = py
            .detach(|| -> PyResult<_> {
                // Too few points is said as such, before the detrending
                // could fail on them.
                scale_dependent_slope(t, &[]).map_err(raise)?;
                let detrended = t.detrended_topography(detrend).map_err(raise)?;
                match order {
                    1 => Ok(scale_dependent_slope(&detrended, &distances)),
                    2 => Ok(scale_dependent_curvature(&detrended, &distances)),
                    _ => Err(value_error(format!(
                        "order = {order}: must be 1 (slope) or 2 (curvature)"
                    ))),
                }
            })?
            .map_err(raise)?;
        let x: Vec<f64> = rows.iter().map(|r| r.x).collect();
        let y = t
            .dy()
            .map(|_| PyArray1::from_vec(py, rows.iter().map(|r| r.y.unwrap_or(f64::NAN)).collect()));
        Ok((PyArray1::from_vec(py, x), y))
    }

    /// The reliability cut-off (m) of a scanning-probe tip of radius
    /// `tip_radius` (m) on the unfiltered heights, or None if the tip
    /// distorts no scale (the core's `tip_reliability_cutoff`).
    fn reliability_cutoff(&self, py: Python<'_>, tip_radius: f64, safety_factor: f64) -> PyResult<Option<f64>> {
        let t = self.single("reliability_cutoff")?;
        py.detach(|| tip_reliability_cutoff(t, tip_radius, safety_factor))
            .map_err(raise)
    }

    /// The statistics: the core's `SurfaceStats` record (what `kefric
    /// surface --json` prints as "surface").
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        record(py, serde_json::to_string(self.surface.stats()))
    }

    /// What each part's file said about its measurement (the core's
    /// `Metadata`; what `kefric surface --json` prints as "metadata").
    fn metadata<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let metadata: Vec<_> = self.surface.parts().iter().map(|(t, _)| t.metadata()).collect();
        record(py, serde_json::to_string(&metadata))
    }

    /// The parts' own statistics records (one, or two for a pair).
    fn parts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let parts: Vec<_> = self.surface.parts().iter().map(|(_, s)| s).collect();
        record(py, serde_json::to_string(&parts))
    }

    /// Whether this is the equivalent surface of two.
    fn is_pair(&self) -> bool {
        self.surface.parts().len() == 2
    }

    /// The parts' topographies, `(heights, nx, ny, dx, dy)` each: heights
    /// row-major (metres, NaN = missing), `dy` None for a profile.
    #[allow(clippy::type_complexity)]
    fn topographies<'py>(&self, py: Python<'py>) -> Vec<(Bound<'py, PyArray1<f64>>, usize, usize, f64, Option<f64>)> {
        self.surface
            .parts()
            .iter()
            .map(|(t, _)| (PyArray1::from_slice(py, t.heights()), t.nx(), t.ny(), t.dx(), t.dy()))
            .collect()
    }

    /// `(detrend, derivative)`, by the Python keywords' names.
    fn options(&self) -> (&'static str, &'static str) {
        let o = self.surface.options();
        (o.detrend.name(), o.derivative.name())
    }

    /// The height distribution of `family` (None: pearson), the core's
    /// `Surface::distribution`.
    #[pyo3(signature = (family=None))]
    fn distribution(&self, py: Python<'_>, family: Option<&str>) -> PyResult<DistributionCore> {
        let family = family.map(Family::parse).transpose().map_err(value_error)?;
        py.detach(|| self.surface.distribution(family))
            .map(DistributionCore::of)
            .map_err(raise)
    }

    /// The family the surface gets when none is named (the core's rule:
    /// Pearson where its upper tail is supported, else empirical).
    fn default_family(&self, py: Python<'_>) -> &'static str {
        py.detach(|| self.surface.default_family()).name()
    }

    /// What the empirical density of the surface is made from: each
    /// part's detrended heights (NaN = missing) and standard deviation σ
    /// (`DistributionCore.empirical` of the one, or
    /// `DistributionCore.empirical_sum` of the two, rebuilds it).
    fn empirical_parts<'py>(&self, py: Python<'py>) -> PyResult<Vec<(Bound<'py, PyArray1<f64>>, f64)>> {
        let detrend = self.surface.options().detrend;
        let mut out = Vec::with_capacity(2);
        for (t, s) in self.surface.parts() {
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
        materials: [f64; 7],
        distribution: &DistributionCore,
    ) -> PyResult<Bound<'py, PyAny>> {
        let p = self
            .surface
            .params(&Materials::from_array(materials), distribution.dist.clone())
            .map_err(raise)?;
        record(py, serde_json::to_string(&p))
    }

    /// The friction of loads (`force` on `area`, or `pressure`: lists of
    /// one length, broadcast by the caller) on `model`, made from
    /// `materials` on this surface: `{"records": [the core's `Friction`
    /// record of each load], "warnings": [one summary a kind (the core's
    /// `Warnings`): the surface's and the loads']}`.
    #[pyo3(signature = (model, materials, force, area, pressure))]
    fn friction<'py>(
        &self,
        py: Python<'py>,
        model: &ModelCore,
        materials: [f64; 7],
        force: Option<Vec<f64>>,
        area: Option<Vec<f64>>,
        pressure: Option<Vec<f64>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let loads = loads_of(&force, &area, &pressure)?;
        if loads.is_empty() {
            return Err(value_error("give force with area, or pressure alone"));
        }
        let materials = Materials::from_array(materials);
        let frictions = py
            .detach(|| self.surface.frictions(&model.0, &materials, &loads))
            .map_err(raise)?;
        let mut warnings = ke_friction::Warnings::new();
        warnings.extend(self.surface.stats().warnings.iter().cloned());
        warnings.extend(ke_friction::Warning::of_params(model.0.params()));
        let mut records = Vec::with_capacity(frictions.len());
        for (f, w) in frictions {
            warnings.note(w);
            records.push(f);
        }
        let summaries: Vec<ke_friction::Summary<'_>> = warnings.summaries().collect();
        let out = serde_json::json!({ "records": records, "warnings": summaries });
        record(py, serde_json::to_string(&out))
    }

    /// The sensitivity of each load (lists as `friction`'s) with
    /// `materials`, the height model `distribution` (None: the default),
    /// `fit` and `model`: μ under each height model and at the two ends
    /// of the band, the core's `Sensitivity` records (JSON list), each μ
    /// the single evaluation with that option.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (materials, distribution, fit, model, force, area, pressure))]
    fn sensitivity<'py>(
        &self,
        py: Python<'py>,
        materials: [f64; 7],
        distribution: Option<&str>,
        fit: &str,
        model: &str,
        force: Option<Vec<f64>>,
        area: Option<Vec<f64>>,
        pressure: Option<Vec<f64>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        use ke_friction::{Fit, ModelKind};
        let loads = loads_of(&force, &area, &pressure)?;
        let options = self.surface.options();
        let request = SurfaceRequest {
            detrend: options.detrend,
            derivative: options.derivative,
            lambda_c: options.lambda_c,
            materials: materials.map(Some),
            distribution: distribution.map(Family::parse).transpose().map_err(value_error)?,
            fit: Fit::parse(fit).map_err(value_error)?,
            model: ModelKind::parse(model).map_err(value_error)?,
            loads: LoadInputs::default(),
            ..SurfaceRequest::default()
        };
        let materials = Materials::from_array(materials);
        let s = py.detach(|| request.sensitivity_of(&self.surface, self.cutoff, materials, &loads));
        record(py, serde_json::to_string(&s))
    }

    /// The surface's warnings, one summary a kind (as `friction`'s).
    fn warnings<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let mut warnings = ke_friction::Warnings::new();
        warnings.extend(self.surface.stats().warnings.iter().cloned());
        let summaries: Vec<ke_friction::Summary<'_>> = warnings.summaries().collect();
        record(py, serde_json::to_string(&summaries))
    }
}
