#!/usr/bin/env python3
"""Independent high-precision reference (Python + mpmath) for the Kogut-Etsion
(2004) static friction model with NON-GAUSSIAN asperity-height densities, as
specified in MODEL.md section 9 (sections 1-4 for the model itself).  Test
oracle for the Rust crate; it shares no code with it and imports nothing from
it.  tools/reference.py (the Gaussian reference) supplies the
single-asperity laws and is used by `check` to confirm that the two
references agree in the Gaussian case.

Usage (from the repository root):

    python3 tools/nongaussian_reference.py check
        self-checks (see cmd_check); prints one summary line at the end,
        exits non-zero on any failure.  -v prints every check.
    python3 tools/nongaussian_reference.py points > tests/data/nongaussian_reference.json
        reference mu and h* at ~40 (psi, theta, F*, distribution) points.
    python3 tools/nongaussian_reference.py mu PSI THETA FSTAR DIST [SK [K]]
        one point (DIST = gaussian | pearson | weibull), debugging aid.

What it computes
----------------
phi*(z*) = g(z*/s)/s with g a standardised density (mean 0, variance 1)
(MODEL.md section 9: the surface's Sk, K are applied to the asperity heights;
s = sigma_s/sigma and y_s* unchanged from section 2):

* Gaussian: g = exp(-x^2/2)/sqrt(2 pi).
* Pearson(Sk, K), K not excess, admissible iff K > Sk^2 + 1.  Coefficients,
  type rules, supports and closed forms of ln g(x) - ln g(0) exactly as in the
  section-9 table (types 0 normal, I (incl. J- and U-shaped), II, III, IV, V,
  VI, VII); roots without cancellation; normalisation by quadrature.
* Weibull(Sk): W ~ Weibull(k, 1) standardised, k from Sk by a bracketed
  monotone root; admissible -1.1395 < Sk <= 2 (the section-9 bounds).
* Model (section 4, fit "consistent" of section 6): P*, Fs* (incl. J_nc), Q*,
  F* = P* - Fs*, mu = Q*/F*; F*(h*) = F solved on the decreasing branch.

Numerics (section 9 "numerical traps")
--------------------------------------
* Working precision mp.dps = 30.  Every integral is a sum of tanh-sinh pieces
  (mpmath.quad) split at the regime boundaries x = 0, 1, x0, 6, 110, at the
  support ends, at the mode / antimode -A0/A1, at z = k*s (|k| <= 16, then
  24, 32, 48, ...), and, for J_nc, at d* - k*eps* (k = 1, 3, 10, 30, ...).
  Each piece's error estimate must be below 1e-24 of the sum of |pieces|,
  otherwise it is bisected.
* Bounded supports: a piece next to a finite support end (or next to z* = d*
  where x^b is singular) is integrated in the distance tau to that end, and
  the density is evaluated from that distance directly (ln of the distance,
  never ln(1 - x/r) of a rounded x).  Where g ~ tau^m with m < 0 (J- or
  U-shaped type I/II) the piece is mapped by tau = L*u^n, n = ceil(1/(m+1)),
  which makes the integrand bounded and smooth in u; x^b (b < 1) at x = 0 and
  the m > 0 ends are handled by tanh-sinh directly.  (This plays the role of
  the Gauss-Jacobi weight suggested in section 9; moments of J-shaped
  densities come out to ~1e-31.)
* mpmath's error estimate is absolute, so every integral is rescaled to order
  one before quadrature (as in tools/reference.py).
* Unbounded supports are integrated to infinity (no 12-sigma cut) except on
  light (exponential or Gaussian) tails, which are cut where the density has
  dropped by exp(-120) below its value at the start of the domain.
* Near-degenerate closed forms (near the Gaussian point, near the gamma line
  B2 = 0, near the type-V line D = 0) are evaluated with guard digits:
  10 + log10(B0/|B2|) + log10(B0^2/|D|) extra decimal digits (the coefficients
  are computed from the exact binary values of the inputs at that precision).
  Type III is taken iff |B2| <= 2^(10-prec)*B0, type V iff
  |D| <= 2^(10-prec)*B0^2 (prec = working precision in bits, ~1e-28): inputs
  are the exact binary doubles given, so (0.5, 3.375) is type III exactly,
  while (0.4, 3.24) is a type I/VI pair 1e-16 off the gamma line.
* Root of F*(h*) = F: bracket (steps of 0.5 in h*) + Anderson-Bjorck at
  dps = 15, then secant refinement at dps = 30 to |dh*| < 1e-22.

Precision: h* and mu agree to ~1e-20 relative between dps 30 and 45 (checked
by `check`), far below the doubles written out.

JSON written by `points`: a list of objects
  {"psi", "theta", "f_star", "distribution": "gaussian"|"pearson"|"weibull",
   "skewness", "kurtosis" (not excess; Weibull: the K implied by its Sk;
   Gaussian: 0 and 3), "h_star", "mu", "pearson_type" ("0","I","II","III",
   "IV","V","VI","VII"; null unless distribution is "pearson")}
beta = 0.04, nu = 0.3, eps* = 0.004 throughout.  Inputs are the exact doubles
listed; outputs float(mpf), round-to-nearest, written with repr.
"""

