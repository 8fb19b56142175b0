//! Lookups in a table: μ, its slope and the separation h*, one point at a
//! time or in batches.

use crate::batch::stop;
use crate::constants::kef_constants;
use crate::macros::{set, set2};
use crate::table::kef_table;
use ke_friction::{LookupError, OnError, Table};
use std::ffi::c_int;

/// [`Table::mu_with_slope_batch_with`] into two arrays.
fn table_slopes(
    table: &Table,
    [psi, theta, f_star]: [&[f64]; 3],
    mu: &mut [f64],
    slope: &mut [f64],
    on_error: OnError,
) -> Result<usize, LookupError> {
    table.mu_with_slope_into(psi, theta, f_star, mu, slope, on_error)
}

/// [`Table::h_star`] at each point into `out`, stopping at the first
/// bad one (the elements before it written).
fn h_star_batch(table: &Table, [psi, theta, f_star]: [&[f64]; 3], out: &mut [f64]) -> Result<usize, LookupError> {
    for (i, h) in out.iter_mut().enumerate() {
        *h = table.h_star(psi[i], theta[i], f_star[i]).map_err(|e| e.at(i))?;
    }
    Ok(0)
}

/// The separation h*(ψ, θ, F*) = h/σ at which the surfaces carry F*, from
/// `table`, into `*h_star` (the mean-plane separation over σ; it falls as
/// F* grows). Errors as kef_table_mu.
///
/// # Safety
/// `table` is NULL or a live table; `h_star` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_h_star(
    table: *const kef_table,
    psi: f64,
    theta: f64,
    f_star: f64,
    h_star: *mut f64,
) -> c_int {
    ffi!(table, h_star => set(h_star, table.h_star(psi, theta, f_star)?))
}

/// h* at `n` points `(psi[i], theta[i], f_star[i])` into `h_star[i]`; a
/// bad point and NULL pointers as in kef_table_mu_batch ("batch element
/// i: " in front of the message, `h_star[0..i)` written, `h_star[i..n)`
/// untouched). `h_star` must not overlap the inputs (KEF_ERR_ARGUMENT,
/// nothing written).
///
/// # Safety
/// `table` is NULL or a live table; `psi`, `theta`, `f_star` NULL or valid
/// for `n` reads; `h_star` NULL or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_table_h_star_batch(
    table: *const kef_table,
    n: usize,
    psi: *const f64,
    theta: *const f64,
    f_star: *const f64,
    h_star: *mut f64,
) -> c_int {
    ffi!(table, psi[n], theta[n], f_star[n], h_star[n] => stop(h_star_batch(table, [psi, theta, f_star], h_star)))
}

/// μ(ψ, θ, F*) from `table` into `*mu` (dimensionless: F* = F/(A_n·H),
/// θ = Δγ/(σH)), assuming the constants (β, ν, ε*, fit, model, heights'
/// distribution) are the table's: ψ and θ of a surface with other
/// constants give a wrong μ here, silently. kef_table_mu_with checks them
/// (the documented path). KEF_ERR_DOMAIN if an argument is outside the
/// table's range, KEF_ERR_ARGUMENT if it is NaN or ±inf, or for a NULL
/// pointer.
///
/// # Safety
/// `table` is NULL or a live table; `mu` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu(
    table: *const kef_table,
    psi: f64,
    theta: f64,
    f_star: f64,
    mu: *mut f64,
) -> c_int {
    ffi!(table, mu => set(mu, table.mu(psi, theta, f_star)?))
}

/// kef_table_mu for a surface pair whose model constants are `constants`
/// (NULL: the defaults): KEF_ERR_DOMAIN, naming the first constant that
/// differs and both values, unless they are the table's (β, ν, ε* within
/// 1e-9 relative; fit, model and distribution equal); then the lookup and
/// its errors as kef_table_mu.
///
/// # Safety
/// `table` is NULL or a live table; `constants` NULL or a live
/// kef_constants; `mu` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_with(
    table: *const kef_table,
    constants: *const kef_constants,
    psi: f64,
    theta: f64,
    f_star: f64,
    mu: *mut f64,
) -> c_int {
    ffi!(table, constants, mu => {
        table.check_constants(constants)?;
        set(mu, table.mu(psi, theta, f_star)?)
    })
}

