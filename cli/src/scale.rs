//! `kefric surface --scan`, `--psd` and `--scale-dependent`: μ against the
//! S-filter's nesting index λs, the power spectral density, and the
//! scale-dependent slope and curvature (MODEL.md §11).

use crate::output::sig;
use crate::output::Failure;
use crate::surface::{evaluate, Args};
use crate::surface_args::request_failure;
use ke_friction::topography::{
    complete_part, default_distances, psd_all, scale_dependent_curvature, scale_dependent_slope, scan, ScaleRow,
    ScanError, ScanRange, Window,
};
use ke_friction::{Shortest, WarningKind, Warnings};
use std::path::Path;

/// The one file of --scan or --psd.
fn single_file<'a>(args: &'a Args, what: &str) -> Result<&'a Path, Failure> {
    match &args.files[..] {
        [one] => Ok(one),
        _ => Err(Failure::input(format!("{what}: takes one surface file"))),
    }
}

/// The columns of a --scan CSV row: the record names of the single
/// command's JSON (`surface`, `model`, `friction`), in this order.
const SCAN_COLUMNS: [(&str, &str); 16] = [
    ("surface", "sigma"),
    ("surface", "skewness"),
    ("surface", "kurtosis"),
    ("surface", "m2"),
    ("surface", "m4"),
    ("surface", "alpha"),
    ("surface", "eta"),
    ("surface", "radius"),
    ("surface", "beta"),
    ("model", "psi"),
    ("model", "theta"),
    ("friction", "pressure"),
    ("friction", "mu"),
    ("friction", "friction_force"),
    ("friction", "separation"),
    ("surface", "lambda_c"),
];

/// A scan row's warning kinds (its record's `warnings`), joined by `sep`.
fn row_kinds(r: &serde_json::Value, sep: &str) -> String {
    let kinds = r.get("warnings").and_then(serde_json::Value::as_array);
    let names: Vec<&str> = kinds
        .into_iter()
        .flatten()
        .filter_map(serde_json::Value::as_str)
        .collect();
    names.join(sep)
}

