//! The paper's Gaussian heights (MODEL.md §4).

use super::density::Density;
use super::family::{DistributionFamily, Parameters};
use super::shape::Form;
use super::DistributionError;
use crate::checks::ParamError;

/// The paper's Gaussian (skewness 0, kurtosis 3): the parameters of
/// [`HeightDistribution::GAUSSIAN`](super::HeightDistribution::GAUSSIAN),
/// which has none.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Gaussian;

impl Parameters for Gaussian {
    fn validate(&self) -> Result<(), ParamError> {
        Ok(())
    }

    fn skewness(&self) -> f64 {
        0.0
    }

    fn kurtosis(&self) -> f64 {
        3.0
    }

    fn is_gaussian(&self) -> bool {
        true
    }

    fn stored(&self) -> Option<[f64; 2]> {
        Some([0.0, 3.0])
    }

    fn density(&self) -> Density {
        Density {
            ln_norm: -0.5 * (2.0 * core::f64::consts::PI).ln(),
            ..Density::plain(super::Shape::Gaussian(Gaussian), None, None, 0.0)
        }
    }
}

impl DistributionFamily for Gaussian {
    type Form = Gaussian;

    /// Skewness 0 and kurtosis 3 only.
    fn from_arguments(
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        _: Option<&[f64]>,
    ) -> Result<Gaussian, DistributionError> {
        for (name, value, normal) in [("skewness", skewness, 0.0), ("kurtosis", kurtosis, 3.0)] {
            if value.is_some_and(|v| v != normal) {
                return Err(DistributionError::Conflict {
                    name,
                    reason: "the gaussian distribution has skewness 0 and kurtosis 3 (ask for pearson)".into(),
                });
            }
        }
        Ok(Gaussian)
    }

    /// The Gaussian, whatever the moments.
    fn from_moments(_: f64, _: f64) -> Option<Result<Gaussian, ParamError>> {
        Some(Ok(Gaussian))
    }

    fn from_stored(_: f64, _: f64) -> Option<Gaussian> {
        Some(Gaussian)
    }
}

impl Form for Gaussian {
    #[inline]
    fn ln(&self, x: f64) -> f64 {
        -0.5 * x * x
    }

    #[inline]
    fn dln(&self, x: f64) -> f64 {
        -x
    }
}
