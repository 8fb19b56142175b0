//! What the subcommands share besides output (`output.rs`): number
//! parsing, the model's and the materials' flags, progress bars, tables
//! and output paths.
use crate::output::{io_message, Failure};
use clap::builder::TypedValueParser;
use ke_friction::bound::help;
use ke_friction::bounds;
use ke_friction::Shortest;
use ke_friction::{Constants, Family, Fit, HeightDistribution, Materials, ModelKind, Named, Params};

/// Parses a finite number, naming the flag on failure.
pub fn parse_f64(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number (e.g. 0.5 or 1e-3)"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("'{s}' is not a finite number"))
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
pub use crate::words::flag as flag_of;

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
    ke_friction::build::check_output(path).map_err(|e| Failure::input(format!("{flag}: {}", io_message(&e))))
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
            .map_err(|e| Failure::of("--table", e)),
    }
}

/// Prints where a table's measured error of μ is largest.
pub fn print_worst(acc: &ke_friction::Accuracy) -> Result<(), Failure> {
    outln!(
        "worst at psi = {}, theta = {}, F* = {}",
        Shortest::rounded(acc.worst[0]),
        Shortest::rounded(acc.worst[1]),
        Shortest::rounded(acc.worst[2])
    )
}

/// The model constants' flags (β, ν, ε*, fit, model), shared by every
/// subcommand that takes them; unset ones take [`Constants::default`].
#[derive(Debug, Clone, clap::Args)]
pub struct ConstantsArgs {
    /// Roughness parameter β = ηRσ (the range: [`bounds::BETA`]).
    #[arg(long, help = help("Roughness parameter β = ηRσ", &bounds::BETA, "[default: 0.04]"), value_parser = parse_f64, allow_hyphen_values = true)]
    pub beta: Option<f64>,
    /// Poisson's ratio ν of the softer material ([`bounds::NU`]).
    #[arg(long, help = help("Poisson's ratio ν of the softer material", &bounds::NU, "[default: 0.3]"), value_parser = parse_f64, allow_hyphen_values = true)]
    pub nu: Option<f64>,
    /// Intermolecular distance ε* = ε/σ ([`bounds::EPS_STAR`]).
    #[arg(long, help = help("Intermolecular distance ε* = ε/σ", &bounds::EPS_STAR, "[default: 0.004]"), value_parser = parse_f64, allow_hyphen_values = true)]
    pub eps_star: Option<f64>,
    /// Friction row: consistent (MODEL.md §4), or as-printed (the literal printed Eq. 18; negative μ for ψ ≳ 2).
    #[arg(long, value_parser = named::<Fit>(), default_value_t = Fit::Consistent)]
    pub fit: Fit,
    /// Model: ke (Kogut–Etsion), or ceb (the CEB-type comparison model, MODEL.md §8).
    #[arg(long, value_parser = named::<ModelKind>(), default_value_t = ModelKind::KogutEtsion)]
    pub model: ModelKind,
    #[command(flatten)]
    pub heights: DistributionArgs,
}

/// The height distribution's flags (MODEL.md §9), shared by `eval`,
/// `build`, `plot` (through [`ConstantsArgs`]) and `lookup` (to check the
/// table's).
#[derive(Debug, Clone, clap::Args)]
pub struct DistributionArgs {
    /// Distribution of the asperity heights (MODEL.md §9) [default: gaussian; pearson with --skewness or --kurtosis; empirical with --heights].
    #[arg(long, value_parser = named::<Family>())]
    pub distribution: Option<Family>,
    /// Skewness Sk of the heights (ISO Ssk): pearson or weibull ([`bounds::PEARSON_SKEWNESS`], [`bounds::WEIBULL_SKEWNESS`]).
    #[arg(long, help = format!("Skewness Sk of the heights (ISO Ssk): pearson ({}; K > Sk² + 1) or weibull ({}) [default: 0].", bounds::PEARSON_SKEWNESS.range(), bounds::WEIBULL_SKEWNESS.range()), value_parser = parse_f64, allow_hyphen_values = true)]
    pub skewness: Option<f64>,
    /// Kurtosis K of the heights, not excess (ISO Sku; 3 for a Gaussian): pearson ([`bounds::PEARSON_KURTOSIS`]).
    #[arg(long, help = format!("Kurtosis K of the heights (ISO Sku): pearson, K > Sk² + 1 and {} [default: 3].", bounds::PEARSON_KURTOSIS.range()), value_parser = parse_f64, allow_hyphen_values = true)]
    pub kurtosis: Option<f64>,
    /// Measured heights for an empirical density: a text file or a .npy array ([`bounds::HEIGHTS`]).
    #[arg(long, value_name = "FILE", help = format!("Measured heights for an empirical density: a text file (one height per line) or a .npy array ({}, any unit).", bounds::HEIGHTS.range()))]
    pub heights: Option<std::path::PathBuf>,
}

