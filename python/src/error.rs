//! The one place that turns the core's errors into Python exceptions, by
//! their [`ErrorKind`] (the table in `ke_friction::error`'s documentation):
//!
//! | kind | Python |
//! |---|---|
//! | `Argument`, `Domain`, `NoMu`, `Tolerance` | `ValueError` |
//! | `Io` | `OSError` |
//! | `Table` | `ke_friction.TableError` (a `ValueError`) |
//! | `Internal` | `RuntimeError` ("this is a bug") |
//!
//! A surface file's read error (the core's `ReadError`) is an `OSError` if the file cannot be
//! read, else a `ValueError` (one over the points limit,
//! `ReadError::TooManyPoints`, included: its message names the limit and
//! `max_points`), but for `ReadError::OutOfMemory`, a `MemoryError`
//! (`SurfaceRequest`'s `out_of_memory`, in `surface.rs`).
//!
//! Errors of the binding itself (a wrong length or layout in a direct call
//! of `_core`) are `ValueError`s too ([`value_error`]).

use ke_friction::{Classify, ErrorKind, LookupError};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;

pyo3::create_exception!(
    _core,
    TableError,
    PyValueError,
    "A table file that is damaged, not a table, or inconsistent (a ValueError)."
);

/// The exception of a failure of kind `kind` saying `message`.
pub fn exception(kind: ErrorKind, message: String) -> PyErr {
    match kind {
        ErrorKind::Argument | ErrorKind::Domain | ErrorKind::NoMu | ErrorKind::Tolerance => {
            PyValueError::new_err(message)
        }
        ErrorKind::Io => PyOSError::new_err(message),
        ErrorKind::Table => TableError::new_err(message),
        ErrorKind::Internal => PyRuntimeError::new_err(format!(
            "{message} (this is a bug in ke_friction: please report it with the inputs)"
        )),
        // A kind added to the core after this binding: not the caller's
        // fault as far as this binding knows.
        other => PyRuntimeError::new_err(format!("{message} (error kind {:?})", other.name())),
    }
}

/// The exception of a core error.
pub fn raise(e: impl Classify) -> PyErr {
    exception(e.kind(), e.to_string())
}

/// A `ValueError` of the binding's own checks.
pub fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// An array element the core could not answer: its index in the flat
/// input, its kind and the element's own message (`psi = 9 is outside the
/// range [0.5, 8]`; the Python layer adds the index in its shape).
#[derive(Debug)]
pub struct Failure {
    pub index: usize,
    pub kind: ErrorKind,
    pub message: String,
}

impl Failure {
    /// A batch's error, its element index moved up by `offset` (the start
    /// of the piece the batch ran on). A batch element's message is the
    /// element's own error, without the "batch element i" prefix; another
    /// error (mismatched lengths, which the binding's checks rule out)
    /// keeps its message, at index `offset`.
    pub fn of_batch(e: LookupError, offset: usize) -> Failure {
        let e = e.shifted(offset);
        let (index, message) = match e {
            LookupError::BatchElement {
                index,
                name,
                value,
                lo,
                hi,
            } => (index, LookupError::OutOfDomain { name, value, lo, hi }.to_string()),
            ref other => (offset, other.to_string()),
        };
        Failure {
            index,
            kind: e.kind(),
            message,
        }
    }

    /// The element `index`'s error `e`.
    pub fn at(index: usize, e: &impl Classify) -> Failure {
        Failure {
            index,
            kind: e.kind(),
            message: e.to_string(),
        }
    }

    /// The exception, with the element's flat index as its attribute
    /// `index` (the Python layer re-raises it with the index in the
    /// array's shape).
    pub fn into_pyerr(self, py: Python<'_>) -> PyErr {
        let err = exception(self.kind, self.message);
        // Setting an attribute on a fresh exception object cannot fail but
        // for lack of memory; the exception then goes without it.
        let _ = err.value(py).setattr("index", self.index);
        err
    }
}
