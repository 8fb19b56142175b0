//! # ke-friction
//!
//! The Kogut–Etsion (2004) static friction model of two rough surfaces:
//! the static friction coefficient μ as a function of the load, the
//! roughness, the materials and the adhesion.
//!
//! - [`Model`]: the model by direct integration (microseconds), at a
//!   separation h* or an external force F*; [`Kind::CebType`] gives the
//!   CEB-type comparison model.
//! - [`Table`]: μ(ψ, θ, F*) from a precomputed table (nanoseconds); the
//!   default table is compiled in.
//! - `build`, `export`, `validate`, `figures` (default features): the table
//!   builder, NumPy export, the paper's statements and figures.
//!
//! The model is specified, equation by equation, in `docs/MODEL.md`; doc
//! comments cite its sections.
//!
//! ```
//! use ke_friction::{Model, Params, Table};
//! let table = Table::embedded();                       // the default table
//! let mu = table.mu(1.0, 0.001, 0.01)?;                // ψ, θ, F*
//! let exact = Model::new(Params::new(1.0, 0.001))?.at_f_star(0.01)?.mu.unwrap();
//! assert!((mu - exact).abs() <= table.domain().tolerance * exact);
//! assert!((exact - 0.52521087083).abs() < 1e-10);       // MODEL.md §7
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]

pub mod asperity;
#[cfg(feature = "builder")]
pub mod build;
#[cfg(feature = "builder")]
pub mod export;
#[cfg(feature = "plot")]
pub mod figures;
mod model;
mod params;
mod quadrature;
pub mod spline;
mod surface;
pub mod table;
pub mod validate;

pub use model::{Contact, EvalError, Model, H_LIMIT};
pub use params::{
    Fit, Kind, ParamError, Params, Physical, BETA_MAX, BETA_MIN, DEFAULT_BETA, DEFAULT_EPS_STAR, DEFAULT_NU,
    EPS_STAR_MAX, EPS_STAR_MIN, PSI_MAX, PSI_MIN, THETA_MAX,
};
pub use table::{Domain, LookupError, Table, TableError};