import json
import math
import random
import sys
import time

from mpmath import mp, mpf

# The single-asperity laws are the Gaussian reference's (tools/reference.py,
# beside this file): only the height density and its integrals are new here.
sys.path.insert(0, __import__("os").path.dirname(__file__))
from reference import D, NoSolution, Params, dispatch, mu_ep, solve_decreasing, x0  # noqa: E402
# The densities and the quadrature, beside this file.
from nongaussian_densities import Gaussian, Pearson, Weibull, make_density  # noqa: E402
from nongaussian_quadrature import integrate  # noqa: E402

mp.dps = 30

# ==========================================================================
# the model (MODEL.md sections 2-4, fit "consistent")
# ==========================================================================
class Model:
    def __init__(self, psi, theta, dens, beta=0.04, nu=0.3, eps_star=0.004):
        # The inputs and the quantities derived from them (psi, theta, beta,
        # nu, eps, K, s, ys, wc, r) are the Gaussian reference's (its
        # Params, MODEL.md sections 1-2); only the density is new here.
        vars(self).update(vars(Params(psi, theta, beta, nu, eps_star)))
        self.dens = dens
        self.logZs = dens.logZ + mp.log(self.s)    # phi = g(z/s)/s

    def d_of_h(self, h):
        return mpf(h) - self.ys

    def I(self, d, wx, a, c):
        """int over x in [a, c] of wx(x) phi(z) dz, x = (z - d)/wc"""
        wc = self.wc
        zA = d + a * wc
        zB = d + c * wc if c != mp.inf else mp.inf
        return integrate(self.dens, self.s, lambda e: wx(e / wc), zA, zB, d,
                         logZ=self.logZs)

    def Ipow(self, d, b, a, c):
        b = mpf(b)
        return self.I(d, lambda x: x ** b, a, c)

    def J_nc(self, d):
        eps = self.eps
        extra = []
        k = 1
        while k * eps < 40:
            extra += [d - k * eps, d - 3 * k * eps]
            k *= 10

        def w(e):
            u = 1 - e / eps
            u2 = 1 / (u * u)
            return u2 - u2 ** 4 / 4
        return D(4) / 3 * integrate(self.dens, self.s, w, -mp.inf, d, d, extra,
                                    logZ=self.logZs)

    def pref(self):
        return D(2) / 3 * mp.pi * self.beta * self.K * self.wc

    def p_star(self, d):
        return self.pref() * (self.Ipow(d, D('1.5'), 0, 1)
                              + D('1.03') * self.Ipow(d, D('1.425'), 1, 6)
                              + D('1.40') * self.Ipow(d, D('1.263'), 6, 110)
                              + 3 / self.K * self.Ipow(d, 1, 110, mp.inf))

    def fs_star(self, d):
        if self.theta == 0:
            return mpf(0)
        r = self.r
        br = (D('0.98') * r ** D('-0.29') * self.Ipow(d, D('0.298'), 0, 1)
              + D('0.79') * r ** D('-0.321') * self.Ipow(d, D('0.356'), 1, 6)
              + D('1.19') * r ** D('-0.332') * self.Ipow(d, D('0.093'), 6, 110)
              + self.J_nc(d))
        return 2 * mp.pi * self.beta * self.theta * br

    def q_star(self, d):
        b = D('1.425')
        el = D('0.52') * self.Ipow(d, D('0.982'), 0, 1)
        ep = D('1.03') * self.I(d, lambda x: x ** b * mu_ep(x), 1, x0())
        return self.pref() * (el + ep)

    def f_star(self, h):
        d = self.d_of_h(h)
        return self.p_star(d) - self.fs_star(d)

    def evaluate(self, h):
        d = self.d_of_h(h)
        P = self.p_star(d)
        Fs = self.fs_star(d)
        Q = self.q_star(d)
        F = P - Fs
        return dict(d_star=d, p_star=P, fs_star=Fs, q_star=Q, f_star=F,
                    mu=Q / F if F > 0 else None)


