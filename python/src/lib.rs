//! The native half of the Python package `ke_friction` (`ke_friction._core`):
//! tables, curves and the model over contiguous float64 arrays, with the
//! GIL released. `pysrc/ke_friction/__init__.py` adds NumPy broadcasting,
//! argument checks and the documented Python API on top.
//!
//! One module per class (`table.rs`, `curve.rs`, `model.rs`,
//! `distribution.rs`, `surface.rs`, `container.rs`, `law.rs`); the core's
//! errors become Python exceptions in `error.rs` alone; the batch and
//! thread machinery is `parallel.rs`; `convert.rs` turns arguments and the
//! core's records between the two languages.

mod container;
mod convert;
mod curve;
mod distribution;
mod error;
mod law;
mod model;
mod parallel;
mod surface;
mod table;

use ke_friction::Named;
use pyo3::prelude::*;

/// Whether `value` is in the core's range `name` (a key of `RANGES`,
/// `ke_friction::bounds::ALL`): the Python side checks an argument it
/// handles itself against the core's bound, never a range of its own.
#[pyfunction]
fn in_range(name: &str, value: f64) -> PyResult<bool> {
    ke_friction::bounds::ALL
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, bound)| bound.contains(value))
        .ok_or_else(|| pyo3::exceptions::PyKeyError::new_err(name.to_string()))
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<table::TableCore>()?;
    m.add_class::<curve::CurveCore>()?;
    m.add_class::<model::ModelCore>()?;
    m.add_class::<distribution::DistributionCore>()?;
    m.add_class::<surface::SurfaceCore>()?;
    m.add_class::<law::FrictionLawCore>()?;
    m.add_class::<container::ContainerCore>()?;
    m.add_function(wrap_pyfunction!(model::params_from_physical, m)?)?;
    m.add_function(wrap_pyfunction!(surface::length_unit, m)?)?;
    m.add_function(wrap_pyfunction!(model::contact_warnings, m)?)?;
    m.add_function(wrap_pyfunction!(in_range, m)?)?;
    m.add("WARNING_KINDS", <ke_friction::WarningKind as Named>::names())?;
    // The crate's version: the workspace's, which the wheel's is too.
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("CURVE_ACCURACY", ke_friction::CURVE_ACCURACY)?;
    m.add("SURFACE_F_STAR", ke_friction::SURFACE_F_STAR)?;
    // The core's name lists (one definition, `named!`): what the Python
    // side checks its string arguments against.
    m.add("DETRENDS", <ke_friction::topography::Detrend as Named>::names())?;
    m.add("DERIVATIVES", <ke_friction::topography::Derivative as Named>::names())?;
    m.add("WINDOWS", <ke_friction::topography::Window as Named>::names())?;
    m.add("FAMILIES", <ke_friction::Family as Named>::names())?;
    m.add("FITS", <ke_friction::Fit as Named>::names())?;
    m.add("MODELS", <ke_friction::ModelKind as Named>::names())?;
    m.add("MATERIALS", ke_friction::Materials::FIELDS)?;
    // The length units' names and symbols (`length_unit` gives metres).
    let units: Vec<&str> = <ke_friction::LengthUnit as Named>::names()
        .into_iter()
        .chain(ke_friction::LengthUnit::SYMBOLS.iter().map(|(s, _)| *s))
        .collect();
    m.add("LENGTH_UNITS", units)?;
    m.add("OUT_OF_RANGE", <ke_friction::OutOfRange as Named>::names())?;
    m.add("LAW_F_STAR_RANGE", ke_friction::LAW_F_STAR_RANGE)?;
    m.add("LAW_TABLE_TOLERANCE", ke_friction::LAW_TABLE_TOLERANCE)?;
    m.add("SCAN_ROWS_MAX", ke_friction::topography::SCAN_ROWS_MAX)?;
    m.add("DEFAULTS", model::defaults(m.py())?)?;
    // Every checked range in words, by name (`ke_friction::bounds::ALL`),
    // for the docstrings.
    let ranges: std::collections::HashMap<&str, &str> = ke_friction::bounds::ALL
        .iter()
        .map(|(name, bound)| (*name, bound.range()))
        .collect();
    m.add("RANGES", ranges)?;
    m.add("TableError", m.py().get_type::<error::TableError>())?;
    Ok(())
}
