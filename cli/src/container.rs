//! `kefric surface CONTAINER --psd`: a contact.engineering container's
//! measurements, each one's reliable 1-D PSD along x and the combined
//! spectrum (the library's `topography::container`). Dispatched from
//! `scale::run_psd` when its one file is a container.

use crate::output::sig;
use crate::output::Failure;
use crate::surface::Args;
use crate::surface_args::{request_failure, spell, SurfaceArgs};
use ke_friction::topography::container::AnalysisError;
use ke_friction::topography::container::{
    combine_scale_dependent, combined_psd, container_analysis, container_scan, measurement_psd, measurement_scales,
    measurement_spectra, read_container, ContainerRecord, ContainerSurface, Measurement, MeasurementPsd,
    MeasurementRecord, MeasurementScale, Resolved, ScanRecord, COMBINED_POINTS_PER_DECADE,
};
use ke_friction::topography::{Field, LambdaS, SurfaceModel, SurfaceRequest};
use ke_friction::{Load, Shortest, Warnings};
use std::path::Path;

/// What the measurements come from: a container, or loose files
/// (`--measurements FILE[@KEY=VALUE,...] ...`, cli/src/measurements.rs).
#[derive(Debug, Clone, Copy)]
pub enum Input<'a> {
    /// A contact.engineering container.
    Container(&'a Path),
    /// Loose files, as given to `--measurements`.
    Loose(&'a [String]),
}

impl Input<'_> {
    /// The input an error names: `surface CONTAINER` or `--measurements`.
    fn context(&self) -> String {
        match self {
            Input::Container(p) => format!("surface {}", p.display()),
            Input::Loose(_) => "--measurements".into(),
        }
    }

    /// The files read (`--json`'s `files`).
    fn files(&self) -> Vec<String> {
        match self {
            Input::Container(p) => vec![p.display().to_string()],
            Input::Loose(files) => files.iter().map(|f| loose_path(f)).collect(),
        }
    }
}

/// The file of a `--measurements` value (its settings apart).
fn loose_path(value: &str) -> String {
    value
        .parse::<ke_friction::topography::container::LooseMeasurement>()
        .map_or_else(|_| value.to_string(), |m| m.path.display().to_string())
}

/// The container's path, or the loose files joined by `+`.
impl std::fmt::Display for Input<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Input::Container(p) => write!(f, "{}", p.display()),
            Input::Loose(files) => {
                let paths: Vec<String> = files.iter().map(|f| loose_path(f)).collect();
                f.write_str(&paths.join(" + "))
            }
        }
    }
}

/// Whether `path` is a container (a zip with `meta.yml` or `index.json`).
pub fn is_container(path: &Path) -> bool {
    ke_friction::topography::container::is_container_file(path)
}

/// `surface CONTAINER --psd` (`--json`: `measurements` with their spectra
/// and `combined: {"q": [...], "c": [...]}`; else CSV rows
/// `measurement,q,c`, the combined spectrum's measurement `combined`).
pub fn run_psd(args: &Args, path: &Input) -> Result<(), Failure> {
    let surfaces = read(&args.read, path)?;
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
        outln!("# {path}: each measurement's reliable 1-D PSD along x and the combined one (q in rad/m, C in m^3)")?;
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
pub fn run_scale_dependent(args: &Args, path: &Input) -> Result<(), Failure> {
    if args.read.lambda_c.is_some() || args.read.lambda_s.is_some() {
        return Err(Failure::input(
            "--lambda-s, --lambda-c: not with --scale-dependent of a container (its statistics are unfiltered)",
        ));
    }
    let surfaces = read(&args.read, path)?;
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
                    path
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
            path
        )?;
    }
    for line in lines {
        outln!("{line}")?;
    }
    Ok(())
}

/// One JSON document, or `{"surfaces": [...]}` for several, with `files`.
fn print_docs(mut docs: Vec<serde_json::Value>, path: &Input) -> Result<(), Failure> {
    let mut doc = if docs.len() == 1 {
        docs.pop().expect("one surface")
    } else {
        serde_json::json!({ "surfaces": docs })
    };
    doc["files"] = serde_json::json!(path.files());
    outln!("{doc}")?;
    Ok(())
}

/// A measurement's record (the core's [`MeasurementRecord`]).
fn measurement_record(m: &Measurement, p: &MeasurementPsd) -> serde_json::Value {
    serde_json::to_value(MeasurementRecord::new(m, p)).expect("a record")
}

