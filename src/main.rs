//! `kefric`: the Kogut–Etsion static friction model from the command line.
//!
//! Thin by design: it parses, calls the library, prints. Bad input exits
//! with status 2 and a one-line message naming the input and its range.

mod cli;

fn main() {
    restore_sigpipe();
    std::process::exit(cli::run());
}

/// Rust ignores SIGPIPE, so `kefric eval … | head -1` would panic on the
/// closed pipe; restore the default (end quietly), as Unix tools do.
fn restore_sigpipe() {
    #[cfg(unix)]
    {
        extern "C" {
            fn signal(signum: i32, handler: usize) -> usize;
        }
        const SIGPIPE: i32 = 13;
        const SIG_DFL: usize = 0;
        // SAFETY: resetting a signal's disposition to the default before
        // any thread starts has no preconditions.
        unsafe {
            signal(SIGPIPE, SIG_DFL);
        }
    }
}
