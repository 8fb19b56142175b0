//! # ke-friction
//!
//! The Kogut–Etsion (2004) static friction model of two rough surfaces:
//! the static friction coefficient μ as a function of the load, the
//! roughness, the materials and the adhesion.
//!
//! - [`Model`]: the model by direct integration (microseconds), at a
//!   separation h* or an external force F*; [`ModelKind::CebType`] gives the
//!   CEB-type comparison model.
//! - [`Table`]: μ(ψ, θ, F*) from a precomputed table (nanoseconds); the
//!   default table is compiled in.
//! - [`Curve`]: μ(F*) for one surface pair (fixed ψ, θ) in a few
//!   nanoseconds, from the model or from a table.
//! - [`FrictionLaw`]: μ and dμ/dp of the contact pressure p in pascals,
//!   for a simulator's contact nodes (a curve at F* = p/H).
//!   [`LawTable`]: its rows at log-spaced pressures for a simulator's
//!   tabulated input, with the measured error of linear interpolation.
//! - `paper` (feature `paper`): the paper's statements, computed from the
//!   model.
//! - `build`, `export` (feature `builder`) and `figures` (feature `plot`):
//!   the table builder and its verification, NumPy export, the figures.
//!   No feature is on by default: a plain dependency is the light runtime
//!   (the model and the lookups).
//!
//! The model is specified, equation by equation, in `docs/MODEL.md`; doc
//! comments cite its sections.
//!
//! ```
//! use ke_friction::{Model, Params, Table};
//! let table = Table::embedded();                       // the default table
//! let mu = table.mu(1.0, 0.001, 0.01)?;                // ψ, θ, F*
//! let exact = Model::new(Params::new(1.0, 0.001))?.at_f_star(0.01)?.mu.unwrap();
//! assert!((mu - exact).abs() <= table.info().tolerance * exact);
//! assert!((exact - 0.52521087083).abs() < 1e-10);       // MODEL.md §7
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]
#![deny(unsafe_op_in_unsafe_fn)]
// Every unsafe block says why it is sound; every unsafe fn states its contract.
#![warn(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]

pub mod bound;
pub mod bounds;
#[cfg(feature = "builder")]
pub mod build;
mod checks;
mod curve;
mod distribution;
mod error;
#[cfg(feature = "builder")]
pub mod export;
#[cfg(feature = "plot")]
pub mod figures;
mod gw;
#[cfg(feature = "builder")]
mod io;
mod law;
mod law_format;
mod law_table;
mod load;
mod model;
mod named;
mod num;
#[cfg(feature = "paper")]
pub mod paper;
mod params;
mod quadrature;
mod rng;
mod special;
mod spline;
pub mod table;
#[cfg(feature = "topography")]
pub mod topography;
mod warning;

pub use checks::ParamError;
pub use curve::{Curve, CurveError, CURVE_ACCURACY, SURFACE_F_STAR};
pub use distribution::{
    Density, DistributionError, Empirical, Family, Gaussian, HeightDistribution, Pearson, PearsonType, Weibull,
    EMPIRICAL_MIN_HEIGHTS, KDE_CENTRES, PEARSON_KURTOSIS_MAX, PEARSON_SKEWNESS_MAX, WEIBULL_SKEWNESS_MAX,
    WEIBULL_SKEWNESS_MIN,
};
pub use error::{Classify, ErrorKind};
pub use gw::BETA_MIN;
pub use law::{FrictionLaw, FrictionLawError, OutOfRange, PressureError, LAW_F_STAR_RANGE};
pub use law_format::{
    law_notes, ls_dyna_number, LawFormat, StressUnit, LS_DYNA_FIELD, LS_DYNA_TABLE_ID, LS_DYNA_VELOCITIES,
    MOOSE_FUNCTION,
};
pub use law_table::{
    LawRow, LawTable, LawTableError, INTERIOR_POINTS, LAW_TABLE_MAX_ROWS, LAW_TABLE_TOLERANCE,
    LAW_TABLE_TOLERANCE_RANGE,
};
pub use load::{Friction, Load, LoadError};
pub use model::{asperity, Contact, EvalError, Model, F_STAR_MAX, H_LIMIT};
pub use named::{LengthUnit, NameError, Named};
pub use num::Shortest;
/// The former name of [`ModelKind`].
#[allow(deprecated)]
pub use params::Kind;
pub use params::{
    Constants, Fit, Materials, ModelKind, Params, Physical, BETA_MAX, DEFAULT_BETA, DEFAULT_EPS_STAR, DEFAULT_NU,
    EPS_STAR_MAX, EPS_STAR_MIN, PSI_MAX, PSI_MIN, THETA_MAX,
};
pub use spline::{Axis, Scale};
pub use table::{
    Accuracy, BuildRecord, ConstantsMismatch, Domain, LookupError, OnError, Precision, Table, TableError, TableInfo,
    FAST_KERNEL_MAX_REL,
};
pub use warning::{
    Summary, Warning, WarningKind, Warnings, FEW_ASPERITIES, F_STAR_RANGE, KURTOSIS_MAX, MU_ADHESION, SPIKE_FRACTION,
    SPIKE_SIGMA, TAIL_MIN_POINTS,
};
