//! Writes X3P files with the library's writer, for `tools/x3p_check.py`
//! (the cross-check against SurfaceTopography's reader). Not a user tool.
//!
//! `cargo run --release --features topography --example write_x3p -- DIR`
//! writes, for each case, `DIR/NAME.x3p`, the heights written
//! (`NAME.orig.npy`) and the heights this library reads back from the file
//! (`NAME.read.npy`), both f64 of shape (ny, nx), and `DIR/index.tsv`:
//! `name<TAB>z type<TAB>nx<TAB>ny<TAB>dx<TAB>dy` (dy empty for a profile).
//!
//! `... --example write_x3p -- --read FILE OUT.npy` reads FILE with the
//! library's reader instead, writes its heights to `OUT.npy` and prints
//! `nx ny dx dy` (for X3P files written by other programs).

use std::path::Path;

use ke_friction::topography::{read_file, write_x3p, ReadOptions, Topography};

#[path = "../tests/npy.rs"]
mod npy;

/// A `.npy` file of f64 heights, shape (ny, nx).
fn write_npy(path: &Path, heights: &[f64], nx: usize, ny: usize) -> std::io::Result<()> {
    let data: Vec<u8> = heights.iter().flat_map(|h| h.to_le_bytes()).collect();
    std::fs::write(path, npy::npy("<f8", false, &[ny, nx], &data))
}

/// A rough-looking map: a few incommensurate waves, about a micrometre.
fn map(nx: usize, ny: usize, dx: f64, dy: f64, missing: &[usize]) -> Topography {
    let mut heights: Vec<f64> = (0..nx * ny)
        .map(|k| {
            let (x, y) = ((k % nx) as f64 * dx, (k / nx) as f64 * dy);
            1e-6 * ((x / 3.1e-6).sin() + 0.5 * (y / 1.7e-6 + 0.3).cos() + 0.2 * ((x + 2.0 * y) / 0.9e-6).sin()) - 0.4e-6
        })
        .collect();
    for &k in missing {
        heights[k] = f64::NAN;
    }
    Topography::map(heights, nx, ny, dx, dy).expect("a valid map")
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let Some(dir) = std::env::args_os().nth(1) else {
        eprintln!("usage: write_x3p DIR");
        std::process::exit(2);
    };
    if dir == "--read" {
        let (Some(file), Some(out)) = (std::env::args_os().nth(2), std::env::args_os().nth(3)) else {
            eprintln!("usage: write_x3p --read FILE OUT.npy");
            std::process::exit(2);
        };
        let t = read_file(file.as_ref(), &ReadOptions::default())?;
        write_npy(out.as_ref(), t.heights(), t.nx(), t.ny())?;
        let dy = t.dy().map(|d| format!("{d:e}")).unwrap_or_default();
        println!("{} {} {:e} {dy}", t.nx(), t.ny(), t.dx());
        return Ok(());
    }
    let dir = std::path::PathBuf::from(dir);
    std::fs::create_dir_all(&dir)?;
    let cases = [
        ("square", map(64, 64, 0.5e-6, 0.5e-6, &[])),
        ("dx-ne-dy", map(48, 20, 0.25e-6, 1.5e-6, &[])),
        ("masked", map(33, 17, 0.1e-6, 0.2e-6, &[0, 1, 40, 100, 33 * 17 - 1])),
        (
            "profile",
            Topography::profile((0..200).map(|i| 1e-7 * (0.1 * f64::from(i)).sin()).collect(), 2e-8)?,
        ),
    ];
    let mut index = String::new();
    for (name, t) in &cases {
        for z in ['D', 'F', 'L', 'I'] {
            let stem = format!("{name}-{z}");
            let path = dir.join(format!("{stem}.x3p"));
            write_x3p(t, &path, z)?;
            let back = read_file(&path, &ReadOptions::default())?;
            write_npy(&dir.join(format!("{stem}.orig.npy")), t.heights(), t.nx(), t.ny())?;
            write_npy(
                &dir.join(format!("{stem}.read.npy")),
                back.heights(),
                back.nx(),
                back.ny(),
            )?;
            let dy = t.dy().map(|d| format!("{d:e}")).unwrap_or_default();
            index.push_str(&format!("{stem}\t{z}\t{}\t{}\t{:e}\t{dy}\n", t.nx(), t.ny(), t.dx()));
        }
    }
    std::fs::write(dir.join("index.tsv"), index)?;
    println!("wrote {} X3P files into {}", 4 * cases.len(), dir.display());
    Ok(())
}
