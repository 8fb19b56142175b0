//! The C ABI of ke-friction: table and curve lookups and the model by
//! direct integration, for C, C++ and Fortran (`include/kefriction.h`,
//! `fortran/ke_friction.f90`).
//!
//! Conventions of every function:
//! - a return code: [`KEF_OK`] (0) or one of the `KEF_ERR_*` codes (or a
//!   NULL handle); on failure [`kef_last_error`] holds the message (the
//!   Rust error's one line: argument, value, valid range) and the outputs
//!   are untouched, except that a batch writes the elements before the
//!   first bad one and nothing from it on (its `_nan` form writes NaN
//!   there instead and goes on);
//! - the code is the core's classification of the error
//!   ([`ke_friction::ErrorKind`]), mapped in one place (`code`);
//! - a NULL pointer where one is required is [`KEF_ERR_ARGUMENT`], never a
//!   crash; no panic crosses the boundary ([`KEF_ERR_INTERNAL`] if one
//!   ever happened);
//! - outputs must not alias each other or the inputs: a call whose output
//!   overlaps another pointer argument is [`KEF_ERR_ARGUMENT`] (the
//!   message names both), nothing written;
//! - tables and curves are immutable: any number of threads may use one
//!   at once; only freeing it must wait until they are done.
//!
//! Every export is one line: the `ffi!` macro checks its pointer
//! arguments (that no output overlaps another argument, then each for
//! NULL), runs the body under `catch_unwind` and turns a failure into its
//! code and message.
#![warn(missing_docs)]
#![deny(unsafe_op_in_unsafe_fn)]
#![warn(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]
// The C names are the contract.
#![allow(non_camel_case_types)]

use ke_friction::{
    Classify, Constants, Curve, ErrorKind, EvalError, Fit, HeightDistribution, LookupError, Model, ModelKind, OnError,
    Params, Physical, Table,
};
use std::borrow::Cow;
use std::cell::Cell;
use std::ffi::{c_char, c_int, CStr, CString};
use std::ops::Range;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Mutex, OnceLock, PoisonError};

/// Success.
pub const KEF_OK: c_int = 0;
/// A finite argument outside its range: a lookup outside the table's or
/// curve's range, a model parameter or constant out of range, a load the
/// model cannot reach; or a table or curve that missed its accuracy.
pub const KEF_ERR_DOMAIN: c_int = 1;
/// A NULL pointer, an argument that is not a usable number (NaN, ±inf),
/// an unknown name, or an invalid F* range for a curve.
pub const KEF_ERR_ARGUMENT: c_int = 2;
/// A table file that cannot be read.
pub const KEF_ERR_IO: c_int = 3;
/// A damaged or incompatible table file.
pub const KEF_ERR_TABLE: c_int = 4;
/// A bug in ke-friction (a caught panic, or a root search that did not
/// converge); please report the message.
pub const KEF_ERR_INTERNAL: c_int = 5;
/// No μ where the model has none: F* <= 0 at that separation (adhesion
/// outweighs the contact load), or no positive μ.
pub const KEF_ERR_NO_MU: c_int = 6;

/// Height distribution family (kef_constants_set_distribution,
/// kef_constants_distribution): the paper's Gaussian, the default
/// (skewness 0, kurtosis 3).
pub const KEF_DIST_GAUSSIAN: c_int = 0;
/// Height distribution family: the Pearson system from skewness Sk and
/// kurtosis K (not excess: 3 for a Gaussian), admissible where
/// K > Sk² + 1, |Sk| <= 5 and K <= 100. Pearson(0, 3) is the Gaussian.
pub const KEF_DIST_PEARSON: c_int = 1;
/// Height distribution family: a standardised Weibull distribution of
/// skewness Sk in (-1.1395, 2]; its kurtosis follows from Sk.
pub const KEF_DIST_WEIBULL: c_int = 2;
/// Height distribution family: an empirical (kernel) density of measured
/// heights, set by kef_constants_set_heights (not by
/// kef_constants_set_distribution).
pub const KEF_DIST_EMPIRICAL: c_int = 3;

