//! A contact.engineering container's measurements, their reliable 1-D
//! spectra and the combined spectrum as JSON, for tools/container_check.py
//! (the cross-check against SurfaceTopography) and the timing of a read.
//!
//! `cargo run --release --example container_dump --features topography -- CONTAINER.zip`

use ke_friction::topography::container::{
    combined_psd, combined_scale_dependent, measurement_psd, read_container, spectral_moments, ContainerOptions,
    Heights, COMBINED_POINTS_PER_DECADE,
};
use serde_json::json;

fn main() {
    let path = std::env::args().nth(1).expect("usage: container_dump CONTAINER.zip");
    let start = std::time::Instant::now();
    let surfaces = match read_container(path.as_ref(), &ContainerOptions::default()) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    let mut out = Vec::new();
    // Read + every measurement's PSD + the combined one (the first surface).
    let mut read_psd_seconds = f64::NAN;
    for s in &surfaces {
        let spectra: Vec<_> = s.measurements.iter().map(measurement_psd).collect();
        let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE);
        read_psd_seconds = start.elapsed().as_secs_f64();
        let measurements: Vec<_> = s
            .measurements
            .iter()
            .zip(&spectra)
            .map(|(m, p)| {
                let (nx, ny) = m.grid();
                let (sx, sy) = m.size();
                json!({
                    "name": m.name, "data_file": m.data_file, "unit": m.unit, "nx": nx, "ny": ny,
                    "size": [sx, sy], "uniform": matches!(m.heights, Heights::Uniform(_)),
                    "q": p.psd.as_ref().map(|p| p.q.clone()), "c": p.psd.as_ref().map(|p| p.c.clone()),
                    "reason": p.reason,
                })
            })
            .collect();
        // The moments over the whole combined band (SurfaceTopography's
        // container c1d_moment).
        let moments = combined.as_ref().and_then(|c| {
            let tau = 2.0 * std::f64::consts::PI;
            spectral_moments(&c.psd, tau / c.psd.q[c.psd.q.len() - 1], tau / c.psd.q[0])
        });
        out.push(json!({
            "measurements": measurements,
            "combined": combined.map(|c| json!({"q": c.psd.q, "c": c.psd.c, "contributors": c.contributors})),
            "moments": moments.map(|m| [m.m0, m.m2, m.m4]),
            "slope": combined_scale_dependent(&s.measurements, 1, 10).map(|c| json!({"d": c.distance, "v": c.mean_square})),
            "curvature": combined_scale_dependent(&s.measurements, 2, 10).map(|c| json!({"d": c.distance, "v": c.mean_square})),
        }));
    }
    let seconds = start.elapsed().as_secs_f64();
    println!(
        "{}",
        json!({"surfaces": out, "seconds": seconds, "read_psd_seconds": read_psd_seconds})
    );
}
