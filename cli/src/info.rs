//! `kefric info`: what a table file holds.

use crate::args::{load_table, print_worst};
use crate::output::Failure;
use ke_friction::build::verify::verify;
use ke_friction::Shortest;
use std::path::PathBuf;

/// Points at which `info` measures the slope's error (as `kefric verify`).
const SLOPE_SAMPLES: usize = 4000;

/// Show what a table holds: its domain, model and constants, tolerance and
/// measured accuracy, nodes, precision, size, format version and checksum.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Table file [default: the embedded default table].
    #[arg(long)]
    pub table: Option<PathBuf>,
    /// Print the table's record as one JSON object (the names Python's Table.info and the NumPy export's metadata use; numbers in shortest round-trip form). The slope's error, measured now, is in the text output only.
    #[arg(long)]
    pub json: bool,
}

/// Runs `kefric info`.
pub fn run(args: Args) -> Result<(), Failure> {
    let table = load_table(args.table.as_deref())?;
    let name = args
        .table
        .as_ref()
        .map_or("(embedded default table)".to_string(), |p| p.display().to_string());
    let info = table.info();
    let (d, acc, b) = (&info.domain, &info.accuracy, &info.build);
    if args.json {
        // The table's record, under the names every front end uses.
        outln!("{}", serde_json::to_string(info).expect("a table's record serialises"))?;
        return Ok(());
    }
    // The file records the error of μ; that of its slope is measured now
    // (a tenth of a second).
    let slope = verify(&table, info.tolerance, SLOPE_SAMPLES, 1, true, &())
        .map_err(|e| Failure::other(e.to_string()))?
        .slope_max_rel
        .unwrap_or(f64::NAN);
    let r = |(lo, hi): (f64, f64)| format!("[{}, {}]", Shortest(lo), Shortest(hi));
    outln!("table:      {name}")?;
    outln!(
        "file:       {} bytes, format version {}, CRC-32 {:08x}, built by {}",
        info.bytes,
        info.format_version,
        info.crc32,
        b.generator
    )?;
    outln!(
        "model:      {}, fit = {}",
        d.constants.kind.name(),
        d.constants.fit.name()
    )?;
    outln!("domain:     psi {}, theta {}, F* {}", r(d.psi), r(d.theta), r(d.f_star))?;
    outln!(
        "constants:  beta = {}, nu = {}, eps_star = {}",
        Shortest(d.constants.beta),
        Shortest(d.constants.nu),
        Shortest(d.constants.eps_star)
    )?;
    outln!("heights:    {}", d.constants.distribution)?;
    outln!(
        "accuracy:   mu max relative error {:.2e} (tolerance {}), 99th percentile {:.2e}, {} points at build",
        acc.max_rel,
        Shortest(info.tolerance),
        acc.p99_rel,
        acc.samples
    )?;
    out!("            ")?;
    print_worst(acc)?;
    outln!(
        "            slope dmu/dF* max relative error {slope:.2e} (measured now at {SLOPE_SAMPLES} points; the file records only mu's)"
    )?;
    outln!(
        "nodes:      {} psi x {} theta x {} F* ({} ghost nodes per end), {} coefficients",
        b.nodes[0],
        b.nodes[1],
        b.nodes[2],
        b.ghosts,
        info.precision.name()
    )?;
    outln!(
        "interpolant: cubic B-spline of ln mu over (ln psi, sqrt theta, ln F*); lookups {}",
        if table.fast_kernel() {
            "use the fast f32 AVX2 kernel on this machine"
        } else {
            "use the portable f64 kernel on this machine"
        }
    )?;
    Ok(())
}
