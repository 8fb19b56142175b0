//! The curve handle μ(F*) of one surface pair: from a table or by direct
//! integration, its lookups and batches, its range, freeing.

use crate::batch::stop;
use crate::constants::kef_constants;
use crate::error::Failure;
use crate::macros::{free, set, set2};
use crate::model::explicit;
use crate::table::kef_table;
use ke_friction::{Constants, Curve, LookupError, Model, OnError};
use std::ffi::c_int;

/// μ(F*) of one surface pair, fixed ψ and θ (opaque). Immutable; may be
/// shared across threads.
pub struct kef_curve(Curve);

pointee!(*const kef_curve => &'a Curve, |p| p.as_ref().map(|c| &c.0));

/// [`Curve::mu_with_slope_batch_with`] into two arrays.
fn curve_slopes(
    curve: &Curve,
    f_star: &[f64],
    mu: &mut [f64],
    slope: &mut [f64],
    on_error: OnError,
) -> Result<usize, LookupError> {
    curve.mu_with_slope_into(f_star, mu, slope, on_error)
}

/// A curve by direct integration over [`lo`, `hi`].
fn model_curve(constants: &Constants, psi: f64, theta: f64, lo: f64, hi: f64) -> Result<Box<kef_curve>, Failure> {
    let model = Model::new(constants.at(psi, theta)?)?;
    Ok(Box::new(kef_curve(Curve::from_model(&model, lo, hi)?)))
}

/// A curve μ(F*) for (ψ, θ) from `table`, over the table's F* range (to
/// free with kef_curve_free), or NULL: KEF_ERR_ARGUMENT for a NULL table
/// or a NaN, KEF_ERR_DOMAIN for ψ or θ outside the table.
///
/// # Safety
/// `table` is NULL or a live table.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_from_table(table: *const kef_table, psi: f64, theta: f64) -> *mut kef_curve {
    ffi!(table => Ok(Box::new(kef_curve(table.curve(psi, theta)?))))
}

/// kef_curve_from_table for a surface pair whose model constants are
/// `constants` (NULL: the defaults): NULL with KEF_ERR_DOMAIN, naming the
/// first constant that differs and both values, unless they are the
/// table's (as kef_table_mu_with); then as kef_curve_from_table.
///
/// # Safety
/// `table` is NULL or a live table; `constants` NULL or a live
/// kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_from_table_with(
    table: *const kef_table,
    constants: *const kef_constants,
    psi: f64,
    theta: f64,
) -> *mut kef_curve {
    ffi!(table, constants => {
        table.check_constants(constants)?;
        Ok(Box::new(kef_curve(table.curve(psi, theta)?)))
    })
}

/// A curve μ(F*) for F* in [f_star_min, f_star_max] by direct integration
/// of the Kogut–Etsion model (ψ, θ, β, ν, ε*; the paper's constants are
/// β = 0.04, ν = 0.3, ε* = 0.004; the default fit and model): within 1e-6
/// relative of the model, about 20 ms to build. kef_curve_from_model_with
/// with these constants.
#[no_mangle]
pub extern "C" fn kef_curve_from_model(
    psi: f64,
    theta: f64,
    beta: f64,
    nu: f64,
    eps_star: f64,
    f_star_min: f64,
    f_star_max: f64,
) -> *mut kef_curve {
    ffi!(=> model_curve(&explicit(beta, nu, eps_star), psi, theta, f_star_min, f_star_max))
}

/// A curve μ(F*) for F* in [f_star_min, f_star_max] by direct integration
/// of the model with `constants` (NULL: the defaults) at (ψ, θ): within
/// 1e-6 relative of the model, about 20 ms to build. NULL on failure:
/// KEF_ERR_DOMAIN for a parameter out of range, KEF_ERR_ARGUMENT for a NaN
/// or an invalid range, KEF_ERR_NO_MU where the model has no positive μ in
/// the range.
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_from_model_with(
    constants: *const kef_constants,
    psi: f64,
    theta: f64,
    f_star_min: f64,
    f_star_max: f64,
) -> *mut kef_curve {
    ffi!(constants => model_curve(constants, psi, theta, f_star_min, f_star_max))
}

