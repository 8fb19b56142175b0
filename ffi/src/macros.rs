//! The machinery of every export: the `ffi!` macro, the guard that turns
//! a failure or a panic into a code and a message, the pointer arguments'
//! checks (NULL, aliasing) and the helpers that write outputs and free
//! handles.

use crate::error::{remember, Failure, Message, KEF_ERR_INTERNAL, KEF_OK};
use std::ffi::{c_char, c_int, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// What an export returns: a code, a handle, a value.
pub(crate) trait Answer {
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
pub(crate) fn guard<A: Answer>(body: impl FnOnce() -> Result<A, Failure>) -> A::C {
    let failure = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(answer)) => return answer.ok(),
        Ok(Err(failure)) => failure,
        Err(_) => Failure {
            code: KEF_ERR_INTERNAL,
            message: Message::Text("internal error: a panic in ke-friction (please report it)".into()),
        },
    };
    remember(failure.message);
    A::failed(failure.code)
}

/// A pointer argument, checked and turned into what Rust uses.
pub(crate) trait Arg<'a> {
    /// What it points to.
    type Rust;
    /// The Rust view of the pointer named `name`, or a failure naming it.
    ///
    /// # Safety
    /// The pointer is NULL or valid as the export's contract says, for `'a`.
    unsafe fn check(self, name: &str) -> Result<Self::Rust, Failure>;
}

/// A pointer to `n` elements, checked and turned into a slice.
pub(crate) trait Array<'a> {
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
pub(crate) fn null(name: &str) -> Failure {
    Failure::argument(format!("{name} is NULL"))
}

macro_rules! pointee {
    ($ptr:ty => $rust:ty, |$p:ident| $view:expr) => {
        impl<'a> $crate::macros::Arg<'a> for $ptr {
            type Rust = $rust;
            unsafe fn check(self, name: &str) -> Result<$rust, $crate::error::Failure> {
                let $p = self;
                // SAFETY: NULL or valid for 'a, by the caller's contract.
                unsafe { $view }.ok_or_else(|| $crate::macros::null(name))
            }
        }
    };
}

pointee!(*mut f64 => &'a mut f64, |p| p.as_mut());
pointee!(*mut usize => &'a mut usize, |p| p.as_mut());
pointee!(*mut u64 => &'a mut u64, |p| p.as_mut());
pointee!(*mut c_int => &'a mut c_int, |p| p.as_mut());
pointee!(*const c_char => &'a CStr, |p| (!p.is_null()).then(|| CStr::from_ptr(p)));

/// The bytes a pointer argument points to, for the aliasing check.
pub(crate) trait Region {
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
pub(crate) type Place = (&'static str, (usize, usize, bool));

/// The failure if an output overlaps another pointer argument (two
/// references to one place, one of them `&mut`, would be undefined
/// behaviour): checked before any reference is made. Inputs may overlap
/// each other.
pub(crate) fn distinct(places: &[Place]) -> Result<(), Failure> {
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
        $crate::macros::guard(|| {
            $crate::macros::distinct(&[$((stringify!($arg), $crate::macros::Region::region(&$arg, ffi!(@count $([$n])?)))),*])?;
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
        $crate::macros::Arg::check($arg, stringify!($arg))
    };
    (@check $arg:ident [$n:expr]) => {
        $crate::macros::Array::check_n($arg, stringify!($arg), $n)
    };
}

/// Writes `value` to `out`.
pub(crate) fn set<T>(out: &mut T, value: T) -> Result<(), Failure> {
    *out = value;
    Ok(())
}

/// Writes a pair to two outputs.
pub(crate) fn set2(a: &mut f64, b: &mut f64, (x, y): (f64, f64)) -> Result<(), Failure> {
    (*a, *b) = (x, y);
    Ok(())
}

/// Frees a handle from `Box::into_raw` unless it is NULL or `keep`.
///
/// # Safety
/// `p` is NULL, `keep`, or from `Box::into_raw`, not yet freed and no
/// longer in use.
pub(crate) unsafe fn free<T>(p: *mut T, keep: *const T) {
    if !p.is_null() && !std::ptr::eq(p.cast_const(), keep) {
        // SAFETY: from Box::into_raw, freed once, by the caller's contract.
        drop(unsafe { Box::from_raw(p) });
    }
}
