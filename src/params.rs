//! Model parameters: dimensionless (MODEL.md §1) or from physical quantities.

use crate::bound::{Bound, End};
use crate::checks::{check_in, ParamError};
use crate::distribution::HeightDistribution;
use crate::gw::{sigma_s_ratio, BETA_MIN};
pub use crate::model::laws::registry::ModelKind;

/// Which Kogut–Etsion friction row to integrate (MODEL.md §6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum Fit {
    /// The self-consistent model of MODEL.md §4: the 1st elastic-plastic
    /// friction row is `1.03·x^1.425·μ_ep(x)`, clipped at the root
    /// `x₀ = 4.2946…` of `μ_ep`. This is the default and what the tables hold.
    #[default]
    Consistent,
    /// The literal printed Eq. 18 of the paper: the factor 0.52 in front of
    /// both rows, and the polynomial integrated unclipped up to `x = 6`.
    /// Offered only to reproduce the printed equation: it gives a negative
    /// Q* (and μ) for ψ ≳ 2.
    AsPrinted,
}

crate::named!(Fit, "fit", [Consistent = "consistent", AsPrinted = "as-printed"]);

/// The former name of [`ModelKind`].
#[deprecated(note = "renamed ModelKind")]
pub type Kind = ModelKind;

/// The model constants of a material pair: everything fixed apart from ψ
/// and θ (MODEL.md §1). A table is built for one set of constants; a
/// [`Model`](crate::Model) evaluates at one ψ, θ with them.
///
/// Field names are the record names every front end uses (JSON keys, the
/// NumPy export's metadata, the Python attributes, the C setters).
///
/// ```
/// use ke_friction::{Constants, Fit};
/// let c = Constants::default().beta(0.05).fit(Fit::Consistent);
/// let p = c.at(1.0, 0.003)?;               // validated parameters at (ψ, θ)
/// assert_eq!((p.psi, p.constants.beta), (1.0, 0.05));
/// assert!(c.at(1.0, -1.0).is_err());        // θ < 0
/// # Ok::<(), ke_friction::ParamError>(())
/// ```
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Constants {
    /// Roughness parameter β = ηRσ, in [`BETA`] (default 0.04).
    pub beta: f64,
    /// Poisson's ratio of the softer material, in [`NU`] (default 0.3).
    pub nu: f64,
    /// Intermolecular distance ε* = ε/σ, in [`EPS_STAR`] (default 0.004).
    pub eps_star: f64,
    /// Which friction row to use (default [`Fit::Consistent`]).
    pub fit: Fit,
    /// Which model to evaluate (default [`ModelKind::KogutEtsion`]); its record
    /// name is `model`.
    #[serde(rename = "model")]
    pub kind: ModelKind,
    /// The asperity heights' distribution (default
    /// [`HeightDistribution::GAUSSIAN`]); its record names are
    /// `distribution`, `skewness` and `kurtosis`.
    #[serde(flatten)]
    pub distribution: HeightDistribution,
}

impl Default for Constants {
    /// β = 0.04, ν = 0.3, ε* = 0.004, [`Fit::Consistent`], [`ModelKind::KogutEtsion`].
    fn default() -> Constants {
        Constants {
            beta: DEFAULT_BETA,
            nu: DEFAULT_NU,
            eps_star: DEFAULT_EPS_STAR,
            fit: Fit::Consistent,
            kind: ModelKind::KogutEtsion,
            distribution: HeightDistribution::GAUSSIAN,
        }
    }
}

impl Constants {
    /// Sets the roughness parameter β.
    pub fn beta(mut self, beta: f64) -> Constants {
        self.beta = beta;
        self
    }

    /// Sets Poisson's ratio ν of the softer material.
    pub fn nu(mut self, nu: f64) -> Constants {
        self.nu = nu;
        self
    }

    /// Sets the intermolecular distance ε*.
    pub fn eps_star(mut self, eps_star: f64) -> Constants {
        self.eps_star = eps_star;
        self
    }

    /// Sets the friction row ([`Fit`]).
    pub fn fit(mut self, fit: Fit) -> Constants {
        self.fit = fit;
        self
    }

