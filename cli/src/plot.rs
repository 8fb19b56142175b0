//! `kefric plot`: the paper's figures 3–6, a μ(F*) curve, a table's error
//! map, μ(F*) for non-Gaussian heights. PNG or SVG by the output file's extension.

use crate::args::{check_writable, fields, flag_of, load_table, number, output_dir, parse_f64, whole};
use crate::model_args::ModelArgs;
use crate::output::Failure;
use ke_friction::bound::help;
use ke_friction::bounds;
use ke_friction::figures::{self, Figure, FigureError, Format};
use ke_friction::topography::{complete_part, psd_all, scan, Psd, ScanRange, SurfaceModel, Window};
use ke_friction::{Family, LookupError, Shortest};
use std::path::{Path, PathBuf};

/// Draw the paper's figures, a curve, or a table's error map, as PNG or SVG
/// (by the output's extension). Images are 1000 × 750 pixels times
/// --scale (default 2: 2000 × 1500), fonts, lines and markers scaled alike.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    what: What,
}

#[derive(Debug, clap::Subcommand)]
// Parsed once per run: the size of the curve's flags does not matter.
#[allow(clippy::large_enum_variant)]
enum What {
    /// Fig. 3: Fs*/P* against F* for ψ = 0.5, 1, 2, 4, 8 (θ = 0.003).
    Fig3(Out),
    /// Fig. 4: Q* against F* (log–log) for ψ = 0.5, 1, 2, 4, 8 (θ = 0.003).
    Fig4(Out),
    /// Fig. 5: μ against F* for ψ = 0.5, 1, 2 (θ = 0.003), with the CEB-type model dashed.
    Fig5(Out),
    /// Fig. 6: μ against F* for ψ = 0.5 and 2, θ = 1e-4, 1e-3, 3e-3.
    Fig6(Out),
    /// μ against F* for any parameters; with --table, the lookup overlaid and the relative difference below.
    Curve(CurveArgs),
    /// A heat map of a table's relative error of μ over (ψ, F*) at one θ, against direct integration.
    TableError(TableErrorArgs),
    /// μ against F* (1e-5 to 0.1) for Gaussian and Pearson (Sk, K) asperity heights (MODEL.md §9), with their standardised densities g(x) on a log axis below. Not part of `plot all`.
    Distributions(DistributionsArgs),
    /// A measured surface (or two pressed together): μ against F* for its Gaussian, Pearson (measured Ssk, Sku) and empirical height densities, with the materials; below, the histogram of its heights (height/σ, log scale) with the fitted densities. Not part of `plot all`.
    Surface(SurfacePlotArgs),
    /// Write fig3.png … fig6.png (PNG) into a directory.
    All(AllArgs),
}

#[derive(Debug, clap::Args)]
struct Out {
    /// Output file; its extension, .png or .svg (any case), picks the format. Its folder must exist. Written beside it, then renamed over it; a symlink is followed (its target is replaced); an existing device, pipe or directory is refused.
    #[arg(long, value_name = "FILE")]
    out: PathBuf,
    #[command(flatten)]
    scale: Scale,
}

#[derive(Debug, clap::Args)]
struct Scale {
    /// Image size: [`figures::BASE_SIZE`] times N ([`bounds::SCALE`]).
    #[arg(long = "scale", value_name = "N", default_value = "2", allow_hyphen_values = true, help = help(&format!("Image size: {} × {} pixels times N, with fonts, lines and markers scaled alike; N", figures::BASE_SIZE.0, figures::BASE_SIZE.1), &bounds::SCALE, ""))]
    text: String,
}

impl Scale {
    /// The scale, checked ([`bounds::SCALE`]).
    fn get(&self) -> Result<u32, Failure> {
        let n = whole("--scale", &self.text)?;
        let n = u32::try_from(n).unwrap_or(u32::MAX);
        figures::size_at(n).map_err(|e| Failure::input(format!("--scale: {e}")))?;
        Ok(n)
    }
}

#[derive(Debug, clap::Args)]
struct CurveArgs {
    #[command(flatten)]
    model: ModelArgs,
    /// Overlay a table's lookup: `--table` alone for the embedded default table, `--table PATH` for a file. The table must hold --psi and --theta and have been built with the same --beta, --nu, --eps-star, --fit and --model. Without it, direct integration only.
    #[arg(long, value_name = "PATH", num_args = 0..=1)]
    table: Option<Option<PathBuf>>,
    /// Range of F*, LO:HI (0 < LO < HI), at 200 loads spaced logarithmically [default: the paper's range, 0 <= h* <= 3 and F* <= 0.1].
    #[arg(long, value_name = "LO:HI")]
    f_star: Option<String>,
    #[command(flatten)]
    out: Out,
}

