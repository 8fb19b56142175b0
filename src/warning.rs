//! What to know about a result that is still returned: one warning type
//! and one list of kinds for every front end (the CLI prints them on
//! stderr, Python raises `ke_friction.ModelWarning`, C sets a bit of
//! `kef_warnings()`), and the plausibility checks that give them.
//!
//! The checks of a contact ([`Warning::of_contact`]) are arithmetic on
//! its numbers: no allocation, no formatting until a message is asked for.

use crate::model::Contact;
use crate::num::Shortest;
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::fmt;

/// The range of loads the paper covers, 1e-5 ≤ F* ≤ 0.1 (MODEL.md §1):
/// outside it the model is extrapolated ([`Warning::FStarBelowRange`],
/// [`Warning::FStarAboveRange`]).
pub const F_STAR_RANGE: (f64, f64) = (1e-5, 0.1);

/// μ above this is adhesion-dominated ([`Warning::AdhesionDominated`]):
/// the friction force exceeds the load pressing the surfaces together.
pub const MU_ADHESION: f64 = 1.0;

/// Fewer asperities than this expected in contact on the nominal area is
/// too few for a statistical model ([`Warning::FewAsperities`]).
pub const FEW_ASPERITIES: f64 = 10.0;

/// Fewer measured heights than this above the separation h (over σ) is a
/// contact on an extrapolated tail ([`Warning::Tail`]): the density there
/// (a fitted family's, or the kernel density's own smoothing) is not
/// supported by measured points.
pub const TAIL_MIN_POINTS: usize = 10;

/// A detrended height further than this many σ from the mean plane is a
/// spike ([`Warning::Spikes`]): a Gaussian surface has one such point in
/// 5e8 (P(|z| > 6) = 2.0e-9).
pub const SPIKE_SIGMA: f64 = 6.0;

/// A kurtosis above this is spiky ([`Warning::Spikes`]): no fitted height
/// family follows it (the measured files range from 1.8 to 9.2 apart from
/// the spiky one, 811; docs/MODEL.md, "Validity domain").
pub const KURTOSIS_MAX: f64 = 20.0;

/// Points beyond [`SPIKE_SIGMA`]·σ, as a fraction of the valid points,
/// above which a surface has spikes ([`Warning::Spikes`]) whatever its
/// kurtosis: 1e-3 is 5e5 times a Gaussian's share (the measured files
/// without spikes have up to 4.9e-4: di-3, K = 5.7).
pub const SPIKE_FRACTION: f64 = 1e-3;

/// A relative slack on the range's ends: a solved F* may exceed 0.1 by
/// rounding (0.10000000000000003) without lying outside the range.
const RANGE_SLACK: f64 = 1e-9;

/// The kinds of [`Warning`], each with a stable name (JSON, Python) and a
/// stable bit (C's `KEF_WARN_*`: `1 << index` in this list).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum WarningKind {
    /// [`Warning::FStarBelowRange`].
    FStarBelowRange,
    /// [`Warning::FStarAboveRange`].
    FStarAboveRange,
    /// [`Warning::NegativeSeparation`].
    NegativeSeparation,
    /// [`Warning::AdhesionDominated`].
    AdhesionDominated,
    /// [`Warning::FewAsperities`].
    FewAsperities,
    /// [`Warning::NonPeriodic`].
    NonPeriodic,
    /// [`Warning::LowBandwidth`].
    LowBandwidth,
    /// [`Warning::Anisotropy`].
    Anisotropy,
    /// [`Warning::IntervalMismatch`].
    IntervalMismatch,
    /// [`Warning::Unreliable`].
    UnreliableScale,
    /// [`Warning::PsiOutsideDomain`].
    PsiOutsideDomain,
    /// [`Warning::ThetaOutsideDomain`].
    ThetaOutsideDomain,
    /// [`Warning::BetaOutsideDomain`].
    BetaOutsideDomain,
    /// [`Warning::Spikes`].
    Spikes,
    /// [`Warning::Tail`].
    Tail,
}

