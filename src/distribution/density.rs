//! The standardised density g of a [`HeightDistribution`](super::HeightDistribution) (its value,
//! support, mode and moments) and the quadrature driver that integrates
//! against it: panels from the mode outwards, Gauss–Jacobi at finite ends.

use super::shape::{End, Form, PowerTails};
use super::Shape;
use crate::quadrature::{Rule, NODES};

/// A standardised density g (mean 0, variance 1) of a
/// [`HeightDistribution`](super::HeightDistribution): its value, support,
/// mode and moments.
#[derive(Debug, Clone)]
pub struct Density {
    pub(super) shape: Shape,
    pub(super) lo: Option<End>,
    pub(super) hi: Option<End>,
    /// ln g(x) = ln_norm + shape(x).
    pub(super) ln_norm: f64,
    pub(super) mode: f64,
}

impl Density {
    /// A density of `shape` with these ends and mode, normalised by the
    /// shape itself (`ln_norm` 0) until its family says otherwise.
    pub(super) fn plain(shape: Shape, lo: Option<End>, hi: Option<End>, mode: f64) -> Density {
        Density {
            shape,
            lo,
            hi,
            ln_norm: 0.0,
            mode,
        }
    }

    /// The support `(lo, hi)` (infinite where unbounded).
    pub fn support(&self) -> (f64, f64) {
        (
            self.lo.map_or(f64::NEG_INFINITY, |e| e.at),
            self.hi.map_or(f64::INFINITY, |e| e.at),
        )
    }

    /// Whether g is infinite at a finite end of its support (a U- or
    /// J-shaped Pearson type I density: the end's power below 0).
    pub fn has_infinite_end(&self) -> bool {
        [self.lo, self.hi].into_iter().flatten().any(|e| e.power < 0.0)
    }

    /// Where g is largest (for a J-shaped density, the end where it is unbounded).
    pub fn mode(&self) -> f64 {
        self.mode
    }

    /// Below the first and above the second, g only falls away from its
    /// mass: the mode for the unimodal families, the outermost kernel
    /// centres for an empirical density (whose outliers make it
    /// multimodal: a tail may not be cut at the first dip).
    pub(crate) fn tails(&self) -> (f64, f64) {
        self.shape.tails(self.mode)
    }

    /// The power tails of a type IV or VII density: `g ~ |x − centre|^−exponent`
    /// on both sides, with g analytic in `1/(x − centre)` out to infinity
    /// (its only singularities are the complex roots of the Pearson
    /// quadratic B(x), `centre ± i·half_width`).
    pub(crate) fn power_tails(&self) -> Option<PowerTails> {
        self.shape.power_tails()
    }

    pub(crate) fn lower_end(&self) -> Option<End> {
        self.lo
    }

    pub(crate) fn upper_end(&self) -> Option<End> {
        self.hi
    }

    /// The scale (in standardised units) on which g may change shape
    /// without its log-slope showing it: a kernel's width for an empirical
    /// density, else unlimited.
    pub(crate) fn smoothness_scale(&self) -> f64 {
        self.shape.smoothness_scale()
    }

    /// ln g(x); −∞ outside the support.
    pub fn ln_pdf(&self, x: f64) -> f64 {
        self.ln_pdf_in(&self.shape, x)
    }

    /// [`ln_pdf`](Self::ln_pdf) with the density's own `form` (the one
    /// [`visit_form`](Self::visit_form) gives): no dispatch on the family.
    #[inline]
    pub(crate) fn ln_pdf_in<F: Form>(&self, form: &F, x: f64) -> f64 {
        if let Some(e) = self.lo {
            if x <= e.at {
                return if x == e.at {
                    self.ln_pdf_at_end_in(form, e, 0.0)
                } else {
                    f64::NEG_INFINITY
                };
            }
        }
        if let Some(e) = self.hi {
            if x >= e.at {
                return if x == e.at {
                    self.ln_pdf_at_end_in(form, e, 0.0)
                } else {
                    f64::NEG_INFINITY
                };
            }
        }
        self.ln_norm + form.ln(x)
    }

    /// g(x); 0 outside the support.
    pub fn pdf(&self, x: f64) -> f64 {
        self.ln_pdf(x).exp()
    }

    /// g'(x)/g(x) inside the support.
    pub fn dln_pdf(&self, x: f64) -> f64 {
        self.shape.dln(x)
    }

    /// ln g at distance `dist ≥ 0` inside the support from its finite end
    /// `e`, computed from the distance itself (no rounding of `e.at ± dist`).
    pub(crate) fn ln_pdf_at_end(&self, e: End, dist: f64) -> f64 {
        self.ln_pdf_at_end_in(&self.shape, e, dist)
    }

    /// [`ln_pdf_at_end`](Self::ln_pdf_at_end) with the density's own `form`.
    pub(crate) fn ln_pdf_at_end_in<F: Form>(&self, form: &F, e: End, dist: f64) -> f64 {
        let upper = self.hi == Some(e);
        let x = if upper { e.at - dist } else { e.at + dist };
        self.ln_norm + form.ln_at_end(e, upper, dist, x)
    }

