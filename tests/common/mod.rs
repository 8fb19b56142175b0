//! Shared tolerances and helpers for the integration tests.
#![allow(dead_code)]

/// Relative agreement with 30-digit quadrature that the issue demands of
/// every model output (MODEL.md §7 values are themselves good to ~1e-15,
/// printed to 11 digits, so this also bounds the printing error).
pub const REFERENCE_REL: f64 = 1e-9;

/// Relative difference, safe at zero.
pub fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// Asserts `|a − b| ≤ tol·max(|a|, |b|)` with a message naming `what`.
#[track_caller]
pub fn assert_rel(what: &str, got: f64, want: f64, tol: f64) {
    let r = rel(got, want);
    assert!(
        r <= tol,
        "{what}: got {got:e}, want {want:e}, relative error {r:e} > {tol:e}"
    );
}
