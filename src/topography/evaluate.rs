//! A measured surface with materials and loads → the model's inputs, the
//! friction at each load and its warnings: what every front end (the CLI's
//! `kefric surface`, its scans and plots, the web page) asks of a surface,
//! once, with an error that says which step failed
//! ([`evaluate_failure`](super::evaluate_failure) names the input to blame).

use super::Surface;
use crate::{
    Classify, DistributionError, ErrorKind, Family, Fit, Friction, Load, LoadError, Materials, Model, ModelKind,
    ParamError, Params, Warning, Warnings,
};

/// How the model is set up on a measured surface: everything but the
/// surface and the loads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceModel {
    /// The materials (E, ν, hardness, adhesion of each body).
    pub materials: Materials,
    /// The heights' family (`None`: [`Surface::default_family`]).
    pub family: Option<Family>,
    /// The fit of the model's relations.
    pub fit: Fit,
    /// The contact law.
    pub kind: ModelKind,
}

impl SurfaceModel {
    /// The Kogut–Etsion model with the consistent fit and the default
    /// family, on `materials`.
    pub fn new(materials: Materials) -> SurfaceModel {
        SurfaceModel {
            materials,
            family: None,
            fit: Fit::Consistent,
            kind: ModelKind::KogutEtsion,
        }
    }
}

/// A surface evaluated ([`Surface::evaluate`]).
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// The model's inputs.
    pub params: Params,
    /// The friction at each load, in the loads' order.
    pub frictions: Vec<Friction>,
    /// Each friction's warnings, in the loads' order (the statistics'
    /// are the surface's own; the model's inputs' are in `domain`).
    pub warnings: Vec<Vec<Warning>>,
    /// The model's inputs outside its validity domain
    /// ([`Warning::of_params`]), with or without loads.
    pub domain: Vec<Warning>,
}

impl Evaluation {
    /// Notes the validity domain's warnings and each friction's in
    /// `warnings`, one result a load.
    pub fn note_into(&self, warnings: &mut Warnings) {
        warnings.extend(self.domain.iter().cloned());
        for w in &self.warnings {
            warnings.note(w.iter().cloned());
        }
    }
}

/// Which step of [`Surface::evaluate`] failed, and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EvaluateError {
    /// The surface's heights do not make the family's distribution.
    #[error(transparent)]
    Distribution(DistributionError),
    /// The surface's statistics with the materials give an input out of
    /// range ([`Params::from_physical`]).
    #[error(transparent)]
    Params(ParamError),
    /// The model refuses the inputs.
    #[error(transparent)]
    Model(ParamError),
    /// A load has no friction.
    #[error(transparent)]
    Load(LoadError),
}

/// The failed step's kind.
impl Classify for EvaluateError {
    fn kind(&self) -> ErrorKind {
        match self {
            EvaluateError::Distribution(e) => e.kind(),
            EvaluateError::Params(e) | EvaluateError::Model(e) => e.kind(),
            EvaluateError::Load(e) => e.kind(),
        }
    }
}

