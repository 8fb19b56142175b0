//! The rough surface: Gaussian asperity heights and the integrals of
//! MODEL.md §4 (Kogut–Etsion) and §8 (CEB-type).
//!
//! Every integral is taken in `x = (z* − d*)/ω_c*`, split at the regime
//! boundaries (the single-asperity laws jump there) and then into panels on
//! which the Gaussian changes by a bounded factor. Each panel gets a
//! [`NODES`]-point Gauss rule; the panel that
//! starts at the contact point `x = 0` gets a Gauss–Jacobi rule with the
//! exact weight `x^b`, and the panels of the non-contact adhesion integral
//! grow geometrically away from `z* = d*`, where its integrand varies on
//! the scale ε*. Tails below `e^−TAIL` of the integrand's largest Gaussian
//! factor are cut; the power tails of Pearson types IV and VII are
//! integrated out to infinity in one panel, in `1/(z* − c)` ([`TailRule`]).
//! No allocation, no recursion: a fixed amount of arithmetic per panel.

use super::asperity::{self, adhesion, load, X_ELASTIC};
use super::laws::{ContactLaw, Law, LoadLaw, Regime};
use crate::distribution::{Density, End, PowerTails, JACOBI_POWER_MAX};
use crate::gw::sigma_s_ratio;
use crate::params::{hardness_coefficient, Params};
use crate::quadrature::{Rule, NODES};

/// Gaussian tails are cut where the density has fallen by `e^−TAIL`
/// relative to its value at the start of the integral (below 1e-17, far
/// under the 1e-12 target even after the polynomial weights `x^b`).
const TAIL: f64 = 40.0;
/// Largest panel, in units of σ_s.
const MAX_STEP: f64 = 2.0;
/// Far from the mean the panel is `STEP_DECAY·σ_s²/|z|`, so that the
/// Gaussian changes by about `e^STEP_DECAY` across it.
const STEP_DECAY: f64 = 8.0;

/// Everything the integrals need that depends only on the parameters
/// (the "plan"; MODEL.md §2).
#[derive(Debug, Clone)]
pub(crate) struct Surface {
    /// The planned single-asperity law.
    law: Law,
    /// σ_s/σ.
    s: f64,
    /// The density of asperity heights φ*.
    heights: Heights,
    /// ω_c* = s/ψ².
    pub(super) omega: f64,
    /// y_s* = h* − d*.
    pub ys: f64,
    eps: f64,
    /// (2/3)πβKω_c*, in front of P* and Q*.
    load_pref: f64,
    /// 2πβθ, in front of Fs*.
    adh_pref: f64,
    /// `a·r^c` of the three contact adhesion rows.
    adh_coef: [f64; 3],
    pub(super) rules: &'static Rules,
}

/// The Gauss rules, the same for every model: computed once per process.
#[derive(Debug)]
pub(super) struct Rules {
    gl: Rule,
    /// Gauss–Jacobi rules for `x^1.5`, `x^0.298` (first panels).
    gj_load: Rule,
    gj_adh: Rule,
    /// Gauss–Jacobi rule for `(1 − x)^½` (CEB-type, at x = 1), which is
    /// also the weight `x^0.5` of the Hertz load's slope.
    pub(super) gj_half: Rule,
    /// Gauss–Jacobi rule for `x^−0.702`, the elastic adhesion's slope.
    gj_adh_slope: Rule,
}

impl Rules {
    fn get() -> &'static Rules {
        static RULES: std::sync::OnceLock<Rules> = std::sync::OnceLock::new();
        RULES.get_or_init(|| Rules {
            gl: Rule::legendre(),
            gj_load: Rule::jacobi(load::ELASTIC.1),
            gj_adh: Rule::jacobi(adhesion::ELASTIC.1),
            gj_half: Rule::jacobi(0.5),
            gj_adh_slope: Rule::jacobi(adhesion::ELASTIC.1 - 1.0),
        })
    }
}

/// The integrals at one separation: P*, Fs*, their d*-derivatives and Q*
/// (what [`Surface::evaluate`] returns, with their prefactors), or the raw
/// integrals of one regime while they are summed (without).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Sums {
    /// P*.
    pub p: f64,
    /// ∂P*/∂d*.
    pub dp: f64,
    /// Fs*.
    pub fs: f64,
    /// ∂Fs*/∂d*.
    pub dfs: f64,
    /// Q* (0 unless asked for).
    pub q: f64,
}