/// A table of μ(ψ, θ, F*) (opaque). Immutable; may be shared across threads.
pub struct kef_table(Cow<'static, Table>);

/// The handle of the embedded table.
static DEFAULT: OnceLock<kef_table> = OnceLock::new();

/// μ(F*) of one surface pair, fixed ψ and θ (opaque). Immutable; may be
/// shared across threads.
pub struct kef_curve(Curve);

/// The model constants (opaque): β, ν, ε*, the friction fit, the model
/// and the asperity heights' distribution, always valid (each setter checks its value). New constants get new
/// setters, so the handle grows without breaking the ABI. A function
/// taking `const kef_constants *` reads NULL as the defaults. Not
/// synchronised: set it on one thread, then share it read-only.
pub struct kef_constants(Constants);

/// The C code of a kind of failure: the one place the core's
/// classification (the table of `ke_friction::ErrorKind`) becomes a code.
fn code(kind: ErrorKind) -> c_int {
    match kind {
        ErrorKind::Argument => KEF_ERR_ARGUMENT,
        ErrorKind::Domain => KEF_ERR_DOMAIN,
        ErrorKind::NoMu => KEF_ERR_NO_MU,
        ErrorKind::Io => KEF_ERR_IO,
        ErrorKind::Table => KEF_ERR_TABLE,
        ErrorKind::Tolerance => KEF_ERR_DOMAIN,
        ErrorKind::Internal => KEF_ERR_INTERNAL,
        _ => KEF_ERR_INTERNAL,
    }
}

/// A failure: its code and message.
struct Failure {
    code: c_int,
    message: String,
}

impl Failure {
    /// A failure of the C side itself (a NULL pointer, an unknown name).
    fn argument(message: String) -> Failure {
        Failure {
            code: KEF_ERR_ARGUMENT,
            message,
        }
    }
}

impl<E: Classify> From<E> for Failure {
    fn from(e: E) -> Failure {
        Failure {
            code: code(e.kind()),
            message: e.to_string(),
        }
    }
}

/// The size of the per-thread message buffer, its NUL included.
const MESSAGE_CAPACITY: usize = 1024;

thread_local! {
    /// This thread's last message, NUL-terminated: one buffer for the
    /// thread's life, overwritten in place, never freed or moved.
    static LAST_ERROR: [Cell<u8>; MESSAGE_CAPACITY] = const { [const { Cell::new(0) }; MESSAGE_CAPACITY] };
}

/// Stores `message` as this thread's last (cut at a character boundary to
/// fit; a NUL in it becomes a space).
fn remember(message: &str) {
    let mut end = message.len().min(MESSAGE_CAPACITY - 1);
    while !message.is_char_boundary(end) {
        end -= 1;
    }
    LAST_ERROR.with(|buffer| {
        for (cell, &b) in buffer.iter().zip(&message.as_bytes()[..end]) {
            cell.set(if b == 0 { b' ' } else { b });
        }
        buffer[end].set(0);
    });
}

/// What an export returns: a code, a handle, a value.
trait Answer {
    /// The C type.
    type C;
    /// The answer of a call that succeeded.
    fn ok(self) -> Self::C;
    /// The answer of a call that failed with `code`.
    fn failed(code: c_int) -> Self::C;
}

impl Answer for () {
    type C = c_int;
    fn ok(self) -> c_int {
        KEF_OK
    }
    fn failed(code: c_int) -> c_int {
        code
    }
}

impl<T> Answer for Box<T> {
    type C = *mut T;
    fn ok(self) -> *mut T {
        Box::into_raw(self)
    }
    fn failed(_: c_int) -> *mut T {
        std::ptr::null_mut()
    }
}

impl Answer for f64 {
    type C = f64;
    fn ok(self) -> f64 {
        self
    }
    fn failed(_: c_int) -> f64 {
        f64::NAN
    }
}

impl Answer for &'static CStr {
    type C = *const c_char;
    fn ok(self) -> *const c_char {
        self.as_ptr()
    }
    fn failed(_: c_int) -> *const c_char {
        std::ptr::null()
    }
}

