//! `kefric surface CONTAINER --psd`: a contact.engineering container's
//! measurements, each one's reliable 1-D PSD along x and the combined
//! spectrum (the library's `topography::container`). Dispatched from
//! `scale::run_psd` when its one file is a container.

use crate::output::Failure;
use crate::surface::Args;
use ke_friction::topography::container::{
    combined_psd, measurement_psd, read_container, ContainerOptions, COMBINED_POINTS_PER_DECADE,
};
use ke_friction::Shortest;
use std::path::Path;

/// Whether `path` is a container (a zip with `meta.yml` or `index.json`).
pub fn is_container(path: &Path) -> bool {
    ke_friction::topography::container::is_container_file(path)
}

/// `surface CONTAINER --psd` (`--json`: `measurements` with their spectra
/// and `combined: {"q": [...], "c": [...]}`; else CSV rows
/// `measurement,q,c`, the combined spectrum's measurement `combined`).
pub fn run_psd(args: &Args, path: &Path) -> Result<(), Failure> {
    for (name, v) in [
        ("tip-radius", args.read.tip_radius),
        ("resolution", args.read.resolution),
    ] {
        if let Some(v) = v.filter(|v| !(v.is_finite() && *v > 0.0)) {
            return Err(Failure::input(format!(
                "--{name}: {} is out of range: must be > 0 and finite (metres)",
                Shortest(v)
            )));
        }
    }
    // For the measurements whose metadata gives no instrument parameters;
    // --resolution takes precedence over --tip-radius, as for one file.
    let options = ContainerOptions {
        read: ke_friction::topography::ReadOptions {
            max_points: args.read.max_points.unwrap_or(ke_friction::topography::MAX_POINTS),
            ..Default::default()
        },
        tip_radius: args.read.tip_radius.filter(|_| args.read.resolution.is_none()),
        resolution: args.read.resolution,
    };
    let surfaces = read_container(path, &options).map_err(|e| Failure::of(format!("surface {}", path.display()), e))?;
    let mut docs = Vec::new();
    let mut rows = Vec::new();
    for s in &surfaces {
        let spectra: Vec<_> = s.measurements.iter().map(measurement_psd).collect();
        let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE);
        let mut measurements = Vec::new();
        for (m, p) in s.measurements.iter().zip(&spectra) {
            let (nx, ny) = m.grid();
            let (sx, sy) = m.size();
            let reliable = p.psd.as_ref().map(|p| {
                let q = &p.q;
                serde_json::json!({"q_min": q.get(1), "q_max": q.last()})
            });
            measurements.push(serde_json::json!({
                "file": m.data_file, "name": m.name, "unit": m.unit, "nx": nx, "ny": ny,
                "dx": sx / nx as f64, "size": [sx, sy], "cutoff": p.cutoff, "reliable": reliable,
                "psd": p.psd.as_ref().map(|p| serde_json::json!({"q": p.q, "c": p.c})), "note": p.reason,
            }));
            if let Some(psd) = &p.psd {
                for (q, c) in psd.q.iter().zip(&psd.c) {
                    rows.push(format!(
                        "{},{},{}",
                        m.name.replace(',', " "),
                        Shortest(*q),
                        Shortest(*c)
                    ));
                }
            }
        }
        if let Some(c) = &combined {
            for (q, v) in c.psd.q.iter().zip(&c.psd.c) {
                rows.push(format!("combined,{},{}", Shortest(*q), Shortest(*v)));
            }
        }
        docs.push(serde_json::json!({
            "name": s.name,
            "measurements": measurements,
            "combined": combined.map(|c| serde_json::json!({"q": c.psd.q, "c": c.psd.c, "contributors": c.contributors})),
        }));
    }
    if args.json {
        let mut doc = if docs.len() == 1 {
            docs.pop().expect("one surface")
        } else {
            serde_json::json!({ "surfaces": docs })
        };
        doc["files"] = serde_json::json!([path.display().to_string()]);
        outln!("{doc}")?;
        return Ok(());
    }
    if !args.csv {
        outln!(
            "# {}: each measurement's reliable 1-D PSD along x and the combined one (q in rad/m, C in m^3)",
            path.display()
        )?;
    }
    outln!("measurement,q,c")?;
    for r in rows {
        outln!("{r}")?;
    }
    Ok(())
}
