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
//! factor are cut. No allocation, no recursion: a fixed amount of
//! arithmetic per panel.

use super::asperity::{self, adhesion, load, CebCapacity, FRICTION_ELASTIC, X0, X_ELASTIC, X_EP1, X_PLASTIC};
use super::quadrature::{Rule, NODES};
use crate::params::{hardness_coefficient, sigma_s_ratio, Fit, Kind, Params};

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
    kind: Kind,
    /// σ_s/σ.
    s: f64,
    inv_s2: f64,
    /// 1/(s√(2π)).
    norm: f64,
    /// ω_c* = s/ψ².
    omega: f64,
    /// y_s* = h* − d*.
    pub ys: f64,
    eps: f64,
    /// (2/3)πβKω_c*, in front of P* and Q*.
    load_pref: f64,
    /// 2πβθ, in front of Fs*.
    adh_pref: f64,
    /// 3/K, the fully plastic load.
    plastic: f64,
    /// `a·r^c` of the three contact adhesion rows.
    adh_coef: [f64; 3],
    /// Coefficient of `x^1.425·μ_ep(x)` in the 1st elastic-plastic friction row.
    q_ep: f64,
    /// Whether the friction row goes on past x₀ (the printed form).
    q_unclipped: bool,
    rules: &'static Rules,
    ceb: CebCapacity,
}

/// The Gauss rules, the same for every model: computed once per process.
#[derive(Debug)]
struct Rules {
    gl: Rule,
    /// Gauss–Jacobi rules for `x^1.5`, `x^0.298`, `x^0.982` (first panels).
    gj_load: Rule,
    gj_adh: Rule,
    gj_fric: Rule,
    /// Gauss–Jacobi rule for `(1 − x)^½` (CEB-type, at x = 1).
    gj_half: Rule,
}

