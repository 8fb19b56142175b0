//! Stands in for the AVX2 kernel on targets other than x86-64 (and with
//! `--cfg ke_friction_portable`): no kernel is ever made, so every table
//! runs the portable one. Compiled on every target, so that it keeps up
//! with [`FastKernel`].

use super::layout::Layout;
use super::{BatchOutput, FastKernel};

/// A kernel that cannot exist.
#[derive(Debug, Clone)]
#[allow(dead_code)] // not constructed, by design; unused on x86-64
pub(super) enum Kernel {}

impl FastKernel for Kernel {
    /// Never a kernel.
    fn new(_: &Layout, _: &[f32]) -> Option<Kernel> {
        None
    }

    /// Unreachable: there is no `Kernel` to call it on.
    fn eval<const SLOPE: bool>(&self, _: f64, _: f64, _: f64) -> (f64, f64) {
        match *self {}
    }

    /// Unreachable: there is no `Kernel` to call it on.
    fn prepare(&self, _: usize) {
        match *self {}
    }

    /// Unreachable: there is no `Kernel` to call it on.
    fn batch(&self, _: &[f64], _: &[f64], _: &[f64], _: BatchOutput) -> Option<usize> {
        match *self {}
    }
}
