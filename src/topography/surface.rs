//! A measured rough surface as the model sees it (MODEL.md §10): one
//! topography, or the equivalent surface of two, with its statistics, its
//! height distribution and, with the materials, the model's inputs.

use super::{combine, StatsError, StatsOptions, SurfaceStats, Topography};
use crate::{DistributionError, Empirical, Family, HeightDistribution, Materials, ParamError, Params, Physical};

/// A rough surface against a flat, from measured heights: one topography,
/// or two rough surfaces pressed together, whose equivalent surface has
/// the sum of their heights ([`combine`]).
///
/// ```
/// use ke_friction::topography::{StatsOptions, Surface, Topography};
/// use ke_friction::{Load, Materials, Model};
/// let n = 128;
/// let heights: Vec<f64> = (0..n * n)
///     .map(|k| {
///         let (x, y) = ((k % n) as f64, (k / n) as f64);
///         2e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin() + (x * 0.13 - y * 0.41).cos())
///     })
///     .collect();
/// let surface = Surface::new(Topography::map(heights, n, n, 1e-6, 1e-6)?, StatsOptions::default())?;
/// let materials = Materials {
///     e1: 70e9, nu1: 0.33, e2: 200e9, nu2: 0.31, hardness: 1e9, delta_gamma: 0.5, epsilon: 0.4e-9,
/// };
/// let distribution = surface.distribution(Some(ke_friction::Family::Gaussian))?;
/// let params = surface.params(&materials, distribution)?;
/// let friction = Load::Force { force: 10.0, area: 1e-5 }
///     .friction(&Model::new(params)?, &surface.physical(&materials))?;
/// assert!(friction.mu > 0.0 && friction.friction_force == Some(10.0 * friction.mu));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Surface {
    parts: Vec<(Topography, SurfaceStats)>,
    options: StatsOptions,
    stats: SurfaceStats,
}

impl Surface {
    /// The family of [`Surface::distribution`] when none is named, where
    /// its upper tail is supported by the measured heights
    /// ([`Surface::default_family`]): the Pearson density of the measured
    /// skewness and kurtosis.
    pub const DEFAULT_FAMILY: Family = Family::Pearson;

    /// The family of [`Surface::distribution`] when none is named and the
    /// Pearson density is refused or its upper tail is not supported by
    /// the measured heights ([`Surface::default_family`]).
    pub const FALLBACK_FAMILY: Family = Family::Empirical;

    /// How far above the highest measured height (in σ) the Pearson
    /// density may still expect one of the N measured heights for it to be
    /// the default ([`Surface::default_family`]): a density expecting,
    /// among N heights, one more than this above everything measured has a
    /// tail no measured point supports, where a light load's contact would
    /// sit (plu-1: h* = 16 against a highest height of 3.3σ).
    pub const PEARSON_TAIL_MARGIN: f64 = 3.0;

    /// The largest measured kurtosis for which the Pearson density is the
    /// default ([`Surface::default_family`]): above it Pearson's power-law
    /// tails inverted the empirical density's μ(F) trend on three of the
    /// four files where it was tried (di-3, K = 5.7; metropro-1, K = 52;
    /// plu-1, K = 9.2; docs/MODEL.md, "The default height model").
    pub const PEARSON_KURTOSIS_MAX: f64 = 4.0;

    /// One measured surface against a flat, its statistics taken with
    /// `options`.
    pub fn new(topography: Topography, options: StatsOptions) -> Result<Surface, StatsError> {
        let stats = topography.stats(&options)?;
        Ok(Surface {
            parts: vec![(topography, stats.clone())],
            options,
            stats,
        })
    }

    /// Two measured rough surfaces pressed together: the equivalent
    /// surface of their summed heights against a flat ([`combine`]). Both
    /// are profiles or both maps, ideally sampled alike (a warning says
    /// when their intervals differ by more than 1 %).
    pub fn pair(a: Topography, b: Topography, options: StatsOptions) -> Result<Surface, StatsError> {
        Surface::join(Surface::new(a, options)?, Surface::new(b, options)?)
    }

    /// Two single surfaces pressed together ([`Surface::pair`] of their
    /// topographies), reusing their statistics. Both must be single
    /// surfaces taken with the same options ([`StatsError::Mismatch`]
    /// otherwise).
    pub fn join(a: Surface, b: Surface) -> Result<Surface, StatsError> {
        if a.parts.len() != 1 || b.parts.len() != 1 || a.options != b.options {
            return Err(StatsError::Mismatch);
        }
        let stats = combine(&a.stats, &b.stats)?;
        let options = a.options;
        let parts = a.parts.into_iter().chain(b.parts).collect();
        Ok(Surface { parts, options, stats })
    }

    /// Records whether the shortest scale analysed is below the
    /// instrument's reliability cut-off `cutoff` (m): a
    /// [`Warning::Unreliable`](super::Warning::Unreliable) in the
    /// statistics if it is (true).
    pub fn check_reliability(&mut self, cutoff: f64) -> bool {
        self.stats.check_reliability(cutoff)
    }