/// The window of z* that matters for the contact integrals (z* ≥ d*) at
/// separation `d`: beyond it the density has fallen by `e^−TAIL` from its
/// largest value on the integrals' range. For a general density, the
/// support, with `d` and ln φ* at its largest on `[d, ∞)` to tell where
/// an unbounded tail becomes negligible.
#[derive(Debug, Clone, Copy)]
pub(super) struct Window {
    lo: f64,
    hi: f64,
    d: f64,
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

/// At most this many panels per integral (a safeguard: the tails of the
/// heaviest admissible densities need a few hundred).
const MAX_PANELS: usize = 100_000;
/// A tail is negligible once its part falls below this fraction (e^−40).
const NEGLIGIBLE: f64 = 4.248354255291589e-18;

/// The density of asperity heights φ*(z*) as the integrals see it.
pub(super) trait Phi {
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
    /// at the regime boundaries added apart (`Surface::add_jumps`).
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
struct Gauss {
    s: f64,
    inv_s2: f64,
    /// 1/(s√(2π)).
    norm: f64,
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
pub(super) struct ZEnd {
    z: f64,
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
    fn jacobi(&self, width: f64) -> bool {
        self.rule.is_some() && width <= self.jacobi_width
    }
}

/// Any other density: `φ*(z*) = g(z*/s)/s` (MODEL.md §9).
#[derive(Debug, Clone)]
struct General {
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
    fn new(g: Density, s: f64) -> General {
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

    fn ln_phi(&self, z: f64) -> f64 {
        self.g.ln_pdf(z * self.inv_s) + self.ln_inv_s
    }
}

impl Phi for General {
    const GENERAL: bool = true;

    fn phi(&self, z: f64) -> f64 {
        self.ln_phi(z).exp()
    }

    fn dw(&self, w: f64, _z: f64, inv_omega: f64) -> f64 {
        -w * inv_omega
    }