/// `surface --measurements ...`: the combined spectrum (`--psd`), the scan
/// over λs (`--scan`) or μ over the whole band, as for a container.
pub fn run_measurements(args: &Args) -> Result<(), Failure> {
    let input = Input::Loose(&args.measurements);
    if args.scale_dependent {
        return run_scale_dependent(args, &input);
    }
    if args.psd {
        return run_psd(args, &input);
    }
    if args.scan {
        return run_scan(args, &input);
    }
    if args.csv {
        return Err(Failure::input(
            "--csv: with --scan or --psd (the single record is --json)",
        ));
    }
    run(args, &input)
}

/// The container's surfaces, read with the instrument flags.
fn read(args: &SurfaceArgs, path: &Input) -> Result<Vec<ContainerSurface>, Failure> {
    // The core's options of a container (the flags a container's meta.yml
    // answers for, --dx, --dy, --channel, refused rather than ignored;
    // --resolution before --tip-radius, as for one file).
    let options = args
        .request()
        .container_options()
        .map_err(|e| request_failure("surface", e))?;
    match path {
        Input::Container(p) => read_container(p, &options).map_err(|e| Failure::of(path.context(), e)),
        Input::Loose(files) => crate::measurements::read(args, files, options).map(|s| vec![s]),
    }
}

/// The request of the flags, its model set-up and its loads, checked
/// (the core's `container_model`, `container_band`).
struct Asked {
    request: SurfaceRequest,
    how: SurfaceModel,
    loads: Vec<Load>,
}

fn asked(args: &Args) -> Result<Asked, Failure> {
    let request = args.request()?;
    let (materials, loads) = request.container_model().map_err(|e| {
        if e.field == Field::File {
            // The materials are missing: the spectra need none.
            let message = e.render(&spell("surface CONTAINER"));
            Failure::classified(format!("{message}; --psd or --scale-dependent need none"), e.kind)
        } else {
            request_failure("surface", e)
        }
    })?;
    // The band's ends checked before the container is read.
    request
        .container_band(&Resolved { ranges: Vec::new() })
        .map_err(|e| request_failure("surface", e))?;
    Ok(Asked {
        how: request.model_of(materials),
        loads,
        request,
    })
}

/// An analysis error, naming the flags to blame.
fn analysis_failure(path: &Input, asked: &Asked, e: AnalysisError) -> Failure {
    request_failure("surface", asked.request.container_failure(&e, &path.to_string()))
}