    /// `[∫g, mean, variance, skewness, kurtosis]`, by the same quadrature
    /// the model uses (to about 1e-13 for densities with light tails).
    pub fn moments(&self) -> [f64; 5] {
        let m = |k: i32| self.integrate(|x| x.powi(k));
        let (m0, m1) = (m(0), m(1));
        let mean = m1 / m0;
        let c = |k: i32| self.integrate(|x| (x - mean).powi(k)) / m0;
        let var = c(2);
        [m0, mean, var, c(3) / var.powf(1.5), c(4) / (var * var)]
    }

    /// `∫ f(x)·g(x) dx` over the support, split at the mode, with
    /// Gauss–Jacobi panels at finite ends and geometric panels into the tails.
    pub(crate) fn integrate(&self, f: impl Fn(f64) -> f64) -> f64 {
        let (lo, hi) = self.support();
        let mut sum = 0.0;
        let mode = self.mode.clamp(lo, hi);
        let start = if mode > lo && mode < hi { mode } else { 0.0 };
        for dir in [-1.0, 1.0] {
            let end = if dir > 0.0 { self.hi } else { self.lo };
            march(self, start, dir, end, &mut |x0, x1, rule| {
                sum += panel_sum(self, x0, x1, rule, end, &f)
            });
        }
        sum
    }

    /// `∫ f(x)·g(x) dx` over x > `t`: [`integrate`](Self::integrate)'s
    /// panels walked up from `t` (the whole integral where `t` is at or
    /// below the support's lower end; 0 at or above its upper end).
    pub(crate) fn integrate_above(&self, t: f64, f: impl Fn(f64) -> f64) -> f64 {
        let (lo, hi) = self.support();
        if t <= lo {
            return self.integrate(f);
        }
        if t >= hi {
            return 0.0;
        }
        let mut sum = 0.0;
        march(self, t, 1.0, self.hi, &mut |x0, x1, rule| {
            sum += panel_sum(self, x0, x1, rule, self.hi, &f)
        });
        sum
    }
}

/// How one panel is integrated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum PanelRule {
    /// Gauss–Legendre.
    Legendre,
    /// Gauss–Jacobi with the end's weight `|x − end|^power` at `x1`.
    JacobiEnd,
}

/// Walks from `x` in direction `dir` (±1) in panels until the support end
/// (`end`) or until the density has become negligible; calls `f(x0, x1,
/// rule)` (with `x0 < x1`).
fn march(g: &Density, x: f64, dir: f64, end: Option<End>, f: &mut impl FnMut(f64, f64, PanelRule)) {
    let peak = g.ln_pdf(g.mode).max(g.ln_pdf(x));
    let peak = if peak.is_finite() { peak } else { g.ln_pdf(x) };
    let mut x = x;
    for _ in 0..100_000 {
        let mut step = 8.0 / g.dln_pdf(x).abs().max(1e-300);
        step = step.max(1e-3 * (1.0 + x.abs()) * f64::EPSILON.sqrt());
        // Far out, panels grow with |x| (power tails) but stay within their
        // distance from 0 for the x^k weights.
        step = step.min(0.5 * (1.0 + x.abs())).min(g.smoothness_scale());
        if let Some(e) = end {
            let dist = (e.at - x) * dir;
            if dist <= 0.0 {
                return;
            }
            if step >= 0.5 * dist && e.takes_jacobi(dist) {
                let (a, b) = if dir > 0.0 { (x, e.at) } else { (e.at, x) };
                f(a, b, PanelRule::JacobiEnd);
                return;
            }
            step = step.min(0.5 * dist);
        }
        let x1 = x + dir * step;
        let (a, b) = if dir > 0.0 { (x, x1) } else { (x1, x) };
        f(a, b, PanelRule::Legendre);
        x = x1;
        // Negligible: the density times (1 + x²)² has fallen by e^−60.
        let ln_g = match end {
            Some(e) => g.ln_pdf_at_end(e, (e.at - x) * dir),
            None => g.ln_pdf(x),
        };
        if ln_g + 2.0 * (1.0 + x * x).ln() < peak - 60.0 || ln_g == f64::NEG_INFINITY {
            return;
        }
    }
}

/// One panel of [`Density::integrate`].
fn panel_sum(g: &Density, x0: f64, x1: f64, rule: PanelRule, end: Option<End>, f: &impl Fn(f64) -> f64) -> f64 {
    let width = x1 - x0;
    match rule {
        PanelRule::Legendre => {
            let r = Rule::shared_legendre();
            (0..NODES)
                .map(|i| {
                    let x = x0 + width * r.t[i];
                    width * r.w[i] * f(x) * g.pdf(x)
                })
                .sum()
        }
        PanelRule::JacobiEnd => {
            let Some(r) = end.and_then(|e| e.jacobi_rule().map(|r| (e, r))) else {
                return 0.0;
            };
            let (e, r) = r;
            let upper = e.at == x1;
            // ∫ |x − e|^p·(g/|x − e|^p) over the panel, in the distance t·width.
            (0..NODES)
                .map(|i| {
                    let dist = width * r.t[i];
                    let x = if upper { x1 - dist } else { x0 + dist };
                    let regular = g.ln_pdf_at_end(e, dist) - e.power * dist.ln();
                    width.powf(e.power + 1.0) * r.w[i] * f(x) * regular.exp()
                })
                .sum()
        }
    }
}
