//! The C ABI of ke-friction: table and curve lookups and the model by
//! direct integration, for C, C++ and Fortran (`include/kefriction.h`,
//! `fortran/ke_friction.f90`).
//!
//! Conventions of every function:
//! - a return code: [`KEF_OK`] (0) or one of the `KEF_ERR_*` codes (or a
//!   NULL handle); on failure [`kef_last_error`] gives the message (the
//!   Rust error's one line: argument, value, valid range; a lookup's is
//!   formatted only then, so that a failing lookup stays cheap) and the outputs
//!   are untouched, except that a batch writes the elements before the
//!   first bad one and nothing from it on (its `_nan` form writes NaN
//!   there instead and goes on);
//! - the code is the core's classification of the error
//!   ([`ke_friction::ErrorKind`]), mapped in one place (`code`);
//! - a NULL pointer where one is required is [`KEF_ERR_ARGUMENT`], never a
//!   crash; no panic crosses the boundary ([`KEF_ERR_INTERNAL`] if one
//!   ever happened);
//! - outputs must not alias each other or the inputs: a call whose output
//!   overlaps another pointer argument is [`KEF_ERR_ARGUMENT`] (the
//!   message names both), nothing written;
//! - tables, curves and laws are immutable (a law's clamped count is atomic): any number of threads may use one
//!   at once; only freeing it must wait until they are done.
//!
//! Every export is one line: the `ffi!` macro checks its pointer
//! arguments (that no output overlaps another argument, then each for
//! NULL), runs the body under `catch_unwind` and turns a failure into its
//! code and message.
#![warn(missing_docs)]
#![deny(unsafe_op_in_unsafe_fn)]
#![warn(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]
// The C names are the contract.
#![allow(non_camel_case_types)]

// The modules, in the header's order: cbindgen reads the items of the crate
// root, then of each module in the order declared here, and writes the
// functions in that order. Each declaration stands alone (a comment above
// it) so that rustfmt keeps the order.

// The `ffi!` macro and the machinery of every export (first: its macros
// serve the modules below).
#[macro_use]
mod macros;

// The return codes and kef_last_error.
mod error;

// The plausibility warnings: KEF_WARN_*, kef_warnings, kef_clear_warnings,
// kef_warning_message.
mod warning;

// kef_version.
mod version;

// The table handle: kef_table_default, _load, _free, _domain.
mod table;

// kef_params_from_physical.
mod surface;

// The table's lookups: kef_table_h_star, kef_table_mu (and _with, which
// checks the constants) and their batches.
mod lookup;

// The curve handle: kef_curve_*.
mod curve;

// Direct integration: kef_model_mu, kef_model_mu_with.
mod model;

// The friction law handle: KEF_LAW_*, kef_law_*.
mod law;

// The model constants handle: kef_constants_new, _free, the setters and
// getters of β, ν, ε*, the fit and the model.
mod constants;

// The heights' distribution: KEF_DIST_*, kef_constants_set_distribution,
// _set_heights, kef_constants_distribution.
mod distribution;

// The batches' shared helpers (no exports).
mod batch;

pub use constants::*;
pub use curve::*;
pub use distribution::*;
pub use error::*;
pub use law::*;
pub use lookup::*;
pub use model::*;
pub use surface::*;
pub use table::*;
pub use version::*;
pub use warning::*;
