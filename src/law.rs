//! A friction law for a simulator: μ and dμ/dp of the contact pressure p
//! in pascals, the model's own load F* = p/H (MODEL.md §1, §12).
//!
//! A finite-element code knows, at each contact node, the nominal contact
//! pressure p; the model's load is the nominal pressure over the hardness
//! of the softer material, F* = p/H. A [`FrictionLaw`] is a [`Curve`] μ(F*)
//! over the pressure range the simulator needs, with the chain rule
//! dμ/dp = (dμ/dF*)/H applied for it, a policy for pressures outside that
//! range chosen once, at construction ([`OutOfRange`]), and an open
//! contact (p ≤ 0, or NaN) always refused: there is no μ without contact.
//!
//! ```
//! use ke_friction::{FrictionLaw, OutOfRange, Params};
//! // ψ = 1, θ = 0.001 and the default constants, H = 1 GPa, the default
//! // pressure range (1e-5·H to 0.1·H), pressures outside it clamped.
//! let law = FrictionLaw::new(Params::new(1.0, 0.001), 1e9, None, OutOfRange::Clamp)?;
//! let (mu, dmu_dp) = law.mu_and_derivative(1e7)?;                  // p = 10 MPa: F* = 0.01
//! assert!((mu / 0.52521087083 - 1.0).abs() < 1e-6);               // MODEL.md §7
//! assert!(dmu_dp < 0.0);                                           // 1/Pa
//! assert_eq!(law.mu(2e8)?, law.mu(1e8)?);                          // clamped at p_max
//! assert_eq!(law.clamped(), 1);
//! assert!(law.mu(0.0).is_err());                                   // an open contact
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::sync::atomic::{AtomicU64, Ordering};

use crate::checks::check_in;
use crate::num::Shortest;
use crate::params::PASCALS;
use crate::{
    Classify, Curve, CurveError, DistributionError, ErrorKind, Model, OnError, ParamError, Params, Physical,
    CURVE_ACCURACY,
};

/// Pressures a batch converts to F* at a time (a stack buffer: no
/// allocation).
const BATCH: usize = 256;

/// What a [`FrictionLaw`] does at a pressure outside its range
/// `[p_min, p_max]` (a positive, finite pressure; p ≤ 0 and NaN are
/// always errors).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum OutOfRange {
    /// μ at the nearest end of the range and dμ/dp = 0 there; each such
    /// call is counted ([`FrictionLaw::clamped`]), so a solver can tell
    /// after a step whether the law was used outside its range.
    #[default]
    Clamp,
    /// An error naming the pressure and the range ([`PressureError`]).
    Error,
}

crate::named!(OutOfRange, "out-of-range policy", [Clamp = "clamp", Error = "error"]);

/// The F* range of a law built without a pressure range: p from 1e-5·H
/// to 0.1·H (the range of the embedded table's F* and of the paper's
/// figures).
pub const LAW_F_STAR_RANGE: (f64, f64) = (1e-5, 0.1);

/// Why a [`FrictionLaw`] cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FrictionLawError {
    /// A model input (ψ, θ, a constant, the hardness, a material) is out
    /// of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The measured surface's heights do not fit the distribution asked for.
    #[error(transparent)]
    Distribution(#[from] DistributionError),
    /// The pressure range is not two positive, finite pressures in order.
    #[error("pressure range [{}, {}] Pa is invalid: p_min and p_max must be positive and finite, with p_min < p_max", Shortest(*.lo), Shortest(*.hi))]
    Range {
        /// `p_min`, Pa.
        lo: f64,
        /// `p_max`, Pa.
        hi: f64,
    },
    /// The curve μ(F*) over the range cannot be built (the model has no μ
    /// at a pressure of the range, or the range is too wide).
    #[error("the friction law over pressures [{} Pa, {} Pa] (F* = p/H in [{}, {}]): {error}", Shortest(*.lo), Shortest(*.hi), Shortest(*.lo / *.hardness), Shortest(*.hi / *.hardness))]
    Curve {
        /// `p_min`, Pa.
        lo: f64,
        /// `p_max`, Pa.
        hi: f64,
        /// H, Pa.
        hardness: f64,
        /// Why.
        error: CurveError,
    },
}

