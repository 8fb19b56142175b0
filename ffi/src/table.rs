//! The table handle: the embedded table, table files, freeing, and the
//! ranges a table covers.

use crate::error::Failure;
use crate::macros::{free, set2};
use ke_friction::Table;
use std::borrow::Cow;
use std::ffi::{c_char, c_int, CStr};
use std::sync::OnceLock;

/// A table of μ(ψ, θ, F*) (opaque). Immutable; may be shared across threads.
pub struct kef_table(Cow<'static, Table>);

/// The handle of the embedded table.
static DEFAULT: OnceLock<kef_table> = OnceLock::new();

pointee!(*const kef_table => &'a Table, |p| p.as_ref().map(|t| &*t.0));

/// The table file at `path`.
fn load(path: &CStr) -> Result<Box<kef_table>, Failure> {
    #[cfg(unix)]
    let path = {
        use std::os::unix::ffi::OsStrExt;
        std::path::PathBuf::from(std::ffi::OsStr::from_bytes(path.to_bytes()))
    };
    #[cfg(not(unix))]
    let path = std::path::PathBuf::from(path.to_string_lossy().into_owned());
    Ok(Box::new(kef_table(Cow::Owned(Table::load(path)?))))
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
    ffi!(path => load(path))
}

/// Frees a table from kef_table_load. NULL and the default table are
/// ignored.
///
/// # Safety
/// `table` is NULL, the default table, or a table from kef_table_load not
/// yet freed and no longer in use by any thread.
#[no_mangle]
pub unsafe extern "C" fn kef_table_free(table: *mut kef_table) {
    // SAFETY: the caller's contract; the default table is kept.
    unsafe { free(table, kef_table_default()) }
}

/// The ranges `table` covers: ψ in [*psi_min, *psi_max], θ in
/// [*theta_min, *theta_max], F* in [*f_star_min, *f_star_max] (the default
/// table: [0.5, 8], [0, 0.01], [1e-5, 0.1]). A lookup inside all three
/// succeeds; one outside any is KEF_ERR_DOMAIN. KEF_ERR_ARGUMENT for a NULL
/// pointer or for outputs that alias each other (the six must be distinct;
/// no output written then).
///
/// # Safety
/// `table` is NULL or a live table; the outputs NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_table_domain(
    table: *const kef_table,
    psi_min: *mut f64,
    psi_max: *mut f64,
    theta_min: *mut f64,
    theta_max: *mut f64,
    f_star_min: *mut f64,
    f_star_max: *mut f64,
) -> c_int {
    ffi!(table, psi_min, psi_max, theta_min, theta_max, f_star_min, f_star_max => {
        let domain = table.domain();
        set2(psi_min, psi_max, domain.psi)?;
        set2(theta_min, theta_max, domain.theta)?;
        set2(f_star_min, f_star_max, domain.f_star)
    })
}