crate::named!(
    WarningKind,
    "warning",
    [
        FStarBelowRange = "f_star_below_range",
        FStarAboveRange = "f_star_above_range",
        NegativeSeparation = "negative_separation",
        AdhesionDominated = "adhesion_dominated",
        FewAsperities = "few_asperities",
        NonPeriodic = "non_periodic",
        LowBandwidth = "low_bandwidth",
        Anisotropy = "anisotropy",
        IntervalMismatch = "interval_mismatch",
        UnreliableScale = "unreliable_scale",
        PsiOutsideDomain = "psi_domain",
        ThetaOutsideDomain = "theta_domain",
        BetaOutsideDomain = "beta_domain",
        Spikes = "spikes",
        Tail = "tail",
    ]
);

impl WarningKind {
    /// The kind's bit in a mask (C's `KEF_WARN_*`): `1 << index`.
    pub const fn bit(self) -> u32 {
        1 << self as u32
    }

    /// Whether the kind is of one result (a load, a contact), as opposed
    /// to a surface's statistics: a summary counts results for these.
    pub const fn per_result(self) -> bool {
        matches!(
            self,
            WarningKind::FStarBelowRange
                | WarningKind::FStarAboveRange
                | WarningKind::NegativeSeparation
                | WarningKind::AdhesionDominated
                | WarningKind::FewAsperities
                | WarningKind::Tail
        )
    }

    /// The kinds whose bits are set in `mask`, in order.
    pub fn of_mask(mask: u32) -> impl Iterator<Item = WarningKind> {
        WarningKind::ALL.into_iter().filter(move |k| mask & k.bit() != 0)
    }
}

/// Something to know about a result that is still returned.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// F* below the paper's range ([`F_STAR_RANGE`]): extrapolated, and
    /// at such light loads μ comes from a handful of the highest summits.
    FStarBelowRange {
        /// The external force F*.
        f_star: f64,
    },
    /// F* above the paper's range (but ≤ [`F_STAR_MAX`](crate::F_STAR_MAX)): extrapolated.
    FStarAboveRange {
        /// The external force F*.
        f_star: f64,
    },
    /// h* < 0: the mean planes of the heights overlap, outside the
    /// paper's range (0 ≤ h* ≤ 3).
    NegativeSeparation {
        /// The separation h*.
        h_star: f64,
    },
    /// μ > [`MU_ADHESION`]: adhesion, not the load, holds the surfaces
    /// together (a light load on sticky surfaces).
    AdhesionDominated {
        /// μ.
        mu: f64,
        /// The external force F*.
        f_star: f64,
    },
    /// Fewer than [`FEW_ASPERITIES`] asperities expected in contact on
    /// the nominal area: too few for a statistical model.
    FewAsperities {
        /// The expected number of asperities in contact, η·A_n·P(z > d).
        count: f64,
    },
    /// Spectral slope and curvature moments of a map or profile that is
    /// not periodic: the rms jump across its edges exceeds the rms height,
    /// so the moments (and β, ψ, μ) are dominated by that jump.
    NonPeriodic {
        /// The rms difference of the heights across the edges (m).
        mismatch: f64,
        /// The rms height σ (m).
        sigma: f64,
    },
    /// α < 1.5: not an isotropic Gaussian surface (α ≥ 1.5 for one), so
    /// the relations of MODEL.md §10 are approximate.
    LowBandwidth {
        /// The bandwidth α.
        alpha: f64,
    },
    /// A ratio m20/m02 or m40/m04 outside 0.8–1.25: the surface is
    /// anisotropic, and the relations assume isotropy.
    Anisotropy {
        /// `"m20/m02"` or `"m40/m04"`.
        ratio: &'static str,
        /// Its value.
        value: f64,
    },
    /// Two surfaces sampled at intervals differing by more than 1 %, so
    /// their m2, m4 belong to different bands.
    IntervalMismatch {
        /// `"dx"` or `"dy"`.
        name: &'static str,
        /// The interval of the first surface (metres).
        first: f64,
        /// The interval of the second surface (metres).
        second: f64,
    },
    /// The shortest scale the statistics see (λs, or 2·max(dx, dy)
    /// without an S-filter) is below the instrument's reliability cut-off:
    /// m2, m4 and so β and ψ come from scales the instrument distorts.
    Unreliable {
        /// The shortest scale the statistics see (metres).
        scale: f64,
        /// The reliability cut-off (metres).
        cutoff: f64,
    },
    /// ψ outside the range the paper covers, 0.5 ≤ ψ ≤ 8 (docs/MODEL.md,
    /// "Validity domain").
    PsiOutsideDomain {
        /// The plasticity index ψ.
        psi: f64,
    },
    /// θ above the paper's upper limit 0.01 ("very high adhesion energy").
    ThetaOutsideDomain {
        /// The adhesion parameter θ.
        theta: f64,
    },
    /// β outside 0.02 ≤ β ≤ 0.16 (within a factor 4 of the paper's single
    /// β = 0.04).
    BetaOutsideDomain {
        /// The roughness parameter β = ηRσ.
        beta: f64,
    },
    /// Spikes in the heights: a kurtosis above [`KURTOSIS_MAX`], or more
    /// than [`SPIKE_FRACTION`] of the points beyond [`SPIKE_SIGMA`]·σ of
    /// the mean plane: outliers (dust, dropouts, tip artefacts) that decide
    /// the height density's tail.
    Spikes {
        /// The kurtosis K of the detrended heights.
        kurtosis: f64,
        /// Points beyond [`SPIKE_SIGMA`]·σ.
        beyond: usize,
        /// The valid points.
        points: usize,
    },
    /// The contacting asperities lie where no (or too few) heights were
    /// measured: fewer than [`TAIL_MIN_POINTS`] measured heights lie above
    /// the separation h, so μ comes from the height density's extrapolated
    /// tail.
    Tail {
        /// The separation h* = h/σ.
        h_star: f64,
        /// The highest measured height over σ.
        max_height: f64,
        /// Measured heights above h (counted exactly up to
        /// the topography's `TAIL_SAMPLE`, 64).
        above: usize,
    },
}