    fn step(&self, z: f64, up: bool) -> f64 {
        let slope = (self.g.dln_pdf(z * self.inv_s) * self.inv_s).abs();
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
            let ln_regular = self.g.ln_pdf_at_end(e.end, dist * self.inv_s) + self.ln_inv_s - e.power * dist.ln();
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
struct TailRule {
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
enum Heights {
    Gauss(Gauss),
    General(std::sync::Arc<General>),
}

/// Which end of the support a panel touches (general densities).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum EndSide {
    None,
    Lower,
    Upper,
    /// All of a power tail beyond the panel's start ([`TailRule`]).
    Tail,
}

/// One panel `[x0, x1]` of an integral in x.
#[derive(Debug, Clone, Copy)]
pub(super) struct Panel {
    pub x0: f64,
    pub x1: f64,
    /// It starts at the regime's start (the contact point for x = 0).
    pub first: bool,
    /// It ends at the regime's end (not cut by the window).
    pub last: bool,
    /// It touches an end of the support (Gauss–Jacobi with the end's weight).
    pub at_end: EndSide,
}

/// Adds a node's load `p` and, with an adhesion exponent `b_adh`, its
/// adhesion `x^b_adh` (from `lx = ln x`), with weights `w`, `dw`.
#[inline(always)]
///
/// The d*-derivatives: for the Gaussian `dw` is `w·φ*'/φ*` and multiplies
/// the laws; for a general density `dw` is `−w/ω` and multiplies the laws'
/// slopes (`dp_dx` for the load), see [`Phi::GENERAL`].
#[allow(clippy::too_many_arguments)]
fn add_node<H: Phi>(acc: &mut Sums, p: f64, dp_dx: f64, x: f64, lx: f64, w: f64, dw: f64, b_adh: Option<f64>) {
    acc.p += p * w;
    acc.dp += if H::GENERAL { dp_dx * dw } else { p * dw };
    if let Some(b) = b_adh {
        let f = (b * lx).exp();
        acc.fs += f * w;
        acc.dfs += if H::GENERAL { b * f / x * dw } else { f * dw };
    }
}

/// Adds the Hertz load `x^1.5` and the elastic adhesion `x^0.298` (both
/// models) at an interior node; returns `x^1.5`.
#[inline(always)]
pub(super) fn elastic_node<H: Phi>(acc: &mut Sums, x: f64, lx: f64, w: f64, dw: f64, adh: bool) -> f64 {
    let p = x * x.sqrt();
    add_node::<H>(acc, p, 1.5 * x.sqrt(), x, lx, w, dw, adh.then_some(adhesion::ELASTIC.1));
    p
}

/// How far past the density's largest value on a range it falls by `e^−TAIL`.
fn tail_cut(s: f64) -> f64 {
    (2.0 * TAIL).sqrt() * s
}

impl Surface {
    /// Plans the integrals for valid parameters.
    pub fn new(p: &Params) -> Surface {
        let pi = core::f64::consts::PI;
        let s = sigma_s_ratio(p.constants.beta);
        let k = hardness_coefficient(p.constants.nu);
        let omega = s / (p.psi * p.psi);
        let r = p.constants.eps_star / omega;
        let gauss = Gauss {
            s,
            inv_s2: 1.0 / (s * s),
            norm: 1.0 / (s * (2.0 * pi).sqrt()),
        };
        let heights = if p.constants.distribution.is_gaussian() {
            Heights::Gauss(gauss)
        } else {
            // Model::new validated the constants.
            let g = Density::new(&p.constants.distribution);
            Heights::General(std::sync::Arc::new(General::new(g, s)))
        };
        Surface {
            law: Law::new(&p.constants),
            s,
            heights,
            omega,
            ys: 1.0 / (4.0 * 3f64.sqrt() * pi * p.constants.beta),
            eps: p.constants.eps_star,
            load_pref: (2.0 / 3.0) * pi * p.constants.beta * k * omega,
            adh_pref: 2.0 * pi * p.constants.beta * p.theta,
            adh_coef: adhesion::ROWS.map(|(a, _, c)| a * r.powf(c)),
            rules: Rules::get(),
        }
    }

    /// P*, Fs* (with their d*-derivatives) and, if `want_q`, Q* at `d`:
    /// one `match` on the law, then static calls.
    pub fn evaluate(&self, d: f64, want_q: bool) -> Sums {
        match &self.law {
            Law::Ke(law) => self.evaluate_law(law, d, want_q),
            Law::Ceb(law) => self.evaluate_law(law, d, want_q),
        }
    }

    /// [`evaluate`](Self::evaluate) with the law `law`.
    #[inline(always)]
    pub(super) fn evaluate_law<L: ContactLaw>(&self, law: &L, d: f64, want_q: bool) -> Sums {
        match &self.heights {
            Heights::Gauss(h) => self.evaluate_with(law, h, d, want_q),
            Heights::General(h) => self.evaluate_with(law, &**h, d, want_q),
        }
    }

    #[inline(always)]
    fn evaluate_with<L: ContactLaw, H: Phi>(&self, law: &L, h: &H, d: f64, want_q: bool) -> Sums {
        let win = h.window(d);
        let mut c = self.contact(law, h, d, win, want_q);
        if self.adh_pref != 0.0 {
            let (j, dj) = self.noncontact(h, d);
            c.fs += j;
            c.dfs += dj;
        }
        Sums {
            p: self.load_pref * c.p,
            dp: self.load_pref * c.dp,
            fs: self.adh_pref * c.fs,
            dfs: self.adh_pref * c.dfs,
            q: self.load_pref * c.q,
        }
    }

    /// Contact integrals of MODEL.md §4 (§8 for the CEB-type law), without
    /// their prefactors: the law's elastic regime, then its regimes above,
    /// each times its coefficients.
    fn contact<L: ContactLaw, H: Phi>(&self, law: &L, h: &H, d: f64, win: Window, want_q: bool) -> Sums {
        let adh = self.adh_pref != 0.0;
        let el = law.elastic(self, h, d, win, adh, want_q);
        let c = &self.adh_coef;
        let mut sums = Sums {
            p: el.p,
            dp: el.dp,
            fs: c[0] * el.fs,
            dfs: c[0] * el.dfs,
            q: el.q,
        };
        for r in law.regimes() {
            let s = self.regime(law, h, d, win, r, adh, want_q);
            sums.p += r.coef * s.p;
            sums.dp += r.coef * s.dp;
            if let Some(row) = r.adhesion {
                sums.fs += c[row] * s.fs;
                sums.dfs += c[row] * s.dfs;
            }
            if let Some(f) = r.friction {
                sums.q += f.coef * s.q;
            }
        }
        if H::GENERAL {
            self.add_jumps(law, h, d, &mut sums);
        }
        sums
    }

    /// One regime's raw integrals (before its coefficients), in two pieces
    /// where it is split.
    #[allow(clippy::too_many_arguments)]
    fn regime<L: ContactLaw, H: Phi>(
        &self,
        law: &L,
        h: &H,
        d: f64,
        win: Window,
        r: &Regime,
        adh: bool,
        want_q: bool,
    ) -> Sums {
        let b_adh = r.adhesion.filter(|_| adh).map(|row| adhesion::ROWS[row].1);
        let q_to = r.friction.map_or(f64::NEG_INFINITY, |f| f.to);
        match r.split.filter(|&x| x > r.xa && x < r.xc) {
            Some(x) => {
                let a = self.piece(law, h, d, win, r.xa, x, r.load, b_adh, want_q && r.xa < q_to);
                let b = self.piece(law, h, d, win, x, r.xc, r.load, b_adh, want_q && x < q_to);
                Sums {
                    p: a.p + b.p,
                    dp: a.dp + b.dp,
                    fs: a.fs + b.fs,
                    dfs: a.dfs + b.dfs,
                    q: a.q + b.q,
                }
            }
            None => self.piece(law, h, d, win, r.xa, r.xc, r.load, b_adh, want_q && r.xa < q_to),
        }
    }

    /// `[xa, xc]` with the load law `load` (one instance of
    /// [`smooth`](Self::smooth) per kind of law: no branch per node).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn piece<L: ContactLaw, H: Phi>(
        &self,
        law: &L,
        h: &H,
        d: f64,
        win: Window,
        xa: f64,
        xc: f64,
        load: LoadLaw,
        b_adh: Option<f64>,
        want_q: bool,
    ) -> Sums {
        match load {
            LoadLaw::Power(b) => {
                let f = move |x: f64, lx: f64| {
                    let p = (b * lx).exp();
                    (p, b * p / x)
                };
                self.smooth(law, h, d, win, xa, xc, f, b_adh, want_q)
            }
            LoadLaw::Linear => self.smooth(law, h, d, win, xa, xc, |x, _| (x, 1.0), b_adh, want_q),
            LoadLaw::Affine(a, b, c) => {
                let f = move |x: f64, _: f64| (a * (b * x + c), a * b);
                self.smooth(law, h, d, win, xa, xc, f, b_adh, want_q)
            }
        }
    }

    /// The terms of ∂P*/∂d*, ∂Fs*/∂d* from the jumps of the laws at the
    /// regime boundaries (x = 1, 6, 110 for both laws here), which move
    /// with d* (general densities, whose derivatives come from the laws'
    /// slopes): the load and the contact adhesion below and above each
    /// boundary, times φ* there.
    fn add_jumps<L: ContactLaw, H: Phi>(&self, law: &L, h: &H, d: f64, sums: &mut Sums) {
        // adh_coef holds the rows' coefficients, the jumps x^b alone.
        let c = &self.adh_coef;
        for j in law.jumps() {
            let phi = h.phi(d + self.omega * j.x);
            let [(r0, f0), (r1, f1)] = j.adhesion;
            sums.dp += (j.load[0] - j.load[1]) * phi;
            sums.dfs += (c[r0] * f0 - c[r1] * f1) * phi;
        }
    }

    /// The elastic regime `0 ≤ x < 1` without friction: the Hertz load and
    /// the elastic adhesion (the default of [`ContactLaw::elastic`]).
    pub(super) fn elastic_hertz<H: Phi>(&self, h: &H, d: f64, win: Window, adh: bool) -> Sums {
        let mut acc = Sums::default();
        self.panels(h, d, win, 0.0, X_ELASTIC, |p| {
            if p.first {
                self.elastic_first_panel(h, d, p.x1, adh, &mut acc);
            } else {
                self.legendre_panel(h, d, p, |x, w, dw| {
                    elastic_node::<H>(&mut acc, x, x.ln(), w, dw, adh);
                });
            }
        });
        acc
    }

    /// The Hertz load `x^1.5` and the elastic adhesion `x^0.298` (the same
    /// in both models) on the panel `[0, x1]`, by their Gauss–Jacobi rules.
    /// A general density also needs the laws' slopes `1.5·x^0.5` and
    /// `0.298·x^−0.702`: their rules give the laws too (`x^1.5 = x^0.5·x`,
    /// `x^0.298 = x^−0.702·x`), so φ* is evaluated on two rules, not four.
    pub(super) fn elastic_first_panel<H: Phi>(&self, h: &H, d: f64, x1: f64, adh: bool, acc: &mut Sums) {
        if H::GENERAL {
            let b = load::ELASTIC.1;
            self.jacobi_panel(h, d, &self.rules.gj_half, b - 1.0, x1, |x, w, dw| {
                acc.p += x * w;
                acc.dp += b * dw;
            });
            if adh {
                let b = adhesion::ELASTIC.1;
                self.jacobi_panel(h, d, &self.rules.gj_adh_slope, b - 1.0, x1, |x, w, dw| {
                    acc.fs += x * w;
                    acc.dfs += b * dw;
                });
            }
            return;
        }
        self.jacobi_panel(h, d, &self.rules.gj_load, load::ELASTIC.1, x1, |_, w, dw| {
            acc.p += w;
            acc.dp += dw;
        });
        if adh {
            self.jacobi_panel(h, d, &self.rules.gj_adh, adhesion::ELASTIC.1, x1, |_, w, dw| {
                acc.fs += w;
                acc.dfs += dw;
            });
        }
    }

    /// A regime `[xa, xc]` with `xa ≥ 1`, where every factor is analytic:
    /// load and its slope `load(x, ln x)`, adhesion `x^b_adh` (if any) and, if `want_q`, the
    /// friction factor `load(x)·μ(x)` (the law's [`ContactLaw::mu`]).
    #[allow(clippy::too_many_arguments)]
    fn smooth<L: ContactLaw, H: Phi>(
        &self,
        law: &L,
        h: &H,
        d: f64,
        win: Window,
        xa: f64,
        xc: f64,
        load: impl Fn(f64, f64) -> (f64, f64),
        b_adh: Option<f64>,
        want_q: bool,
    ) -> Sums {
        let mut acc = Sums::default();
        self.panels(h, d, win, xa, xc, |p| {
            self.legendre_panel(h, d, p, |x, w, dw| {
                let lx = x.ln();
                let (p, dp_dx) = load(x, lx);
                add_node::<H>(&mut acc, p, dp_dx, x, lx, w, dw, b_adh);
                if want_q {
                    acc.q += p * law.mu(x) * w;
                }
            })
        });
        acc
    }

    /// The non-contact adhesion integral `J_nc` (MODEL.md §4) and its
    /// d*-derivative, in the gap `g = d* − z* ≥ 0`.
    fn noncontact<H: Phi>(&self, h: &H, d: f64) -> (f64, f64) {
        if H::GENERAL {
            return self.noncontact_general(h, d);
        }
        let s = self.s;
        // The largest gap g = d* − z*, at z* = −hypot(min(d*, 0), cut).
        let g_max = d + d.min(0.0).hypot(tail_cut(s));
        // Asperities above z_hi add less than e^−TAIL of J_nc: there φ* is
        // below e^−TAIL of ε*·(u at z* = 0)^−2 ≲ J_nc, and ∫ (…) dg* ≤ (4/3)ε*.
        // Skipping them keeps the work bounded for large d* (the panels
        // shrink like 1/|z*| far out).
        let norm = 1.0 / (s * (2.0 * core::f64::consts::PI).sqrt());
        let worst = 4.0 * norm * (d.max(0.0) + s + self.eps).powi(2) / self.eps;
        let z_hi = s * (2.0 * (TAIL + worst.ln().max(0.0))).sqrt();
        let mut g0 = (d - z_hi).max(0.0);
        let (mut j, mut dj) = (0.0, 0.0);
        // Panels [ε(2^k − 1), ε(2^(k+1) − 1)]: each is at least a third of its
        // distance from the pole of u^−2 at g = −ε away, so the rule converges fast.
        let mut width = self.eps + g0;
        while g0 < g_max {
            let step = h.step(d - g0, false);
            let w = if width < step { width } else { step };
            let g1 = if g0 + 1.5 * w >= g_max { g_max } else { g0 + w };
            let hw = g1 - g0;
            for (t, wt) in self.rules.gl.t.iter().zip(&self.rules.gl.w) {
                let g = g0 + hw * t;
                let z = d - g;
                let wp = hw * wt * h.phi(z);
                let a = asperity::adhesion_noncontact(1.0 + g / self.eps);
                j += a * wp;
                dj += h.dw(a * wp, z, 0.0);
            }
            g0 = g1;
            width *= 2.0;
        }
        (j, dj)
    }

    /// `J_nc` for a general density: from the upper end of the support (or
    /// z* = d*) down to its lower end or until the rest is negligible.
    fn noncontact_general<H: Phi>(&self, h: &H, d: f64) -> (f64, f64) {
        let (lo_end, hi_end) = h.ends();
        let mut g0 = hi_end.map_or(0.0, |e| (d - e.z).max(0.0));
        let g_max = lo_end.map_or(f64::INFINITY, |e| d - e.z);
        let mut width = self.eps + g0;
        let mut scale = 0.0f64;
        let tail = h.tails().0;
        let eps = self.eps;
        // Adds a node of weight `wp` (φ* included) at gap `g`; returns its
        // part of J_nc. d* moves the law a(1 + (d* − z*)/ε*), not φ*: its
        // slope a'/ε* here, and a(1)·φ*(d*) for the moving end z* = d*.
        let add = |j: &mut f64, dj: &mut f64, g: f64, wp: f64| {
            let u = 1.0 + g / eps;
            let part = asperity::adhesion_noncontact(u) * wp;
            *j += part;
            *dj += asperity::adhesion_noncontact_slope(u) / eps * wp;
            part
        };
        let (mut j, mut dj) = (0.0, asperity::adhesion_noncontact(1.0) * h.phi(d));
        // A first panel at the upper end of the support (below z* = d*).
        if let Some(e) = hi_end.filter(|_| g0 > 0.0) {
            let w = width.min(h.step(e.z, false)).min(0.5 * (g_max - g0));
            if e.jacobi(w) {
                h.end_panel(e, w, |dist, wp| {
                    add(&mut j, &mut dj, g0 + dist, wp);
                });
                g0 += w;
                width = self.eps + g0;
            }
        }
        for _ in 0..MAX_PANELS {
            if g0 >= g_max {
                break;
            }
            let z0 = d - g0;
            // The law a(1 + (d* − z*)/ε*) has its pole at z* = d* + ε*.
            if h.tail_from(z0, false, d + eps) {
                h.tail_panel(z0, false, |z, wp| {
                    add(&mut j, &mut dj, d - z, wp);
                });
                break;
            }
            let mut w = width.min(h.step(z0, false));
            if let Some(e) = hi_end {
                // Graded away from the upper end of the support.
                let dist = e.z - z0;
                if dist > 0.0 {
                    w = w.min(dist);
                }
            }
            if let Some(e) = lo_end {
                let dist = z0 - e.z;
                if e.jacobi(w.max(dist)) && w >= 0.5 * dist {
                    h.end_panel(e, dist, |t, wp| {
                        add(&mut j, &mut dj, g_max - t, wp);
                    });
                    break;
                }
                w = w.min(0.5 * dist);
            }
            let g1 = g0 + w;
            let hw = g1 - g0;
            let mut local = 0.0;
            for (t, wt) in self.rules.gl.t.iter().zip(&self.rules.gl.w) {
                let g = g0 + hw * t;
                local += add(&mut j, &mut dj, g, hw * wt * h.phi(d - g));
            }
            scale = scale.max(local.abs());
            g0 = g1;
            width *= 2.0;
            if d - g0 < tail && local.abs() <= NEGLIGIBLE * scale {
                break;
            }
        }
        (j, dj)
    }

    /// Calls `f(panel)` for the panels covering `[xa, xc]` within the
    /// window; `first` marks a panel starting at `xa`, `last` one ending at
    /// `xc` (not cut by the window).
    #[inline(always)]
    pub(super) fn panels<H: Phi>(&self, h: &H, d: f64, win: Window, xa: f64, xc: f64, mut f: impl FnMut(Panel)) {
        let (om, inv_om) = (self.omega, 1.0 / self.omega);
        let x_lo = (win.lo - d) * inv_om;
        let x_hi = (win.hi - d) * inv_om;
        let start = xa.max(x_lo);
        let end = xc.min(x_hi);
        if start.is_nan() || end.is_nan() || start >= end {
            return;
        }
        let last_is_end = end == xc;
        let mut x = start;
        let mut first = start == xa;
        let mut from_end = H::GENERAL && start == x_lo && start > xa;
        let (lo_end, hi_end) = if H::GENERAL { h.ends() } else { (None, None) };
        let at_hi_end = H::GENERAL && end == x_hi && hi_end.is_some();
        for _ in 0..MAX_PANELS {
            // A panel no longer than its distance from x = 0 keeps the
            // branch point of x^b far enough away for geometric convergence.
            let z = d + om * x;
            if H::GENERAL && end == f64::INFINITY && h.tail_from(z, true, d) {
                f(Panel {
                    x0: x,
                    x1: end,
                    first,
                    last: true,
                    at_end: EndSide::Tail,
                });
                break;
            }
            let dx = h.step(z, true) * inv_om;
            let mut dx = if x > 0.0 && x < dx { x } else { dx };
            let mut jacobi_end = false;
            if H::GENERAL {
                if let Some(e) = lo_end.filter(|_| !from_end) {
                    // Graded away from the lower end of the support.
                    dx = dx.min((z - e.z) * inv_om);
                }
                if let Some(e) = hi_end {
                    // Graded towards the upper end: a panel no longer than
                    // its distance from it, and the one that reaches it by
                    // the end's Gauss–Jacobi rule where that is exact.
                    let dist = (e.z - d) * inv_om - x;
                    let reaches = at_hi_end && (!first || x > 0.0);
                    if reaches && dx >= 0.5 * dist && e.jacobi(dist * om) {
                        jacobi_end = true;
                        dx = dist;
                    } else {
                        // Even stretched by 1.5 to the regime's end, the
                        // panel stays its own length away from the end.
                        dx = dx.min(dist / 3.0);
                    }
                }
                if from_end {
                    // The first panel from the lower end of the support:
                    // Gauss–Jacobi, or a tiny first panel where that is not exact.
                    let e = lo_end.expect("a lower end");
                    if !e.jacobi(dx * om) {
                        dx *= 1e-9;
                        from_end = false;
                    }
                }
            }
            let (x1, last) = if jacobi_end || x + 1.5 * dx >= end {
                (end, true)
            } else {
                (x + dx, false)
            };
            f(Panel {
                x0: x,
                x1,
                first,
                last: last && last_is_end,
                at_end: if jacobi_end {
                    EndSide::Upper
                } else if from_end {
                    EndSide::Lower
                } else {
                    EndSide::None
                },
            });
            if last || (H::GENERAL && h.negligible(d + om * x1, win)) {
                break;
            }
            first = false;
            from_end = false;
            x = x1;
        }
    }

    /// Gauss–Legendre on the panel (or, at an end of a general density's
    /// support, Gauss–Jacobi with the end's weight): calls `f(x, w·φ,
    /// w·φ')` with the weights for `dz* = ω dx`.
    #[inline(always)]
    pub(super) fn legendre_panel<H: Phi>(&self, h: &H, d: f64, p: Panel, mut f: impl FnMut(f64, f64, f64)) {
        let (x0, x1) = (p.x0, p.x1);
        if H::GENERAL && p.at_end != EndSide::None {
            let (lo_end, hi_end) = h.ends();
            let om = self.omega;
            let width = om * (x1 - x0);
            match p.at_end {
                EndSide::Tail => h.tail_panel(d + om * x0, true, |z, w| f((z - d) / om, w, h.dw(w, z, 1.0 / om))),
                EndSide::Upper => {
                    let e = hi_end.expect("an upper end");
                    h.end_panel(e, width, |dist, w| {
                        let z = e.z - dist;
                        f((z - d) / om, w, h.dw(w, z, 1.0 / om))
                    });
                }
                _ => {
                    let e = lo_end.expect("a lower end");
                    h.end_panel(e, width, |dist, w| {
                        let z = e.z + dist;
                        f((z - d) / om, w, h.dw(w, z, 1.0 / om))
                    });
                }
            }
            return;
        }
        let hw = self.omega * (x1 - x0);
        for (t, wt) in self.rules.gl.t.iter().zip(&self.rules.gl.w) {
            let x = x0 + (x1 - x0) * t;
            let z = d + self.omega * x;
            let w = hw * wt * h.phi(z);
            f(x, w, h.dw(w, z, 1.0 / self.omega));
        }
    }

    /// Gauss–Jacobi for `∫₀^x1 x^b (…) dz*`: calls `f(x, w·φ, w·φ')` with
    /// weights that already include `x^b`.
    #[inline(always)]
    pub(super) fn jacobi_panel<H: Phi>(
        &self,
        h: &H,
        d: f64,
        rule: &Rule,
        b: f64,
        x1: f64,
        mut f: impl FnMut(f64, f64, f64),
    ) {
        let scale = self.omega * x1.powf(b + 1.0);
        for i in 0..NODES {
            let x = x1 * rule.t[i];
            let z = d + self.omega * x;
            let w = scale * rule.w[i] * h.phi(z);
            f(x, w, h.dw(w, z, 1.0 / self.omega));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Constants;
    use serde_json::Value;

    impl Surface {
        /// `I^b[xa, xc]` (MODEL.md §4) with the same panels and rules as the
        /// model's own integrals.
        fn moment(&self, d: f64, b: f64, xa: f64, xc: f64) -> f64 {
            let Heights::Gauss(h) = &self.heights else {
                panic!("a Gaussian surface")
            };
            let win = h.window(d);
            let rule = Rule::jacobi(b);
            let mut sum = 0.0;
            self.panels(h, d, win, xa, xc, |p| {
                if p.first && xa == 0.0 {
                    self.jacobi_panel(h, d, &rule, b, p.x1, |_, w, _| sum += w);
                } else {
                    self.legendre_panel(h, d, p, |x, w, _| sum += x.powf(b) * w);
                }
            });
            sum
        }
    }

    /// MODEL.md §5: `I^b[0,∞)` in closed form through the parabolic cylinder
    /// function (values from `tools/reference.py`, mpmath `pcfd`), and the
    /// pieces `I^b[0,1]`, `I^b[1,∞)` from 30-digit quadrature.
    #[test]
    fn moments_match_the_closed_form_semi_infinite_integrals() {
        let doc: Value = serde_json::from_str(include_str!("../../tests/data/reference_points.json")).unwrap();
        let mut n = 0;
        for p in doc["points"].as_array().unwrap() {
            if p["kind"] != "closed_form" {
                continue;
            }
            let f = |k: &str| p[k].as_f64().unwrap();
            let surface = Surface::new(&Params::new(f("psi"), 0.0).beta(f("beta")));
            let (b, d) = (f("b"), f("d_star"));
            let lower = surface.moment(d, b, 0.0, 1.0);
            let upper = surface.moment(d, b, 1.0, f64::INFINITY);
            let whole = surface.moment(d, b, 0.0, f64::INFINITY);
            for (what, got, want) in [
                ("I[0,1]", lower, f("i_0_1")),
                ("I[1,inf)", upper, f("i_1_inf")),
                ("I[0,inf)", whole, f("i_0_inf")),
                ("I[0,1]+I[1,inf)", lower + upper, f("i_0_inf")),
            ] {
                let rel = ((got - want) / want).abs();
                assert!(rel < 1e-12, "b = {b}, d* = {d}: {what} = {got:e} vs {want:e} ({rel:e})");
            }
            n += 1;
        }
        assert!(n >= 6);
    }

    /// The test-only Hertz law (x^1.5 at every interference, no plastic
    /// regime) through the same integrals: P* matches the closed form
    /// `(2/3)πβKω_c*·I^1.5[0,∞)` (MODEL.md §5), and, where every contact
    /// is elastic (ψ small), the Kogut–Etsion model; with a bounded Pearson
    /// density (K = 2.5) too: the general path, with the jumps.
    #[test]
    fn a_test_only_hertz_law_goes_through_the_same_integrals() {
        use crate::model::laws::hertz::Hertz;
        let doc: Value = serde_json::from_str(include_str!("../../tests/data/reference_points.json")).unwrap();
        let p = doc["points"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["kind"] == "closed_form" && p["b"] == 1.5)
            .expect("a closed form for b = 1.5");
        let f = |k: &str| p[k].as_f64().unwrap();
        let surface = Surface::new(&Params::new(f("psi"), 0.0).beta(f("beta")));
        let s = surface.evaluate_law(&Hertz::new(), f("d_star"), true);
        let want = surface.load_pref * f("i_0_inf");
        assert!(s.p.is_finite() && s.p > 0.0 && s.dp < 0.0, "{s:?}");
        assert!(((s.p - want) / want).abs() < 1e-12, "P* = {:e} vs {want:e}", s.p);
        assert_eq!((s.fs, s.q), (0.0, 0.0));

        let gaussian = Constants::default();
        let pearson = Constants::default().distribution(crate::HeightDistribution::pearson(0.0, 2.5).unwrap());
        for c in [gaussian, pearson] {
            let params = c.at(0.1, 0.003).unwrap();
            let surface = Surface::new(&params);
            for d in [0.5, 1.0, 2.0] {
                let hertz = surface.evaluate_law(&Hertz::new(), d, true);
                let ke = surface.evaluate(d, true);
                assert!(hertz.p.is_finite() && hertz.p > 0.0, "{hertz:?}");
                for (what, a, b) in [
                    ("P*", hertz.p, ke.p),
                    ("dP*", hertz.dp, ke.dp),
                    ("Fs*", hertz.fs, ke.fs),
                    ("dFs*", hertz.dfs, ke.dfs),
                ] {
                    assert!(((a - b) / b).abs() < 1e-9, "d* = {d}: {what} {a:e} vs {b:e}");
                }
            }
        }
    }
}
