//! `kefric params`: the dimensionless parameters of SI inputs.

use crate::args::SiArgs;
use crate::output::Failure;
use ke_friction::Shortest;

/// Convert SI quantities (moduli, Poisson's ratios, hardness, roughness,
/// adhesion) to the model's ψ, θ, β, ν and ε*.
///
/// ψ = (2E'/(πKH))·(σ_s/R)^½ (E' the combined modulus, K = 0.454 + 0.41ν₁,
/// σ_s/σ from β), θ = Δγ/(σH), β = ηRσ, ε* = ε/σ.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub si: SiArgs,
    /// Print one JSON object (numbers in shortest round-trip form).
    #[arg(long)]
    pub json: bool,
}

/// Runs `kefric params`.
pub fn run(args: Args) -> Result<(), Failure> {
    if !args.si.any() {
        return Err(Failure::input(
            "--e1: missing: give the ten SI inputs (see kefric params --help)",
        ));
    }
    let p = args.si.params()?;
    if args.json {
        outln!("{}", serde_json::to_string(&p).expect("parameters serialise"))?;
    } else {
        outln!("psi = {}", Shortest(p.psi))?;
        outln!("theta = {}", Shortest(p.theta))?;
        outln!("beta = {}", Shortest(p.constants.beta))?;
        outln!("nu = {}", Shortest(p.constants.nu))?;
        outln!("eps_star = {}", Shortest(p.constants.eps_star))?;
    }
    Ok(())
}