impl Warning {
    /// The warning's kind (its name: [`WarningKind::name`]).
    pub const fn kind(&self) -> WarningKind {
        match self {
            Warning::FStarBelowRange { .. } => WarningKind::FStarBelowRange,
            Warning::FStarAboveRange { .. } => WarningKind::FStarAboveRange,
            Warning::NegativeSeparation { .. } => WarningKind::NegativeSeparation,
            Warning::AdhesionDominated { .. } => WarningKind::AdhesionDominated,
            Warning::FewAsperities { .. } => WarningKind::FewAsperities,
            Warning::NonPeriodic { .. } => WarningKind::NonPeriodic,
            Warning::LowBandwidth { .. } => WarningKind::LowBandwidth,
            Warning::Anisotropy { .. } => WarningKind::Anisotropy,
            Warning::IntervalMismatch { .. } => WarningKind::IntervalMismatch,
            Warning::Unreliable { .. } => WarningKind::UnreliableScale,
            Warning::PsiOutsideDomain { .. } => WarningKind::PsiOutsideDomain,
            Warning::ThetaOutsideDomain { .. } => WarningKind::ThetaOutsideDomain,
            Warning::BetaOutsideDomain { .. } => WarningKind::BetaOutsideDomain,
            Warning::Spikes { .. } => WarningKind::Spikes,
            Warning::Tail { .. } => WarningKind::Tail,
        }
    }

