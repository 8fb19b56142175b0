//! What the subcommands share: failures and their exit codes, number
//! parsing, the model's flags, progress bars, tables and output paths.

use ke_friction::{Fit, Kind, Model, Params, DEFAULT_BETA, DEFAULT_EPS_STAR, DEFAULT_NU};
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

    /// Prints the message as one line on stderr; returns the exit status.
    pub fn report(&self) -> i32 {
        eprintln!("error: {}", self.message);
        self.code
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

/// Fails early (before long work) if the file `path`, given by `flag`,
/// cannot be written: a directory, no file name, or a parent directory
/// that does not exist.
pub fn check_writable(flag: &str, path: &std::path::Path) -> Result<(), Failure> {
    if path.is_dir() {
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

/// The output directory `path`, given by `flag`, created with its parents
/// if missing (before long work). A path that exists and is not a
/// directory, or that has no name of its own (`/`, `..`, empty), is an
/// error.
pub fn output_dir(flag: &str, path: &std::path::Path) -> Result<(), Failure> {
    if path.file_name().is_none() {
        let what = if path.as_os_str().is_empty() {
            "empty path".into()
        } else {
            format!("{} has no directory name", path.display())
        };
        return Err(Failure::input(format!(
            "{flag}: {what} (name a directory to write into)"
        )));
    }
    if path.exists() && !path.is_dir() {
        return Err(Failure::input(format!(
            "{flag}: {} exists and is not a directory",
            path.display()
        )));
    }
    std::fs::create_dir_all(path)
        .map_err(|e| Failure::input(format!("{flag}: cannot create directory {}: {e}", path.display())))
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
pub fn load_table(path: Option<&std::path::Path>) -> Result<std::borrow::Cow<'static, ke_friction::Table>, Failure> {
    use std::borrow::Cow;
    match path {
        None => Ok(Cow::Borrowed(ke_friction::Table::embedded())),
        Some(path) => ke_friction::Table::load(path)
            .map(Cow::Owned)
            .map_err(|e| Failure::input(format!("--table {}: {e}", path.display()))),
    }
}

/// Prints where a table's measured error of μ is largest.
pub fn print_worst(acc: &ke_friction::table::Accuracy) {
    println!(
        "worst at psi = {:.6}, theta = {:.6e}, F* = {:.6e}",
        acc.worst[0], acc.worst[1], acc.worst[2]
    );
}

/// The model's parameters, shared by the subcommands that evaluate it.
#[derive(Debug, Clone, clap::Args)]
pub struct ModelArgs {
    /// Plasticity index ψ > 0.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub psi: f64,
    /// Adhesion parameter θ ≥ 0.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub theta: f64,
    /// Roughness parameter β = ηRσ > 0.01928.
    #[arg(long, value_parser = parse_f64, default_value_t = DEFAULT_BETA, allow_hyphen_values = true)]
    pub beta: f64,
    /// Poisson's ratio ν of the softer material, in [0, 0.5).
    #[arg(long, value_parser = parse_f64, default_value_t = DEFAULT_NU, allow_hyphen_values = true)]
    pub nu: f64,
    /// Intermolecular distance ε* = ε/σ > 0.
    #[arg(long, value_parser = parse_f64, default_value_t = DEFAULT_EPS_STAR, allow_hyphen_values = true)]
    pub eps_star: f64,
    /// Friction row: the self-consistent model, or the literal printed Eq. 18.
    #[arg(long, value_enum, default_value_t = FitArg::Consistent)]
    pub fit: FitArg,
    /// Kogut–Etsion, or the CEB-type comparison model (MODEL.md §8).
    #[arg(long, value_enum, default_value_t = ModelKindArg::Ke)]
    pub model: ModelKindArg,
}

/// `--fit` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum FitArg {
    /// MODEL.md §4 (the default).
    Consistent,
    /// The literal printed Eq. 18 (negative μ for ψ ≳ 2).
    AsPrinted,
}

impl From<FitArg> for Fit {
    fn from(f: FitArg) -> Fit {
        match f {
            FitArg::Consistent => Fit::Consistent,
            FitArg::AsPrinted => Fit::AsPrinted,
        }
    }
}

/// `--model` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum ModelKindArg {
    /// Kogut–Etsion (2004).
    Ke,
    /// CEB-type (approximate reconstruction).
    Ceb,
}

impl From<ModelKindArg> for Kind {
    fn from(k: ModelKindArg) -> Kind {
        match k {
            ModelKindArg::Ke => Kind::KogutEtsion,
            ModelKindArg::Ceb => Kind::CebType,
        }
    }
}

impl ModelArgs {
    /// The validated model, or a message naming the offending flag.
    pub fn model(&self) -> Result<Model, Failure> {
        let params = Params::new(self.psi, self.theta)
            .beta(self.beta)
            .nu(self.nu)
            .eps_star(self.eps_star)
            .fit(self.fit.into())
            .kind(self.model.into());
        Model::new(params).map_err(|e| Failure::input(format!("{}: {e}", flag_of(e.name))))
    }
}

/// 17 significant digits: every double round-trips.
pub fn full(x: f64) -> String {
    format!("{x:.16e}")
}