def _solve_bracket(g, h_lo=-8, h_hi=12, tol=None):
    """root of the decreasing g on the positive branch (reference.py's
    search: steps of 0.5 from h = 0, then Anderson-Bjorck)"""
    return solve_decreasing(g, tol,
                            lambda h: 'h* > %s' % h_hi if h > h_hi else None,
                            lambda h: 'h* < %s' % h_lo if h < h_lo else None)


def solve_mu(psi, theta, dist, sk=None, K=None, f=None, dps=30, coarse=True, beta=0.04, nu=0.3, eps_star=0.004):
    """h* with F*(h*) = f and the model values there (constants beta, nu,
    eps_star: the paper's by default).  Returns (h, res, dens)."""
    fm = None
    h0 = None
    if coarse:
        with mp.workdps(15):
            dens = make_density(dist, sk, K)
            m = Model(psi, theta, dens, beta, nu, eps_star)
            fm = mpf(f)
            h0 = _solve_bracket(lambda h: m.f_star(h) - fm, tol=mpf('1e-11'))
    with mp.workdps(dps):
        dens = make_density(dist, sk, K)
        m = Model(psi, theta, dens, beta, nu, eps_star)
        fm = mpf(f)
        g = lambda h: m.f_star(h) - fm
        tol = mpf(10) ** (-(dps - 8))
        if h0 is None:
            h = _solve_bracket(g, tol=tol)
        else:
            # secant refinement from the dps-15 root
            a, b = mpf(h0), mpf(h0) + mpf('1e-9')
            ga, gb = g(a), g(b)
            h = None
            for _ in range(12):
                if gb == ga:
                    h = b
                    break
                c = b - gb * (b - a) / (gb - ga)
                a, ga = b, gb
                b = c
                gb = g(b)
                if abs(b - a) < tol:
                    h = b
                    break
            if h is None or abs(b - mpf(h0)) > mpf('1e-6'):
                # fall back to the safe bracketing solver
                h = _solve_bracket(g, tol=tol)
        res = m.evaluate(h)
        res['h_star'] = h
        return h, res, dens


# ==========================================================================
# check
# ==========================================================================
class Checker:
    def __init__(self, verbose):
        self.n = 0
        self.fail = []
        self.verbose = verbose
        self.worst = {}

    def ok(self, group, label, cond, info=''):
        self.n += 1
        if not cond:
            self.fail.append(label)
        if self.verbose or not cond:
            print('  %-4s %-12s %s %s' % ('ok' if cond else 'FAIL', group, label, info),
                  flush=True)

    def rel(self, group, label, a, b, tol):
        r = abs(a - b) / abs(b) if b != 0 else abs(a)
        self.worst[group] = max(self.worst.get(group, mpf(0)), r)
        self.ok(group, label, r <= tol, '%s vs %s rel %.2e (tol %.0e)'
                % (mp.nstr(a, 15), mp.nstr(b, 15), float(r), float(tol)))
        return r


