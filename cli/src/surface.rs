//! `kefric surface`: a measured surface (or two) → statistics → the
//! model's inputs (with materials) → μ and the friction force (with a
//! load). The flags that read a surface ([`SurfaceArgs`]) and take a load
//! ([`LoadArgs`]) are shared with `eval` and `plot`.

use crate::args::{named, parse_f64, MaterialsArgs};
use crate::load_args::LoadArgs;
use crate::output::{sig, Failure};
use crate::surface_args::{intervals, request_failure, SurfaceArgs};
use ke_friction::bound::help;
use ke_friction::bounds;
use ke_friction::topography::SCAN_ROWS_MAX;
use ke_friction::topography::{
    Format, Sensitivity, Source, Surface, SurfaceRecord, SurfaceRequest, SurfaceStats, SENSITIVITY_FAMILIES,
};
use ke_friction::{Family, Fit, Friction, Load, Materials, ModelKind, Params, Warnings};
use std::path::PathBuf;

/// Statistics of a measured surface and, with materials and a load, μ.
///
/// Reads a height map or profile (ISO 25178-72 X3P, .npy, text: one
/// column = a profile, a matrix = a map, `x y z` triples on a regular
/// grid; or an instrument's own file: the list below), detrends it, and prints σ (Sq), Sk (Ssk), K (Sku), the spectral
/// moments m0, m2, m4 and the summit density η, radius R and β of
/// MODEL.md §10. Two files are two rough surfaces pressed together: their
/// equivalent surface (heights added) against a flat. With the seven
/// material flags it prints ψ, θ, β, ν, ε* and the height distribution;
/// with --force and --area (or --pressure) also F*, μ, the friction force
/// Q = μF and the separation. β and ψ depend on the sampling intervals,
/// which are printed beside them.
#[derive(Debug, clap::Args)]
#[command(after_help = formats_help())]
pub struct Args {
    /// The surface file, and optionally a second rough surface pressed against it.
    #[arg(value_name = "FILE", num_args = 1..=2, required_unless_present = "measurements")]
    pub files: Vec<PathBuf>,
    /// Files that are measurements of one surface (several instruments or positions), combined as a contact.engineering container's: FILE or FILE@KEY=VALUE,... with KEY one of name, unit, size (100 or 100x80, in unit), height_scale, detrend_mode (center, height, curvature), is_periodic, data_source, tip_radius or resolution (m). Not with FILE.
    #[arg(long, value_name = "FILE[@KEY=VALUE,...]", num_args = 1.., conflicts_with = "files")]
    pub measurements: Vec<String>,
    #[command(flatten)]
    pub read: SurfaceArgs,
    #[command(flatten)]
    pub materials: MaterialsArgs,
    /// Height distribution of the model: pearson (from the measured Ssk, Sku), gaussian, weibull (from Ssk) or empirical (the measured heights) [default: pearson where K <= 4 and its upper tail is supported by the measured heights, else empirical (MODEL.md, "The default height model")].
    #[arg(long, value_parser = named::<Family>())]
    pub distribution: Option<Family>,
    /// Friction row: consistent (MODEL.md §4), or as-printed.
    #[arg(long, value_parser = named::<Fit>(), default_value_t = Fit::Consistent)]
    pub fit: Fit,
    /// Model: ke (Kogut–Etsion), or ceb (the CEB-type comparison model).
    #[arg(long, value_parser = named::<ModelKind>(), default_value_t = ModelKind::KogutEtsion)]
    pub model: ModelKind,
    #[command(flatten)]
    pub load: LoadArgs,
    #[command(flatten)]
    pub sensitivity: SensitivityArg,
    /// Print one JSON object (SI units; the library's record names).
    #[arg(long)]
    pub json: bool,
    /// Print CSV (with --scan, --psd or --scale-dependent): a header line, then one row a scale or wavevector.
    #[arg(long, conflicts_with = "json")]
    pub csv: bool,
    /// μ against the scale: the statistics (with materials: ψ, θ; with a load: μ) at S-filter nesting indices λs log-spaced from --from to --to, one row each, equal to the single command at that --lambda-s.
    #[arg(long, conflicts_with = "psd")]
    pub scan: bool,
    /// The smallest λs of --scan (m) [default: 2·max(dx, dy)].
    #[arg(long, value_name = "M", value_parser = parse_f64, allow_hyphen_values = true, requires = "scan")]
    pub from: Option<f64>,
    /// The largest λs of --scan (m) [default: a tenth of the scan size].
    #[arg(long, value_name = "M", value_parser = parse_f64, allow_hyphen_values = true, requires = "scan")]
    pub to: Option<f64>,
    /// Values a decade of --scan ([`bounds::PER_DECADE`]; at most [`SCAN_ROWS_MAX`] rows).
    #[arg(long, value_name = "N", default_value_t = 5, requires = "scan", help = help("Values a decade of --scan", &bounds::PER_DECADE, &format!("(a scan has at most {SCAN_ROWS_MAX} rows: --from to --to spans at most {}/N decades)", SCAN_ROWS_MAX - 1)))]
    pub per_decade: usize,
    /// The power spectral density of the detrended heights (unfiltered): 1-D along x (and y) averaged over lines, and the radially averaged 2-D PSD of a map, in SurfaceTopography's conventions (q in rad/m; C in m³, or m⁴ for 2-D).
    #[arg(long)]
    pub psd: bool,
    /// A Hann window for --psd.
    #[arg(long, requires = "psd")]
    pub hann: bool,
    /// The scale-dependent rms slope and rms curvature (Sanner et al. 2022) of the heights detrended as the statistics are (--detrend; unfiltered) along x (and y), at stencil lengths log-spaced 5 a decade from 2·max(dx, dy) to half the scan size; with --tip-radius or --resolution, the reliability cut-off in the header. Of a container: the measurements' combined rms slope and curvature along x, 10 lengths a decade, as SurfaceTopography's container computes them, each row naming its measurements.
    #[arg(long, conflicts_with_all = ["psd", "scan"])]
    pub scale_dependent: bool,
}