impl ConstantsArgs {
    /// The constants the flags ask for (not yet validated, except the
    /// distribution's flags, which must agree with each other).
    pub fn constants(&self) -> Result<Constants, Failure> {
        let d = Constants::default();
        Ok(Constants {
            beta: self.beta.unwrap_or(d.beta),
            nu: self.nu.unwrap_or(d.nu),
            eps_star: self.eps_star.unwrap_or(d.eps_star),
            fit: self.fit,
            kind: self.model,
            distribution: self.heights.distribution()?,
        })
    }

    /// The dimensionless constants given (they conflict with SI inputs).
    pub(crate) fn given(&self) -> [(&'static str, Option<f64>); 3] {
        [("--beta", self.beta), ("--nu", self.nu), ("--eps-star", self.eps_star)]
    }
}

/// The materials' SI flags ([`Materials`]): all seven together. With
/// `--sigma`, `--radius` and `--density` ([`SiArgs`]) or a measured
/// surface (`kefric surface`, `--surface`) they give ψ, θ, β, ν and ε*.
#[derive(Debug, Clone, clap::Args)]
pub struct MaterialsArgs {
    /// Young's modulus E₁ of the softer material ([`bounds::PASCALS`]).
    #[arg(long, value_name = "PA", help = help("Young's modulus E₁ of the softer material", &bounds::PASCALS, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub e1: Option<f64>,
    /// Poisson's ratio ν₁ of the softer material ([`bounds::NU`]).
    #[arg(long, help = help("Poisson's ratio ν₁ of the softer material", &bounds::NU, "(sets ν and the hardness coefficient K)"), value_parser = parse_f64, allow_hyphen_values = true)]
    pub nu1: Option<f64>,
    /// Young's modulus E₂ of the other material ([`bounds::PASCALS`]).
    #[arg(long, value_name = "PA", help = help("Young's modulus E₂ of the other material", &bounds::PASCALS, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub e2: Option<f64>,
    /// Poisson's ratio ν₂ of the other material ([`bounds::NU2`]).
    #[arg(long, help = help("Poisson's ratio ν₂ of the other material", &bounds::NU2, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub nu2: Option<f64>,
    /// Hardness H of the softer material ([`bounds::PASCALS`]).
    #[arg(long, value_name = "PA", help = help("Hardness H of the softer material", &bounds::PASCALS, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub hardness: Option<f64>,
    /// Energy of adhesion Δγ ([`bounds::ENERGY`]).
    #[arg(long, value_name = "J_PER_M2", help = help("Energy of adhesion Δγ", &bounds::ENERGY, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub delta_gamma: Option<f64>,
    /// Intermolecular distance ε ([`bounds::METRES`]).
    #[arg(long, value_name = "M", help = help("Intermolecular distance ε", &bounds::METRES, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub epsilon: Option<f64>,
}

impl MaterialsArgs {
    /// The flags and values, in the order of [`Materials`]' fields.
    fn given(&self) -> [(&'static str, Option<f64>); 7] {
        [
            ("--e1", self.e1),
            ("--nu1", self.nu1),
            ("--e2", self.e2),
            ("--nu2", self.nu2),
            ("--hardness", self.hardness),
            ("--delta-gamma", self.delta_gamma),
            ("--epsilon", self.epsilon),
        ]
    }

    /// The values, in the order of [`Materials`]' fields.
    pub fn values(&self) -> [Option<f64>; 7] {
        self.given().map(|(_, v)| v)
    }

    /// Whether any of the flags is given.
    pub fn any(&self) -> bool {
        self.given().iter().any(|(_, v)| v.is_some())
    }

    /// The materials, or a message naming the first missing flag and
    /// listing the others that go with it (`extra`: the flags of the
    /// roughness that go with them, if any).
    pub fn materials(&self, extra: &[(&'static str, Option<f64>)]) -> Result<Materials, Failure> {
        let given: Vec<(&str, Option<f64>)> = self.given().into_iter().chain(extra.iter().copied()).collect();
        let values = crate::words::together(&given).map_err(Failure::input)?;
        let mut seven = [0.0; 7];
        seven.copy_from_slice(&values[..7]);
        Ok(Materials::from_array(seven))
    }
}

/// A [`ke_friction::ParamError`] of [`Params::from_physical`] as a failure naming the
/// flag: `--density` for β (it is the last of η, R, σ one tunes),
/// `roughness` for the dimensionless results (ψ, θ, ν, ε*).
pub fn physical_failure(e: ke_friction::ParamError, roughness: &str) -> Failure {
    Failure::input(format!("{}: {e}", crate::words::param_flag(e.name, roughness)))
}

/// The help heading the SI inputs are declared under; [`help_headings`]
/// replaces it in each subcommand by one naming the flags they replace
/// there.
const SI_HEADING: &str = "SI inputs";

/// The SI inputs that give ψ, θ, β, ν and ε* ([`Params::from_physical`]):
/// all ten together, in place of the dimensionless flags.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = SI_HEADING)]
pub struct SiArgs {
    #[command(flatten)]
    pub materials: MaterialsArgs,
    /// Standard deviation σ of the surface heights (Sq) ([`bounds::METRES`]).
    #[arg(long, value_name = "M", help = help("Standard deviation σ of the surface heights (Sq)", &bounds::METRES, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub sigma: Option<f64>,
    /// Mean summit radius of curvature R ([`bounds::METRES`]).
    #[arg(long, value_name = "M", help = help("Mean summit radius of curvature R", &bounds::METRES, ""), value_parser = parse_f64, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// Areal density η of summits ([`bounds::DENSITY`]; β = ηRσ: [`bounds::BETA_ADMISSIBLE`]).
    #[arg(long, value_name = "PER_M2", help = help("Areal density η of summits", &bounds::DENSITY, &format!("(β = ηRσ must be {})", bounds::BETA_ADMISSIBLE.range())), value_parser = parse_f64, allow_hyphen_values = true)]
    pub density: Option<f64>,
}

impl SiArgs {
    /// The roughness flags and values.
    pub(crate) fn roughness(&self) -> [(&'static str, Option<f64>); 3] {
        [
            ("--sigma", self.sigma),
            ("--radius", self.radius),
            ("--density", self.density),
        ]
    }

    /// Whether any SI flag is given.
    pub fn any(&self) -> bool {
        self.materials.any() || self.roughness().iter().any(|(_, v)| v.is_some())
    }

    /// The dimensionless parameters of the SI inputs, or a message naming
    /// the missing or unphysical one.
    pub fn params(&self) -> Result<Params, Failure> {
        let materials = self.materials.materials(&self.roughness())?;
        let [sigma, radius, density] = self.roughness().map(|(_, v)| v.unwrap_or_default());
        Params::from_physical(&materials.with_roughness(sigma, radius, density))
            .map_err(|e| physical_failure(e, "SI inputs"))
    }
}

impl DistributionArgs {
    /// The height distribution of `--distribution`, `--skewness`,
    /// `--kurtosis` and `--heights`, by the core's rules
    /// ([`HeightDistribution::from_arguments`]), validated.
    pub fn distribution(&self) -> Result<HeightDistribution, Failure> {
        let heights = self.heights.as_deref().map(crate::heights::read).transpose()?;
        HeightDistribution::from_arguments(self.distribution, self.skewness, self.kurtosis, heights.as_deref()).map_err(
            |e| match (&e, &self.heights) {
                (ke_friction::DistributionError::Value(_), Some(path)) if e.name() == "heights" => {
                    Failure::input(format!("--heights {}: {e}", path.display()))
                }
                _ => Failure::input(format!("{}: {e}", flag_of(e.name()))),
            },
        )
    }

    /// Whether any of the flags is given.
    pub fn any(&self) -> bool {
        self.distribution.is_some() || self.skewness.is_some() || self.kurtosis.is_some() || self.heights.is_some()
    }
}

/// The value parser of a flag taking one of a core set of names
/// ([`Named`]): `--help` lists the names, and any other is refused with
/// the core's message ([`ke_friction::NameError`]: one wording of an
/// unknown name for every front end).
pub fn named<T: Named + Send + Sync>() -> impl TypedValueParser<Value = T> {
    NamedParser(std::marker::PhantomData)
}

/// [`named`]'s parser: [`Named::parse`], with the names as clap's possible
/// values (for `--help` and completion only).
#[derive(Clone, Copy)]
struct NamedParser<T>(std::marker::PhantomData<T>);

impl<T: Named + Send + Sync> TypedValueParser for NamedParser<T> {
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<T, clap::Error> {
        // clap's `try_map` keeps the core's error as the source, which
        // `value_message` (cli/src/main.rs) prints after the flag.
        clap::builder::StringValueParser::new()
            .try_map(|s: String| T::parse(&s))
            .parse_ref(cmd, arg, value)
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        Some(Box::new(T::names().into_iter().map(clap::builder::PossibleValue::new)))
    }
}

/// The model's settings as text (6 significant digits; `--json` has
/// every digit), with the flags' spellings
/// (`psi = 1, theta = 0.003, …, fit = consistent, model = ke`).
pub fn describe(p: &Params) -> String {
    p.describe()
}

/// The flags the SI inputs stand in for, where a subcommand has them.
const DIMENSIONLESS: [&str; 5] = ["psi", "theta", "beta", "nu", "eps_star"];

/// `command` (and its subcommands) with the help headings that depend on
/// its flag set: the SI inputs' heading names the dimensionless flags
/// this subcommand has (`lookup` has no `--beta`, `params` none at all),
/// and the material flags without the roughness ones are headed as
/// materials. Generated, so the help cannot name a flag the subcommand
/// does not take.
pub fn help_headings(mut command: clap::Command) -> clap::Command {
    let names: Vec<String> = command.get_subcommands().map(|c| c.get_name().to_string()).collect();
    for name in names {
        command = command.mut_subcommand(name, help_headings);
    }
    let has = |command: &clap::Command, id: &str| command.get_arguments().any(|a| a.get_id() == id);
    if !has(&command, "e1") {
        return command;
    }
    let (heading, ids): (String, Vec<String>) = if has(&command, "sigma") {
        let replaced: Vec<String> = DIMENSIONLESS
            .iter()
            .filter(|id| has(&command, id))
            .map(|id| flag_of(id))
            .collect();
        let heading = if replaced.is_empty() {
            format!("{SI_HEADING} (all ten together)")
        } else {
            format!("{SI_HEADING} (all ten together, in place of {})", replaced.join(", "))
        };
        let ids = command
            .get_arguments()
            .filter(|a| a.get_help_heading() == Some(SI_HEADING))
            .map(|a| a.get_id().to_string())
            .chain(Materials::FIELDS.iter().map(|id| id.to_string()))
            .collect();
        (heading, ids)
    } else {
        let heading = "Materials (all seven together)".to_string();
        (heading, Materials::FIELDS.iter().map(|id| id.to_string()).collect())
    };
    // In place (`mut_arg` would move each to the end of the help).
    command.mut_args(|a| {
        if ids.iter().any(|id| a.get_id() == id.as_str()) {
            a.help_heading(heading.clone())
        } else {
            a
        }
    })
}