impl Classify for FrictionLawError {
    /// A bad input keeps its kind; an invalid range is `Argument` (NaN, ∞)
    /// or `Domain`; a curve's error keeps its kind.
    fn kind(&self) -> ErrorKind {
        match self {
            FrictionLawError::Param(e) => e.kind(),
            FrictionLawError::Distribution(e) => e.kind(),
            FrictionLawError::Range { lo, hi } => {
                if lo.is_finite() && hi.is_finite() {
                    ErrorKind::Domain
                } else {
                    ErrorKind::Argument
                }
            }
            FrictionLawError::Curve { error, .. } => error.kind(),
        }
    }
}

/// Why a [`FrictionLaw`] has no μ at a pressure: a small `Copy` value (the
/// message is formatted only when it is displayed).
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PressureError {
    /// The pressure is NaN, ≤ 0 (an open contact, −∞ included) or, under
    /// [`OutOfRange::Error`], outside the law's range (+∞ included). In a batch, `index`
    /// is the element's position.
    #[error("{}pressure = {} Pa {}", Index(*.index), Shortest(*.value), Reason(*.value, *.lo, *.hi))]
    Pressure {
        /// The element's position in a batch (`None` for one call).
        index: Option<usize>,
        /// The rejected pressure, Pa.
        value: f64,
        /// `p_min`, Pa.
        lo: f64,
        /// `p_max`, Pa.
        hi: f64,
    },
    /// Batch slices of different lengths.
    #[error("batch slices differ in length: pressure {pressure}, {name} {out}")]
    LengthMismatch {
        /// Length of the pressures.
        pressure: usize,
        /// The output that differs (`"mu"` or `"dmu_dp"`).
        name: &'static str,
        /// Its length.
        out: usize,
    },
}

/// "batch element i: " or nothing.
struct Index(Option<usize>);

impl std::fmt::Display for Index {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            Some(i) => write!(f, "batch element {i}: "),
            None => Ok(()),
        }
    }
}

/// Why a pressure has no μ, in words.
struct Reason(f64, f64, f64);

impl std::fmt::Display for Reason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Reason(p, lo, hi) = *self;
        if p.is_nan() {
            write!(f, "is not a number: must be > 0 Pa (a closed contact)")
        } else if p <= 0.0 {
            write!(f, "is an open contact: a friction coefficient needs pressure > 0 Pa")
        } else if p.is_infinite() {
            write!(f, "is not finite: must be > 0 Pa and finite")
        } else {
            write!(
                f,
                "is outside the law's range [{}, {}] Pa (policy error; build the law over a wider range, or with policy clamp)",
                Shortest(lo),
                Shortest(hi)
            )
        }
    }
}

impl PressureError {
    /// This error as the error of batch element `index`.
    pub fn at(self, index: usize) -> PressureError {
        match self {
            PressureError::Pressure { value, lo, hi, .. } => PressureError::Pressure {
                index: Some(index),
                value,
                lo,
                hi,
            },
            other => other,
        }
    }

    /// The element's index, for a batch element's error.
    pub fn index(&self) -> Option<usize> {
        match self {
            PressureError::Pressure { index, .. } => *index,
            PressureError::LengthMismatch { .. } => None,
        }
    }
}

impl Classify for PressureError {
    /// p ≤ 0 (an open contact) is [`ErrorKind::NoMu`]; NaN, ±∞ (+∞ only
    /// under [`OutOfRange::Error`]) and slices
    /// of different lengths are [`ErrorKind::Argument`]; a pressure outside
    /// the range is [`ErrorKind::Domain`].
    fn kind(&self) -> ErrorKind {
        match *self {
            PressureError::Pressure { value, .. } if value.is_finite() && value <= 0.0 => ErrorKind::NoMu,
            PressureError::Pressure { value, .. } => ErrorKind::of_value(value),
            PressureError::LengthMismatch { .. } => ErrorKind::Argument,
        }
    }
}

