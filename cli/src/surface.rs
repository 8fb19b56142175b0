//! `kefric surface`: a measured surface (or two) → statistics → the
//! model's inputs (with materials) → μ and the friction force (with a
//! load). The flags that read a surface ([`SurfaceArgs`]) and take a load
//! ([`LoadArgs`]) are shared with `eval` and `plot`.

use crate::args::{named, parse_f64, physical_failure, Failure, MaterialsArgs};
use ke_friction::topography::{
    read_dy_defaulting_to_dx, read_file, tip_reliability_cutoff, Channel, Derivative, Detrend, Format, ReadError,
    ReadOptions, StatsOptions, Surface, SurfaceRecord, SurfaceStats, Topography, MAX_POINTS, TIP_SAFETY_FACTOR,
};
use ke_friction::{Family, Fit, Friction, LengthUnit, Load, Materials, Model, ModelKind, Params, Shortest, Warnings};
use std::path::{Path, PathBuf};

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
    #[arg(value_name = "FILE", num_args = 1..=2, required = true)]
    pub files: Vec<PathBuf>,
    #[command(flatten)]
    pub read: SurfaceArgs,
    #[command(flatten)]
    pub materials: MaterialsArgs,
    /// Height distribution of the model: pearson (from the measured Ssk, Sku), gaussian, weibull (from Ssk) or empirical (the measured heights) [default: pearson].
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
    /// Values a decade of --scan.
    #[arg(long, value_name = "N", default_value_t = 5, requires = "scan")]
    pub per_decade: usize,
    /// The power spectral density of the detrended heights (unfiltered): 1-D along x (and y) averaged over lines, and the radially averaged 2-D PSD of a map, in SurfaceTopography's conventions (q in rad/m; C in m³, or m⁴ for 2-D).
    #[arg(long)]
    pub psd: bool,
    /// A Hann window for --psd.
    #[arg(long, requires = "psd")]
    pub hann: bool,
    /// The scale-dependent rms slope and rms curvature (Sanner et al. 2022) of the heights as read (unfiltered, undetrended) along x (and y), at stencil lengths log-spaced 5 a decade from 2·max(dx, dy) to half the scan size; with --tip-radius or --resolution, the reliability cut-off in the header.
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

/// How a surface file is read and its statistics taken.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "Reading a surface")]
pub struct SurfaceArgs {
    /// Sampling interval along x, in --xy-unit (for .npy and text matrices, which have none; X3P, xyz and the instruments' files give their own).
    #[arg(long, value_name = "DX", value_parser = parse_f64, allow_hyphen_values = true)]
    pub dx: Option<f64>,
    /// Sampling interval along y, in --xy-unit [default: --dx].
    #[arg(long, value_name = "DY", value_parser = parse_f64, allow_hyphen_values = true)]
    pub dy: Option<f64>,
    /// Unit of the heights in .npy and text files (X3P and the instruments' files give their own).
    #[arg(long, value_parser = named::<LengthUnit>(), default_value_t = LengthUnit::M)]
    pub z_unit: LengthUnit,
    /// Unit of --dx, --dy and of the x, y columns of xyz text files.
    #[arg(long, value_parser = named::<LengthUnit>(), default_value_t = LengthUnit::M)]
    pub xy_unit: LengthUnit,
    /// Detrending: the least-squares plane (a line for a profile), a line along x, or the mean only.
    #[arg(long, value_parser = named::<Detrend>(), default_value_t = Detrend::Plane)]
    pub detrend: Detrend,
    /// Slope and curvature moments: non-periodic finite differences, or periodic spectral moments (periodic data, no missing points).
    #[arg(long, value_parser = named::<Derivative>(), default_value_t = Derivative::FiniteDifference)]
    pub derivative: Derivative,
    /// The most points (heights) a surface file may have: one that declares more is refused before anything is read or allocated (reading needs about 8 bytes a point) [default: 268435456 = 2^28, 2 GiB of heights].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub max_points: Option<u64>,
    /// The channel to read from a file with several (AFM: height, amplitude, phase, ...): its name or its index from 0 [default: the height channel]; a wrong or ambiguous choice lists the file's channels.
    #[arg(long, value_name = "NAME|N")]
    pub channel: Option<Channel>,
    /// S-filter nesting index λs in metres (ISO 16610-61 Gaussian, 50 % transmission at λs): wavelengths shorter than λs are removed before the statistics; `auto` = the reliability cut-off of --tip-radius or --resolution. At least 2·max(dx, dy).
    #[arg(long, value_name = "M|auto", value_parser = parse_lambda)]
    pub lambda_s: Option<Lambda>,
    /// L-filter nesting index λc in metres (ISO 16610-61 Gaussian): form and waviness longer than λc are removed (the roughness is z minus its Gaussian mean at λc), after the detrending. At most the scan size.
    #[arg(long, value_name = "M", value_parser = parse_f64, allow_hyphen_values = true)]
    pub lambda_c: Option<f64>,
    /// Scanning-probe tip radius (m): the reliability cut-off is the scale below which the scale-dependent curvature reaches −1/(2·R) (Sanner et al. 2022).
    #[arg(long, value_name = "M", value_parser = parse_f64, allow_hyphen_values = true)]
    pub tip_radius: Option<f64>,
    /// The instrument's lateral resolution (m): the reliability cut-off of an optical instrument (takes precedence over --tip-radius).
    #[arg(long, value_name = "M", value_parser = parse_f64, allow_hyphen_values = true)]
    pub resolution: Option<f64>,
}

