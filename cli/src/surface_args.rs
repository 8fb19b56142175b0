//! How a surface file is read and its statistics taken (`--dx`, units,
//! filters, `--channel`, …), shared by `surface`, `eval --surface` and
//! `plot surface`; and the model's inputs of a read surface.

use crate::args::{named, parse_f64};
use crate::output::{sig, Failure};
use ke_friction::flags;
use ke_friction::topography::{
    read_dy_defaulting_to_dx, read_file, Channel, Derivative, Detrend, EvaluateError, Evaluation, ReadError,
    ReadOptions, StatsOptions, Surface, SurfaceModel, SurfaceStats, Topography, MAX_POINTS,
};
use ke_friction::{Classify, LengthUnit, Load, Model, Params, Shortest};
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
                Ok(None) => {
                    // Only a tip radius gives none (a resolution is its own cut-off).
                    let radius = self.tip_radius.unwrap_or(f64::NAN);
                    errln!(
                        "warning: {}",
                        flags::auto_without_cutoff(path.display(), flags::LAMBDA_S_TIP_FLAGS, radius)
                    );
                    None
                }
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
        flags::reliability_cutoff(t, self.resolution, self.tip_radius)
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
            ReadError::NeedInterval { path, name } => {
                Failure::input(flags::no_interval(format!("{flag}: {}", path.display()), name))
            }
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

/// [`Surface::evaluate`] with the CLI's failure ([`failure`]).
pub fn evaluate(surface: &Surface, how: &SurfaceModel, loads: &[Load], load_flag: &str) -> Result<Evaluation, Failure> {
    surface.evaluate(how, loads).map_err(|e| failure(e, how, load_flag))
}

/// [`Surface::model_params`] with the CLI's failure.
pub fn params(surface: &Surface, how: &SurfaceModel) -> Result<Params, Failure> {
    surface.model_params(how).map_err(|e| failure(e, how, ""))
}

/// [`Surface::model`] with the CLI's failure.
pub fn model(surface: &Surface, how: &SurfaceModel) -> Result<Model, Failure> {
    surface.model(how).map_err(|e| failure(e, how, ""))
}

/// A failed step of a surface's evaluation in the CLI's words
/// ([`flags::evaluate_failure`]; `load_flag` names a load's) with its
/// error's exit status.
fn failure(e: EvaluateError, how: &SurfaceModel, load_flag: &str) -> Failure {
    Failure::classified(flags::evaluate_failure(&e, how.family, load_flag), e.kind())
}
