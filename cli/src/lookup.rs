//! `kefric lookup`: μ, ∂μ/∂F* and h* from a table, for one point or for
//! CSV rows streamed from stdin.

use crate::args::{flag_of, load_table, parse_f64, DistributionArgs, SiArgs};
use crate::output::Failure;
use ke_friction::Shortest;
use ke_friction::{LookupError, Table};
use std::fmt::Write as _;
use std::io::{BufRead, Read, Write};
use std::path::PathBuf;

/// Look up μ(ψ, θ, F*), ∂μ/∂F* and h* in a table (the embedded default
/// without --table), at one point or, with --csv, at every row of stdin.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Plasticity index ψ, within the table's range (the default table: 0.5 to 8). Required unless --csv or the SI inputs are given.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub psi: Option<f64>,
    /// Adhesion parameter θ, within the table's range (the default table: 0 to 0.01). Required unless --csv or the SI inputs are given.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub theta: Option<f64>,
    /// External force F* = F/(A_n·H), within the table's range (the default table: 1e-5 to 0.1). Required unless --csv.
    #[arg(long, value_parser = parse_f64, allow_hyphen_values = true)]
    pub f_star: Option<f64>,
    /// Table file [default: the embedded default table].
    #[arg(long)]
    pub table: Option<PathBuf>,
    /// Print one JSON object (numbers in shortest round-trip form).
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Read psi,theta,f_star rows from stdin (a header line is optional; lines up to 1 MiB);
    /// write psi,theta,f_star,mu,dmu_df_star,h_star rows to stdout. A bad
    /// row stops the run with its line number (exit 2); the rows before it
    /// are complete.
    #[arg(long, conflicts_with_all = ["psi", "theta", "f_star"])]
    pub csv: bool,
    #[arg(long, help = exact_help())]
    pub exact: bool,
    #[command(flatten)]
    pub si: SiArgs,
    /// The distribution the lookup is for: refused unless it is the table's.
    #[command(flatten)]
    pub distribution: DistributionArgs,
}

/// μ, ∂μ/∂F* and h* at one point.
struct Row {
    mu: f64,
    slope: f64,
    h_star: f64,
}

fn row(table: &Table, exact: bool, psi: f64, theta: f64, f_star: f64) -> Result<Row, LookupError> {
    let (mu, slope) = if exact {
        table.mu_with_slope_portable(psi, theta, f_star)?
    } else {
        table.mu_with_slope(psi, theta, f_star)?
    };
    let h_star = table.h_star(psi, theta, f_star)?;
    Ok(Row { mu, slope, h_star })
}

/// Runs `kefric lookup`.
pub fn run(args: Args) -> Result<(), Failure> {
    let table = load_table(args.table.as_deref())?;
    let table = &*table;
    check_distribution(&args.distribution, table)?;
    if args.csv {
        if args.si.any() {
            return Err(Failure::input(
                "--csv: the rows give psi and theta; the SI inputs do not apply",
            ));
        }
        return csv(table, args.exact);
    }
    let (psi, theta) = point(&args, table)?;
    let f_star = args
        .f_star
        .ok_or_else(|| Failure::input("--f-star: required (or --csv)"))?;
    let r = row(table, args.exact, psi, theta, f_star).map_err(|e| {
        let flag = match e {
            LookupError::OutOfDomain { name, .. } if args.si.any() && name != "f_star" => "SI inputs".into(),
            LookupError::OutOfDomain { name, .. } => flag_of(name),
            _ => "lookup".into(),
        };
        Failure::input(format!("{flag}: {e}"))
    })?;
    if args.json {
        let row = serde_json::json!({
            "psi": psi,
            "theta": theta,
            "f_star": f_star,
            "mu": r.mu,
            "dmu_df_star": r.slope,
            "h_star": r.h_star,
        });
        outln!("{row}")?;
    } else {
        // Text: 6 significant digits (every digit: --json, --csv).
        if args.si.any() {
            outln!("psi = {}, theta = {}", Shortest::sig(psi), Shortest::sig(theta))?;
        }
        outln!("mu = {}", Shortest::sig(r.mu))?;
        outln!("dmu/dF* = {}", Shortest::sig(r.slope))?;
        outln!("h* = {}", Shortest::sig(r.h_star))?;
    }
    let mut warnings = ke_friction::Warnings::new();
    warnings.note(ke_friction::Warning::of_point(f_star, r.h_star, Some(r.mu)));
    crate::output::warn(&warnings);
    Ok(())
}

/// Refuses a distribution other than the table's (the core's
/// [`Table::check_constants`], as for the SI inputs' β, ν, ε*).
fn check_distribution(flags: &DistributionArgs, table: &Table) -> Result<(), Failure> {
    if !flags.any() {
        return Ok(());
    }
    let asked = flags.distribution()?;
    let flag = if flags.heights.is_some() {
        "--heights"
    } else if flags.kurtosis.is_some() {
        "--kurtosis"
    } else if flags.skewness.is_some() {
        "--skewness"
    } else {
        "--distribution"
    };
    let constants = table.domain().constants.clone().distribution(asked);
    table
        .check_constants(&constants)
        .map_err(|e| Failure::input(format!("{flag}: {e}")))
}

