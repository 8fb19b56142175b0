//! Conversions between Python's values and the core's: array arguments as
//! slices (copied where not aligned), the NaN flag as the core's
//! [`OnError`], the core's records as Python dicts.

use crate::error::{exception, value_error};
use ke_friction::{ErrorKind, OnError};
use numpy::{PyArrayMethods, PyReadonlyArray1, PyReadwriteArray1, PyUntypedArrayMethods};
use pyo3::prelude::*;
use std::borrow::Cow;

/// The data of array argument `name`: in place where it is contiguous and
/// aligned, else a copy of a contiguous array that is not aligned (a view
/// at an odd offset into a buffer, `np.frombuffer(b[1:])`).
pub fn slice<'a>(name: &str, a: &'a PyReadonlyArray1<'_, f64>) -> PyResult<Cow<'a, [f64]>> {
    if let Ok(s) = a.as_slice() {
        return Ok(Cow::Borrowed(s));
    }
    if !a.is_contiguous() {
        return Err(value_error(format!("{name} must be contiguous")));
    }
    let (ptr, n) = (a.data().cast_const(), a.len());
    // SAFETY: a contiguous array of `n` f64 starts at `ptr`, aligned or
    // not (hence `read_unaligned`); the read-only borrow `a` keeps it alive,
    // and the GIL, held here, keeps Python code from changing it meanwhile.
    Ok(Cow::Owned(
        (0..n).map(|i| unsafe { ptr.add(i).read_unaligned() }).collect(),
    ))
}

/// The contiguous data of output array `name`.
pub fn slice_mut<'a>(name: &str, a: &'a mut PyReadwriteArray1<'_, f64>) -> PyResult<&'a mut [f64]> {
    a.as_slice_mut()
        .map_err(|_| value_error(format!("{name} must be contiguous")))
}

/// A `ValueError` unless every named length is `n` (the Python layer
/// always passes equal lengths; this keeps a direct call of `_core` from
/// panicking).
pub fn same_len(n: usize, named: &[(&str, usize)]) -> PyResult<()> {
    match named.iter().find(|(_, len)| *len != n) {
        None => Ok(()),
        Some((name, len)) => Err(value_error(format!("{name} has {len} elements, not {n}"))),
    }
}

/// The core's policy for bad elements: NaN there (`nan`, the Python
/// layer's `out_of_domain="nan"`), or stop at the first.
pub fn on_error(nan: bool) -> OnError {
    if nan {
        OnError::Nan
    } else {
        OnError::Stop
    }
}

/// A record of the core (`serde_json::to_string` of its `Serialize`
/// type) as Python objects, by Python's `json.loads`: dicts with the
/// core's field names, lists for tuples and arrays.
pub fn record<'py>(py: Python<'py>, json: serde_json::Result<String>) -> PyResult<Bound<'py, PyAny>> {
    let text = json.map_err(|e| exception(ErrorKind::Internal, format!("a record does not serialise: {e}")))?;
    py.import("json")?.call_method1("loads", (text,))
}
