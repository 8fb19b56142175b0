//! The friction law handle: μ and dμ/dp of a contact pressure in pascals,
//! for a simulator's contact nodes (kef_law_*).

use crate::constants::kef_constants;
use crate::error::Failure;
use crate::macros::Answer;
use crate::macros::{free, set, set2};
use ke_friction::topography::{read_file, ReadOptions, StatsOptions, Surface};
use ke_friction::{Constants, FrictionLaw, OnError, OutOfRange, Physical, PressureError};
use ke_friction::{Family, Materials, Named};
use std::ffi::{c_char, c_int, CStr};
use std::sync::atomic::{AtomicPtr, Ordering};
use std::sync::{Mutex, PoisonError};

/// Out-of-range policy of a kef_law: a positive pressure outside
/// [p_min, p_max] gets mu at the nearest end and dmu/dp = 0, and is
/// counted (kef_law_clamped). No error path, no message.
pub const KEF_LAW_CLAMP: c_int = 0;
/// Out-of-range policy of a kef_law: a positive pressure outside
/// [p_min, p_max] is KEF_ERR_DOMAIN.
pub const KEF_LAW_ERROR: c_int = 1;

/// A friction law mu(p), dmu/dp of one surface pair in SI units (opaque).
/// Immutable but for its clamped count (atomic); may be shared across
/// threads.
pub struct kef_law(FrictionLaw);

