//! The C ABI of ke-friction: table and curve lookups and the model by
//! direct integration, for C, C++ and Fortran (`include/kefriction.h`,
//! `fortran/ke_friction.f90`).
//!
//! Conventions of every function:
//! - a return code: [`KEF_OK`] (0) or one of the `KEF_ERR_*` codes (or a
//!   NULL handle); on failure [`kef_last_error`] holds the message (the
//!   Rust error's one line: argument, value, valid range) and the outputs
//!   are untouched, except that a batch writes the elements before the
//!   first bad one and nothing from it on;
//! - a NULL pointer where one is required is [`KEF_ERR_ARGUMENT`], never a
//!   crash; no panic crosses the boundary ([`KEF_ERR_INTERNAL`] if one
//!   ever happened);
//! - tables and curves are immutable: any number of threads may use one
//!   at once; only freeing it must wait until they are done.
#![warn(missing_docs)]
#![deny(unsafe_op_in_unsafe_fn)]
#![warn(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]
// The C names are the contract.
#![allow(non_camel_case_types)]

use ke_friction::num::Shortest;
use ke_friction::{Curve, CurveError, LookupError, Model, Params, Table, TableError};
use std::borrow::Cow;
use std::cell::RefCell;
use std::ffi::{c_char, c_int, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::OnceLock;

/// Success.
pub const KEF_OK: c_int = 0;
/// A lookup argument outside the table's or curve's range, or NaN; or no
/// μ where the model has none (F* <= 0, or no solution).
pub const KEF_ERR_DOMAIN: c_int = 1;
/// A NULL pointer, or an invalid model parameter (e.g. psi <= 0,
/// f_star_min >= f_star_max).
pub const KEF_ERR_ARGUMENT: c_int = 2;
/// A table file that cannot be read.
pub const KEF_ERR_IO: c_int = 3;
/// A damaged or incompatible table file.
pub const KEF_ERR_TABLE: c_int = 4;
/// A bug in ke-friction (a caught panic); please report the message.
pub const KEF_ERR_INTERNAL: c_int = 5;

/// A table of μ(ψ, θ, F*) (opaque). Immutable; may be shared across threads.
pub struct kef_table(Cow<'static, Table>);

/// The handle of the embedded table.
static DEFAULT: OnceLock<kef_table> = OnceLock::new();

/// μ(F*) of one surface pair, fixed ψ and θ (opaque). Immutable; may be
/// shared across threads.
pub struct kef_curve(Curve);

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// A failure: its code and message.
struct Failure(c_int, String);

fn domain(e: LookupError) -> Failure {
    Failure(KEF_ERR_DOMAIN, e.to_string())
}

fn null(name: &str) -> Failure {
    Failure(KEF_ERR_ARGUMENT, format!("{name} is NULL"))
}

fn remember(message: &str) {
    let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
    LAST_ERROR.with(|e| *e.borrow_mut() = text);
}

/// Runs `body`, turning a failure or a panic into its code and message.
fn guard(body: impl FnOnce() -> Result<(), Failure>) -> c_int {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => KEF_OK,
        Ok(Err(Failure(code, message))) => {
            remember(&message);
            code
        }
        Err(_) => {
            remember("internal error: a panic in ke-friction (please report it)");
            KEF_ERR_INTERNAL
        }
    }
}

/// Runs `body`, returning its handle or NULL on a failure or a panic.
fn guard_ptr<T>(body: impl FnOnce() -> Result<*mut T, Failure>) -> *mut T {
    let mut out = std::ptr::null_mut();
    guard(|| {
        out = body()?;
        Ok(())
    });
    out
}

/// The table behind `table`, or a failure naming it.
///
/// # Safety
/// `table` is NULL or a pointer from `kef_table_default`/`kef_table_load`
/// not yet freed.
unsafe fn table_ref<'a>(table: *const kef_table) -> Result<&'a Table, Failure> {
    // SAFETY: the caller's contract: NULL or a live table.
    unsafe { table.as_ref() }.map(|t| &*t.0).ok_or_else(|| null("table"))
}

/// The curve behind `curve`, or a failure naming it.
///
/// # Safety
/// `curve` is NULL or a pointer from a `kef_curve_from_*` not yet freed.
unsafe fn curve_ref<'a>(curve: *const kef_curve) -> Result<&'a Curve, Failure> {
    // SAFETY: the caller's contract: NULL or a live curve.
    unsafe { curve.as_ref() }.map(|c| &c.0).ok_or_else(|| null("curve"))
}

/// Writes `value` through `out`, or fails if `out` is NULL.
///
/// # Safety
/// `out` is NULL or valid for one write of a double.
unsafe fn put(out: *mut f64, value: f64) {
    // SAFETY: the caller checked `out` is not NULL and it is writable.
    unsafe { out.write(value) }
}

/// Fails if any of the pointers is NULL.
fn required(pointers: &[(&str, bool)]) -> Result<(), Failure> {
    match pointers.iter().find(|(_, is_null)| *is_null) {
        Some((name, _)) => Err(null(name)),
        None => Ok(()),
    }
}

/// The message of this thread's last failure ("" if none): valid until the
/// next failing call on this thread. Never NULL; do not free it.
#[no_mangle]
pub extern "C" fn kef_last_error() -> *const c_char {
    LAST_ERROR.with(|e| e.borrow().as_ptr())
}

/// The table compiled into the library (ψ in [0.5, 8], θ in [0, 0.01],
/// F* in [1e-5, 0.1]; μ within 1e-4 relative of direct integration).
/// Never NULL; never freed (kef_table_free ignores it).
#[no_mangle]
pub extern "C" fn kef_table_default() -> *const kef_table {
    DEFAULT.get_or_init(|| kef_table(Cow::Borrowed(Table::embedded())))
}

/// Loads a table file (`path`: a NUL-terminated path, UTF-8 on Windows).
/// Returns a table to free with kef_table_free, or NULL with
/// KEF_ERR_ARGUMENT (NULL path), KEF_ERR_IO (unreadable file) or
/// KEF_ERR_TABLE (damaged or incompatible file) in kef_last_error.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn kef_table_load(path: *const c_char) -> *mut kef_table {
    guard_ptr(|| {
        if path.is_null() {
            return Err(null("path"));
        }
        // SAFETY: not NULL, and NUL-terminated by the caller's contract.
        let bytes = unsafe { CStr::from_ptr(path) }.to_bytes();
        #[cfg(not(unix))]
        let path = std::path::PathBuf::from(String::from_utf8_lossy(bytes).into_owned());
        #[cfg(unix)]
        let path = {
            use std::os::unix::ffi::OsStrExt;
            std::path::PathBuf::from(std::ffi::OsStr::from_bytes(bytes))
        };
        let table = Table::load(&path).map_err(|e| match e {
            TableError::Io { .. } => Failure(KEF_ERR_IO, e.to_string()),
            _ => Failure(KEF_ERR_TABLE, format!("{}: {e}", path.display())),
        })?;
        Ok(Box::into_raw(Box::new(kef_table(Cow::Owned(table)))))
    })
}

