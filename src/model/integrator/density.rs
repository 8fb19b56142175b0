//! The density of asperity heights φ* as the integrals see it: the
//! Gaussian, any other density (its support's ends and power tails),
//! and the window of z* that matters.

use crate::distribution::{Density, End, Form, FormVisitor, PowerTails, JACOBI_POWER_MAX};
use crate::quadrature::{Rule, NODES};

/// Gaussian tails are cut where the density has fallen by `e^−TAIL`
/// relative to its value at the start of the integral (below 1e-17, far
/// under the 1e-12 target even after the polynomial weights `x^b`).
pub(super) const TAIL: f64 = 40.0;
/// Largest panel, in units of σ_s.
const MAX_STEP: f64 = 2.0;
/// Far from the mean the panel is `STEP_DECAY·σ_s²/|z|`, so that the
/// Gaussian changes by about `e^STEP_DECAY` across it.
const STEP_DECAY: f64 = 8.0;

/// The window of z* that matters for the contact integrals (z* ≥ d*) at
/// separation `d`: beyond it the density has fallen by `e^−TAIL` from its
/// largest value on the integrals' range. For a general density, the
/// support, with `d` and ln φ* at its largest on `[d, ∞)` to tell where
/// an unbounded tail becomes negligible.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Window {
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) d: f64,
    ln_ref: f64,
}

impl Window {
    fn contact(d: f64, s: f64) -> Window {
        let cut = tail_cut(s);
        Window {
            lo: -cut,
            hi: d.max(0.0).hypot(cut),
            d,
            ln_ref: 0.0,
        }
    }
}

/// The density of asperity heights φ*(z*) as the integrals see it.
pub(crate) trait Phi {
    /// Whether this is a general density (support ends, unbounded tails);
    /// false for the Gaussian, whose integrals keep their fixed windows.
    const GENERAL: bool;
    /// φ*(z).
    fn phi(&self, z: f64) -> f64;
    /// A node's weight for ∂/∂d* from its weight `w`: for the Gaussian
    /// `w·φ*'(z)/φ*(z)`, which the laws multiply (differentiating under the
    /// integral); for a general density `−w/ω`, which the laws' slopes
    /// multiply (d* moves the laws, not the density: no terms at the ends
    /// of the support, which may be infinite there), with the laws' jumps
    /// at the regime boundaries added apart (`Integrals::add_jumps`).
    fn dw(&self, w: f64, z: f64, inv_omega: f64) -> f64;
    /// Panel length in z* for a panel from height `z` upwards (`up`) or
    /// downwards.
    fn step(&self, z: f64, up: bool) -> f64;
    /// The window of the contact integrals at `d`.
    fn window(&self, d: f64) -> Window;
    /// The finite ends of the support (lower, upper), in z*.
    fn ends(&self) -> (Option<&ZEnd>, Option<&ZEnd>) {
        (None, None)
    }
    /// Below the first and above the second, φ* only falls away from the
    /// mass: where a tail may be cut once it is negligible (the mode for a
    /// unimodal density; the outermost kernels for an empirical one).
    fn tails(&self) -> (f64, f64) {
        (0.0, 0.0)
    }
    /// Whether the contact integrals' tail beyond `z` is negligible.
    fn negligible(&self, _z: f64, _win: Window) -> bool {
        false
    }
    /// The end panel of width `width` at `e`: calls `f(dist, w)` with the
    /// distance of each node from the end and its weight `w = wt·φ*`.
    fn end_panel(&self, _e: &ZEnd, _width: f64, _f: impl FnMut(f64, f64)) {}
    /// Whether all of the integral beyond `z` (upwards if `up`) may be one
    /// panel of the power tail's rule ([`TailRule`]), for an integrand whose
    /// law is analytic except at `singular`.
    fn tail_from(&self, _z: f64, _up: bool, _singular: f64) -> bool {
        false
    }
    /// That panel: calls `f(z, w)` with each node's height and its weight
    /// `w = wt·φ*` for `dz*`.
    fn tail_panel(&self, _z: f64, _up: bool, _f: impl FnMut(f64, f64)) {}
}