#[derive(Debug, clap::Args)]
struct TableErrorArgs {
    /// Table file [default: the embedded default table].
    #[arg(long, value_name = "PATH")]
    table: Option<PathBuf>,
    /// Adhesion parameter θ of the map; must lie in the table's θ range (the embedded table's: 0 to 0.01). The map covers the table's whole ψ and F* ranges (embedded: ψ 0.5 to 8, F* 1e-5 to 0.1) in 64 × 96 cells.
    #[arg(long, value_parser = parse_f64, default_value_t = figures::PAPER_THETA, allow_hyphen_values = true)]
    theta: f64,
    #[command(flatten)]
    out: Out,
}

#[derive(Debug, clap::Args)]
struct DistributionsArgs {
    /// Plasticity index ψ of the μ(F*) panel.
    #[arg(long, value_parser = parse_f64, default_value_t = 1.0, allow_hyphen_values = true)]
    psi: f64,
    /// Adhesion parameter θ of the μ(F*) panel.
    #[arg(long, value_parser = parse_f64, default_value_t = 0.001, allow_hyphen_values = true)]
    theta: f64,
    #[command(flatten)]
    out: Out,
}

#[derive(Debug, clap::Args)]
struct SurfacePlotArgs {
    /// The surface file, and optionally a second rough surface pressed against it (then no histogram: the summed heights are not a sample).
    #[arg(value_name = "FILE", num_args = 1..=2, required_unless_present = "measurements")]
    files: Vec<PathBuf>,
    /// Files that are measurements of one surface, as `kefric surface --measurements`: FILE or FILE@KEY=VALUE,... (with --psd or --scan). Not with FILE.
    #[arg(long, value_name = "FILE[@KEY=VALUE,...]", num_args = 1.., conflicts_with = "files")]
    measurements: Vec<String>,
    #[command(flatten)]
    read: crate::surface_args::SurfaceArgs,
    #[command(flatten)]
    materials: crate::args::MaterialsArgs,
    #[arg(long, value_name = "LO:HI", help = surface_f_star_help())]
    f_star: Option<String>,
    /// Draw the power spectral densities instead (log–log, 2π/λs and 2π/λc marked); no materials needed. A container (or --measurements): each measurement's reliable 1-D PSD in its colour and the combined one.
    #[arg(long, conflicts_with = "scan")]
    psd: bool,
    /// Draw μ (with a load; else ψ), ψ and β against the S-filter's λs instead, from 2·max(dx, dy) to a tenth of the scan size, the reliability cut-off (--tip-radius, --resolution) marked. A container (or --measurements; materials needed): μ of the combined spectrum from the smallest reliable scale, the spread across measurements shaded, the measurements each λs rests on below.
    #[arg(long)]
    scan: bool,
    /// Values a decade of --scan.
    #[arg(long, value_name = "N", default_value_t = 8, requires = "scan")]
    per_decade: usize,
    #[command(flatten)]
    load: crate::load_args::LoadArgs,
    #[command(flatten)]
    out: Out,
}

#[derive(Debug, clap::Args)]
struct AllArgs {
    /// Directory for fig3.png … fig6.png (created, with its parents, if missing; existing files are replaced).
    #[arg(long, value_name = "DIR")]
    out_dir: PathBuf,
    #[command(flatten)]
    scale: Scale,
}

/// `plot surface --f-star`'s help, quoting the library's default range.
fn surface_f_star_help() -> String {
    let (lo, hi) = figures::DISTRIBUTIONS_F_STAR;
    format!(
        "Range of F*, LO:HI (0 < LO < HI), at {} loads spaced logarithmically [default: {}:{}, the library's figures::DISTRIBUTIONS_F_STAR]; or --force START:STOP:COUNT with --area (the axis in newtons) or --pressure START:STOP:COUNT (in pascals), drawn from START to STOP; a single --force or --pressure: the default range in newtons or pascals, widened to hold it.",
        figures::DISTRIBUTIONS_LOADS,
        ke_friction::Shortest(lo),
        ke_friction::Shortest(hi)
    )
}

/// Cells of the error map along ψ and F*.
const MAP_CELLS: (usize, usize) = (64, 96);

