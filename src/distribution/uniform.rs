//! A test-only family (`#[cfg(test)]`): the uniform density on
//! [−√3, √3], all that adding a family takes — this file and one line in
//! `families!`. Pearson(0, 1.8) is the same density by another road (A1 =
//! 0: a flat type II), which the tests below check through the model.

use super::density::Density;
use super::family::{DistributionFamily, Parameters};
use super::shape::{End, Form};
use super::{DistributionError, Shape};
use crate::checks::ParamError;

/// The standardised uniform distribution (skewness 0, kurtosis 1.8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Uniform;

const HALF_WIDTH: f64 = 1.732_050_807_568_877_2; // √3
const KURTOSIS: f64 = 1.8;

impl Parameters for Uniform {
    fn validate(&self) -> Result<(), ParamError> {
        Ok(())
    }

    fn skewness(&self) -> f64 {
        0.0
    }

    fn kurtosis(&self) -> f64 {
        KURTOSIS
    }

    fn stored(&self) -> Option<[f64; 2]> {
        Some([0.0, KURTOSIS])
    }

    fn density(&self) -> Density {
        let end = |at: f64| End {
            at,
            power: 0.0,
            jacobi_width: f64::INFINITY,
        };
        Density {
            ln_norm: -(2.0 * HALF_WIDTH).ln(),
            ..Density::plain(Shape::Uniform(Uniform), Some(end(-HALF_WIDTH)), Some(end(HALF_WIDTH)), 0.0)
        }
    }
}

impl DistributionFamily for Uniform {
    type Form = Uniform;

    fn from_arguments(
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        _: Option<&[f64]>,
    ) -> Result<Uniform, DistributionError> {
        match (skewness, kurtosis) {
            (None | Some(0.0), None | Some(KURTOSIS)) => Ok(Uniform),
            _ => Err(DistributionError::Conflict {
                name: "skewness",
                reason: "the uniform distribution has skewness 0 and kurtosis 1.8".into(),
            }),
        }
    }

    fn from_moments(_: f64, _: f64) -> Option<Result<Uniform, ParamError>> {
        Some(Ok(Uniform))
    }

    fn from_stored(_: f64, _: f64) -> Option<Uniform> {
        Some(Uniform)
    }
}

impl Form for Uniform {
    fn ln(&self, _: f64) -> f64 {
        0.0
    }

    fn dln(&self, _: f64) -> f64 {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use crate::distribution::{Family, HeightDistribution, Uniform};
    use crate::table::format::DistributionSpec;
    use crate::{Constants, Model, Named};

    /// Its moments, its name and code, a table's record of it, and the
    /// model's μ against Pearson(0, 1.8), the same density by its own code.
    #[test]
    fn a_test_only_uniform_family_goes_through_every_seam() {
        let d = HeightDistribution::Uniform(Uniform);
        let [m0, mean, var, sk, k] = d.density().unwrap().moments();
        assert!((m0 - 1.0).abs() < 1e-13 && mean.abs() < 1e-13 && (var - 1.0).abs() < 1e-13, "{m0} {mean} {var}");
        assert!(sk.abs() < 1e-13 && (k - 1.8).abs() < 1e-12, "{sk} {k}");
        assert_eq!(Family::parse("uniform"), Ok(Family::Uniform));
        assert_eq!(Family::from_code(4), Some(Family::Uniform));
        assert_eq!(HeightDistribution::from_arguments(Some(Family::Uniform), None, None, None), Ok(d.clone()));
        assert_eq!(HeightDistribution::of_moments(Family::Uniform, 0.3, 5.0), Some(Ok(d.clone())));
        let spec = DistributionSpec::of(&d).unwrap();
        assert_eq!(spec.distribution(), Ok(d.clone()));
        assert_eq!(d.to_string(), "uniform (skewness 0, kurtosis 1.8)");

        let pearson = HeightDistribution::pearson(0.0, 1.8).unwrap();
        let model = |d: HeightDistribution| Model::new(Constants::default().distribution(d).at(1.0, 1e-3).unwrap()).unwrap();
        let (u, p) = (model(d), model(pearson));
        for f_star in [1e-4, 1e-3, 1e-2] {
            let (a, b) = (u.at_f_star(f_star).unwrap().mu.unwrap(), p.at_f_star(f_star).unwrap().mu.unwrap());
            assert!((a - b).abs() <= 1e-9 * b.abs(), "F* = {f_star}: μ {a} (uniform) against {b} (Pearson(0, 1.8))");
        }
    }
}
