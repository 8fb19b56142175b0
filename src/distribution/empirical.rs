//! The empirical family: a kernel density of measured heights (MODEL.md §9).

use super::density::Density;
use super::family::{DistributionFamily, Parameters};
use super::shape::Form;
use super::{DistributionError, Shape};
use crate::bound::Bound;
use crate::checks::{check_count, check_in, ParamError};
use std::sync::Arc;

/// Fewest finite heights an [`Empirical`] density accepts.
pub const EMPIRICAL_MIN_HEIGHTS: usize = 100;
/// The finite heights an empirical density needs: at least [`EMPIRICAL_MIN_HEIGHTS`].
pub static HEIGHTS: Bound = Bound::whole(EMPIRICAL_MIN_HEIGHTS, usize::MAX).unit("finite values");
/// A standard deviation of [`Empirical::sum`]: > 0.
pub static SD: Bound = Bound::above(0.0);

/// An empirical density of measured heights (MODEL.md §9;
/// [`HeightDistribution::Empirical`](super::HeightDistribution::Empirical)): the heights are
/// standardised, binned onto at most [`KDE_CENTRES`] evenly spaced centres
/// (no more than four per kernel width) and smoothed by a
/// Gaussian kernel of Silverman's bandwidth `h = 1.06·n^(−1/5)`, then
/// rescaled so that the density has mean 0 and variance 1 exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Empirical(pub(super) Arc<Kde>);

/// Most bin centres of an [`Empirical`] density.
pub const KDE_CENTRES: usize = 2000;

#[derive(Debug, PartialEq)]
pub(super) struct Kde {
    /// Heights given (finite ones).
    pub(super) n: usize,
    /// Skewness and kurtosis of the heights.
    pub(super) skewness: f64,
    pub(super) kurtosis: f64,
    /// Standardised centres (mean 0, and variance `1 − h²` with the
    /// weights), and their weights (sum 1).
    pub(super) centres: Vec<f64>,
    pub(super) weights: Vec<f64>,
    /// Kernel width, in standardised units.
    pub(super) h: f64,
}

/// Kernels further than this many widths away are left out (e^−40.5).
const KDE_REACH: f64 = 9.0;

impl Kde {
    /// The kernel density of weighted `atoms` (x, weight; weights summing
    /// to `total`) lying in `lo..=hi`, with kernel width `h0`: linear binning
    /// onto evenly spaced centres, about four per kernel width (binning
    /// then changes the density by ~1e-3 of itself) and at most
    /// [`KDE_CENTRES`], then standardised so that the smoothed density has
    /// mean 0 and variance (of the centres) + h² = 1.
    fn binned(
        n: usize,
        [skewness, kurtosis]: [f64; 2],
        (lo, hi): (f64, f64),
        h0: f64,
        atoms: impl Iterator<Item = (f64, f64)>,
        total: f64,
    ) -> Kde {
        let m = (((hi - lo) / (0.25 * h0)).ceil() as usize + 1).clamp(16, KDE_CENTRES);
        let step = (hi - lo) / (m - 1) as f64;
        let mut weights = vec![0.0; m];
        for (x, w) in atoms {
            let t = (x - lo) / step;
            let i = (t.floor().max(0.0) as usize).min(m - 2);
            let f = (t - i as f64).clamp(0.0, 1.0);
            weights[i] += w * (1.0 - f);
            weights[i + 1] += w * f;
        }
        weights.iter_mut().for_each(|w| *w /= total);
        let centres: Vec<f64> = (0..m).map(|i| lo + step * i as f64).collect();
        let cm: f64 = centres.iter().zip(&weights).map(|(c, w)| c * w).sum();
        let cv: f64 = centres.iter().zip(&weights).map(|(c, w)| (c - cm) * (c - cm) * w).sum();
        let scale = 1.0 / (cv + h0 * h0).sqrt();
        Kde {
            n,
            skewness,
            kurtosis,
            centres: centres.into_iter().map(|c| (c - cm) * scale).collect(),
            weights,
            h: h0 * scale,
        }
    }
}

