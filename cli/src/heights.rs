//! `--heights FILE`: measured heights for an empirical density, read by
//! the library's surface readers (X3P, .npy, text); only the heights are
//! used, so files without sampling intervals are fine.

use crate::output::Failure;
use ke_friction::topography::{read_file, ReadError, ReadOptions};
use std::path::Path;

/// The heights in `path` (NaN = missing, kept for the density to skip).
pub fn read(path: &Path) -> Result<Vec<f64>, Failure> {
    let fail = |e: ReadError| Failure::of("--heights", e);
    let read = |options: &ReadOptions| read_file(path, options);
    let surface = match read(&ReadOptions::default()) {
        // The intervals do not matter for a density of heights.
        Err(ReadError::NeedInterval { .. }) => read(&ReadOptions {
            dx: Some(1.0),
            dy: Some(1.0),
            ..ReadOptions::default()
        }),
        other => other,
    }
    .map_err(fail)?;
    Ok(surface.heights().to_vec())
}
