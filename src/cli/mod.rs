//! Argument parsing and the subcommands of `kefric`.

mod eval;

use clap::{Parser, Subcommand};
use std::fmt::Display;

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
}

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
}

/// Parses the command line, runs the subcommand, returns the exit status.
pub fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(err) => return clap_exit(err),
    };
    let result = match cli.command {
        Command::Eval(args) => eval::run(args),
    };
    match result {
        Ok(()) => 0,
        Err(f) => {
            eprintln!("error: {}", f.message);
            f.code
        }
    }
}

/// Help and version go to stdout with status 0; parse errors become one
/// line on stderr with status 2.
fn clap_exit(err: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match err.kind() {
        ErrorKind::DisplayHelp
        | ErrorKind::DisplayVersion
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = err.print();
            if err.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                2
            } else {
                0
            }
        }
        _ => {
            let text = err.render().to_string();
            let line: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty() && !l.starts_with("Usage:"))
                .map(str::trim)
                .collect();
            eprintln!("{}", line.join(" "));
            2
        }
    }
}

/// Parses a finite number, naming the flag on failure.
pub fn parse_f64(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{s} is not a finite number"))
    }
}

/// The flag that sets a [`ke_friction::Params`] field, for messages.
pub fn flag_of(field: &str) -> String {
    format!("--{}", field.replace('_', "-"))
}
