//! Stands in for the curve's AVX2 batch on targets other than x86-64: it
//! is never detected, so batches run the scalar loop.

use super::Curve;

/// A batch kernel that cannot exist.
#[derive(Debug, Clone, Copy)]
pub(super) enum Batch {}

impl Batch {
    /// Never a kernel.
    pub(super) fn detect() -> Option<Batch> {
        None
    }

    /// Unreachable: there is no `Batch` to call it on.
    pub(super) fn mu(self, _: &Curve, _: &[f64], _: &mut [f64]) -> usize {
        match self {}
    }
}