/// The paper's Gaussian φ*.
#[derive(Debug, Clone)]
pub(crate) struct Gauss {
    pub(super) s: f64,
    pub(super) inv_s2: f64,
    /// 1/(s√(2π)).
    pub(super) norm: f64,
}

impl Phi for Gauss {
    const GENERAL: bool = false;

    #[inline(always)]
    fn phi(&self, z: f64) -> f64 {
        self.norm * (-0.5 * z * z * self.inv_s2).exp()
    }

    #[inline(always)]
    fn dw(&self, w: f64, z: f64, _inv_omega: f64) -> f64 {
        -w * z * self.inv_s2
    }

    #[inline(always)]
    fn step(&self, z: f64, _up: bool) -> f64 {
        let s = self.s;
        let far = STEP_DECAY * s * s / (z.abs() + s);
        if far < MAX_STEP * s {
            far
        } else {
            MAX_STEP * s
        }
    }

    fn window(&self, d: f64) -> Window {
        Window::contact(d, self.s)
    }
}

/// A finite end of the support in z*: `φ* ~ |z* − z|^power` next to it.
#[derive(Debug, Clone)]
pub(crate) struct ZEnd {
    pub(super) z: f64,
    power: f64,
    /// The end in the standardised density's units.
    end: End,
    /// Widest panel (in z*) the Gauss–Jacobi rule may take.
    jacobi_width: f64,
    /// Gauss–Jacobi rule with weight `t^power` (when `power < JACOBI_POWER_MAX`).
    rule: Option<Rule>,
}

impl ZEnd {
    /// Whether a panel of `width` reaching this end takes its Gauss–Jacobi rule.
    pub(super) fn jacobi(&self, width: f64) -> bool {
        self.rule.is_some() && width <= self.jacobi_width
    }
}

/// Any other density: `φ*(z*) = g(z*/s)/s` (MODEL.md §9).
#[derive(Debug, Clone)]
pub(crate) struct General {
    g: Density,
    inv_s: f64,
    ln_inv_s: f64,
    /// Largest panel near the mass, and anywhere (2 σ_s growing with |z*|
    /// into power tails; two kernel widths for an empirical density, whose
    /// outliers are bumps of that width however far out).
    max_step: f64,
    max_step_far: f64,
    mode: f64,
    /// The power tails (types IV, VII), in z*.
    poles: Option<PowerTails>,
    /// Their one-panel rule, where it is exact.
    tail_rule: Option<TailRule>,
    tails: (f64, f64),
    lo: Option<ZEnd>,
    hi: Option<ZEnd>,
}

impl General {
    pub(super) fn new(g: Density, s: f64) -> General {
        let zend = |e: Option<End>| {
            e.map(|e| ZEnd {
                z: s * e.at,
                power: e.power,
                end: e,
                jacobi_width: s * e.jacobi_width,
                rule: e.jacobi_rule(),
            })
        };
        let power_tails = g.power_tails();
        General {
            lo: zend(g.lower_end()),
            hi: zend(g.upper_end()),
            max_step: MAX_STEP * s * g.smoothness_scale().min(1.0),
            max_step_far: MAX_STEP * s * g.smoothness_scale(),
            mode: s * g.mode(),
            poles: power_tails.map(|p| PowerTails {
                centre: s * p.centre,
                half_width: s * p.half_width,
                exponent: p.exponent,
            }),
            tail_rule: power_tails.and_then(|p| TailRule::new(p.exponent)),
            tails: (s * g.tails().0, s * g.tails().1),
            inv_s: 1.0 / s,
            ln_inv_s: -s.ln(),
            g,
        }
    }

    /// The fraction of the summits above `z` (in z*): ∫ φ* over z* > z,
    /// the density's own quadrature walked up from `z` (Gauss panels,
    /// Gauss–Jacobi at a singular end).
    pub(super) fn fraction_above(&self, z: f64) -> f64 {
        self.g.integrate_above(z * self.inv_s, |_| 1.0).min(1.0)
    }

