//! `kefric verify`: re-measure a table against direct integration.

use crate::args::{load_table, print_worst, Bar};
use crate::output::Failure;
use ke_friction::bound::help;
use ke_friction::bounds;
use ke_friction::build::verify::{check_samples, verify};
use ke_friction::Shortest;
use std::path::PathBuf;

/// Check a table against direct integration; exit 1 if it misses its
/// recorded tolerance.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Table file [default: the embedded default table].
    #[arg(long)]
    pub table: Option<PathBuf>,
    /// Points to check (half random, half cell centres), [`bounds::SAMPLES`].
    #[arg(long, default_value_t = 4000, allow_hyphen_values = true, help = help("Points to check (half random, half cell centres)", &bounds::SAMPLES, ""))]
    pub samples: usize,
    /// Seed of the points (the default differs from the build's 2004, so new points are checked).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    pub seed: u64,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// Runs `kefric verify`.
pub fn run(args: Args) -> Result<(), Failure> {
    check_samples(args.samples).map_err(|e| Failure::input(format!("--samples: {e}")))?;
    let table = load_table(args.table.as_deref())?;
    let info = table.info();
    let bar = Bar::new(args.quiet);
    let checked =
        verify(&table, info.tolerance, args.samples, args.seed, true, &bar).map_err(|e| Failure::of("verify", e))?;
    bar.done();
    let (recorded, acc) = (&info.accuracy, &checked.accuracy);
    outln!(
        "recorded at build: max relative error {:.3e}, 99th percentile {:.3e} ({} points)",
        recorded.max_rel,
        recorded.p99_rel,
        recorded.samples
    )?;
    outln!(
        "measured now:      max relative error {:.3e}, 99th percentile {:.3e} ({} points, seed {})",
        acc.max_rel,
        acc.p99_rel,
        acc.samples,
        args.seed
    )?;
    print_worst(acc)?;
    if let Some(slope) = checked.slope_max_rel {
        outln!("slope dmu/dF*:     max relative error {slope:.3e} (same points; reported, not checked)")?;
    }
    // The figures above are the exact (f64) interpolant's; where this
    // machine runs the f32 kernel, its rounding adds to them.
    if table.fast_kernel() {
        outln!(
            "fast f32 kernel:   max relative deviation from the exact interpolant {:.3e} (same points)",
            checked.kernel_deviation
        )?;
    }
    if checked.passes() {
        outln!("ok: within the table's tolerance {}", Shortest(checked.tolerance))?;
        Ok(())
    } else {
        Err(Failure::other(format!(
            "the table misses its tolerance: max relative error {:.3e} > {}",
            checked.max_rel(),
            Shortest(checked.tolerance)
        )))
    }
}
