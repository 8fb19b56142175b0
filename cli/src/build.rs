//! `kefric build`: integrate, tabulate, verify, write atomically.

use crate::args::{check_writable, fields, flag_of, number, parse_f64, print_worst, whole, Bar, ConstantsArgs};
use crate::output::Failure;
use ke_friction::bounds;
use ke_friction::build::{build, threads, BuildError, BuildOptions, Precision};
use ke_friction::Shortest;
use std::path::PathBuf;
use std::time::Instant;

/// Build a table of μ(ψ, θ, F*) by direct integration and verify it.
///
/// The defaults build the default table, tables/default.kft (the table the
/// library embeds); any other build needs --out.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Output file, written to a temporary name beside it and then renamed
    /// over it. A symlink is followed (its target is replaced, the link
    /// stays); an existing device, pipe or directory is refused. Required
    /// unless every other option is at its default (which rebuilds
    /// tables/default.kft).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Range of ψ, LO:HI ([`bounds::GHOST_PSI`]).
    #[arg(long, value_name = "LO:HI", help = format!("Range of ψ, LO:HI, {}.", bounds::GHOST_PSI.range()), default_value_t = range_text(defaults().psi), allow_hyphen_values = true)]
    pub psi: String,
    /// Range of θ, LO:HI ([`bounds::GHOST_THETA`]).
    #[arg(long, value_name = "LO:HI", help = format!("Range of θ, LO:HI, {} and {}.", bounds::THETA_NON_NEGATIVE.range(), bounds::GHOST_THETA.range()), default_value_t = range_text(defaults().theta), allow_hyphen_values = true)]
    pub theta: String,
    /// Range of F*, LO:HI ([`bounds::F_STAR_END`], [`bounds::GHOST_F_STAR`]).
    #[arg(long, value_name = "LO:HI", help = format!("Range of F*, LO:HI, {}, HI {}, {}.", bounds::F_STAR.range(), bounds::F_STAR_END.range(), bounds::GHOST_F_STAR.range()), default_value_t = range_text(defaults().f_star), allow_hyphen_values = true)]
    pub f_star: String,
    /// Nodes across the ψ, θ, F* ranges, NP,NT,NF ([`bounds::NODES`]).
    #[arg(long, value_name = "NP,NT,NF", help = format!("Nodes across the ψ, θ, F* ranges, NP,NT,NF, each {}.", bounds::NODES.range()), default_value_t = nodes_text(defaults().nodes), allow_hyphen_values = true)]
    pub nodes: String,
    /// Ghost nodes beyond each end of the ψ and F* ranges ([`bounds::GHOSTS`]).
    #[arg(long, help = format!("Ghost nodes beyond each end of the ψ and F* ranges (and above θ's), {}.", bounds::GHOSTS.range()), default_value_t = defaults().ghosts, allow_hyphen_values = true)]
    pub ghosts: usize,
    /// Integration grid in h*, LO:HI:COUNT ([`bounds::H_STAR`], [`bounds::H_NODES`]).
    #[arg(long, value_name = "LO:HI:COUNT", help = format!("Integration grid in h*, LO:HI:COUNT (LO and HI {}; COUNT {}).", bounds::H_STAR.range(), bounds::H_NODES.range()), default_value_t = h_text(defaults().h_star), allow_hyphen_values = true)]
    pub h_star: String,
    #[command(flatten)]
    pub constants: ConstantsArgs,
    /// Stored precision of the coefficients.
    #[arg(long, value_enum, default_value_t = PrecisionArg::F32)]
    pub precision: PrecisionArg,
    /// Maximum relative error of μ the table must meet ([`bounds::TOLERANCE`]).
    #[arg(long, help = format!("Maximum relative error of μ the table must meet, {}; the build fails otherwise.", bounds::TOLERANCE.range()), value_parser = parse_f64, default_value_t = defaults().tolerance, allow_hyphen_values = true)]
    pub tolerance: f64,
    /// Points checked against direct integration ([`bounds::SAMPLES`]).
    #[arg(long, help = format!("Points checked against direct integration (half random, half cell centres), {}.", bounds::SAMPLES.range()), default_value_t = defaults().samples, allow_hyphen_values = true)]
    pub samples: usize,
    /// Seed of those points.
    #[arg(long, default_value_t = defaults().seed, allow_hyphen_values = true)]
    pub seed: u64,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// Where the default build writes (the table the library embeds).
const DEFAULT_OUT: &str = "tables/default.kft";

fn defaults() -> BuildOptions {
    BuildOptions::default()
}

fn range_text((lo, hi): (f64, f64)) -> String {
    format!("{}:{}", Shortest(lo), Shortest(hi))
}

fn nodes_text([a, b, c]: [usize; 3]) -> String {
    format!("{a},{b},{c}")
}

