//! The surface friction model: direct integration at a separation h* or an
//! external force F* (MODEL.md §4–5).

pub mod asperity;
mod integrals;
mod integrator;
pub(crate) mod laws;

use crate::checks::ParamError;
use crate::num::Shortest;
use crate::params::Params;
use integrals::Integrals;

/// The largest external force the model takes, F* = 1: a nominal
/// pressure equal to the hardness (MODEL.md §1). Above it every asperity
/// would be fully plastic beyond the nominal area; the model has no
/// meaning there and F* > 1 is refused as a domain error.
pub const F_STAR_MAX: f64 = 1.0;

/// The state of the contact at one separation (all quantities dimensionless,
/// MODEL.md §1).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Contact {
    /// Separation of the mean surface heights h*.
    pub h_star: f64,
    /// Separation of the mean asperity heights d* = h* − y_s*.
    pub d_star: f64,
    /// Contact load P*.
    pub p_star: f64,
    /// Adhesion force Fs*.
    pub fs_star: f64,
    /// Static friction force Q*.
    pub q_star: f64,
    /// External force F* = P* − Fs*.
    pub f_star: f64,
    /// Static friction coefficient μ = Q*/F*; `None` where F* ≤ 0, where it
    /// is undefined.
    pub mu: Option<f64>,
}

impl Contact {
    /// μ, or [`EvalError::NoMu`] (naming F* and h*) where it is undefined:
    /// what every front end reports for a contact without μ.
    pub fn mu_or_err(&self) -> Result<f64, EvalError> {
        self.mu.ok_or(EvalError::NoMu {
            f_star: self.f_star,
            h_star: self.h_star,
        })
    }
}

/// An evaluation that cannot be done.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EvalError {
    /// h* is NaN, infinite or beyond the supported range.
    #[error("h_star = {} is out of range: must be finite, within ±{}", Shortest(*.0), Shortest(H_LIMIT))]
    HStar(f64),
    /// F* is NaN, infinite, zero or negative.
    #[error("f_star = {} is out of range: must be > 0 and finite", Shortest(*.0))]
    FStar(f64),
    /// F* above [`F_STAR_MAX`] = 1: a nominal pressure
    /// above the hardness, where the model has no meaning.
    #[error("f_star = {} is out of range: must be <= {} (a nominal pressure above the hardness: the model has no meaning there)", Shortest::sig(*.0), Shortest(F_STAR_MAX))]
    FStarAboveHardness(f64),
    /// No separation in the supported range gives this F*.
    #[error("f_star = {} is out of reach: the largest F* for h_star >= -{} is {}", Shortest(*.f_star), Shortest(H_LIMIT), Shortest(*.f_max))]
    FStarTooLarge {
        /// The requested F*.
        f_star: f64,
        /// F* at the lower end of the h* range.
        f_max: f64,
    },
    /// μ is not defined, or not positive, at this point: the external
    /// force is not positive at this separation (adhesion outweighs the
    /// contact load), or the friction fit gives μ ≤ 0 there.
    #[error("no positive mu at f_star = {}, h_star = {}", Shortest(*.f_star), Shortest(*.h_star))]
    NoMu {
        /// F* at that separation.
        f_star: f64,
        /// The separation.
        h_star: f64,
    },
    /// The root search did not converge (a bug: please report it with the
    /// parameters).
    #[error("no convergence solving F*(h*) = {} after {iterations} iterations (last h* = {})", Shortest(*.f_star), Shortest(*.h_star))]
    NoConvergence {
        /// The requested F*.
        f_star: f64,
        /// The last iterate.
        h_star: f64,
        /// Iterations done.
        iterations: usize,
    },
}

/// Largest |ln F*(h*) − ln F*| at which the root search may stop on a
/// vanishing step (a converged Newton step leaves ~1e-15).
const SOLVE_RESIDUAL: f64 = 1e-9;

/// |h*| beyond this is rejected: far outside any physical contact, and the
/// integrals would lose all precision to cancellation in `z* − d*`.
pub const H_LIMIT: f64 = 1e6;

/// A validated model, ready to evaluate ("plan once, evaluate many").
///
/// ```
/// use ke_friction::{Model, Params};
/// let model = Model::new(Params::new(1.0, 0.001))?;
/// let c = model.at_f_star(0.01)?;
/// assert!((c.h_star - 1.4692414618).abs() < 1e-9); // MODEL.md §7
/// assert!((c.mu.unwrap() - 0.52521087083).abs() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Model {
    params: Params,
    integrals: Integrals,
}