# (Sk, K, expected type) covering every type of the section-9 table
PEARSON_CASES = [
    (0.0, 3.0, '0'),
    (0.3, 2.7, 'I'),
    (0.8, 2.5, 'I'),            # J-shaped
    (-0.8, 2.5, 'I'),           # J-shaped, mirrored
    (0.0, 1.8, 'II'),           # U-shaped symmetric beta
    (0.0, 2.5, 'II'),
    (0.5, 3.375, 'III'),        # gamma line, exact in binary
    (-0.5, 3.375, 'III'),
    (0.8, 4.1, 'VI'),
    (-0.6, 3.6, 'VI'),
    (0.3, 5.0, 'IV'),
    (-0.8, 8.0, 'IV'),
    (0.0, 8.0, 'VII'),
    (0.0, 4.0, 'VII'),
]


def type_v_kurtosis(sk):
    """K on the type-V line D = 0 for this Sk (the root above the gamma line)"""
    sk = mpf(sk)

    def Dfun(K):
        S2 = sk * sk
        return (sk * (K + 3)) ** 2 - 4 * (4 * K - 3 * S2) * (2 * K - 3 * S2 - 6)
    lo = 3 + D('1.5') * sk ** 2 + mpf('1e-12')   # D > 0 just above the gamma line
    hi = lo
    while Dfun(hi) > 0:
        hi = 3 + (hi - 3) * 2
    return mp.findroot(Dfun, (lo, hi), solver='anderson')