    /// `f` called with these heights as a [`Phi`] whose density's form is
    /// known at compile time ([`Formed`]): one dispatch on the family per
    /// integral instead of one per node.
    #[inline(always)]
    pub(crate) fn visit<V: PhiVisitor>(&self, visitor: V) -> V::Out {
        struct Visit<'a, V> {
            h: &'a General,
            visitor: V,
        }
        impl<V: PhiVisitor> FormVisitor for Visit<'_, V> {
            type Out = V::Out;
            #[inline(always)]
            fn visit<F: Form>(self, form: &F) -> V::Out {
                self.visitor.visit(&Formed { h: self.h, form })
            }
        }
        self.g.visit_form(Visit { h: self, visitor })
    }
}

/// A computation generic over the heights' [`Phi`] ([`General::visit`]).
pub(crate) trait PhiVisitor {
    /// What the computation returns.
    type Out;
    /// The computation with the heights `h`.
    fn visit<H: Phi>(self, h: &H) -> Self::Out;
}

/// [`General`] heights with their density's form `F`.
pub(crate) struct Formed<'a, F> {
    h: &'a General,
    form: &'a F,
}

impl<F> std::ops::Deref for Formed<'_, F> {
    type Target = General;
    fn deref(&self) -> &General {
        self.h
    }
}

impl<F: Form> Formed<'_, F> {
    #[inline]
    fn ln_phi(&self, z: f64) -> f64 {
        self.g.ln_pdf_in(self.form, z * self.inv_s) + self.ln_inv_s
    }
}

impl<F: Form> Phi for Formed<'_, F> {
    const GENERAL: bool = true;

    fn phi(&self, z: f64) -> f64 {
        self.ln_phi(z).exp()
    }

    fn dw(&self, w: f64, _z: f64, inv_omega: f64) -> f64 {
        -w * inv_omega
    }

    fn step(&self, z: f64, up: bool) -> f64 {
        let slope = (self.form.dln(z * self.inv_s) * self.inv_s).abs();
        // Far out, a panel half its distance from the mass; a panel moving
        // away from the complex singularities of a type IV/VII density may
        // be as long as its distance from them (its nodes then converge
        // like ρ^−2n with ρ ≥ 3 + √8), which halves the panels of a power
        // tail. Towards them, or the mass, half.
        let far = match self.poles {
            Some(PowerTails { centre: c, .. }) if (z > c) == up => (z - c).abs(),
            _ => 0.5 * z.abs(),
        };
        let cap = self.max_step.max(far.min(self.max_step_far));
        let step = STEP_DECAY / slope;
        // At an end of the support the slope is infinite (or, a rounding
        // away, huge): the end's Gauss–Jacobi rule holds the singular
        // factor, and the rest is smooth on the scale of the support.
        let at_end = [&self.lo, &self.hi]
            .into_iter()
            .flatten()
            .any(|e| (z - e.z).abs() <= 1e-9 * (1.0 + e.z.abs()));
        if step < cap && slope.is_finite() && !at_end {
            step
        } else {
            cap
        }
    }

    fn window(&self, d: f64) -> Window {
        let mut top = d.max(self.mode);
        if self.lo.as_ref().is_some_and(|e| top == e.z) {
            // A J-shaped density is infinite at its end: look just inside.
            top += 1e-6 * (1.0 + top.abs());
        }
        let top = match &self.hi {
            Some(e) if top >= e.z => d,
            _ => top,
        };
        Window {
            lo: self.lo.as_ref().map_or(f64::NEG_INFINITY, |e| e.z),
            hi: self.hi.as_ref().map_or(f64::INFINITY, |e| e.z),
            d,
            ln_ref: self.ln_phi(top),
        }
    }

    fn ends(&self) -> (Option<&ZEnd>, Option<&ZEnd>) {
        (self.lo.as_ref(), self.hi.as_ref())
    }

    fn tails(&self) -> (f64, f64) {
        self.tails
    }

    fn negligible(&self, z: f64, win: Window) -> bool {
        if z <= self.tails.1 {
            return false;
        }
        let ln = self.ln_phi(z) + 2.0 * (1.0 + (z - win.d).abs() * self.inv_s).ln();
        ln.is_nan() || ln < win.ln_ref - TAIL
    }

    fn tail_from(&self, z: f64, up: bool, singular: f64) -> bool {
        let (Some(p), Some(_)) = (&self.poles, &self.tail_rule) else {
            return false;
        };
        // In t = S/|z' − c| (S = |z − c|, c the poles' centre) the panel is
        // [0, 1]. The poles sit at t = ±i·S/half_width and the law's
        // singularity at t = S/r: the rule's nodes converge at least like
        // (3 + √8)^−24 if those stay beyond ±2i, and t ≤ −1 or t ≥ 2.
        let sign = if up { 1.0 } else { -1.0 };
        let dist = sign * (z - p.centre);
        let r = sign * (singular - p.centre);
        dist >= 2.0 * p.half_width && dist >= 2.0 * r && dist >= -r
    }

    fn tail_panel(&self, z: f64, up: bool, mut f: impl FnMut(f64, f64)) {
        let (Some(p), Some(rule)) = (&self.poles, &self.tail_rule) else {
            return;
        };
        let dist = if up { z - p.centre } else { p.centre - z };
        let ln_dist = dist.ln();
        for i in 0..NODES {
            let r = dist * rule.inv_t[i];
            let zi = if up { p.centre + r } else { p.centre - r };
            f(zi, (rule.ln_w[i] + ln_dist + self.ln_phi(zi)).exp());
        }
    }

    fn end_panel(&self, e: &ZEnd, width: f64, mut f: impl FnMut(f64, f64)) {
        let Some(rule) = &e.rule else { return };
        // ∫ dist^power·(φ*/dist^power): the rule's weights hold dist^power.
        let scale = width.powf(e.power + 1.0);
        for i in 0..NODES {
            let dist = width * rule.t[i];
            let ln_regular =
                self.g.ln_pdf_at_end_in(self.form, e.end, dist * self.inv_s) + self.ln_inv_s - e.power * dist.ln();
            f(dist, scale * rule.w[i] * ln_regular.exp());
        }
    }
}