/// μ(p) and dμ/dp of one surface pair, in SI units, for a simulator: built
/// once from the model inputs and the hardness, then evaluated at each
/// contact node's pressure in a few nanoseconds, with no allocation, from
/// any number of threads (`Send + Sync`).
///
/// - μ(p) = μ(F* = p/H) from a [`Curve`] built by direct integration over
///   `[p_min/H, p_max/H]`: its largest relative error against the model,
///   measured when it is built, is [`max_error`](Self::max_error), at most
///   [`CURVE_ACCURACY`] (1e-6).
/// - dμ/dp = (dμ/dF*)/H, in 1/Pa: the slope of the curve's cubic
///   (continuous across cells).
/// - Outside `[p_min, p_max]` (a positive p, +∞ included: clamped, +∞
///   gets μ(p_max) as 1e300 does): the [`OutOfRange`] policy chosen at
///   construction. p ≤ 0 (an open contact, −∞ included) and NaN are always
///   errors — in a batch, NaN under [`OnError::Nan`].
#[derive(Debug)]
pub struct FrictionLaw {
    /// μ(F*) over `[p_min/H, p_max/H]`.
    curve: Curve,
    /// The model inputs.
    params: Params,
    /// H, Pa.
    hardness: f64,
    /// `[p_min, p_max]`, Pa.
    range: (f64, f64),
    /// The policy outside the range.
    policy: OutOfRange,
    /// μ at `p_min` and at `p_max` (what `Clamp` answers).
    ends: (f64, f64),
    /// Calls answered by clamping, since construction (or the last reset).
    clamped: AtomicU64,
}

impl Clone for FrictionLaw {
    /// A copy with the same clamped count (then counted apart).
    fn clone(&self) -> FrictionLaw {
        FrictionLaw {
            curve: self.curve.clone(),
            params: self.params.clone(),
            hardness: self.hardness,
            range: self.range,
            policy: self.policy,
            ends: self.ends,
            clamped: AtomicU64::new(self.clamped()),
        }
    }
}

