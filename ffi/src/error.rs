//! The return codes, the one mapping of the core's errors to them, and
//! this thread's last message (kef_last_error).

use ke_friction::{Classify, ErrorKind, LookupError, PressureError};
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

/// A failure's message: text, or an error of a lookup kept as it is and
/// formatted only if [`kef_last_error`] asks for it (formatting three
/// numbers costs forty lookups; a loop where some nodes are open must not
/// pay it per node).
pub(crate) enum Message {
    /// Formatted already.
    Text(String),
    /// Formatted on demand.
    Lazy(Lazy),
}

/// The errors whose messages are formatted on demand: the lookups' (small
/// `Copy` values, stored as they are).
#[derive(Clone, Copy)]
pub(crate) enum Lazy {
    /// A table's or curve's lookup.
    Lookup(LookupError),
    /// A friction law's pressure.
    Pressure(PressureError),
}

impl std::fmt::Display for Lazy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Lazy::Lookup(e) => e.fmt(f),
            Lazy::Pressure(e) => e.fmt(f),
        }
    }
}

impl From<LookupError> for Message {
    fn from(e: LookupError) -> Message {
        Message::Lazy(Lazy::Lookup(e))
    }
}

impl From<PressureError> for Message {
    fn from(e: PressureError) -> Message {
        Message::Lazy(Lazy::Pressure(e))
    }
}

/// The core's errors whose messages are formatted at once (construction
/// and I/O: rare, and slow anyway).
macro_rules! formatted {
    ($($error:ty),+ $(,)?) => {
        $(impl From<$error> for Message {
            fn from(e: $error) -> Message {
                Message::Text(e.to_string())
            }
        })+
    };
}

formatted!(
    ke_friction::ParamError,
    ke_friction::CurveError,
    ke_friction::TableError,
    ke_friction::EvalError,
    ke_friction::DistributionError,
    ke_friction::FrictionLawError,
    ke_friction::ConstantsMismatch,
    ke_friction::topography::ReadError,
    ke_friction::topography::StatsError,
);

/// A failure: its code and message.
pub(crate) struct Failure {
    pub(crate) code: c_int,
    pub(crate) message: Message,
}

impl Failure {
    /// A failure of the C side itself (a NULL pointer, an unknown name).
    pub(crate) fn argument(message: String) -> Failure {
        Failure {
            code: KEF_ERR_ARGUMENT,
            message: Message::Text(message),
        }
    }
}

impl<E: Classify + Into<Message>> From<E> for Failure {
    fn from(e: E) -> Failure {
        Failure {
            code: code(e.kind()),
            message: e.into(),
        }
    }
}

/// The size of the per-thread message buffer, its NUL included.
const MESSAGE_CAPACITY: usize = 1024;

thread_local! {
    /// This thread's last message, NUL-terminated: one buffer for the
    /// thread's life, overwritten in place, never freed or moved.
    static LAST_ERROR: [Cell<u8>; MESSAGE_CAPACITY] = const { [const { Cell::new(0) }; MESSAGE_CAPACITY] };
    /// This thread's last failure if its message is not formatted yet.
    static PENDING: Cell<Option<Lazy>> = const { Cell::new(None) };
}

/// Writes into the thread's buffer from its start, cutting at a character
/// boundary to leave room for the NUL (a NUL in the text becomes a space).
struct Buffer<'a> {
    cells: &'a [Cell<u8>; MESSAGE_CAPACITY],
    len: usize,
}

impl std::fmt::Write for Buffer<'_> {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let room = MESSAGE_CAPACITY - 1 - self.len;
        let mut end = s.len().min(room);
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        for (cell, &b) in self.cells[self.len..].iter().zip(&s.as_bytes()[..end]) {
            cell.set(if b == 0 { b' ' } else { b });
        }
        self.len += end;
        self.cells[self.len].set(0);
        // A cut message is still a message: the rest is dropped.
        Ok(())
    }
}

/// Writes `message` (formatted) into this thread's buffer.
fn write(message: &dyn std::fmt::Display) {
    use std::fmt::Write as _;
    LAST_ERROR.with(|cells| {
        let mut buffer = Buffer { cells, len: 0 };
        cells[0].set(0);
        // Buffer::write_str never fails; a Display that does leaves what it wrote.
        let _ = write!(buffer, "{message}");
    });
}

/// Stores `message` as this thread's last: text at once, a lookup's error
/// as it is (formatted by [`kef_last_error`]).
pub(crate) fn remember(message: Message) {
    match message {
        Message::Text(text) => {
            PENDING.with(|p| p.set(None));
            write(&text);
        }
        Message::Lazy(e) => PENDING.with(|p| p.set(Some(e))),
    }
}

/// The message of this thread's last failure ("" if none), formatted by
/// this call: call it after the call that failed (a lookup's message is
/// formatted only when asked for, so that a failing lookup costs about
/// what a lookup does). Never NULL; do not free it. The pointer stays
/// valid until the thread exits: it points to one buffer per thread,
/// overwritten in place (never freed or moved) by this function and by
/// failures of calls that build or load; a pointer kept from an earlier
/// call is safe to read, and holds the last message formatted. A message
/// longer than 1023 bytes is cut.
#[no_mangle]
pub extern "C" fn kef_last_error() -> *const c_char {
    if let Some(e) = PENDING.with(Cell::take) {
        write(&e);
    }
    LAST_ERROR.with(|buffer| buffer.as_ptr().cast())
}
