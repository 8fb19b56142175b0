//! The sweeps and fits behind the paper's statements: the h* sweep, the
//! log–log exponents, extremes, crossings, the friction peak and the
//! CEB-type comparison.
//!
//! # How the power-law exponents are fitted
//!
//! The paper's exponents m (Q* ≈ C·F*^m, its Eq. 22) and n (μ ∝ F*^−n, its
//! Eq. 23) are least-squares slopes in log–log coordinates. The slope depends
//! on how the points are sampled, so it is defined once, in
//! [`loglog_slope_over_h`]:
//!
//! * [`SWEEP_POINTS`] = 301 points equally spaced in h* over 0 ≤ h* ≤ 3 (the
//!   paper's range of separations, MODEL.md §1), i.e. h* = 0, 0.01, …, 3;
//! * points with F* > [`PAPER_F_STAR_MAX`] = 0.1 dropped (the paper's range of
//!   loads, MODEL.md §1; this only matters at ψ = 2, where
//!   F*(h* = 0) = 0.13);
//! * ordinary least squares of ln y on ln F*, every point weighted equally.
//!
//! This definition reproduces every number MODEL.md §7 quotes: m = 0.841
//! (ψ = 0.5), 0.856 (ψ = 0.5, ε* = 0.01), 0.619 (ψ = 2), n = 0.1122
//! (ψ = 0.67) and 0.1276 (ψ = 1.01). Alternatives that do *not* reproduce
//! the n values of MODEL.md §6 item 1: points equally spaced in ln F* over
//! the same h* range give n = 0.106 / 0.118; over the F* range of the
//! paper's figures, 1e-5 ≤ F* ≤ 0.1, n = 0.096 / 0.094; over
//! 1e-4 ≤ F* ≤ 0.1, n = 0.116 / 0.118. At ψ = 2 keeping F* > 0.1 (h* near
//! 0) gives m = 0.573 instead of 0.62.

use super::{PaperError, PAPER_F_STAR_MAX, PAPER_H_STAR_RANGE};
use crate::{Contact, Model, ModelKind, Params};

/// Points of the h* sweep: h* = 0, 0.01, …, 3.
pub const SWEEP_POINTS: usize = 301;
/// A log–log fit needs at least this many points with F* ≤ 0.1 (of the
/// 301): fewer means the sweep left the paper's range of loads.
pub const MIN_FIT_POINTS: usize = 251;

/// The contact at each of the [`SWEEP_POINTS`] separations
/// h* = 0, 0.01, …, 3.
pub fn sweep_h(model: &Model) -> Vec<Contact> {
    h_points(SWEEP_POINTS)
        .map(|h| model.at_h_star(h).expect("h* in [0, 3] is always in range"))
        .collect()
}

/// `n` evenly spaced separations over [`PAPER_H_STAR_RANGE`], both ends included.
pub fn h_points(n: usize) -> impl Iterator<Item = f64> {
    let (a, b) = PAPER_H_STAR_RANGE;
    let last = (n - 1) as f64;
    (0..n).map(move |i| a + (b - a) * i as f64 / last)
}

/// Least-squares slope of `ys` on `xs`.
fn slope(xs: &[f64], ys: &[f64]) -> f64 {
    let n = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxy: f64 = xs.iter().zip(ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// A power-law exponent fitted in log–log coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogLogFit {
    /// The exponent (m, or n = −slope for μ ∝ F*^−n).
    pub exponent: f64,
    /// Points the fit used (those of the sweep with F* ≤ 0.1).
    pub points: usize,
}

/// The slope of ln y against ln F* (module docs: h* = 0, 0.01, …, 3,
/// F* ≤ 0.1, ordinary least squares). `what` names y in errors.
pub fn loglog_slope_over_h(
    model: &Model,
    what: &'static str,
    y: impl Fn(&Contact) -> f64,
) -> Result<LogLogFit, PaperError> {
    let (mut ln_f, mut ln_y) = (Vec::new(), Vec::new());
    for c in sweep_h(model) {
        if c.f_star > PAPER_F_STAR_MAX {
            continue;
        }
        for (name, v) in [("F*", c.f_star), (what, y(&c))] {
            if v.is_nan() || v <= 0.0 {
                return Err(PaperError::NotPositive {
                    what: name,
                    h_star: c.h_star,
                    value: v,
                });
            }
        }
        ln_f.push(c.f_star.ln());
        ln_y.push(y(&c).ln());
    }
    if ln_f.len() < MIN_FIT_POINTS {
        return Err(PaperError::TooFewPoints { points: ln_f.len() });
    }
    Ok(LogLogFit {
        exponent: slope(&ln_f, &ln_y),
        points: ln_f.len(),
    })
}

/// m in Q* ≈ C·F*^m (the paper's Eq. 22).
pub fn power_m(model: &Model) -> Result<LogLogFit, PaperError> {
    loglog_slope_over_h(model, "Q*", |c| c.q_star)
}

/// n in μ ∝ F*^−n (the paper's Eq. 23).
pub fn exponent_n(model: &Model) -> Result<LogLogFit, PaperError> {
    let fit = loglog_slope_over_h(model, "mu", |c| c.q_star / c.f_star)?;
    Ok(LogLogFit {
        exponent: -fit.exponent,
        ..fit
    })
}

/// A value at a separation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtH {
    /// The separation h*.
    pub h_star: f64,
    /// F* there.
    pub f_star: f64,
    /// The value.
    pub value: f64,
}