    /// How far from plausible: of two warnings of one kind the larger is
    /// the worse (the one a summary states).
    fn severity(&self) -> f64 {
        match *self {
            Warning::FStarBelowRange { f_star } => -f_star,
            Warning::FStarAboveRange { f_star } => f_star,
            Warning::NegativeSeparation { h_star } => -h_star,
            Warning::AdhesionDominated { mu, .. } => mu,
            Warning::FewAsperities { count } => -count,
            Warning::NonPeriodic { mismatch, sigma } => mismatch / sigma,
            Warning::LowBandwidth { alpha } => -alpha,
            Warning::Anisotropy { value, .. } => value.max(1.0 / value),
            Warning::IntervalMismatch { first, second, .. } => (first / second).max(second / first),
            Warning::Unreliable { scale, cutoff } => cutoff / scale,
            // Distance outside the range, as a ratio.
            Warning::PsiOutsideDomain { psi } => (psi / 8.0).max(0.5 / psi),
            Warning::ThetaOutsideDomain { theta } => theta,
            Warning::BetaOutsideDomain { beta } => (beta / 0.16).max(0.02 / beta),
            Warning::Spikes { kurtosis, .. } => kurtosis,
            Warning::Tail { h_star, max_height, .. } => h_star - max_height,
        }
    }