impl Surface {
    /// The model's inputs of this surface set up as `how`, and the friction
    /// at each of `loads` (the model is built only if there are loads).
    ///
    /// ```
    /// use ke_friction::topography::{StatsOptions, Surface, SurfaceModel, Topography};
    /// use ke_friction::{Load, Materials};
    /// let n = 128;
    /// let heights: Vec<f64> = (0..n * n)
    ///     .map(|k| {
    ///         let (x, y) = ((k % n) as f64, (k / n) as f64);
    ///         2e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin() + (x * 0.13 - y * 0.41).cos())
    ///     })
    ///     .collect();
    /// let surface = Surface::new(Topography::map(heights, n, n, 1e-6, 1e-6)?, StatsOptions::default())?;
    /// let how = SurfaceModel::new(Materials {
    ///     e1: 70e9, nu1: 0.33, e2: 200e9, nu2: 0.31, hardness: 1e9, delta_gamma: 0.5, epsilon: 0.4e-9,
    /// });
    /// let loads = [Load::Pressure(1e6), Load::Pressure(1e7)];
    /// let e = surface.evaluate(&how, &loads)?;
    /// assert_eq!((e.frictions.len(), e.warnings.len()), (2, 2));
    /// assert!(e.params.psi > 0.0 && e.frictions.iter().all(|f| f.mu > 0.0));
    /// assert!(surface.evaluate(&how, &[])?.frictions.is_empty());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn evaluate(&self, how: &SurfaceModel, loads: &[Load]) -> Result<Evaluation, EvaluateError> {
        let params = self.model_params(how)?;
        let mut evaluation = Evaluation {
            domain: Warning::of_params(&params).collect(),
            params,
            frictions: Vec::new(),
            warnings: Vec::new(),
        };
        if loads.is_empty() {
            return Ok(evaluation);
        }
        let model = Model::new(evaluation.params.clone()).map_err(EvaluateError::Model)?;
        (evaluation.frictions, evaluation.warnings) = self
            .frictions(&model, &how.materials, loads)
            .map_err(EvaluateError::Load)?
            .into_iter()
            .unzip();
        Ok(evaluation)
    }

    /// The friction at each of `loads` on `model`, whose inputs came from
    /// this surface with `materials`, each with its warnings: the
    /// contact's, and [`Warning::Tail`] where fewer than
    /// [`TAIL_MIN_POINTS`](crate::TAIL_MIN_POINTS) measured
    /// heights lie above the separation ([`Surface::tail_warning`]).
    pub fn frictions(
        &self,
        model: &Model,
        materials: &Materials,
        loads: &[Load],
    ) -> Result<Vec<(Friction, Vec<Warning>)>, LoadError> {
        let physical = self.physical(materials);
        loads
            .iter()
            .map(|load| {
                let friction = load.friction(model, &physical)?;
                let mut warnings: Vec<Warning> = friction.warnings(model, &physical).collect();
                warnings.extend(self.tail_warning(friction.contact.h_star));
                Ok((friction, warnings))
            })
            .collect()
    }

    /// The model's inputs of this surface set up as `how`: the
    /// distribution of its heights, then [`Params::from_physical`] with the
    /// materials, the fit and the law.
    pub fn model_params(&self, how: &SurfaceModel) -> Result<Params, EvaluateError> {
        let distribution = self.distribution(how.family).map_err(EvaluateError::Distribution)?;
        // Params::from_physical validated it; fit and law change no range.
        Ok(self
            .params(&how.materials, distribution)
            .map_err(EvaluateError::Params)?
            .fit(how.fit)
            .kind(how.kind))
    }

    /// [`Warning::Tail`] if fewer than
    /// [`TAIL_MIN_POINTS`](crate::TAIL_MIN_POINTS) measured
    /// heights lie above the separation `h_star` (h/σ, of the mean plane
    /// of the heights): the contacting asperities are where the density
    /// is extrapolated, whatever its family (the empirical kernel density
    /// too). `None` for a pair, whose summed heights are not kept.
    pub fn tail_warning(&self, h_star: f64) -> Option<Warning> {
        let tail = self.stats().tail.as_ref()?;
        Warning::of_tail(h_star, tail.max(), tail.count_above(h_star))
    }

    /// The model of this surface set up as `how`.
    pub fn model(&self, how: &SurfaceModel) -> Result<Model, EvaluateError> {
        Model::new(self.model_params(how)?).map_err(EvaluateError::Model)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::topography::{evaluate_failure, Field};
    use crate::topography::{StatsOptions, Topography};

    fn surface() -> Surface {
        let n = 96;
        let heights: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as f64, (k / n) as f64);
                2e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin())
            })
            .collect();
        Surface::new(
            Topography::map(heights, n, n, 1e-6, 1e-6).unwrap(),
            StatsOptions::default(),
        )
        .unwrap()
    }

    const MATERIALS: Materials = Materials::from_array([70e9, 0.33, 200e9, 0.31, 1e9, 0.5, 0.4e-9]);

    /// Each step's failure names its step and, in the CLI's words, its flag;
    /// a success gives each load its friction and warnings.
    #[test]
    fn each_step_of_an_evaluation_fails_with_its_own_error() {
        let s = surface();
        let how = SurfaceModel::new(MATERIALS);
        let loads = [Load::Pressure(1e5), Load::Pressure(1e6)];
        let e = s.evaluate(&how, &loads).unwrap();
        assert_eq!(e.frictions.len(), 2);
        assert!(e.frictions[1].mu != e.frictions[0].mu);
        let mut noted = Warnings::new();
        e.note_into(&mut noted);

        let soft = SurfaceModel {
            materials: Materials {
                hardness: -1.0,
                ..MATERIALS
            },
            ..how
        };
        let err = s.evaluate(&soft, &loads).unwrap_err();
        assert!(
            matches!(err, EvaluateError::Params(ref p) if p.name == "hardness"),
            "{err:?}"
        );
        assert!(
            evaluate_failure(&err, None, Field::Pressure).field == Field::Hardness,
            "{err}"
        );

        let err = s.evaluate(&how, &[Load::Pressure(-1.0)]).unwrap_err();
        assert!(matches!(err, EvaluateError::Load(_)), "{err:?}");
        assert!(
            evaluate_failure(&err, None, Field::Pressure).field == Field::Pressure,
            "{err}"
        );
        assert_eq!(
            err.kind(),
            LoadError::Load(ParamError {
                name: "pressure",
                value: -1.0,
                range: ""
            })
            .kind()
        );
    }
}