impl AtH {
    fn of(c: &Contact, value: f64) -> AtH {
        AtH {
            h_star: c.h_star,
            f_star: c.f_star,
            value,
        }
    }
}

/// The smallest and largest of `y` over the h* sweep, among points with
/// 0 < F* ≤ `f_max` (`f64::INFINITY`: every point with F* > 0). `None` if
/// no point qualifies.
pub fn extremes_over_h(model: &Model, f_max: f64, y: impl Fn(&Contact) -> f64) -> Option<(AtH, AtH)> {
    let mut out: Option<(AtH, AtH)> = None;
    for c in sweep_h(model) {
        if !(c.f_star > 0.0 && c.f_star <= f_max) {
            continue;
        }
        let p = AtH::of(&c, y(&c));
        out = Some(match out {
            None => (p, p),
            Some((lo, hi)) => (
                if p.value < lo.value { p } else { lo },
                if p.value > hi.value { p } else { hi },
            ),
        });
    }
    out
}

/// The largest Fs*/P* over the h* sweep (every point, whatever F*).
pub fn max_adhesion_ratio(model: &Model) -> AtH {
    sweep_h(model).iter().map(|c| AtH::of(c, c.fs_star / c.p_star)).fold(
        AtH {
            h_star: f64::NAN,
            f_star: f64::NAN,
            value: 0.0,
        },
        |a, b| if b.value > a.value { b } else { a },
    )
}

/// Fs*/P* at the load F*.
pub fn adhesion_ratio_at(model: &Model, f_star: f64) -> Result<f64, PaperError> {
    let c = model.at_f_star(f_star)?;
    Ok(c.fs_star / c.p_star)
}

/// An interval of F* that holds a crossing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// Lower end: Fs*/P* is above the level here.
    pub lo: f64,
    /// Upper end: Fs*/P* is at or below the level here.
    pub hi: f64,
}

/// Where Fs*/P* falls through `level` as F* grows from `lo` to `hi`: 60
/// bisections in ln F*, which shrink the bracket to a relative width below
/// 1e-9 for any starting bracket within the paper's range of loads.
pub fn adhesion_ratio_crossing(model: &Model, level: f64, (lo, hi): (f64, f64)) -> Result<Bracket, PaperError> {
    let excess = |f: f64| adhesion_ratio_at(model, f).map(|r| r - level);
    if !(excess(lo)? > 0.0 && excess(hi)? <= 0.0) {
        return Err(PaperError::NoCrossing { level, lo, hi });
    }
    let (mut lo, mut hi) = (lo, hi);
    for _ in 0..60 {
        let mid = (lo * hi).sqrt();
        if excess(mid)? > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Bracket { lo, hi })
}

/// The maximum of Q*(h*) on `[a, b]`, by golden-section search (80 steps;
/// Q* must have a single maximum there).
pub fn friction_peak(model: &Model, (a, b): (f64, f64)) -> Result<Contact, PaperError> {
    let q = |h: f64| model.at_h_star(h).map(|c| c.q_star);
    let g = (5.0_f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (a, b);
    for _ in 0..80 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if q(x1)? < q(x2)? {
            a = x1;
        } else {
            b = x2;
        }
    }
    Ok(model.at_h_star(0.5 * (a + b))?)
}

/// μ_KE / μ_CEB at each load (default β, ν, ε*; MODEL.md §8).
pub fn ke_over_ceb(psi: f64, theta: f64, loads: &[f64]) -> Result<Vec<f64>, PaperError> {
    let ke = Model::new(Params::new(psi, theta))?;
    let ceb = Model::new(Params::new(psi, theta).kind(ModelKind::CebType))?;
    loads
        .iter()
        .map(|&f| {
            let a = ke.at_f_star(f)?;
            let b = ceb.at_f_star(f)?;
            Ok(a.q_star / a.f_star / (b.q_star / b.f_star))
        })
        .collect()
}

