//! The parameter checks: one rule for every input (finite and in its
//! range) and one error naming the input, its value and the range. A leaf:
//! the parameters and the distributions both use it.

use crate::bound::Bound;
use crate::error::{Classify, ErrorKind};
use crate::num::Shortest;

/// An input outside its valid range. The message names the input, its
/// value and the range, e.g. `theta = -0.2 is out of range: must be >= 0`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{name} = {} is out of range: must be {range}", Shortest(*.value))]
pub struct ParamError {
    /// The input's name, as in [`Params`](crate::Params) / [`Physical`](crate::Physical).
    pub name: &'static str,
    /// The rejected value.
    pub value: f64,
    /// The valid range, in words.
    pub range: &'static str,
}

/// Rejects NaN, infinities and values outside `bound`, which states
/// itself in the message.
pub(crate) fn check_in(name: &'static str, value: f64, bound: &'static Bound) -> Result<(), ParamError> {
    if value.is_finite() && bound.contains(value) {
        Ok(())
    } else {
        Err(ParamError {
            name,
            value,
            range: bound.range(),
        })
    }
}

/// Rejects a count outside `bound`.
pub(crate) fn check_count(name: &'static str, count: usize, bound: &'static Bound) -> Result<(), ParamError> {
    check_in(name, count as f64, bound)
}

/// Rejects NaN, infinities and values failing `ok`: for relations
/// between inputs (a range of one input is a [`Bound`], [`check_in`]).
pub(crate) fn check(
    name: &'static str,
    value: f64,
    range: &'static str,
    ok: impl Fn(f64) -> bool,
) -> Result<(), ParamError> {
    if value.is_finite() && ok(value) {
        Ok(())
    } else {
        Err(ParamError { name, value, range })
    }
}

impl Classify for ParamError {
    /// [`ErrorKind::Argument`] for NaN or ∞, else [`ErrorKind::Domain`].
    fn kind(&self) -> ErrorKind {
        ErrorKind::of_value(self.value)
    }
}