/// Runs `kefric plot`.
pub fn run(args: Args) -> Result<(), Failure> {
    match args.what {
        What::Fig3(o) => figure(Figure::Fig3, &o),
        What::Fig4(o) => figure(Figure::Fig4, &o),
        What::Fig5(o) => figure(Figure::Fig5, &o),
        What::Fig6(o) => figure(Figure::Fig6, &o),
        What::Curve(a) => {
            let (out, scale) = output(&a.out)?;
            let model = a.model.model()?;
            let table = a.table.as_ref().map(|path| load_table(path.as_deref())).transpose()?;
            let range = a.f_star.as_deref().map(f_star_range).transpose()?;
            let page = figures::curve_page(&model, table.as_deref(), range).map_err(failure)?;
            // The warnings `eval` gives at the ends of the range drawn.
            if let Some((lo, hi)) = range {
                let mut warnings = ke_friction::Warnings::new();
                for c in [lo, hi].into_iter().filter_map(|f| model.at_f_star(f).ok()) {
                    warnings.note_contact(&c);
                }
                crate::output::warn(&warnings);
            }
            page.save_scaled(out, scale).map_err(failure)?;
            wrote(out)?;
            Ok(())
        }
        What::TableError(a) => {
            let (out, scale) = output(&a.out)?;
            let table = load_table(a.table.as_deref())?;
            let map = figures::table_error(&table, a.theta, MAP_CELLS.0, MAP_CELLS.1).map_err(failure)?;
            map.save_scaled(out, scale).map_err(failure)?;
            wrote(out)?;
            Ok(())
        }
        What::Distributions(a) => {
            let (out, scale) = output(&a.out)?;
            let page = figures::distributions_page(a.psi, a.theta).map_err(failure)?;
            page.save_scaled(out, scale).map_err(failure)?;
            wrote(out)?;
            Ok(())
        }
        What::Surface(a)
            if !a.measurements.is_empty() || (a.files.len() == 1 && crate::container::is_container(&a.files[0])) =>
        {
            measurements_plot(&a)
        }
        What::Surface(a) if a.psd || a.scan => scale_plot(&a),
        What::Surface(a) => {
            let (out, scale) = output(&a.out)?;
            let surface = a.read.surface("surface", &a.files)?;
            let materials = a.materials.materials(&[])?;
            let axis = load_axis(&a, &surface, &materials)?;
            let mut fits = Vec::new();
            for family in [Family::Gaussian, Family::Pearson, Family::Empirical] {
                let how = SurfaceModel {
                    family: Some(family),
                    ..SurfaceModel::new(materials)
                };
                let fit = crate::surface_args::model(&surface, &how);
                match fit {
                    Ok(model) => fits.push((fit_label(family, surface.stats()), model)),
                    // A fit the surface does not admit (e.g. a skewness
                    // beyond Pearson's range) is left out, and said so.
                    Err(f) if family != Family::Gaussian => {
                        errln!("note: no {} fit: {}", family.name(), f.message())
                    }
                    Err(f) => return Err(f),
                }
            }
            let standardised = match surface.parts() {
                [(t, s)] => Some(
                    t.band_heights(&surface.options())
                        .map_err(|e| Failure::of("surface", e))?
                        .into_iter()
                        .map(|z| z / s.sigma)
                        .collect::<Vec<f64>>(),
                ),
                _ => None,
            };
            let names: Vec<String> = a
                .files
                .iter()
                .map(|p| {
                    p.file_name()
                        .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into_owned())
                })
                .collect();
            let intervals = format!("at {}", crate::surface_args::intervals(surface.stats()));
            // The warnings `kefric surface` gives: the surface's, and those
            // of every load drawn of every fit ("N of M results": M = the
            // loads × the fits).
            let mut warnings = ke_friction::Warnings::new();
            warnings.extend(surface.stats().warnings.iter().cloned());
            if let Some((_, model)) = fits.first() {
                warnings.extend(ke_friction::Warning::of_params(model.params()));
            }
            for (_, model) in &fits {
                for f in axis.loads() {
                    if let Ok(c) = model.at_f_star(f / axis.per_f_star) {
                        warnings.note_contact(&c);
                    }
                }
            }
            crate::output::warn(&warnings);
            let page = figures::surface_page(
                &names.join(" + "),
                &intervals,
                standardised.as_deref(),
                &fits,
                Some(&axis),
            )
            .map_err(failure)?;
            page.save_scaled(out, scale).map_err(failure)?;
            wrote(out)?;
            Ok(())
        }
        What::All(a) => {
            let scale = a.scale.get()?;
            output_dir("--out-dir", &a.out_dir)?;
            for path in figures::save_all(&a.out_dir, scale).map_err(failure)? {
                wrote(&path)?;
            }
            Ok(())
        }
    }
}

