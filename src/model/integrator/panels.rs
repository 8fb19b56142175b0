//! The law-independent machinery of the integrals: the panels of an
//! integral in x, their Gauss rules (Gauss–Jacobi at the contact point and
//! at the ends of a bounded support), the nodes of the elastic regime
//! (Hertz load, elastic adhesion) and the non-contact adhesion.

use super::density::{tail_cut, Phi, Window, TAIL};
use super::{Integrator, Sums};
use crate::model::asperity::{self, adhesion, HERTZ, X_ELASTIC};
use crate::quadrature::{Rule, NODES};

/// At most this many panels per integral (a safeguard: the tails of the
/// heaviest admissible densities need a few hundred).
const MAX_PANELS: usize = 100_000;
/// A tail is negligible once its part falls below this fraction (e^−40).
const NEGLIGIBLE: f64 = 4.248354255291589e-18;

/// Which end of the support a panel touches (general densities).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EndSide {
    None,
    Lower,
    Upper,
    /// All of a power tail beyond the panel's start ([`TailRule`](super::density::TailRule)).
    Tail,
}

/// One panel `[x0, x1]` of an integral in x.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Panel {
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
pub(crate) fn add_node<H: Phi>(
    acc: &mut Sums,
    p: f64,
    dp_dx: f64,
    x: f64,
    lx: f64,
    w: f64,
    dw: f64,
    b_adh: Option<f64>,
) {
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
pub(crate) fn elastic_node<H: Phi>(acc: &mut Sums, x: f64, lx: f64, w: f64, dw: f64, adh: bool) -> f64 {
    let p = x * x.sqrt();
    add_node::<H>(acc, p, 1.5 * x.sqrt(), x, lx, w, dw, adh.then_some(adhesion::ELASTIC.1));
    p
}

impl Integrator {
    /// The elastic regime `0 ≤ x < 1` without friction: the Hertz load and
    /// the elastic adhesion (the default of [`ContactLaw::elastic`](crate::model::laws::ContactLaw::elastic)).
    pub(crate) fn elastic_hertz<H: Phi>(&self, h: &H, d: f64, win: Window, adh: bool) -> Sums {
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
    pub(crate) fn elastic_first_panel<H: Phi>(&self, h: &H, d: f64, x1: f64, adh: bool, acc: &mut Sums) {
        if H::GENERAL {
            let b = HERTZ.1;
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
        self.jacobi_panel(h, d, &self.rules.gj_load, HERTZ.1, x1, |_, w, dw| {
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

    /// The non-contact adhesion integral `J_nc` (MODEL.md §4) and its
    /// d*-derivative, in the gap `g = d* − z* ≥ 0`.
    pub(crate) fn noncontact<H: Phi>(&self, h: &H, d: f64) -> (f64, f64) {
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
    pub(crate) fn panels<H: Phi>(&self, h: &H, d: f64, win: Window, xa: f64, xc: f64, mut f: impl FnMut(Panel)) {
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
    pub(crate) fn legendre_panel<H: Phi>(&self, h: &H, d: f64, p: Panel, mut f: impl FnMut(f64, f64, f64)) {
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
    pub(crate) fn jacobi_panel<H: Phi>(
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