impl Model {
    /// Checks `params` (MODEL.md §1) and plans the integrals.
    pub fn new(params: Params) -> Result<Model, ParamError> {
        params.validate()?;
        Ok(Model {
            integrals: Integrals::new(&params),
            params,
        })
    }

    /// The parameters this model was built from.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// y_s* = h* − d*, the offset between the two reference planes.
    pub fn y_s(&self) -> f64 {
        self.integrals.ys
    }

    /// The contact at separation `h_star` (MODEL.md §4).
    pub fn at_h_star(&self, h_star: f64) -> Result<Contact, EvalError> {
        if !(h_star.is_finite() && h_star.abs() <= H_LIMIT) {
            return Err(EvalError::HStar(h_star));
        }
        let d = h_star - self.integrals.ys;
        let s = self.integrals.evaluate(d, true);
        let f = s.p - s.fs;
        Ok(Contact {
            h_star,
            d_star: d,
            p_star: s.p,
            fs_star: s.fs,
            q_star: s.q,
            f_star: f,
            mu: (f > 0.0).then(|| s.q / f),
        })
    }

    /// The expected number of asperities in contact in `contact` on a
    /// nominal area holding `summits` summits (η·A_n): `summits` times the
    /// fraction of the summit heights above d*. Fewer than
    /// [`FEW_ASPERITIES`](crate::FEW_ASPERITIES) is too few for this
    /// statistical model ([`Warning::of_asperities`](crate::Warning::of_asperities)).
    ///
    /// ```
    /// use ke_friction::{Model, Params};
    /// let model = Model::new(Params::new(1.0, 0.001))?;
    /// let c = model.at_h_star(model.y_s())?; // d* = 0: half the summits touch
    /// assert!((model.asperities_in_contact(&c, 1e4) - 5e3).abs() < 1e-9);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn asperities_in_contact(&self, contact: &Contact, summits: f64) -> f64 {
        summits * self.integrals.contact_fraction(contact.d_star)
    }

    /// F* and dF*/dh* at `h_star` (no friction integrals).
    pub fn force(&self, h_star: f64) -> (f64, f64) {
        let s = self.integrals.evaluate(h_star - self.integrals.ys, false);
        (s.p - s.fs, s.dp - s.dfs)
    }

    /// The contact where the external force is `f_star`: solves
    /// F*(h*) = f_star on the branch where F* > 0 and decreases
    /// (MODEL.md §5), to full double precision.
    ///
    /// F* > [`F_STAR_MAX`] = 1 (a nominal pressure
    /// above the hardness) is [`EvalError::FStarAboveHardness`]: the model
    /// has no meaning there.
    pub fn at_f_star(&self, f_star: f64) -> Result<Contact, EvalError> {
        check_f_star(f_star)?;
        let h = self.solve_h(f_star, 1.0)?;
        self.at_h_star(h)
    }

    /// μ and dμ/dF* where the external force is `f_star`: μ by direct
    /// integration ([`at_f_star`](Self::at_f_star)); the slope as dμ/dh*
    /// from a five-point difference over a step in h* that moves F* by
    /// about 0.1% (at most 1e-3·(1 + |h*|); error near 1e-10 relative), divided by the analytic
    /// dF*/dh*. An error where μ is undefined (F* ≤ 0) at or near `f_star`.
    pub fn mu_with_slope_at_f_star(&self, f_star: f64) -> Result<(f64, f64), EvalError> {
        check_f_star(f_star)?;
        let h = self.solve_h(f_star, 1.0)?;
        let (force, d_force) = self.force(h);
        let mu_at = |h: f64| -> Result<f64, EvalError> { self.at_h_star(h)?.mu_or_err() };
        // A step that moves F* by about 0.1%, at most 1e-3·(1 + |h*|): where
        // dF*/dh* nearly vanishes (a J-shaped end meeting a regime
        // boundary) the step would otherwise leave the contact altogether.
        let step = 1e-3 * (force / d_force).abs().min(1.0 + h.abs());
        let d_mu_dh = (-mu_at(h + 2.0 * step)? + 8.0 * mu_at(h + step)? - 8.0 * mu_at(h - step)?
            + mu_at(h - 2.0 * step)?)
            / (12.0 * step);
        Ok((mu_at(h)?, d_mu_dh / d_force))
    }

    /// Like [`at_f_star`](Self::at_f_star) but returns only h*, starting the
    /// search at `guess` (a nearby solution makes it faster). Any F* the
    /// model reaches is solved, also above 1: a table's ghost nodes lie
    /// there (values for the interpolant, never answers).
    pub fn solve_h(&self, f_star: f64, guess: f64) -> Result<f64, EvalError> {
        if !(f_star.is_finite() && f_star > 0.0) {
            return Err(EvalError::FStar(f_star));
        }

        let target = f_star.ln();
        // Newton on g(h) = ln F*(h) − ln f, safeguarded by a bracket
        // [lo, hi] with g(lo) > 0 > g(hi); F* ≤ 0 lies beyond the root.
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut h = if guess.is_finite() {
            guess.clamp(-H_LIMIT, H_LIMIT)
        } else {
            1.0
        };
        let mut max_step = 1.0;
        const ITERATIONS: usize = 200;
        for _ in 0..ITERATIONS {
            let (f, df) = self.force(h);
            let mut next;
            // |ln F*(h) − ln f|: a step-size convergence counts only with a
            // small residual (a derivative that is off, e.g. at a kink where
            // the contact plane passes an end of a bounded density, must not
            // stop the search).
            let mut residual = f64::INFINITY;
            if f > 0.0 && f.is_finite() {
                let g = f.ln() - target;
                residual = g.abs();
                if g == 0.0 {
                    return Ok(h);
                }
                if g > 0.0 {
                    lo = h;
                } else {
                    hi = h;
                }
                let slope = df / f;
                next = if slope < 0.0 { h - g / slope } else { f64::NAN };
            } else {
                hi = h;
                next = f64::NAN;
            }
            let tol = 2.0 * f64::EPSILON * h.abs().max(1.0);
            if (next - h).abs() <= tol && residual > SOLVE_RESIDUAL {
                // Newton stalled away from the root: bisect, or widen the search.
                next = f64::NAN;
            }
            if (next - h).abs() <= tol {
                // Converged, even where the root is a bound of the bracket
                // (the step rounds to h = hi or lo): bisecting on would
                // only walk back to it, one halving per evaluation.
                return Ok(next);
            }
            let bracketed = lo.is_finite() && hi.is_finite();
            if !(next > lo && next < hi) {
                next = if bracketed {
                    0.5 * (lo + hi)
                } else if lo.is_finite() {
                    lo + max_step
                } else {
                    hi - max_step
                };
                if !bracketed {
                    // Searching for the root's side (e.g. where F* ≤ 0 down to
                    // deep penetrations): grow the step, or ITERATIONS steps of
                    // 1 would not get past h* = −200.
                    max_step *= 2.0;
                }
            }
            if !bracketed && (next - h).abs() > max_step {
                next = h + max_step.copysign(next - h);
                max_step *= 2.0;
            }
            if next < -H_LIMIT {
                if h <= -H_LIMIT {
                    let f_max = self.force(-H_LIMIT).0;
                    return Err(EvalError::FStarTooLarge { f_star, f_max });
                }
                next = -H_LIMIT;
            }
            if (next - h).abs() <= tol || (bracketed && hi - lo <= tol) {
                return Ok(next);
            }
            h = next;
        }
        Err(EvalError::NoConvergence {
            f_star,
            h_star: h,
            iterations: ITERATIONS,
        })
    }
}

/// Refuses F* above [`F_STAR_MAX`] (a nominal pressure
/// above the hardness), where the model has no meaning.
fn check_f_star(f_star: f64) -> Result<(), EvalError> {
    // +∞ is not a number to compare: EvalError::FStar, from the solver.
    if f_star.is_finite() && f_star > F_STAR_MAX {
        return Err(EvalError::FStarAboveHardness(f_star));
    }
    Ok(())
}

impl crate::Classify for EvalError {
    /// `Argument`/`Domain` for a bad h* or F*, `NoMu`, or `Internal` for
    /// a root search that did not converge.
    fn kind(&self) -> crate::ErrorKind {
        use EvalError::*;
        match self {
            HStar(v) | FStar(v) => crate::ErrorKind::of_value(*v),
            FStarTooLarge { .. } | FStarAboveHardness(_) => crate::ErrorKind::Domain,
            NoMu { .. } => crate::ErrorKind::NoMu,
            NoConvergence { .. } => crate::ErrorKind::Internal,
        }
    }
}
