//! `DistributionCore`: an asperity-height distribution (MODEL.md §9) and
//! its standardised density.

use crate::convert::{same_len, slice, slice_mut};
use crate::error::{raise, value_error};
use ke_friction::{Density, Family, HeightDistribution, Named};
use numpy::{PyReadonlyArray1, PyReadwriteArray1};
use pyo3::prelude::*;

/// A validated height distribution, its density, and its kurtosis (for
/// Weibull a quadrature, so computed once).
#[pyclass(frozen, module = "ke_friction._core")]
pub struct DistributionCore {
    /// The distribution, as the core's constants take it.
    pub dist: HeightDistribution,
    density: Density,
    kurtosis: f64,
}

impl DistributionCore {
    /// The core of a distribution that validated.
    pub fn of(dist: HeightDistribution) -> DistributionCore {
        DistributionCore {
            // Every constructor below validated it.
            density: dist.density().expect("a validated distribution"),
            kurtosis: dist.kurtosis(),
            dist,
        }
    }

    /// `pdf` or `ln_pdf` of the density at each `x` into `out`.
    fn fill(
        &self,
        py: Python<'_>,
        x: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray1<'_, f64>,
        f: fn(&Density, f64) -> f64,
    ) -> PyResult<()> {
        let x = slice("x", &x)?;
        let out = slice_mut("out", &mut out)?;
        same_len(out.len(), &[("x", x.len())])?;
        let density = &self.density;
        py.detach(|| {
            for (o, &v) in out.iter_mut().zip(x.iter()) {
                *o = f(density, v);
            }
        });
        Ok(())
    }
}

#[pymethods]
impl DistributionCore {
    /// The paper's Gaussian.
    #[staticmethod]
    fn gaussian() -> DistributionCore {
        DistributionCore::of(HeightDistribution::GAUSSIAN)
    }

    /// Pearson(skewness, kurtosis), validated (the core's message names
    /// the bound).
    #[staticmethod]
    fn pearson(skewness: f64, kurtosis: f64) -> PyResult<DistributionCore> {
        HeightDistribution::pearson(skewness, kurtosis)
            .map(DistributionCore::of)
            .map_err(raise)
    }

    /// Weibull of `skewness`, validated.
    #[staticmethod]
    fn weibull(skewness: f64) -> PyResult<DistributionCore> {
        HeightDistribution::weibull(skewness)
            .map(DistributionCore::of)
            .map_err(raise)
    }