    /// The plausibility warnings of a contact: F* outside the paper's
    /// range, h* < 0, μ > 1 (adhesion-dominated). Arithmetic only.
    ///
    /// ```
    /// use ke_friction::{Model, Params, Warning, WarningKind};
    /// let c = Model::new(Params::new(1.0, 0.001))?.at_f_star(1e-7)?;
    /// let kinds: Vec<WarningKind> = Warning::of_contact(&c).map(|w| w.kind()).collect();
    /// assert_eq!(kinds, [WarningKind::FStarBelowRange]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn of_contact(c: &Contact) -> impl Iterator<Item = Warning> {
        Warning::of_point(c.f_star, c.h_star, c.mu)
    }

    /// [`Warning::of_contact`] of a point known by F*, h* and μ alone (a
    /// table's lookup).
    pub fn of_point(f_star: f64, h_star: f64, mu: Option<f64>) -> impl Iterator<Item = Warning> {
        // F* <= 0 has no μ (the contact's own answer), not a light load.
        let below = (f_star > 0.0 && f_star < F_STAR_RANGE.0 * (1.0 - RANGE_SLACK))
            .then_some(Warning::FStarBelowRange { f_star });
        let above = (f_star > F_STAR_RANGE.1 * (1.0 + RANGE_SLACK)).then_some(Warning::FStarAboveRange { f_star });
        let negative = (h_star < 0.0).then_some(Warning::NegativeSeparation { h_star });
        let adhesion = mu
            .filter(|&mu| mu > MU_ADHESION)
            .map(|mu| Warning::AdhesionDominated { mu, f_star });
        [below, above, negative, adhesion].into_iter().flatten()
    }

    /// The bits ([`WarningKind::bit`]) of [`Warning::of_contact`]'s
    /// warnings: what C's `kef_warnings()` accumulates.
    pub fn mask_of_contact(c: &Contact) -> u32 {
        Warning::of_contact(c).fold(0, |m, w| m | w.kind().bit())
    }

    /// [`Warning::FewAsperities`] if fewer than [`FEW_ASPERITIES`] are
    /// expected in contact (`count`, e.g. from
    /// [`Model::asperities_in_contact`](crate::Model::asperities_in_contact)).
    pub fn of_asperities(count: f64) -> Option<Warning> {
        (count < FEW_ASPERITIES).then_some(Warning::FewAsperities { count })
    }

    /// The model's inputs outside its validity domain (docs/MODEL.md,
    /// "Validity domain"): ψ outside [0.5, 8], θ above 0.01, β outside
    /// [0.02, 0.16]. Arithmetic only.
    ///
    /// ```
    /// use ke_friction::{Params, Warning, WarningKind};
    /// let kinds = |p: &Params| Warning::of_params(p).map(|w| w.kind()).collect::<Vec<_>>();
    /// assert!(kinds(&Params::new(2.0, 0.001)).is_empty());
    /// assert_eq!(kinds(&Params::new(209.0, 0.02)), [WarningKind::PsiOutsideDomain, WarningKind::ThetaOutsideDomain]);
    /// ```
    pub fn of_params(params: &crate::Params) -> impl Iterator<Item = Warning> {
        use crate::bound::domain;
        let (psi, theta, beta) = (params.psi, params.theta, params.constants.beta);
        let psi = (!domain::PSI.contains(psi)).then_some(Warning::PsiOutsideDomain { psi });
        let theta = (!domain::THETA.contains(theta)).then_some(Warning::ThetaOutsideDomain { theta });
        let beta = (!domain::BETA.contains(beta)).then_some(Warning::BetaOutsideDomain { beta });
        [psi, theta, beta].into_iter().flatten()
    }

    /// [`Warning::Spikes`] if the heights' kurtosis exceeds
    /// [`KURTOSIS_MAX`] or more than [`SPIKE_FRACTION`] of the `points`
    /// lie beyond [`SPIKE_SIGMA`]·σ (`beyond` of them).
    pub fn of_spikes(kurtosis: f64, beyond: usize, points: usize) -> Option<Warning> {
        (kurtosis > KURTOSIS_MAX || beyond as f64 > SPIKE_FRACTION * points as f64).then_some(Warning::Spikes {
            kurtosis,
            beyond,
            points,
        })
    }

    /// [`Warning::Tail`] if fewer than [`TAIL_MIN_POINTS`] of the measured
    /// heights lie above the separation `h_star` (h/σ): `max_height` is
    /// the highest over σ, `above` the count above h* (exact below
    /// the topography's `TAIL_SAMPLE`, 64).
    pub fn of_tail(h_star: f64, max_height: f64, above: usize) -> Option<Warning> {
        (above < TAIL_MIN_POINTS).then_some(Warning::Tail {
            h_star,
            max_height,
            above,
        })
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = Shortest::sig;
        let (lo, hi) = (Shortest(F_STAR_RANGE.0), Shortest(F_STAR_RANGE.1));
        match *self {
            Warning::FStarBelowRange { f_star } => write!(
                f,
                "F* = {} is below the range the paper covers ({lo} <= F* <= {hi}): so light a load touches only \
                 the highest summits, and the model is extrapolated there",
                s(f_star)
            ),
            Warning::FStarAboveRange { f_star } => write!(
                f,
                "F* = {} is above the range the paper covers ({lo} <= F* <= {hi}): the model is extrapolated there \
                 (F* > {} is refused: a pressure above the hardness)",
                s(f_star),
                Shortest(crate::F_STAR_MAX)
            ),
            Warning::NegativeSeparation { h_star } => write!(
                f,
                "h* = {} is below 0: the mean planes overlap, outside the range the paper covers (0 <= h* <= 3); \
                 the model is extrapolated there",
                s(h_star)
            ),
            Warning::AdhesionDominated { mu, f_star } => write!(
                f,
                "mu = {} > {} at F* = {}: adhesion dominates (the friction force exceeds the load); \
                 this mu is the adhesive contact's, not a friction coefficient of the load",
                s(mu),
                Shortest(MU_ADHESION),
                s(f_star)
            ),
            Warning::FewAsperities { count } => write!(
                f,
                "about {} asperities are in contact on the nominal area (fewer than {}): too few for the \
                 statistical model; give a larger area or a heavier load",
                s(count),
                Shortest(FEW_ASPERITIES)
            ),
            Warning::NonPeriodic { mismatch, sigma } => write!(
                f,
                "derivative = spectral on a surface that is not periodic: its heights jump by {} m (rms) across \
                 the edges, more than the rms height {} m, so m2, m4, beta and psi are dominated by the jump; \
                 use the finite-difference derivative (the default) for a non-periodic measurement",
                s(mismatch),
                s(sigma)
            ),
            Warning::LowBandwidth { alpha } => write!(
                f,
                "the bandwidth alpha = {} is below 1.5: this is not an isotropic Gaussian surface, \
                 so the summit density, radius and beta are approximate",
                s(alpha)
            ),
            Warning::Anisotropy { ratio, value } => write!(
                f,
                "{ratio} = {} is outside 0.8-1.25: the surface is anisotropic, and the relations assume an \
                 isotropic surface; analyse each direction apart (profiles along x and along y) and quote both \
                 results, or slide along the direction of the measurement",
                s(value)
            ),
            Warning::IntervalMismatch { name, first, second } => write!(
                f,
                "the two surfaces have {name} = {} m and {} m (differing by more than 1 %): \
                 their slope and curvature moments belong to different bands; the result keeps the first's",
                s(first),
                s(second)
            ),
            Warning::Unreliable { scale, cutoff } => write!(
                f,
                "the shortest scale analysed, {} m, is below the instrument's reliability cut-off \
                 {} m: beta, R, eta and psi come from distorted scales; filter at lambda_s = {} m \
                 (or lambda_s auto)",
                s(scale),
                s(cutoff),
                s(cutoff)
            ),
            Warning::PsiOutsideDomain { psi } => write!(
                f,
                "psi = {} is outside the range the paper covers (psi {}): {}; the model is extrapolated there",
                s(psi),
                crate::bound::domain::PSI.range(),
                if psi > 8.0 {
                    "the paper finds the friction at psi = 8 \"unreasonably small\" and the model \"may be \
                     invalid at large plasticity index values\" (no strain hardening)"
                } else {
                    "below 0.5 the contact is elastic and adhesion-dominated, unstudied"
                }
            ),
            Warning::ThetaOutsideDomain { theta } => write!(
                f,
                "theta = {} is above the range the paper covers (theta {}; its upper limit is \"very high \
                 adhesion energy\" of very clean surfaces in vacuum): the model is extrapolated there",
                s(theta),
                crate::bound::domain::THETA.range()
            ),
            Warning::BetaOutsideDomain { beta } => write!(
                f,
                "beta = {} is outside {} (within a factor 4 of the paper's beta = 0.04, from Greenwood and Williamson): \
                 the surface is unlike those the model was built for; check the band (lambda_s) and \
                 the sampling",
                s(beta),
                crate::bound::domain::BETA.range()
            ),
            Warning::Spikes {
                kurtosis,
                beyond,
                points,
            } => write!(
                f,
                "the heights have spikes: kurtosis {} (limit {}), {beyond} of {points} points beyond {} sigma \
                 of the mean plane; outliers decide the height density's tail: clean the data (remove \
                 outliers, fill dropouts) or filter (lambda_s)",
                s(kurtosis),
                Shortest(KURTOSIS_MAX),
                Shortest(SPIKE_SIGMA)
            ),
            Warning::Tail {
                h_star,
                max_height,
                above,
            } => write!(
                f,
                "the contact lies on an extrapolated tail: h* = {} with the highest measured height at {} \
                 sigma and {above} measured points above the separation (fewer than {}): mu comes from the \
                 height density beyond the data; compare the empirical and gaussian height models, or a \
                 heavier load",
                s(h_star),
                s(max_height),
                TAIL_MIN_POINTS
            ),
        }
    }
}

