//! Prints the power spectral densities of a `.npy` height array as JSON,
//! for `tools/psd_check.py` (the cross-check against SurfaceTopography).
//! Not a user tool.
//!
//! `cargo run --release --features topography --example psd_dump -- FILE.npy DX [DY] [none|hann]`
//!
//! FILE.npy: f64 heights in metres, 1-D (a profile sampled every DX metres)
//! or 2-D of shape (ny, nx) (a map, rows along x, DY metres apart). Prints
//! `{"x": {"q": [...], "c": [...]}, "y": ..., "area": ...}` (q in rad/m, C
//! in m³ or m⁴; `y` and `area` null for a profile), with the window named
//! (default none).

#[path = "dump/mod.rs"]
mod dump;
use std::path::Path;
use std::process::ExitCode;

use ke_friction::topography::{psd_area, psd_profile_x, psd_profile_y, read_file, Psd, ReadOptions, Window};
use serde_json::{json, Value};

fn value(psd: &Psd) -> Value {
    json!({"q": psd.q, "c": psd.c})
}

fn run(args: &[String]) -> Result<Value, Box<dyn std::error::Error>> {
    let usage = "usage: psd_dump FILE.npy DX [DY] [none|hann]";
    let (file, rest) = args.split_first().ok_or(usage)?;
    let mut numbers = Vec::new();
    let mut window = Window::None;
    for a in rest {
        match a.as_str() {
            "none" => window = Window::None,
            "hann" => window = Window::Hann,
            other => numbers.push(other.parse::<f64>()?),
        }
    }
    let options = ReadOptions {
        dx: Some(*numbers.first().ok_or(usage)?),
        dy: numbers.get(1).copied(),
        ..ReadOptions::default()
    };
    let t = read_file(Path::new(file), &options)?;
    let x = value(&psd_profile_x(&t, window)?);
    if t.is_profile() {
        return Ok(json!({"x": x, "y": null, "area": null}));
    }
    let y = value(&psd_profile_y(&t, window)?);
    let area = value(&psd_area(&t, window)?);
    Ok(json!({"x": x, "y": y, "area": area}))
}

fn main() -> ExitCode {
    dump::main("psd_dump", run)
}
