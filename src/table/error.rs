//! Why a lookup has no answer, what a batch does then, and a batch of
//! (μ, slope) pairs written to two arrays.

use crate::num::Shortest;
use std::ops::Range;

/// A lookup argument outside a table's domain or a curve's range, or not
/// a number.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LookupError {
    /// The argument is NaN or outside `[lo, hi]`.
    #[error("{name} = {} is outside the range [{}, {}]", Shortest(*.value), Shortest(*.lo), Shortest(*.hi))]
    OutOfDomain {
        /// `"psi"`, `"theta"` or `"f_star"`.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Lower end of the table's range.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
    /// Batch slices of different lengths.
    #[error("batch slices differ in length: psi {psi}, theta {theta}, f_star {f_star}, out {out}")]
    LengthMismatch {
        /// Length of `psi`.
        psi: usize,
        /// Length of `theta`.
        theta: usize,
        /// Length of `f_star`.
        f_star: usize,
        /// Length of `out`.
        out: usize,
    },
    /// A curve's batch slices of different lengths.
    #[error("batch slices differ in length: f_star {f_star}, out {out}")]
    CurveLengthMismatch {
        /// Length of `f_star`.
        f_star: usize,
        /// Length of `out`.
        out: usize,
    },
    /// A batch element was NaN or out of the domain; `index` says which.
    #[error("batch element {index}: {name} = {} is outside the range [{}, {}]", Shortest(*.value), Shortest(*.lo), Shortest(*.hi))]
    BatchElement {
        /// Position in the slices.
        index: usize,
        /// `"psi"`, `"theta"` or `"f_star"`.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Lower end of the table's range.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
}

impl LookupError {
    /// This error as the error of batch element `index` (an element's own
    /// [`OutOfDomain`](LookupError::OutOfDomain) becomes
    /// [`BatchElement`](LookupError::BatchElement) with the same fields).
    pub fn at(self, index: usize) -> LookupError {
        match self {
            LookupError::OutOfDomain { name, value, lo, hi }
            | LookupError::BatchElement {
                name, value, lo, hi, ..
            } => LookupError::BatchElement {
                index,
                name,
                value,
                lo,
                hi,
            },
            other => other,
        }
    }

    /// For a caller that split a batch into pieces: a batch element's
    /// index moved by `offset` (the piece's start); other errors as they are.
    pub fn shifted(self, offset: usize) -> LookupError {
        match self {
            LookupError::BatchElement { index, .. } => self.at(index + offset),
            other => other,
        }
    }

    /// The element's index, for a batch element's error.
    pub fn index(&self) -> Option<usize> {
        match self {
            LookupError::BatchElement { index, .. } => Some(*index),
            _ => None,
        }
    }
}

/// What a batch does at an element it cannot answer (NaN, or outside the
/// table's domain or the curve's range). Every batch function of [`Table`](crate::Table)
/// and [`Curve`](crate::Curve) follows it, and the C and Python bindings
/// hand it on rather than re-implement it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OnError {
    /// Stop at the first bad element `i`: `out[..i]` holds the results,
    /// `out[i..]` is untouched, and the error is
    /// [`LookupError::BatchElement`] with index `i` and the element's own
    /// error (see [`LookupError::shifted`] for split batches).
    #[default]
    Stop,
    /// Write NaN at each bad element (a NaN pair for slopes) and finish the
    /// batch; the call returns how many elements are NaN.
    Nan,
}

impl OnError {
    /// At bad element `index` with error `e`: go on (`Nan`), or the batch
    /// error (`Stop`).
    pub(crate) fn bad(self, index: usize, e: LookupError) -> Result<(), LookupError> {
        match self {
            OnError::Stop => Err(e.at(index)),
            OnError::Nan => Ok(()),
        }
    }
}

impl crate::Classify for LookupError {
    /// [`crate::ErrorKind::Argument`] for NaN or a length mismatch, else
    /// [`crate::ErrorKind::Domain`].
    fn kind(&self) -> crate::ErrorKind {
        use LookupError::*;
        match self {
            OutOfDomain { value, .. } | BatchElement { value, .. } => crate::ErrorKind::of_value(*value),
            LengthMismatch { .. } | CurveLengthMismatch { .. } => crate::ErrorKind::Argument,
        }
    }
}

/// The pairs in a stack buffer: at most this many at a time.
const CHUNK: usize = 256;

/// A batch of (μ, slope) pairs written to two arrays `mu` and `slope` (as
/// C and NumPy callers hold them): `batch(range, out)` runs a pairs batch
/// for elements `range` into `out`, a stack buffer of at most 256 pairs at
/// a time; the NaN count, or the first bad element's error (elements
/// before it written, none from it on). `mu` and `slope` have one length
/// (the callers check it against their inputs').
pub(crate) fn scatter_pairs(
    mu: &mut [f64],
    slope: &mut [f64],
    mut batch: impl FnMut(Range<usize>, &mut [(f64, f64)]) -> Result<usize, LookupError>,
) -> Result<usize, LookupError> {
    debug_assert_eq!(mu.len(), slope.len());
    let mut buffer = [(0.0, 0.0); CHUNK];
    let mut nan = 0;
    for start in (0..mu.len()).step_by(CHUNK) {
        let end = mu.len().min(start + CHUNK);
        let out = &mut buffer[..end - start];
        let result = batch(start..end, out);
        let done = match &result {
            Ok(_) => out.len(),
            Err(e) => e.index().unwrap_or(0),
        };
        for (k, &(m, s)) in out[..done].iter().enumerate() {
            (mu[start + k], slope[start + k]) = (m, s);
        }
        nan += result.map_err(|e| e.shifted(start))?;
    }
    Ok(nan)
}