fn h_text((lo, hi, n): (f64, f64, usize)) -> String {
    format!("{}:{}:{n}", Shortest(lo), Shortest(hi))
}

/// `--precision` values.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum PrecisionArg {
    /// 4 bytes a coefficient.
    F32,
    /// 8 bytes a coefficient.
    F64,
}

/// Parses `LO:HI`.
fn pair(flag: &str, text: &str) -> Result<(f64, f64), Failure> {
    let [lo, hi] = fields(flag, text, ':', "LO:HI")?;
    Ok((number(flag, lo)?, number(flag, hi)?))
}

impl Args {
    /// The build options these flags ask for.
    pub fn options(&self) -> Result<BuildOptions, Failure> {
        let [np, nt, nf] = fields("--nodes", &self.nodes, ',', "NP,NT,NF (three whole numbers)")?;
        let [h_lo, h_hi, h_n] = fields("--h-star", &self.h_star, ':', "LO:HI:COUNT")?;
        let o = BuildOptions {
            psi: pair("--psi", &self.psi)?,
            theta: pair("--theta", &self.theta)?,
            f_star: pair("--f-star", &self.f_star)?,
            nodes: [whole("--nodes", np)?, whole("--nodes", nt)?, whole("--nodes", nf)?],
            ghosts: self.ghosts,
            h_star: (
                number("--h-star", h_lo)?,
                number("--h-star", h_hi)?,
                whole("--h-star", h_n)?,
            ),
            constants: self.constants.constants()?,
            precision: match self.precision {
                PrecisionArg::F32 => Precision::F32,
                PrecisionArg::F64 => Precision::F64,
            },
            tolerance: self.tolerance,
            samples: self.samples,
            seed: self.seed,
        };
        o.validate().map_err(|e| {
            let name = match &e {
                BuildError::Option(p) => p.name,
                BuildError::Range { name, .. } => name,
                _ => "build",
            };
            Failure::input(format!("{}: {e}", option_flag(name)))
        })?;
        Ok(o)
    }

    /// Where to write: `--out`, or the default table's path for the default
    /// build only (so no other build can replace the embedded table).
    fn out(&self, options: &BuildOptions) -> Result<PathBuf, Failure> {
        match &self.out {
            Some(out) => Ok(out.clone()),
            None if *options == defaults() => Ok(PathBuf::from(DEFAULT_OUT)),
            None => Err(Failure::input(format!(
                "--out: required: these options differ from the default build, which alone writes {DEFAULT_OUT} (the table the library embeds); pass --out FILE"
            ))),
        }
    }
}

/// The flag behind a build option's name.
fn option_flag(name: &str) -> String {
    match name {
        "psi_nodes" | "theta_nodes" | "f_nodes" => "--nodes".into(),
        "h_nodes" => "--h-star".into(),
        "grid_nodes" | "grid_points" => "--nodes".into(),
        other => flag_of(other),
    }
}

/// Runs `kefric build`.
pub fn run(args: Args) -> Result<(), Failure> {
    let options = args.options()?;
    let out = args.out(&options)?;
    check_writable("--out", &out)?;
    let started = Instant::now();
    let bar = Bar::new(args.quiet);
    let built = build(&options, &bar).map_err(|e| match e {
        // The options put a ghost node where the model has no μ.
        BuildError::Ghost { .. } => Failure::input(format!("--f-star/--nodes: {e}")),
        _ => Failure::of("build", e),
    })?;
    bar.done();
    built
        .write(&out)
        .map_err(|e| Failure::output(format_args!("--out {}", out.display()), &e))?;
    let secs = started.elapsed().as_secs_f64();
    let t = &built.table;
    let info = t.info();
    let acc = &info.accuracy;
    let axes = t.axes();
    outln!("wrote {} ({} bytes)", out.display(), built.bytes.len())?;
    let h_nodes = options.h_star.2;
    outln!(
        "F*(h*) guess grid: {} psi x {} theta x {h_nodes} h* = {} force evaluations",
        axes[0].nodes,
        axes[1].nodes,
        axes[0].nodes * axes[1].nodes * h_nodes
    )?;
    outln!(
        "lookup grid: {} psi x {} theta x {} F* nodes ({} ghost nodes per end on psi and F*), {} coefficients",
        axes[0].nodes,
        axes[1].nodes,
        axes[2].nodes,
        options.ghosts,
        options.precision.name()
    )?;
    outln!(
        "accuracy of mu vs direct integration ({} points): max relative error {:.3e} (tolerance {}), 99th percentile {:.3e}",
        acc.samples,
        acc.max_rel,
        Shortest(info.tolerance),
        acc.p99_rel
    )?;
    print_worst(acc)?;
    outln!("build time: {secs:.1} s on {} threads", threads())?;
    Ok(())
}
