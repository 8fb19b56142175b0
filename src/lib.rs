//! # ke-friction
//!
//! The Kogut–Etsion (2004) static friction model of two rough surfaces:
//! the static friction coefficient μ as a function of the load, the
//! roughness, the materials and the adhesion.
//!
//! The model is specified, equation by equation, in `MODEL.md` (shipped as
//! `docs/MODEL.md`); doc comments cite its sections.
//!
//! ```
//! use ke_friction::{Model, Params};
//! // ψ = 1, θ = 0.001, defaults β = 0.04, ν = 0.3, ε* = 0.004.
//! let model = Model::new(Params::new(1.0, 0.001))?;
//! let contact = model.at_h_star(2.0)?;
//! assert!((contact.mu.unwrap() - 0.59567907943).abs() < 1e-9);
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
pub use params::{Fit, Kind, ParamError, Params, Physical, BETA_MIN, DEFAULT_BETA, DEFAULT_EPS_STAR, DEFAULT_NU};
pub use table::{Domain, LookupError, Table, TableError};
