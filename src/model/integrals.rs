//! The surface integrals of MODEL.md §4 (Kogut–Etsion) and §8 (CEB-type)
//! for one contact law, summed over its regimes ([`Integrals`]; not to be
//! confused with a measured surface, `topography::Surface`).
//!
//! The law's elastic regime comes from the law ([`ContactLaw::elastic`]),
//! the regimes above it from [`ContactLaw::regimes`] by the shared
//! `smooth` integral; the panels, rules and height densities are the
//! law-independent [`Integrator`]'s.

use super::asperity::adhesion;
use super::integrator::{add_node, Heights, Integrator, Phi, PhiVisitor, Sums, Window};
use super::laws::{ContactLaw, Law, LawVisitor, LoadLaw, Regime};
use crate::params::{hardness_coefficient, Params};

/// The planned integrals of a rough surface: its contact law and the
/// integrals' machinery.
#[derive(Debug, Clone)]
pub(crate) struct Integrals {
    /// The planned single-asperity law.
    law: Law,
    /// The panels, rules and height density.
    grid: Integrator,
    /// y_s* = h* − d*.
    pub ys: f64,
    /// (2/3)πβKω_c*, in front of P* and Q*.
    load_pref: f64,
    /// 2πβθ, in front of Fs*.
    adh_pref: f64,
}

impl Integrals {
    /// The fraction of the asperities in contact at separation `d` (d*)
    /// ([`Integrator::contact_fraction`]).
    pub fn contact_fraction(&self, d: f64) -> f64 {
        self.grid.contact_fraction(d)
    }

    /// Plans the integrals for valid parameters.
    pub fn new(p: &Params) -> Integrals {
        let pi = core::f64::consts::PI;
        let grid = Integrator::new(p);
        let k = hardness_coefficient(p.constants.nu);
        Integrals {
            law: Law::new(&p.constants),
            ys: 1.0 / (4.0 * 3f64.sqrt() * pi * p.constants.beta),
            load_pref: (2.0 / 3.0) * pi * p.constants.beta * k * grid.omega,
            adh_pref: 2.0 * pi * p.constants.beta * p.theta,
            grid,
        }
    }