/// ψ and θ from the flags, or from the SI inputs (whose β, ν and ε* must
/// be the table's).
fn point(args: &Args, table: &Table) -> Result<(f64, f64), Failure> {
    if !args.si.any() {
        let required = |flag: &str, v: Option<f64>| {
            v.ok_or_else(|| Failure::input(format!("{flag}: required (or --csv, or the SI inputs, see --help)")))
        };
        return Ok((required("--psi", args.psi)?, required("--theta", args.theta)?));
    }
    if let Some(flag) = [("--psi", args.psi), ("--theta", args.theta)]
        .iter()
        .find_map(|(f, v)| v.map(|_| *f))
    {
        return Err(Failure::input(format!(
            "{flag}: give either --psi and --theta or the SI inputs, not both"
        )));
    }
    let p = args.si.params()?;
    // The SI inputs give β, ν, ε*; the rest is the table's (the
    // distribution flags are checked by check_distribution).
    let held = &table.domain().constants;
    let constants = held
        .clone()
        .beta(p.constants.beta)
        .nu(p.constants.nu)
        .eps_star(p.constants.eps_star);
    table.check_constants(&constants).map_err(|e| {
        let flag = match e.name {
            "beta" => "--density",
            "nu" => "--nu1",
            _ => "--epsilon",
        };
        Failure::input(format!("{flag}: the SI inputs give {e}"))
    })?;
    Ok((p.psi, p.theta))
}

/// `--exact`'s help, quoting the library's bound.
fn exact_help() -> String {
    format!(
        "Use the portable f64 kernel (the table's exact interpolant) instead of the fast f32 one (which may differ by up to {} relative)",
        ke_friction::FAST_KERNEL_MAX_REL
    )
}

/// The longest CSV line `lookup --csv` reads (1 MiB), end of line included.
pub const CSV_LINE_MAX: usize = 1 << 20;

/// Streams CSV rows from stdin to stdout.
fn csv(table: &Table, exact: bool) -> Result<(), Failure> {
    let stdin = std::io::stdin().lock();
    let stdout = std::io::stdout().lock();
    let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout);
    let write_failed = |e: std::io::Error| Failure::output("stdout", &e);
    out.write_all(b"psi,theta,f_star,mu,dmu_df_star,h_star\n")
        .map_err(write_failed)?;
    let mut warnings = ke_friction::Warnings::new();
    let mut line = String::new();
    let mut text = String::new();
    let mut input = stdin;
    let mut number = 0usize;
    let result = loop {
        line.clear();
        // At most CSV_LINE_MAX bytes a line: a line without end is an
        // error, not an unbounded allocation.
        match (&mut input).take(CSV_LINE_MAX as u64 + 1).read_line(&mut line) {
            Ok(0) => break Ok(()),
            Ok(n) if n > CSV_LINE_MAX => {
                break Err(Failure::input(format!(
                    "--csv: line {}: longer than {CSV_LINE_MAX} bytes (a line holds psi,theta,f_star)",
                    number + 1
                )))
            }
            Ok(_) => {}
            Err(e) => {
                break Err(Failure::input(format!(
                    "--csv: line {}: cannot read stdin: {e}",
                    number + 1
                )))
            }
        }
        number += 1;
        let fields: Vec<&str> = line.trim_end_matches(['\n', '\r']).split(',').map(str::trim).collect();
        if fields.len() == 1 && fields[0].is_empty() {
            continue;
        }
        if number == 1 && fields == ["psi", "theta", "f_star"] {
            continue;
        }
        let bad = |why: String| Failure::input(format!("--csv: line {number}: {why}"));
        let [psi, theta, f_star] = match fields.as_slice() {
            [a, b, c] => {
                let num = |name: &str, t: &str| parse_f64(t).map_err(|e| bad(format!("{name}: {e}")));
                match (num("psi", a), num("theta", b), num("f_star", c)) {
                    (Ok(a), Ok(b), Ok(c)) => [a, b, c],
                    (Err(e), _, _) | (_, Err(e), _) | (_, _, Err(e)) => break Err(e),
                }
            }
            _ => {
                break Err(bad(format!(
                    "expected 3 fields psi,theta,f_star, found {}",
                    fields.len()
                )))
            }
        };
        let r = match row(table, exact, psi, theta, f_star) {
            Ok(r) => r,
            Err(e) => break Err(bad(e.to_string())),
        };
        warnings.note(ke_friction::Warning::of_point(f_star, r.h_star, Some(r.mu)));
        text.clear();
        let _ = writeln!(
            text,
            "{},{},{},{},{},{}",
            Shortest(psi),
            Shortest(theta),
            Shortest(f_star),
            Shortest(r.mu),
            Shortest(r.slope),
            Shortest(r.h_star)
        );
        if let Err(e) = out.write_all(text.as_bytes()) {
            break Err(write_failed(e));
        }
    };
    // The rows before a bad one are complete lines; flush them either way.
    out.flush().map_err(write_failed)?;
    crate::output::warn(&warnings);
    result
}
