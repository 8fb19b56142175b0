//! What every subcommand writes through: failures and their exit codes,
//! stdout and stderr, the core's warnings, the one format of numbers in
//! text. A leaf: it uses nothing else of the CLI.

use ke_friction::{Classify, ErrorKind, Shortest, Warnings};
use std::fmt::Display;

/// A failure to report: the message, and whether it is the user's input
/// (exit 2) or something else (exit 1).
#[derive(Debug)]
pub struct Failure {
    message: String,
    code: i32,
}

impl Failure {
    /// Bad input: exit status 2.
    pub fn input(message: impl Display) -> Failure {
        Failure {
            message: message.to_string(),
            code: 2,
        }
    }

    /// Anything else (e.g. a build that misses its tolerance): exit status 1.
    pub fn other(message: impl Display) -> Failure {
        Failure {
            message: message.to_string(),
            code: 1,
        }
    }

    /// A library error, by its [`ErrorKind`]: the CLI's one mapping of
    /// kinds to exit statuses. Argument, domain, no μ, a damaged table, an
    /// input that cannot be read: 2; a missed tolerance: 1; a bug: 70
    /// (EX_SOFTWARE), saying so.
    pub fn of(context: impl Display, e: impl Classify) -> Failure {
        Failure::classified(format!("{context}: {e}"), e.kind())
    }

    /// `message` with the exit status of `kind` ([`Failure::of`]).
    pub fn classified(message: String, kind: ErrorKind) -> Failure {
        match kind {
            ErrorKind::Tolerance => Failure::other(message),
            ErrorKind::Internal => Failure {
                message: format!("{message} (this is a bug: please report it with the command line)"),
                code: 70,
            },
            _ => Failure::input(message),
        }
    }

    /// Output that cannot be written (`what`: `stdout` or a file's flag
    /// and path): exit status 1.
    pub fn output(what: impl Display, e: &std::io::Error) -> Failure {
        Failure::other(format!("{what}: {}", io_message(e)))
    }

    /// The message.
    pub fn message(&self) -> &str {
        &self.message
    }

    /// Prints the message as one line on stderr; returns the exit status.
    pub fn report(&self) -> i32 {
        errln!("error: {}", self.message);
        self.code
    }
}

/// A system error's message without Rust's " (os error N)" suffix:
/// `No space left on device`.
pub fn io_message(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.rfind(" (os error ") {
        Some(at) if text.ends_with(')') => text[..at].to_string(),
        _ => text,
    }
}

/// Writes to stdout through one checked path: a failed write (a full
/// disk, a closed pipe) is a [`Failure`] (`error: stdout: …`, exit 1),
/// never a panic as `println!` would give.
pub fn write_stdout(args: std::fmt::Arguments, newline: bool) -> Result<(), Failure> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_fmt(args)
        .and_then(|()| if newline { out.write_all(b"\n") } else { Ok(()) })
        .map_err(|e| Failure::output("stdout", &e))
}

/// Flushes stdout (at the end of a run): what is still buffered must
/// reach it, or the run fails.
pub fn flush_stdout() -> Result<(), Failure> {
    use std::io::Write;
    std::io::stdout().flush().map_err(|e| Failure::output("stdout", &e))
}

/// Writes a line to stderr; if stderr itself cannot be written there is
/// nowhere left to say so, and the exit status still tells.
pub fn write_stderr(args: std::fmt::Arguments) {
    use std::io::Write;
    let mut err = std::io::stderr().lock();
    let _ = err.write_fmt(args).and_then(|()| err.write_all(b"\n"));
}

/// Prints the warnings on stderr, one line a kind (`warning: …`, with the
/// count and the worst value over many results): the CLI's one place for
/// the core's warnings ([`ke_friction::Warnings`]).
pub fn warn(warnings: &Warnings) {
    for s in warnings.summaries() {
        errln!("warning: {s}");
    }
}

/// Six significant digits, shortest form: the one format of numbers in
/// text ([`Shortest::sig`]).
pub fn sig(x: f64) -> Shortest {
    Shortest::sig(x)
}
