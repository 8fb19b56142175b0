//! `kefric surface CONTAINER --psd`: a contact.engineering container's
//! measurements, each one's reliable 1-D PSD along x and the combined
//! spectrum (the library's `topography::container`). Dispatched from
//! `scale::run_psd` when its one file is a container.

use crate::output::sig;
use crate::output::Failure;
use crate::surface::Args;
use crate::surface_args::request_failure;
use ke_friction::topography::container::AnalysisError;
use ke_friction::topography::container::{
    combine_scale_dependent, combined_psd, container_analysis, container_scan, measurement_scales, measurement_spectra,
    read_container, Band, ContainerOptions, ContainerSurface, Measurement, MeasurementPsd, MeasurementScale, Resolved,
    COMBINED_POINTS_PER_DECADE,
};
use ke_friction::topography::{evaluate_failure, Field, LambdaS, SurfaceModel};
use ke_friction::{Load, Shortest, Warnings};
use std::path::Path;

/// Whether `path` is a container (a zip with `meta.yml` or `index.json`).
pub fn is_container(path: &Path) -> bool {
    ke_friction::topography::container::is_container_file(path)
}

/// `surface CONTAINER --psd` (`--json`: `measurements` with their spectra
/// and `combined: {"q": [...], "c": [...]}`; else CSV rows
/// `measurement,q,c`, the combined spectrum's measurement `combined`).
pub fn run_psd(args: &Args, path: &Path) -> Result<(), Failure> {
    let surfaces = read(args, path)?;
    let mut docs = Vec::new();
    let mut rows = Vec::new();
    for s in &surfaces {
        let spectra = measurement_spectra(&s.measurements);
        let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE);
        let mut measurements = Vec::new();
        for (m, p) in s.measurements.iter().zip(&spectra) {
            let mut record = measurement_record(m, p);
            record["psd"] = serde_json::json!(p.psd.as_ref().map(|p| serde_json::json!({"q": p.q, "c": p.c})));
            measurements.push(record);
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
        return print_docs(docs, path);
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

/// The CSV columns of `surface CONTAINER --scale-dependent`.
const SCALE_HEADER: &str = "distance,rms_slope,rms_curvature,slope_from,curvature_from";

/// `surface CONTAINER --scale-dependent`: the combined scale-dependent rms
/// slope and rms curvature along x against the stencil length, as
/// SurfaceTopography's container `scale_dependent_statistical_property`
/// (the mean square over the measurements with a value at each length of
/// a grid aligned to whole decades, 10 a decade; nonuniform profiles
/// included), each row naming the measurements it rests on (CSV rows, or
/// `--json`: `measurements` each with its own `slope` and `curvature`, and
/// `combined: {"slope": ..., "curvature": ...}`).
pub fn run_scale_dependent(args: &Args, path: &Path) -> Result<(), Failure> {
    if args.read.lambda_c.is_some() || args.read.lambda_s.is_some() {
        return Err(Failure::input(
            "--lambda-s, --lambda-c: not with --scale-dependent of a container (its statistics are unfiltered)",
        ));
    }
    let surfaces = read(args, path)?;
    let per = COMBINED_POINTS_PER_DECADE;
    let mut docs = Vec::new();
    let mut lines = vec![SCALE_HEADER.to_string()];
    for s in &surfaces {
        let scales = measurement_scales(&s.measurements, per);
        let names = |idx: &[usize]| -> Vec<String> { idx.iter().map(|&i| s.measurements[i].name.clone()).collect() };
        let nullable = |v: &[f64]| -> Vec<Option<f64>> { v.iter().map(|x| x.is_finite().then_some(*x)).collect() };
        let rms = |v: &[f64]| -> Vec<Option<f64>> { v.iter().map(|x| x.is_finite().then(|| x.sqrt())).collect() };
        let own = |m: &MeasurementScale| serde_json::json!({"distance": m.distance, "rms": rms(&m.mean_square)});
        let spectra = measurement_spectra(&s.measurements);
        let measurements: Vec<_> = s
            .measurements
            .iter()
            .zip(&spectra)
            .zip(&scales)
            .map(|((m, p), [slope, curvature])| {
                let mut record = measurement_record(m, p);
                record["scale_cutoff"] = serde_json::json!(slope.cutoff);
                record["slope"] = own(slope);
                record["curvature"] = own(curvature);
                record
            })
            .collect();
        let slopes: Vec<MeasurementScale> = scales.iter().map(|[s, _]| s.clone()).collect();
        let curvatures: Vec<MeasurementScale> = scales.iter().map(|[_, c]| c.clone()).collect();
        let slope = combine_scale_dependent(&slopes);
        let curvature = combine_scale_dependent(&curvatures);
        if slope.is_none() && curvature.is_none() {
            return Err(Failure::classified(
                format!(
                    "surface {}: --scale-dependent: no measurement has a stencil length in its reliable band",
                    path.display()
                ),
                ke_friction::ErrorKind::Domain,
            ));
        }
        let combined = |c: &Option<ke_friction::topography::container::CombinedScale>| {
            c.as_ref().map(|c| {
                serde_json::json!({
                    "distance": c.distance, "rms": rms(&c.mean_square), "mean_square": nullable(&c.mean_square),
                    "rests_on": c.contributors.iter().map(|i| names(i)).collect::<Vec<_>>(),
                })
            })
        };
        docs.push(serde_json::json!({
            "name": s.name,
            "measurements": measurements,
            "combined": {"slope": combined(&slope), "curvature": combined(&curvature)},
        }));
        // Rows on the union of the two grids (a curvature starts at twice
        // the shortest length of a slope).
        type Cell = Option<(f64, String)>;
        let mut rows: std::collections::BTreeMap<i64, (f64, [Cell; 2])> = Default::default();
        for (k, c) in [&slope, &curvature].into_iter().enumerate() {
            let Some(c) = c else { continue };
            for (((g, d), v), from) in c
                .grid_index
                .iter()
                .zip(&c.distance)
                .zip(&c.mean_square)
                .zip(&c.contributors)
            {
                let cell = (v.sqrt(), names(from).join(" ").replace(',', " "));
                rows.entry(*g).or_insert((*d, [None, None])).1[k] = Some(cell);
            }
        }
        for (d, [sl, cu]) in rows.into_values() {
            let value = |c: &Option<(f64, String)>| match c {
                Some((v, _)) if v.is_finite() => Shortest(*v).to_string(),
                _ => String::new(),
            };
            let from = |c: &Option<(f64, String)>| c.as_ref().map_or(String::new(), |c| c.1.clone());
            lines.push(format!(
                "{},{},{},{},{}",
                Shortest(d),
                value(&sl),
                value(&cu),
                from(&sl),
                from(&cu)
            ));
        }
    }
    if args.json {
        return print_docs(docs, path);
    }
    if !args.csv {
        outln!(
            "# {}: the measurements' combined scale-dependent rms slope (1) and rms curvature (1/m) along x, against the stencil length (m); each row's measurements",
            path.display()
        )?;
    }
    for line in lines {
        outln!("{line}")?;
    }
    Ok(())
}

/// One JSON document, or `{"surfaces": [...]}` for several, with `files`.
fn print_docs(mut docs: Vec<serde_json::Value>, path: &Path) -> Result<(), Failure> {
    let mut doc = if docs.len() == 1 {
        docs.pop().expect("one surface")
    } else {
        serde_json::json!({ "surfaces": docs })
    };
    doc["files"] = serde_json::json!([path.display().to_string()]);
    outln!("{doc}")?;
    Ok(())
}

/// A measurement's record: file, name, unit, grid, spacing, size, the
/// reliability cut-off and the reliable range (q and wavelength).
fn measurement_record(m: &Measurement, p: &MeasurementPsd) -> serde_json::Value {
    let (nx, ny) = m.grid();
    let (sx, sy) = m.size();
    let reliable = p.psd.as_ref().map(|p| {
        let (q_min, q_max) = (p.q.get(1).copied(), p.q.last().copied());
        serde_json::json!({
            "q_min": q_min, "q_max": q_max,
            "lambda_min": q_max.map(|q| 2.0 * std::f64::consts::PI / q),
            "lambda_max": q_min.map(|q| 2.0 * std::f64::consts::PI / q),
        })
    });
    serde_json::json!({
        "file": m.data_file, "name": m.name, "unit": m.unit, "nx": nx, "ny": ny,
        "dx": sx / nx as f64, "size": [sx, sy], "cutoff": p.cutoff, "reliable": reliable, "note": p.reason,
    })
}

/// The container's surfaces, read with the instrument flags.
fn read(args: &Args, path: &Path) -> Result<Vec<ContainerSurface>, Failure> {
    // A container's meta.yml gives each measurement's spacing, unit and
    // detrending: flags that would set them for a loose file are refused
    // rather than ignored.
    for (flag, given) in [
        ("--dx", args.read.dx.is_some()),
        ("--dy", args.read.dy.is_some()),
        ("--channel", args.read.channel.is_some()),
    ] {
        if given {
            return Err(Failure::input(format!(
                "{flag}: not with a container (its meta.yml and data files give each measurement's)"
            )));
        }
    }
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
    read_container(path, &options).map_err(|e| Failure::of(format!("surface {}", path.display()), e))
}

/// The model set-up, the loads and the band asked for, checked.
struct Asked {
    how: SurfaceModel,
    loads: Vec<Load>,
    band: Option<Band>,
    load_field: Field,
    family: Option<ke_friction::Family>,
}

fn asked(args: &Args) -> Result<Asked, Failure> {
    let request = args.request()?;
    let checked = request.check().map_err(|e| request_failure("surface", e))?;
    let Some(materials) = checked.materials else {
        return Err(Failure::input(
            "surface CONTAINER: μ from a container needs the materials (--e1, --nu1, --e2, --nu2, --hardness, --delta-gamma, --epsilon); --psd or --scale-dependent need none",
        ));
    };
    for (flag, v) in [("--lambda-c", args.read.lambda_c)] {
        if let Some(v) = v.filter(|v| !(v.is_finite() && *v > 0.0)) {
            return Err(Failure::input(format!(
                "{flag}: {} is out of range: must be > 0 and finite (metres)",
                Shortest(v)
            )));
        }
    }
    let lambda_s = match args.read.lambda_s {
        Some(LambdaS::Metres(v)) if !(v.is_finite() && v > 0.0) => {
            return Err(Failure::input(format!(
                "--lambda-s: {} is out of range: must be > 0 and finite (metres), or auto",
                Shortest(v)
            )))
        }
        Some(LambdaS::Metres(v)) => Some(v),
        // auto: the smallest reliable scale of any measurement, the default.
        Some(LambdaS::Auto) | None => None,
    };
    let band = match (lambda_s, args.read.lambda_c) {
        (None, None) => None,
        (s, c) => Some((s, c)),
    };
    Ok(Asked {
        how: SurfaceModel {
            materials,
            family: args.distribution,
            fit: args.fit,
            kind: args.model,
        },
        loads: checked.loads.unwrap_or_default(),
        band: band.map(|(s, c)| Band {
            lambda_s: s.unwrap_or(f64::NAN),
            lambda_c: c.unwrap_or(f64::NAN),
        }),
        load_field: request.loads.field(),
        family: args.distribution,
    })
}

/// An analysis error, naming the flags to blame.
fn analysis_failure(path: &Path, asked: &Asked, e: AnalysisError) -> Failure {
    match e {
        AnalysisError::Evaluate(e) => request_failure("surface", evaluate_failure(&e, asked.family, asked.load_field)),
        AnalysisError::Band(_) if asked.band.is_some() => Failure::of("--lambda-s, --lambda-c", e),
        e => Failure::of(format!("surface {}", path.display()), e),
    }
}

/// The band asked for, its missing end from the default band.
fn band_of(asked: &Asked, resolved: &Resolved) -> Option<Band> {
    let given = asked.band?;
    let default = resolved.default_band();
    let pick = |v: f64, d: Option<f64>| if v.is_nan() { d.unwrap_or(f64::NAN) } else { v };
    Some(Band {
        lambda_s: pick(given.lambda_s, default.map(|b| b.lambda_s)),
        lambda_c: pick(given.lambda_c, default.map(|b| b.lambda_c)),
    })
}

/// `surface CONTAINER` with the materials: μ from the whole band of the
/// combined spectrum (text, or `--json`: `measurements`, `combined`,
/// `model`, `friction`, `warnings`).
pub fn run(args: &Args, path: &Path) -> Result<(), Failure> {
    if args.from.is_some() || args.to.is_some() {
        return Err(Failure::input(
            "--from, --to: not with a container (its scan runs over λs from the smallest reliable scale)",
        ));
    }
    let asked = asked(args)?;
    let surfaces = read(args, path)?;
    let mut docs = Vec::new();
    let mut warnings = Warnings::new();
    let mut text = Vec::new();
    for s in &surfaces {
        let spectra = measurement_spectra(&s.measurements);
        let resolved = Resolved::of(&spectra);
        let band = band_of(&asked, &resolved);
        let a = container_analysis(
            &s.measurements,
            &spectra,
            band,
            COMBINED_POINTS_PER_DECADE,
            &asked.how,
            &asked.loads,
        )
        .map_err(|e| analysis_failure(path, &asked, e))?;
        warnings.extend(a.warnings.iter().cloned());
        let measurements: Vec<_> = s
            .measurements
            .iter()
            .zip(&spectra)
            .map(|(m, p)| measurement_record(m, p))
            .collect();
        let names = |idx: &[usize]| -> Vec<String> { idx.iter().map(|&i| s.measurements[i].name.clone()).collect() };
        let record = serde_json::to_value(&a).expect("a record");
        docs.push(serde_json::json!({
            "name": s.name,
            "measurements": measurements,
            "combined": {
                "band": record["band"], "moments": record["moments"], "roughness": record["roughness"],
                "heights_from": s.measurements[a.heights_from].name,
                "rests_on": names(&a.measurements),
            },
            "model": record["model"],
            "friction": record["frictions"],
            "warnings": record["warnings"],
        }));
        text.push(format!("surface: {}", s.name.as_deref().unwrap_or("(unnamed)")));
        for (m, p) in s.measurements.iter().zip(&spectra) {
            let (nx, ny) = m.grid();
            let range = Resolved::of(std::slice::from_ref(p)).ranges[0];
            text.push(format!(
                "  measurement {}: {} x {} points, reliable {}",
                m.name,
                nx,
                ny,
                range.map_or("none".to_string(), |r| format!("{} m to {} m", sig(r.0), sig(r.1)))
            ));
        }
        text.push(format!(
            "band: λs {} m to λc {} m (rests on {}; heights from {})",
            sig(a.band.lambda_s),
            sig(a.band.lambda_c),
            names(&a.measurements).join(", "),
            s.measurements[a.heights_from].name
        ));
        text.push(format!(
            "moments: m0 {} m^2, m2 {}, m4 {} 1/m^2",
            sig(a.moments.m0),
            sig(a.moments.m2),
            sig(a.moments.m4)
        ));
        let r = &a.roughness;
        text.push(format!(
            "roughness: sigma {} m, alpha {}, eta {} 1/m^2, R {} m, beta {}",
            sig(r.sigma),
            sig(r.alpha),
            sig(r.eta),
            sig(r.radius),
            sig(r.beta)
        ));
        text.push(format!(
            "model: psi {}, theta {}, beta {}",
            sig(a.model.psi),
            sig(a.model.theta),
            sig(a.model.constants.beta)
        ));
        for f in &a.frictions {
            let (load, q) = f.as_given();
            let unit = if f.force.is_some() { "N" } else { "Pa" };
            text.push(format!(
                "load {} {unit}: mu {} (friction {} {unit})",
                sig(load),
                sig(f.mu),
                sig(q)
            ));
        }
    }
    crate::output::warn(&warnings);
    if args.json {
        return print_docs(docs, path);
    }
    for line in text {
        outln!("{line}")?;
    }
    Ok(())
}

/// The CSV columns of a container scan row.
const SCAN_HEADER: &str = "lambda_s,lambda_c,measurements,sigma,alpha,eta,radius,beta,mu,mu_min,mu_max,warnings,error";

/// `surface CONTAINER --scan`: μ over λs from the smallest reliable scale
/// towards λc, each row with the measurements it rests on, its warnings and
/// the spread of μ across the measurements taken alone (text/CSV rows, or
/// `--json`: `measurements` and `rows`).
pub fn run_scan(args: &Args, path: &Path) -> Result<(), Failure> {
    if args.from.is_some() || args.to.is_some() {
        return Err(Failure::input(
            "--from, --to: not with a container (its scan runs over λs from the smallest reliable scale to λc)",
        ));
    }
    if !(1..=1000).contains(&args.per_decade) {
        return Err(Failure::input(format!(
            "--per-decade: {} is out of range: 1 to 1000",
            args.per_decade
        )));
    }
    let asked = asked(args)?;
    if asked.loads.len() > 1 {
        return Err(Failure::input("--force, --pressure: one load with --scan, not a range"));
    }
    if matches!(args.read.lambda_s, Some(LambdaS::Metres(_))) {
        return Err(Failure::input("--lambda-s: not with --scan (the scan runs over λs)"));
    }
    let surfaces = read(args, path)?;
    let mut docs = Vec::new();
    let mut lines = vec![SCAN_HEADER.to_string()];
    let mut warnings = Warnings::new();
    for s in &surfaces {
        let spectra = measurement_spectra(&s.measurements);
        let rows = container_scan(
            &s.measurements,
            &spectra,
            args.read.lambda_c,
            args.per_decade as u32,
            &asked.how,
            &asked.loads,
        )
        .map_err(|e| analysis_failure(path, &asked, e))?;
        let names = |idx: &[usize]| -> Vec<String> { idx.iter().map(|&i| s.measurements[i].name.clone()).collect() };
        let mut records = Vec::with_capacity(rows.len());
        for row in &rows {
            let mut record = serde_json::json!({
                "lambda_s": row.band.lambda_s, "lambda_c": row.band.lambda_c,
                "measurements": names(&row.measurements),
                "spread": row.spread.as_ref().map(|v| v.iter().map(|(lo, hi)| serde_json::json!({"mu_min": lo, "mu_max": hi})).collect::<Vec<_>>()),
            });
            let mut cells = vec![
                Shortest(row.band.lambda_s).to_string(),
                Shortest(row.band.lambda_c).to_string(),
                names(&row.measurements).join(" ").replace(',', " "),
            ];
            match &row.result {
                Ok(a) => {
                    warnings.note(a.warnings.iter().cloned());
                    let full = serde_json::to_value(a).expect("a record");
                    for key in ["moments", "roughness", "model", "warnings"] {
                        record[key] = full[key].clone();
                    }
                    record["friction"] = full["frictions"].get(0).cloned().unwrap_or_default();
                    let r = &a.roughness;
                    for v in [r.sigma, r.alpha, r.eta, r.radius, r.beta] {
                        cells.push(Shortest(v).to_string());
                    }
                    cells.push(
                        a.frictions
                            .first()
                            .map_or(String::new(), |f| Shortest(f.mu).to_string()),
                    );
                    let (lo, hi) = row
                        .spread
                        .as_ref()
                        .map_or((None, None), |v| (Some(v[0].0), Some(v[0].1)));
                    cells.push(lo.map_or(String::new(), |v| Shortest(v).to_string()));
                    cells.push(hi.map_or(String::new(), |v| Shortest(v).to_string()));
                    let kinds: Vec<&str> = a.warnings.iter().map(|w| w.kind().name()).collect();
                    cells.push(kinds.join(" "));
                    cells.push(String::new());
                }
                Err(e) => {
                    record["error"] = e.to_string().into();
                    cells.extend(std::iter::repeat_n(String::new(), 9));
                    cells.push(format!("\"{}\"", e.to_string().replace('"', "'")));
                }
            }
            lines.push(cells.join(","));
            records.push(record);
        }
        let measurements: Vec<_> = s
            .measurements
            .iter()
            .zip(&spectra)
            .map(|(m, p)| measurement_record(m, p))
            .collect();
        docs.push(serde_json::json!({"name": s.name, "measurements": measurements, "rows": records}));
    }
    crate::output::warn(&warnings);
    if args.json {
        return print_docs(docs, path);
    }
    if !args.csv {
        outln!(
            "# {}: μ from the combined spectrum over [λs, λc] (m); mu_min..mu_max: μ from each measurement alone",
            path.display()
        )?;
    }
    for line in lines {
        outln!("{line}")?;
    }
    Ok(())
}
