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

impl crate::ParamError {
    /// [`ErrorKind::Argument`] for NaN or ∞, else [`ErrorKind::Domain`].
    pub fn kind(&self) -> ErrorKind {
        ErrorKind::of_value(self.value)
    }
}

impl crate::LookupError {
    /// [`ErrorKind::Argument`] for NaN or a length mismatch, else
    /// [`ErrorKind::Domain`].
    pub fn kind(&self) -> ErrorKind {
        use crate::LookupError::*;
        match self {
            OutOfDomain { value, .. } | BatchElement { value, .. } => ErrorKind::of_value(*value),
            LengthMismatch { .. } | CurveLengthMismatch { .. } => ErrorKind::Argument,
        }
    }
}

impl crate::EvalError {
    /// `Argument`/`Domain` for a bad h* or F*, `NoMu`, or `Internal` for
    /// a root search that did not converge.
    pub fn kind(&self) -> ErrorKind {
        use crate::EvalError::*;
        match self {
            HStar(v) | FStar(v) => ErrorKind::of_value(*v),
            FStarTooLarge { .. } => ErrorKind::Domain,
            NoMu { .. } => ErrorKind::NoMu,
            NoConvergence { .. } => ErrorKind::Internal,
        }
    }
}

impl crate::TableError {
    /// [`ErrorKind::Io`] for a file that cannot be read, else
    /// [`ErrorKind::Table`].
    pub fn kind(&self) -> ErrorKind {
        match self {
            crate::TableError::Io { .. } => ErrorKind::Io,
            crate::TableError::File { error, .. } => error.kind(),
            _ => ErrorKind::Table,
        }
    }
}

impl crate::CurveError {
    /// By cause: a bad range is `Argument`, the model's or lookup's error
    /// keeps its kind, no positive μ is `NoMu`, a missed accuracy is
    /// `Tolerance`.
    pub fn kind(&self) -> ErrorKind {
        use crate::CurveError::*;
        match self {
            Range { .. } => ErrorKind::Argument,
            TooWide { .. } => ErrorKind::Domain,
            Model { error, .. } => error.kind(),
            NoMu { .. } => ErrorKind::NoMu,
            Lookup(e) => e.kind(),
            Accuracy { .. } => ErrorKind::Tolerance,
        }
    }
}

#[cfg(feature = "builder")]
impl crate::build::BuildError {
    /// By cause: options are `Argument`/`Domain`, the model's error keeps
    /// its kind (a ghost node without μ is `NoMu`), a missed tolerance is
    /// `Tolerance`, coefficients a file cannot hold are `Domain` (the
    /// options' range).
    pub fn kind(&self) -> ErrorKind {
        use crate::build::BuildError::*;
        match self {
            Option(e) => e.kind(),
            Range { .. } => ErrorKind::Domain,
            Eval { error, .. } | Ghost { error, .. } => error.kind(),
            Tolerance { .. } => ErrorKind::Tolerance,
            Unstorable(_) => ErrorKind::Domain,
        }
    }
}

#[cfg(feature = "plot")]
impl crate::figures::FigureError {
    /// By cause (`Io` for a figure that cannot be written).
    pub fn kind(&self) -> ErrorKind {
        use crate::figures::FigureError::*;
        match self {
            Format { .. } | Scale { .. } | Empty(_) | TableMismatch { .. } => ErrorKind::Argument,
            Params(e) => e.kind(),
            Eval(e) => e.kind(),
            Lookup(e) => e.kind(),
            Direct(e) => e.kind(),
            Draw { .. } => ErrorKind::Io,
        }
    }
}

#[cfg(feature = "paper")]
impl crate::paper::PaperError {
    /// The parameters' or the model's kind; a statement that cannot be
    /// computed from fixed inputs is `Internal`.
    pub fn kind(&self) -> ErrorKind {
        use crate::paper::PaperError::*;
        match self {
            Params(e) => e.kind(),
            Eval(e) => e.kind(),
            _ => ErrorKind::Internal,
        }
    }
}