    /// The distribution of `Model`'s keywords, by the core's rules
    /// (`HeightDistribution::from_arguments`; the error names the keyword).
    #[staticmethod]
    #[pyo3(signature = (family, skewness, kurtosis, heights))]
    fn from_arguments(
        py: Python<'_>,
        family: Option<&str>,
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        heights: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<DistributionCore> {
        let family = family.map(Family::parse).transpose().map_err(value_error)?;
        let heights = heights.map(|h| slice("heights", &h).map(|v| v.to_vec())).transpose()?;
        py.detach(|| {
            HeightDistribution::from_arguments(family, skewness, kurtosis, heights.as_deref()).map(DistributionCore::of)
        })
        .map_err(raise)
    }

    /// The empirical density of `heights` (NaN skipped), validated.
    #[staticmethod]
    fn empirical(py: Python<'_>, heights: PyReadonlyArray1<'_, f64>) -> PyResult<DistributionCore> {
        let heights = slice("heights", &heights)?;
        py.detach(|| HeightDistribution::empirical(&heights).map(DistributionCore::of))
            .map_err(raise)
    }

    /// The distribution of `family` with the values a table stores (and
    /// a pickle keeps: `stored`), validated (`HeightDistribution::of_family`).
    #[staticmethod]
    fn of_stored(family: &str, skewness: f64, kurtosis: f64) -> PyResult<DistributionCore> {
        let family = <Family as Named>::parse(family).map_err(value_error)?;
        let d = HeightDistribution::of_family(family, skewness, kurtosis)
            .ok_or_else(|| value_error(format!("{family}: made of measured heights, not of values")))?;
        d.validate().map_err(raise)?;
        Ok(DistributionCore::of(d))
    }

    /// The (skewness, kurtosis) a table stores for it, or None (an
    /// empirical density: its heights make it).
    fn stored(&self) -> Option<(f64, f64)> {
        self.dist.stored().map(|[s, k]| (s, k))
    }

    /// The density of `sd`·X + `other_sd`·Y, X and Y of the empirical
    /// densities of `heights` and `other` (`Empirical::sum`): a pair of
    /// surfaces' empirical density, rebuilt from its parts.
    #[staticmethod]
    fn empirical_sum(
        py: Python<'_>,
        heights: PyReadonlyArray1<'_, f64>,
        sd: f64,
        other: PyReadonlyArray1<'_, f64>,
        other_sd: f64,
    ) -> PyResult<DistributionCore> {
        let (a, b) = (slice("heights", &heights)?, slice("other", &other)?);
        py.detach(|| {
            let (HeightDistribution::Empirical(a), HeightDistribution::Empirical(b)) =
                (HeightDistribution::empirical(&a)?, HeightDistribution::empirical(&b)?)
            else {
                unreachable!("empirical densities")
            };
            a.sum(sd, &b, other_sd)
                .map(|e| DistributionCore::of(HeightDistribution::Empirical(e)))
        })
        .map_err(raise)
    }

    /// The family's name (one of the core's `Family` names).
    fn family(&self) -> &'static str {
        self.dist.family()
    }

    fn skewness(&self) -> f64 {
        self.dist.skewness()
    }

    /// Not excess; for Weibull the one the skewness implies.
    fn kurtosis(&self) -> f64 {
        self.kurtosis
    }

    fn is_gaussian(&self) -> bool {
        self.dist.is_gaussian()
    }

    /// Number of heights of an empirical density, else None.
    fn heights(&self) -> Option<usize> {
        match &self.dist {
            HeightDistribution::Empirical(e) => Some(e.len()),
            _ => None,
        }
    }

    /// The kernel width of an empirical density, else None.
    fn bandwidth(&self) -> Option<f64> {
        match &self.dist {
            HeightDistribution::Empirical(e) => Some(e.bandwidth()),
            _ => None,
        }
    }

    fn support(&self) -> (f64, f64) {
        self.density.support()
    }

    fn mode(&self) -> f64 {
        self.density.mode()
    }

    /// "0" (normal), "I", …, "VII" for a Pearson density (and the
    /// Gaussian), else None.
    fn pearson_type(&self) -> Option<&'static str> {
        self.density.pearson_type().map(|t| t.name())
    }

    /// `(mass, mean, variance, skewness, kurtosis)` of the density by the
    /// model's quadrature.
    fn moments(&self, py: Python<'_>) -> (f64, f64, f64, f64, f64) {
        let [m, mean, var, sk, k] = py.detach(|| self.density.moments());
        (m, mean, var, sk, k)
    }

    /// g(x) at each `x` into `out` (0 outside the support).
    fn pdf_into(&self, py: Python<'_>, x: PyReadonlyArray1<'_, f64>, out: PyReadwriteArray1<'_, f64>) -> PyResult<()> {
        self.fill(py, x, out, Density::pdf)
    }

    /// ln g(x) at each `x` into `out` (−inf outside the support).
    fn ln_pdf_into(
        &self,
        py: Python<'_>,
        x: PyReadonlyArray1<'_, f64>,
        out: PyReadwriteArray1<'_, f64>,
    ) -> PyResult<()> {
        self.fill(py, x, out, Density::ln_pdf)
    }

    /// Whether the two are the same distribution (for an empirical one,
    /// the same density).
    fn same(&self, other: &DistributionCore) -> bool {
        self.dist == other.dist
    }
}
