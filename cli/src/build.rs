//! `kefric build`: integrate, tabulate, verify, write atomically.

use crate::args::{
    check_writable, fields, flag_of, number, parse_f64, print_worst, whole, Bar, Failure, FitArg, ModelKindArg,
};
use ke_friction::build::{build, threads, BuildOptions, Precision};
use ke_friction::io::write_atomic;
use std::path::PathBuf;
use std::time::Instant;

/// Build a table of μ(ψ, θ, F*) by direct integration and verify it.
///
/// The defaults build the default table (tables/default.kft).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Output file (written to a temporary name, then renamed).
    #[arg(long, default_value = "tables/default.kft")]
    pub out: PathBuf,
    /// Range of ψ, LO:HI.
    #[arg(long, value_name = "LO:HI", default_value = "0.5:8", allow_hyphen_values = true)]
    pub psi: String,
    /// Range of θ, LO:HI.
    #[arg(long, value_name = "LO:HI", default_value = "0:0.01", allow_hyphen_values = true)]
    pub theta: String,
    /// Range of F*, LO:HI.
    #[arg(long, value_name = "LO:HI", default_value = "1e-5:0.1", allow_hyphen_values = true)]
    pub f_star: String,
    /// Nodes across the ψ, θ, F* ranges, NP,NT,NF.
    #[arg(long, value_name = "NP,NT,NF", allow_hyphen_values = true)]
    pub nodes: Option<String>,
    /// Ghost nodes beyond each end of the ψ and F* ranges.
    #[arg(long, allow_hyphen_values = true)]
    pub ghosts: Option<usize>,
    /// Integration grid in h*, LO:HI:COUNT.
    #[arg(long, value_name = "LO:HI:COUNT", allow_hyphen_values = true)]
    pub h_star: Option<String>,
    /// Roughness parameter β.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub beta: Option<f64>,
    /// Poisson's ratio ν.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub nu: Option<f64>,
    /// Intermolecular distance ε*.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub eps_star: Option<f64>,
    /// Friction row.
    #[arg(long, value_enum, default_value_t = FitArg::Consistent)]
    pub fit: FitArg,
    /// Model.
    #[arg(long, value_enum, default_value_t = ModelKindArg::Ke)]
    pub model: ModelKindArg,
    /// Stored precision of the coefficients.
    #[arg(long, value_enum, default_value_t = PrecisionArg::F32)]
    pub precision: PrecisionArg,
    /// Maximum relative error of μ the table must meet.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Points checked against direct integration.
    #[arg(long, allow_hyphen_values = true)]
    pub samples: Option<usize>,
    /// Seed of those points.
    #[arg(long, allow_hyphen_values = true)]
    pub seed: Option<u64>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
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
        let mut o = BuildOptions {
            psi: pair("--psi", &self.psi)?,
            theta: pair("--theta", &self.theta)?,
            f_star: pair("--f-star", &self.f_star)?,
            ..BuildOptions::default()
        };
        if let Some(nodes) = &self.nodes {
            let [np, nt, nf] = fields("--nodes", nodes, ',', "NP,NT,NF (three whole numbers)")?;
            o.nodes = [whole("--nodes", np)?, whole("--nodes", nt)?, whole("--nodes", nf)?];
        }
        if let Some(h) = &self.h_star {
            let [lo, hi, n] = fields("--h-star", h, ':', "LO:HI:COUNT")?;
            o.h_star = (number("--h-star", lo)?, number("--h-star", hi)?, whole("--h-star", n)?);
        }
        o.ghosts = self.ghosts.unwrap_or(o.ghosts);
        o.beta = self.beta.unwrap_or(o.beta);
        o.nu = self.nu.unwrap_or(o.nu);
        o.eps_star = self.eps_star.unwrap_or(o.eps_star);
        o.fit = self.fit.into();
        o.kind = self.model.into();
        o.precision = match self.precision {
            PrecisionArg::F32 => Precision::F32,
            PrecisionArg::F64 => Precision::F64,
        };
        o.tolerance = self.tolerance.unwrap_or(o.tolerance);
        o.samples = self.samples.unwrap_or(o.samples);
        o.seed = self.seed.unwrap_or(o.seed);
        o.validate()
            .map_err(|e| Failure::input(format!("{}: {e}", option_flag(e.name))))?;
        Ok(o)
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
    check_writable("--out", &args.out)?;
    let started = Instant::now();
    let bar = Bar::new(args.quiet);
    let built = build(&options, &bar).map_err(|e| Failure::other(e.to_string()))?;
    bar.done();
    write_atomic(&args.out, &built.bytes)
        .map_err(|e| Failure::input(format!("--out: cannot write {}: {e}", args.out.display())))?;
    let secs = started.elapsed().as_secs_f64();
    let t = &built.table;
    let info = t.info();
    let acc = &info.accuracy;
    let axes = t.axes();
    println!("wrote {} ({} bytes)", args.out.display(), built.bytes.len());
    let h_nodes = options.h_star.2;
    println!(
        "F*(h*) guess grid: {} psi x {} theta x {h_nodes} h* = {} force evaluations",
        axes[0].nodes,
        axes[1].nodes,
        axes[0].nodes * axes[1].nodes * h_nodes
    );
    println!(
        "lookup grid: {} psi x {} theta x {} F* nodes ({} ghost nodes per end on psi and F*), {:?} coefficients",
        axes[0].nodes, axes[1].nodes, axes[2].nodes, options.ghosts, options.precision
    );
    println!(
        "accuracy of mu vs direct integration ({} points): max relative error {:.3e} (tolerance {:.1e}), 99th percentile {:.3e}",
        acc.samples, acc.max_rel, info.tolerance, acc.p99_rel
    );
    print_worst(acc);
    println!("build time: {secs:.1} s on {} threads", threads());
    Ok(())
}
