//! One analysis request for every front end: what a user asks of a
//! measured surface (the file, how to read it, the filters and the
//! reliability cut-off, the materials, the height model and the loads),
//! checked, read and evaluated once, here. The CLI (`kefric surface`,
//! `eval --surface`, `law --surface`, `plot surface`), the Python package
//! and the web page only translate their inputs into a [`SurfaceRequest`]
//! and a [`Field`] of an error into their own spelling (`--tip-radius`,
//! `tip_radius=`, the page's label): the words of every message are the
//! core's, the names of the inputs the front end's.

use super::{
    read_bytes, read_file, tip_reliability_cutoff, Channel, Derivative, Detrend, EvaluateError, Evaluation, ReadError,
    ReadOptions, StatsError, StatsOptions, Surface, SurfaceModel, Topography, MAX_POINTS, TIP_SAFETY_FACTOR,
};
use crate::{Classify, ErrorKind, Family, Fit, Load, LoadError, Materials, ModelKind, Shortest, Warnings};
use std::path::Path;

mod field;
mod sensitivity;
pub use field::{Field, Message, Part, RequestError};
pub use sensitivity::{band_ends, BandEnd, Outcome, Sensitivity, SENSITIVITY_FAMILIES};

/// The S-filter's nesting index asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LambdaS {
    /// This many metres.
    Metres(f64),
    /// The instrument's reliability cut-off (from the tip radius or the
    /// resolution).
    Auto,
}

/// What is known of an instrument's reliability cut-off (m): nothing
/// (`Unknown`: neither a tip radius nor a resolution was given), or a
/// cut-off that may be `None` (a tip whose radius distorts no scale of
/// the data).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cutoff {
    /// Neither a tip radius nor a resolution given.
    Unknown,
    /// The cut-off (`None`: no scale of the data is distorted).
    Known(Option<f64>),
}

impl Cutoff {
    /// The cut-off, if known and some.
    pub fn value(self) -> Option<f64> {
        match self {
            Cutoff::Unknown => None,
            Cutoff::Known(c) => c,
        }
    }
}

/// Where a surface comes from.
#[derive(Debug, Clone, Copy)]
pub enum Source<'a> {
    /// A file, read as a stream.
    Path(&'a Path),
    /// A file's content in memory (`name`: its name, for the format's
    /// extension and messages).
    Bytes {
        /// The content.
        bytes: &'a [u8],
        /// The file's name.
        name: &'a str,
    },
}

impl Source<'_> {
    /// The name of the source in messages.
    pub fn name(&self) -> String {
        match self {
            Source::Path(p) => p.display().to_string(),
            Source::Bytes { name, .. } => name.to_string(),
        }
    }
}

/// The loads of a request: forces on one area, or pressures.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadInputs {
    /// Normal forces (N), each on `area`.
    pub force: Option<Vec<f64>>,
    /// The nominal area (m²) of the forces.
    pub area: Option<f64>,
    /// Nominal pressures (Pa), in place of forces.
    pub pressure: Option<Vec<f64>>,
}

impl LoadInputs {
    /// One load: a force on an area, or a pressure (or none).
    pub fn one(force: Option<f64>, area: Option<f64>, pressure: Option<f64>) -> LoadInputs {
        LoadInputs {
            force: force.map(|f| vec![f]),
            area,
            pressure: pressure.map(|p| vec![p]),
        }
    }

    /// The input the loads were given by: [`Field::Pressure`] or
    /// [`Field::Force`].
    pub fn field(&self) -> Field {
        if self.pressure.is_some() {
            Field::Pressure
        } else {
            Field::Force
        }
    }

    /// Whether a load is given.
    pub fn any(&self) -> bool {
        self.force.is_some() || self.pressure.is_some()
    }

    /// The loads, each checked (finite, > 0), or `None` when none is
    /// given; an error names the input.
    pub fn loads(&self) -> Result<Option<Vec<Load>>, RequestError> {
        let field = self.field();
        let n = match (&self.force, &self.pressure) {
            (Some(f), None) => f.len(),
            (None, Some(p)) => p.len(),
            (None, None) if self.area.is_none() => return Ok(None),
            _ => 1,
        };
        let mut loads = Vec::with_capacity(n);
        for k in 0..n {
            let pick = |v: &Option<Vec<f64>>| v.as_ref().map(|v| v[k]);
            let load = Load::from_parts(pick(&self.force), self.area, pick(&self.pressure)).map_err(|e| {
                RequestError::domain(
                    Field::Force,
                    Message::text(format!("{e} (")).field(Field::Pressure).then(")"),
                )
            })?;
            let Some(load) = load else { return Ok(None) };
            load.pressure().map_err(|e| {
                let field = Field::of_name(e.name).unwrap_or(field);
                RequestError::new(field, Message::text(e.to_string()), e.kind())
            })?;
            loads.push(load);
        }
        Ok(Some(loads))
    }
}

