//! Stands in for the AVX2 kernel on targets other than x86-64: no kernel
//! is ever made, so every table runs the portable one.

use super::layout::Layout;
use super::BatchOutput;

/// A kernel that cannot exist.
#[derive(Debug, Clone)]
pub(super) enum Kernel {}

impl Kernel {
    /// Never a kernel.
    pub(super) fn new(_: &Layout, _: &[f32]) -> Option<Kernel> {
        None
    }

    /// Unreachable: there is no `Kernel` to call it on.
    pub(super) fn eval<const SLOPE: bool>(&self, _: f64, _: f64, _: f64) -> (f64, f64) {
        match *self {}
    }

    /// Unreachable: there is no `Kernel` to call it on.
    pub(super) fn prepare(&self, _: usize) {
        match *self {}
    }

    /// Unreachable: there is no `Kernel` to call it on.
    pub(super) fn batch(&self, _: &[f64], _: &[f64], _: &[f64], _: BatchOutput) -> Option<usize> {
        match *self {}
    }
}