impl Empirical {
    /// The density of `heights` (any unit; NaN entries are skipped). At
    /// least [`EMPIRICAL_MIN_HEIGHTS`] finite heights, not all equal.
    pub fn new(heights: &[f64]) -> Result<Empirical, ParamError> {
        let finite = || heights.iter().copied().filter(|v| v.is_finite());
        let n = finite().count();
        check_count("heights", n, &HEIGHTS)?;
        if let Some(bad) = heights.iter().find(|v| v.is_infinite()) {
            return Err(ParamError {
                name: "heights",
                value: *bad,
                range: "finite (NaN marks a missing point)",
            });
        }
        let nf = n as f64;
        let mean = finite().sum::<f64>() / nf;
        let [m2, m3, m4] = finite().fold([0.0; 3], |[a, b, c], v| {
            let d = v - mean;
            [a + d * d, b + d * d * d, c + d * d * d * d]
        });
        let (m2, m3, m4) = (m2 / nf, m3 / nf, m4 / nf);
        let sd = m2.sqrt();
        if !(sd > 1e-12 * mean.abs().max(f64::MIN_POSITIVE) && sd.is_finite()) {
            return Err(ParamError {
                name: "heights",
                value: sd,
                range: "a standard deviation > 0 (the heights are constant)",
            });
        }
        let (lo, hi) = finite().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            let x = (v - mean) / sd;
            (a.min(x), b.max(x))
        });
        let h0 = 1.06 * (n as f64).powf(-0.2);
        let atoms = finite().map(|v| ((v - mean) / sd, 1.0));
        let kde = Kde::binned(n, [m3 / (m2 * sd), m4 / (m2 * m2)], (lo, hi), h0, atoms, nf);
        Ok(Empirical(Arc::new(kde)))
    }

    /// The density of the sum of two independent heights, `sd`·X + `other_sd`·Y,
    /// with X of this density and Y of `other` (both standardised): the
    /// convolution of the two (MODEL.md §10, two rough surfaces). Their
    /// kernels combine into one Gaussian kernel; their bin centres are
    /// convolved and binned again (at most [`KDE_CENTRES`]); skewness and
    /// kurtosis follow from the cumulants, which add. [`Empirical::len`]
    /// of the sum is the smaller of the two counts.
    ///
    /// ```
    /// use ke_friction::HeightDistribution;
    /// let a: Vec<f64> = (0..2000).map(|i| ((i as f64) * 0.61).sin()).collect();
    /// let b: Vec<f64> = (0..3000).map(|i| ((i as f64) * 0.37).cos().powi(3)).collect();
    /// let (HeightDistribution::Empirical(x), HeightDistribution::Empirical(y)) =
    ///     (HeightDistribution::empirical(&a)?, HeightDistribution::empirical(&b)?) else { unreachable!() };
    /// let sum = x.sum(1.0, &y, 2.0)?;
    /// let d = HeightDistribution::Empirical(sum).density()?;
    /// let [mass, mean, var, _, _] = d.moments();
    /// assert!((mass - 1.0).abs() < 1e-9 && mean.abs() < 1e-9 && (var - 1.0).abs() < 1e-9);
    /// # Ok::<(), ke_friction::ParamError>(())
    /// ```
    pub fn sum(&self, sd: f64, other: &Empirical, other_sd: f64) -> Result<Empirical, ParamError> {
        check_in("sd", sd, &SD)?;
        check_in("other_sd", other_sd, &SD)?;
        let (a, b) = (&*self.0, &*other.0);
        let total = sd.hypot(other_sd);
        let (wa, wb) = (sd / total, other_sd / total);
        let h0 = (wa * a.h).hypot(wb * b.h);
        let ends = |k: &Kde| (k.centres[0], k.centres[k.centres.len() - 1]);
        let ((alo, ahi), (blo, bhi)) = (ends(a), ends(b));
        let skewness = wa.powi(3) * a.skewness + wb.powi(3) * b.skewness;
        let kurtosis = 3.0 + wa.powi(4) * (a.kurtosis - 3.0) + wb.powi(4) * (b.kurtosis - 3.0);
        let atoms = a.centres.iter().zip(&a.weights).flat_map(|(&ca, &pa)| {
            b.centres
                .iter()
                .zip(&b.weights)
                .map(move |(&cb, &pb)| (wa * ca + wb * cb, pa * pb))
        });
        Ok(Empirical(Arc::new(Kde::binned(
            a.n.min(b.n),
            [skewness, kurtosis],
            (wa * alo + wb * blo, wa * ahi + wb * bhi),
            h0,
            atoms,
            1.0,
        ))))
    }

    /// Number of heights the density was built from.
    pub fn len(&self) -> usize {
        self.0.n
    }

    /// Always false: an empirical density has at least [`EMPIRICAL_MIN_HEIGHTS`] heights.
    pub fn is_empty(&self) -> bool {
        self.0.n == 0
    }

    /// Kernel width (Silverman's bandwidth, in units of the standardised heights).
    pub fn bandwidth(&self) -> f64 {
        self.0.h
    }
}

impl Parameters for Empirical {
    fn validate(&self) -> Result<(), ParamError> {
        Ok(())
    }

    fn skewness(&self) -> f64 {
        self.0.skewness
    }

