//! The model constants handle: its lifetime, the setters and getters of
//! β, ν, ε*, the fit and the model.

use crate::error::Failure;
use crate::macros::{free, Arg};
use ke_friction::{Constants, Fit, ModelKind, Named};
use std::ffi::{c_char, c_int, CStr, CString};
use std::sync::{Mutex, OnceLock, PoisonError};

/// The model constants (opaque): β, ν, ε*, the friction fit, the model
/// and the asperity heights' distribution, always valid (each setter checks its value). New constants get new
/// setters, so the handle grows without breaking the ABI. A function
/// taking `const kef_constants *` reads NULL as the defaults. Not
/// synchronised: set it on one thread, then share it read-only.
pub struct kef_constants(Constants);

pointee!(*mut kef_constants => &'a mut Constants, |p| p.as_mut().map(|c| &mut c.0));

/// The defaults, for a NULL `const kef_constants *`.
static DEFAULT_CONSTANTS: OnceLock<Constants> = OnceLock::new();

impl<'a> Arg<'a> for *const kef_constants {
    type Rust = &'a Constants;
    /// NULL is the defaults ([`Constants::default`]).
    unsafe fn check(self, _: &str) -> Result<&'a Constants, Failure> {
        // SAFETY: NULL or a live handle for 'a, by the caller's contract.
        let given = unsafe { self.as_ref() }.map(|c| &c.0);
        Ok(given.unwrap_or_else(|| DEFAULT_CONSTANTS.get_or_init(Constants::default)))
    }
}

/// `constants` changed by `change`, if the result is valid.
pub(crate) fn update(
    constants: &mut Constants,
    change: impl FnOnce(Constants) -> Result<Constants, Failure>,
) -> Result<(), Failure> {
    let next = change(constants.clone())?;
    next.validate()?;
    *constants = next;
    Ok(())
}

/// The value named `name` of a core name list (the core's message, listing
/// the names, for an unknown one).
pub(crate) fn named<T: Named>(name: &CStr) -> Result<T, Failure> {
    T::parse(&name.to_string_lossy()).map_err(|e| Failure::argument(e.to_string()))
}

/// The fit named `name`.
fn fit_named(name: &CStr) -> Result<Fit, Failure> {
    named(name)
}

/// The model named `name`.
fn kind_named(name: &CStr) -> Result<ModelKind, Failure> {
    named(name)
}

/// `name` as a C string for the life of the program (one allocation per
/// distinct name).
fn static_c(name: &'static str) -> Result<&'static CStr, Failure> {
    static NAMES: Mutex<Vec<&'static CStr>> = Mutex::new(Vec::new());
    let mut names = NAMES.lock().unwrap_or_else(PoisonError::into_inner);
    if let Some(&c) = names.iter().find(|c| c.to_bytes() == name.as_bytes()) {
        return Ok(c);
    }
    let c: &'static CStr = Box::leak(
        CString::new(name)
            .map_err(|e| Failure::argument(e.to_string()))?
            .into_boxed_c_str(),
    );
    names.push(c);
    Ok(c)
}

/// New model constants with the defaults (β = 0.04, ν = 0.3, ε* = 0.004,
/// fit "consistent", model "ke", Gaussian heights), to free with kef_constants_free. NULL
/// only if a panic was caught.
#[no_mangle]
pub extern "C" fn kef_constants_new() -> *mut kef_constants {
    ffi!(=> Ok(Box::new(kef_constants(Constants::default()))))
}

/// Frees model constants. NULL is ignored.
///
/// # Safety
/// `constants` is NULL or from kef_constants_new, not yet freed and no
/// longer in use.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_free(constants: *mut kef_constants) {
    // SAFETY: the caller's contract.
    unsafe { free(constants, std::ptr::null()) }
}

/// Sets β, the roughness parameter ηRσ, checked at once: KEF_ERR_DOMAIN
/// outside its range (the library's `bounds::BETA`, named in the message
/// of kef_last_error), KEF_ERR_ARGUMENT for NaN, ±inf or a NULL
/// handle; the handle is unchanged on failure.
///
/// # Safety
/// `constants` is NULL or a live kef_constants that no other thread uses.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_beta(constants: *mut kef_constants, beta: f64) -> c_int {
    ffi!(constants => update(constants, |c| Ok(c.beta(beta))))
}

/// Sets ν, Poisson's ratio of the softer material, in [0, 0.5); checked
/// as kef_constants_set_beta.
///
/// # Safety
/// As kef_constants_set_beta.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_nu(constants: *mut kef_constants, nu: f64) -> c_int {
    ffi!(constants => update(constants, |c| Ok(c.nu(nu))))
}

/// Sets ε* = ε/σ, the intermolecular distance, in [1e-9, 100]; checked as
/// kef_constants_set_beta.
///
/// # Safety
/// As kef_constants_set_beta.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_eps_star(constants: *mut kef_constants, eps_star: f64) -> c_int {
    ffi!(constants => update(constants, |c| Ok(c.eps_star(eps_star))))
}

/// Sets the friction fit by name: "consistent" (the default) or
/// "as-printed" (the paper's printed Eq. 18). KEF_ERR_ARGUMENT for another
/// name or a NULL pointer.
///
/// # Safety
/// As kef_constants_set_beta; `name` NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_fit(constants: *mut kef_constants, name: *const c_char) -> c_int {
    ffi!(constants, name => update(constants, |c| Ok(c.fit(fit_named(name)?))))
}

/// Sets the model by name: "ke" (Kogut–Etsion, the default) or "ceb" (the
/// CEB-type comparison model). KEF_ERR_ARGUMENT for another name or a
/// NULL pointer.
///
/// # Safety
/// As kef_constants_set_fit.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_model(constants: *mut kef_constants, name: *const c_char) -> c_int {
    ffi!(constants, name => update(constants, |c| Ok(c.kind(kind_named(name)?))))
}

/// β of `constants` (NULL: the default).
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_beta(constants: *const kef_constants) -> f64 {
    ffi!(constants => Ok(constants.beta))
}

/// ν of `constants` (NULL: the default).
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_nu(constants: *const kef_constants) -> f64 {
    ffi!(constants => Ok(constants.nu))
}

/// ε* of `constants` (NULL: the default).
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_eps_star(constants: *const kef_constants) -> f64 {
    ffi!(constants => Ok(constants.eps_star))
}

/// The fit's name of `constants` (NULL: the default): a static string,
/// not to free.
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_fit(constants: *const kef_constants) -> *const c_char {
    ffi!(constants => static_c(constants.fit.name()))
}

/// The model's name of `constants` (NULL: the default): a static string,
/// not to free.
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_model(constants: *const kef_constants) -> *const c_char {
    ffi!(constants => static_c(constants.kind.name()))
}