    /// Sets the model ([`ModelKind`]).
    pub fn kind(mut self, kind: ModelKind) -> Constants {
        self.kind = kind;
        self
    }

    /// Sets the asperity heights' distribution ([`HeightDistribution`]).
    pub fn distribution(mut self, distribution: HeightDistribution) -> Constants {
        self.distribution = distribution;
        self
    }

    /// The parameters at (ψ, θ) with these constants, validated.
    pub fn at(&self, psi: f64, theta: f64) -> Result<Params, ParamError> {
        let p = self.unchecked_at(psi, theta);
        p.validate()?;
        Ok(p)
    }

    /// The parameters at (ψ, θ), not yet validated (for builders that
    /// validate later, or report the first bad field themselves).
    pub fn unchecked_at(&self, psi: f64, theta: f64) -> Params {
        Params {
            psi,
            theta,
            constants: self.clone(),
        }
    }

    /// Checks every constant against MODEL.md §1 and the numerical limits
    /// documented on the fields.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_in("beta", self.beta, &BETA)?;
        check_in("nu", self.nu, &NU)?;
        check_in("eps_star", self.eps_star, &EPS_STAR)?;
        self.distribution.validate()
    }
}

/// Dimensionless model inputs (MODEL.md §1): ψ, θ and the [`Constants`].
///
/// Built with [`Params::new`] and the builder-style setters, or with
/// [`Constants::at`]; checked once, by [`Model::new`](crate::Model::new).
///
/// ```
/// use ke_friction::{Fit, Params};
/// let p = Params::new(1.0, 0.003).beta(0.05).nu(0.3).eps_star(0.004).fit(Fit::Consistent);
/// assert_eq!((p.psi, p.constants.beta), (1.0, 0.05));
/// ```
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Params {
    /// Plasticity index ψ, in [`PSI`] (the paper covers 0.5–8).
    pub psi: f64,
    /// Adhesion parameter θ = Δγ/(σH), in [`THETA_NON_NEGATIVE`] and
    /// [`THETA_AT_MOST`] (the paper covers 1e-4–0.01).
    pub theta: f64,
    /// The model constants (serialised flat, beside ψ and θ).
    #[serde(flatten)]
    pub constants: Constants,
}

/// Default roughness parameter β (Greenwood & Williamson, as in the paper).
pub const DEFAULT_BETA: f64 = 0.04;
/// Default Poisson's ratio ν.
pub const DEFAULT_NU: f64 = 0.3;
/// Default intermolecular distance ε* (MODEL.md §6, item 3).
pub const DEFAULT_EPS_STAR: f64 = 0.004;

// Upper (and for ψ, ε* lower) limits. MODEL.md §1 only asks ψ, ε* > 0 and
// θ ≥ 0, but far outside these bounds the model degenerates in double
// precision (ω_c* = s/ψ² or r = ε*/ω_c* under- or overflows, Fs* or the load
// prefactor ∝ β overflows) and returns NaN, infinities or roots that are not
// roots. The bounds are decades beyond any physical surface.
/// Smallest accepted ψ.
pub const PSI_MIN: f64 = 1e-3;
/// Largest accepted ψ.
pub const PSI_MAX: f64 = 1e3;
/// Largest accepted θ.
pub const THETA_MAX: f64 = 1e3;
/// Largest accepted β.
pub const BETA_MAX: f64 = 100.0;
/// The accepted ψ: [1e-3, 1e3].
pub static PSI: Bound = Bound::new(End::Closed(PSI_MIN), End::Closed(PSI_MAX));
/// θ >= 0 (checked first: a negative θ is refused as such).
pub static THETA_NON_NEGATIVE: Bound = Bound::at_least(0.0);
/// θ <= 1e3.
pub static THETA_AT_MOST: Bound = Bound::at_most(THETA_MAX);
/// The accepted β: (β_min, 100] (σ_s real, [`BETA_MIN`]).
pub static BETA: Bound = Bound::new(End::Open(BETA_MIN), End::Closed(BETA_MAX));
/// The accepted Poisson's ratio of the softer material: [0, 0.5).
pub static NU: Bound = Bound::new(End::Closed(0.0), End::Open(0.5));
/// The accepted ε*: [1e-9, 100].
pub static EPS_STAR: Bound = Bound::new(End::Closed(EPS_STAR_MIN), End::Closed(EPS_STAR_MAX));
/// The β at which σ_s is real (> [`BETA_MIN`]): what a β computed from
/// physical inputs or a measured surface must satisfy.
pub static BETA_ADMISSIBLE: Bound = Bound::above(BETA_MIN);
/// A modulus, hardness or other pressure of [`Physical`]: > 0 Pa.
pub static PASCALS: Bound = Bound::above(0.0).unit("Pa");
/// A length of [`Physical`]: > 0 m.
pub static METRES: Bound = Bound::above(0.0).unit("m");
/// The areal density of summits: > 0 per m².
pub static DENSITY: Bound = Bound::above(0.0).unit("per m²");
/// The energy of adhesion: >= 0 J/m².
pub static ENERGY: Bound = Bound::at_least(0.0).unit("J/m²");
/// Poisson's ratio of the other (harder) material: [-1, 0.5].
pub static NU2: Bound = Bound::new(End::Closed(-1.0), End::Closed(0.5));
/// Smallest accepted ε*.
pub const EPS_STAR_MIN: f64 = 1e-9;
/// Largest accepted ε*.
pub const EPS_STAR_MAX: f64 = 100.0;