/// `surface --scan`: one row a λs.
pub fn run_scan(args: &Args) -> Result<(), Failure> {
    let path = single_file(args, "--scan")?;
    if crate::container::is_container(path) {
        return crate::container::run_scan(args, &crate::container::Input::Container(path));
    }
    let load = args.load.load()?;
    let request = args.request()?;
    let materials = request.check().map_err(|e| request_failure("surface", e))?.materials;
    let t = args.read.read("surface", path)?;
    let (options, cutoff) = args.read.options_for("surface", path, &t)?;
    let cutoff = cutoff.value();
    let default = ScanRange::default_for(&t);
    let range = ScanRange {
        from: args.from.unwrap_or(default.from),
        to: args.to.unwrap_or(default.to),
        per_decade: args.per_decade,
    };
    let tty = std::io::IsTerminal::is_terminal(&std::io::stderr());
    let rows = scan(&t, &options, &range, cutoff, |done, total| {
        if tty {
            eprint!("\rscan: {done}/{total}");
        }
    })
    .map_err(|e| Failure::of(scan_flags(&e), e))?;
    if tty {
        eprintln!();
    }
    let mut records = Vec::with_capacity(rows.len());
    let mut unreliable = 0;
    // The rows' warnings, one result a row: summarised once per kind at
    // the end, as the single command does (the cut-off's own line below).
    let mut warnings = Warnings::new();
    for row in &rows {
        let mut record = serde_json::json!({ "lambda_s": row.lambda_s, "reliable": row.reliable });
        match &row.surface {
            Ok(surface) => {
                unreliable += usize::from(row.reliable == Some(false));
                match evaluate(args, surface, materials.as_ref(), load.as_slice()) {
                    Ok((params, friction, row_warnings)) => {
                        let kinds: Vec<&str> = row_warnings.summaries().map(|s| s.worst.kind().name()).collect();
                        record["warnings"] = kinds.into();
                        warnings.note(
                            row_warnings
                                .summaries()
                                .map(|s| s.worst.clone())
                                .filter(|w| w.kind() != WarningKind::UnreliableScale),
                        );
                        record["surface"] = serde_json::to_value(surface.stats()).expect("a record");
                        if let Some(p) = params {
                            record["model"] = serde_json::to_value(p).expect("a record");
                        }
                        if let Some(f) = friction.first() {
                            record["friction"] = serde_json::to_value(f).expect("a record");
                        }
                    }
                    Err(f) => record["error"] = f.message().into(),
                }
            }
            Err(e) => record["error"] = e.to_string().into(),
        }
        records.push(record);
    }
    if unreliable > 0 {
        errln!(
            "warning: {unreliable} of {} scales are below the reliability cut-off {} m (reliable: false)",
            rows.len(),
            Shortest(cutoff.unwrap_or(f64::NAN))
        );
    }
    crate::output::warn(&warnings);
    let failed = records.iter().filter(|r| r.get("error").is_some()).count();
    if failed > 0 {
        errln!(
            "warning: {failed} of {} scales have no result (the row's error says why)",
            rows.len()
        );
    }
    if args.json {
        let doc = serde_json::json!({
            "files": [path.display().to_string()],
            "detrend": options.detrend,
            "derivative": options.derivative,
            "lambda_c": options.lambda_c,
            "cutoff": cutoff,
            "rows": records,
            "warnings": warnings.summaries().collect::<Vec<_>>(),
        });
        outln!("{}", serde_json::to_string(&doc).expect("a scan record serialises"))?;
        return Ok(());
    }
    let cell = |r: &serde_json::Value, (group, name): (&str, &str)| -> String {
        match r
            .get(group)
            .and_then(|g| g.get(name))
            .and_then(serde_json::Value::as_f64)
        {
            Some(v) => Shortest(v).to_string(),
            None => String::new(),
        }
    };
    if args.csv {
        let names: Vec<&str> = SCAN_COLUMNS.iter().map(|(_, n)| *n).collect();
        outln!("lambda_s,reliable,{},error,warnings", names.join(","))?;
        for r in &records {
            let cells: Vec<String> = SCAN_COLUMNS.iter().map(|&c| cell(r, c)).collect();
            let reliable = r["reliable"].as_bool().map_or(String::new(), |b| b.to_string());
            let error = r
                .get("error")
                .and_then(|e| e.as_str())
                .unwrap_or("")
                .replace(['"', '\n'], " ");
            outln!(
                "{},{reliable},{},\"{error}\",{}",
                Shortest(r["lambda_s"].as_f64().unwrap_or(f64::NAN)),
                cells.join(","),
                row_kinds(r, ";")
            )?;
        }
        return Ok(());
    }
    outln!(
        "# {}: mu against the S-filter nesting index lambda_s (m); lambda_c = {}",
        path.display(),
        options
            .lambda_c
            .map_or("none".to_string(), |l| format!("{} m", Shortest(l)))
    )?;
    outln!(
        "{:>12} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10}  warnings",
        "lambda_s",
        "reliable",
        "beta",
        "R",
        "eta",
        "psi",
        "mu"
    )?;
    for r in &records {
        let v = |c| {
            let s = cell(r, c);
            if s.is_empty() {
                "-".to_string()
            } else {
                format!("{}", sig(s.parse().unwrap_or(f64::NAN)))
            }
        };
        let reliable = r["reliable"]
            .as_bool()
            .map_or("-".to_string(), |b| if b { "yes" } else { "no" }.into());
        let kinds = row_kinds(r, ",");
        outln!(
            "{:>12} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10}  {}",
            sig(r["lambda_s"].as_f64().unwrap_or(f64::NAN)).to_string(),
            reliable,
            v(("surface", "beta")),
            v(("surface", "radius")),
            v(("surface", "eta")),
            v(("model", "psi")),
            v(("friction", "mu")),
            if kinds.is_empty() { "-" } else { &kinds }
        )?;
        if let Some(e) = r.get("error").and_then(|e| e.as_str()) {
            outln!("#   {e}")?;
        }
    }
    Ok(())
}

/// `surface --psd`: the power spectral densities of the detrended heights.
pub fn run_psd(args: &Args) -> Result<(), Failure> {
    let path = single_file(args, "--psd")?;
    if crate::container::is_container(path) {
        return crate::container::run_psd(args, &crate::container::Input::Container(path));
    }
    // Missing points: the largest complete rectangle, said so. The heights
    // as read are dropped once cut and detrended: one map held while the
    // spectra are taken.
    let detrended = {
        let read = args.read.read("surface", path)?;
        let (t, rectangle) = complete_part(&read).map_err(|e| Failure::of(format!("--psd: {}", path.display()), e))?;
        if let Some(r) = rectangle {
            errln!("warning: --psd: {}: {r}", path.display());
        }
        t.detrended_topography(args.read.options().detrend)
            .map_err(|e| Failure::of(format!("surface {}", path.display()), e))?
        // `read` and its cut part are dropped here.
    };
    let window = if args.hann { Window::Hann } else { Window::None };
    let spectra = psd_all(&detrended, window).map_err(|e| Failure::of(format!("--psd: {}", path.display()), e))?;
    if args.json {
        let mut doc = serde_json::Map::new();
        doc.insert("files".into(), serde_json::json!([path.display().to_string()]));
        doc.insert("window".into(), window.name().into());
        for (name, p) in &spectra {
            doc.insert(name.to_string(), serde_json::json!({ "q": p.q, "c": p.c }));
        }
        outln!("{}", serde_json::Value::Object(doc))?;
        return Ok(());
    }
    if !args.csv {
        outln!(
            "# {}: power spectral density (q in rad/m; C in m^3 along x, y; m^4 for the area)",
            path.display()
        )?;
    }
    outln!("direction,q,c")?;
    for (name, p) in &spectra {
        for (q, c) in p.q.iter().zip(&p.c) {
            outln!("{name},{},{}", Shortest(*q), Shortest(*c))?;
        }
    }
    Ok(())
}