/// The reliability cut-off of a scanning probe of tip radius `radius` (m)
/// on `t` (safety factor [`TIP_SAFETY_FACTOR`], ½).
fn tip_cutoff(t: &Topography, radius: f64) -> Result<Option<f64>, String> {
    if !(radius.is_finite() && radius > 0.0) {
        return Err(format!(
            "--tip-radius {} is out of range: must be > 0 (metres)",
            Shortest(radius)
        ));
    }
    tip_reliability_cutoff(t, radius, TIP_SAFETY_FACTOR).map_err(|e| e.to_string())
}

/// `--lambda-s`: a length or `auto`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Lambda {
    /// Metres.
    Metres(f64),
    /// The reliability cut-off.
    Auto,
}

fn parse_lambda(s: &str) -> Result<Lambda, String> {
    if s == "auto" {
        Ok(Lambda::Auto)
    } else {
        parse_f64(s).map(Lambda::Metres)
    }
}

impl SurfaceArgs {
    /// The options of the statistics.
    pub fn options(&self) -> StatsOptions {
        StatsOptions {
            detrend: self.detrend,
            derivative: self.derivative,
            lambda_s: None,
            lambda_c: None,
        }
    }

    /// The options of the statistics of `t`: the filters' nesting indices
    /// included (`--lambda-s auto`: the reliability cut-off).
    pub fn options_for(&self, flag: &str, path: &Path, t: &Topography) -> Result<StatsOptions, Failure> {
        let lambda_s = match self.lambda_s {
            None => None,
            Some(Lambda::Metres(m)) => Some(m),
            Some(Lambda::Auto) => match self.reliability(t) {
                Ok(Some(cutoff)) => Some(cutoff),
                Ok(None) => None,
                Err(e) => {
                    return Err(Failure::input(format!(
                        "{flag}: {}: --lambda-s auto: {e}",
                        path.display()
                    )))
                }
            },
        };
        Ok(StatsOptions {
            lambda_s,
            lambda_c: self.lambda_c,
            ..self.options()
        })
    }

    /// The instrument's reliability cut-off (m): --resolution as given, or
    /// from --tip-radius; `None` when the data show no tip artefact.
    pub fn reliability(&self, t: &Topography) -> Result<Option<f64>, String> {
        match (self.resolution, self.tip_radius) {
            (Some(r), _) => Ok(Some(r)),
            (None, Some(radius)) => tip_cutoff(t, radius),
            (None, None) => Err("give --tip-radius or --resolution for the reliability cut-off".into()),
        }
    }

    /// The topography in `path`; `flag` names the input in messages.
    pub fn read(&self, flag: &str, path: &Path) -> Result<ke_friction::topography::Topography, Failure> {
        let metres = self.xy_unit.metres();
        let interval = |name: &str, v: Option<f64>| -> Result<Option<f64>, Failure> {
            match v {
                Some(v) if v <= 0.0 => Err(Failure::input(format!(
                    "--{name}: {} is out of range: must be > 0",
                    Shortest(v)
                ))),
                v => Ok(v.map(|v| v * metres)),
            }
        };
        let dx = interval("dx", self.dx)?;
        let dy = interval("dy", self.dy)?;
        let options = |dy: Option<f64>| ReadOptions {
            dx,
            dy,
            z_unit: self.z_unit.metres(),
            xy_unit: metres,
            max_points: self.max_points.unwrap_or(MAX_POINTS),
            channel: self.channel.clone(),
            ..ReadOptions::default()
        };
        let read = read_dy_defaulting_to_dx(&options(dy), |options| read_file(path, options));
        read.map_err(|e| match e {
            ReadError::NeedInterval { path, name } => Failure::input(format!(
                "{flag}: {}: the file gives no sampling interval {name}: give --dx (and --dy for a map, if it differs), in --xy-unit",
                path.display()
            )),
            ReadError::Conflict {
                path,
                name,
                file,
                option,
            } => Failure::input(format!(
                "{flag}: {}: the file gives {name} = {} m, --{name} {} m: leave --{name} out to use the file's",
                path.display(),
                Shortest(file),
                Shortest(option)
            )),
            e => Failure::of(flag, e),
        })
    }