impl Params {
    /// The settings as text, 6 significant digits, with the names the
    /// front ends' flags and fields use (`psi = 1, theta = 0.003, beta =
    /// 0.04, nu = 0.3, eps_star = 0.004, fit = consistent, model = ke`, and
    /// `, heights = …` for non-Gaussian heights): `kefric`'s headers and a
    /// law table's notes.
    pub fn describe(&self) -> String {
        use crate::Shortest;
        let c = &self.constants;
        format!(
            "psi = {}, theta = {}, beta = {}, nu = {}, eps_star = {}, fit = {}, model = {}",
            Shortest::sig(self.psi),
            Shortest::sig(self.theta),
            Shortest::sig(c.beta),
            Shortest::sig(c.nu),
            Shortest::sig(c.eps_star),
            c.fit.name(),
            c.kind.name()
        ) + &if c.distribution.is_gaussian() {
            String::new()
        } else {
            format!(", heights = {}", c.distribution)
        }
    }

    /// Parameters with the default [`Constants`]: β = 0.04, ν = 0.3,
    /// ε* = 0.004, [`Fit::Consistent`] and [`ModelKind::KogutEtsion`].
    pub fn new(psi: f64, theta: f64) -> Params {
        Constants::default().unchecked_at(psi, theta)
    }

    /// Sets the roughness parameter β.
    pub fn beta(mut self, beta: f64) -> Params {
        self.constants.beta = beta;
        self
    }

    /// Sets Poisson's ratio ν of the softer material.
    pub fn nu(mut self, nu: f64) -> Params {
        self.constants.nu = nu;
        self
    }

    /// Sets the intermolecular distance ε*.
    pub fn eps_star(mut self, eps_star: f64) -> Params {
        self.constants.eps_star = eps_star;
        self
    }

    /// Sets the friction row ([`Fit`]).
    pub fn fit(mut self, fit: Fit) -> Params {
        self.constants.fit = fit;
        self
    }

    /// Sets the model ([`ModelKind`]).
    pub fn kind(mut self, kind: ModelKind) -> Params {
        self.constants.kind = kind;
        self
    }

    /// Sets the asperity heights' distribution ([`HeightDistribution`]).
    pub fn distribution(mut self, distribution: HeightDistribution) -> Params {
        self.constants.distribution = distribution;
        self
    }

    /// Replaces all the constants.
    pub fn constants(mut self, constants: Constants) -> Params {
        self.constants = constants;
        self
    }