/// Runs `body`, turning a failure or a panic into its code (or NULL) and
/// message.
fn guard<A: Answer>(body: impl FnOnce() -> Result<A, Failure>) -> A::C {
    let failure = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(answer)) => return answer.ok(),
        Ok(Err(failure)) => failure,
        Err(_) => Failure {
            code: KEF_ERR_INTERNAL,
            message: "internal error: a panic in ke-friction (please report it)".into(),
        },
    };
    remember(&failure.message);
    A::failed(failure.code)
}

/// A pointer argument, checked and turned into what Rust uses.
trait Arg<'a> {
    /// What it points to.
    type Rust;
    /// The Rust view of the pointer named `name`, or a failure naming it.
    ///
    /// # Safety
    /// The pointer is NULL or valid as the export's contract says, for `'a`.
    unsafe fn check(self, name: &str) -> Result<Self::Rust, Failure>;
}

/// A pointer to `n` elements, checked and turned into a slice.
trait Array<'a> {
    /// The slice.
    type Rust;
    /// The slice of `n` elements at the pointer named `name` (NULL allowed
    /// only when `n` is 0).
    ///
    /// # Safety
    /// The pointer is NULL or valid for `n` elements (writes for an output)
    /// for `'a`, and an output overlaps no other argument (as [`distinct`]
    /// checked).
    unsafe fn check_n(self, name: &str, n: usize) -> Result<Self::Rust, Failure>;
}

/// The failure for a NULL pointer.
fn null(name: &str) -> Failure {
    Failure::argument(format!("{name} is NULL"))
}