impl FrictionLaw {
    /// The law of the model at `params` (ψ, θ and the constants) on a
    /// softer material of hardness `hardness` (Pa), over the pressures
    /// `range` (Pa; `None`: [`LAW_F_STAR_RANGE`] times H), with `policy`
    /// outside it. Builds the curve by direct integration (milliseconds).
    pub fn new(
        params: Params,
        hardness: f64,
        range: Option<(f64, f64)>,
        policy: OutOfRange,
    ) -> Result<FrictionLaw, FrictionLawError> {
        check_in("hardness", hardness, &PASCALS)?;
        let (lo, hi) = range.unwrap_or((LAW_F_STAR_RANGE.0 * hardness, LAW_F_STAR_RANGE.1 * hardness));
        if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && lo < hi) {
            return Err(FrictionLawError::Range { lo, hi });
        }
        let model = Model::new(params)?;
        let curve = Curve::from_model(&model, lo / hardness, hi / hardness).map_err(|error| match error {
            CurveError::Range { .. } => FrictionLawError::Range { lo, hi },
            error => FrictionLawError::Curve {
                lo,
                hi,
                hardness,
                error,
            },
        })?;
        let (f_lo, f_hi) = curve.range();
        let at_end = |f: f64| {
            curve.mu(f).map_err(|e| FrictionLawError::Curve {
                lo,
                hi,
                hardness,
                error: e.into(),
            })
        };
        let ends = (at_end(f_lo)?, at_end(f_hi)?);
        Ok(FrictionLaw {
            curve,
            params: model.params().clone(),
            hardness,
            range: (lo, hi),
            policy,
            ends,
            clamped: AtomicU64::new(0),
        })
    }

    /// The law of physical (SI) inputs ([`Params::from_physical`]; H is
    /// `physical.hardness`) with the default constants' fit and model.
    pub fn from_physical(
        physical: &Physical,
        range: Option<(f64, f64)>,
        policy: OutOfRange,
    ) -> Result<FrictionLaw, FrictionLawError> {
        FrictionLaw::new(Params::from_physical(physical)?, physical.hardness, range, policy)
    }

    /// The law of `materials` on a measured surface, with the heights'
    /// distribution of `family` ([`Surface::distribution`](crate::topography::Surface::distribution);
    /// `None`: its default), as `kefric surface` computes it: σ, R, η and
    /// the skewness and kurtosis from the surface's statistics, β, ε*, ψ, θ
    /// from them and the materials, H = `materials.hardness`.
    #[cfg(feature = "topography")]
    pub fn from_surface(
        surface: &crate::topography::Surface,
        materials: &crate::Materials,
        family: Option<crate::Family>,
        range: Option<(f64, f64)>,
        policy: OutOfRange,
    ) -> Result<FrictionLaw, FrictionLawError> {
        let params = surface.params(materials, surface.distribution(family)?)?;
        FrictionLaw::new(params, materials.hardness, range, policy)
    }

    /// μ at the pressure `p` (Pa): an error for p ≤ 0 (−∞ too) or NaN,
    /// and outside the range (+∞ too) under [`OutOfRange::Error`].
    #[inline]
    pub fn mu(&self, p: f64) -> Result<f64, PressureError> {
        match self.curve.mu(p / self.hardness) {
            Ok(mu) => Ok(mu),
            Err(_) => self.outside(p).map(|(mu, _)| mu),
        }
    }

    /// μ and dμ/dp (1/Pa) at the pressure `p` (Pa), for an implicit
    /// solver's Jacobian; errors as in [`mu`](Self::mu). Clamped, the
    /// derivative is 0 (μ is constant beyond the range's end).
    #[inline]
    pub fn mu_and_derivative(&self, p: f64) -> Result<(f64, f64), PressureError> {
        match self.curve.mu_with_slope(p / self.hardness) {
            Ok((mu, slope)) => Ok((mu, slope / self.hardness)),
            Err(_) => self.outside(p),
        }
    }

    /// The answer at a pressure the curve does not cover: clamped, or the
    /// error. p/H is in the curve's range iff p is in `[p_min, p_max]`
    /// (division is correctly rounded, so monotone), so only the pressure
    /// itself is looked at here.
    #[cold]
    #[inline(never)]
    fn outside(&self, p: f64) -> Result<(f64, f64), PressureError> {
        let error = PressureError::Pressure {
            index: None,
            value: p,
            lo: self.range.0,
            hi: self.range.1,
        };
        // +∞ is above the range like any large pressure: clamped to
        // μ(p_max), not refused (FRIC_COEF gave it the open-contact μ).
        if p.is_nan() || p <= 0.0 || self.policy == OutOfRange::Error {
            return Err(error);
        }
        self.clamped.fetch_add(1, Ordering::Relaxed);
        Ok((if p < self.range.0 { self.ends.0 } else { self.ends.1 }, 0.0))
    }

    /// μ at many pressures, written into `mu` (no allocation). With
    /// [`OnError::Stop`], at the first pressure `i` without μ, `mu[..i]`
    /// holds the results, `mu[i..]` is untouched and the error has index
    /// `i`; with [`OnError::Nan`] such elements are NaN and the batch goes
    /// on. Returns how many elements are NaN.
    pub fn mu_batch(&self, p: &[f64], mu: &mut [f64], on_error: OnError) -> Result<usize, PressureError> {
        lengths(p.len(), "mu", mu.len())?;
        let mut nan = 0;
        let (mut f, mut got) = ([0.0; BATCH], [0.0; BATCH]);
        for (k, (p, out)) in p.chunks(BATCH).zip(mu.chunks_mut(BATCH)).enumerate() {
            let (f, got) = (&mut f[..p.len()], &mut got[..p.len()]);
            self.loads(p, f);
            // The curve's batch (its AVX2 kernel where the CPU has one):
            // NaN exactly where p/H is outside its range or NaN.
            let _ = self.curve.mu_batch_with(f, got, OnError::Nan);
            for (i, (&v, o)) in got.iter().zip(out.iter_mut()).enumerate() {
                if !v.is_nan() {
                    *o = v;
                    continue;
                }
                match self.outside(p[i]) {
                    Ok((m, _)) => *o = m,
                    Err(e) => {
                        bad(on_error, k * BATCH + i, e)?;
                        *o = f64::NAN;
                        nan += 1;
                    }
                }
            }
        }
        Ok(nan)
    }

    /// F* = p/H of each pressure.
    #[inline]
    fn loads(&self, p: &[f64], f: &mut [f64]) {
        for (f, &p) in f.iter_mut().zip(p) {
            *f = p / self.hardness;
        }
    }

    /// μ and dμ/dp (1/Pa) at many pressures, into `mu` and `dmu_dp`; the
    /// contract of [`mu_batch`](Self::mu_batch) (a NaN pair at a bad
    /// element under [`OnError::Nan`]).
    pub fn mu_and_derivative_batch(
        &self,
        p: &[f64],
        mu: &mut [f64],
        dmu_dp: &mut [f64],
        on_error: OnError,
    ) -> Result<usize, PressureError> {
        lengths(p.len(), "mu", mu.len())?;
        lengths(p.len(), "dmu_dp", dmu_dp.len())?;
        let mut nan = 0;
        let (mut f, mut got) = ([0.0; BATCH], [(0.0, 0.0); BATCH]);
        for (k, ((p, m), d)) in p
            .chunks(BATCH)
            .zip(mu.chunks_mut(BATCH))
            .zip(dmu_dp.chunks_mut(BATCH))
            .enumerate()
        {
            let (f, got) = (&mut f[..p.len()], &mut got[..p.len()]);
            self.loads(p, f);
            // The curve's pairs batch; NaN pairs outside its range.
            let _ = self.curve.mu_with_slope_batch_with(f, got, OnError::Nan);
            for (i, ((&(v, slope), m), d)) in got.iter().zip(m.iter_mut()).zip(d.iter_mut()).enumerate() {
                if !v.is_nan() {
                    (*m, *d) = (v, slope / self.hardness);
                    continue;
                }
                match self.outside(p[i]) {
                    Ok(v) => (*m, *d) = v,
                    Err(e) => {
                        bad(on_error, k * BATCH + i, e)?;
                        (*m, *d) = (f64::NAN, f64::NAN);
                        nan += 1;
                    }
                }
            }
        }
        Ok(nan)
    }

    /// How many calls (batch elements count one each) were answered by
    /// clamping since the law was built or [`reset_clamped`](Self::reset_clamped)
    /// (a relaxed counter: exact once the calls that made it have returned).
    pub fn clamped(&self) -> u64 {
        self.clamped.load(Ordering::Relaxed)
    }

    /// Sets the clamped count to 0 and returns what it was (e.g. at the
    /// start of a solver's step).
    pub fn reset_clamped(&self) -> u64 {
        self.clamped.swap(0, Ordering::Relaxed)
    }

    /// The model inputs (ψ, θ and the constants).
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The hardness H of the softer material, Pa.
    pub fn hardness(&self) -> f64 {
        self.hardness
    }

    /// The pressure range `[p_min, p_max]`, Pa.
    pub fn range(&self) -> (f64, f64) {
        self.range
    }

    /// The policy outside the range.
    pub fn policy(&self) -> OutOfRange {
        self.policy
    }

    /// The largest relative error of μ against direct integration,
    /// measured when the law was built (≤ [`accuracy`](Self::accuracy)).
    pub fn max_error(&self) -> f64 {
        self.curve.max_error()
    }

    /// The accuracy the law is built to: [`CURVE_ACCURACY`].
    pub fn accuracy(&self) -> f64 {
        CURVE_ACCURACY
    }

    /// The curve μ(F*) underneath (F* = p/H).
    pub fn curve(&self) -> &Curve {
        &self.curve
    }
}

