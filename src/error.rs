//! One classification of every error, for every front end.
//!
//! Each public error type has a `kind()`: what the failure means to the
//! caller, independent of where it happened. The CLI maps it to an exit
//! status, the C ABI to a return code, the Python package to an exception
//! class — each in one place, so the three cannot disagree.

/// What kind of failure an error is.
///
/// | kind | meaning | CLI | C | Python |
/// |---|---|---|---|---|
/// | `Argument` | not a usable number (NaN, ∞) or a wrong length | 2 | `KEF_ERR_ARGUMENT` | `ValueError` |
/// | `Domain` | a valid number outside its range | 2 | `KEF_ERR_DOMAIN` | `ValueError` |
/// | `NoMu` | μ undefined there: F* ≤ 0 at that separation (or μ ≤ 0) | 2 | `KEF_ERR_NO_MU` | `ValueError` (or NaN) |
/// | `Io` | a file that cannot be read or written | 2 (read), 1 (write) | `KEF_ERR_IO` | `OSError` |
/// | `Table` | a damaged or incompatible table file | 2 | `KEF_ERR_TABLE` | `ke_friction.TableError` |
/// | `Tolerance` | a table or curve that missed its accuracy | 1 | `KEF_ERR_DOMAIN` | `ValueError` |
/// | `Internal` | a bug: please report it with the inputs | 70 | `KEF_ERR_INTERNAL` | `RuntimeError` |
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// Not a usable number (NaN, infinite) or a wrong length.
    Argument,
    /// A valid number outside its range.
    Domain,
    /// μ is undefined at the point asked for (F* ≤ 0 at that separation,
    /// or the friction fit gives μ ≤ 0).
    NoMu,
    /// A file that cannot be read or written.
    Io,
    /// A damaged or incompatible table file.
    Table,
    /// A table or curve that missed the accuracy it was asked for.
    Tolerance,
    /// A bug (e.g. a root search that did not converge).
    Internal,
}

impl ErrorKind {
    /// The kind of a rejected number: `Argument` if it is NaN or
    /// infinite, else `Domain`.
    pub fn of_value(value: f64) -> ErrorKind {
        if value.is_finite() {
            ErrorKind::Domain
        } else {
            ErrorKind::Argument
        }
    }

    /// The kind's name: `"argument"`, `"domain"`, `"no_mu"`, `"io"`,
    /// `"table"`, `"tolerance"` or `"internal"`.
    pub const fn name(self) -> &'static str {
        match self {
            ErrorKind::Argument => "argument",
            ErrorKind::Domain => "domain",
            ErrorKind::NoMu => "no_mu",
            ErrorKind::Io => "io",
            ErrorKind::Table => "table",
            ErrorKind::Tolerance => "tolerance",
            ErrorKind::Internal => "internal",
        }
    }
}

/// The classification of an error, beside each error type: what the
/// failure means to the caller ([`ErrorKind`]). Every front end maps the
/// kind in one place (exit status, C return code, Python exception).
pub trait Classify: std::error::Error {
    /// The error's kind.
    fn kind(&self) -> ErrorKind;
}