    /// The surface of one file, or the equivalent surface of two.
    pub fn surface(&self, flag: &str, files: &[PathBuf]) -> Result<Surface, Failure> {
        let stats_failure =
            |e: ke_friction::topography::StatsError, what: String| Failure::of(format!("{flag} {what}"), e);
        let name = |p: &PathBuf| p.display().to_string();
        let one = |p: &PathBuf| {
            let t = self.read(flag, p)?;
            let options = self.options_for(flag, p, &t)?;
            let cutoff = match (self.resolution, self.tip_radius) {
                (None, None) => None,
                _ => self
                    .reliability(&t)
                    .map_err(|e| Failure::input(format!("{flag}: {}: {e}", p.display())))?,
            };
            let mut surface = Surface::new(t, options).map_err(|e| stats_failure(e, name(p)))?;
            if let Some(cutoff) = cutoff {
                surface.check_reliability(cutoff);
            }
            Ok(surface)
        };
        match files {
            [single] => one(single),
            [a, b] => {
                // Each surface's own failure names its file; the pair's
                // (a profile with a map) names both.
                Surface::join(one(a)?, one(b)?).map_err(|e| stats_failure(e, format!("{} + {}", name(a), name(b))))
            }
            _ => Err(Failure::input(format!("{flag}: give one surface file or two"))),
        }
    }
}

/// The load's flags: a force on an area, or a pressure; each one value or
/// a range of loads.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "Load (--force with --area, or --pressure)")]
pub struct LoadArgs {
    /// Normal force F, N (> 0), on the nominal area --area; or START:STOP:COUNT, COUNT forces spaced logarithmically.
    #[arg(
        long,
        value_name = "N|START:STOP:COUNT",
        allow_hyphen_values = true,
        requires = "area",
        conflicts_with = "pressure"
    )]
    pub force: Option<String>,
    /// Nominal contact area A_n, m² (> 0).
    #[arg(long, value_name = "M2", value_parser = parse_f64, allow_hyphen_values = true, requires = "force")]
    pub area: Option<f64>,
    /// Nominal pressure F/A_n, Pa (> 0), in place of --force and --area; or START:STOP:COUNT, spaced logarithmically.
    #[arg(long, value_name = "PA|START:STOP:COUNT", allow_hyphen_values = true)]
    pub pressure: Option<String>,
}

impl LoadArgs {
    /// The flag the load was given by: `--force` or `--pressure`.
    pub fn flag(&self) -> &'static str {
        if self.pressure.is_some() {
            "--pressure"
        } else {
            "--force"
        }
    }

    /// Whether a load is given.
    pub fn any(&self) -> bool {
        self.force.is_some() || self.pressure.is_some()
    }

    /// Whether the load is a range (START:STOP:COUNT).
    pub fn is_range(&self) -> bool {
        self.force
            .as_deref()
            .or(self.pressure.as_deref())
            .is_some_and(|t| t.contains(':'))
    }

    /// The loads, if given: one, or COUNT spaced logarithmically from
    /// START to STOP; each checked (a message names the flag).
    pub fn loads(&self) -> Result<Option<Vec<Load>>, Failure> {
        let flag = self.flag();
        let values = match self.force.as_deref().or(self.pressure.as_deref()) {
            Some(text) => Some(crate::eval::points(flag, text, crate::eval::Spacing::Log)?),
            None => None,
        };
        let (force, pressure) = match (&self.force, &values) {
            (Some(_), Some(v)) => (Some(v.as_slice()), None),
            (None, Some(v)) => (None, Some(v.as_slice())),
            _ => (None, None),
        };
        let n = values.as_ref().map_or(1, Vec::len);
        let mut loads = Vec::with_capacity(n);
        for k in 0..n {
            let Some(load) = Load::from_parts(force.map(|v| v[k]), self.area, pressure.map(|v| v[k]))
                .map_err(|e| Failure::input(format!("--force: {e} (--pressure)")))?
            else {
                return Ok(None);
            };
            load.pressure().map_err(|e| {
                Failure::input(format!(
                    "{}: {e}",
                    crate::args::flag_of(e.name.split(' ').next().unwrap_or(e.name))
                ))
            })?;
            loads.push(load);
        }
        Ok(Some(loads))
    }

    /// The load, if one is given, checked; a range is refused (where one
    /// load is taken: `--scan`).
    pub fn load(&self) -> Result<Option<Load>, Failure> {
        if self.is_range() {
            return Err(Failure::input(format!(
                "{}: one load here, not a range START:STOP:COUNT",
                self.flag()
            )));
        }
        Ok(self.loads()?.and_then(|l| l.into_iter().next()))
    }
}