/// What is asked of one measured surface (or two pressed together): every
/// input of every front end, in SI units where it has one.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceRequest {
    /// The sampling interval along x, in `xy_unit`, for files that give none.
    pub dx: Option<f64>,
    /// The sampling interval along y, in `xy_unit` (default: `dx`, for
    /// files that give none).
    pub dy: Option<f64>,
    /// Metres per unit of the heights of `.npy` and text files.
    pub z_unit: f64,
    /// Metres per unit of `dx`, `dy` and text files' x, y columns.
    pub xy_unit: f64,
    /// The most points a file may have.
    pub max_points: u64,
    /// The channel of a file with several.
    pub channel: Option<Channel>,
    /// The detrending.
    pub detrend: Detrend,
    /// The derivative of the slope and curvature moments.
    pub derivative: Derivative,
    /// The S-filter's nesting index.
    pub lambda_s: Option<LambdaS>,
    /// The L-filter's nesting index (m).
    pub lambda_c: Option<f64>,
    /// The scanning probe's tip radius (m): the reliability cut-off.
    pub tip_radius: Option<f64>,
    /// The instrument's lateral resolution (m): the reliability cut-off
    /// (before the tip radius).
    pub resolution: Option<f64>,
    /// The seven materials' values, in [`Materials::FIELDS`]' order: all
    /// or none.
    pub materials: [Option<f64>; 7],
    /// The heights' family (`None`: [`Surface::DEFAULT_FAMILY`]).
    pub distribution: Option<Family>,
    /// The fit of the model's relations.
    pub fit: Fit,
    /// The contact law.
    pub model: ModelKind,
    /// The loads.
    pub loads: LoadInputs,
    /// With loads: μ under each height model and at the ends of the
    /// band too ([`Sensitivity`]).
    pub sensitivity: bool,
}

impl Default for SurfaceRequest {
    fn default() -> SurfaceRequest {
        SurfaceRequest {
            dx: None,
            dy: None,
            z_unit: 1.0,
            xy_unit: 1.0,
            max_points: MAX_POINTS,
            channel: None,
            detrend: Detrend::Plane,
            derivative: Derivative::FiniteDifference,
            lambda_s: None,
            lambda_c: None,
            tip_radius: None,
            resolution: None,
            materials: [None; 7],
            distribution: None,
            fit: Fit::Consistent,
            model: ModelKind::KogutEtsion,
            loads: LoadInputs::default(),
            sensitivity: true,
        }
    }
}

/// The inputs of a request that need no surface, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Checked {
    /// The materials, if given.
    pub materials: Option<Materials>,
    /// The loads, if given.
    pub loads: Option<Vec<Load>>,
}

/// A measured surface analysed ([`SurfaceRequest::run`]).
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The surface (or the equivalent surface of two).
    pub surface: Surface,
    /// What is known of the reliability cut-off.
    pub cutoff: Cutoff,
    /// The model's inputs and the friction at each load (with materials).
    pub evaluation: Option<Evaluation>,
    /// The statistics' warnings and each load's.
    pub warnings: Warnings,
    /// Each load's sensitivity (with loads, unless switched off).
    pub sensitivity: Vec<Sensitivity>,
    /// What the request did that the user did not ask for in so many
    /// words ([`SurfaceRequest::auto_without_cutoff`]): warnings whose
    /// inputs each front end spells its own way.
    pub notes: Vec<Message>,
}

impl SurfaceRequest {
    /// The interval `field` (`dx`, `dy`) in metres: > 0 where given.
    fn interval(&self, field: Field, value: Option<f64>) -> Result<Option<f64>, RequestError> {
        match value {
            Some(v) if v.is_nan() || v <= 0.0 => Err(RequestError::new(
                field,
                Message::text(format!("{} is out of range: must be > 0", Shortest(v))),
                ErrorKind::of_value(v),
            )),
            v => Ok(v.map(|v| v * self.xy_unit)),
        }
    }