/// `surface --scale-dependent`: the rms slope and curvature of the heights
/// detrended as the statistics are (`--detrend`; unfiltered) against the
/// stencil length, at the core's default distances of the curvature (from
/// 2·max(dx, dy), the shortest stencil both orders have: no empty cells).
pub fn run_scale_dependent(args: &Args) -> Result<(), Failure> {
    let path = single_file(args, "--scale-dependent")?;
    if crate::container::is_container(path) {
        return crate::container::run_scale_dependent(args, &crate::container::Input::Container(path));
    }
    let read = &args.read;
    let t = read.read("surface", path)?;
    let failed =
        |e: ke_friction::topography::ScaleError| Failure::of(format!("--scale-dependent: {}", path.display()), e);
    let (_, cutoff) = read.options_for("surface", path, &t)?;
    let cutoff = cutoff.value();
    // Too few points is said as such, before the detrending could fail on them.
    scale_dependent_slope(&t, &[]).map_err(failed)?;
    scale_dependent_curvature(&t, &[]).map_err(failed)?;
    // The statistics' detrending (m2 = the square of the slope at one
    // interval of these heights).
    let t = t
        .detrended_topography(read.options().detrend)
        .map_err(|e| Failure::of(format!("--scale-dependent: {}", path.display()), e))?;
    let distances = default_distances(&t, 2);
    let slope = scale_dependent_slope(&t, &distances).map_err(failed)?;
    let curvature = scale_dependent_curvature(&t, &distances).map_err(failed)?;
    let map = t.dy().is_some();
    let columns: &[&str] = if map {
        &["distance", "slope_x", "slope_y", "curvature_x", "curvature_y"]
    } else {
        &["distance", "slope_x", "curvature_x"]
    };
    let row = |s: &ScaleRow, c: &ScaleRow| -> Vec<f64> {
        let mut v = vec![s.distance, s.x];
        if map {
            v.push(s.y.unwrap_or(f64::NAN));
        }
        v.push(c.x);
        if map {
            v.push(c.y.unwrap_or(f64::NAN));
        }
        v
    };
    let rows: Vec<Vec<f64>> = slope.iter().zip(&curvature).map(|(s, c)| row(s, c)).collect();
    if args.json {
        let mut doc = serde_json::Map::new();
        doc.insert("files".into(), serde_json::json!([path.display().to_string()]));
        doc.insert("cutoff".into(), serde_json::json!(cutoff));
        for (k, name) in columns.iter().enumerate() {
            // NaN (no value at that length) is null in JSON.
            let values: Vec<Option<f64>> = rows.iter().map(|r| r[k].is_finite().then_some(r[k])).collect();
            doc.insert(name.to_string(), serde_json::json!(values));
        }
        outln!("{}", serde_json::Value::Object(doc))?;
        return Ok(());
    }
    if !args.csv {
        outln!(
            "# {}: scale-dependent rms slope (1) and rms curvature (1/m) of the detrended heights, against the stencil length (m)",
            path.display()
        )?;
        match cutoff {
            Some(c) => outln!(
                "# reliability cut-off: {} m (the rows below it are distorted by the instrument)",
                sig(c)
            )?,
            None if read.resolution.is_some() || read.tip_radius.is_some() => {
                outln!("# reliability cut-off: none (the tip distorts no scale)")?
            }
            None => {}
        }
    }
    outln!("{}", columns.join(","))?;
    for r in &rows {
        let cells: Vec<String> = r
            .iter()
            .map(|v| {
                if v.is_finite() {
                    Shortest(*v).to_string()
                } else {
                    "nan".into()
                }
            })
            .collect();
        outln!("{}", cells.join(","))?;
    }
    Ok(())
}

/// The flags a refused scan range names.
pub(crate) fn scan_flags(e: &ScanError) -> &'static str {
    match e {
        ScanError::PerDecade { .. } => "--per-decade",
        _ => "--from/--to",
    }
}
