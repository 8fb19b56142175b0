//! `kefric`: the Kogut–Etsion static friction model from the command line.
//!
//! Thin by design: it parses, calls the library, prints. Bad input exits
//! with status 2 and a one-line message naming the input and its range.

#![deny(unsafe_op_in_unsafe_fn)]
#![warn(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]

/// `println!` through [`args::write_stdout`]: `outln!(…)?` fails the run
/// (exit 1) when stdout cannot be written.
macro_rules! outln {
    ($($t:tt)*) => { $crate::args::write_stdout(format_args!($($t)*), true) };
}

/// `print!` through [`args::write_stdout`].
macro_rules! out {
    ($($t:tt)*) => { $crate::args::write_stdout(format_args!($($t)*), false) };
}

/// `eprintln!` that cannot panic (see [`args::write_stderr`]).
macro_rules! errln {
    ($($t:tt)*) => { $crate::args::write_stderr(format_args!($($t)*)) };
}

mod args;
mod build;
mod eval;
mod export;
mod heights;
mod info;
mod law;
mod lookup;
mod params;
mod plot;
mod scale;
mod surface;
mod validate;
mod verify;

use args::Failure;
use clap::{Parser, Subcommand};

fn main() {
    restore_sigpipe();
    std::process::exit(run());
}

/// The Kogut–Etsion (2004) static friction model of rough surfaces.
#[derive(Debug, Parser)]
#[command(name = "kefric", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Evaluate the model by direct integration at given h* or F*.
    Eval(eval::Args),
    /// Build a table by direct integration, verify it, write it atomically.
    Build(build::Args),
    /// Check a table against direct integration.
    Verify(verify::Args),
    /// Look up μ and ∂μ/∂F* in a table.
    Lookup(lookup::Args),
    /// Draw the paper's figures, a curve, or a table's error map.
    Plot(plot::Args),
    /// Compare this model with the statements of the paper.
    Validate(validate::Args),
    /// Export a table to NumPy .npz/.npy.
    Export(export::Args),
    /// Show what a table file holds.
    Info(info::Args),
    /// Convert SI inputs to the model's ψ, θ, β, ν, ε*.
    Params(params::Args),
    /// A friction law's table for a simulator: pressure, μ, dμ/dp as CSV.
    Law(law::Args),
    Surface(surface::Args),
}

/// Parses the command line, runs the subcommand, returns the exit status.
fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(err) => return clap_exit(err),
    };
    let result = match cli.command {
        Command::Eval(args) => eval::run(args),
        Command::Build(args) => build::run(args),
        Command::Verify(args) => verify::run(args),
        Command::Lookup(args) => lookup::run(args),
        Command::Plot(args) => plot::run(args),
        Command::Validate(args) => validate::run(args),
        Command::Export(args) => export::run(args),
        Command::Info(args) => info::run(args),
        Command::Params(args) => params::run(args),
        Command::Law(args) => law::run(args),
        Command::Surface(args) => surface::run(args),
    };
    // Whatever the command left in stdout's buffer must be written too.
    match result.and_then(|()| args::flush_stdout()) {
        Ok(()) => 0,
        Err(f) => f.report(),
    }
}

/// Help and version go to stdout with status 0; parse errors become one
/// line on stderr with status 2.
fn clap_exit(err: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match err.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            if let Err(e) = err.print() {
                return Failure::output("stdout", &e).report();
            }
            if err.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                2
            } else {
                0
            }
        }
        ErrorKind::ValueValidation | ErrorKind::InvalidValue => {
            // The same voice as every other input error: `error: --FLAG: …`.
            errln!("error: {}", value_message(&err));
            2
        }
        _ => {
            let text = err.render().to_string();
            let line: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty() && !l.starts_with("Usage:"))
                .map(str::trim)
                .collect();
            errln!("{}", line.join(" "));
            2
        }
    }
}

/// `--FLAG: 'VALUE' is not …` for a value clap rejected.
fn value_message(err: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue};
    let context = |kind| match err.get(kind) {
        Some(ContextValue::String(s)) => s.clone(),
        Some(ContextValue::Strings(v)) => v.join(", "),
        _ => String::new(),
    };
    // "--f-star <F_STAR>" → "--f-star".
    let arg = context(ContextKind::InvalidArg);
    let flag = arg.split_whitespace().next().unwrap_or("input").to_string();
    let why = match std::error::Error::source(err) {
        Some(source) => source.to_string(),
        None => format!(
            "'{}' is not one of: {}",
            context(ContextKind::InvalidValue),
            context(ContextKind::ValidValue)
        ),
    };
    format!("{flag}: {why}")
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