/// Frees a table from kef_table_load. NULL and the default table are
/// ignored.
///
/// # Safety
/// `table` is NULL, the default table, or a table from kef_table_load not
/// yet freed and no longer in use by any thread.
#[no_mangle]
pub unsafe extern "C" fn kef_table_free(table: *mut kef_table) {
    if table.is_null() || std::ptr::eq(table.cast_const(), kef_table_default()) {
        return;
    }
    // SAFETY: a pointer from Box::into_raw in kef_table_load, freed once.
    drop(unsafe { Box::from_raw(table) });
}

/// μ(ψ, θ, F*) from `table` into `*mu` (dimensionless: F* = F/(A_n·H),
/// θ = Δγ/(σH)). KEF_ERR_DOMAIN if an argument is NaN or outside the
/// table's range; KEF_ERR_ARGUMENT for a NULL pointer.
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
    guard(|| {
        // SAFETY: the caller's contract.
        let table = unsafe { table_ref(table) }?;
        required(&[("mu", mu.is_null())])?;
        let value = table.mu(psi, theta, f_star).map_err(domain)?;
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { put(mu, value) };
        Ok(())
    })
}

/// μ and ∂μ/∂F* from `table` into `*mu` and `*dmu_df_star`; errors as
/// kef_table_mu.
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
    guard(|| {
        // SAFETY: the caller's contract.
        let table = unsafe { table_ref(table) }?;
        required(&[("mu", mu.is_null()), ("dmu_df_star", dmu_df_star.is_null())])?;
        let (m, s) = table.mu_with_slope(psi, theta, f_star).map_err(domain)?;
        // SAFETY: both checked non-NULL; writable by the caller's contract.
        unsafe {
            put(mu, m);
            put(dmu_df_star, s);
        }
        Ok(())
    })
}

/// The slice of `n` doubles at `p`, or a failure naming it (NULL is only
/// allowed when `n` is 0).
///
/// # Safety
/// `p` is NULL or valid for `n` reads.
unsafe fn input<'a>(name: &str, p: *const f64, n: usize) -> Result<&'a [f64], Failure> {
    match (p.is_null(), n) {
        (_, 0) => Ok(&[]),
        (true, _) => Err(null(name)),
        // SAFETY: valid for n reads by the caller's contract.
        (false, _) => Ok(unsafe { std::slice::from_raw_parts(p, n) }),
    }
}