/// The error for slices of different lengths.
fn lengths(pressure: usize, name: &'static str, out: usize) -> Result<(), PressureError> {
    if pressure == out {
        Ok(())
    } else {
        Err(PressureError::LengthMismatch { pressure, name, out })
    }
}

/// At bad element `index` with error `e`: go on (`Nan`), or the batch
/// error (`Stop`).
fn bad(on_error: OnError, index: usize, e: PressureError) -> Result<(), PressureError> {
    match on_error {
        OnError::Stop => Err(e.at(index)),
        OnError::Nan => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Constants, Named};

    /// The hardness of the tests, Pa.
    const H: f64 = 1.3e9;

    fn law(policy: OutOfRange) -> FrictionLaw {
        FrictionLaw::new(Params::new(1.0, 0.001), H, Some((1e4, 1e8)), policy).unwrap()
    }

    /// μ by direct integration at pressure `p` (the exact model).
    fn exact(model: &Model, p: f64) -> f64 {
        model.at_f_star(p / H).unwrap().mu.unwrap()
    }

    #[test]
    fn the_law_is_the_model_at_f_star_p_over_h_within_the_curve_accuracy() {
        let law = law(OutOfRange::Error);
        let model = Model::new(Params::new(1.0, 0.001)).unwrap();
        let mut rng = crate::rng::SplitMix64(7);
        let mut worst = 0.0f64;
        for _ in 0..200 {
            let p = 1e4 * 1e4f64.powf(rng.unit());
            let want = exact(&model, p);
            worst = worst.max((law.mu(p).unwrap() / want - 1.0).abs());
        }
        // The curve's contract (CURVE_ACCURACY, measured at build time at
        // two points a cell) with a margin for points between those.
        assert!(worst <= 2.0 * CURVE_ACCURACY, "{worst:e}");
        assert!(law.max_error() <= law.accuracy());
        // MODEL.md §7: μ(F* = 0.01) = 0.52521087083 at ψ = 1, θ = 0.001.
        assert!((law.mu(0.01 * H).unwrap() / 0.52521087083 - 1.0).abs() < 1e-6);
    }

    #[test]
    fn the_pressure_derivative_matches_a_finite_difference_of_the_model() {
        let law = law(OutOfRange::Error);
        let model = Model::new(Params::new(1.0, 0.001)).unwrap();
        for p in [2e4, 3.3e5, 1e6, 7e6, 5e7] {
            let (mu, d) = law.mu_and_derivative(p).unwrap();
            assert_eq!(mu, law.mu(p).unwrap());
            // A central difference of the exact model over ±0.1 % of p:
            // truncation error ~1e-7 of the slope for this smooth μ.
            let h = 1e-3 * p;
            let fd = (exact(&model, p + h) - exact(&model, p - h)) / (2.0 * h);
            assert!((d / fd - 1.0).abs() < 1e-4, "p = {p}: {d:e} against {fd:e}");
        }
    }

    #[test]
    fn clamp_answers_the_ends_with_zero_slope_and_counts() {
        let law = law(OutOfRange::Clamp);
        let (lo, hi) = law.range();
        assert_eq!(law.mu_and_derivative(10.0).unwrap(), (law.mu(lo).unwrap(), 0.0));
        assert_eq!(law.mu_and_derivative(1e9).unwrap(), (law.mu(hi).unwrap(), 0.0));
        assert_eq!(law.clamped(), 2);
        // Open contacts (−∞ too) and NaN are never clamped.
        for p in [0.0, -1.0, f64::NAN, f64::NEG_INFINITY, -0.0] {
            assert!(law.mu(p).is_err(), "{p}");
        }
        // +∞ is above the range as 1e300 is (issue 46: FRIC_COEF gave it
        // the open-contact μ(p_min)).
        for p in [1e300, f64::INFINITY] {
            assert_eq!(law.mu_and_derivative(p).unwrap(), (law.mu(hi).unwrap(), 0.0), "{p}");
            let (mut mu, mut d) = ([0.0], [0.0]);
            assert_eq!(
                law.mu_and_derivative_batch(&[p], &mut mu, &mut d, OnError::Nan)
                    .unwrap(),
                0
            );
            assert_eq!((mu[0], d[0]), (law.mu(hi).unwrap(), 0.0));
        }
        assert_eq!(law.reset_clamped(), 6);
        assert_eq!(law.clamped(), 0);
    }

    #[test]
    fn errors_name_the_pressure_and_the_range_and_classify() {
        let law = law(OutOfRange::Error);
        let e = law.mu(2e8).unwrap_err();
        assert_eq!(
            e.to_string(),
            "pressure = 2e8 Pa is outside the law's range [10000, 1e8] Pa \
             (policy error; build the law over a wider range, or with policy clamp)"
        );
        assert_eq!(e.kind(), ErrorKind::Domain);
        let e = law.mu(0.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "pressure = 0 Pa is an open contact: a friction coefficient needs pressure > 0 Pa"
        );
        assert_eq!(e.kind(), ErrorKind::NoMu);
        assert_eq!(law.mu(f64::NAN).unwrap_err().kind(), ErrorKind::Argument);
        assert_eq!(law.clamped(), 0);
    }

    #[test]
    fn long_batches_are_the_scalar_calls_bit_for_bit_across_buffers() {
        // 1000 pressures over three stack buffers: in range, beyond each
        // end, open (p <= 0), NaN and infinite, at scattered places.
        let p: Vec<f64> = (0..1000)
            .map(|i| match i % 97 {
                3 => 10.0,
                17 => 5e8,
                41 => -1.0,
                59 => f64::NAN,
                83 => f64::INFINITY,
                _ => 1e4 * 1e4f64.powf(i as f64 / 999.0),
            })
            .collect();
        for policy in [OutOfRange::Clamp, OutOfRange::Error] {
            let law = law(policy);
            let (mut mu, mut m2, mut d2) = (vec![0.0; 1000], vec![0.0; 1000], vec![0.0; 1000]);
            let nan = law.mu_batch(&p, &mut mu, OnError::Nan).unwrap();
            let clamped = law.reset_clamped();
            assert_eq!(
                nan,
                law.mu_and_derivative_batch(&p, &mut m2, &mut d2, OnError::Nan).unwrap()
            );
            assert_eq!(law.reset_clamped(), clamped);
            let mut want_nan = 0;
            for i in 0..1000 {
                match law.mu_and_derivative(p[i]) {
                    Ok((m, d)) => {
                        assert_eq!(mu[i].to_bits(), m.to_bits(), "{policy:?} p[{i}] = {}", p[i]);
                        assert_eq!((m2[i].to_bits(), d2[i].to_bits()), (m.to_bits(), d.to_bits()), "p[{i}]");
                    }
                    Err(_) => {
                        want_nan += 1;
                        assert!(mu[i].is_nan() && m2[i].is_nan() && d2[i].is_nan(), "p[{i}]");
                    }
                }
            }
            assert_eq!(nan, want_nan, "{policy:?}");
            assert_eq!(
                law.reset_clamped(),
                clamped,
                "{policy:?}: the scalar calls clamp as the batches"
            );
            // Stop: the first bad element in the third buffer is named.
            let e = law.mu_batch(&p[600..], &mut mu[600..], OnError::Stop).unwrap_err();
            let first = (600..1000).find(|&i| law.mu(p[i]).is_err()).unwrap();
            assert_eq!(e.index(), Some(first - 600), "{policy:?}");
        }
    }

    #[test]
    fn batches_follow_the_stop_and_nan_contract() {
        let law = law(OutOfRange::Clamp);
        let p = [1e5, -3.0, 1e12, f64::NAN, 2e6];
        let (mut mu, mut d) = ([7.0; 5], [7.0; 5]);
        let e = law
            .mu_and_derivative_batch(&p, &mut mu, &mut d, OnError::Stop)
            .unwrap_err();
        assert_eq!(e.index(), Some(1));
        assert!(e
            .to_string()
            .starts_with("batch element 1: pressure = -3 Pa is an open contact"));
        assert_eq!((mu[0], d[0]), law.mu_and_derivative(1e5).unwrap());
        assert_eq!(&mu[1..], &[7.0; 4]);
        let n = law.mu_and_derivative_batch(&p, &mut mu, &mut d, OnError::Nan).unwrap();
        assert_eq!(n, 2);
        for (i, &p) in p.iter().enumerate() {
            match law.mu_and_derivative(p) {
                Ok((m, s)) => assert_eq!((mu[i], d[i]), (m, s)),
                Err(_) => assert!(mu[i].is_nan() && d[i].is_nan()),
            }
        }
        let mut only = [0.0; 5];
        assert_eq!(law.mu_batch(&p, &mut only, OnError::Nan).unwrap(), 2);
        assert_eq!(only[4], mu[4]);
        assert!(matches!(
            law.mu_batch(&p, &mut [0.0; 4], OnError::Nan),
            Err(PressureError::LengthMismatch {
                pressure: 5,
                out: 4,
                ..
            })
        ));
    }

    #[test]
    fn a_bad_range_or_hardness_is_refused_naming_it() {
        let p = Params::new(1.0, 0.001);
        let e = FrictionLaw::new(p.clone(), H, Some((1e6, 1e5)), OutOfRange::Clamp).unwrap_err();
        assert!(matches!(e, FrictionLawError::Range { .. }), "{e}");
        let e = FrictionLaw::new(p.clone(), -1.0, None, OutOfRange::Clamp).unwrap_err();
        assert!(e.to_string().starts_with("hardness = -1 is out of range"), "{e}");
        let e = FrictionLaw::new(p.beta(1e9), H, None, OutOfRange::Clamp).unwrap_err();
        assert!(e.to_string().starts_with("beta = "), "{e}");
    }

    #[test]
    fn the_default_range_is_the_curves_f_star_range_times_h() {
        let c = Constants::default().beta(0.05);
        let law = FrictionLaw::new(c.at(2.0, 0.003).unwrap(), H, None, OutOfRange::Error).unwrap();
        assert_eq!(law.range(), (1e-5 * H, 0.1 * H));
        assert_eq!(law.params().constants.beta, 0.05);
        assert_eq!(OutOfRange::parse("clamp").unwrap(), OutOfRange::Clamp);
        fn send_sync<T: Send + Sync>() {}
        send_sync::<FrictionLaw>();
    }
}