/// One panel for all of a power tail beyond `Z` (types IV, VII): with
/// `z* = c ± S/t` (`S = |Z − c|`, `c` the poles' centre), `∫ F dz* =
/// ∫₀¹ F·S/t² dt`, and φ* ~ `t^q` there times a function analytic at
/// t = 0. Gauss–Jacobi with weight `t^(q−3)` leaves `t^0` for the linear
/// laws of the plastic regime (`x·φ*·S/t² ~ t^(q−3)`) and `t^3` for the
/// non-contact adhesion (`u^−2 ~ t²`): both exact at the rule's rate.
#[derive(Debug, Clone)]
pub(super) struct TailRule {
    /// `1/tᵢ`.
    inv_t: [f64; NODES],
    /// `ln(wᵢ/tᵢ^(q−1))`: the rule's weight, over the `t^(q−3)` it holds
    /// and the Jacobian's `t²`.
    ln_w: [f64; NODES],
}

impl TailRule {
    /// The rule for tails `φ* ~ |z*|^−q`, if its power `q − 3` takes a
    /// Gauss–Jacobi rule.
    fn new(q: f64) -> Option<TailRule> {
        let power = q - 3.0;
        if !(power > -1.0 && power < JACOBI_POWER_MAX) {
            return None;
        }
        let rule = Rule::jacobi(power);
        Some(TailRule {
            inv_t: rule.t.map(|t| 1.0 / t),
            ln_w: std::array::from_fn(|i| rule.w[i].ln() - (q - 1.0) * rule.t[i].ln()),
        })
    }
}

/// Which density the integrals use.
#[derive(Debug, Clone)]
pub(crate) enum Heights {
    Gauss(Gauss),
    General(std::sync::Arc<General>),
}

/// How far past the density's largest value on a range it falls by `e^−TAIL`.
pub(super) fn tail_cut(s: f64) -> f64 {
    (2.0 * TAIL).sqrt() * s
}
