//! The inputs of a request as errors name them ([`Field`]) and the
//! messages that name them ([`Message`], [`RequestError`]): the core's
//! words, each front end's spelling of the inputs.

use crate::{Classify, ErrorKind};
use std::fmt;

/// One input of a [`SurfaceRequest`](super::SurfaceRequest), as errors name it: each front end
/// spells it its own way (the CLI `--` and the name with `-` for `_`,
/// Python the name as a keyword, the web page its field's label).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Field {
    /// The surface file (or bytes) itself.
    File,
    /// The sampling interval along x.
    Dx,
    /// The sampling interval along y.
    Dy,
    /// The unit of the heights of `.npy` and text files.
    ZUnit,
    /// The unit of the intervals and of text files' x, y columns.
    XyUnit,
    /// The most points a file may have.
    MaxPoints,
    /// The channel of a file with several.
    Channel,
    /// The detrending.
    Detrend,
    /// The derivative of the slope and curvature moments.
    Derivative,
    /// The S-filter's nesting index.
    LambdaS,
    /// The L-filter's nesting index.
    LambdaC,
    /// The scanning probe's tip radius.
    TipRadius,
    /// The instrument's lateral resolution.
    Resolution,
    /// Young's modulus of body 1.
    E1,
    /// Poisson's ratio of body 1.
    Nu1,
    /// Young's modulus of body 2.
    E2,
    /// Poisson's ratio of body 2.
    Nu2,
    /// The softer material's hardness.
    Hardness,
    /// The energy of adhesion.
    DeltaGamma,
    /// The intermolecular distance.
    Epsilon,
    /// The height distribution's family.
    Distribution,
    /// The fit of the model's relations.
    Fit,
    /// The contact law.
    Model,
    /// The normal force.
    Force,
    /// The nominal area.
    Area,
    /// The nominal pressure.
    Pressure,
}

crate::named!(
    Field,
    "input",
    [
        File = "file",
        Dx = "dx",
        Dy = "dy",
        ZUnit = "z_unit",
        XyUnit = "xy_unit",
        MaxPoints = "max_points",
        Channel = "channel",
        Detrend = "detrend",
        Derivative = "derivative",
        LambdaS = "lambda_s",
        LambdaC = "lambda_c",
        TipRadius = "tip_radius",
        Resolution = "resolution",
        E1 = "e1",
        Nu1 = "nu1",
        E2 = "e2",
        Nu2 = "nu2",
        Hardness = "hardness",
        DeltaGamma = "delta_gamma",
        Epsilon = "epsilon",
        Distribution = "distribution",
        Fit = "fit",
        Model = "model",
        Force = "force",
        Area = "area",
        Pressure = "pressure",
    ]
);

impl Field {
    /// The materials' fields, in [`Materials::FIELDS`](crate::Materials::FIELDS)' order.
    pub const MATERIALS: [Field; 7] = [
        Field::E1,
        Field::Nu1,
        Field::E2,
        Field::Nu2,
        Field::Hardness,
        Field::DeltaGamma,
        Field::Epsilon,
    ];

    /// The field of a record name or a parameter's name (`"hardness"`,
    /// `"force"`; a parameter named with words after its name, `"pressure
    /// (= force/area)"`, by its first word).
    pub fn of_name(name: &str) -> Option<Field> {
        let first = name.split([' ', '(']).next().unwrap_or(name);
        Field::ALL.iter().copied().find(|f| f.name() == first)
    }

    /// The CLI's flag of the field: `--` and its name with `-` for `_`
    /// (`--tip-radius`); the CLI and the Python package's messages about
    /// the command line use it.
    pub fn flag(self) -> String {
        format!("--{}", self.name().replace('_', "-"))
    }
}

/// A piece of a [`Message`]: the core's words, or an input named in the
/// front end's spelling.
#[derive(Debug, Clone, PartialEq)]
pub enum Part {
    /// Words.
    Text(String),
    /// An input, spelled by the front end.
    Field(Field),
}

/// A message whose inputs each front end names its own way
/// ([`Message::render`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Message(pub Vec<Part>);

impl Message {
    /// The message of words alone.
    pub fn text(words: impl Into<String>) -> Message {
        Message(vec![Part::Text(words.into())])
    }

    /// The message with `words` after it.
    pub fn then(mut self, words: impl Into<String>) -> Message {
        self.0.push(Part::Text(words.into()));
        self
    }

    /// The message with the input `field` named after it.
    pub fn field(mut self, field: Field) -> Message {
        self.0.push(Part::Field(field));
        self
    }

    /// The message with each input spelled by `spell`.
    pub fn render(&self, spell: &dyn Fn(Field) -> String) -> String {
        self.0
            .iter()
            .map(|p| match p {
                Part::Text(t) => t.clone(),
                Part::Field(f) => spell(*f),
            })
            .collect()
    }
}

/// Inputs named by their record names (`tip_radius`).
impl fmt::Display for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(&|field| field.name().to_string()))
    }
}

/// Why a [`SurfaceRequest`](super::SurfaceRequest) has no answer: the input to blame, the
/// message (which may name other inputs) and the error's kind.
#[derive(Debug, Clone, PartialEq)]
pub struct RequestError {
    /// The input to blame.
    pub field: Field,
    /// Why, in the core's words.
    pub message: Message,
    /// The kind (a bad value, an I/O failure, ...).
    pub kind: ErrorKind,
    /// Memory for the heights could not be had (Python: `MemoryError`).
    pub out_of_memory: bool,
}

impl RequestError {
    pub(super) fn new(field: Field, message: Message, kind: ErrorKind) -> RequestError {
        RequestError {
            field,
            message,
            kind,
            out_of_memory: false,
        }
    }

    pub(super) fn domain(field: Field, message: Message) -> RequestError {
        RequestError::new(field, message, ErrorKind::Domain)
    }

    /// `field: message`, each input spelled by `spell`.
    pub fn render(&self, spell: &dyn Fn(Field) -> String) -> String {
        format!("{}: {}", spell(self.field), self.message.render(spell))
    }
}

/// `field: message`, inputs named by their record names.
impl fmt::Display for RequestError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field.name(), self.message)
    }
}

impl std::error::Error for RequestError {}

impl Classify for RequestError {
    fn kind(&self) -> ErrorKind {
        self.kind
    }
}

impl Message {
    /// The message with `other` after it.
    pub fn then_message(mut self, other: Message) -> Message {
        self.0.extend(other.0);
        self
    }
}