impl Rules {
    fn get() -> &'static Rules {
        static RULES: std::sync::OnceLock<Rules> = std::sync::OnceLock::new();
        RULES.get_or_init(|| Rules {
            gl: Rule::legendre(),
            gj_load: Rule::jacobi(load::ELASTIC.1),
            gj_adh: Rule::jacobi(adhesion::ELASTIC.1),
            gj_fric: Rule::jacobi(FRICTION_ELASTIC.1),
            gj_half: Rule::jacobi(0.5),
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
/// largest value on the integrals' range.
#[derive(Debug, Clone, Copy)]
struct Window {
    lo: f64,
    hi: f64,
}

impl Window {
    fn contact(d: f64, s: f64) -> Window {
        let cut = tail_cut(s);
        Window {
            lo: -cut,
            hi: d.max(0.0).hypot(cut),
        }
    }
}

/// Adds a node's load `p` and, with an adhesion exponent `b_adh`, its
/// adhesion `x^b_adh` (from `lx = ln x`), with weights `w`, `dw`.
#[inline(always)]
fn add_node(acc: &mut Sums, p: f64, lx: f64, w: f64, dw: f64, b_adh: Option<f64>) {
    acc.p += p * w;
    acc.dp += p * dw;
    if let Some(b) = b_adh {
        let f = (b * lx).exp();
        acc.fs += f * w;
        acc.dfs += f * dw;
    }
}

/// Adds the Hertz load `x^1.5` and the elastic adhesion `x^0.298` (both
/// models) at an interior node; returns `x^1.5`.
#[inline(always)]
fn elastic_node(acc: &mut Sums, x: f64, lx: f64, w: f64, dw: f64, adh: bool) -> f64 {
    let p = x * x.sqrt();
    add_node(acc, p, lx, w, dw, adh.then_some(adhesion::ELASTIC.1));
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
        let (q_ep, q_unclipped) = match p.constants.fit {
            Fit::Consistent => (load::EP1.0, false),
            Fit::AsPrinted => (FRICTION_ELASTIC.0, true),
        };
        Surface {
            kind: p.constants.kind,
            s,
            inv_s2: 1.0 / (s * s),
            norm: 1.0 / (s * (2.0 * pi).sqrt()),
            omega,
            ys: 1.0 / (4.0 * 3f64.sqrt() * pi * p.constants.beta),
            eps: p.constants.eps_star,
            load_pref: (2.0 / 3.0) * pi * p.constants.beta * k * omega,
            adh_pref: 2.0 * pi * p.constants.beta * p.theta,
            plastic: 3.0 / k,
            adh_coef: [adhesion::ELASTIC, adhesion::EP1, adhesion::EP2].map(|(a, _, c)| a * r.powf(c)),
            q_ep,
            q_unclipped,
            rules: Rules::get(),
            ceb: CebCapacity::new(p.constants.nu),
        }
    }

    /// P*, Fs* (with their d*-derivatives) and, if `want_q`, Q* at `d`.
    pub fn evaluate(&self, d: f64, want_q: bool) -> Sums {
        let win = Window::contact(d, self.s);
        let mut c = match self.kind {
            Kind::KogutEtsion => self.contact_ke(d, win, want_q),
            Kind::CebType => self.contact_ceb(d, win, want_q),
        };
        if self.adh_pref != 0.0 {
            let (j, dj) = self.noncontact(d);
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

    /// Contact integrals of MODEL.md §4, without their prefactors.
    fn contact_ke(&self, d: f64, win: Window, want_q: bool) -> Sums {
        let adh = self.adh_pref != 0.0;
        let el = self.elastic(d, win, adh, want_q);
        // A power-law regime [xa, xc]: load x^b_load, adhesion exponent b_adh.
        let regime = |xa: f64, xc: f64, b_load: f64, b_adh: f64, want_q: bool| {
            let law = move |_: f64, lx: f64| (b_load * lx).exp();
            self.smooth(d, win, xa, xc, law, adh.then_some(b_adh), want_q)
        };
        let ep1a = regime(X_ELASTIC, X0, load::EP1.1, adhesion::EP1.1, want_q);
        let ep1b = regime(X0, X_EP1, load::EP1.1, adhesion::EP1.1, want_q && self.q_unclipped);
        let ep2 = regime(X_EP1, X_PLASTIC, load::EP2.1, adhesion::EP2.1, false);
        let pl = self.smooth(d, win, X_PLASTIC, f64::INFINITY, |x, _| x, None, false);
        let (a1, a2, a3) = (load::EP1.0, load::EP2.0, self.plastic);
        let p = el.p + a1 * (ep1a.p + ep1b.p) + a2 * ep2.p + a3 * pl.p;
        let dp = el.dp + a1 * (ep1a.dp + ep1b.dp) + a2 * ep2.dp + a3 * pl.dp;
        let [c0, c1, c2] = self.adh_coef;
        let fs = c0 * el.fs + c1 * (ep1a.fs + ep1b.fs) + c2 * ep2.fs;
        let dfs = c0 * el.dfs + c1 * (ep1a.dfs + ep1b.dfs) + c2 * ep2.dfs;
        let q = FRICTION_ELASTIC.0 * el.q + self.q_ep * (ep1a.q + ep1b.q);
        Sums { p, dp, fs, dfs, q }
    }

    /// Contact integrals of the CEB-type model (MODEL.md §8): Hertz load
    /// and `μ_CEB` below x = 1, the volume-conserving load `1.5(2x − 1)`
    /// above, and the Kogut–Etsion adhesion throughout.
    fn contact_ceb(&self, d: f64, win: Window, want_q: bool) -> Sums {
        let adh = self.adh_pref != 0.0;
        let el = self.elastic_ceb(d, win, adh, want_q);
        let law = |x: f64, _: f64| 1.5 * (2.0 * x - 1.0);
        let ep1 = self.smooth(d, win, X_ELASTIC, X_EP1, law, adh.then_some(adhesion::EP1.1), false);
        let ep2 = self.smooth(d, win, X_EP1, X_PLASTIC, law, adh.then_some(adhesion::EP2.1), false);
        let pl = self.smooth(d, win, X_PLASTIC, f64::INFINITY, law, None, false);
        let p = el.p + ep1.p + ep2.p + pl.p;
        let dp = el.dp + ep1.dp + ep2.dp + pl.dp;
        let [c0, c1, c2] = self.adh_coef;
        let fs = c0 * el.fs + c1 * ep1.fs + c2 * ep2.fs;
        let dfs = c0 * el.dfs + c1 * ep1.dfs + c2 * ep2.dfs;
        Sums {
            p,
            dp,
            fs,
            dfs,
            q: el.q,
        }
    }

    /// The elastic regime of the CEB-type model: `Q̄ = μ_CEB·P̄`, with the
    /// branch `μ2` below the crossing `xc` and `μ1` (which vanishes like
    /// `(1 − x)^½` at x = 1) above it.
    fn elastic_ceb(&self, d: f64, win: Window, adh: bool, want_q: bool) -> Sums {
        let xc = self.ceb.x_cross;
        let ceb = &self.ceb;
        let mut acc = Sums::default();
        let m15 = ceb.mu2_power_coefficient();
        self.panels(d, win, 0.0, xc, |x0, x1, first, _| {
            if first {
                self.elastic_first_panel(d, x1, adh, &mut acc);
                if want_q {
                    // acc.p is so far just ∫₀^x1 x^1.5 φ*, the first panel's load.
                    acc.q += m15 * acc.p;
                    self.legendre_panel(d, x0, x1, |x, w, _| acc.q += x * ceb.mu2_remainder(x) * w);
                }
            } else {
                self.legendre_panel(d, x0, x1, |x, w, dw| {
                    let p = elastic_node(&mut acc, x, x.ln(), w, dw, adh);
                    if want_q {
                        acc.q += (m15 * p + x * ceb.mu2_remainder(x)) * w;
                    }
                });
            }
        });
        self.panels(d, win, xc, X_ELASTIC, |x0, x1, _, last| {
            self.legendre_panel(d, x0, x1, |x, w, dw| {
                elastic_node(&mut acc, x, x.ln(), w, dw, adh);
                if want_q && !last {
                    acc.q += ceb.mu1_factor(x) * (1.0 - x).sqrt() * w;
                }
            });
            if want_q && last {
                // (1 − x)^½ at x = 1: the mirrored Gauss–Jacobi rule.
                let width = X_ELASTIC - x0;
                let scale = self.omega * width.powf(1.5);
                for (t, wt) in self.rules.gj_half.t.iter().zip(&self.rules.gj_half.w) {
                    let x = X_ELASTIC - width * t;
                    acc.q += scale * wt * self.phi(d + self.omega * x) * ceb.mu1_factor(x);
                }
            }
        });
        acc
    }

    /// The fully elastic regime `0 ≤ x < 1` of the Kogut–Etsion model.
    fn elastic(&self, d: f64, win: Window, adh: bool, want_q: bool) -> Sums {
        let mut acc = Sums::default();
        let b_fric = FRICTION_ELASTIC.1;
        self.panels(d, win, 0.0, X_ELASTIC, |x0, x1, first, _| {
            if first {
                self.elastic_first_panel(d, x1, adh, &mut acc);
                if want_q {
                    self.jacobi_panel(d, &self.rules.gj_fric, b_fric, x1, |_, w, _| acc.q += w);
                }
            } else {
                self.legendre_panel(d, x0, x1, |x, w, dw| {
                    let lx = x.ln();
                    elastic_node(&mut acc, x, lx, w, dw, adh);
                    if want_q {
                        acc.q += (b_fric * lx).exp() * w;
                    }
                });
            }
        });
        acc
    }

    /// The Hertz load `x^1.5` and the elastic adhesion `x^0.298` (the same
    /// in both models) on the panel `[0, x1]`, by their Gauss–Jacobi rules.
    fn elastic_first_panel(&self, d: f64, x1: f64, adh: bool, acc: &mut Sums) {
        self.jacobi_panel(d, &self.rules.gj_load, load::ELASTIC.1, x1, |_, w, dw| {
            acc.p += w;
            acc.dp += dw;
        });
        if adh {
            self.jacobi_panel(d, &self.rules.gj_adh, adhesion::ELASTIC.1, x1, |_, w, dw| {
                acc.fs += w;
                acc.dfs += dw;
            });
        }
    }

    /// A regime `[xa, xc]` with `xa ≥ 1`, where every factor is analytic:
    /// load `load(x, ln x)`, adhesion `x^b_adh` (if any) and, if `want_q`, the
    /// friction factor `x^1.425·μ_ep(x)`.
    #[allow(clippy::too_many_arguments)]
    fn smooth(
        &self,
        d: f64,
        win: Window,
        xa: f64,
        xc: f64,
        load: impl Fn(f64, f64) -> f64,
        b_adh: Option<f64>,
        want_q: bool,
    ) -> Sums {
        let mut acc = Sums::default();
        self.panels(d, win, xa, xc, |x0, x1, _, _| {
            self.legendre_panel(d, x0, x1, |x, w, dw| {
                let lx = x.ln();
                let p = load(x, lx);
                add_node(&mut acc, p, lx, w, dw, b_adh);
                if want_q {
                    acc.q += p * asperity::mu_ep(x) * w;
                }
            })
        });
        acc
    }

    /// The non-contact adhesion integral `J_nc` (MODEL.md §4) and its
    /// d*-derivative, in the gap `g = d* − z* ≥ 0`.
    fn noncontact(&self, d: f64) -> (f64, f64) {
        // The largest gap g = d* − z*, at z* = −hypot(min(d*, 0), cut).
        let g_max = d + d.min(0.0).hypot(tail_cut(self.s));
        // Asperities above z_hi add less than e^−TAIL of J_nc: there φ* is
        // below e^−TAIL of ε*·(u at z* = 0)^−2 ≲ J_nc, and ∫ (…) dg* ≤ (4/3)ε*.
        // Skipping them keeps the work bounded for large d* (the panels
        // shrink like 1/|z*| far out).
        let worst = 4.0 * self.norm * (d.max(0.0) + self.s + self.eps).powi(2) / self.eps;
        let z_hi = self.s * (2.0 * (TAIL + worst.ln().max(0.0))).sqrt();
        let mut g0 = (d - z_hi).max(0.0);
        let (mut j, mut dj) = (0.0, 0.0);
        // Panels [ε(2^k − 1), ε(2^(k+1) − 1)]: each is at least a third of its
        // distance from the pole of u^−2 at g = −ε away, so the rule converges fast.
        let mut width = self.eps + g0;
        while g0 < g_max {
            let step = self.step(d - g0);
            let w = if width < step { width } else { step };
            let g1 = if g0 + 1.5 * w >= g_max { g_max } else { g0 + w };
            let h = g1 - g0;
            for (t, wt) in self.rules.gl.t.iter().zip(&self.rules.gl.w) {
                let g = g0 + h * t;
                let z = d - g;
                let wp = h * wt * self.phi(z);
                let a = asperity::adhesion_noncontact(1.0 + g / self.eps);
                j += a * wp;
                dj -= a * wp * z * self.inv_s2;
            }
            g0 = g1;
            width *= 2.0;
        }
        (j, dj)
    }

    /// Calls `f(x0, x1, first, last)` for the panels covering `[xa, xc]`
    /// within the window; `first` marks a panel starting at `xa`, `last` one
    /// ending at `xc` (not cut by the window).
    #[inline(always)]
    fn panels(&self, d: f64, win: Window, xa: f64, xc: f64, mut f: impl FnMut(f64, f64, bool, bool)) {
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
        loop {
            // A panel no longer than its distance from x = 0 keeps the
            // branch point of x^b far enough away for geometric convergence.
            let dx = self.step(d + om * x) * inv_om;
            let dx = if x > 0.0 && x < dx { x } else { dx };
            let (x1, last) = if x + 1.5 * dx >= end {
                (end, true)
            } else {
                (x + dx, false)
            };
            f(x, x1, first, last && last_is_end);
            if last {
                break;
            }
            first = false;
            x = x1;
        }
    }

    /// Panel length in z* at height `z`.
    #[inline(always)]
    fn step(&self, z: f64) -> f64 {
        let s = self.s;
        let far = STEP_DECAY * s * s / (z.abs() + s);
        if far < MAX_STEP * s {
            far
        } else {
            MAX_STEP * s
        }
    }

    /// Gaussian density of asperity heights φ*(z*) (MODEL.md §2).
    #[inline(always)]
    fn phi(&self, z: f64) -> f64 {
        self.norm * (-0.5 * z * z * self.inv_s2).exp()
    }

    /// Gauss–Legendre on `[x0, x1]`: calls `f(x, w·φ, w·φ')` with the
    /// weights for `dz* = ω dx`.
    #[inline(always)]
    fn legendre_panel(&self, d: f64, x0: f64, x1: f64, mut f: impl FnMut(f64, f64, f64)) {
        let h = self.omega * (x1 - x0);
        for (t, wt) in self.rules.gl.t.iter().zip(&self.rules.gl.w) {
            let x = x0 + (x1 - x0) * t;
            let z = d + self.omega * x;
            let w = h * wt * self.phi(z);
            f(x, w, -w * z * self.inv_s2);
        }
    }

    /// Gauss–Jacobi for `∫₀^x1 x^b (…) dz*`: calls `f(x, w·φ, w·φ')` with
    /// weights that already include `x^b`.
    #[inline(always)]
    fn jacobi_panel(&self, d: f64, rule: &Rule, b: f64, x1: f64, mut f: impl FnMut(f64, f64, f64)) {
        let scale = self.omega * x1.powf(b + 1.0);
        for i in 0..NODES {
            let x = x1 * rule.t[i];
            let z = d + self.omega * x;
            let w = scale * rule.w[i] * self.phi(z);
            f(x, w, -w * z * self.inv_s2);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    impl Surface {
        /// `I^b[xa, xc]` (MODEL.md §4) with the same panels and rules as the
        /// model's own integrals.
        fn moment(&self, d: f64, b: f64, xa: f64, xc: f64) -> f64 {
            let win = Window::contact(d, self.s);
            let rule = Rule::jacobi(b);
            let mut sum = 0.0;
            self.panels(d, win, xa, xc, |x0, x1, first, _| {
                if first && xa == 0.0 {
                    self.jacobi_panel(d, &rule, b, x1, |_, w, _| sum += w);
                } else {
                    self.legendre_panel(d, x0, x1, |x, w, _| sum += x.powf(b) * w);
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
}