/// A warning is recorded as `{"kind": "...", "message": "...", ...}` with
/// its values by their field names (`f_star`, `h_star`, `mu`, `count`,
/// `mismatch` and `sigma`, `alpha`, `ratio` and `value`, `name`, `first`
/// and `second`, `scale` and `cutoff`).
impl Serialize for Warning {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        self.entries(&mut map)?;
        map.end()
    }
}

impl Warning {
    /// The record's entries ([`Warning`]'s `Serialize`).
    fn entries<M: SerializeMap>(&self, map: &mut M) -> Result<(), M::Error> {
        map.serialize_entry("kind", &self.kind())?;
        map.serialize_entry("message", &self.to_string())?;
        match self {
            Warning::FStarBelowRange { f_star } | Warning::FStarAboveRange { f_star } => {
                map.serialize_entry("f_star", f_star)?
            }
            Warning::NegativeSeparation { h_star } => map.serialize_entry("h_star", h_star)?,
            Warning::AdhesionDominated { mu, f_star } => {
                map.serialize_entry("mu", mu)?;
                map.serialize_entry("f_star", f_star)?;
            }
            Warning::FewAsperities { count } => map.serialize_entry("count", count)?,
            Warning::NonPeriodic { mismatch, sigma } => {
                map.serialize_entry("mismatch", mismatch)?;
                map.serialize_entry("sigma", sigma)?;
            }
            Warning::LowBandwidth { alpha } => map.serialize_entry("alpha", alpha)?,
            Warning::Anisotropy { ratio, value } => {
                map.serialize_entry("ratio", ratio)?;
                map.serialize_entry("value", value)?;
            }
            Warning::Unreliable { scale, cutoff } => {
                map.serialize_entry("scale", scale)?;
                map.serialize_entry("cutoff", cutoff)?;
            }
            Warning::IntervalMismatch { name, first, second } => {
                map.serialize_entry("name", name)?;
                map.serialize_entry("first", first)?;
                map.serialize_entry("second", second)?;
            }
            Warning::PsiOutsideDomain { psi } => map.serialize_entry("psi", psi)?,
            Warning::ThetaOutsideDomain { theta } => map.serialize_entry("theta", theta)?,
            Warning::BetaOutsideDomain { beta } => map.serialize_entry("beta", beta)?,
            Warning::Spikes {
                kurtosis,
                beyond,
                points,
            } => {
                map.serialize_entry("kurtosis", kurtosis)?;
                map.serialize_entry("beyond", beyond)?;
                map.serialize_entry("points", points)?;
            }
            Warning::Tail {
                h_star,
                max_height,
                above,
            } => {
                map.serialize_entry("h_star", h_star)?;
                map.serialize_entry("max_height", max_height)?;
                map.serialize_entry("above", above)?;
            }
        }
        Ok(())
    }
}