/// The writable slice of `n` doubles at `p` (see [`input`]).
///
/// # Safety
/// `p` is NULL or valid for `n` writes, and overlaps no input.
unsafe fn output<'a>(name: &str, p: *mut f64, n: usize) -> Result<&'a mut [f64], Failure> {
    match (p.is_null(), n) {
        (_, 0) => Ok(&mut []),
        (true, _) => Err(null(name)),
        // SAFETY: valid for n writes and unaliased by the caller's contract.
        (false, _) => Ok(unsafe { std::slice::from_raw_parts_mut(p, n) }),
    }
}

/// The index of the first query outside `table`'s domain (or NaN), with
/// its error.
fn first_bad(table: &Table, psi: &[f64], theta: &[f64], f_star: &[f64]) -> Option<(usize, LookupError)> {
    let [(p0, p1), (t0, t1), (f0, f1)] = table.domain().ranges();
    let inside = |v: f64, lo: f64, hi: f64| v >= lo && v <= hi;
    let i =
        (0..psi.len()).find(|&i| !(inside(psi[i], p0, p1) && inside(theta[i], t0, t1) && inside(f_star[i], f0, f1)))?;
    Some((i, table.mu(psi[i], theta[i], f_star[i]).err()?))
}

/// μ at `n` points `(psi[i], theta[i], f_star[i])` into `mu[i]`, vectorised (AVX2
/// where the CPU has it). On a point outside the table, KEF_ERR_DOMAIN
/// with its index in the message; `mu` is written before that index and
/// not from it on. Pointers may be NULL only when n is 0; `mu` must not
/// overlap the inputs.
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
    guard(|| {
        // SAFETY: the caller's contract, for each pointer.
        let (table, psi, theta, f_star, mu) = unsafe {
            (
                table_ref(table)?,
                input("psi", psi, n)?,
                input("theta", theta, n)?,
                input("f_star", f_star, n)?,
                output("mu", mu, n)?,
            )
        };
        let (good, bad) = match first_bad(table, psi, theta, f_star) {
            Some((i, e)) => (i, Some((i, e))),
            None => (n, None),
        };
        table
            .mu_batch(&psi[..good], &theta[..good], &f_star[..good], &mut mu[..good])
            .map_err(domain)?;
        match bad {
            Some((i, e)) => Err(Failure(KEF_ERR_DOMAIN, format!("batch element {i}: {e}"))),
            None => Ok(()),
        }
    })
}

/// A curve μ(F*) for (ψ, θ) from `table`, over the table's F* range (to
/// free with kef_curve_free), or NULL: KEF_ERR_ARGUMENT for a NULL table,
/// KEF_ERR_DOMAIN for ψ or θ outside the table.
///
/// # Safety
/// `table` is NULL or a live table.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_from_table(table: *const kef_table, psi: f64, theta: f64) -> *mut kef_curve {
    guard_ptr(|| {
        // SAFETY: the caller's contract.
        let table = unsafe { table_ref(table) }?;
        let curve = table.curve(psi, theta).map_err(curve_failure)?;
        Ok(Box::into_raw(Box::new(kef_curve(curve))))
    })
}

fn curve_failure(e: CurveError) -> Failure {
    let code = match e {
        CurveError::Range { .. } | CurveError::TooWide { .. } => KEF_ERR_ARGUMENT,
        _ => KEF_ERR_DOMAIN,
    };
    Failure(code, e.to_string())
}

fn model(psi: f64, theta: f64, beta: f64, nu: f64, eps_star: f64) -> Result<Model, Failure> {
    let params = Params::new(psi, theta).beta(beta).nu(nu).eps_star(eps_star);
    Model::new(params).map_err(|e| Failure(KEF_ERR_ARGUMENT, e.to_string()))
}

/// A curve μ(F*) for F* in [f_star_min, f_star_max] by direct integration
/// of the Kogut–Etsion model (ψ, θ, β, ν, ε*; the paper's constants are
/// β = 0.04, ν = 0.3, ε* = 0.004): within 1e-6 relative of the model,
/// about 20 ms to build. Returns NULL with KEF_ERR_ARGUMENT for an
/// invalid parameter or range, KEF_ERR_DOMAIN where the model has no
/// positive μ in the range.
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
    guard_ptr(|| {
        let m = model(psi, theta, beta, nu, eps_star)?;
        let curve = Curve::from_model(&m, f_star_min, f_star_max).map_err(curve_failure)?;
        Ok(Box::into_raw(Box::new(kef_curve(curve))))
    })
}