/// Six significant digits, shortest form: the one format of numbers in
/// text ([`Shortest::sig`]).
pub fn sig(x: f64) -> Shortest {
    Shortest::sig(x)
}

/// The sampling intervals, for beside β and ψ: `dx = 1e-6 m, dy = 1e-6 m`.
pub fn intervals(s: &SurfaceStats) -> String {
    let mut text = match s.dy {
        Some(dy) => format!("dx = {} m, dy = {} m", sig(s.dx), sig(dy)),
        None => format!("dx = {} m", sig(s.dx)),
    };
    // The band, where filtered: β and ψ depend on it as on the intervals.
    for (name, lambda) in [("lambda_s", s.lambda_s), ("lambda_c", s.lambda_c)] {
        if let Some(lambda) = lambda {
            text.push_str(&format!(", {name} = {} m", sig(lambda)));
        }
    }
    text
}

/// The model's inputs for `materials` on `surface` with the distribution
/// `family` asks for (`None`: the surface's default, pearson).
pub fn params(
    surface: &Surface,
    materials: &Materials,
    family: Option<Family>,
    fit: Fit,
    model: ModelKind,
) -> Result<Params, Failure> {
    let distribution = surface.distribution(family.map(Family::name)).map_err(|e| {
        let hint = if family == Some(Family::Empirical) {
            ""
        } else {
            " (try --distribution empirical)"
        };
        Failure::input(format!("--distribution: the surface's {e}{hint}"))
    })?;
    let p = surface
        .params(materials, distribution)
        .map_err(|e| physical_failure(e, "the surface with these materials"))?;
    // Params::from_physical validated it; fit and model change no range.
    Ok(p.fit(fit).kind(model))
}

/// Runs `kefric surface`.
pub fn run(args: Args) -> Result<(), Failure> {
    if args.csv && !(args.scan || args.psd || args.scale_dependent) {
        return Err(Failure::input(
            "--csv: with --scan, --psd or --scale-dependent (the single record is --json)",
        ));
    }
    if args.scale_dependent {
        return crate::scale::run_scale_dependent(&args);
    }
    if args.psd {
        return crate::scale::run_psd(&args);
    }
    if args.scan {
        return crate::scale::run_scan(&args);
    }
    let loads = args.load.loads()?;
    let surface = args.read.surface("surface", &args.files)?;
    let materials = if args.materials.any() {
        Some(args.materials.materials(&[])?)
    } else {
        if let Some(flag) = [
            (args.distribution.is_some(), "--distribution"),
            (loads.is_some(), args.load.flag()),
        ]
        .iter()
        .find_map(|(given, flag)| given.then_some(*flag))
        {
            return Err(Failure::input(format!(
                "{flag}: needs the materials (--e1, --nu1, --e2, --nu2, --hardness, --delta-gamma, --epsilon)"
            )));
        }
        None
    };
    let loads = loads.unwrap_or_default();
    let (params, friction, warnings) = evaluate(&args, &surface, materials.as_ref(), &loads)?;
    crate::args::warn(&warnings);
    if args.json {
        let files = args.files.iter().map(|p| p.display().to_string()).collect();
        let record = SurfaceRecord::new(files, &surface, params.as_ref(), None)
            .with_frictions(&friction, args.load.is_range())
            .with_warnings(&warnings);
        outln!(
            "{}",
            serde_json::to_string(&record).expect("a surface record serialises")
        )?;
        return Ok(());
    }
    print_text(&args, &surface, params.as_ref(), &friction)
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
    let params = materials
        .map(|m| params(surface, m, args.distribution, args.fit, args.model))
        .transpose()?;
    let mut frictions = Vec::with_capacity(loads.len());
    if let (false, Some(p), Some(m)) = (loads.is_empty(), &params, materials) {
        let model =
            Model::new(p.clone()).map_err(|e| Failure::input(format!("the surface with these materials: {e}")))?;
        let physical = surface.physical(m);
        for load in loads {
            let f = load
                .friction(&model, &physical)
                .map_err(|e| Failure::of(args.load.flag(), e))?;
            warnings.note(f.warnings(&model, &physical));
            frictions.push(f);
        }
    }
    Ok((params, frictions, warnings))
}

fn print_text(args: &Args, surface: &Surface, params: Option<&Params>, friction: &[Friction]) -> Result<(), Failure> {
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
        let (l, q) = match (f.force, f.friction_force) {
            (Some(force), Some(q)) => (force, q),
            _ => (f.pressure, f.friction_stress),
        };
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
    use ke_friction::Named;

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