/// The warnings of many results (a sweep of loads, say), once per kind:
/// how many results gave each kind, of how many, and the worst of them.
/// What the CLI prints and Python warns.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Warnings {
    /// Per kind, in order of first appearance: the worst warning and the count.
    kinds: Vec<(Warning, usize)>,
    /// The results noted.
    total: usize,
}

impl Warnings {
    /// No warnings, no results.
    pub fn new() -> Warnings {
        Warnings::default()
    }

    /// Notes one result (a contact, a load) and adds `warnings`, its own.
    pub fn note(&mut self, warnings: impl IntoIterator<Item = Warning>) {
        self.total += 1;
        self.extend(warnings);
    }

    /// Notes a contact and its [`Warning::of_contact`] warnings.
    pub fn note_contact(&mut self, c: &Contact) {
        self.note(Warning::of_contact(c));
    }

    /// Adds warnings not tied to one result (a surface's).
    pub fn extend(&mut self, warnings: impl IntoIterator<Item = Warning>) {
        for w in warnings {
            match self.kinds.iter_mut().find(|(k, _)| k.kind() == w.kind()) {
                Some((worst, count)) => {
                    *count += 1;
                    if w.severity() > worst.severity() {
                        *worst = w;
                    }
                }
                None => self.kinds.push((w, 1)),
            }
        }
    }

    /// Whether there is no warning.
    pub fn is_empty(&self) -> bool {
        self.kinds.is_empty()
    }

    /// The bits of the kinds present ([`WarningKind::bit`]).
    pub fn mask(&self) -> u32 {
        self.kinds.iter().fold(0, |m, (w, _)| m | w.kind().bit())
    }

    /// One summary per kind, in order of first appearance.
    pub fn summaries(&self) -> impl Iterator<Item = Summary<'_>> {
        self.kinds.iter().map(move |(worst, count)| Summary {
            worst,
            count: *count,
            total: self.total,
        })
    }
}

/// The warnings of one kind over many results ([`Warnings::summaries`]):
/// the worst, how many results gave it and of how many. Its Display is
/// the worst's message, preceded by `"3 of 7 results; the worst: "` when
/// more than one result was noted and the kind is a result's
/// ([`WarningKind::per_result`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary<'a> {
    /// The worst warning of the kind.
    pub worst: &'a Warning,
    /// How many results gave the kind.
    pub count: usize,
    /// How many results were noted (0 when the warnings were not tied to
    /// results).
    pub total: usize,
}

