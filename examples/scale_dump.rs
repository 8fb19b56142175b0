//! Prints the scale-dependent rms slope and curvature and the tip-radius
//! reliability cut-off of a `.npy` height array as JSON, for
//! `tools/scale_check.py` (the cross-check against SurfaceTopography), and
//! times the scale-dependent slope. Not a user tool.
//!
//! `cargo run --release --features topography --example scale_dump -- FILE.npy dx=DX [dy=DY] d=D1,D2,... [tip=R] [f=0.5] [repeat=N]`
//!
//! FILE.npy: f64 heights in metres, 1-D (a profile sampled every DX metres)
//! or 2-D of shape (ny, nx) (a map, rows along x, DY metres apart). Prints
//! `{"slope": [{"d": .., "x": .., "y": ..}, ..], "curvature": [..],
//! "cutoff": .., "slope_seconds": ..}`: rms slope and curvature per
//! distance (`y` null for a profile, NaN printed as null), the cut-off for
//! tip radius R and safety factor f (null if none, or if no `tip=`), and
//! with `repeat=N` the best of N timings (seconds, one thread) of
//! `scale_dependent_slope` at the distances given.

#[path = "dump/mod.rs"]
mod dump;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use ke_friction::topography::{
    read_file, scale_dependent_curvature, scale_dependent_slope, tip_reliability_cutoff, ReadOptions, ScaleRow,
};
use serde_json::{json, Value};

fn rows(rows: &[ScaleRow]) -> Value {
    rows.iter()
        .map(|r| json!({"d": r.distance, "x": r.x, "y": r.y}))
        .collect()
}

fn run(args: &[String]) -> Result<Value, Box<dyn std::error::Error>> {
    let usage = "usage: scale_dump FILE.npy dx=DX [dy=DY] d=D1,D2,... [tip=R] [f=0.5] [repeat=N]";
    let (file, rest) = args.split_first().ok_or(usage)?;
    let (mut dx, mut dy, mut distances, mut tip, mut factor, mut repeat) = (None, None, Vec::new(), None, 0.5, 0);
    for a in rest {
        let (key, value) = a.split_once('=').ok_or(usage)?;
        match key {
            "dx" => dx = Some(value.parse::<f64>()?),
            "dy" => dy = Some(value.parse::<f64>()?),
            "d" => distances = value.split(',').map(str::parse::<f64>).collect::<Result<Vec<_>, _>>()?,
            "tip" => tip = Some(value.parse::<f64>()?),
            "f" => factor = value.parse::<f64>()?,
            "repeat" => repeat = value.parse::<usize>()?,
            _ => return Err(usage.into()),
        }
    }
    let options = ReadOptions {
        dx: Some(dx.ok_or(usage)?),
        dy,
        ..ReadOptions::default()
    };
    let t = read_file(Path::new(file), &options)?;
    let slope = scale_dependent_slope(&t, &distances)?;
    let curvature = scale_dependent_curvature(&t, &distances)?;
    let cutoff = match tip {
        Some(r) => tip_reliability_cutoff(&t, r, factor)?,
        None => None,
    };
    let mut best: Option<f64> = None;
    for _ in 0..repeat {
        let start = Instant::now();
        let r = scale_dependent_slope(&t, &distances)?;
        let seconds = start.elapsed().as_secs_f64();
        std::hint::black_box(r);
        best = Some(best.map_or(seconds, |b| b.min(seconds)));
    }
    Ok(json!({
        "slope": rows(&slope),
        "curvature": rows(&curvature),
        "cutoff": cutoff,
        "slope_seconds": best,
    }))
}

fn main() -> ExitCode {
    dump::main("scale_dump", run)
}