/// `surface CONTAINER` with the materials: μ from the whole band of the
/// combined spectrum (text, or `--json`: `measurements`, `combined`,
/// `model`, `friction`, `warnings`).
pub fn run(args: &Args, path: &Input) -> Result<(), Failure> {
    if args.from.is_some() || args.to.is_some() {
        return Err(Failure::input(
            "--from, --to: not with a container (its scan runs over λs from the smallest reliable scale)",
        ));
    }
    let asked = asked(args)?;
    let surfaces = read(&args.read, path)?;
    let mut docs = Vec::new();
    let mut warnings = Warnings::new();
    let mut text = Vec::new();
    for s in &surfaces {
        let spectra = measurement_spectra(&s.measurements);
        let resolved = Resolved::of(&spectra);
        let band = asked
            .request
            .container_band(&resolved)
            .map_err(|e| request_failure("surface", e))?;
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
        let names = |idx: &[usize]| -> Vec<String> { idx.iter().map(|&i| s.measurements[i].name.clone()).collect() };
        docs.push(serde_json::to_value(ContainerRecord::new(s, &spectra, &a)).expect("a record"));
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
pub fn run_scan(args: &Args, path: &Input) -> Result<(), Failure> {
    if args.from.is_some() || args.to.is_some() {
        return Err(Failure::input(
            "--from, --to: not with a container (its scan runs over λs from the smallest reliable scale to λc)",
        ));
    }
    if !ke_friction::topography::PER_DECADE.contains(args.per_decade as f64) {
        return Err(Failure::input(format!(
            "--per-decade: {} is out of range: must be {}",
            args.per_decade,
            ke_friction::topography::PER_DECADE.range()
        )));
    }
    let asked = asked(args)?;
    if asked.loads.len() > 1 {
        return Err(Failure::input("--force, --pressure: one load with --scan, not a range"));
    }
    if matches!(args.read.lambda_s, Some(LambdaS::Metres(_))) {
        return Err(Failure::input("--lambda-s: not with --scan (the scan runs over λs)"));
    }
    let surfaces = read(&args.read, path)?;
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
            let record = serde_json::to_value(ScanRecord::new(s, row)).expect("a record");
            let mut cells = vec![
                Shortest(row.band.lambda_s).to_string(),
                Shortest(row.band.lambda_c).to_string(),
                names(&row.measurements).join(" ").replace(',', " "),
            ];
            match &row.result {
                Ok(a) => {
                    warnings.note(a.warnings.iter().cloned());
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
            "# {path}: μ from the combined spectrum over [λs, λc] (m); mu_min..mu_max: μ from each measurement alone"
        )?;
    }
    for line in lines {
        outln!("{line}")?;
    }
    Ok(())
}

/// `plot surface CONTAINER --psd` or `--scan` (or `--measurements`): the
/// page of each surface of the input (a container may hold several: the
/// first is drawn, the others named in a note). `how` and `load` are the
/// scan's materials and load (ψ without a load); `lambda_c` its λc.
pub fn plot_page(
    read_args: &SurfaceArgs,
    path: &Input,
    psd: bool,
    how: Option<&SurfaceModel>,
    load: Option<Load>,
    per_decade: usize,
) -> Result<ke_friction::figures::Page, Failure> {
    use ke_friction::figures::{container_psd_page, container_scan_page, FigureError};
    let figure = |e: FigureError| Failure::of(format!("plot surface {path}"), e);
    let surfaces = read(read_args, path)?;
    let Some(s) = surfaces.first() else {
        return Err(Failure::input(format!(
            "{}: no surface in the container",
            path.context()
        )));
    };
    if surfaces.len() > 1 {
        errln!(
            "note: {}: {} surfaces; the first ({}) is drawn",
            path.context(),
            surfaces.len(),
            s.name.as_deref().unwrap_or("unnamed")
        );
    }
    // A container's surface name, else its file; loose files: their count
    // (the legend names each).
    let title = match (&s.name, path) {
        (Some(name), _) => name.clone(),
        (None, Input::Container(_)) => path.to_string(),
        (None, Input::Loose(files)) => format!("{} measurements (--measurements)", files.len()),
    };
    let spectra: Vec<_> = s.measurements.iter().map(measurement_psd).collect();
    if psd {
        let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE);
        let labelled: Vec<(String, &MeasurementPsd)> = s
            .measurements
            .iter()
            .zip(&spectra)
            .map(|(m, p)| (label(m), p))
            .collect();
        // The filters marked as for one surface (`auto`: the smallest
        // reliable scale of any measurement, the band's default λs).
        let lambda_s = match read_args.lambda_s {
            Some(LambdaS::Metres(v)) => Some(v),
            Some(LambdaS::Auto) => Resolved::of(&spectra).default_band().map(|b| b.lambda_s),
            None => None,
        };
        for (flag, v) in [("--lambda-s", lambda_s), ("--lambda-c", read_args.lambda_c)] {
            if let Some(v) = v.filter(|v| !(v.is_finite() && *v > 0.0)) {
                return Err(Failure::input(format!(
                    "{flag}: {} is out of range: must be > 0 and finite (metres)",
                    Shortest(v)
                )));
            }
        }
        return container_psd_page(
            &title,
            &labelled,
            combined.as_ref().map(|c| &c.psd),
            lambda_s,
            read_args.lambda_c,
        )
        .map_err(figure);
    }
    let Some(how) = how else {
        return Err(Failure::input(
            "plot surface --scan of several measurements: needs the materials (--e1, --nu1, --e2, --nu2, --hardness, --delta-gamma, --epsilon)",
        ));
    };
    if !(1..=1000).contains(&per_decade) {
        return Err(Failure::input(format!(
            "--per-decade: {per_decade} is out of range: 1 to 1000"
        )));
    }
    if let Some(v) = read_args.lambda_c.filter(|v| !(v.is_finite() && *v > 0.0)) {
        return Err(Failure::input(format!(
            "--lambda-c: {} is out of range: must be > 0 and finite (metres)",
            Shortest(v)
        )));
    }
    if read_args.lambda_s.is_some() {
        return Err(Failure::input("--lambda-s: not with --scan (the scan runs over λs)"));
    }
    let loads: Vec<Load> = load.into_iter().collect();
    let rows = container_scan(
        &s.measurements,
        &spectra,
        read_args.lambda_c,
        per_decade as u32,
        how,
        &loads,
    )
    .map_err(|e| match e {
        AnalysisError::Band(_) if read_args.lambda_c.is_some() => Failure::of("--lambda-c", e),
        e => Failure::of(path.context(), e),
    })?;
    let mut warnings = Warnings::new();
    for row in &rows {
        if let Ok(a) = &row.result {
            warnings.note(a.warnings.iter().cloned());
        }
    }
    crate::output::warn(&warnings);
    let names: Vec<String> = s.measurements.iter().map(|m| m.name.clone()).collect();
    container_scan_page(&title, &names, &Resolved::of(&spectra).ranges, &rows).map_err(figure)
}

/// A measurement's legend label: its name and grid (`512 × 512 map`,
/// `3001-point profile`).
fn label(m: &Measurement) -> String {
    match m.grid() {
        (nx, 1) => format!("{} ({nx}-point profile)", m.name),
        (nx, ny) => format!("{} ({nx} × {ny} map)", m.name),
    }
}