    /// The statistics of the surface (of the equivalent surface, for a pair).
    pub fn stats(&self) -> &SurfaceStats {
        &self.stats
    }

    /// The measured topographies (one, or two for a pair) and their own
    /// statistics.
    pub fn parts(&self) -> &[(Topography, SurfaceStats)] {
        &self.parts
    }

    /// The options the statistics were taken with.
    pub fn options(&self) -> StatsOptions {
        self.options
    }

    /// The height distribution of the surface for a [`Family`] (`None`:
    /// [`Surface::default_family`]):
    ///
    /// - [`Family::Gaussian`]: the paper's;
    /// - [`Family::Pearson`]: the Pearson density of the measured skewness and
    ///   kurtosis (a pair's from the added cumulants);
    /// - [`Family::Weibull`]: the Weibull density of the measured skewness;
    /// - [`Family::Empirical`]: the kernel density of the detrended heights (a
    ///   pair's: the convolution of the two, [`crate::Empirical::sum`]);
    /// - any other family: its [`HeightDistribution::of_moments`].
    ///
    /// A measured skewness or kurtosis outside the family's range is an
    /// error naming it (`skewness` or `kurtosis`).
    pub fn distribution(&self, family: Option<Family>) -> Result<HeightDistribution, DistributionError> {
        let family = family.unwrap_or_else(|| self.default_family());
        if let Some(d) = HeightDistribution::of_moments(family, self.stats.skewness, self.stats.kurtosis) {
            return Ok(d?);
        }
        // The empirical density: of the detrended heights, or a pair's
        // convolution.
        let mut densities = Vec::with_capacity(2);
        for (t, s) in &self.parts {
            let heights = t.band_heights(&self.options).map_err(|e| DistributionError::Conflict {
                name: "heights",
                reason: e.to_string(),
            })?;
            densities.push((Empirical::new(&heights)?, s.sigma));
        }
        let (first, sd) = densities.remove(0);
        Ok(HeightDistribution::Empirical(match densities.pop() {
            None => first,
            Some((second, other_sd)) => first.sum(sd, &second, other_sd)?,
        }))
    }

    /// The family a surface gets when none is named (docs/MODEL.md,
    /// "The default height model"): [`DEFAULT_FAMILY`](Self::DEFAULT_FAMILY)
    /// (Pearson) if the measured skewness and kurtosis make one, the
    /// kurtosis is at most [`PEARSON_KURTOSIS_MAX`](Self::PEARSON_KURTOSIS_MAX)
    /// and its upper tail the measured heights support, N·P(z > z_max + m) < 1 with
    /// m = [`PEARSON_TAIL_MARGIN`](Self::PEARSON_TAIL_MARGIN)
    /// ([`Surface::pearson_tail_excess`]);
    /// else [`FALLBACK_FAMILY`](Self::FALLBACK_FAMILY) (the measured
    /// heights' own density). A pair (no kept tail) is judged by its
    /// kurtosis alone.
    pub fn default_family(&self) -> Family {
        if self.stats.kurtosis > Self::PEARSON_KURTOSIS_MAX {
            return Self::FALLBACK_FAMILY;
        }
        match self.pearson_tail_excess() {
            Some(Some(excess)) if excess >= 1.0 => Self::FALLBACK_FAMILY,
            Some(None) => Self::FALLBACK_FAMILY,
            _ => Self::DEFAULT_FAMILY,
        }
    }

    /// N·P(z > z_max + m), m = [`PEARSON_TAIL_MARGIN`](Self::PEARSON_TAIL_MARGIN):
    /// how many heights, of the N measured, the Pearson density of the
    /// measured skewness and kurtosis expects more than m σ above the
    /// highest measured height z_max. `None` for a pair (its tail is not kept);
    /// `Some(None)` where the moments make no Pearson density.
    pub fn pearson_tail_excess(&self) -> Option<Option<f64>> {
        let tail = self.stats.tail.as_ref()?;
        let Ok(density) =
            HeightDistribution::pearson(self.stats.skewness, self.stats.kurtosis).and_then(|d| d.density())
        else {
            return Some(None);
        };
        let z_max = tail.max() + Self::PEARSON_TAIL_MARGIN;
        let p = density.integrate(|x| if x > z_max { 1.0 } else { 0.0 });
        Some(Some(p * self.stats.points as f64))
    }

    /// The physical inputs of `materials` on this surface: σ, R and η from
    /// its statistics.
    pub fn physical(&self, materials: &Materials) -> Physical {
        materials.with_roughness(self.stats.sigma, self.stats.radius, self.stats.eta)
    }

    /// The model's inputs for `materials` on this surface with height
    /// distribution `distribution` ([`Params::from_physical`]): ψ, θ, β,
    /// ν, ε*.
    pub fn params(&self, materials: &Materials, distribution: HeightDistribution) -> Result<Params, ParamError> {
        Ok(Params::from_physical(&self.physical(materials))?.distribution(distribution))
    }
}