pointee!(*const kef_law => &'a FrictionLaw, |p| p.as_ref().map(|l| &l.0));

/// The policy of a `KEF_LAW_*` code.
fn policy(code: c_int) -> Result<OutOfRange, Failure> {
    match code {
        KEF_LAW_CLAMP => Ok(OutOfRange::Clamp),
        KEF_LAW_ERROR => Ok(OutOfRange::Error),
        other => Err(Failure::argument(format!(
            "policy = {other} is unknown: must be KEF_LAW_CLAMP ({KEF_LAW_CLAMP}) or KEF_LAW_ERROR ({KEF_LAW_ERROR})"
        ))),
    }
}

/// The range of two C arguments: both 0 is the default.
fn range(p_min: f64, p_max: f64) -> Option<(f64, f64)> {
    (p_min != 0.0 || p_max != 0.0).then_some((p_min, p_max))
}

/// [`FrictionLaw::mu_and_derivative_batch`] as a C batch.
fn pairs(
    law: &FrictionLaw,
    p: &[f64],
    mu: &mut [f64],
    dmu_dp: &mut [f64],
    on_error: OnError,
) -> Result<usize, PressureError> {
    law.mu_and_derivative_batch(p, mu, dmu_dp, on_error)
}

/// A friction law of the model with `constants` (NULL: the defaults) at
/// (ψ, θ) on a softer material of hardness `hardness` (Pa), over the
/// contact pressures [p_min, p_max] (Pa; both 0: 1e-5·H to 0.1·H), with
/// `policy` (KEF_LAW_CLAMP or KEF_LAW_ERROR) outside it: mu within 1e-6
/// relative of the model, about 20 ms to build. To free with
/// kef_law_free. NULL on failure: KEF_ERR_DOMAIN for an input out of
/// range, KEF_ERR_ARGUMENT for a NaN, an invalid range or an unknown
/// policy, KEF_ERR_NO_MU where the model has no positive mu in the range.
///
/// # Safety
/// `constants` is NULL or a live kef_constants.
#[no_mangle]
pub unsafe extern "C" fn kef_law_new(
    constants: *const kef_constants,
    psi: f64,
    theta: f64,
    hardness: f64,
    p_min: f64,
    p_max: f64,
    policy: c_int,
) -> *mut kef_law {
    ffi!(constants => {
        let params = constants.at(psi, theta)?;
        Ok(Box::new(kef_law(FrictionLaw::new(params, hardness, range(p_min, p_max), self::policy(policy)?)?)))
    })
}

/// A friction law from physical (SI) quantities, as kef_params_from_physical
/// takes them (material 1 the softer: `e1`, `nu1`, `hardness`; material 2:
/// `e2`, `nu2`; the roughness `sigma`, `radius`, `density`; the adhesion
/// `delta_gamma`, `epsilon`), with the default fit, model and Gaussian
/// heights; range and policy as kef_law_new. NULL on failure (the message
/// names the input and its range).
#[no_mangle]
pub extern "C" fn kef_law_from_physical(
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
    p_min: f64,
    p_max: f64,
    policy: c_int,
) -> *mut kef_law {
    ffi!(=> {
        let physical = Physical { e1, nu1, e2, nu2, hardness, sigma, radius, density, delta_gamma, epsilon };
        Ok(Box::new(kef_law(FrictionLaw::from_physical(&physical, range(p_min, p_max), self::policy(policy)?)?)))
    })
}

/// The law of a measured surface, as `kefric surface` computes it: the
/// file read by the same readers (X3P, .npy, text; lengths in metres; a
/// file that gives no sampling interval is refused, naming what is
/// missing), the statistics with its defaults (plane detrending, finite
/// differences, no filters), the heights' distribution `family`
/// ("gaussian", "pearson", "weibull", "empirical"; NULL or "": the
/// default of `kefric surface`, Pearson of the measured skewness and
/// kurtosis), and the materials (SI: material 1 the softer, `e1`, `nu1`,
/// `hardness`; material 2 `e2`, `nu2`; the adhesion `delta_gamma`,
/// `epsilon`) for ψ, θ, β, ε*. Range and policy as kef_law_new. NULL on
/// failure: KEF_ERR_IO for a file that cannot be read, KEF_ERR_ARGUMENT
/// for a malformed one or an unknown family, KEF_ERR_DOMAIN for a surface
/// or material out of the model's range (the message names it).
///
/// # Safety
/// `path` is NULL or a NUL-terminated string; `family` NULL or one.
#[no_mangle]
pub unsafe extern "C" fn kef_law_from_surface(
    path: *const c_char,
    family: *const c_char,
    e1: f64,
    nu1: f64,
    e2: f64,
    nu2: f64,
    hardness: f64,
    delta_gamma: f64,
    epsilon: f64,
    p_min: f64,
    p_max: f64,
    policy: c_int,
) -> *mut kef_law {
    // SAFETY: NULL or a NUL-terminated string, by the contract.
    let family = unsafe { (!family.is_null()).then(|| CStr::from_ptr(family)) };
    ffi!(path => {
        let path = std::path::Path::new(path.to_str().map_err(|_| Failure::argument("path is not UTF-8".into()))?);
        let family = family
            .map(|f| f.to_str().map_err(|_| Failure::argument("family is not UTF-8".into())))
            .transpose()?
            .filter(|f| !f.is_empty())
            .map(Family::parse)
            .transpose()
            .map_err(|e| Failure::argument(e.to_string()))?;
        let materials = Materials { e1, nu1, e2, nu2, hardness, delta_gamma, epsilon };
        let topography = read_file(path, &ReadOptions::default())?;
        let surface = Surface::new(topography, StatsOptions::default())?;
        let law = FrictionLaw::from_surface(&surface, &materials, family, range(p_min, p_max), self::policy(policy)?)?;
        Ok(Box::new(kef_law(law)))
    })
}

/// mu at the contact pressure `p` (Pa) into `*mu`. KEF_ERR_NO_MU for
/// p <= 0 (an open contact: no friction coefficient; -inf too),
/// KEF_ERR_ARGUMENT for NaN, KEF_ERR_DOMAIN outside the range under
/// KEF_LAW_ERROR (+inf: KEF_ERR_ARGUMENT there; under KEF_LAW_CLAMP it is
/// clamped to mu(p_max) like any pressure above the range).
/// A failure costs about what a lookup does (its message is formatted by
/// kef_last_error).
///
/// # Safety
/// `law` is NULL or a live law; `mu` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_law_mu(law: *const kef_law, p: f64, mu: *mut f64) -> c_int {
    ffi!(law, mu => set(mu, law.mu(p)?))
}

/// mu and dmu/dp (1/Pa) at the contact pressure `p` (Pa), for an implicit
/// solver's Jacobian; errors as kef_law_mu; the outputs must be distinct.
///
/// # Safety
/// `law` is NULL or a live law; `mu`, `dmu_dp` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_law_mu_and_derivative(
    law: *const kef_law,
    p: f64,
    mu: *mut f64,
    dmu_dp: *mut f64,
) -> c_int {
    ffi!(law, mu, dmu_dp => set2(mu, dmu_dp, law.mu_and_derivative(p)?))
}

/// mu at `n` pressures `p[i]` into `mu[i]`; at the first pressure without
/// mu, its code (the message names its index), `mu[0..i)` written and
/// `mu[i..n)` untouched. No output may overlap another argument.
///
/// # Safety
/// `law` is NULL or a live law; `p` NULL or valid for `n` reads; `mu` NULL
/// or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_law_mu_batch(law: *const kef_law, n: usize, p: *const f64, mu: *mut f64) -> c_int {
    ffi!(law, p[n], mu[n] => Ok(law.mu_batch(p, mu, OnError::Stop).map(|_| ())?))
}

