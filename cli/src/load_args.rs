//! The load's flags (a force on an area, or a pressure) and the ranges
//! `START:STOP:COUNT` that `eval`, `surface` and `plot` take.

use crate::args::{flag_of, number, parse_f64};
use crate::output::Failure;
use ke_friction::bounds;
use ke_friction::topography::LoadInputs;
use ke_friction::Load;

/// Spacing of the points of a range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spacing {
    /// Equal steps.
    Linear,
    /// Equal ratios (all points > 0).
    Log,
}

/// Parses `X` or `START:STOP:COUNT` into the points; `flag` names the input.
pub fn points(flag: &str, text: &str, spacing: Spacing) -> Result<Vec<f64>, Failure> {
    let bad = |why: String| Failure::input(format!("{flag}: {why}"));
    let parts: Vec<&str> = text.split(':').collect();
    let num = |s: &str| number(flag, s);
    let positive = |v: f64| {
        if spacing == Spacing::Log && v <= 0.0 {
            Err(bad(format!(
                "{} is out of range: must be > 0",
                ke_friction::Shortest(v)
            )))
        } else {
            Ok(v)
        }
    };
    match parts.as_slice() {
        // One value: the core checks its range (its message, as every
        // front end gives it); a range's ends must be > 0 to be spaced.
        [one] => Ok(vec![num(one)?]),
        [a, b, n] => {
            let (a, b) = (positive(num(a)?)?, positive(num(b)?)?);
            let n: usize = n
                .trim()
                .parse()
                .ok()
                .filter(|&n: &usize| bounds::LOAD_COUNT.contains(n as f64))
                .ok_or_else(|| {
                    bad(format!(
                        "COUNT '{n}' is out of range: must be {}",
                        bounds::LOAD_COUNT.range()
                    ))
                })?;
            Ok((0..n)
                .map(|i| {
                    let t = if n == 1 { 0.0 } else { i as f64 / (n - 1) as f64 };
                    match spacing {
                        Spacing::Linear => a + (b - a) * t,
                        Spacing::Log => a * (b / a).powf(t),
                    }
                })
                .collect())
        }
        _ => Err(bad(format!("'{text}' is not a number or START:STOP:COUNT"))),
    }
}

/// The load's flags: a force on an area, or a pressure; each one value or
/// a range of loads.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "Load (--force with --area, or --pressure)")]
pub struct LoadArgs {
    /// Normal force F ([`bounds::FORCE`]) on the nominal area --area, or START:STOP:COUNT.
    #[arg(
        long,
        help = format!("Normal force F ({}), on the nominal area --area; or START:STOP:COUNT, COUNT forces spaced logarithmically.", bounds::FORCE.range()),
        value_name = "N|START:STOP:COUNT",
        allow_hyphen_values = true,
        requires = "area",
        conflicts_with = "pressure"
    )]
    pub force: Option<String>,
    /// Nominal contact area A_n ([`bounds::AREA`]).
    #[arg(long, value_name = "M2", help = format!("Nominal contact area A_n ({}).", bounds::AREA.range()), value_parser = parse_f64, allow_hyphen_values = true, requires = "force")]
    pub area: Option<f64>,
    /// Nominal pressure F/A_n ([`bounds::PASCALS`]), or START:STOP:COUNT.
    #[arg(long, value_name = "PA|START:STOP:COUNT", help = format!("Nominal pressure F/A_n ({}), in place of --force and --area; or START:STOP:COUNT, spaced logarithmically.", bounds::PASCALS.range()), allow_hyphen_values = true)]
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

    /// The loads as given (ranges spaced), for the core's request, which
    /// checks them.
    pub fn inputs(&self) -> Result<LoadInputs, Failure> {
        let spaced = |flag: &str, text: &Option<String>| -> Result<Option<Vec<f64>>, Failure> {
            text.as_deref().map(|t| points(flag, t, Spacing::Log)).transpose()
        };
        Ok(LoadInputs {
            force: spaced("--force", &self.force)?,
            area: self.area,
            pressure: spaced("--pressure", &self.pressure)?,
        })
    }

    /// The loads, if given: one, or COUNT spaced logarithmically from
    /// START to STOP; each checked (a message names the flag).
    pub fn loads(&self) -> Result<Option<Vec<Load>>, Failure> {
        let flag = self.flag();
        let values = match self.force.as_deref().or(self.pressure.as_deref()) {
            Some(text) => Some(points(flag, text, Spacing::Log)?),
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
            load.pressure()
                .map_err(|e| Failure::input(format!("{}: {e}", flag_of(e.name.split(' ').next().unwrap_or(e.name)))))?;
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