def cmd_check(verbose=False):
    t0 = time.time()
    ck = Checker(verbose)
    tol_mom = mpf('1e-12')

    # ---- 1. moments of every Pearson type, and the closed forms vs -int (A1t+A0)/B
    vline = []
    for skv in ('0.6', '-0.4'):
        with mp.workdps(60):
            Kv = type_v_kurtosis(mpf(skv))
        vline.append((mpf(skv), +Kv, 'V'))
    cases = [(mpf(a), mpf(b), t) for a, b, t in PEARSON_CASES] + vline
    # near-degenerate pairs (guard digits): near Gaussian, near gamma line, near V
    near = [(mpf('1e-7'), 3 + mpf('2e-7'), None), (mpf('-1e-7'), 3 - mpf('1e-7'), None),
            (mpf('0.5'), mpf('3.375') - mpf('1e-9'), 'I'),
            (mpf('0.5'), mpf('3.375') + mpf('1e-9'), 'VI'),
            (vline[0][0], vline[0][1] - mpf('1e-9'), 'VI'),
            (vline[0][0], vline[0][1] + mpf('1e-9'), 'IV')]
    for sk, K, t in cases + near:
        dn = Pearson(sk, K)
        lab = 'Pearson(%s, %s)' % (mp.nstr(sk, 8), mp.nstr(K, 12))
        if t is not None:
            ck.ok('type', lab + ' type ' + t, dn.ptype == t, 'got %s' % dn.ptype)
        m0, mean, var, sk_q, K_q = dn.moments()
        ck.ok('moments', lab + ' [%s] mass/mean/var/Sk/K' % dn.ptype,
              abs(m0 - 1) < tol_mom and abs(mean) < tol_mom and abs(var - 1) < tol_mom
              and abs(sk_q - sk) < tol_mom and abs(K_q - K) < tol_mom,
              'dev %.1e %.1e %.1e %.1e %.1e' % tuple(float(abs(v)) for v in
                                                     (m0 - 1, mean, var - 1, sk_q - sk, K_q - K)))
        worst = max(abs(m0 - 1), abs(mean), abs(var - 1), abs(sk_q - sk), abs(K_q - K))
        ck.worst['moments'] = max(ck.worst.get('moments', mpf(0)), worst)
        # closed form of ln g(x) - ln g(0) against -int_0^x (A1 t + A0)/B(t) dt
        # at 50 digits (independent of the type formulas)
        if dn.ptype != '0':
            lo = dn.lo if dn.lo != -mp.inf else mpf(-6)
            hi = dn.hi if dn.hi != mp.inf else mpf(6)
            wmax = mpf(0)
            for fr in ('0.003', '0.2', '0.5', '0.8', '0.997'):
                x = lo + (hi - lo) * mpf(fr)
                l0 = dn.logg(mpf(0), -dn.lo, dn.hi)
                lx = dn.logg(x, x - dn.lo, dn.hi - x)
                with mp.workdps(50):
                    A1, A0, B0, B1, B2 = [mpf(v) for v in (dn.A1, dn.A0, dn.B0, dn.B1, dn.B2)]
                    ex = -mp.quad(lambda t: (A1 * t + A0) / (B0 + B1 * t + B2 * t * t), [0, x])
                wmax = max(wmax, abs((lx - l0) - ex) / max(1, abs(ex)))
            ck.ok('closedform', lab + ' [%s] ln g closed form vs integral' % dn.ptype,
                  wmax < mpf('1e-20'), '%.1e' % float(wmax))
            ck.worst['closedform'] = max(ck.worst.get('closedform', mpf(0)), wmax)
    # J-shaped really J-shaped
    dj = Pearson(0.8, 2.5)
    ck.ok('type', 'Pearson(0.8, 2.5) J-shaped (g -> inf at an end)',
          any(m < 0 for m in dj.ends.values()), str({k: mp.nstr(v, 6) for k, v in dj.ends.items()}))

    # ---- Weibull
    wb0 = Weibull(0.0)
    ck.rel('weibull', 'k(Sk=0) = 3.6023494257', wb0.k, mpf('3.6023494257'), mpf('3e-11'))
    ck.rel('weibull', 'K(Sk=0) = 2.717', wb0.K, mpf('2.717'), mpf('2e-4'))
    for skv in (2.0, 0.8, 0.0, -0.5, -1.0):
        wb = Weibull(skv)
        m0, mean, var, sk_q, K_q = wb.moments()
        ck.ok('moments', 'Weibull(Sk=%s) k=%s mass/mean/var/Sk/K' % (skv, mp.nstr(wb.k, 10)),
              abs(m0 - 1) < tol_mom and abs(mean) < tol_mom and abs(var - 1) < tol_mom
              and abs(sk_q - skv) < tol_mom and abs(K_q - wb.K) < tol_mom,
              'dev %.1e %.1e %.1e %.1e %.1e' % tuple(float(abs(v)) for v in
                                                     (m0 - 1, mean, var - 1, sk_q - skv, K_q - wb.K)))

    # ---- validation messages
    for args, frag in (((0.9, 1.5), 'Sk^2 + 1'), ((0.0, 1.0), 'Sk^2 + 1')):
        try:
            Pearson(*args)
            ck.ok('validate', 'Pearson%r rejected' % (args,), False)
        except ValueError as e:
            ck.ok('validate', 'Pearson%r rejected' % (args,), frag in str(e), str(e))
    for skv in (-1.2, -1.1395, 2.1):
        try:
            Weibull(skv)
            ck.ok('validate', 'Weibull(%r) rejected' % skv, False)
        except ValueError as e:
            ck.ok('validate', 'Weibull(%r) rejected' % skv, '-1.1395 < Sk <= 2' in str(e), str(e))

    # ---- 2. Pearson(0, 3) == Gaussian; Gaussian == tools/reference.py
    import os
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import reference as gref
    g = Gaussian()
    p03 = Pearson(0, 3)
    for psi, th, h in ((0.5, 0.003, 1.0), (1.0, 0.001, 2.0), (4.0, 0.0003, 3.0)):
        mg = Model(psi, th, g).evaluate(mpf(h))
        mp_ = Model(psi, th, p03).evaluate(mpf(h))
        # mu = Q/F does not depend on the normalisation; P* does
        for k in ('p_star', 'mu'):
            ck.rel('pearson03', 'Pearson(0,3) %s = Gaussian %s psi=%s th=%s h=%s'
                   % (k, k, psi, th, h), mp_[k], mg[k], mpf('1e-12'))
        rg = gref.evaluate('ke', 'consistent', gref.Params(psi, th), mpf(h))
        for k in ('p_star', 'fs_star', 'q_star', 'mu'):
            ck.rel('vs_reference', 'Gaussian %s = reference.py psi=%s th=%s h=%s' % (k, psi, th, h),
                   mg[k], rg[k], mpf('1e-20'))
    # MODEL.md section 7 solved row
    h, r, _ = solve_mu(1.0, 0.001, 'gaussian', f=0.01)
    ck.rel('section7', 'Gaussian h*(psi=1, th=1e-3, F=0.01)', h, mpf('1.4692414618'), mpf('1e-10'))
    ck.rel('section7', 'Gaussian mu(psi=1, th=1e-3, F=0.01)', r['mu'], mpf('5.2521087083e-01'),
           mpf('1e-10'))
    ck.rel('section7', 'F*(h*) - F (F the double 0.01)', r['f_star'], mpf(0.01), mpf('1e-20'))
    # near-Gaussian Pearson is continuous (closed forms with guard digits)
    mg = Model(1.0, 0.001, g).evaluate(mpf(2))['mu']
    for sk, K in ((1e-7, 3 + 2e-7), (-1e-7, 3 - 1e-7)):
        mn = Model(1.0, 0.001, Pearson(sk, K)).evaluate(mpf(2))['mu']
        ck.rel('continuity', 'near-Gaussian Pearson(%g, 3%+g) mu ~ Gaussian' % (sk, K - 3),
               mn, mg, mpf('1e-5'))
    # continuity across the gamma line and the V line (mu at fixed h*)
    for (sk, K) in ((0.5, 3.375), (float(vline[0][0]), float(vline[0][1]))):
        vals = [Model(1.0, 0.001, Pearson(sk, K + dk)).evaluate(mpf('2.5'))['mu']
                for dk in (-1e-10, 0.0, 1e-10)]
        types = [Pearson(sk, K + dk).ptype for dk in (-1e-10, 0.0, 1e-10)]
        spread = max(abs(v - vals[1]) for v in vals) / vals[1]
        ck.ok('continuity', 'mu continuous across Pearson(%g, %.10g) types %s' % (sk, K, types),
              spread < mpf('1e-7'), 'spread %.1e' % float(spread))

    # ---- 3. precision: dps 30 vs 45 at stress points
    stress = [('pearson', 0.8, 2.5, 0.5, 0.003, 1.0),   # J-shaped, bounded, d near end
              ('pearson', -0.8, 2.5, 2.0, 0.001, 1.5),
              ('pearson', 0.0, 8.0, 1.0, 0.001, 4.5),  # heavy tails, large h
              ('pearson', -0.5, 3.375, 1.0, 0.001, 3.0),
              ('weibull', -0.8, None, 1.0, 0.003, 2.0)]
    for dist, sk, K, psi, th, h in stress:
        vals = []
        for dps in (30, 45):
            with mp.workdps(dps):
                vals.append(Model(psi, th, make_density(dist, sk, K)).evaluate(mpf(h)))
        worst = max(abs(vals[0][k] - vals[1][k]) / abs(vals[1][k])
                    for k in ('p_star', 'fs_star', 'q_star', 'f_star'))
        ck.worst['dps30_vs_45'] = max(ck.worst.get('dps30_vs_45', mpf(0)), worst)
        ck.ok('precision', '%s(%s,%s) psi=%s th=%s h=%s dps30 vs 45' % (dist, sk, K, psi, th, h),
              worst < mpf('1e-20'), '%.1e' % float(worst))

    # ---- 4. the issue's values (psi = 1, theta = 0.001, F* = 1e-4)
    issue = []
    for dist, sk, K, quoted in (('gaussian', None, None, '0.7567'),
                                ('pearson', 0.0, 8.0, '0.2529'),
                                ('pearson', -0.5, 3.375, '1.00')):
        h, r, dn = solve_mu(1.0, 0.001, dist, sk, K, f=1e-4)
        q = mpf(quoted)
        digits = len(quoted.split('.')[1])
        agree = abs(r['mu'] - q) <= mpf(5) * mpf(10) ** (-digits - 1) * (1 + mpf('1e-9'))
        lab = '%s(%s,%s)' % (dist, sk, K) if dist != 'gaussian' else 'gaussian'
        issue.append('%s mu=%s h*=%s [%s]' % (lab, mp.nstr(r['mu'], 10), mp.nstr(h, 10),
                                              dn.ptype or '-'))
        ck.ok('issue', 'issue value %s: mu = %s (quoted %s) h* = %s' % (
            lab, mp.nstr(r['mu'], 12), quoted, mp.nstr(h, 12)), agree)

    dt = time.time() - t0
    worst = ' '.join('%s=%.1e' % (k, float(v)) for k, v in sorted(ck.worst.items()))
    print('%s: %d checks, %d failed%s; issue values (psi=1, theta=1e-3, F*=1e-4): %s; '
          'max rel dev: %s; %.0f s' % (
              'PASS' if not ck.fail else 'FAIL', ck.n, len(ck.fail),
              (' (' + ', '.join(ck.fail) + ')') if ck.fail else '', '; '.join(issue),
              worst, dt))
    return 0 if not ck.fail else 1


