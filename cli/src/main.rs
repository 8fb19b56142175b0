//! `kefric`: the Kogut–Etsion static friction model from the command line.
//!
//! Thin by design: it parses, calls the library, prints. Bad input exits
//! with status 2 and a one-line message naming the input and its range.

#![deny(unsafe_op_in_unsafe_fn)]
#![warn(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]

/// `println!` through [`output::write_stdout`]: `outln!(…)?` fails the run
/// (exit 1) when stdout cannot be written.
macro_rules! outln {
    ($($t:tt)*) => { $crate::output::write_stdout(format_args!($($t)*), true) };
}

/// `print!` through [`output::write_stdout`].
macro_rules! out {
    ($($t:tt)*) => { $crate::output::write_stdout(format_args!($($t)*), false) };
}

/// `eprintln!` that cannot panic (see [`output::write_stderr`]).
macro_rules! errln {
    ($($t:tt)*) => { $crate::output::write_stderr(format_args!($($t)*)) };
}

mod args;
mod build;
mod container;
mod eval;
mod export;
mod heights;
mod info;
mod law;
mod load_args;
mod lookup;
mod measurements;
mod model_args;
mod output;
mod params;
mod plot;
mod scale;
mod surface;
mod surface_args;
mod validate;
mod verify;
mod words;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use output::Failure;

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

/// The command line's definition: the derived one with the help headings
/// that depend on each subcommand's flags ([`args::help_headings`]).
fn command() -> clap::Command {
    negative_numbers(args::help_headings(Cli::command()))
}

/// Every (sub)command takes a negative number as a flag's value without
/// `=` (`--skewness -1`, `--h-star -0.5`), not as an unknown flag.
fn negative_numbers(mut command: clap::Command) -> clap::Command {
    let names: Vec<String> = command.get_subcommands().map(|c| c.get_name().to_string()).collect();
    for name in names {
        command = command.mut_subcommand(name, negative_numbers);
    }
    command.allow_negative_numbers(true)
}