    /// Checks every field against MODEL.md §1 and the numerical limits
    /// documented on the fields. The one place parameters are validated;
    /// [`Model::new`](crate::Model::new) calls it.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_in("psi", self.psi, &PSI)?;
        check_in("theta", self.theta, &THETA_NON_NEGATIVE)?;
        check_in("theta", self.theta, &THETA_AT_MOST)?;
        self.constants.validate()
    }

    /// Dimensionless parameters from physical (SI) quantities, with the
    /// formulas of MODEL.md §1–2. Material 1 is the softer one: `hardness`
    /// is its hardness and `nu1` sets the hardness coefficient K.
    ///
    /// ```
    /// use ke_friction::{Params, Physical};
    /// // Aluminium on steel, σ = 100 nm, R = 10 µm, β = 0.04.
    /// let phys = Physical {
    ///     e1: 70e9, nu1: 0.33, e2: 210e9, nu2: 0.3, hardness: 1.0e9,
    ///     sigma: 100e-9, radius: 10e-6, density: 0.04 / (10e-6 * 100e-9),
    ///     delta_gamma: 0.3, epsilon: 0.4e-9,
    /// };
    /// let p = Params::from_physical(&phys).unwrap();
    /// assert!((p.constants.beta - 0.04).abs() < 1e-12);
    /// assert!((p.constants.eps_star - 0.004).abs() < 1e-12);
    /// ```
    pub fn from_physical(phys: &Physical) -> Result<Params, ParamError> {
        check_in("e1", phys.e1, &PASCALS)?;
        check_in("e2", phys.e2, &PASCALS)?;
        check_in("nu1", phys.nu1, &NU)?;
        check_in("nu2", phys.nu2, &NU2)?;
        check_in("hardness", phys.hardness, &PASCALS)?;
        check_in("sigma", phys.sigma, &METRES)?;
        check_in("radius", phys.radius, &METRES)?;
        check_in("density", phys.density, &DENSITY)?;
        check_in("delta_gamma", phys.delta_gamma, &ENERGY)?;
        check_in("epsilon", phys.epsilon, &METRES)?;
        let beta = phys.density * phys.radius * phys.sigma;
        check_in("beta (= density·radius·sigma)", beta, &BETA_ADMISSIBLE)?;
        let inv_e = (1.0 - phys.nu1 * phys.nu1) / phys.e1 + (1.0 - phys.nu2 * phys.nu2) / phys.e2;
        let e = 1.0 / inv_e;
        let k = hardness_coefficient(phys.nu1);
        let sigma_s = phys.sigma * sigma_s_ratio(beta);
        let psi = 2.0 * e / (core::f64::consts::PI * k * phys.hardness) * (sigma_s / phys.radius).sqrt();
        let params = Params::new(psi, phys.delta_gamma / (phys.sigma * phys.hardness))
            .beta(beta)
            .nu(phys.nu1)
            .eps_star(phys.epsilon / phys.sigma);
        params.validate()?;
        Ok(params)
    }
}

/// Physical (SI) inputs of the model, for [`Params::from_physical`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Physical {
    /// Young's modulus of material 1 (the softer one), Pa.
    pub e1: f64,
    /// Poisson's ratio of material 1 (the softer one); sets K.
    pub nu1: f64,
    /// Young's modulus of material 2, Pa.
    pub e2: f64,
    /// Poisson's ratio of material 2.
    pub nu2: f64,
    /// Hardness H of the softer material, Pa.
    pub hardness: f64,
    /// Standard deviation σ of the surface heights, m.
    pub sigma: f64,
    /// Asperity radius of curvature R, m.
    pub radius: f64,
    /// Areal density of asperities η, 1/m².
    pub density: f64,
    /// Energy of adhesion Δγ, J/m².
    pub delta_gamma: f64,
    /// Intermolecular distance ε, m.
    pub epsilon: f64,
}

/// The materials and adhesion of two bodies in contact (SI): the
/// [`Physical`] inputs less the roughness (σ, R, η), which a measured
/// surface supplies (`topography::Surface`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Materials {
    /// Young's modulus of material 1 (the softer one), Pa.
    pub e1: f64,
    /// Poisson's ratio of material 1 (the softer one); sets K.
    pub nu1: f64,
    /// Young's modulus of material 2, Pa.
    pub e2: f64,
    /// Poisson's ratio of material 2.
    pub nu2: f64,
    /// Hardness H of the softer material, Pa.
    pub hardness: f64,
    /// Energy of adhesion Δγ, J/m².
    pub delta_gamma: f64,
    /// Intermolecular distance ε, m.
    pub epsilon: f64,
}