/// kef_law_mu_batch that does not stop: NaN at each pressure without mu
/// (p <= 0, NaN, and outside the range under KEF_LAW_ERROR), the count in
/// `*n_nan` (required), KEF_OK.
///
/// # Safety
/// As kef_law_mu_batch; `n_nan` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_law_mu_batch_nan(
    law: *const kef_law,
    n: usize,
    p: *const f64,
    mu: *mut f64,
    n_nan: *mut usize,
) -> c_int {
    ffi!(law, p[n], mu[n], n_nan => set(n_nan, law.mu_batch(p, mu, OnError::Nan)?))
}

/// mu and dmu/dp at `n` pressures into `mu[i]` and `dmu_dp[i]`; the
/// contract of kef_law_mu_batch.
///
/// # Safety
/// As kef_law_mu_batch; `dmu_dp` NULL or valid for `n` writes.
#[no_mangle]
pub unsafe extern "C" fn kef_law_mu_and_derivative_batch(
    law: *const kef_law,
    n: usize,
    p: *const f64,
    mu: *mut f64,
    dmu_dp: *mut f64,
) -> c_int {
    ffi!(law, p[n], mu[n], dmu_dp[n] => Ok(pairs(law, p, mu, dmu_dp, OnError::Stop).map(|_| ())?))
}

/// kef_law_mu_and_derivative_batch that does not stop: NaN in both
/// outputs at each pressure without mu, the count in `*n_nan`, KEF_OK.
///
/// # Safety
/// As kef_law_mu_and_derivative_batch; `n_nan` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_law_mu_and_derivative_batch_nan(
    law: *const kef_law,
    n: usize,
    p: *const f64,
    mu: *mut f64,
    dmu_dp: *mut f64,
    n_nan: *mut usize,
) -> c_int {
    ffi!(law, p[n], mu[n], dmu_dp[n], n_nan => set(n_nan, pairs(law, p, mu, dmu_dp, OnError::Nan)?))
}

/// How many calls (batch elements one each) `law` answered by clamping
/// since it was built or last reset, into `*count`; with `reset` nonzero
/// the count is set to 0 at the same time (e.g. at each solver step).
///
/// # Safety
/// `law` is NULL or a live law; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_law_clamped(law: *const kef_law, reset: c_int, count: *mut u64) -> c_int {
    ffi!(law, count => set(count, if reset != 0 { law.reset_clamped() } else { law.clamped() }))
}

/// The pressure range [*p_min, *p_max] (Pa) and the hardness `*hardness`
/// (Pa) of `law`; the outputs must be distinct.
///
/// # Safety
/// `law` is NULL or a live law; the outputs NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn kef_law_range(
    law: *const kef_law,
    p_min: *mut f64,
    p_max: *mut f64,
    hardness: *mut f64,
) -> c_int {
    ffi!(law, p_min, p_max, hardness => {
        (*p_min, *p_max) = law.range();
        set(hardness, law.hardness())
    })
}

/// The largest relative error of mu against direct integration, measured
/// when `law` was built (at most 1e-6); NaN for a NULL law.
///
/// # Safety
/// `law` is NULL or a live law.
#[no_mangle]
pub unsafe extern "C" fn kef_law_max_error(law: *const kef_law) -> f64 {
    ffi!(law => Ok(law.max_error()))
}

/// One law of [`kef_law_from_props`]: its property list's bits, the law,
/// the entry added before it.
struct Shared {
    key: Vec<u64>,
    law: &'static kef_law,
    next: *const Shared,
}

/// The laws of [`kef_law_from_props`], newest first: an append-only list
/// of entries that live for the life of the process (as their laws do).
/// Readers walk it from here without a lock (the hot path: one lookup
/// per block of nodes, from every solver thread); only adding a new list
/// takes [`ADDING`]. Our own 20 lines rather than arc-swap or
/// crossbeam-epoch: what those crates solve is reclaiming replaced data,
/// and nothing here is ever replaced or freed.
static SHARED: AtomicPtr<Shared> = AtomicPtr::new(std::ptr::null_mut());

/// Held while an entry is added (so two threads building the same list
/// keep one law).
static ADDING: Mutex<()> = Mutex::new(());

/// The shared entries, newest first (lock-free).
fn shared_laws() -> impl Iterator<Item = &'static Shared> {
    // SAFETY: every pointer in the list is a leaked `Shared`, published
    // with Release after it was fully written (`add`), read with Acquire.
    // SAFETY: as above.
    let head = unsafe { SHARED.load(Ordering::Acquire).as_ref() };
    // SAFETY: as above: `next` was written before its entry was published.
    std::iter::successors(head, |e| unsafe { e.next.as_ref() })
}

