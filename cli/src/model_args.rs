//! The model's flags shared by `eval`, `law` and `plot`: ψ and θ
//! (with the constants), the SI inputs, or a measured surface with the
//! materials. Apart from `args.rs` so that the shared flags (`args`) and
//! the measured surface's (`surface`) depend on nothing of each other.

use crate::args::{flag_of, parse_f64, ConstantsArgs, SiArgs};
use crate::output::{warn, Failure};
use crate::surface_args::request_failure;
use ke_friction::bound::help;
use ke_friction::bounds;
use ke_friction::topography::{Cutoff, Sensitivity, Source, Surface, SurfaceRequest};
use ke_friction::{Load, Materials, Model, Params, Physical, Shortest, Warnings};

/// The model's parameters, shared by the subcommands that evaluate it:
/// dimensionless (ψ, θ, β, ν, ε*) or SI quantities ([`SiArgs`]).
#[derive(Debug, Clone, clap::Args)]
pub struct ModelArgs {
    /// Plasticity index ψ ([`bounds::PSI`]). Required unless the SI inputs are given.
    #[arg(long, help = help("Plasticity index ψ", &bounds::PSI, "(the paper: 0.5 to 8). Required unless the SI inputs are given."), value_parser = parse_f64, allow_hyphen_values = true)]
    pub psi: Option<f64>,
    /// Adhesion parameter θ = Δγ/(σH) ([`bounds::THETA_AT_MOST`]). Required unless the SI inputs are given.
    #[arg(long, help = format!("Adhesion parameter θ = Δγ/(σH), {} and {} (the paper: 1e-4 to 0.01). Required unless the SI inputs are given.", bounds::THETA_NON_NEGATIVE.range(), bounds::THETA_AT_MOST.range()), value_parser = parse_f64, allow_hyphen_values = true)]
    pub theta: Option<f64>,
    #[command(flatten)]
    pub constants: ConstantsArgs,
    #[command(flatten)]
    pub si: SiArgs,
    /// A measured surface (X3P, .npy, text or an instrument's own file, see `kefric surface --help`; give it twice for two rough surfaces pressed together): sigma, R, eta and the height distribution (--distribution, default pearson from its Ssk and Sku where K <= 4 and its tail is supported, else empirical) come from it, with the seven material flags (--e1 … --epsilon). See `kefric surface`.
    #[arg(long, value_name = "FILE", action = clap::ArgAction::Append)]
    pub surface: Vec<std::path::PathBuf>,
    #[command(flatten)]
    pub read: crate::surface_args::SurfaceArgs,
}

impl ModelArgs {
    /// The parameters, and where σ, R and η came from when a surface gave
    /// them (`sigma, R, eta of FILE at dx = …`: β and ψ hold at those
    /// sampling intervals only, so outputs print it beside them).
    pub fn params_and_source(&self) -> Result<(Params, Option<SurfaceSource>), Failure> {
        if !self.surface.is_empty() {
            return self.surface_params().map(|(p, source)| (p, Some(source)));
        }
        let params = if self.si.any() {
            let dimensionless = [("--psi", self.psi), ("--theta", self.theta)];
            if let Some((flag, _)) = dimensionless
                .iter()
                .chain(&self.constants.given())
                .find(|(_, v)| v.is_some())
            {
                return Err(Failure::input(format!(
                    "{flag}: give either the dimensionless inputs or the SI inputs, not both"
                )));
            }
            self.si.params()?
        } else {
            let required = |flag: &str, v: Option<f64>| {
                v.ok_or_else(|| Failure::input(format!("{flag}: required (or give the SI inputs, see --help)")))
            };
            self.constants
                .constants()?
                .unchecked_at(required("--psi", self.psi)?, required("--theta", self.theta)?)
        };
        let c = self.constants.constants()?;
        Ok((params.fit(c.fit).kind(c.kind).distribution(c.distribution), None))
    }

