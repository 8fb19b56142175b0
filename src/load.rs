//! A load in SI units (a force on a nominal area, or a pressure) and the
//! friction it meets: F* = F/(A_n·H) (MODEL.md §1), μ at that F*, the
//! friction force Q = μ·F and the separation h = h*·σ.

use crate::bound::Bound;
use crate::checks::check_in;
use crate::params::PASCALS;

/// The force of a [`Load::Force`]: > 0 N.
pub static FORCE: Bound = Bound::above(0.0).unit("N");
/// The nominal contact area of a [`Load::Force`]: > 0 m².
pub static AREA: Bound = Bound::above(0.0).unit("m²");
/// F* = pressure/hardness: > 0.
pub static F_STAR: Bound = Bound::above(0.0);
/// The loads a front end's range of loads may list (the CLI's
/// `START:STOP:COUNT`): each is a model evaluation, so the count is bounded.
pub static LOAD_COUNT: Bound = Bound::whole(1, 1_000_000);
use crate::{Contact, EvalError, Model, ParamError, Physical, Warning};

/// A normal load on a rough contact, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// A normal force (N) on a nominal contact area A_n (m²).
    Force {
        /// The normal force F, N (> 0).
        force: f64,
        /// The nominal contact area A_n, m² (> 0).
        area: f64,
    },
    /// A nominal pressure F/A_n, Pa (> 0).
    Pressure(f64),
}

impl Load {
    /// The load of a front end's three optional inputs: a force with an
    /// area, or a pressure alone, or none (`None`); any other combination
    /// is [`LoadError::Parts`]. The values are checked by
    /// [`Load::pressure`].
    pub fn from_parts(force: Option<f64>, area: Option<f64>, pressure: Option<f64>) -> Result<Option<Load>, LoadError> {
        match (force, area, pressure) {
            (Some(force), Some(area), None) => Ok(Some(Load::Force { force, area })),
            (None, None, Some(p)) => Ok(Some(Load::Pressure(p))),
            (None, None, None) => Ok(None),
            _ => Err(LoadError::Parts),
        }
    }

    /// The nominal pressure F/A_n (Pa), the load checked: a force and an
    /// area (or a pressure) finite and > 0. F/A_n is rounded to 15
    /// significant digits (what a decimal input such as `1e-5` holds), so
    /// that 10 N on 1e-5 m² is 1e6 Pa, as `--pressure 1e6`, and not
    /// 999999.9999999999 (1e-5 is not exact in binary); a change of at
    /// most 5·10⁻¹⁵ relative.
    ///
    /// ```
    /// use ke_friction::Load;
    /// assert_eq!(Load::Force { force: 10.0, area: 1e-5 }.pressure()?, 1e6);
    /// # Ok::<(), ke_friction::ParamError>(())
    /// ```
    pub fn pressure(&self) -> Result<f64, ParamError> {
        match *self {
            Load::Force { force, area } => {
                check_in("force", force, &FORCE)?;
                check_in("area", area, &AREA)?;
                let p = decimal(force / area);
                check_in("pressure (= force/area)", p, &PASCALS)?;
                Ok(p)
            }
            Load::Pressure(p) => {
                check_in("pressure", p, &PASCALS)?;
                Ok(p)
            }
        }
    }

    /// The dimensionless external force F* = F/(A_n·H) on a softer
    /// material of hardness `hardness` (Pa).
    ///
    /// ```
    /// use ke_friction::Load;
    /// // 10 N on 10 mm² against a hardness of 1 GPa.
    /// let f = Load::Force { force: 10.0, area: 1e-5 }.f_star(1e9)?;
    /// assert!((f - 1e-3).abs() < 1e-15);
    /// # Ok::<(), ke_friction::ParamError>(())
    /// ```
    pub fn f_star(&self, hardness: f64) -> Result<f64, ParamError> {
        f_star_of(self.pressure()?, hardness)
    }

    /// The force F, N (`None` for a pressure).
    pub fn force(&self) -> Option<f64> {
        match *self {
            Load::Force { force, .. } => Some(force),
            Load::Pressure(_) => None,
        }
    }

