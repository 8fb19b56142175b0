//! A surface pair's dimensionless parameters from physical quantities.

use ke_friction::{Params, Physical};
use std::ffi::c_int;

/// The dimensionless parameters of a surface pair from physical (SI)
/// quantities (MODEL.md §1–2), into `*psi` (plasticity index), `*theta`
/// (= Δγ/(σH)), `*beta` (= ηRσ), `*nu` (= nu1) and `*eps_star` (= ε/σ):
/// the inputs of kef_table_mu (ψ, θ) and of kef_model_mu (all five).
/// Material 1 is the softer one: `e1`, `nu1` its Young's modulus (Pa) and
/// Poisson's ratio, `hardness` its hardness H (Pa); `e2`, `nu2` those of
/// material 2; `sigma` the standard deviation of the surface heights (m),
/// `radius` the asperity radius R (m), `density` the areal density of
/// asperities η (1/m²), `delta_gamma` the energy of adhesion Δγ (J/m²),
/// `epsilon` the intermolecular distance ε (m). KEF_ERR_DOMAIN for an input
/// or a result out of its range (the message names it and the range),
/// KEF_ERR_ARGUMENT for NaN, ±inf, a NULL output or outputs that alias
/// each other (the five must be distinct; the message names two); no
/// output is written on failure. Inputs outside the model's validity
/// domain (psi outside [0.5, 8], theta > 0.01, beta outside [0.02, 0.16])
/// are returned and set KEF_WARN_PSI_DOMAIN, KEF_WARN_THETA_DOMAIN,
/// KEF_WARN_BETA_DOMAIN (kef_warnings).
///
/// # Safety
/// The outputs are NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_params_from_physical(
    e1: f64,
    nu1: f64,
    e2: f64,
    nu2: f64,
    hardness: f64,
    sigma: f64,
    radius: f64,
    density: f64,
    delta_gamma: f64,
    epsilon: f64,
    psi: *mut f64,
    theta: *mut f64,
    beta: *mut f64,
    nu: *mut f64,
    eps_star: *mut f64,
) -> c_int {
    ffi!(psi, theta, beta, nu, eps_star => {
        let physical = Physical { e1, nu1, e2, nu2, hardness, sigma, radius, density, delta_gamma, epsilon };
        let p = Params::from_physical(&physical)?;
        crate::warning::note_params(&p);
        (*psi, *theta) = (p.psi, p.theta);
        (*beta, *nu, *eps_star) = (p.constants.beta, p.constants.nu, p.constants.eps_star);
        Ok(())
    })
}