/// μ(F*) from `curve` into `*mu`: KEF_ERR_DOMAIN for F* NaN or outside the
/// curve's range.
///
/// # Safety
/// `curve` is NULL or a live curve; `mu` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu(curve: *const kef_curve, f_star: f64, mu: *mut f64) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let curve = unsafe { curve_ref(curve) }?;
        required(&[("mu", mu.is_null())])?;
        let value = curve.mu(f_star).map_err(domain)?;
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { put(mu, value) };
        Ok(())
    })
}

/// μ and dμ/dF* from `curve`; errors as kef_curve_mu.
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
    guard(|| {
        // SAFETY: the caller's contract.
        let curve = unsafe { curve_ref(curve) }?;
        required(&[("mu", mu.is_null()), ("dmu_df_star", dmu_df_star.is_null())])?;
        let (m, s) = curve.mu_with_slope(f_star).map_err(domain)?;
        // SAFETY: both checked non-NULL; writable by the caller's contract.
        unsafe {
            put(mu, m);
            put(dmu_df_star, s);
        }
        Ok(())
    })
}

/// μ at `n` loads `f_star[i]` into `mu[i]` (AVX2 where the CPU has it); a
/// bad load as in kef_table_mu_batch.
///
/// # Safety
/// `curve` is NULL or a live curve; `f_star` NULL or valid for `n` reads;
/// `mu` NULL or valid for `n` writes, not overlapping `f_star`.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_mu_batch(
    curve: *const kef_curve,
    n: usize,
    f_star: *const f64,
    mu: *mut f64,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract, for each pointer.
        let (curve, f_star, mu) = unsafe { (curve_ref(curve)?, input("f_star", f_star, n)?, output("mu", mu, n)?) };
        let (lo, hi) = curve.range();
        let good = f_star.iter().position(|&f| !(f >= lo && f <= hi)).unwrap_or(n);
        curve.mu_batch(&f_star[..good], &mut mu[..good]).map_err(domain)?;
        match f_star.get(good) {
            Some(&f) => {
                let e = curve.mu(f).err().map_or_else(String::new, |e| e.to_string());
                Err(Failure(KEF_ERR_DOMAIN, format!("batch element {good}: {e}")))
            }
            None => Ok(()),
        }
    })
}

/// The F* range [*f_star_min, *f_star_max] of `curve`.
///
/// # Safety
/// `curve` is NULL or a live curve; the outputs NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_range(curve: *const kef_curve, f_star_min: *mut f64, f_star_max: *mut f64) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract.
        let curve = unsafe { curve_ref(curve) }?;
        required(&[
            ("f_star_min", f_star_min.is_null()),
            ("f_star_max", f_star_max.is_null()),
        ])?;
        let (lo, hi) = curve.range();
        // SAFETY: both checked non-NULL; writable by the caller's contract.
        unsafe {
            put(f_star_min, lo);
            put(f_star_max, hi);
        }
        Ok(())
    })
}

/// Frees a curve. NULL is ignored.
///
/// # Safety
/// `curve` is NULL or a curve from a kef_curve_from_* not yet freed and no
/// longer in use by any thread.
#[no_mangle]
pub unsafe extern "C" fn kef_curve_free(curve: *mut kef_curve) {
    if !curve.is_null() {
        // SAFETY: a pointer from Box::into_raw, freed once.
        drop(unsafe { Box::from_raw(curve) });
    }
}

/// μ of the Kogut–Etsion model by direct integration (microseconds) at
/// F* (ψ, θ, β, ν, ε* as for kef_curve_from_model). KEF_ERR_ARGUMENT for
/// an invalid parameter or a NULL `mu`; KEF_ERR_DOMAIN where the model has
/// no μ (F* <= 0, or beyond the largest force the model reaches).
///
/// # Safety
/// `mu` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_model_mu(
    psi: f64,
    theta: f64,
    beta: f64,
    nu: f64,
    eps_star: f64,
    f_star: f64,
    mu: *mut f64,
) -> c_int {
    guard(|| {
        required(&[("mu", mu.is_null())])?;
        let m = model(psi, theta, beta, nu, eps_star)?;
        let contact = m
            .at_f_star(f_star)
            .map_err(|e| Failure(KEF_ERR_DOMAIN, e.to_string()))?;
        let value = contact.mu.ok_or_else(|| {
            Failure(
                KEF_ERR_DOMAIN,
                format!(
                    "no mu at f_star = {}: the net normal force is not positive",
                    Shortest(f_star)
                ),
            )
        })?;
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { put(mu, value) };
        Ok(())
    })
}