/// The formats read, one line each, from the library's registry (by the
/// file's extension, else by its content).
fn formats_help() -> String {
    let mut help = String::from("Formats (by the file's extension, else by its content):\n");
    // A format chosen by neither (text read as a matrix) is left out.
    let formats: Vec<Format> = Format::all().filter(|f| !f.extensions().is_empty()).collect();
    let extensions = |f: &Format| {
        f.extensions()
            .iter()
            .map(|e| format!(".{e}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let name_width = formats.iter().map(|f| f.name().len()).max().unwrap_or(0);
    let ext_width = formats.iter().map(|f| extensions(f).len()).max().unwrap_or(0);
    for f in &formats {
        help.push_str(&format!(
            "  {:<name_width$} {:<ext_width$} {}\n",
            f.name(),
            extensions(f),
            f.description()
        ));
    }
    help
}

/// `--sensitivity` (`kefric surface`, `kefric eval --surface`).
#[derive(Debug, clap::Args)]
pub struct SensitivityArg {
    /// μ under each of the core's `SENSITIVITY_FAMILIES` and at the band's ends, or not.
    #[arg(long = "sensitivity", value_enum, default_value_t = OnOff::On, help = sensitivity_help())]
    pub value: OnOff,
}

impl SensitivityArg {
    /// Whether the sensitivity is asked for.
    pub fn on(&self) -> bool {
        self.value == OnOff::On
    }
}

/// `--sensitivity`'s help: the height models by the core's list.
fn sensitivity_help() -> String {
    let families: Vec<&str> = SENSITIVITY_FAMILIES.iter().map(|f| f.name()).collect();
    format!(
        "With a load on a measured surface (for eval, or an F*): μ under each height model ({}) and at the two ends \
         of the reliable band too, beside μ (`off`: the single number, faster)",
        families.join(", ")
    )
}

/// `--sensitivity`: μ under the other height models and at the band's
/// ends beside each μ, or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum OnOff {
    /// Computed and shown.
    On,
    /// Not computed (the single number, faster).
    Off,
}

impl Args {
    /// The request of the flags (the files apart).
    pub fn request(&self) -> Result<SurfaceRequest, Failure> {
        Ok(SurfaceRequest {
            materials: self.materials.values(),
            distribution: self.distribution,
            fit: self.fit,
            model: self.model,
            loads: self.load.inputs()?,
            sensitivity: self.sensitivity.on(),
            ..self.read.request()
        })
    }
}

/// Runs `kefric surface`.
pub fn run(args: Args) -> Result<(), Failure> {
    // --scan, --psd and --scale-dependent run from main.rs (scale.rs), a
    // container from main.rs too (container.rs).
    if args.csv {
        return Err(Failure::input(
            "--csv: with --scan, --psd or --scale-dependent (the single record is --json)",
        ));
    }
    let request = args.request()?;
    let sources: Vec<Source> = args.files.iter().map(|p| Source::Path(p)).collect();
    let analysis = request.run(&sources).map_err(|e| request_failure("surface", e))?;
    for note in &analysis.notes {
        errln!("warning: {}", note.render(&crate::surface_args::spell("surface")));
    }
    crate::output::warn(&analysis.warnings);
    let surface = &analysis.surface;
    let params = analysis.evaluation.as_ref().map(|e| &e.params);
    let friction: &[Friction] = analysis.evaluation.as_ref().map_or(&[], |e| &e.frictions);
    if args.json {
        let files = args.files.iter().map(|p| p.display().to_string()).collect();
        let record = SurfaceRecord::new(files, surface, params, None)
            .with_sensitivity(friction, &analysis.sensitivity, args.load.is_range())
            .with_warnings(&analysis.warnings);
        outln!(
            "{}",
            serde_json::to_string(&record).expect("a surface record serialises")
        )?;
        return Ok(());
    }
    print_text(&args, surface, params, friction, &analysis.sensitivity)
}

/// The model's inputs of `surface` with `materials`, and with loads μ at
/// each; the warnings of the surface and of each result.
pub fn evaluate(
    args: &Args,
    surface: &Surface,
    materials: Option<&Materials>,
    loads: &[Load],
) -> Result<(Option<Params>, Vec<Friction>, Warnings), Failure> {
    let mut warnings = Warnings::new();
    warnings.extend(surface.stats().warnings.iter().cloned());
    let Some(materials) = materials else {
        return Ok((None, Vec::new(), warnings));
    };
    let request = SurfaceRequest {
        sensitivity: false,
        ..args.request()?
    };
    let e = request
        .evaluate(surface, *materials, loads)
        .map_err(|e| request_failure("surface", e))?;
    e.note_into(&mut warnings);
    Ok((Some(e.params), e.frictions, warnings))
}

/// The sensitivity of one μ in a line: the range and which choice gives
/// which end.
pub fn sensitivity_line(s: &Sensitivity) -> Option<String> {
    let ((lo_what, lo), (hi_what, hi)) = s.range()?;
    Some(format!(
        "{} to {} ({lo_what} to {hi_what}; height models {}, band lambda_s {})",
        sig(lo),
        sig(hi),
        SENSITIVITY_FAMILIES.map(|f| f.name()).join("/"),
        s.lambda_s
            .iter()
            .map(|b| format!("{} m", sig(b.lambda_s)))
            .collect::<Vec<_>>()
            .join(" to ")
    ))
}

fn print_text(
    args: &Args,
    surface: &Surface,
    params: Option<&Params>,
    friction: &[Friction],
    sensitivity: &[Sensitivity],
) -> Result<(), Failure> {
    let s = surface.stats();
    let shape = |s: &SurfaceStats| {
        if s.dy.is_some() {
            format!("map {} x {}", s.nx, s.ny)
        } else {
            format!("profile of {}", s.nx)
        }
    };
    for ((_, own), path) in surface.parts().iter().zip(&args.files) {
        outln!(
            "# {}: {}, {}, {} points, {} missing",
            path.display(),
            shape(own),
            intervals(own),
            own.points,
            own.missing
        )?;
    }
    let options = surface.options();
    outln!(
        "# detrend = {}, derivative = {}, lambda_s = {}, lambda_c = {}{}",
        options.detrend,
        options.derivative,
        options.lambda_s.map_or("none".to_string(), |l| format!("{} m", sig(l))),
        options.lambda_c.map_or("none".to_string(), |l| format!("{} m", sig(l))),
        if surface.parts().len() > 1 {
            "; the equivalent surface of the two (heights added)"
        } else {
            ""
        }
    )?;
    let row = |name: &str, value: String, unit: &str| outln!("{name:<28} {value:>14} {unit}");
    let opt = |v: Option<f64>| v.map_or("-".to_string(), |v| sig(v).to_string());
    row("sigma (Sq)", sig(s.sigma).to_string(), "m")?;
    row("skewness (Ssk)", sig(s.skewness).to_string(), "")?;
    row("kurtosis (Sku)", sig(s.kurtosis).to_string(), "")?;
    row("m20, slope x", sig(s.m20).to_string(), "")?;
    row("m02, slope y", opt(s.m02), "")?;
    row("m40, curvature x", sig(s.m40).to_string(), "1/m²")?;
    row("m04, curvature y", opt(s.m04), "1/m²")?;
    row("m2", sig(s.m2).to_string(), "")?;
    row("m4", sig(s.m4).to_string(), "1/m²")?;
    row("alpha (bandwidth)", sig(s.alpha).to_string(), "")?;
    row("eta (summit density)", sig(s.eta).to_string(), "1/m²")?;
    row("R (summit radius)", sig(s.radius).to_string(), "m")?;
    row(
        "beta = eta R sigma",
        sig(s.beta).to_string(),
        &format!("(at {})", intervals(s)),
    )?;
    row("sigma_s (summit heights)", sig(s.sigma_s).to_string(), "m")?;
    row("y_s (mean summit height)", sig(s.y_s).to_string(), "m")?;
    row("m20/m02", opt(s.anisotropy_m2), "")?;
    row("m40/m04", opt(s.anisotropy_m4), "")?;
    if let Some(p) = params {
        outln!("# model inputs (at {}):", intervals(s))?;
        row("psi", sig(p.psi).to_string(), "")?;
        row("theta", sig(p.theta).to_string(), "")?;
        row("beta", sig(p.constants.beta).to_string(), "")?;
        row("nu", sig(p.constants.nu).to_string(), "")?;
        row("eps_star", sig(p.constants.eps_star).to_string(), "")?;
        outln!("{:<28} {}", "heights", p.constants.distribution)?;
    } else {
        outln!("# give the materials (--e1 … --epsilon) for psi and theta, and --force --area for mu")?;
    }
    if friction.len() > 1 || args.load.is_range() {
        return print_loads(friction);
    }
    if let Some(f) = friction.first() {
        match (f.force, f.area) {
            (Some(force), Some(area)) => outln!(
                "# load: F = {} N on A_n = {} m² ({} Pa)",
                sig(force),
                sig(area),
                sig(f.pressure)
            )?,
            _ => outln!("# load: {} Pa", sig(f.pressure))?,
        }
        row("F* = F/(A_n H)", sig(f.contact.f_star).to_string(), "")?;
        row("mu", sig(f.mu).to_string(), "")?;
        if let Some(line) = sensitivity.first().and_then(sensitivity_line) {
            outln!("{:<28} {line}", "mu sensitivity")?;
        }
        match f.friction_force {
            Some(q) => row("Q = mu F (friction force)", sig(q).to_string(), "N")?,
            None => row("mu F/A_n (friction stress)", sig(f.friction_stress).to_string(), "Pa")?,
        }
        row("h* (separation / sigma)", sig(f.contact.h_star).to_string(), "")?;
        row("separation h", sig(f.separation).to_string(), "m")?;
    }
    Ok(())
}

/// The friction of a range of loads: one row a load.
fn print_loads(friction: &[Friction]) -> Result<(), Failure> {
    let by_force = friction.first().is_some_and(|f| f.force.is_some());
    if let Some(area) = friction.first().and_then(|f| f.area) {
        outln!("# loads on A_n = {} m²", sig(area))?;
    }
    let (load, resistance) = if by_force {
        ("F (N)", "Q = mu F (N)")
    } else {
        ("p (Pa)", "mu p (Pa)")
    };
    outln!(
        "{load:>12} {:>12} {:>12} {resistance:>14} {:>12} {:>12}",
        "F*",
        "mu",
        "h*",
        "h (m)"
    )?;
    for f in friction {
        let (l, q) = f.as_given();
        outln!(
            "{:>12} {:>12} {:>12} {:>14} {:>12} {:>12}",
            sig(l).to_string(),
            sig(f.contact.f_star).to_string(),
            sig(f.mu).to_string(),
            sig(q).to_string(),
            sig(f.contact.h_star).to_string(),
            sig(f.separation).to_string()
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{Args as _, Command};
    use ke_friction::topography::{Derivative, Detrend};
    use ke_friction::{LengthUnit, Named};

    /// Every flag naming one of the core's sets takes exactly its names
    /// (in its order) and parses them to its values.
    #[test]
    fn flag_values_are_the_cores_names() {
        fn check<T: Named + std::fmt::Debug + Send + Sync>(command: &Command, id: &str) {
            let arg = command.get_arguments().find(|a| a.get_id() == id).unwrap();
            let names: Vec<String> = arg
                .get_possible_values()
                .iter()
                .map(|p| p.get_name().to_string())
                .collect();
            assert_eq!(names, T::names(), "--{id}");
            for &v in T::all() {
                let flag = format!("--{}", id.replace('_', "-"));
                let m = Args::augment_args(Command::new("t"))
                    .try_get_matches_from(["t", "f", &flag, v.name()])
                    .unwrap();
                assert_eq!(m.get_one::<T>(id), Some(&v), "{flag} {}", v.name());
            }
        }
        let command = Args::augment_args(Command::new("t"));
        check::<Family>(&command, "distribution");
        check::<Fit>(&command, "fit");
        check::<ModelKind>(&command, "model");
        check::<LengthUnit>(&command, "z_unit");
        check::<LengthUnit>(&command, "xy_unit");
        check::<Detrend>(&command, "detrend");
        check::<Derivative>(&command, "derivative");
    }
}