    fn kurtosis(&self) -> f64 {
        self.0.kurtosis
    }

    fn heights(&self) -> Option<usize> {
        Some(self.0.n)
    }

    /// None: tables do not hold measured heights.
    fn stored(&self) -> Option<[f64; 2]> {
        None
    }

    /// The kernel density itself (normalised by construction), its mode at
    /// the highest centre.
    fn density(&self) -> Density {
        let kde = &*self.0;
        let mode = kde
            .centres
            .iter()
            .copied()
            .max_by(|a, b| kde_value(kde, *a).total_cmp(&kde_value(kde, *b)))
            .unwrap_or(0.0);
        Density::plain(Shape::Empirical(self.clone()), None, None, mode)
    }
}

impl DistributionFamily for Empirical {
    type Form = Empirical;
    const TAKES_HEIGHTS: bool = true;

    /// The heights, and neither skewness nor kurtosis.
    fn from_arguments(
        skewness: Option<f64>,
        kurtosis: Option<f64>,
        heights: Option<&[f64]>,
    ) -> Result<Empirical, DistributionError> {
        let conflict = |name: &'static str, reason: &str| {
            Err(DistributionError::Conflict {
                name,
                reason: reason.into(),
            })
        };
        if let Some(name) = [("skewness", skewness), ("kurtosis", kurtosis)]
            .into_iter()
            .find_map(|(name, v)| v.map(|_| name))
        {
            return conflict(name, "not with an empirical density (the heights give its shape)");
        }
        match heights {
            Some(heights) => Ok(Empirical::new(heights)?),
            None => conflict("heights", "the empirical distribution needs measured heights"),
        }
    }

    /// None: the heights themselves make it.
    fn from_moments(_: f64, _: f64) -> Option<Result<Empirical, ParamError>> {
        None
    }

    /// None: its heights make it.
    fn from_stored(_: f64, _: f64) -> Option<Empirical> {
        None
    }
}

impl Form for Empirical {
    #[inline]
    fn ln(&self, x: f64) -> f64 {
        kde_value(&self.0, x).ln()
    }

    #[inline]
    fn dln(&self, x: f64) -> f64 {
        let (v, dv) = kde_value_slope(&self.0, x);
        dv / v
    }

    /// The outermost kernel centres: outliers make the density
    /// multimodal, and a tail may not be cut at the first dip.
    fn tails(&self, _: f64) -> (f64, f64) {
        let c = &self.0.centres;
        (c[0], c[c.len() - 1])
    }

    /// A kernel's width.
    fn smoothness_scale(&self) -> f64 {
        self.0.h
    }
}

fn kde_value(kde: &Kde, x: f64) -> f64 {
    kde_value_slope(kde, x).0
}

/// The kernel density and its slope at `x`: the kernels within
/// [`KDE_REACH`] widths, by a recurrence from the nearest centre (the
/// centres are evenly spaced: two exponentials per call).
fn kde_value_slope(kde: &Kde, x: f64) -> (f64, f64) {
    let (h, c, w) = (kde.h, &kde.centres, &kde.weights);
    let n = c.len();
    let delta = (c[n - 1] - c[0]) / (n - 1) as f64;
    let inv_h2 = 1.0 / (h * h);
    let norm = 1.0 / (h * (2.0 * core::f64::consts::PI).sqrt());
    let reach = (KDE_REACH * h / delta).ceil() as isize;
    let j0 = ((x - c[0]) / delta)
        .round()
        .clamp(-(reach + 1) as f64, (n as isize + reach) as f64) as isize;
    let t = x - (c[0] + delta * j0 as f64);
    // Kernel j0 + m: exp(−(t − mδ)²/2h²) = base·r^m·q_m, q_m = exp(−m²δ²/2h²).
    let base = (-0.5 * t * t * inv_h2).exp();
    let r = (t * delta * inv_h2).exp();
    let q = (-0.5 * delta * delta * inv_h2).exp();
    let (mut v, mut dv) = (0.0, 0.0);
    let mut add = |j: isize, k: f64| {
        if (0..n as isize).contains(&j) {
            let j = j as usize;
            let term = w[j] * k;
            v += term;
            dv -= term * (x - c[j]) * inv_h2;
        }
    };
    add(j0, base);
    for (dir, ratio) in [(1isize, r), (-1, 1.0 / r)] {
        // k_m = base·ratio^m·q^(m²): k_(m+1) = k_m·ratio·q^(2m+1).
        let (mut k, mut qm) = (base, q);
        for m in 1..=reach {
            k *= ratio * qm;
            qm *= q * q;
            add(j0 + dir * m, k);
        }
    }
    (v * norm, dv * norm)
}