/// A fit's legend label: its family and, for Pearson, the measured
/// moments it matches (the empirical one matches them too); short, so
/// that the legend leaves the curves room.
fn fit_label(family: Family, stats: &ke_friction::topography::SurfaceStats) -> String {
    match family {
        Family::Pearson => format!(
            "pearson (Ssk {}, Sku {})",
            Shortest::rounded(stats.skewness),
            Shortest::rounded(stats.kurtosis)
        ),
        Family::Empirical => "empirical (the measured heights)".to_string(),
        other => other.name().to_string(),
    }
}

/// `plot surface CONTAINER` (or `--measurements ...`) `--psd` or `--scan`:
/// each measurement's spectrum and the combined one, or μ against λs with
/// its spread and the measurements each λs rests on.
fn measurements_plot(a: &SurfacePlotArgs) -> Result<(), Failure> {
    use crate::container::Input;
    let input = match &a.files[..] {
        [path] => Input::Container(path),
        _ => Input::Loose(&a.measurements),
    };
    if !(a.psd || a.scan) {
        return Err(Failure::input(format!(
            "plot surface {input}: several measurements are drawn with --psd or --scan"
        )));
    }
    if a.f_star.is_some() {
        return Err(Failure::input("--f-star: not with --psd or --scan"));
    }
    let (out, scale) = output(&a.out)?;
    let how = a
        .materials
        .any()
        .then(|| a.materials.materials(&[]))
        .transpose()?
        .map(SurfaceModel::new);
    let load = if a.scan { a.load.load()? } else { None };
    let page = crate::container::plot_page(&a.read, &input, a.psd, how.as_ref(), load, a.per_decade)?;
    page.save_scaled(out, scale).map_err(failure)?;
    wrote(out)
}

/// `plot surface --psd` or `--scan`.
fn scale_plot(a: &SurfacePlotArgs) -> Result<(), Failure> {
    let (out, scale) = output(&a.out)?;
    let [path] = &a.files[..] else {
        return Err(Failure::input("--psd/--scan: take one surface file"));
    };
    let name = path
        .file_name()
        .map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
    let t = a.read.read("surface", path)?;
    let (options, cutoff) = a.read.options_for("surface", path, &t)?;
    let page = if a.psd {
        // Missing points: the largest complete rectangle, said so.
        let (part, rectangle) = complete_part(&t).map_err(|e| Failure::of(format!("--psd: {}", path.display()), e))?;
        if let Some(r) = rectangle {
            errln!("warning: --psd: {}: {r}", path.display());
        }
        let detrended = part
            .detrended_topography(options.detrend)
            .map_err(|e| Failure::of("surface", e))?;
        let spectra =
            psd_all(&detrended, Window::None).map_err(|e| Failure::of(format!("--psd: {}", path.display()), e))?;
        let label = |name| match name {
            "x" => "along x",
            "y" => "along y",
            _ => "area (radial)",
        };
        let spectra: Vec<(&str, &Psd)> = spectra.iter().map(|(n, p)| (label(n), p)).collect();
        figures::psd_page(&name, &spectra, options.lambda_s, options.lambda_c).map_err(failure)?
    } else {
        let load = a.load.load()?;
        let materials = a.materials.any().then(|| a.materials.materials(&[])).transpose()?;
        let cutoff = cutoff.value();
        let range = ScanRange {
            per_decade: a.per_decade,
            ..ScanRange::default_for(&t)
        };
        let rows = scan(&t, &options, &range, cutoff, |_, _| {}).map_err(|e| Failure::of("--scan", e))?;
        let mut points = Vec::with_capacity(rows.len());
        for row in rows {
            let Ok(surface) = row.surface else { continue };
            // ψ wherever the surface has inputs, μ wherever the load has one.
            let how = materials.map(SurfaceModel::new);
            let params = how.as_ref().and_then(|how| surface.model_params(how).ok());
            let mu = how
                .as_ref()
                .zip(load)
                .and_then(|(how, load)| surface.evaluate(how, &[load]).ok())
                .map(|e| e.frictions[0].mu);
            points.push(figures::ScanPoint {
                lambda_s: row.lambda_s,
                mu,
                psi: params.map(|p| p.psi),
                beta: surface.stats().beta,
            });
        }
        figures::scan_page(&name, &points, cutoff).map_err(failure)?
    };
    page.save_scaled(out, scale).map_err(failure)?;
    wrote(out)
}

