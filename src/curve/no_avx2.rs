//! Stands in for the curve's AVX2 batch on targets other than x86-64 (and
//! with `--cfg ke_friction_portable`): it is never detected, so batches
//! run the scalar loop. Compiled on every target.

use super::{BatchKernel, Curve};

/// A batch kernel that cannot exist.
#[derive(Debug, Clone, Copy)]
#[allow(dead_code)] // not constructed, by design; unused on x86-64
pub(super) enum Batch {}

impl BatchKernel for Batch {
    /// Never a kernel.
    fn detect() -> Option<Batch> {
        None
    }

    /// Unreachable: there is no `Batch` to call it on.
    fn mu(self, _: &Curve, _: &[f64], _: &mut [f64]) -> usize {
        match self {}
    }
}