/// A summary is recorded as its worst warning's record with `count` and
/// `of` (the results that gave the kind, and the results noted) and
/// `summary` (its Display: the line a front end shows).
impl Serialize for Summary<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        self.worst.entries(&mut map)?;
        map.serialize_entry("count", &self.count)?;
        map.serialize_entry("of", &self.total)?;
        map.serialize_entry("summary", &self.to_string())?;
        map.end()
    }
}

impl fmt::Display for Summary<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.total > 1 && self.worst.kind().per_result() {
            write!(f, "{} of {} results; the worst: {}", self.count, self.total, self.worst)
        } else {
            write!(f, "{}", self.worst)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Model, Params};

    /// Every kind has its own bit, and the bits are its index (C's
    /// constants depend on that order).
    #[test]
    fn kinds_have_distinct_bits_in_list_order() {
        for (i, k) in WarningKind::ALL.iter().enumerate() {
            assert_eq!(k.bit(), 1 << i);
        }
        let all = WarningKind::ALL.iter().fold(0, |m, k| m | k.bit());
        assert_eq!(WarningKind::of_mask(all).count(), WarningKind::ALL.len());
    }

    fn contact(h_star: f64, f_star: f64, mu: Option<f64>) -> Contact {
        Contact {
            h_star,
            d_star: h_star,
            p_star: f_star,
            fs_star: 0.0,
            q_star: 0.0,
            f_star,
            mu,
        }
    }

    #[test]
    fn a_contact_in_the_papers_range_gives_no_warning() {
        let model = Model::new(Params::new(1.0, 0.001)).unwrap();
        for f in [1e-5, 1e-3, 0.01] {
            let c = model.at_f_star(f).unwrap();
            assert_eq!(Warning::of_contact(&c).count(), 0, "F* = {f}");
        }
    }

    #[test]
    fn each_implausible_contact_gives_its_kind() {
        let kinds = |c: Contact| Warning::of_contact(&c).map(|w| w.kind()).collect::<Vec<_>>();
        assert_eq!(kinds(contact(3.0, 2e-11, Some(0.5))), [WarningKind::FStarBelowRange]);
        assert_eq!(
            kinds(contact(6.0, -2e-10, None)),
            [],
            "no mu, no load: not a light load"
        );
        assert_eq!(
            kinds(contact(-0.5, 0.5, Some(0.1))),
            [WarningKind::FStarAboveRange, WarningKind::NegativeSeparation]
        );
        assert_eq!(kinds(contact(2.0, 1e-3, Some(1.5))), [WarningKind::AdhesionDominated]);
        assert_eq!(
            Warning::mask_of_contact(&contact(3.0, 1e-7, Some(6762.0))),
            WarningKind::FStarBelowRange.bit() | WarningKind::AdhesionDominated.bit()
        );
    }

    #[test]
    fn a_summary_states_the_count_and_the_worst() {
        let mut w = Warnings::new();
        for f in [1e-6, 1e-3, 2e-11, 1e-7] {
            w.note_contact(&contact(3.0, f, Some(0.5)));
        }
        let s: Vec<String> = w.summaries().map(|s| s.to_string()).collect();
        assert_eq!(s.len(), 1);
        assert!(
            s[0].starts_with("3 of 4 results; the worst: F* = 2e-11 is below"),
            "{}",
            s[0]
        );
        assert_eq!(w.mask(), WarningKind::FStarBelowRange.bit());
    }

    /// Messages give numbers with 6 significant digits at most.
    #[test]
    fn messages_round_to_six_digits() {
        let w = Warning::AdhesionDominated {
            mu: 6762.123456789,
            f_star: 2.0000000000000004e-11,
        };
        assert!(w.to_string().starts_with("mu = 6762.12 > 1 at F* = 2e-11:"), "{w}");
    }
}
