//! `kefric info`: what a table file holds.

use crate::args::{load_table, print_worst, Failure};
use ke_friction::build::verify::verify;
use ke_friction::num::Shortest;
use ke_friction::num::{json_numbers, json_object, Json};
use ke_friction::Table;
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
    /// Print one JSON object (numbers in shortest round-trip form).
    #[arg(long)]
    pub json: bool,
}

/// Runs `kefric info`.
pub fn run(args: Args) -> Result<(), Failure> {
    // Read once (bounded) and checked; the last four bytes are the CRC-32
    // of the rest.
    let (table, bytes): (std::borrow::Cow<Table>, std::borrow::Cow<[u8]>) = match &args.table {
        None => (load_table(None)?, Table::embedded_bytes().into()),
        Some(path) => {
            let bad = |e: ke_friction::TableError| Failure::input(format!("--table {}: {e}", path.display()));
            let bytes = Table::read_file(path).map_err(bad)?;
            (
                std::borrow::Cow::Owned(Table::from_bytes(&bytes).map_err(bad)?),
                bytes.into(),
            )
        }
    };
    let crc = bytes.len().checked_sub(4).map(|at| &bytes[at..]);
    let checksum = crc.map_or(0, |c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]));
    let name = args
        .table
        .as_ref()
        .map_or("(embedded default table)".to_string(), |p| p.display().to_string());
    let info = table.info();
    let (d, acc, b) = (&info.domain, &info.accuracy, &info.build);
    // The file records the error of μ; that of its slope is measured now
    // (a tenth of a second).
    let slope = verify(&table, info.tolerance, SLOPE_SAMPLES, 1, true, &())
        .map_err(|e| Failure::other(e.to_string()))?
        .slope_max_rel
        .unwrap_or(f64::NAN);
    if args.json {
        let range = |(lo, hi): (f64, f64)| Json::Raw(json_numbers(&[lo, hi]));
        outln!(
            "{}",
            json_object(&[
                ("file", Json::Str(&name)),
                ("bytes", Json::Int(bytes.len() as u64)),
                ("crc32", Json::Raw(format!("\"{checksum:08x}\""))),
                ("format_version", Json::Int(info.format_version.into())),
                ("model", Json::Str(d.constants.kind.name())),
                ("fit", Json::Str(d.constants.fit.name())),
                ("psi", range(d.psi)),
                ("theta", range(d.theta)),
                ("f_star", range(d.f_star)),
                ("beta", Json::Num(d.constants.beta)),
                ("nu", Json::Num(d.constants.nu)),
                ("eps_star", Json::Num(d.constants.eps_star)),
                ("tolerance", Json::Num(info.tolerance)),
                ("max_rel_error", Json::Num(acc.max_rel)),
                ("p99_rel_error", Json::Num(acc.p99_rel)),
                ("accuracy_samples", Json::Int(acc.samples as u64)),
                ("worst", Json::Raw(json_numbers(&acc.worst))),
                ("slope_max_rel_error", Json::Num(slope)),
                ("slope_samples", Json::Int(SLOPE_SAMPLES as u64)),
                (
                    "nodes",
                    Json::Raw(format!("[{},{},{}]", b.nodes[0], b.nodes[1], b.nodes[2])),
                ),
                ("ghosts", Json::Int(b.ghosts as u64)),
                ("precision", Json::Str(info.precision.name())),
                ("generator", Json::Str(&b.generator)),
            ])
        )?;
        return Ok(());
    }
    let r = |(lo, hi): (f64, f64)| format!("[{}, {}]", Shortest(lo), Shortest(hi));
    outln!("table:      {name}")?;
    outln!(
        "file:       {} bytes, format version {}, CRC-32 {checksum:08x}, built by {}",
        bytes.len(),
        info.format_version,
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
