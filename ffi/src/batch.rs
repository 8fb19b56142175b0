//! The batches' shared helper: the stop mode's result (the (μ, slope)
//! pairs into two arrays are the core's `mu_with_slope_into`).

use crate::error::Failure;
use ke_friction::LookupError;

/// A batch in [`OnError::Stop`](ke_friction::OnError::Stop) mode: success, or the core's error.
pub(crate) fn stop(result: Result<usize, LookupError>) -> Result<(), Failure> {
    result.map(|_| ()).map_err(Failure::from)
}