/// The shared law of exactly these property bits, if built.
fn find_shared(props: &[f64]) -> Option<&'static kef_law> {
    shared_laws()
        .find(|e| e.key.len() == props.len() && e.key.iter().zip(props).all(|(k, p)| *k == p.to_bits()))
        .map(|e| e.law)
}

impl Answer for &'static kef_law {
    type C = *const kef_law;
    fn ok(self) -> *const kef_law {
        self
    }
    fn failed(_: c_int) -> *const kef_law {
        std::ptr::null()
    }
}

/// The law of a property list (the layout of [`kef_law_from_props`]).
fn law_of_props(props: &[f64]) -> Result<FrictionLaw, Failure> {
    let &[psi, theta, hardness, ref rest @ ..] = props else {
        return Err(props_length(props.len()));
    };
    let (range, constants) = match *rest {
        [] => (None, Constants::default()),
        [p_min, p_max] => (range(p_min, p_max), Constants::default()),
        [p_min, p_max, beta, nu, eps_star] => (
            range(p_min, p_max),
            Constants::default().beta(beta).nu(nu).eps_star(eps_star),
        ),
        _ => return Err(props_length(props.len())),
    };
    Ok(FrictionLaw::new(
        constants.at(psi, theta)?,
        hardness,
        range,
        OutOfRange::Clamp,
    )?)
}

/// The failure for a property list of the wrong length.
fn props_length(n: usize) -> Failure {
    Failure::argument(format!(
        "n_props = {n}: must be 3 (psi, theta, hardness), 5 (and p_min, p_max) or 8 (and beta, nu, eps_star)"
    ))
}

/// The shared law of `props`: found without a lock, or built (outside
/// any lock, so that other property lists are not held up) and added.
fn shared(props: &[f64]) -> Result<&'static kef_law, Failure> {
    if let Some(law) = find_shared(props) {
        return Ok(law);
    }
    let built = law_of_props(props)?;
    let _adding = ADDING.lock().unwrap_or_else(PoisonError::into_inner);
    // Another thread may have added it meanwhile: keep the first.
    if let Some(law) = find_shared(props) {
        return Ok(law);
    }
    let law: &'static kef_law = Box::leak(Box::new(kef_law(built)));
    let entry = Box::leak(Box::new(Shared {
        key: props.iter().map(|p| p.to_bits()).collect(),
        law,
        // Only adders (holding ADDING) store: this is the current head.
        next: SHARED.load(Ordering::Acquire),
    }));
    SHARED.store(entry, Ordering::Release);
    Ok(law)
}

/// The law of a solver's property list, built on the first call with
/// these values and shared by every later call (from any thread) for the
/// life of the process: what a user subroutine called per block of nodes
/// with its material's properties needs (ffi/abaqus/fric_coef.f). Not to
/// free. `props[0..n_props)`: psi, theta, the hardness H (in the solver
/// model's stress unit, as the pressures it passes: MPa in an N-mm model;
/// μ depends on p/H only, dμ/dp comes out per that unit); then
/// optionally p_min, p_max (the same unit; both 0: 1e-5*H to 0.1*H); then
/// optionally beta, nu, eps_star (else the defaults 0.04, 0.3, 0.004);
/// n_props is 3, 5 or 8. The policy is KEF_LAW_CLAMP (a solver needs a
/// number at every closed node; kef_law_clamped counts). NULL on failure
/// (errors as kef_law_new; KEF_ERR_ARGUMENT for another n_props); a
/// failed list is not kept (the next call tries again). A list already
/// built is found without a lock (the lookup Abaqus makes per block).
///
/// # Safety
/// `props` is NULL or valid for `n_props` reads.
#[no_mangle]
pub unsafe extern "C" fn kef_law_from_props(n_props: usize, props: *const f64) -> *const kef_law {
    ffi!(props[n_props] => shared(props))
}

/// Frees a law. NULL and the shared laws of kef_law_from_props are
/// ignored.
///
/// # Safety
/// `law` is NULL, a law from kef_law_from_props, or one from kef_law_new
/// or kef_law_from_physical not yet freed and no longer in use by any
/// thread.
#[no_mangle]
pub unsafe extern "C" fn kef_law_free(law: *mut kef_law) {
    if shared_laws().any(|e| std::ptr::eq(e.law, law)) {
        return;
    }
    // SAFETY: the caller's contract (a shared law was returned above).
    unsafe { free(law, std::ptr::null()) }
}