/// The loads a curve of the paper's figures spans: F* at h* = 3 (its lower
/// end) up to F* at h* = 0 or 0.1, whichever is less (MODEL.md §1; the
/// curves of `kefric plot` span the same). For several models (the two
/// lines of a ratio), the loads all of them span.
pub fn plotted_loads(models: &[&Model]) -> Result<(f64, f64), PaperError> {
    let (h0, h1) = PAPER_H_STAR_RANGE;
    let (mut lo, mut hi) = (0.0_f64, PAPER_F_STAR_MAX);
    for m in models {
        lo = lo.max(m.at_h_star(h1)?.f_star);
        hi = hi.min(m.at_h_star(h0)?.f_star);
    }
    Ok((lo, hi))
}

/// Samples per decade of F* at which [`holds_where`] tests a criterion
/// before it refines the ends of each stretch.
pub const SAMPLES_PER_DECADE: usize = 20;

/// Where a criterion holds over a range of loads.
#[derive(Debug, Clone, PartialEq)]
pub struct Coverage {
    /// The range tested: the loads the paper plots.
    pub range: (f64, f64),
    /// The stretches of F* where the criterion holds, in increasing order;
    /// their inner ends found to 1e-6 relative by bisection in ln F*.
    pub holds: Vec<(f64, f64)>,
    /// The value at the lower and at the upper end of the range.
    pub ends: (f64, f64),
    /// The smallest and the largest value on the samples.
    pub extremes: ((f64, f64), (f64, f64)),
}

impl Coverage {
    /// The criterion holds at every sampled load of the range.
    pub fn everywhere(&self) -> bool {
        self.holds.len() == 1 && self.holds[0] == self.range
    }

    /// The criterion holds at no sampled load.
    pub fn nowhere(&self) -> bool {
        self.holds.is_empty()
    }
}

/// Tests `ok(y(F*))` at [`SAMPLES_PER_DECADE`] loads per decade, equally
/// spaced in ln F* over `range` (both ends included), and returns where it
/// holds. Between two samples that disagree the switch is located by
/// bisection in ln F* (one switch between neighbours is assumed: the
/// quantities tested are smooth and cross a band edge once).
pub fn holds_where(
    range: (f64, f64),
    y: impl Fn(f64) -> Result<f64, PaperError>,
    ok: impl Fn(f64) -> bool,
) -> Result<Coverage, PaperError> {
    let (lo, hi) = range;
    let n = ((hi / lo).log10() * SAMPLES_PER_DECADE as f64).ceil().max(1.0) as usize;
    let f = |i: usize| {
        if i == n {
            hi
        } else {
            lo * (hi / lo).powf(i as f64 / n as f64)
        }
    };
    let mut samples = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let x = f(i);
        samples.push((x, y(x)?));
    }
    // The load where ok() switches between a and b (a's state on the left).
    let switch = |mut a: f64, mut b: f64| -> Result<f64, PaperError> {
        let left = ok(y(a)?);
        while b / a - 1.0 > 1e-6 {
            let mid = (a * b).sqrt();
            if ok(y(mid)?) == left {
                a = mid;
            } else {
                b = mid;
            }
        }
        Ok((a * b).sqrt())
    };
    let mut holds = Vec::new();
    let mut start = ok(samples[0].1).then_some(lo);
    for w in samples.windows(2) {
        let ((a, ya), (b, yb)) = (w[0], w[1]);
        match (ok(ya), ok(yb)) {
            (true, false) => holds.push((start.take().unwrap_or(a), switch(a, b)?)),
            (false, true) => start = Some(switch(a, b)?),
            _ => {}
        }
    }
    if let Some(s) = start {
        holds.push((s, hi));
    }
    let min = samples
        .iter()
        .copied()
        .fold(samples[0], |m, p| if p.1 < m.1 { p } else { m });
    let max = samples
        .iter()
        .copied()
        .fold(samples[0], |m, p| if p.1 > m.1 { p } else { m });
    Ok(Coverage {
        range,
        holds,
        ends: (samples[0].1, samples[n].1),
        extremes: (min, max),
    })
}

/// μ_KE / μ_CEB at the load F* (default β, ν, ε*; MODEL.md §8), for
/// models built once.
pub fn ke_over_ceb_at(ke: &Model, ceb: &Model, f_star: f64) -> Result<f64, PaperError> {
    let a = ke.at_f_star(f_star)?;
    let b = ceb.at_f_star(f_star)?;
    Ok(a.q_star / a.f_star / (b.q_star / b.f_star))
}