fn figure(fig: Figure, o: &Out) -> Result<(), Failure> {
    let (out, scale) = output(o)?;
    fig.page().and_then(|p| p.save_scaled(out, scale)).map_err(failure)?;
    wrote(out)?;
    Ok(())
}

/// Checks `--out` and `--scale` before any work: a known extension, a
/// writable place, a valid scale.
fn output(o: &Out) -> Result<(&Path, u32), Failure> {
    let scale = o.scale.get()?;
    Format::from_path(&o.out).map_err(|e| Failure::input(format!("--out: {e}")))?;
    check_writable("--out", &o.out)?;
    Ok((&o.out, scale))
}

/// The μ panel's axis of `plot surface`: F* over `--f-star LO:HI`
/// (default 1e-5:0.1), or the force in newtons (`--force
/// START:STOP:COUNT --area`) or the pressure in pascals (`--pressure
/// START:STOP:COUNT`) from START to STOP.
fn load_axis(
    a: &SurfacePlotArgs,
    surface: &ke_friction::topography::Surface,
    materials: &ke_friction::Materials,
) -> Result<figures::LoadAxis, Failure> {
    let flag = a.load.flag();
    if !a.load.any() {
        let range = a.f_star.as_deref().map(f_star_range).transpose()?;
        return Ok(figures::LoadAxis::f_star(
            range.unwrap_or(ke_friction::figures::DISTRIBUTIONS_F_STAR),
        ));
    }
    if a.f_star.is_some() {
        return Err(Failure::input(format!("--f-star: give it or {flag}, not both")));
    }
    let loads = a.load.loads()?.unwrap_or_default();
    let value = |l: &ke_friction::Load| l.force().unwrap_or_else(|| l.pressure().unwrap_or(f64::NAN));
    let (mut lo, mut hi) = match (loads.first(), loads.last()) {
        (Some(first), Some(last)) => (value(first), value(last)),
        _ => (f64::NAN, f64::NAN),
    };
    // The axis' value at F* = 1: A_n·H newtons, or H pascals.
    let hardness = surface.physical(materials).hardness;
    let (title, per_f_star) = match a.load.area {
        Some(area) if a.load.force.is_some() => ("F (N)", area * hardness),
        _ => ("p (Pa)", hardness),
    };
    let mut mark = None;
    if loads.len() == 1 && lo > 0.0 && lo.is_finite() {
        // One load: the default F* range in this unit, widened to hold it,
        // the load marked on the curves.
        mark = Some(lo);
        let (a, b) = figures::DISTRIBUTIONS_F_STAR;
        (lo, hi) = ((a * per_f_star).min(lo / 2.0), (b * per_f_star).max(hi * 2.0));
    }
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return Err(Failure::input(format!(
            "{flag}: the plot needs a range START:STOP:COUNT with START < STOP, or a single load"
        )));
    }
    Ok(figures::LoadAxis {
        title: title.into(),
        per_f_star,
        range: (lo, hi),
        mark,
    })
}

/// `--f-star LO:HI` of `plot curve`: finite, 0 < LO < HI.
fn f_star_range(text: &str) -> Result<(f64, f64), Failure> {
    let [lo, hi] = fields("--f-star", text, ':', "LO:HI")?;
    let (lo, hi) = (number("--f-star", lo)?, number("--f-star", hi)?);
    if !(lo > 0.0 && lo < hi) {
        return Err(Failure::input(format!("--f-star: '{text}' must have 0 < LO < HI")));
    }
    Ok((lo, hi))
}

fn wrote(path: &Path) -> Result<(), Failure> {
    outln!("wrote {}", path.display())
}

/// Bad input names its flag (exit 2); a failed drawing is exit 1.
fn failure(e: FigureError) -> Failure {
    match &e {
        FigureError::Format { .. } => Failure::input(format!("--out: {e}")),
        FigureError::Scale { .. } => Failure::input(format!("--scale: {e}")),
        FigureError::Params(p) => Failure::input(format!("{}: {e}", flag_of(p.name))),
        FigureError::Lookup(LookupError::OutOfDomain { name, .. }) => Failure::input(format!("{}: {e}", flag_of(name))),
        FigureError::TableMismatch { .. } => Failure::input(format!("--table: {e}")),
        FigureError::Empty(_) => Failure::input(e),
        _ => Failure::of("plot", e),
    }
}
