//! The return codes, the one mapping of the core's errors to them, and
//! this thread's last message (kef_last_error).

use ke_friction::{Classify, ErrorKind};
use std::cell::Cell;
use std::ffi::{c_char, c_int};

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
pub(crate) struct Failure {
    pub(crate) code: c_int,
    pub(crate) message: String,
}

impl Failure {
    /// A failure of the C side itself (a NULL pointer, an unknown name).
    pub(crate) fn argument(message: String) -> Failure {
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
pub(crate) fn remember(message: &str) {
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