    /// P*, Fs* (with their d*-derivatives) and, if `want_q`, Q* at `d`:
    /// one `match` on the law, then static calls.
    pub fn evaluate(&self, d: f64, want_q: bool) -> Sums {
        struct Evaluate<'a> {
            s: &'a Integrals,
            d: f64,
            want_q: bool,
        }
        impl LawVisitor for Evaluate<'_> {
            type Out = Sums;
            #[inline(always)]
            fn visit<L: ContactLaw>(self, law: &L) -> Sums {
                self.s.evaluate_law(law, self.d, self.want_q)
            }
        }
        self.law.visit(Evaluate { s: self, d, want_q })
    }

    /// [`evaluate`](Self::evaluate) with the law `law`.
    #[inline(always)]
    pub(super) fn evaluate_law<L: ContactLaw>(&self, law: &L, d: f64, want_q: bool) -> Sums {
        match &self.grid.heights {
            Heights::Gauss(h) => self.evaluate_with(law, h, d, want_q),
            Heights::General(h) => {
                struct With<'a, L> {
                    s: &'a Integrals,
                    law: &'a L,
                    d: f64,
                    want_q: bool,
                }
                impl<L: ContactLaw> PhiVisitor for With<'_, L> {
                    type Out = Sums;
                    #[inline(always)]
                    fn visit<H: Phi>(self, h: &H) -> Sums {
                        self.s.evaluate_with(self.law, h, self.d, self.want_q)
                    }
                }
                h.visit(With {
                    s: self,
                    law,
                    d,
                    want_q,
                })
            }
        }
    }

    #[inline(always)]
    fn evaluate_with<L: ContactLaw, H: Phi>(&self, law: &L, h: &H, d: f64, want_q: bool) -> Sums {
        let win = h.window(d);
        let mut c = self.contact(law, h, d, win, want_q);
        if self.adh_pref != 0.0 {
            let (j, dj) = self.grid.noncontact(h, d);
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
    pub(super) fn contact<L: ContactLaw, H: Phi>(&self, law: &L, h: &H, d: f64, win: Window, want_q: bool) -> Sums {
        let adh = self.adh_pref != 0.0;
        let el = law.elastic(&self.grid, h, d, win, adh, want_q);
        let c = &self.grid.adh_coef;
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
        let c = &self.grid.adh_coef;
        for j in law.jumps() {
            let phi = h.phi(d + self.grid.omega * j.x);
            let [(r0, f0), (r1, f1)] = j.adhesion;
            sums.dp += (j.load[0] - j.load[1]) * phi;
            sums.dfs += (c[r0] * f0 - c[r1] * f1) * phi;
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
        self.grid.panels(h, d, win, xa, xc, |p| {
            self.grid.legendre_panel(h, d, p, |x, w, dw| {
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Constants;
    use serde_json::Value;

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
        let integrals = Integrals::new(&Params::new(f("psi"), 0.0).beta(f("beta")));
        let s = integrals.evaluate_law(&Hertz::new(), f("d_star"), true);
        let want = integrals.load_pref * f("i_0_inf");
        assert!(s.p.is_finite() && s.p > 0.0 && s.dp < 0.0, "{s:?}");
        assert!(((s.p - want) / want).abs() < 1e-12, "P* = {:e} vs {want:e}", s.p);
        assert_eq!((s.fs, s.q), (0.0, 0.0));

        let gaussian = Constants::default();
        let pearson = Constants::default().distribution(crate::HeightDistribution::pearson(0.0, 2.5).unwrap());
        for c in [gaussian, pearson] {
            let params = c.at(0.1, 0.003).unwrap();
            let integrals = Integrals::new(&params);
            for d in [0.5, 1.0, 2.0] {
                let hertz = integrals.evaluate_law(&Hertz::new(), d, true);
                let ke = integrals.evaluate(d, true);
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

/// A Pearson density infinite at both ends of its support (Sk = 5,
/// K = 27: type I, powers −0.99 and −0.79) whose upper end crosses the
/// law's first regime boundary x = 1 near F* = 7.8e-4 (issue 46: `kefric
/// law` failed there). P*(d*) falls by 0.5 % within Δd* = 1e-4 there (the
/// law's 3 % step at x = 1 times the summits piled at the end): a cusp of
/// the model, which the integrals follow to a brute-force sum.
#[cfg(test)]
mod singular_end {
    use super::*;
    use crate::{Constants, HeightDistribution, Model};

    /// P* across the crossing against a brute-force sum: x = b − (b − a)·u¹⁰
    /// (the end's singularity at x_hi ≥ b tamed), 100,000 midpoints in u,
    /// the density from its distance to the end.
    #[test]
    fn p_star_is_right_finite_and_falling_across_the_crossing() {
        let p = Params::new(1.0, 0.001).distribution(HeightDistribution::pearson(5.0, 27.0).unwrap());
        let it = Integrals::new(&p);
        let g = p.constants.distribution.density().unwrap();
        assert!(g.has_infinite_end());
        let e = g.upper_end().unwrap();
        let s = crate::gw::sigma_s_ratio(p.constants.beta);
        let om = s; // ψ = 1
        let mut last = f64::INFINITY;
        for k in 0..=12 {
            let d = 4.1750 + k as f64 * 0.0002;
            let xh = (e.at * s - d) / om;
            let brute = |a: f64, b: f64, f: &dyn Fn(f64) -> f64| -> f64 {
                if b <= a {
                    return 0.0;
                }
                let n = 100_000;
                let mut sum = 0.0;
                for i in 0..n {
                    let u = (i as f64 + 0.5) / n as f64;
                    let back = (b - a) * u.powi(10);
                    let phi = g.ln_pdf_at_end(e, om * ((xh - b) + back) / s).exp() / s;
                    sum += f(b - back) * phi * om * (b - a) * 10.0 * u.powi(9);
                }
                sum / n as f64
            };
            // Below x_hi ≈ 1: the Hertz load, and the 1st elastic-plastic one.
            let want = it.load_pref
                * (brute(0.0, xh.min(1.0), &|x| x.powf(1.5)) + brute(1.0, xh.min(6.0), &|x| 1.03 * x.powf(1.425)));
            let got = it.evaluate(d, false).p;
            assert!(got.is_finite() && got < last, "d* = {d}: P* = {got:e} after {last:e}");
            assert!(
                (got / want - 1.0).abs() < 1e-9,
                "d* = {d} (x_hi = {xh}): {got:e} vs {want:e}"
            );
            last = got;
        }
    }

    /// μ(F*) by direct integration is finite around the cusp for Sk = 5,
    /// K = 27 and densities beside it (Sk 4 to 5, K from just above the
    /// bound Sk² + 1 to 1.1·Sk² + 1): no NaN, no failed solve.
    #[test]
    fn mu_is_finite_around_the_cusp() {
        for (sk, k) in [(5.0, 27.0), (5.0, 26.01), (4.5, 22.0), (4.0, 17.5), (4.0, 18.6)] {
            let c = Constants::default().distribution(HeightDistribution::pearson(sk, k).unwrap());
            let m = Model::new(c.at(1.0, 0.001).unwrap()).unwrap();
            for f in [7.0e-4, 7.7e-4, 7.8e-4, 7.82e-4, 7.83e-4, 7.9e-4, 1.46e-3, 2e-3] {
                let mu = m.at_f_star(f).unwrap().mu.unwrap();
                assert!(mu.is_finite() && mu > 0.0, "Sk {sk}, K {k}, F* {f}: mu = {mu}");
            }
        }
    }
}