impl Materials {
    /// The field names, in order: the record names every front end uses
    /// (the CLI's flags are these with `-` for `_`; the web page's keys;
    /// Python's keyword arguments) and the order of [`from_array`](Self::from_array).
    pub const FIELDS: [&'static str; 7] = ["e1", "nu1", "e2", "nu2", "hardness", "delta_gamma", "epsilon"];

    /// The materials from their values in the order of [`FIELDS`](Self::FIELDS).
    pub const fn from_array(v: [f64; 7]) -> Materials {
        let [e1, nu1, e2, nu2, hardness, delta_gamma, epsilon] = v;
        Materials {
            e1,
            nu1,
            e2,
            nu2,
            hardness,
            delta_gamma,
            epsilon,
        }
    }

    /// The physical inputs of these materials on a surface of roughness
    /// `sigma` (the std of the surface heights, m), `radius` (the summit
    /// radius R, m) and `density` (the summit density η, 1/m²).
    pub fn with_roughness(&self, sigma: f64, radius: f64, density: f64) -> Physical {
        Physical {
            e1: self.e1,
            nu1: self.nu1,
            e2: self.e2,
            nu2: self.nu2,
            hardness: self.hardness,
            sigma,
            radius,
            density,
            delta_gamma: self.delta_gamma,
            epsilon: self.epsilon,
        }
    }
}

/// Hardness coefficient `K = 0.454 + 0.41ν` (MODEL.md §2).
pub(crate) fn hardness_coefficient(nu: f64) -> f64 {
    0.454 + 0.41 * nu
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `FIELDS` are the record's field names in order, and `from_array`
    /// fills them in that order.
    #[test]
    fn materials_fields_are_the_record_names_in_order() {
        let v = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];
        let json = serde_json::to_value(Materials::from_array(v)).unwrap();
        let record = json.as_object().unwrap();
        assert_eq!(record.keys().count(), Materials::FIELDS.len());
        for (name, want) in Materials::FIELDS.iter().zip(v) {
            assert_eq!(record[*name].as_f64(), Some(want), "{name}");
        }
    }

    #[test]
    fn validation_names_the_field_and_range() {
        let err = Params::new(1.0, -0.2).validate().unwrap_err();
        assert_eq!(err.name, "theta");
        assert_eq!(err.to_string(), "theta = -0.2 is out of range: must be >= 0");
        assert_eq!(Params::new(f64::NAN, 0.0).validate().unwrap_err().name, "psi");
        assert_eq!(Params::new(1.0, f64::INFINITY).validate().unwrap_err().name, "theta");
        assert_eq!(Params::new(1.0, 0.0).beta(0.019).validate().unwrap_err().name, "beta");
        assert_eq!(Params::new(1.0, 0.0).nu(0.5).validate().unwrap_err().name, "nu");
        assert_eq!(
            Params::new(1.0, 0.0).eps_star(0.0).validate().unwrap_err().name,
            "eps_star"
        );
        assert!(Params::new(1.0, 0.0).beta(BETA_MIN.next_up()).validate().is_ok());
    }

    #[test]
    fn messages_state_the_bounds() {
        let p = Params::new(1.0, 0.0);
        let text = |r: Result<(), ParamError>| r.unwrap_err().to_string();
        let cases = [
            (
                text(Params::new(0.0, 0.0).validate()),
                "psi = 0 is out of range: must be in [1e-3, 1e3]",
            ),
            (
                text(Params::new(1.0, 2e3).validate()),
                "theta = 2000 is out of range: must be <= 1e3",
            ),
            (
                text(p.clone().nu(0.5).validate()),
                "nu = 0.5 is out of range: must be in [0, 0.5)",
            ),
            (
                text(p.clone().eps_star(1e3).validate()),
                "eps_star = 1000 is out of range: must be in [1e-9, 100]",
            ),
        ];
        for (got, want) in cases {
            assert_eq!(got, want);
        }
        for (v, ok) in [
            (1e-3, true),
            (1e-3f64.next_down(), false),
            (1e3, true),
            (1e3f64.next_up(), false),
        ] {
            assert_eq!(Params::new(v, 0.0).validate().is_ok(), ok, "{v}");
        }
        assert!(Params::new(1.0, -0.0).validate().is_ok());
        assert!(p.clone().nu(0.0).validate().is_ok() && p.clone().nu(0.5f64.next_down()).validate().is_ok());
        assert!(p.clone().eps_star(1e-9).validate().is_ok() && p.clone().eps_star(100.0).validate().is_ok());
    }

