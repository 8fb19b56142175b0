//! `kefric plot`: the paper's figures 3–6, a μ(F*) curve, a table's error
//! map. PNG or SVG by the output file's extension.

use crate::args::{check_writable, flag_of, load_table, output_dir, parse_f64, Failure, ModelArgs};
use ke_friction::figures::{self, Figure, FigureError, Format};
use ke_friction::LookupError;
use std::path::{Path, PathBuf};

/// Draw the paper's figures, a curve, or a table's error map.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    what: What,
}

#[derive(Debug, clap::Subcommand)]
// Parsed once per run: the size of the curve's flags does not matter.
#[allow(clippy::large_enum_variant)]
enum What {
    /// Fig. 3: Fs*/P* against F* for ψ = 0.5, 1, 2, 4, 8 (θ = 0.003).
    Fig3(Out),
    /// Fig. 4: Q* against F* (log–log) for ψ = 0.5, 1, 2, 4, 8 (θ = 0.003).
    Fig4(Out),
    /// Fig. 5: μ against F* for ψ = 0.5, 1, 2 (θ = 0.003), with the CEB-type model dashed.
    Fig5(Out),
    /// Fig. 6: μ against F* for ψ = 0.5 and 2, θ = 1e-4, 1e-3, 3e-3.
    Fig6(Out),
    /// μ against F* for any parameters; with --table, the lookup overlaid and the relative difference below.
    Curve(CurveArgs),
    /// A heat map of a table's relative error of μ over (ψ, F*) at one θ, against direct integration.
    TableError(TableErrorArgs),
    /// Write fig3.png … fig6.png into a directory.
    All(AllArgs),
}

#[derive(Debug, clap::Args)]
struct Out {
    /// Output file: .png or .svg.
    #[arg(long, value_name = "FILE")]
    out: PathBuf,
}

#[derive(Debug, clap::Args)]
struct CurveArgs {
    #[command(flatten)]
    model: ModelArgs,
    /// Overlay a table's lookup: the embedded default table, or the file PATH.
    #[arg(long, value_name = "PATH", num_args = 0..=1)]
    table: Option<Option<PathBuf>>,
    #[command(flatten)]
    out: Out,
}

#[derive(Debug, clap::Args)]
struct TableErrorArgs {
    /// Table file (default: the embedded default table).
    #[arg(long, value_name = "PATH")]
    table: Option<PathBuf>,
    /// Adhesion parameter θ of the map.
    #[arg(long, value_parser = parse_f64, default_value_t = figures::PAPER_THETA, allow_hyphen_values = true)]
    theta: f64,
    #[command(flatten)]
    out: Out,
}

#[derive(Debug, clap::Args)]
struct AllArgs {
    /// Directory for fig3.png … fig6.png (created, with its parents, if missing).
    #[arg(long, value_name = "DIR")]
    out_dir: PathBuf,
}

/// Cells of the error map along ψ and F*.
const MAP_CELLS: (usize, usize) = (64, 96);

/// Runs `kefric plot`.
pub fn run(args: Args) -> Result<(), Failure> {
    match args.what {
        What::Fig3(o) => figure(Figure::Fig3, &o.out),
        What::Fig4(o) => figure(Figure::Fig4, &o.out),
        What::Fig5(o) => figure(Figure::Fig5, &o.out),
        What::Fig6(o) => figure(Figure::Fig6, &o.out),
        What::Curve(a) => {
            let out = output(&a.out.out)?;
            let model = a.model.model()?;
            let table = a.table.as_ref().map(|path| load_table(path.as_deref())).transpose()?;
            let page = figures::curve_page(&model, table.as_deref()).map_err(failure)?;
            page.save(out).map_err(failure)?;
            wrote(out);
            Ok(())
        }
        What::TableError(a) => {
            let out = output(&a.out.out)?;
            let table = load_table(a.table.as_deref())?;
            let map = figures::table_error(&table, a.theta, MAP_CELLS.0, MAP_CELLS.1).map_err(failure)?;
            map.save(out).map_err(failure)?;
            wrote(out);
            Ok(())
        }
        What::All(a) => {
            output_dir("--out-dir", &a.out_dir)?;
            for path in figures::save_all(&a.out_dir).map_err(failure)? {
                wrote(&path);
            }
            Ok(())
        }
    }
}

fn figure(fig: Figure, out: &Path) -> Result<(), Failure> {
    let out = output(out)?;
    fig.page().and_then(|p| p.save(out)).map_err(failure)?;
    wrote(out);
    Ok(())
}

/// Checks `--out` before any work: a known extension, a writable place.
fn output(path: &Path) -> Result<&Path, Failure> {
    Format::from_path(path).map_err(|e| Failure::input(format!("--out: {e}")))?;
    check_writable("--out", path)?;
    Ok(path)
}

fn wrote(path: &Path) {
    println!("wrote {}", path.display());
}

/// Bad input names its flag (exit 2); a failed drawing is exit 1.
fn failure(e: FigureError) -> Failure {
    match &e {
        FigureError::Format { .. } => Failure::input(format!("--out: {e}")),
        FigureError::Params(p) => Failure::input(format!("{}: {e}", flag_of(p.name))),
        FigureError::Lookup(LookupError::OutOfDomain { name, .. }) => Failure::input(format!("{}: {e}", flag_of(name))),
        FigureError::TableMismatch { .. } => Failure::input(format!("--table: {e}")),
        FigureError::Empty(_) => Failure::input(e),
        _ => Failure::other(e),
    }
}
