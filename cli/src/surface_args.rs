//! How a surface file is read and its statistics taken (`--dx`, units,
//! filters, `--channel`, …), shared by `surface`, `eval --surface` and
//! `plot surface`; and the model's inputs of a read surface.

use crate::args::{named, parse_f64};
use crate::output::{sig, Failure};
use ke_friction::topography::{
    evaluate_failure, Channel, Cutoff, Derivative, Detrend, EvaluateError, Field, LambdaS, RequestError, Source,
    StatsOptions, Surface, SurfaceModel, SurfaceRequest, SurfaceStats, Topography, MAX_POINTS,
};
use ke_friction::{LengthUnit, Model};
use std::path::{Path, PathBuf};

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
    pub lambda_s: Option<LambdaS>,
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

fn parse_lambda(s: &str) -> Result<LambdaS, String> {
    if s == "auto" {
        Ok(LambdaS::Auto)
    } else {
        parse_f64(s).map(LambdaS::Metres)
    }
}

/// A request's failure in the CLI's words: each input its flag, the file
/// `flag` (the command, `surface`, or `--surface`).
pub fn request_failure(flag: &str, e: RequestError) -> Failure {
    Failure::classified(e.render(&spell(flag)), e.kind)
}

/// The CLI's spelling of a request's inputs: `--` and the name (the file:
/// `flag`).
pub fn spell(flag: &str) -> impl Fn(Field) -> String + '_ {
    move |f| {
        if f == Field::File {
            flag.to_string()
        } else {
            f.flag()
        }
    }
}

impl SurfaceArgs {
    /// The request of these flags (no materials, model or loads yet).
    pub fn request(&self) -> SurfaceRequest {
        SurfaceRequest {
            dx: self.dx,
            dy: self.dy,
            z_unit: self.z_unit.metres(),
            xy_unit: self.xy_unit.metres(),
            max_points: self.max_points.unwrap_or(MAX_POINTS),
            channel: self.channel.clone(),
            detrend: self.detrend,
            derivative: self.derivative,
            lambda_s: self.lambda_s,
            lambda_c: self.lambda_c,
            tip_radius: self.tip_radius,
            resolution: self.resolution,
            ..SurfaceRequest::default()
        }
    }

    /// The options of the statistics (no filters).
    pub fn options(&self) -> StatsOptions {
        StatsOptions {
            detrend: self.detrend,
            derivative: self.derivative,
            lambda_s: None,
            lambda_c: None,
        }
    }

    /// The reliability cut-off of `t` (read from `path`) and the
    /// statistics' options with it (`--lambda-s auto`; a tip radius that
    /// distorts no scale: a warning, no S-filter).
    pub fn options_for(&self, flag: &str, path: &Path, t: &Topography) -> Result<(StatsOptions, Cutoff), Failure> {
        let request = self.request();
        let name = path.display().to_string();
        let cutoff = request.cutoff(t, &name).map_err(|e| request_failure(flag, e))?;
        let options = request
            .stats_options(cutoff, &name)
            .map_err(|e| request_failure(flag, e))?;
        if let Some(note) = request.auto_without_cutoff(cutoff, &name) {
            errln!("warning: {}", note.render(&spell(flag)));
        }
        Ok((options, cutoff))
    }

    /// The topography in `path`; `flag` names the input in messages.
    pub fn read(&self, flag: &str, path: &Path) -> Result<Topography, Failure> {
        let request = self.request();
        request.check().map_err(|e| request_failure(flag, e))?;
        request.read(Source::Path(path)).map_err(|e| request_failure(flag, e))
    }

    /// The surface of one file, or the equivalent surface of two.
    pub fn surface(&self, flag: &str, files: &[PathBuf]) -> Result<Surface, Failure> {
        let request = self.request();
        request.check().map_err(|e| request_failure(flag, e))?;
        let sources: Vec<Source> = files.iter().map(|p| Source::Path(p)).collect();
        let (surface, cutoff) = request.surface(&sources).map_err(|e| request_failure(flag, e))?;
        for source in &sources {
            if let Some(note) = request.auto_without_cutoff(cutoff, &source.name()) {
                errln!("warning: {}", note.render(&spell(flag)));
            }
        }
        Ok(surface)
    }
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

/// [`Surface::model`] with the CLI's failure.
pub fn model(surface: &Surface, how: &SurfaceModel) -> Result<Model, Failure> {
    surface.model(how).map_err(|e| failure(e, how, Field::Force))
}

/// A failed step of a surface's evaluation in the CLI's words (`load`
/// names a load's input).
fn failure(e: EvaluateError, how: &SurfaceModel, load: Field) -> Failure {
    request_failure("surface", evaluate_failure(&e, how.family, load))
}
