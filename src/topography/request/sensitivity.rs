//! How much a measured surface's μ moves with the choices a user cannot
//! judge alone: the height model (the same load under each admissible
//! family) and the band (λs at the two ends of the reliable band). Each
//! value is exactly the single evaluation with that option
//! ([`SurfaceRequest::run`](super::SurfaceRequest::run) with it).

use super::super::{ScanRange, StatsOptions, Surface};
use super::{Cutoff, SurfaceRequest};
use crate::{Family, Load, Materials};
use serde::ser::{SerializeMap, Serializer};
use serde::Serialize;

/// The height models every surface answer is compared under, in order.
pub const SENSITIVITY_FAMILIES: [Family; 3] = [Family::Gaussian, Family::Pearson, Family::Empirical];

/// μ under one option, or why that option gives none.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The friction coefficient.
    Mu(f64),
    /// Why there is none (the core's words).
    Error(String),
}

impl Serialize for Outcome {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(1))?;
        match self {
            Outcome::Mu(mu) => map.serialize_entry("mu", mu)?,
            Outcome::Error(e) => map.serialize_entry("error", e)?,
        }
        map.end()
    }
}

/// μ at one end of the band.
#[derive(Debug, Clone, PartialEq)]
pub struct BandEnd {
    /// The S-filter's nesting index (m).
    pub lambda_s: f64,
    /// μ there.
    pub outcome: Outcome,
}

impl Serialize for BandEnd {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(2))?;
        map.serialize_entry("lambda_s", &self.lambda_s)?;
        match &self.outcome {
            Outcome::Mu(mu) => map.serialize_entry("mu", mu)?,
            Outcome::Error(e) => map.serialize_entry("error", e)?,
        }
        map.end()
    }
}

/// One load's μ under each height model and at each end of the band.
#[derive(Debug, Clone, PartialEq)]
pub struct Sensitivity {
    /// μ under each of [`SENSITIVITY_FAMILIES`], in order.
    pub distribution: Vec<(Family, Outcome)>,
    /// μ at the short and the long end of the reliable band.
    pub lambda_s: Vec<BandEnd>,
}

impl Serialize for Sensitivity {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        struct Families<'a>(&'a [(Family, Outcome)]);
        impl Serialize for Families<'_> {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let mut map = serializer.serialize_map(Some(self.0.len()))?;
                for (family, outcome) in self.0 {
                    map.serialize_entry(family.name(), outcome)?;
                }
                map.end()
            }
        }
        let mut map = serializer.serialize_map(Some(2))?;
        map.serialize_entry("distribution", &Families(&self.distribution))?;
        map.serialize_entry("lambda_s", &self.lambda_s)?;
        map.end()
    }
}

impl Sensitivity {
    /// Every μ given, with what gave it: `(label, μ)`, the height models
    /// by name, the band's ends as `lambda_s = … m`.
    pub fn values(&self) -> Vec<(String, f64)> {
        let mut v: Vec<(String, f64)> = self
            .distribution
            .iter()
            .filter_map(|(f, o)| match o {
                Outcome::Mu(mu) => Some((f.name().to_string(), *mu)),
                Outcome::Error(_) => None,
            })
            .collect();
        v.extend(self.lambda_s.iter().filter_map(|b| match b.outcome {
            Outcome::Mu(mu) => Some((format!("lambda_s = {} m", crate::Shortest(b.lambda_s)), mu)),
            Outcome::Error(_) => None,
        }));
        v
    }

    /// The lowest and the highest μ with what gave each, if any.
    pub fn range(&self) -> Option<((String, f64), (String, f64))> {
        let v = self.values();
        let lo = v.iter().min_by(|a, b| a.1.total_cmp(&b.1))?.clone();
        let hi = v.iter().max_by(|a, b| a.1.total_cmp(&b.1))?.clone();
        Some((lo, hi))
    }
}

/// The two ends of the reliable band of `surface`: λs at the reliability
/// cut-off when one is known, else at 2·max(Δx, Δy); and the default
/// scan's largest λs. A pair: its first part's.
pub fn band_ends(surface: &Surface, cutoff: Cutoff) -> [f64; 2] {
    let t = &surface.parts()[0].0;
    let range = ScanRange::default_for(t);
    let short = cutoff.value().unwrap_or(range.from);
    [short, range.to.max(short)]
}

/// The sensitivity of each of `loads` on `surface` (its friction
/// `evaluation` under the request's own choices).
pub(super) fn of(
    request: &SurfaceRequest,
    surface: &Surface,
    cutoff: Cutoff,
    materials: Materials,
    loads: &[Load],
    given: Option<&super::super::Evaluation>,
) -> Vec<Sensitivity> {
    // The request's own evaluation answers for its family: not solved again.
    let known = given.map(|e| (e.params.constants.distribution.family_kind(), &e.frictions));
    let outcomes = |s: &Surface, family: Option<Family>| -> Vec<Outcome> {
        let how = super::super::SurfaceModel {
            family,
            ..request.model_of(materials)
        };
        match s.evaluate(&how, loads) {
            Ok(e) => e.frictions.iter().map(|f| Outcome::Mu(f.mu)).collect(),
            Err(e) => {
                let e = super::evaluate_failure(&e, family, request.loads.field());
                vec![Outcome::Error(e.message.to_string()); loads.len()]
            }
        }
    };
    let families: Vec<Vec<Outcome>> = SENSITIVITY_FAMILIES
        .iter()
        .map(|&f| match known {
            Some((family, frictions)) if family == f && frictions.len() == loads.len() => {
                frictions.iter().map(|f| Outcome::Mu(f.mu)).collect()
            }
            _ => outcomes(surface, Some(f)),
        })
        .collect();
    let bands: Vec<(f64, Vec<Outcome>)> = band_ends(surface, cutoff)
        .into_iter()
        .map(|lambda_s| {
            let options = StatsOptions {
                lambda_s: Some(lambda_s),
                ..surface.options()
            };
            let rebuilt = rebuild(surface, options, cutoff);
            let outcome = match rebuilt {
                Ok(s) => outcomes(&s, request.distribution),
                Err(e) => vec![Outcome::Error(e.to_string()); loads.len()],
            };
            (lambda_s, outcome)
        })
        .collect();
    (0..loads.len())
        .map(|k| Sensitivity {
            distribution: SENSITIVITY_FAMILIES
                .iter()
                .zip(&families)
                .map(|(&f, o)| (f, o[k].clone()))
                .collect(),
            lambda_s: bands
                .iter()
                .map(|(l, o)| BandEnd {
                    lambda_s: *l,
                    outcome: o[k].clone(),
                })
                .collect(),
        })
        .collect()
}

/// The surface of the same heights with `options`, checked against the
/// cut-off as the single evaluation is.
fn rebuild(surface: &Surface, options: StatsOptions, cutoff: Cutoff) -> Result<Surface, super::super::StatsError> {
    let one = |t: &super::super::Topography| {
        let mut s = Surface::new(t.clone(), options)?;
        if let Some(c) = cutoff.value() {
            s.check_reliability(c);
        }
        Ok(s)
    };
    match surface.parts() {
        [(a, _), (b, _)] => Surface::join(one(a)?, one(b)?),
        parts => one(&parts[0].0),
    }
}
