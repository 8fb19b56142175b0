//! `kefric export`: a table's values and its integration grid as NumPy arrays.

use crate::args::{check_writable, load_table, output_dir, Bar};
use crate::output::Failure;
use ke_friction::build::BuildError;
use ke_friction::export::{arrays, texts, write_npy_dir, write_npz};
use std::path::PathBuf;
use std::time::Instant;

/// Export a table to NumPy: its nodes (`psi`, `theta`, `f_star`), `mu` and
/// `h_star` there, the build's integration grid (`grid_*`, recomputed), the
/// model constants (`beta`, `nu`, `eps_star`), the table's own interpolant
/// (`spline_ln_mu`, `knots_*`), `metadata` (the table's record, as `kefric info --json` prints it) and `interpolant` (how to evaluate it), both UTF-8 JSON bytes:
/// `json.loads(z["metadata"].tobytes())`).
#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("output").required(true).args(["npz", "npy"])))]
pub struct Args {
    /// Table file (default: the embedded default table).
    #[arg(long)]
    pub table: Option<PathBuf>,
    /// Write one .npz file (uncompressed, like numpy.savez), atomically. A
    /// symlink is followed (its target is replaced, the link stays); an
    /// existing device, pipe or directory is refused.
    #[arg(long, value_name = "FILE")]
    pub npz: Option<PathBuf>,
    /// Write one NAME.npy per array into this directory (created, with its
    /// parents, if missing), all or nothing: the files are written into a
    /// temporary directory beside it and moved in only when all are.
    #[arg(long, value_name = "DIR")]
    pub npy: Option<PathBuf>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// Runs `kefric export`.
pub fn run(args: Args) -> Result<(), Failure> {
    let (flag, path, want_dir) = match (&args.npz, &args.npy) {
        (Some(p), None) => ("--npz", p, false),
        (None, Some(p)) => ("--npy", p, true),
        _ => unreachable!("clap requires exactly one of --npz and --npy"),
    };
    let table = load_table(args.table.as_deref())?;
    let table = &*table;
    if want_dir {
        // The directory itself appears only when every file is written.
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            output_dir(flag, parent)?;
        }
        if path.file_name().is_none() || (path.exists() && !path.is_dir()) {
            return Err(Failure::input(format!(
                "{flag}: {} is not a directory name",
                path.display()
            )));
        }
    } else {
        check_writable(flag, path)?;
    }
    let started = Instant::now();
    let bar = Bar::new(args.quiet);
    let named = arrays(table, &bar).map_err(|e| match (&e, &args.table) {
        // The table records build options the builder rejects: a bad file.
        (BuildError::Option(_), Some(t)) => {
            Failure::input(format!("--table {}: recorded build options: {e}", t.display()))
        }
        _ => Failure::of("export", e),
    })?;
    bar.done();
    let texts = texts(table);
    let written = if want_dir {
        write_npy_dir(path, &named, &texts)
    } else {
        write_npz(path, &named, &texts)
    };
    written.map_err(|e| Failure::output(format_args!("{flag} {}", path.display()), &e))?;
    let shape = |name: &str| {
        named
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, a)| format!("{:?}", a.shape()))
            .unwrap_or_default()
    };
    outln!(
        "wrote {} ({} arrays: mu {}, grid_mu {}) in {:.1} s",
        path.display(),
        named.len() + 1,
        shape("mu"),
        shape("grid_mu"),
        started.elapsed().as_secs_f64()
    )?;
    Ok(())
}
