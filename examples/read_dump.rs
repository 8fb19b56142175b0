//! Reads a surface file with the library's readers and writes its heights
//! as a `.npy` file (f8, shape (ny, nx), NaN where missing), printing the
//! grid and the metadata as JSON: for `python/tests/test_formats_a.py`
//! (the instruments' formats against SurfaceTopography's readers). Not a
//! user tool.
//!
//! `cargo run --release --features topography --example read_dump -- FILE OUT.npy [CHANNEL]`
//!
//! Prints `{"nx", "ny", "dx", "dy", "metadata"}` (metres; `dy` null for a
//! profile).

#[path = "dump/mod.rs"]
mod dump;
#[path = "../tests/npy.rs"]
mod npy;

use std::path::Path;
use std::process::ExitCode;

use ke_friction::topography::{read_file, ReadOptions};
use serde_json::{json, Value};

fn run(args: &[String]) -> Result<Value, Box<dyn std::error::Error>> {
    let [file, out, rest @ ..] = args else {
        return Err("usage: read_dump FILE OUT.npy [CHANNEL]".into());
    };
    let options = ReadOptions {
        channel: rest.first().map(|c| c.parse()).transpose()?,
        ..ReadOptions::default()
    };
    let t = read_file(Path::new(file), &options)?;
    let data: Vec<u8> = t.heights().iter().flat_map(|h| h.to_le_bytes()).collect();
    std::fs::write(out, npy::npy("<f8", false, &[t.ny(), t.nx()], &data))?;
    Ok(json!({"nx": t.nx(), "ny": t.ny(), "dx": t.dx(), "dy": t.dy(), "metadata": t.metadata()}))
}

fn main() -> ExitCode {
    dump::main("read_dump", run)
}