# ==========================================================================
# points
# ==========================================================================
def _loguni(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def point_list():
    """(distribution, Sk, K, label) and the seeded (psi, theta, F*) draws"""
    # type-V line at Sk = 0.6 / -0.4 (as doubles) for near-V pairs
    with mp.workdps(40):
        kv1 = float(type_v_kurtosis(0.6))
        kv2 = float(type_v_kurtosis(-0.4))
    dists = [
        ('gaussian', 0.0, 3.0), ('gaussian', 0.0, 3.0), ('gaussian', 0.0, 3.0),
        ('pearson', 0.0, 3.0),                       # type 0 through the Pearson path
        ('pearson', 0.3, 2.7), ('pearson', -0.4, 2.9),           # I
        ('pearson', 0.8, 2.5), ('pearson', -0.8, 2.5),           # I, J-shaped
        ('pearson', 0.7, 2.6), ('pearson', -0.75, 2.6),          # I, J-shaped
        ('pearson', 0.0, 2.5), ('pearson', 0.0, 2.8),            # II
        ('pearson', 0.5, 3.375), ('pearson', -0.5, 3.375),       # III (exact)
        ('pearson', 0.75, 3.84375), ('pearson', -0.25, 3.09375),  # III (exact)
        ('pearson', 0.5, 3.375 - 1e-3), ('pearson', 0.5, 3.375 + 1e-3),   # I | VI
        ('pearson', -0.5, 3.375 - 1e-7), ('pearson', -0.5, 3.375 + 1e-7),  # I | VI
        ('pearson', 0.8, 4.1), ('pearson', -0.6, 3.6),           # VI
        ('pearson', 0.6, kv1 - 1e-4), ('pearson', 0.6, kv1 + 1e-4),   # near V: VI | IV
        ('pearson', -0.4, kv2 - 1e-8), ('pearson', -0.4, kv2 + 1e-8),  # near V: VI | IV
        ('pearson', 0.3, 5.0), ('pearson', -0.8, 8.0),           # IV
        ('pearson', 0.8, 8.0), ('pearson', -0.3, 6.0),           # IV
        ('pearson', 0.0, 8.0), ('pearson', 0.0, 5.0),            # VII
        ('weibull', 0.0, None), ('weibull', 0.5, None),
        ('weibull', -0.5, None), ('weibull', -0.8, None),
    ]
    rng = random.Random(20261209)
    out = []
    for dist, sk, K in dists:
        psi = _loguni(rng, 0.5, 4)
        theta = _loguni(rng, 1e-4, 3e-3)
        f = _loguni(rng, 1e-4, 0.05)
        out.append((psi, theta, f, dist, sk, K))
    # the issue's three points
    out += [(1.0, 0.001, 1e-4, 'gaussian', 0.0, 3.0),
            (1.0, 0.001, 1e-4, 'pearson', 0.0, 8.0),
            (1.0, 0.001, 1e-4, 'pearson', -0.5, 3.375)]
    return out


def cmd_points():
    t0 = time.time()
    pts = []
    for psi, theta, f, dist, sk, K in point_list():
        t1 = time.time()
        try:
            h, r, dn = solve_mu(psi, theta, dist, sk if dist != 'gaussian' else None,
                                K if dist == 'pearson' else None, f=f)
        except NoSolution as e:
            print('skip %s(%s,%s) psi=%r theta=%r F=%r: %s' % (dist, sk, K, psi, theta, f, e),
                  file=sys.stderr)
            continue
        if r['mu'] is None or abs(r['f_star'] / mpf(f) - 1) > mpf('1e-18'):
            print('skip (residual) %s(%s,%s) psi=%r theta=%r F=%r' % (dist, sk, K, psi, theta, f),
                  file=sys.stderr)
            continue
        rec = dict(psi=psi, theta=theta, f_star=f, distribution=dist,
                   skewness=float(dn.sk) if dist != 'gaussian' else 0.0,
                   kurtosis=float(dn.K) if dist != 'gaussian' else 3.0,
                   h_star=float(h), mu=float(r['mu']),
                   pearson_type=dn.ptype if dist == 'pearson' else None)
        if dist == 'pearson':
            rec['skewness'], rec['kurtosis'] = sk, K      # the exact input doubles
        pts.append(rec)
        print('[%6.1f s, %5.1f s] %-8s Sk=%-6s K=%-20r type=%-4s psi=%.4g th=%.3g F=%.3g '
              'h*=%.10f mu=%.10g' % (time.time() - t0, time.time() - t1, dist, rec['skewness'],
                                     rec['kurtosis'], rec['pearson_type'] or '-', psi, theta,
                                     f, rec['h_star'], rec['mu']), file=sys.stderr, flush=True)
    sys.stdout.write('[\n' + ',\n'.join(' ' + json.dumps(p) for p in pts) + '\n]\n')
    print('wrote %d points in %.0f s' % (len(pts), time.time() - t0), file=sys.stderr)
    return 0


def cmd_mu(args):
    psi, theta, f, dist = float(args[0]), float(args[1]), float(args[2]), args[3]
    sk = float(args[4]) if len(args) > 4 else None
    K = float(args[5]) if len(args) > 5 else None
    t0 = time.time()
    h, r, dn = solve_mu(psi, theta, dist, sk, K, f=f)
    print('type', dn.ptype, 'lo', mp.nstr(dn.lo, 10), 'hi', mp.nstr(dn.hi, 10))
    print('h_star', h)
    for k, v in r.items():
        print(k, v)
    print('%.1f s' % (time.time() - t0))
    return 0


def main(argv):
    return dispatch(argv, __doc__, {
        'check': lambda args: cmd_check('-v' in args),
        'points': lambda args: cmd_points(),
        'mu': cmd_mu,
    })


if __name__ == '__main__':
    sys.exit(main(sys.argv))
