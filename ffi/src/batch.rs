//! The batches' shared helpers: the stop mode's result and the (μ, slope)
//! pairs scattered into two arrays.

use crate::error::Failure;
use ke_friction::LookupError;
use std::ops::Range;

/// A batch in [`OnError::Stop`](ke_friction::OnError::Stop) mode: success, or the core's error.
pub(crate) fn stop(result: Result<usize, LookupError>) -> Result<(), Failure> {
    result.map(|_| ()).map_err(Failure::from)
}

/// The pairs in a stack buffer: at most this many at a time.
const CHUNK: usize = 256;

/// A batch of (μ, slope) pairs written to `mu` and `slope`: `batch(range,
/// out)` runs the core's batch for elements `range` into `out`, chunk by
/// chunk; the NaN count, or the first bad element's error (elements before
/// it written, none from it on).
pub(crate) fn scatter(
    mu: &mut [f64],
    slope: &mut [f64],
    mut batch: impl FnMut(Range<usize>, &mut [(f64, f64)]) -> Result<usize, LookupError>,
) -> Result<usize, LookupError> {
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