    /// The materials, if given: all seven or none.
    pub fn materials(&self) -> Result<Option<Materials>, RequestError> {
        if self.materials.iter().all(Option::is_none) {
            return Ok(None);
        }
        if let Some(k) = self.materials.iter().position(Option::is_none) {
            let mut message = Message::text("missing: the SI inputs go together (");
            for (i, f) in Field::MATERIALS.iter().enumerate() {
                if i > 0 {
                    message = message.then(", ");
                }
                message = message.field(*f);
            }
            return Err(RequestError::domain(Field::MATERIALS[k], message.then(")")));
        }
        Ok(Some(Materials::from_array(
            self.materials.map(|v| v.unwrap_or_default()),
        )))
    }

    /// The inputs that need no surface, checked: the intervals, the
    /// materials (all or none), the loads, and that a height model or a
    /// load has the materials.
    pub fn check(&self) -> Result<Checked, RequestError> {
        self.interval(Field::Dx, self.dx)?;
        self.interval(Field::Dy, self.dy)?;
        let loads = self.loads.loads()?;
        let materials = self.materials()?;
        if materials.is_none() {
            let needs = if self.distribution.is_some() {
                Some(Field::Distribution)
            } else if loads.is_some() {
                Some(self.loads.field())
            } else {
                None
            };
            if let Some(field) = needs {
                return Err(RequestError::domain(field, materials_needed()));
            }
        }
        for (field, value) in [
            (Field::TipRadius, self.tip_radius),
            (Field::Resolution, self.resolution),
        ] {
            if let Some(v) = value.filter(|v| !(v.is_finite() && *v > 0.0)) {
                return Err(RequestError::new(
                    field,
                    Message::text(format!("{} is out of range: must be > 0 (metres)", Shortest(v))),
                    ErrorKind::of_value(v),
                ));
            }
        }
        Ok(Checked { materials, loads })
    }

    /// The reader's options.
    pub fn read_options(&self) -> Result<ReadOptions, RequestError> {
        Ok(ReadOptions {
            dx: self.interval(Field::Dx, self.dx)?,
            dy: self.interval(Field::Dy, self.dy)?,
            z_unit: self.z_unit,
            xy_unit: self.xy_unit,
            max_points: self.max_points,
            channel: self.channel.clone(),
            ..ReadOptions::default()
        })
    }

    /// The topography of `source`.
    pub fn read(&self, source: Source<'_>) -> Result<Topography, RequestError> {
        let options = self.read_options()?;
        match source {
            Source::Path(path) => read_file(path, &options),
            Source::Bytes { bytes, name } => read_bytes(bytes, name, &options),
        }
        .map_err(|e| read_failure(e, &source.name()))
    }

    /// The reliability cut-off of `t`: the resolution as given, or that of
    /// the tip radius; [`Cutoff::Unknown`] without either.
    pub fn cutoff(&self, t: &Topography, name: &str) -> Result<Cutoff, RequestError> {
        match (self.resolution, self.tip_radius) {
            (None, None) => Ok(Cutoff::Unknown),
            (Some(r), _) => Ok(Cutoff::Known(Some(r))),
            (None, Some(radius)) => tip_reliability_cutoff(t, radius, TIP_SAFETY_FACTOR)
                .map(Cutoff::Known)
                .map_err(|e| RequestError::new(Field::File, Message::text(format!("{name}: {e}")), e.kind())),
        }
    }

    /// The statistics' options with the reliability cut-off `cutoff`
    /// (`lambda_s` auto).
    pub fn stats_options(&self, cutoff: Cutoff, name: &str) -> Result<StatsOptions, RequestError> {
        let lambda_s = match (self.lambda_s, cutoff) {
            (None, _) => None,
            (Some(LambdaS::Metres(m)), _) => Some(m),
            (Some(LambdaS::Auto), Cutoff::Known(c)) => c,
            (Some(LambdaS::Auto), Cutoff::Unknown) => {
                return Err(RequestError::domain(
                    Field::File,
                    Message::text(format!("{name}: "))
                        .field(Field::LambdaS)
                        .then(" auto: ")
                        .then_message(reliability_needed()),
                ))
            }
        };
        Ok(StatsOptions {
            detrend: self.detrend,
            derivative: self.derivative,
            lambda_s,
            lambda_c: self.lambda_c,
        })
    }

    /// The note that `lambda_s` auto applied no S-filter: the tip radius
    /// distorts no scale of `name`'s data (the cut-off is known to be
    /// none). A warning, not a refusal: the unfiltered result is right for
    /// that tip, and an error would fail a batch of files of which some
    /// have a cut-off (issue 49).
    pub fn auto_without_cutoff(&self, cutoff: Cutoff, name: &str) -> Option<Message> {
        if self.lambda_s != Some(LambdaS::Auto) || cutoff != Cutoff::Known(None) {
            return None;
        }
        let radius = self.tip_radius?;
        Some(
            Message::text(format!("{name}: "))
                .field(Field::LambdaS)
                .then(" auto: ")
                .field(Field::TipRadius)
                .then(format!(
                    " {} m distorts no scale of these data (reliability cut-off: none): no S-filter applied \
                     (lambda_s = none)",
                    Shortest(radius)
                )),
        )
    }