/// μ(F*) from `curve` into `*mu`: KEF_ERR_DOMAIN for F* outside the
/// curve's range, KEF_ERR_ARGUMENT for NaN or ±inf.
///
/// # Safety
/// `curve` is NULL or a live curve; `mu` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu(curve: *const kef_curve, f_star: f64, mu: *mut f64) -> c_int {
    ffi!(curve, mu => set(mu, curve.mu(f_star)?))
}

/// μ and dμ/dF* from `curve`; errors as kef_curve_mu, and
/// KEF_ERR_ARGUMENT if the two outputs alias (they must be distinct).
///
/// # Safety
/// `curve` is NULL or a live curve; `mu`, `dmu_df_star` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu_with_slope(
    curve: *const kef_curve,
    f_star: f64,
    mu: *mut f64,
    dmu_df_star: *mut f64,
) -> c_int {
    ffi!(curve, mu, dmu_df_star => set2(mu, dmu_df_star, curve.mu_with_slope(f_star)?))
}

/// μ at `n` loads `f_star[i]` into `mu[i]` (AVX2 where the CPU has it); a
/// bad load and NULL pointers as in kef_table_mu_batch. `mu` must not
/// overlap `f_star` (KEF_ERR_ARGUMENT, nothing written).
///
/// # Safety
/// `curve` is NULL or a live curve; `f_star` NULL or valid for `n` reads;
/// `mu` NULL or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu_batch(
    curve: *const kef_curve,
    n: usize,
    f_star: *const f64,
    mu: *mut f64,
) -> c_int {
    ffi!(curve, f_star[n], mu[n] => stop(curve.mu_batch_with(f_star, mu, OnError::Stop)))
}

/// kef_curve_mu_batch that does not stop: NaN at each load outside the
/// curve's range (or NaN), the count in `*n_nan` (required), KEF_OK. No
/// output may overlap another argument.
///
/// # Safety
/// As kef_curve_mu_batch; `n_nan` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu_batch_nan(
    curve: *const kef_curve,
    n: usize,
    f_star: *const f64,
    mu: *mut f64,
    n_nan: *mut usize,
) -> c_int {
    ffi!(curve, f_star[n], mu[n], n_nan => set(n_nan, curve.mu_batch_with(f_star, mu, OnError::Nan)?))
}

/// μ and dμ/dF* at `n` loads into `mu[i]` and `dmu_df_star[i]`; a bad
/// load and NULL pointers as in kef_table_mu_batch. No output may overlap
/// another argument (KEF_ERR_ARGUMENT, nothing written).
///
/// # Safety
/// As kef_curve_mu_batch; `dmu_df_star` NULL or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu_with_slope_batch(
    curve: *const kef_curve,
    n: usize,
    f_star: *const f64,
    mu: *mut f64,
    dmu_df_star: *mut f64,
) -> c_int {
    ffi!(curve, f_star[n], mu[n], dmu_df_star[n] => stop(curve_slopes(curve, f_star, mu, dmu_df_star, OnError::Stop)))
}

/// kef_curve_mu_with_slope_batch that does not stop: NaN in both outputs
/// at each bad load, the count in `*n_nan`, KEF_OK. No output may overlap
/// another argument.
///
/// # Safety
/// As kef_curve_mu_with_slope_batch; `n_nan` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu_with_slope_batch_nan(
    curve: *const kef_curve,
    n: usize,
    f_star: *const f64,
    mu: *mut f64,
    dmu_df_star: *mut f64,
    n_nan: *mut usize,
) -> c_int {
    ffi!(curve, f_star[n], mu[n], dmu_df_star[n], n_nan =>
        set(n_nan, curve_slopes(curve, f_star, mu, dmu_df_star, OnError::Nan)?))
}

/// The F* range [*f_star_min, *f_star_max] of `curve`. KEF_ERR_ARGUMENT
/// for a NULL pointer or if the two outputs alias (they must be distinct).
///
/// # Safety
/// `curve` is NULL or a live curve; the outputs NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_range(curve: *const kef_curve, f_star_min: *mut f64, f_star_max: *mut f64) -> c_int {
    ffi!(curve, f_star_min, f_star_max => set2(f_star_min, f_star_max, curve.range()))
}

/// Frees a curve. NULL is ignored.
///
/// # Safety
/// `curve` is NULL or a curve from a kef_curve_from_* not yet freed and no
/// longer in use by any thread.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_free(curve: *mut kef_curve) {
    // SAFETY: the caller's contract.
    unsafe { free(curve, std::ptr::null()) }
}
