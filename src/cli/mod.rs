//! Argument parsing and the subcommands of `kefric`.

mod build;
mod eval;
mod export;
mod lookup;
mod plot;
mod validate;
mod verify;

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

    /// Anything else (e.g. a build that misses its tolerance): exit status 1.
    pub fn other(message: impl Display) -> Failure {
        Failure {
            message: message.to_string(),
            code: 1,
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
        Command::Build(args) => build::run(args),
        Command::Verify(args) => verify::run(args),
        Command::Lookup(args) => lookup::run(args),
        Command::Plot(args) => plot::run(args),
        Command::Validate(args) => validate::run(args),
        Command::Export(args) => export::run(args),
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
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
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
    let v: f64 = s.trim().parse().map_err(|_| format!("'{s}' is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{s} is not a finite number"))
    }
}

/// A number for `flag`: bad input names the flag.
pub fn number(flag: &str, text: &str) -> Result<f64, Failure> {
    parse_f64(text).map_err(|e| Failure::input(format!("{flag}: {e}")))
}

/// A whole number for `flag`.
pub fn whole(flag: &str, text: &str) -> Result<usize, Failure> {
    text.trim()
        .parse()
        .map_err(|_| Failure::input(format!("{flag}: '{text}' is not a whole number")))
}

/// The `N` fields of `text` split at `sep`, or a message naming `flag` and
/// the expected `form` (e.g. `LO:HI`).
pub fn fields<'a, const N: usize>(flag: &str, text: &'a str, sep: char, form: &str) -> Result<[&'a str; N], Failure> {
    let parts: Vec<&str> = text.split(sep).collect();
    parts
        .try_into()
        .map_err(|_| Failure::input(format!("{flag}: '{text}' is not {form}")))
}

/// The flag that sets a [`ke_friction::Params`] field, for messages.
pub fn flag_of(field: &str) -> String {
    format!("--{}", field.replace('_', "-"))
}

/// Fails early (before long work) if `path`, given by `flag`, cannot be
/// written: a directory where a file is wanted (or a file where a
/// directory is, with `want_dir`), no file name, or a parent directory
/// that does not exist.
pub fn check_writable(flag: &str, path: &std::path::Path, want_dir: bool) -> Result<(), Failure> {
    if want_dir {
        if path.exists() && !path.is_dir() {
            return Err(Failure::input(format!(
                "{flag}: {} exists and is not a directory",
                path.display()
            )));
        }
    } else if path.is_dir() {
        return Err(Failure::input(format!("{flag}: {} is a directory", path.display())));
    }
    if path.file_name().is_none() {
        return Err(Failure::input(format!("{flag}: {} has no file name", path.display())));
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => std::path::Path::new("."),
    };
    if !parent.is_dir() {
        return Err(Failure::input(format!(
            "{flag}: directory {} does not exist",
            parent.display()
        )));
    }
    Ok(())
}

/// A progress bar on stderr with rate and ETA; hidden when stderr is not a
/// terminal or with `--quiet`.
pub struct Bar(indicatif::ProgressBar);

impl Bar {
    /// A bar, hidden if `quiet` or stderr is not a terminal.
    pub fn new(quiet: bool) -> Bar {
        use std::io::IsTerminal;
        let bar = if quiet || !std::io::stderr().is_terminal() {
            indicatif::ProgressBar::hidden()
        } else {
            indicatif::ProgressBar::new(0)
        };
        bar.set_style(
            indicatif::ProgressStyle::with_template("{msg:40} [{bar:30}] {pos}/{len} {per_sec} ETA {eta}")
                .expect("valid template")
                .progress_chars("=> "),
        );
        Bar(bar)
    }

    /// Clears the bar.
    pub fn done(&self) {
        self.0.finish_and_clear();
    }
}

impl ke_friction::build::Progress for Bar {
    fn stage(&self, name: &str, total: u64) {
        self.0.set_message(name.to_string());
        self.0.set_length(total);
        self.0.set_position(0);
        self.0.reset_eta();
    }

    fn advance(&self, n: u64) {
        self.0.inc(n);
    }
}

/// The table at `path`, or the embedded default table without one; any
/// problem with the file is bad input (exit 2) naming it.
pub fn table(path: Option<&std::path::Path>) -> Result<std::borrow::Cow<'static, ke_friction::Table>, Failure> {
    use std::borrow::Cow;
    match path {
        None => Ok(Cow::Borrowed(ke_friction::Table::embedded())),
        Some(path) => ke_friction::Table::load(path)
            .map(Cow::Owned)
            .map_err(|e| Failure::input(format!("--table {}: {e}", path.display()))),
    }
}

/// Prints where a table's measured error of μ is largest.
pub fn print_worst(acc: &ke_friction::table::format::Accuracy) {
    println!(
        "worst at psi = {:.6}, theta = {:.6e}, F* = {:.6e}",
        acc.worst[0], acc.worst[1], acc.worst[2]
    );
}