    /// The parameters of `--surface` with the materials: the flags the
    /// surface supplies (σ, R, η, the distribution's moments) and the
    /// dimensionless ones are refused beside it.
    fn surface_params(&self) -> Result<(Params, SurfaceSource), Failure> {
        let h = &self.constants.heights;
        let supplied = [
            ("--psi", self.psi.is_some()),
            ("--theta", self.theta.is_some()),
            ("--beta", self.constants.beta.is_some()),
            ("--nu", self.constants.nu.is_some()),
            ("--eps-star", self.constants.eps_star.is_some()),
            ("--sigma", self.si.sigma.is_some()),
            ("--radius", self.si.radius.is_some()),
            ("--density", self.si.density.is_some()),
            ("--skewness", h.skewness.is_some()),
            ("--kurtosis", h.kurtosis.is_some()),
            ("--heights", h.heights.is_some()),
        ];
        if let Some((flag, _)) = supplied.iter().find(|(_, given)| *given) {
            return Err(Failure::input(format!(
                "{flag}: the surface supplies it: give --surface with the seven material flags only"
            )));
        }
        let materials = self.si.materials.materials(&[])?;
        let request = SurfaceRequest {
            materials: self.si.materials.values(),
            distribution: h.distribution,
            fit: self.constants.fit,
            model: self.constants.model,
            ..self.read.request()
        };
        let flag = "--surface";
        request.check().map_err(|e| request_failure(flag, e))?;
        let sources: Vec<Source> = self.surface.iter().map(|p| Source::Path(p)).collect();
        let (surface, cutoff) = request.surface(&sources).map_err(|e| request_failure(flag, e))?;
        let mut warnings = Warnings::new();
        warnings.extend(surface.stats().warnings.iter().cloned());
        warn(&warnings);
        let params = request
            .evaluate(&surface, materials, &[])
            .map_err(|e| request_failure(flag, e))?
            .params;
        let source = SurfaceSource {
            physical: surface.physical(&materials),
            files: self.surface.iter().map(|p| p.display().to_string()).collect(),
            dx: surface.stats().dx,
            dy: surface.stats().dy,
            lambda_s: surface.stats().lambda_s,
            lambda_c: surface.stats().lambda_c,
            analysis: Box::new((request, surface, cutoff, materials)),
        };
        Ok((params, source))
    }

    /// The SI quantities behind the model (the hardness and σ a load in
    /// newtons or pascals needs): the surface's with the materials, or the
    /// SI inputs; `None` for dimensionless inputs.
    pub fn physical(&self, source: Option<&SurfaceSource>) -> Result<Option<Physical>, Failure> {
        if let Some(source) = source {
            return Ok(Some(source.physical));
        }
        if !self.si.any() {
            return Ok(None);
        }
        let materials = self.si.materials.materials(&self.si.roughness())?;
        let [sigma, radius, density] = self.si.roughness().map(|(_, v)| v.unwrap_or_default());
        Ok(Some(materials.with_roughness(sigma, radius, density)))
    }

    /// The validated model, or a message naming the offending flag.
    pub fn model(&self) -> Result<Model, Failure> {
        self.model_and_source().map(|(m, _)| m)
    }

    /// The validated model and where σ, R and η came from
    /// ([`ModelArgs::params_and_source`]).
    pub fn model_and_source(&self) -> Result<(Model, Option<SurfaceSource>), Failure> {
        let (params, source) = self.params_and_source()?;
        let model = Model::new(params).map_err(|e| {
            let flag = if !self.surface.is_empty() {
                ke_friction::topography::WITH_MATERIALS.to_string()
            } else if self.si.any() {
                "SI inputs".to_string()
            } else {
                flag_of(e.name)
            };
            Failure::input(format!("{flag}: {e}"))
        })?;
        Ok((model, source))
    }
}

/// The measured surface that gave σ, R and η (`--surface`), and its
/// sampling intervals (named as in the surface record), at which alone
/// the β and ψ it gives hold.
#[derive(Debug, Clone, serde::Serialize)]
pub struct SurfaceSource {
    /// The surface's σ, R, η with the materials (for a load in SI units).
    #[serde(skip)]
    pub physical: Physical,
    /// The surface files.
    #[serde(rename = "surface")]
    pub files: Vec<String>,
    /// Sampling interval along x (m).
    pub dx: f64,
    /// Sampling interval along y (m), for a map.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dy: Option<f64>,
    /// The S-filter's nesting index (m), if filtered.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda_s: Option<f64>,
    /// The L-filter's nesting index (m), if filtered.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda_c: Option<f64>,
    /// The request, the surface, its reliability cut-off and the
    /// materials (for the sensitivity of a μ).
    #[serde(skip)]
    pub analysis: Box<(SurfaceRequest, Surface, Cutoff, Materials)>,
}

impl SurfaceSource {
    /// The sensitivity of μ at each F* of `f_star` on this surface.
    pub fn sensitivity(&self, f_star: impl Iterator<Item = f64>) -> Vec<Sensitivity> {
        let (request, surface, cutoff, materials) = &*self.analysis;
        let loads: Vec<Load> = f_star.map(|f| Load::Pressure(f * self.physical.hardness)).collect();
        request.sensitivity_of(surface, *cutoff, *materials, &loads)
    }
}

impl std::fmt::Display for SurfaceSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "sigma, R, eta of {} at dx = {} m",
            self.files.join(" + "),
            Shortest(self.dx)
        )?;
        if let Some(dy) = self.dy {
            write!(f, ", dy = {} m", Shortest(dy))?;
        }
        for (name, lambda) in [("lambda_s", self.lambda_s), ("lambda_c", self.lambda_c)] {
            if let Some(lambda) = lambda {
                write!(f, ", {name} = {} m", Shortest(lambda))?;
            }
        }
        Ok(())
    }
}
