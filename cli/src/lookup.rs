//! `kefric lookup`: μ and ∂μ/∂F* from a table.

use crate::args::{flag_of, full, load_table, parse_f64, Failure};
use ke_friction::LookupError;
use std::path::PathBuf;

/// Look up μ(ψ, θ, F*) and ∂μ/∂F* in a table (the embedded default without --table).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Plasticity index ψ.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub psi: f64,
    /// Adhesion parameter θ.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub theta: f64,
    /// External force F*.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub f_star: f64,
    /// Table file.
    #[arg(long)]
    pub table: Option<PathBuf>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// Runs `kefric lookup`.
pub fn run(args: Args) -> Result<(), Failure> {
    let table = load_table(args.table.as_deref())?;
    let table = &*table;
    let (mu, slope) = table.mu_with_slope(args.psi, args.theta, args.f_star).map_err(|e| {
        let flag = match e {
            LookupError::OutOfDomain { name, .. } => flag_of(name),
            _ => "lookup".into(),
        };
        Failure::input(format!("{flag}: {e}"))
    })?;
    if args.json {
        println!(
            "{{\"psi\":{},\"theta\":{},\"f_star\":{},\"mu\":{},\"dmu_df_star\":{}}}",
            full(args.psi),
            full(args.theta),
            full(args.f_star),
            full(mu),
            full(slope)
        );
    } else {
        println!("mu = {mu:.8e}");
        println!("dmu/dF* = {slope:.8e}");
    }
    Ok(())
}