    #[test]
    fn beta_is_checked_against_beta_min() {
        let beta = |b: f64| Params::new(1.0, 0.0).beta(b).validate();
        assert_eq!(
            beta(0.019).unwrap_err().to_string(),
            format!("beta = 0.019 is out of range: must be {}", BETA.range())
        );
        assert!(beta(BETA_MIN).is_err() && beta(BETA_MIN.next_up()).is_ok());
        assert!(beta(BETA_MAX).is_ok() && beta(BETA_MAX.next_up()).is_err());
        // σ_s/σ is real exactly above BETA_MIN.
        assert!(sigma_s_ratio(BETA_MIN).is_nan() || sigma_s_ratio(BETA_MIN) == 0.0);
        assert!(sigma_s_ratio(BETA_MIN.next_up()) > 0.0);
    }

    #[test]
    fn derived_constants_match_model_md() {
        // MODEL.md §2: K = 0.577 and σ_s/σ = 0.87618 at the defaults.
        assert!((hardness_coefficient(0.3) - 0.577).abs() < 1e-12);
        assert!((sigma_s_ratio(0.04) - 0.87618).abs() < 5e-6);
    }

    #[test]
    fn physical_inputs_map_to_the_dimensionless_ones() {
        // Equal materials, E = 100 GPa, ν = 0.3: 1/E' = 2(1 − ν²)/E.
        let phys = Physical {
            e1: 100e9,
            nu1: 0.3,
            e2: 100e9,
            nu2: 0.3,
            hardness: 2e9,
            sigma: 50e-9,
            radius: 20e-6,
            density: 0.05 / (20e-6 * 50e-9),
            delta_gamma: 0.5,
            epsilon: 0.3e-9,
        };
        let p = Params::from_physical(&phys).unwrap();
        let e = 100e9 / (2.0 * (1.0 - 0.09));
        let s = sigma_s_ratio(0.05);
        let psi = 2.0 * e / (core::f64::consts::PI * 0.577 * 2e9) * (s * 50e-9 / 20e-6f64).sqrt();
        assert!((p.psi / psi - 1.0).abs() < 1e-12);
        assert!((p.theta - 0.5 / (50e-9 * 2e9)).abs() < 1e-15);
        assert!((p.constants.beta - 0.05).abs() < 1e-12);
        assert!((p.constants.eps_star - 0.006).abs() < 1e-12);
        let bad = Physical { hardness: -1.0, ..phys };
        assert_eq!(Params::from_physical(&bad).unwrap_err().name, "hardness");
        let refused = |phys: Physical| Params::from_physical(&phys).unwrap_err().to_string();
        assert_eq!(
            refused(Physical { e1: -1.0, ..phys }),
            "e1 = -1 is out of range: must be > 0 Pa"
        );
        assert_eq!(
            refused(Physical { nu2: 0.6, ..phys }),
            "nu2 = 0.6 is out of range: must be in [-1, 0.5]"
        );
        assert_eq!(
            refused(Physical { density: 0.0, ..phys }),
            "density = 0 is out of range: must be > 0 per m²"
        );
        assert_eq!(
            refused(Physical {
                delta_gamma: -1.0,
                ..phys
            }),
            "delta_gamma = -1 is out of range: must be >= 0 J/m²"
        );
        assert_eq!(
            refused(Physical { radius: 0.0, ..phys }),
            "radius = 0 is out of range: must be > 0 m"
        );
        let rough = Physical {
            density: 0.019 / (20e-6 * 50e-9),
            ..phys
        };
        let text = Params::from_physical(&rough).unwrap_err().to_string();
        assert!(text.starts_with("beta (= density·radius·sigma) = 0.0190"), "{text}");
        assert!(
            text.ends_with(&format!(" is out of range: must be {}", BETA_ADMISSIBLE.range())),
            "{text}"
        );
    }
}