/// kef_table_mu_batch for surface pairs whose model constants are
/// `constants` (NULL: the defaults), checked once as kef_table_mu_with
/// (nothing written on a mismatch).
///
/// # Safety
/// As kef_table_mu_batch; `constants` NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_batch_with(
    table: *const kef_table,
    constants: *const kef_constants,
    n: usize,
    psi: *const f64,
    theta: *const f64,
    f_star: *const f64,
    mu: *mut f64,
) -> c_int {
    ffi!(table, constants, psi[n], theta[n], f_star[n], mu[n] => {
        table.check_constants(constants)?;
        stop(table.mu_batch_with(psi, theta, f_star, mu, OnError::Stop))
    })
}

/// μ and ∂μ/∂F* from `table` into `*mu` and `*dmu_df_star`; errors as
/// kef_table_mu, and KEF_ERR_ARGUMENT if the two outputs alias (they must
/// be distinct).
///
/// # Safety
/// `table` is NULL or a live table; `mu`, `dmu_df_star` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_with_slope(
    table: *const kef_table,
    psi: f64,
    theta: f64,
    f_star: f64,
    mu: *mut f64,
    dmu_df_star: *mut f64,
) -> c_int {
    ffi!(table, mu, dmu_df_star => set2(mu, dmu_df_star, table.mu_with_slope(psi, theta, f_star)?))
}

/// μ at `n` points `(psi[i], theta[i], f_star[i])` into `mu[i]`,
/// vectorised (AVX2 where the CPU has it). At the first point `i` outside
/// the table (or NaN), the error of kef_table_mu for it with "batch element
/// i: " in front; `mu[0..i)` is written, `mu[i..n)` untouched. Pointers may
/// be NULL only when n is 0 (KEF_ERR_ARGUMENT otherwise); `mu` must not
/// overlap the inputs (KEF_ERR_ARGUMENT, nothing written).
///
/// # Safety
/// `table` is NULL or a live table; `psi`, `theta`, `f_star` NULL or valid
/// for `n` reads; `mu` NULL or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_batch(
    table: *const kef_table,
    n: usize,
    psi: *const f64,
    theta: *const f64,
    f_star: *const f64,
    mu: *mut f64,
) -> c_int {
    ffi!(table, psi[n], theta[n], f_star[n], mu[n] => stop(table.mu_batch_with(psi, theta, f_star, mu, OnError::Stop)))
}

/// kef_table_mu_batch that does not stop: NaN in `mu[i]` at each point
/// outside the table (or NaN), valid values elsewhere, the number of NaN
/// elements in `*n_nan`, and KEF_OK. `n_nan` is required (KEF_ERR_ARGUMENT
/// if NULL) and must not overlap another argument.
///
/// # Safety
/// As kef_table_mu_batch; `n_nan` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_batch_nan(
    table: *const kef_table,
    n: usize,
    psi: *const f64,
    theta: *const f64,
    f_star: *const f64,
    mu: *mut f64,
    n_nan: *mut usize,
) -> c_int {
    ffi!(table, psi[n], theta[n], f_star[n], mu[n], n_nan =>
        set(n_nan, table.mu_batch_with(psi, theta, f_star, mu, OnError::Nan)?))
}

/// μ and ∂μ/∂F* at `n` points into `mu[i]` and `dmu_df_star[i]`; errors,
/// NULL pointers and a bad point as kef_table_mu_batch (both outputs
/// written before it, neither from it on). No output may overlap another
/// argument (KEF_ERR_ARGUMENT, nothing written).
///
/// # Safety
/// As kef_table_mu_batch; `dmu_df_star` NULL or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_with_slope_batch(
    table: *const kef_table,
    n: usize,
    psi: *const f64,
    theta: *const f64,
    f_star: *const f64,
    mu: *mut f64,
    dmu_df_star: *mut f64,
) -> c_int {
    ffi!(table, psi[n], theta[n], f_star[n], mu[n], dmu_df_star[n] =>
        stop(table_slopes(table, [psi, theta, f_star], mu, dmu_df_star, OnError::Stop)))
}

/// kef_table_mu_with_slope_batch that does not stop: NaN in both outputs
/// at each point outside the table, the count in `*n_nan`, KEF_OK. No
/// output may overlap another argument.
///
/// # Safety
/// As kef_table_mu_with_slope_batch; `n_nan` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_mu_with_slope_batch_nan(
    table: *const kef_table,
    n: usize,
    psi: *const f64,
    theta: *const f64,
    f_star: *const f64,
    mu: *mut f64,
    dmu_df_star: *mut f64,
    n_nan: *mut usize,
) -> c_int {
    ffi!(table, psi[n], theta[n], f_star[n], mu[n], dmu_df_star[n], n_nan =>
        set(n_nan, table_slopes(table, [psi, theta, f_star], mu, dmu_df_star, OnError::Nan)?))
}
