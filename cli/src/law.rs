//! `kefric law`: a friction law's solver-ready table, `pressure,mu,dmu_dp`
//! as CSV at log-spaced pressures ([`ke_friction::LawTable`]).

use crate::args::{describe, fields, number, whole};
use crate::model_args::ModelArgs;
use crate::output::Failure;
use ke_friction::{FrictionLaw, FrictionLawError, LawTable, OutOfRange, Shortest, LAW_TABLE_TOLERANCE};

/// Write μ(p) and dμ/dp of a friction law as CSV, for a simulator.
///
/// Rows `pressure,mu,dmu_dp` (Pa, 1, 1/Pa) at log-spaced contact
/// pressures, F* = p/H, after a header of `#` lines: the inputs, the units,
/// the version and the measured worst relative error of linear
/// interpolation between rows (what MOOSE's PiecewiseLinear, LS-DYNA
/// curves and COMSOL interpolation functions do). The model's inputs are
/// those of `kefric eval` (ψ and θ with `--hardness`, or the SI materials
/// and roughness, or `--surface FILE` with the materials).
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub model: ModelArgs,
    /// The contact pressures, Pa: START:STOP (the rows chosen to meet --tolerance) or START:STOP:COUNT (COUNT rows, as --rows).
    #[arg(long, value_name = "START:STOP[:COUNT]")]
    pub pressure: String,
    /// The number of rows (2 to 1000000) [default: the fewest that meet --tolerance].
    #[arg(long, value_name = "N")]
    pub rows: Option<String>,
    /// The worst relative error of linear interpolation between rows, in [1e-6, 0.5] [default: 1e-3]: the rows are the fewest that meet it (with --rows or COUNT, a warning says when they do not).
    #[arg(long, value_name = "T", value_parser = crate::args::parse_f64, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
}

/// The pressure range and the rows asked for (`--pressure`'s COUNT or
/// `--rows`).
fn pressures(args: &Args) -> Result<(f64, f64, Option<usize>), Failure> {
    let flag = "--pressure";
    let form = "START:STOP or START:STOP:COUNT (pressures in Pa)";
    let (lo, hi, count) = match args.pressure.split(':').count() {
        3 => {
            let [a, b, n] = fields::<3>(flag, &args.pressure, ':', form)?;
            (a, b, Some(whole(flag, n)?))
        }
        _ => {
            let [a, b] = fields::<2>(flag, &args.pressure, ':', form)?;
            (a, b, None)
        }
    };
    let (lo, hi) = (number(flag, lo)?, number(flag, hi)?);
    if !(lo > 0.0 && lo < hi) {
        return Err(Failure::input(format!(
            "{flag}: [{}, {}] Pa is out of range: START and STOP must be > 0 with START < STOP",
            Shortest(lo),
            Shortest(hi)
        )));
    }
    let rows = match (&args.rows, count) {
        (Some(r), Some(n)) => {
            let r = whole("--rows", r)?;
            if r != n {
                return Err(Failure::input(format!(
                    "--rows: {r} differs from --pressure's COUNT {n}: give one of them"
                )));
            }
            Some(r)
        }
        (Some(r), None) => Some(whole("--rows", r)?),
        (None, n) => n,
    };
    Ok((lo, hi, rows))
}

/// The law's failure, naming the flag: the hardness, the pressures, or the
/// model input.
fn law_failure(e: FrictionLawError) -> Failure {
    let flag = match &e {
        FrictionLawError::Param(p) => crate::args::flag_of(p.name),
        _ => "--pressure".to_string(),
    };
    Failure::of(flag, e)
}

/// Runs `kefric law`.
pub fn run(args: Args) -> Result<(), Failure> {
    let (lo, hi, rows) = pressures(&args)?;
    let hardness =
        args.model.si.materials.hardness.ok_or_else(|| {
            Failure::input("--hardness: required: the hardness H of the softer material, Pa (F* = p/H)")
        })?;
    // With ψ and θ, --hardness is the law's own input, not one of the SI
    // materials (which go together).
    let mut model = args.model.clone();
    if model.psi.is_some() || model.theta.is_some() {
        model.si.materials.hardness = None;
    }
    // The model's inputs are checked (and named by their flags) first; the
    // surface read once (its warnings printed once).
    let (checked, source) = model.model_and_source()?;
    let params = checked.params().clone();
    let law = FrictionLaw::new(params, hardness, Some((lo, hi)), OutOfRange::Error).map_err(law_failure)?;
    let tolerance = args.tolerance.unwrap_or(LAW_TABLE_TOLERANCE);
    let table = match rows {
        Some(n) => LawTable::with_rows(&law, lo, hi, n).map_err(|e| Failure::of("--rows", e))?,
        None => LawTable::for_tolerance(&law, lo, hi, tolerance).map_err(|e| Failure::of("--tolerance", e))?,
    };

    outln!(
        "# ke-friction {} (kefric law): the Kogut-Etsion static friction coefficient mu of the contact pressure p, at F* = p/H",
        env!("CARGO_PKG_VERSION")
    )?;
    outln!("# {}", describe(law.params()))?;
    if let Some(source) = &source {
        outln!("# {source}")?;
    }
    outln!(
        "# hardness H = {} Pa; pressure from {} to {} Pa, {} rows, log-spaced",
        Shortest(hardness),
        Shortest(lo),
        Shortest(hi),
        table.rows.len()
    )?;
    outln!("# units: pressure Pa, mu 1, dmu_dp 1/Pa")?;
    outln!(
        "# worst relative error of linear interpolation in p between rows: {} (measured at {} points inside every interval, the midpoint among them{}); the law is within {} of the model",
        Shortest::rounded(table.interpolation_error),
        ke_friction::INTERIOR_POINTS,
        if rows.is_none() {
            format!("; rows chosen for a tolerance of {}", Shortest(tolerance))
        } else {
            String::new()
        },
        Shortest::rounded(law.max_error())
    )?;
    outln!("pressure,mu,dmu_dp")?;
    for r in &table.rows {
        outln!("{},{},{}", Shortest(r.pressure), Shortest(r.mu), Shortest(r.dmu_dp))?;
    }
    if rows.is_some() && table.interpolation_error > tolerance {
        errln!(
            "warning: linear interpolation between these {} rows is off by up to {} (relative), more than {}: leave out the count to get the fewest rows that meet it",
            table.rows.len(),
            Shortest::rounded(table.interpolation_error),
            Shortest(tolerance)
        );
    }
    Ok(())
}
