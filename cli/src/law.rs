//! `kefric law`: a friction law's solver-ready table at log-spaced
//! pressures ([`ke_friction::LawTable`]), as CSV or in a solver's own input
//! syntax ([`ke_friction::LawFormat`]).

use crate::args::{describe, fields, named, number, whole};
use crate::model_args::ModelArgs;
use crate::output::Failure;
use ke_friction::bound::help;
use ke_friction::bounds;
use ke_friction::{
    law_notes, FrictionLaw, FrictionLawError, LawFormat, LawTable, OutOfRange, Shortest, StressUnit,
    LAW_TABLE_TOLERANCE,
};

/// Write μ(p) and dμ/dp of a friction law for a simulator: CSV or a
/// solver's input syntax.
///
/// Rows at log-spaced contact pressures, F* = p/H: `--format csv` writes
/// `pressure_Pa,mu,dmu_dp_per_Pa` and the rows only (NumPy's and pandas'
/// defaults read it) and the notes as `#` lines on stderr; `abaqus`
/// (`*FRICTION`), `ls-dyna` (`*DEFINE_TABLE` for FS = -2), `moose`
/// (`PiecewiseLinear`, `axis = x`) and `comsol` (an interpolation-function
/// file) carry the notes in their comment form: the inputs, the units, the
/// version and the measured worst relative error of linear interpolation
/// between rows (what every one of these solvers does between rows). The
/// model's inputs are those of `kefric eval` (ψ and θ with `--hardness`,
/// or the SI materials and roughness, or `--surface FILE` with the
/// materials).
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub model: ModelArgs,
    /// The contact pressures, Pa: START:STOP (the rows chosen to meet --tolerance) or START:STOP:COUNT (COUNT rows, as --rows).
    #[arg(long, value_name = "START:STOP[:COUNT]")]
    pub pressure: String,
    /// The number of rows ([`bounds::LAW_ROWS`]) [default: the fewest that meet --tolerance].
    #[arg(long, value_name = "N", help = help("The number of rows", &bounds::LAW_ROWS, "[default: the fewest that meet --tolerance]"))]
    pub rows: Option<String>,
    /// The worst relative error of linear interpolation between rows ([`bounds::LAW_TOLERANCE`]).
    #[arg(long, value_name = "T", help = help("The worst relative error of linear interpolation between rows", &bounds::LAW_TOLERANCE, "[default: 1e-3]: the rows are the fewest that meet it (with --rows or COUNT, a warning says when they do not)"), value_parser = crate::args::parse_f64, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// The syntax: csv, abaqus (*FRICTION), ls-dyna (*DEFINE_TABLE for *CONTACT FS = -2), moose (PiecewiseLinear), comsol (interpolation-function file).
    #[arg(long, value_parser = named::<LawFormat>(), default_value_t = LawFormat::Csv)]
    pub format: LawFormat,
    /// The unit the pressures are written in (dmu_dp in its inverse): the solver model's stress unit (Pa, MPa, psi); --pressure and --hardness stay in Pa.
    #[arg(long, value_parser = named::<StressUnit>(), default_value_t = StressUnit::Pa)]
    pub stress_unit: StressUnit,
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

    let mut inputs = vec![describe(law.params())];
    inputs.extend(source.map(|s| s.to_string()));
    let notes = law_notes(
        &law,
        &table,
        args.stress_unit,
        rows.is_none().then_some(tolerance),
        &inputs,
    );
    if args.format == LawFormat::Csv {
        // CSV holds the names and the rows only (so that NumPy's and
        // pandas' defaults read it): its notes go to stderr.
        for n in &notes {
            errln!("# {n}");
        }
    }
    out!("{}", table.to_format(args.format, args.stress_unit, &notes))?;
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