    /// The surface of one source, its statistics checked against the
    /// reliability cut-off.
    pub fn part(&self, source: Source<'_>) -> Result<(Surface, Cutoff), RequestError> {
        let t = self.read(source)?;
        self.part_of(t, &source.name())
    }

    /// The surface of the topography `t` (named `name`).
    pub fn part_of(&self, t: Topography, name: &str) -> Result<(Surface, Cutoff), RequestError> {
        let cutoff = self.cutoff(&t, name)?;
        let options = self.stats_options(cutoff, name)?;
        let mut surface = Surface::new(t, options).map_err(|e| stats_failure(e, name))?;
        if let Some(c) = cutoff.value() {
            surface.check_reliability(c);
        }
        Ok((surface, cutoff))
    }

    /// The surface of one source, or the equivalent surface of two.
    pub fn surface(&self, sources: &[Source<'_>]) -> Result<(Surface, Cutoff), RequestError> {
        match sources {
            [one] => self.part(*one),
            [a, b] => {
                let (sa, ca) = self.part(*a)?;
                let (sb, cb) = self.part(*b)?;
                let cutoff = if ca == cb { ca } else { Cutoff::Unknown };
                let surface =
                    Surface::join(sa, sb).map_err(|e| stats_failure(e, &format!("{} + {}", a.name(), b.name())))?;
                Ok((surface, cutoff))
            }
            _ => Err(RequestError::domain(
                Field::File,
                Message::text("give one surface file or two"),
            )),
        }
    }

    /// How the model is set up on the surface, with `materials`.
    pub fn model_of(&self, materials: Materials) -> SurfaceModel {
        SurfaceModel {
            materials,
            family: self.distribution,
            fit: self.fit,
            kind: self.model,
        }
    }

    /// The model's inputs of `surface` and the friction at `loads`
    /// ([`Surface::evaluate`]), an error naming the input to blame.
    pub fn evaluate(
        &self,
        surface: &Surface,
        materials: Materials,
        loads: &[Load],
    ) -> Result<Evaluation, RequestError> {
        surface
            .evaluate(&self.model_of(materials), loads)
            .map_err(|e| evaluate_failure(&e, self.distribution, self.loads.field()))
    }

    /// The request answered: the inputs checked, the surface of `sources`
    /// (one file, or two pressed together) read, its statistics taken and,
    /// with the materials, the model's inputs and, with loads, the
    /// friction at each, its warnings and its sensitivity.
    pub fn run(&self, sources: &[Source<'_>]) -> Result<Analysis, RequestError> {
        let checked = self.check()?;
        let (surface, cutoff) = self.surface(sources)?;
        let mut analysis = self.analyse(surface, cutoff, &checked)?;
        analysis.notes = sources
            .iter()
            .filter_map(|s| self.auto_without_cutoff(cutoff, &s.name()))
            .collect();
        Ok(analysis)
    }

    /// [`run`](Self::run) on a surface already made.
    pub fn analyse(&self, surface: Surface, cutoff: Cutoff, checked: &Checked) -> Result<Analysis, RequestError> {
        let mut warnings = Warnings::new();
        warnings.extend(surface.stats().warnings.iter().cloned());
        let loads = checked.loads.clone().unwrap_or_default();
        let evaluation = match checked.materials {
            None => None,
            Some(materials) => {
                let e = self.evaluate(&surface, materials, &loads)?;
                e.note_into(&mut warnings);
                Some(e)
            }
        };
        let sensitivity = match (&evaluation, checked.materials) {
            (Some(e), Some(materials)) if self.sensitivity && !e.frictions.is_empty() => {
                sensitivity::of(self, &surface, cutoff, materials, &loads, Some(e))
            }
            _ => Vec::new(),
        };
        Ok(Analysis {
            surface,
            cutoff,
            evaluation,
            warnings,
            sensitivity,
            notes: Vec::new(),
        })
    }
}

impl SurfaceRequest {
    /// The sensitivity of each of `loads` on `surface` (whose reliability
    /// cut-off is `cutoff`) with `materials`: μ under each of
    /// [`SENSITIVITY_FAMILIES`] and at the
    /// two ends of the band ([`band_ends`]), the other
    /// choices this request's.
    pub fn sensitivity_of(
        &self,
        surface: &Surface,
        cutoff: Cutoff,
        materials: Materials,
        loads: &[Load],
    ) -> Vec<Sensitivity> {
        sensitivity::of(self, surface, cutoff, materials, loads, None)
    }
}

/// A load or a height model given without the materials.
pub(crate) fn materials_needed() -> Message {
    let mut message = Message::text("needs the materials (");
    for (i, f) in Field::MATERIALS.iter().enumerate() {
        if i > 0 {
            message = message.then(", ");
        }
        message = message.field(*f);
    }
    message.then(")")
}

/// `lambda_s auto` or a reliability check without what gives the cut-off.
pub fn reliability_needed() -> Message {
    Message::text("give ")
        .field(Field::TipRadius)
        .then(" or ")
        .field(Field::Resolution)
        .then(" for the reliability cut-off")
}

/// A reader's failure on the file `name`, naming the input to blame.
fn read_failure(e: ReadError, name: &str) -> RequestError {
    let kind = e.kind();
    if matches!(e, ReadError::OutOfMemory { .. }) {
        return RequestError {
            out_of_memory: true,
            ..RequestError::new(Field::File, Message::text(e.to_string()), kind)
        };
    }
    match e {
        ReadError::NeedInterval { name: which, .. } => {
            let (field, also) = if which == "dy" {
                (Field::Dy, None)
            } else {
                (Field::Dx, Some(Field::Dy))
            };
            let mut m =
                Message::text(format!("{name}: the file gives no sampling interval {which}: give ")).field(field);
            if let Some(also) = also {
                m = m.then(" (and ").field(also).then(" for a map, if it differs)");
            }
            RequestError::new(Field::File, m.then(", in ").field(Field::XyUnit), kind)
        }
        ReadError::Conflict {
            name: which,
            file,
            option,
            ..
        } => {
            let field = if which == "dy" { Field::Dy } else { Field::Dx };
            RequestError::new(
                Field::File,
                Message::text(format!("{name}: the file gives {which} = {} m, ", Shortest(file)))
                    .field(field)
                    .then(format!(" {} m: leave ", Shortest(option)))
                    .field(field)
                    .then(" out to use the file's"),
                kind,
            )
        }
        e => RequestError::new(Field::File, Message::text(e.to_string()), kind),
    }
}

/// The statistics' failure on the surface `name`.
fn stats_failure(e: StatsError, name: &str) -> RequestError {
    RequestError::new(Field::File, Message::text(format!("{name}: {e}")), e.kind())
}

/// A failed step of a surface's evaluation, naming the input to blame
/// (`family`: the height model asked for; `load`: the loads' input).
pub fn evaluate_failure(e: &EvaluateError, family: Option<Family>, load: Field) -> RequestError {
    match e {
        EvaluateError::Distribution(d) => {
            let mut m = Message::text(format!("the surface's {d}"));
            if family != Some(Family::Empirical) {
                m = m
                    .then(" (try ")
                    .field(Field::Distribution)
                    .then(format!(" {})", Family::Empirical.name()));
            }
            RequestError::new(Field::Distribution, m, d.kind())
        }
        EvaluateError::Params(p) => {
            let field = param_field(p.name);
            RequestError::new(
                field.unwrap_or(Field::File),
                Message::text(if field.is_some() {
                    p.to_string()
                } else {
                    format!("{WITH_MATERIALS}: {p}")
                }),
                p.kind(),
            )
        }
        EvaluateError::Model(p) => {
            RequestError::new(Field::File, Message::text(format!("{WITH_MATERIALS}: {p}")), p.kind())
        }
        EvaluateError::Load(l) => {
            let field = match l {
                LoadError::Load(p) => Field::of_name(p.name).unwrap_or(load),
                _ => load,
            };
            RequestError::new(field, Message::text(l.to_string()), l.kind())
        }
    }
}

/// What a measured surface with materials is called in messages.
pub const WITH_MATERIALS: &str = "the surface with these materials";

/// The input to blame for a parameter named `name` out of range: β's
/// bound is the summit density's (none on a measured surface: the
/// surface as a whole), a derived parameter (ψ, θ, ν, ε*) the surface's
/// with its materials (`None`), any other its own field.
pub fn param_field(name: &str) -> Option<Field> {
    match name {
        n if n.starts_with("beta") => None,
        "psi" | "theta" | "nu" | "eps_star" => None,
        n => Field::of_name(n),
    }
}

#[cfg(test)]
mod tests;