    /// The friction this load meets on `model`, whose parameters came from
    /// `physical` ([`crate::Params::from_physical`]): F*, the contact at
    /// that F* and, in SI units, the separation and the friction force.
    pub fn friction(&self, model: &Model, physical: &Physical) -> Result<Friction, LoadError> {
        let pressure = self.pressure()?;
        let f_star = f_star_of(pressure, physical.hardness)?;
        let contact = model.at_f_star(f_star)?;
        let mu = contact.mu.ok_or(LoadError::Eval(EvalError::NoMu {
            f_star,
            h_star: contact.h_star,
        }))?;
        Ok(Friction {
            force: self.force(),
            area: match *self {
                Load::Force { area, .. } => Some(area),
                Load::Pressure(_) => None,
            },
            pressure,
            mu,
            friction_force: self.force().map(|f| mu * f),
            friction_stress: mu * pressure,
            separation: contact.h_star * physical.sigma,
            contact,
        })
    }
}

/// `x` rounded to 15 significant digits. Kept here (not a crate): a
/// formatting round trip, exact in Rust's float formatting and parsing.
fn decimal(x: f64) -> f64 {
    if !x.is_finite() {
        return x;
    }
    format!("{x:.14e}").parse().unwrap_or(x)
}

/// F* = `pressure`/`hardness`, checked.
fn f_star_of(pressure: f64, hardness: f64) -> Result<f64, ParamError> {
    check_in("hardness", hardness, &PASCALS)?;
    let f = pressure / hardness;
    check_in("f_star (= pressure/hardness)", f, &F_STAR)?;
    Ok(f)
}

/// The friction a [`Load`] meets ([`Load::friction`]), in SI units and
/// dimensionless: the record `kefric surface --json` prints (flat) and
/// Python's `Surface.friction` returns, with these field names.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Friction {
    /// The normal force F, N (for a [`Load::Force`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub force: Option<f64>,
    /// The nominal area A_n, m² (for a [`Load::Force`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area: Option<f64>,
    /// The nominal pressure F/A_n, Pa.
    pub pressure: f64,
    /// The static friction coefficient μ.
    pub mu: f64,
    /// The static friction force Q = μ·F, N (for a [`Load::Force`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_force: Option<f64>,
    /// The static friction stress μ·F/A_n, Pa.
    pub friction_stress: f64,
    /// The separation of the mean surface heights h = h*·σ, m.
    pub separation: f64,
    /// The dimensionless contact at F* (h*, d*, P*, Fs*, Q*, F*, μ).
    #[serde(flatten)]
    pub contact: Contact,
}

impl Friction {
    /// The load and the friction as the load was given: (F, Q) in newtons
    /// for a force on an area, (p, μp) in pascals for a pressure.
    ///
    /// ```
    /// use ke_friction::{Load, Materials, Model};
    /// let steel = Materials::from_array([200e9, 0.3, 200e9, 0.3, 2e9, 0.5, 0.4e-9]);
    /// let physical = steel.with_roughness(1e-6, 100e-6, 1e9);
    /// let model = Model::new(ke_friction::Params::from_physical(&physical)?)?;
    /// let by_force = Load::Force { force: 100.0, area: 1e-4 }.friction(&model, &physical)?;
    /// assert_eq!(by_force.as_given(), (100.0, by_force.mu * 100.0));
    /// let by_pressure = Load::Pressure(1e6).friction(&model, &physical)?;
    /// assert_eq!(by_pressure.as_given(), (1e6, by_pressure.mu * 1e6));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn as_given(&self) -> (f64, f64) {
        match (self.force, self.friction_force) {
            (Some(force), Some(q)) => (force, q),
            _ => (self.pressure, self.friction_stress),
        }
    }

    /// The plausibility warnings of this result on `model` (the one it
    /// came from, with `physical`): the contact's
    /// ([`Warning::of_contact`]) and, for a force on a known area, too
    /// few asperities in contact ([`Warning::of_asperities`]: η·A_n
    /// summits, those above d* touching).
    pub fn warnings(&self, model: &Model, physical: &Physical) -> impl Iterator<Item = Warning> {
        let few = self
            .area
            .and_then(|a| Warning::of_asperities(model.asperities_in_contact(&self.contact, physical.density * a)));
        Warning::of_contact(&self.contact).chain(few)
    }
}

/// Why a [`Load`] has no friction: a bad load, or the model's error at its F*.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LoadError {
    /// Neither a force with an area nor a pressure alone.
    #[error("give the force with the area, or the pressure alone")]
    Parts,
    /// The force, area, pressure or the F* they give is out of range.
    #[error(transparent)]
    Load(#[from] ParamError),
    /// The model has no μ at that F* (e.g. beyond the largest F*).
    #[error(transparent)]
    Eval(#[from] EvalError),
}

/// The error's kind (the load's, or the model's).
impl crate::Classify for LoadError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            LoadError::Parts => crate::ErrorKind::Argument,
            LoadError::Load(e) => e.kind(),
            LoadError::Eval(e) => e.kind(),
        }
    }
}
