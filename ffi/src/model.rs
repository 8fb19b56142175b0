//! μ of the model by direct integration, one point at a time.

use crate::constants::kef_constants;
use crate::error::Failure;
use crate::macros::set;
use ke_friction::{Constants, Model};
use std::ffi::c_int;

/// The constants of the functions that take β, ν and ε* themselves.
pub(crate) fn explicit(beta: f64, nu: f64, eps_star: f64) -> Constants {
    Constants::default().beta(beta).nu(nu).eps_star(eps_star)
}

/// μ by direct integration at F* = `f_star`.
/// Sets the thread's warnings (`kef_warnings`) of the contact returned.
fn model_mu(constants: &Constants, psi: f64, theta: f64, f_star: f64) -> Result<f64, Failure> {
    let contact = Model::new(constants.at(psi, theta)?)?.at_f_star(f_star)?;
    let mu = contact.mu_or_err()?;
    crate::warning::note(&contact);
    Ok(mu)
}

/// μ of the Kogut–Etsion model by direct integration (microseconds) at
/// F* with β, ν, ε* given (the default fit and model):
/// kef_model_mu_with with these constants. Both set the thread's
/// warnings (kef_warnings) of the result: F* outside 1e-5..0.1, h* < 0,
/// mu > 1.
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
    ffi!(mu => set(mu, model_mu(&explicit(beta, nu, eps_star), psi, theta, f_star)?))
}

/// μ of the model with `constants` (NULL: the defaults) by direct
/// integration (microseconds) at (ψ, θ, F*). KEF_ERR_DOMAIN for a
/// parameter out of range, F* > 1 (a pressure above the hardness) or an F*
/// the model cannot reach, KEF_ERR_ARGUMENT
/// for a NaN or ±inf or a NULL `mu`, KEF_ERR_NO_MU where the model has no
/// μ (F* <= 0 at that separation), KEF_ERR_INTERNAL if the root search
/// does not converge.
///
/// # Safety
/// `constants` is NULL or a live kef_constants; `mu` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_model_mu_with(
    constants: *const kef_constants,
    psi: f64,
    theta: f64,
    f_star: f64,
    mu: *mut f64,
) -> c_int {
    ffi!(constants, mu => set(mu, model_mu(constants, psi, theta, f_star)?))
}