/// Parses the command line, runs the subcommand, returns the exit status.
fn run() -> i32 {
    let cli = match command().try_get_matches().and_then(|m| Cli::from_arg_matches(&m)) {
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
        Command::Surface(args) if !args.measurements.is_empty() => container::run_measurements(&args),
        Command::Surface(args) if args.scale_dependent => scale::run_scale_dependent(&args),
        Command::Surface(args) if args.psd => scale::run_psd(&args),
        Command::Surface(args) if args.scan => scale::run_scan(&args),
        Command::Surface(args) if args.files.len() == 1 && container::is_container(&args.files[0]) => {
            if args.csv {
                Err(Failure::input(
                    "--csv: with --scan, --psd or --scale-dependent (the single record is --json)",
                ))
            } else {
                container::run(&args, &container::Input::Container(&args.files[0]))
            }
        }
        Command::Surface(args) => surface::run(args),
    };
    // Whatever the command left in stdout's buffer must be written too.
    match result.and_then(|()| output::flush_stdout()) {
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
        // A CLI-only switch (`--precision`, `--sensitivity`): worded as the
        // core's unknown name.
        None => {
            let valid = match err.get(ContextKind::ValidValue) {
                Some(ContextValue::Strings(v)) => v.clone(),
                _ => Vec::new(),
            };
            ke_friction::NameError::new("value", &context(ContextKind::InvalidValue), valid).to_string()
        }
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

#[cfg(test)]
mod tests {
    use super::command;

    /// The `--flag`s named in `text` (`--f-star`, not `--` alone or `---`).
    fn flags_in(text: &str) -> Vec<String> {
        let mut flags = Vec::new();
        for (i, _) in text.match_indices("--") {
            let before = text[..i].chars().next_back();
            if before.is_some_and(|c| c == '-' || c.is_alphanumeric()) {
                continue;
            }
            let name: String = text[i + 2..]
                .chars()
                .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '-')
                .collect();
            let name = name.trim_end_matches('-');
            if name.starts_with(|c: char| c.is_ascii_lowercase()) {
                flags.push(format!("--{name}"));
            }
        }
        flags
    }

    /// The long flags `command` takes (with `--help`, `--version`).
    fn flags_of(command: &clap::Command) -> Vec<String> {
        command
            .get_arguments()
            .filter_map(|a| a.get_long())
            .map(|l| format!("--{l}"))
            .chain(["--help".to_string(), "--version".to_string()])
            .collect()
    }

    /// Every subcommand, with its path (`["plot", "surface"]`).
    fn walk(command: &clap::Command, path: Vec<String>, out: &mut Vec<(Vec<String>, clap::Command)>) {
        for sub in command.get_subcommands() {
            let mut p = path.clone();
            p.push(sub.get_name().to_string());
            walk(sub, p.clone(), out);
            out.push((p, sub.clone()));
        }
    }

    fn subcommands() -> Vec<(Vec<String>, clap::Command)> {
        let mut cmd = command().bin_name("kefric");
        cmd.build();
        let mut out = Vec::new();
        walk(&cmd, Vec::new(), &mut out);
        out
    }

    /// Every flag a subcommand's help names (in a flag's help, a heading,
    /// the about text) is one that subcommand takes: "in place of --beta"
    /// in a command without `--beta` would send a user to a refusal.
    #[test]
    fn every_flag_named_in_a_subcommands_help_is_one_it_takes() {
        let mut wrong = Vec::new();
        for (path, mut sub) in subcommands() {
            if path.iter().any(|p| p == "help") {
                continue; // clap's own
            }
            let flags = flags_of(&sub);
            let mut help = format!("{}\n{}", sub.render_long_help(), sub.render_help());
            // A parent's list of subcommands quotes their abouts, each
            // checked with its own subcommand.
            while let Some(start) = help.find("\nCommands:\n") {
                let end = help[start..].find("\n\n").map_or(help.len(), |e| start + e);
                help.replace_range(start..end, "");
            }
            for flag in flags_in(&help) {
                if !flags.contains(&flag) && !wrong.contains(&(path.join(" "), flag.clone())) {
                    wrong.push((path.join(" "), flag));
                }
            }
        }
        assert!(
            wrong.is_empty(),
            "flags named in a help that the subcommand does not take: {wrong:?}"
        );
        // The check sees what it is meant to: the SI heading of `lookup`
        // names exactly its dimensionless flags, and `params` none.
        let help = |name: &str| {
            let (_, mut sub) = subcommands().into_iter().find(|(p, _)| p == &[name]).unwrap();
            sub.render_help().to_string()
        };
        assert!(help("lookup").contains("SI inputs (all ten together, in place of --psi, --theta):"));
        assert!(help("eval").contains("in place of --psi, --theta, --beta, --nu, --eps-star):"));
        assert!(help("params").contains("SI inputs (all ten together):"));
        assert!(help("surface").contains("Materials (all seven together):"));
    }

    /// Every `kefric SUBCOMMAND …` line of the README's and REFERENCE.md's
    /// code blocks (with its `\` continuations and its comment) uses only
    /// flags that subcommand takes.
    #[test]
    fn every_flag_in_the_docs_code_blocks_belongs_to_its_subcommand() {
        let subs = subcommands();
        let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
        let mut checked = 0;
        let mut wrong = Vec::new();
        for doc in ["README.md", "docs/REFERENCE.md"] {
            let text = std::fs::read_to_string(format!("{root}/{doc}")).unwrap();
            let mut in_block = false;
            let mut lines = text.lines();
            while let Some(line) = lines.next() {
                if line.trim_start().starts_with("```") {
                    in_block = !in_block;
                    continue;
                }
                let Some(at) = line.find("kefric ").filter(|_| in_block) else {
                    continue;
                };
                let mut command = line[at + "kefric ".len()..].to_string();
                while command.trim_end().ends_with('\\') {
                    command = command.trim_end().trim_end_matches('\\').to_string();
                    command.push(' ');
                    command.push_str(lines.next().unwrap_or_default());
                }
                let words: Vec<&str> = command.split_whitespace().collect();
                // The longest subcommand path the words start with.
                let Some((path, sub)) = subs
                    .iter()
                    .filter(|(p, _)| words.len() >= p.len() && p.iter().zip(&words).all(|(a, b)| a == b))
                    .max_by_key(|(p, _)| p.len())
                else {
                    wrong.push((doc, command.clone(), "no such subcommand".to_string()));
                    continue;
                };
                checked += 1;
                let flags = flags_of(sub);
                for flag in flags_in(&command) {
                    if !flags.contains(&flag) {
                        wrong.push((doc, path.join(" "), flag));
                    }
                }
            }
        }
        assert!(
            wrong.is_empty(),
            "flags in the docs' examples their subcommand does not take: {wrong:#?}"
        );
        assert!(
            checked >= 15,
            "only {checked} kefric lines found in the docs' code blocks"
        );
    }
}