macro_rules! pointee {
    ($ptr:ty => $rust:ty, |$p:ident| $view:expr) => {
        impl<'a> Arg<'a> for $ptr {
            type Rust = $rust;
            unsafe fn check(self, name: &str) -> Result<$rust, Failure> {
                let $p = self;
                // SAFETY: NULL or valid for 'a, by the caller's contract.
                unsafe { $view }.ok_or_else(|| null(name))
            }
        }
    };
}
pointee!(*const kef_table => &'a Table, |p| p.as_ref().map(|t| &*t.0));
pointee!(*const kef_curve => &'a Curve, |p| p.as_ref().map(|c| &c.0));
pointee!(*mut kef_constants => &'a mut Constants, |p| p.as_mut().map(|c| &mut c.0));
pointee!(*mut f64 => &'a mut f64, |p| p.as_mut());
pointee!(*mut usize => &'a mut usize, |p| p.as_mut());
pointee!(*mut c_int => &'a mut c_int, |p| p.as_mut());
pointee!(*const c_char => &'a CStr, |p| (!p.is_null()).then(|| CStr::from_ptr(p)));

/// The bytes a pointer argument points to, for the aliasing check.
trait Region {
    /// The address and byte length of `count` elements at the pointer
    /// (none for NULL), and whether the export writes them.
    fn region(&self, count: usize) -> (usize, usize, bool);
}

impl<T> Region for *const T {
    fn region(&self, count: usize) -> (usize, usize, bool) {
        let len = if self.is_null() {
            0
        } else {
            count.saturating_mul(size_of::<T>())
        };
        (self.addr(), len, false)
    }
}

impl<T> Region for *mut T {
    fn region(&self, count: usize) -> (usize, usize, bool) {
        let (start, len, _) = self.cast_const().region(count);
        (start, len, true)
    }
}

/// A pointer argument's bytes: its name, [`Region::region`].
type Place = (&'static str, (usize, usize, bool));

/// The failure if an output overlaps another pointer argument (two
/// references to one place, one of them `&mut`, would be undefined
/// behaviour): checked before any reference is made. Inputs may overlap
/// each other.
fn distinct(places: &[Place]) -> Result<(), Failure> {
    for (i, &(second, (b, b_len, b_written))) in places.iter().enumerate() {
        for &(first, (a, a_len, a_written)) in &places[..i] {
            let overlap = a_len > 0 && b_len > 0 && a < b.saturating_add(b_len) && b < a.saturating_add(a_len);
            if overlap && (a_written || b_written) {
                return Err(Failure::argument(format!(
                    "{first} and {second} overlap: outputs must not alias each other or the inputs"
                )));
            }
        }
    }
    Ok(())
}

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

impl<'a> Array<'a> for *const f64 {
    type Rust = &'a [f64];
    unsafe fn check_n(self, name: &str, n: usize) -> Result<&'a [f64], Failure> {
        match (self.is_null(), n) {
            (_, 0) => Ok(&[]),
            (true, _) => Err(null(name)),
            // SAFETY: valid for n reads by the caller's contract.
            (false, _) => Ok(unsafe { std::slice::from_raw_parts(self, n) }),
        }
    }
}

impl<'a> Array<'a> for *mut f64 {
    type Rust = &'a mut [f64];
    unsafe fn check_n(self, name: &str, n: usize) -> Result<&'a mut [f64], Failure> {
        match (self.is_null(), n) {
            (_, 0) => Ok(&mut []),
            (true, _) => Err(null(name)),
            // SAFETY: valid for n writes and unaliased by the caller's contract.
            (false, _) => Ok(unsafe { std::slice::from_raw_parts_mut(self, n) }),
        }
    }
}

/// The body of an export: `ffi!(p, q[n], … => body)` checks that no
/// output overlaps another pointer argument ([`distinct`]), then each
/// pointer argument in order (`q[n]`: an array of `n`), rebinding it to
/// its Rust view, then runs `body` (a `Result<A, Failure>`) under
/// [`guard`].
macro_rules! ffi {
    ($($arg:ident $([$n:expr])?),* => $body:expr) => {
        guard(|| {
            distinct(&[$((stringify!($arg), Region::region(&$arg, ffi!(@count $([$n])?)))),*])?;
            $(
                // SAFETY: the export's `# Safety` contract: every pointer
                // argument is NULL or valid as it says.
                let $arg = unsafe { ffi!(@check $arg $([$n])?) }?;
            )*
            $body
        })
    };
    (@count) => {
        1
    };
    (@count [$n:expr]) => {
        $n
    };
    (@check $arg:ident) => {
        Arg::check($arg, stringify!($arg))
    };
    (@check $arg:ident [$n:expr]) => {
        Array::check_n($arg, stringify!($arg), $n)
    };
}

/// Writes `value` to `out`.
fn set<T>(out: &mut T, value: T) -> Result<(), Failure> {
    *out = value;
    Ok(())
}

/// Writes a pair to two outputs.
fn set2(a: &mut f64, b: &mut f64, (x, y): (f64, f64)) -> Result<(), Failure> {
    (*a, *b) = (x, y);
    Ok(())
}

/// A batch in [`OnError::Stop`] mode: success, or the core's error.
fn stop(result: Result<usize, LookupError>) -> Result<(), Failure> {
    result.map(|_| ()).map_err(Failure::from)
}

/// The pairs in a stack buffer: at most this many at a time.
const CHUNK: usize = 256;

/// A batch of (μ, slope) pairs written to `mu` and `slope`: `batch(range,
/// out)` runs the core's batch for elements `range` into `out`, chunk by
/// chunk; the NaN count, or the first bad element's error (elements before
/// it written, none from it on).
fn scatter(
    mu: &mut [f64],
    slope: &mut [f64],
    mut batch: impl FnMut(Range<usize>, &mut [(f64, f64)]) -> Result<usize, LookupError>,
) -> Result<usize, LookupError> {
    let mut buffer = [(0.0, 0.0); CHUNK];
    let mut nan = 0;
    for start in (0..mu.len()).step_by(CHUNK) {
        let end = mu.len().min(start + CHUNK);
        let out = &mut buffer[..end - start];
        let result = batch(start..end, out);
        let done = match &result {
            Ok(_) => out.len(),
            Err(e) => e.index().unwrap_or(0),
        };
        for (k, &(m, s)) in out[..done].iter().enumerate() {
            (mu[start + k], slope[start + k]) = (m, s);
        }
        nan += result.map_err(|e| e.shifted(start))?;
    }
    Ok(nan)
}

/// [`Table::mu_with_slope_batch_with`] into two arrays.
fn table_slopes(
    table: &Table,
    [psi, theta, f_star]: [&[f64]; 3],
    mu: &mut [f64],
    slope: &mut [f64],
    on_error: OnError,
) -> Result<usize, LookupError> {
    table.prepare_batch(mu.len());
    scatter(mu, slope, |r, out| {
        table.mu_with_slope_batch_with(&psi[r.clone()], &theta[r.clone()], &f_star[r], out, on_error)
    })
}

/// [`Curve::mu_with_slope_batch_with`] into two arrays.
fn curve_slopes(
    curve: &Curve,
    f_star: &[f64],
    mu: &mut [f64],
    slope: &mut [f64],
    on_error: OnError,
) -> Result<usize, LookupError> {
    scatter(mu, slope, |r, out| {
        curve.mu_with_slope_batch_with(&f_star[r], out, on_error)
    })
}

/// [`Table::h_star`] at each point into `out`, stopping at the first
/// bad one (the elements before it written).
fn h_star_batch(table: &Table, [psi, theta, f_star]: [&[f64]; 3], out: &mut [f64]) -> Result<usize, LookupError> {
    for (i, h) in out.iter_mut().enumerate() {
        *h = table.h_star(psi[i], theta[i], f_star[i]).map_err(|e| e.at(i))?;
    }
    Ok(0)
}

/// Frees a handle from `Box::into_raw` unless it is NULL or `keep`.
///
/// # Safety
/// `p` is NULL, `keep`, or from `Box::into_raw`, not yet freed and no
/// longer in use.
unsafe fn free<T>(p: *mut T, keep: *const T) {
    if !p.is_null() && !std::ptr::eq(p.cast_const(), keep) {
        // SAFETY: from Box::into_raw, freed once, by the caller's contract.
        drop(unsafe { Box::from_raw(p) });
    }
}

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

/// The constants of the functions that take β, ν and ε* themselves.
fn explicit(beta: f64, nu: f64, eps_star: f64) -> Constants {
    Constants::default().beta(beta).nu(nu).eps_star(eps_star)
}

/// μ by direct integration at F* = `f_star`.
fn model_mu(constants: &Constants, psi: f64, theta: f64, f_star: f64) -> Result<f64, Failure> {
    let contact = Model::new(constants.at(psi, theta)?)?.at_f_star(f_star)?;
    let no_mu = EvalError::NoMu {
        f_star: contact.f_star,
        h_star: contact.h_star,
    };
    Ok(contact.mu.ok_or(no_mu)?)
}

/// A curve by direct integration over [`lo`, `hi`].
fn model_curve(constants: &Constants, psi: f64, theta: f64, lo: f64, hi: f64) -> Result<Box<kef_curve>, Failure> {
    let model = Model::new(constants.at(psi, theta)?)?;
    Ok(Box::new(kef_curve(Curve::from_model(&model, lo, hi)?)))
}

/// `constants` changed by `change`, if the result is valid.
fn update(
    constants: &mut Constants,
    change: impl FnOnce(Constants) -> Result<Constants, Failure>,
) -> Result<(), Failure> {
    let next = change(constants.clone())?;
    next.validate()?;
    *constants = next;
    Ok(())
}

/// The value named `name` among `all` (`what`: the setting, for the message).
fn named<T: Copy>(
    what: &str,
    name: &CStr,
    from_name: fn(&str) -> Option<T>,
    all: &[T],
    name_of: fn(T) -> &'static str,
) -> Result<T, Failure> {
    let text = name.to_string_lossy();
    from_name(&text).ok_or_else(|| {
        let known: Vec<String> = all.iter().map(|&v| format!("\"{}\"", name_of(v))).collect();
        Failure::argument(format!("{what} \"{text}\" is unknown: must be {}", known.join(" or ")))
    })
}

/// The fit named `name`.
fn fit_named(name: &CStr) -> Result<Fit, Failure> {
    named("fit", name, Fit::from_name, &Fit::ALL, Fit::name)
}

/// The model named `name`.
fn kind_named(name: &CStr) -> Result<ModelKind, Failure> {
    named("model", name, ModelKind::from_name, &ModelKind::ALL, ModelKind::name)
}

/// The distribution of family `family` (a `KEF_DIST_*` code other than
/// [`KEF_DIST_EMPIRICAL`]) with `skewness` and `kurtosis` (the latter read
/// by [`KEF_DIST_PEARSON`] alone, neither by [`KEF_DIST_GAUSSIAN`]),
/// validated.
fn distribution(family: c_int, skewness: f64, kurtosis: f64) -> Result<HeightDistribution, Failure> {
    match family {
        KEF_DIST_GAUSSIAN => Ok(HeightDistribution::Gaussian),
        KEF_DIST_PEARSON => Ok(HeightDistribution::pearson(skewness, kurtosis)?),
        KEF_DIST_WEIBULL => Ok(HeightDistribution::weibull(skewness)?),
        KEF_DIST_EMPIRICAL => Err(Failure::argument(
            "family 3 (KEF_DIST_EMPIRICAL) is set by kef_constants_set_heights".into(),
        )),
        other => Err(Failure::argument(format!(
            "family {other} is unknown: must be KEF_DIST_GAUSSIAN (0), KEF_DIST_PEARSON (1) or KEF_DIST_WEIBULL (2)"
        ))),
    }
}

/// The `KEF_DIST_*` code of a distribution.
fn family_code(d: &HeightDistribution) -> c_int {
    match d {
        HeightDistribution::Gaussian => KEF_DIST_GAUSSIAN,
        HeightDistribution::Pearson { .. } => KEF_DIST_PEARSON,
        HeightDistribution::Weibull { .. } => KEF_DIST_WEIBULL,
        HeightDistribution::Empirical(_) => KEF_DIST_EMPIRICAL,
        // A family added to the core after this binding.
        _ => -1,
    }
}

/// Writes the distribution's family, skewness and kurtosis.
fn describe(d: &HeightDistribution, family: &mut c_int, skewness: &mut f64, kurtosis: &mut f64) -> Result<(), Failure> {
    let code = family_code(d);
    if code < 0 {
        return Err(Failure {
            code: KEF_ERR_INTERNAL,
            message: format!("the distribution family \"{}\" has no KEF_DIST_* code", d.family()),
        });
    }
    (*family, *skewness, *kurtosis) = (code, d.skewness(), d.kurtosis());
    Ok(())
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

/// The message of this thread's last failure ("" if none). Never NULL; do
/// not free it. The pointer stays valid until the thread exits: it points
/// to one buffer per thread that each later failure on the thread
/// overwrites in place (never freed or moved), so reading it after a call
/// that failed, even one made after the pointer was taken, is safe and
/// gives that call's message. A message longer than 1023 bytes is cut.
#[no_mangle]
pub extern "C" fn kef_last_error() -> *const c_char {
    LAST_ERROR.with(|buffer| buffer.as_ptr().cast())
}

/// The library's version ("MAJOR.MINOR.PATCH", the crate's version), a
/// static string: never NULL, not to free.
#[no_mangle]
pub extern "C" fn kef_version() -> *const c_char {
    ffi!(=> Ok(VERSION))
}

/// The crate's version, NUL-terminated.
const VERSION: &CStr = match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
    Ok(v) => v,
    Err(_) => panic!("the crate version has no NUL"),
};

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
/// output is written on failure.
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
        (*psi, *theta) = (p.psi, p.theta);
        (*beta, *nu, *eps_star) = (p.constants.beta, p.constants.nu, p.constants.eps_star);
        Ok(())
    })
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
/// θ = Δγ/(σH)). KEF_ERR_DOMAIN if an argument is outside the table's
/// range, KEF_ERR_ARGUMENT if it is NaN or ±inf, or for a NULL pointer.
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

/// μ of the Kogut–Etsion model by direct integration (microseconds) at
/// F* with β, ν, ε* given (the default fit and model):
/// kef_model_mu_with with these constants.
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
/// parameter out of range or an F* the model cannot reach, KEF_ERR_ARGUMENT
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
/// outside (0.01928, 100], KEF_ERR_ARGUMENT for NaN, ±inf or a NULL
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

/// Sets the asperity heights' distribution (MODEL.md §9) to `family`:
/// KEF_DIST_GAUSSIAN (the default; `skewness` and `kurtosis` ignored),
/// KEF_DIST_PEARSON (skewness Sk and kurtosis K, not excess: 3 for a
/// Gaussian; admissible where K > Sk² + 1, |Sk| <= 5, K <= 100) or
/// KEF_DIST_WEIBULL (skewness Sk in (-1.1395, 2]; `kurtosis` ignored: it
/// follows from Sk). Checked at once: KEF_ERR_DOMAIN for a value outside
/// its admissible region (the message names it and the bound, e.g.
/// "kurtosis = 1.2 is out of range: must be > skewness² + 1 ..."),
/// KEF_ERR_ARGUMENT for NaN or ±inf where it is read, an unknown family,
/// KEF_DIST_EMPIRICAL (see kef_constants_set_heights) or a NULL handle;
/// the handle is unchanged on failure.
///
/// # Safety
/// As kef_constants_set_beta.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_distribution(
    constants: *mut kef_constants,
    family: c_int,
    skewness: f64,
    kurtosis: f64,
) -> c_int {
    ffi!(constants => update(constants, |c| Ok(c.distribution(distribution(family, skewness, kurtosis)?))))
}

/// Sets the asperity heights' distribution to the empirical (kernel)
/// density of `n` measured heights (any unit; NaN entries are skipped as
/// missing points): at least 100 finite values, not all equal, no ±inf.
/// The data are copied (the density is built at once; the array may be
/// freed after the call). KEF_ERR_DOMAIN for too few heights or constant
/// ones, KEF_ERR_ARGUMENT for an infinite height, a NULL handle, or
/// `heights` NULL with `n` > 0; the handle is unchanged on failure.
/// kef_constants_distribution then gives KEF_DIST_EMPIRICAL and the
/// heights' skewness and kurtosis.
///
/// # Safety
/// As kef_constants_set_beta; `heights` NULL or valid for `n` reads.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_heights(
    constants: *mut kef_constants,
    heights: *const f64,
    n: usize,
) -> c_int {
    ffi!(constants, heights[n] => update(constants, |c| Ok(c.distribution(HeightDistribution::empirical(heights)?))))
}

/// The asperity heights' distribution of `constants` (NULL: the default,
/// the Gaussian): its family into `*family` (a KEF_DIST_* code), its
/// skewness into `*skewness` and its kurtosis (not excess) into
/// `*kurtosis`: 0 and 3 for the Gaussian, the values set for Pearson, the
/// kurtosis its skewness implies for Weibull (2.717 at Sk = 0), the
/// heights' own for an empirical density. KEF_ERR_ARGUMENT for a NULL
/// output or outputs that alias each other (the three must be distinct;
/// no output written then).
///
/// # Safety
/// `constants` is NULL or a live kef_constants; the outputs NULL or
/// writable.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_distribution(
    constants: *const kef_constants,
    family: *mut c_int,
    skewness: *mut f64,
    kurtosis: *mut f64,
) -> c_int {
    ffi!(constants, family, skewness, kurtosis => describe(&constants.distribution, family, skewness, kurtosis))
}
