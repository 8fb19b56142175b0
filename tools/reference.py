#!/usr/bin/env python3
"""Independent high-precision reference implementation (Python + mpmath) of the
Kogut-Etsion (2004) static friction model as specified in MODEL.md, used as a
test oracle for the Rust crate.

Usage (from the repository root):

    python3 tools/reference.py check      # reproduce every reference value of
                                          # MODEL.md sections 7 and 8, plus the
                                          # section-5 closed-form checks; exits
                                          # non-zero on any failure
    python3 tools/reference.py generate   # write tests/data/reference_points.json
                                          # (fixed seed random.Random(20261121))
    python3 tools/reference.py point ke consistent PSI THETA H_STAR
                                          # print one point (debugging aid)

What is implemented (all at mp.dps = 30):

* KE model (MODEL.md section 4), fit "consistent": Q integrates
  1.03 x^1.425 mu_ep(x) over [1, x0], x0 = root of mu_ep (4.2946...);
  fit "as-printed" (section 6, last paragraph): 0.52 in front of both the
  elastic row and the polynomial bracket, polynomial integrated unclipped over
  [1, 6].
* CEB-type model (section 8): P_CEB, Q_CEB with mu_CEB, same Fs.
* Solving F*(h*) = f on the positive branch (bracketing + Anderson-Bjorck,
  |dh| < 1e-22).
* Closed form I^b[0, inf) via the parabolic cylinder function (mpmath.pcfd).

All integrals I^b[a, c] are done in x = (z - d)/omega_c with tanh-sinh
quadrature (mpmath.quad), split at every regime boundary (0, 1, x0, 6, 110), at
z = k*s (every standard deviation, so the Gaussian peak never sits inside a
long interval) and, for J_nc, at t = d - z = k*eps (k = 1, 3, 10, 30, ...).
Gaussian tails are cut where phi is below exp(-120) relative to its largest
value on the integration domain.  The quadrature error estimate of every
sub-interval is checked; intervals that do not converge are bisected.

Output tests/data/reference_points.json: {"generator": str, "points": [...]},
each point one of
  {"model": "ke"|"ceb", "fit": "consistent"|"as-printed"|null (null for ceb),
   "mode": "h"|"f", "psi", "theta", "beta", "nu", "eps_star", "h_star",
   "d_star", "p_star", "fs_star", "q_star", "f_star", "mu" (null if f_star <= 0)}
  (mode "h": h_star is the input; mode "f": f_star is the input target and
  h_star the solved separation, F*(h_star) = f_star to ~1e-20)
  {"kind": "closed_form", "b", "psi", "beta", "d_star",
   "i_0_inf" (pcfd closed form), "i_0_1", "i_1_inf" (quadrature)}
All numbers are doubles (Python repr, round-trip exact).

Inputs are taken as the exact binary value of the Python floats given (so the
Rust side can feed exactly the same doubles); model constants (0.454, 1.03,
3.717e-4, ...) are the exact decimal values.
"""

import json
import math
import random
import sys
import time

import mpmath
from mpmath import mp, mpf

mp.dps = 30

# --------------------------------------------------------------------------
# constants
# --------------------------------------------------------------------------
TAIL_LOG = mpf(120)           # cut Gaussian tails below exp(-120) relative
QUAD_RTOL = mpf(10) ** -24     # accepted relative quadrature error per piece


def D(s):
    return mpf(s)


def mu_ep(x):
    """single-asperity friction coefficient, 1st elastic-plastic regime"""
    return D('0.85') - D('0.40') * x + D('0.09') * x ** 2 - D('0.01') * x ** 3


_X0 = {}


def x0():
    if mp.prec not in _X0:
        _X0[mp.prec] = mp.findroot(mu_ep, mpf('4.2946'))
    return _X0[mp.prec]


class Params:
    """Dimensionless inputs and derived quantities (MODEL.md sections 1, 2)."""

    def __init__(self, psi, theta, beta=0.04, nu=0.3, eps_star=0.004):
        self.psi = mpf(psi)
        self.theta = mpf(theta)
        self.beta = mpf(beta)
        self.nu = mpf(nu)
        self.eps = mpf(eps_star)
        self.K = D('0.454') + D('0.41') * self.nu
        self.s = mp.sqrt(1 - D('3.717e-4') / self.beta ** 2)
        self.ys = 1 / (4 * mp.sqrt(3) * mp.pi * self.beta)
        self.wc = self.s / self.psi ** 2
        self.r = self.eps / self.wc

    def phi(self, z):
        s = self.s
        return mp.exp(-z * z / (2 * s * s)) / (s * mp.sqrt(2 * mp.pi))

    def d_of_h(self, h):
        return mpf(h) - self.ys


# --------------------------------------------------------------------------
# quadrature helpers
# --------------------------------------------------------------------------
def _quad_interval(f, a, b, scale, depth=0):
    """integral over [a, b]; bisect until the error estimate is below
    QUAD_RTOL * scale (scale = magnitude of the whole integral)"""
    v, err = mp.quad(f, [a, b], error=True)
    if err <= QUAD_RTOL * scale:
        return v
    if depth >= 8:
        print("warning: quadrature did not converge on [%s, %s]: v=%s err=%s scale=%s"
              % (mp.nstr(a, 8), mp.nstr(b, 8), mp.nstr(v, 8), mp.nstr(err, 3),
                 mp.nstr(scale, 3)), file=sys.stderr)
        return v
    m = (a + b) / 2
    return (_quad_interval(f, a, m, scale, depth + 1)
            + _quad_interval(f, m, b, scale, depth + 1))


def quad_pts(f, pts):
    """sum of tanh-sinh integrals over consecutive points; every piece must have
    an error estimate below QUAD_RTOL relative to the sum of |pieces|"""
    pts = sorted(set(pts))
    ivs = [(a, b) for a, b in zip(pts, pts[1:]) if b > a]
    # mpmath's tanh-sinh error estimate works on absolute values, so integrate
    # a normalised integrand (integral of order one) and scale back at the end
    S = max(abs(f((a + b) / 2)) * (b - a) for a, b in ivs) if ivs else mpf(0)
    if S == 0:
        return mpf(0)
    g = lambda x: f(x) / S
    return S * _quad_pieces(g, ivs)


def _quad_pieces(f, ivs):
    pieces = [mp.quad(f, [a, b], error=True) for a, b in ivs]
    scale = sum(abs(v) for v, e in pieces)
    if scale == 0:
        return mpf(0)
    tot = mpf(0)
    for (a, b), (v, err) in zip(ivs, pieces):
        if err <= QUAD_RTOL * scale:
            tot += v
        else:
            m = (a + b) / 2
            tot += _quad_interval(f, a, m, scale) + _quad_interval(f, m, b, scale)
    return tot


def z_hi_cut(p, d):
    """upper z beyond which phi is < exp(-TAIL_LOG) relative to max phi on z >= d"""
    zm = max(d, mpf(0))
    return mp.sqrt(zm ** 2 + 2 * p.s ** 2 * TAIL_LOG)


def z_lo_cut(p, d):
    """lower z below which phi is < exp(-TAIL_LOG) relative to max phi on z <= d"""
    zm = min(d, mpf(0))
    return -mp.sqrt(zm ** 2 + 2 * p.s ** 2 * TAIL_LOG)


def gauss_splits_z(p):
    k = int(mp.ceil(mp.sqrt(2 * TAIL_LOG))) + 12
    return [j * p.s for j in range(-k, k + 1)]


def I_weighted(p, d, g, a, c):
    """int_{x=a}^{c} g(x) phi(d + x wc) wc dx   (= I^b[a,c] for g = x^b).
    c may be mp.inf."""
    wc = p.wc
    xcut = (z_hi_cut(p, d) - d) / wc
    c = min(c, xcut) if c != mp.inf else xcut
    a = mpf(a)
    if c <= a:
        return mpf(0)
    pts = [a, c]
    for z in gauss_splits_z(p):
        x = (z - d) / wc
        if a < x < c:
            pts.append(x)

    def f(x):
        return g(x) * p.phi(d + x * wc) * wc
    return quad_pts(f, pts)


def I_pow(p, d, b, a, c):
    b = mpf(b)
    return I_weighted(p, d, lambda x: x ** b, a, c)


def J_nc(p, d):
    """(4/3) int_{-inf}^{d} (u^-2 - u^-8/4) phi(z) dz, u = 1 + (d - z)/eps,
    integrated in t = d - z >= 0."""
    eps = p.eps
    tcut = d - z_lo_cut(p, d)
    pts = [mpf(0), tcut]
    j = 0
    while eps * 10 ** j < tcut:           # k = 1, 3, 10, 30, 100, ...
        for k in (10 ** j, 3 * 10 ** j):
            if k * eps < tcut:
                pts.append(k * eps)
        j += 1
    for z in gauss_splits_z(p):
        t = d - z
        if 0 < t < tcut:
            pts.append(t)

    def f(t):
        u = 1 + t / eps
        u2 = 1 / (u * u)
        return (u2 - u2 ** 4 / 4) * p.phi(d - t)
    return D(4) / 3 * quad_pts(f, pts)


# --------------------------------------------------------------------------
# models
# --------------------------------------------------------------------------
def fs_star(p, d):
    if p.theta == 0:
        return mpf(0)
    r = p.r
    bracket = (D('0.98') * r ** D('-0.29') * I_pow(p, d, D('0.298'), 0, 1)
               + D('0.79') * r ** D('-0.321') * I_pow(p, d, D('0.356'), 1, 6)
               + D('1.19') * r ** D('-0.332') * I_pow(p, d, D('0.093'), 6, 110)
               + J_nc(p, d))
    return 2 * mp.pi * p.beta * p.theta * bracket


def pref(p):
    return D(2) / 3 * mp.pi * p.beta * p.K * p.wc


def p_star_ke(p, d):
    return pref(p) * (I_pow(p, d, D('1.5'), 0, 1)
                      + D('1.03') * I_pow(p, d, D('1.425'), 1, 6)
                      + D('1.40') * I_pow(p, d, D('1.263'), 6, 110)
                      + 3 / p.K * I_pow(p, d, 1, 110, mp.inf))


def q_star_ke(p, d, fit='consistent'):
    el = D('0.52') * I_pow(p, d, D('0.982'), 0, 1)
    b = D('1.425')
    if fit == 'consistent':
        ep = D('1.03') * I_weighted(p, d, lambda x: x ** b * mu_ep(x), 1, x0())
    elif fit == 'as-printed':
        ep = D('0.52') * I_weighted(p, d, lambda x: x ** b * mu_ep(x), 1, 6)
    else:
        raise ValueError(fit)
    return pref(p) * (el + ep)


# ---- CEB-type ----
ZETA = D('0.48')


def _ceb_consts(p):
    nu, z = p.nu, ZETA
    c1 = -1 + D('1.5') * z * mp.atan(1 / z) - z ** 2 / (2 * (1 + z ** 2))
    c3 = 9 * mp.pi ** 2 / 16 * (2 - nu / 2 + 7 * nu ** 2 / 8)
    c4 = 9 * mp.pi / 4 * (1 - 2 * nu) * (1 - nu / 2)
    return c1, c3, c4


def mu_ceb_branches(p, x):
    c1, c3, c4 = _ceb_consts(p)
    c5 = D('1.5') * (1 - 2 * p.nu) ** 2 - D('0.56') / (p.K ** 2 * x)
    mu1 = D('0.2045') / (p.K * abs(c1)) * mp.sqrt(1 / x - 1)
    mu2 = (-c4 + mp.sqrt(c4 ** 2 - 4 * c3 * c5)) / (2 * c3)
    return mu1, mu2


def mu_ceb(p, x):
    if not (0 < x < 1):
        return mpf(0)
    return min(mu_ceb_branches(p, x))


_XC_CACHE = {}


def ceb_cross(p):
    key = (p.nu, mp.prec)
    if key not in _XC_CACHE:
        def g(x):
            m1, m2 = mu_ceb_branches(p, x)
            return m1 - m2
        # scan for sign changes of mu1 - mu2 on (0, 1)
        roots = []
        n = 400
        prev_x, prev_g = None, None
        for i in range(1, n):
            x = mpf(i) / n
            gx = g(x)
            if prev_g is not None and (gx > 0) != (prev_g > 0):
                roots.append(mp.findroot(g, (prev_x, x), solver='anderson'))
            prev_x, prev_g = x, gx
        _XC_CACHE[key] = roots
    return _XC_CACHE[key]


def p_star_ceb(p, d):
    return pref(p) * (I_pow(p, d, D('1.5'), 0, 1)
                      + I_weighted(p, d, lambda x: D('1.5') * (2 * x - 1), 1, mp.inf))


def q_star_ceb(p, d):
    pts = [mpf(0)] + ceb_cross(p) + [mpf(1)]
    tot = mpf(0)
    for a, c in zip(pts, pts[1:]):
        tot += I_weighted(p, d, lambda x: mu_ceb(p, x) * x ** D('1.5'), a, c)
    return pref(p) * tot


# --------------------------------------------------------------------------
# evaluation at h* and at F*
# --------------------------------------------------------------------------
def f_only(model, p, h):
    d = p.d_of_h(h)
    P = p_star_ke(p, d) if model == 'ke' else p_star_ceb(p, d)
    return P - fs_star(p, d)


def evaluate(model, fit, p, h):
    d = p.d_of_h(h)
    if model == 'ke':
        P = p_star_ke(p, d)
        Q = q_star_ke(p, d, fit)
    elif model == 'ceb':
        P = p_star_ceb(p, d)
        Q = q_star_ceb(p, d)
    else:
        raise ValueError(model)
    Fs = fs_star(p, d)
    F = P - Fs
    mu = Q / F if F > 0 else None
    return dict(d_star=d, p_star=P, fs_star=Fs, q_star=Q, f_star=F, mu=mu)


class NoSolution(Exception):
    pass


def solve_h(model, p, f, d_min=-6, d_max=9, tol=mpf(10) ** -22):
    """h* with F*(h*) = f on the positive branch (F decreasing there)."""
    f = mpf(f)
    return solve_decreasing(
        lambda h: f_only(model, p, h) - f, tol,
        lambda h: 'd* > %s' % d_max if p.d_of_h(h) > d_max else None,
        lambda h: 'd* < %s' % d_min if p.d_of_h(h) < d_min else None)


def solve_decreasing(g, tol, too_high, too_low):
    """The root of a decreasing g: steps of 0.5 from h = 0 until the sign
    changes, then Anderson-Bjorck regula falsi to |b - a| < tol.
    too_high(h) / too_low(h) give a message (NoSolution) where a step
    leaves the range, else None.  Shared by tools/nongaussian_reference.py."""
    step = mpf('0.5')
    h = mpf(0)
    gh = g(h)
    if gh > 0:
        a, ga = h, gh
        while True:
            b = a + step
            if too_high(b):
                raise NoSolution(too_high(b))
            gb = g(b)
            if gb <= 0:
                break
            a, ga = b, gb
    else:
        b, gb = h, gh
        while True:
            a = b - step
            if too_low(a):
                raise NoSolution(too_low(a))
            ga = g(a)
            if ga > 0:
                break
            b, gb = a, ga
    if gb == 0:
        return b
    # Anderson-Bjorck regula falsi on [a, b], g(a) > 0 > g(b)
    side = 0
    for _ in range(200):
        c = b - gb * (b - a) / (gb - ga)
        if not (min(a, b) < c < max(a, b)):
            c = (a + b) / 2
        gc = g(c)
        if gc == 0:
            return c
        if (gc > 0) == (ga > 0):
            # replace a; b retained
            if side == 1:
                m = 1 - gc / ga
                gb = gb * (m if m > 0 else mpf('0.5'))
            a, ga = c, gc
            side = 1
        else:
            if side == -1:
                m = 1 - gc / gb
                ga = ga * (m if m > 0 else mpf('0.5'))
            b, gb = c, gc
            side = -1
        if abs(b - a) < tol:
            break
    # return the end point with the smaller residual
    return a if abs(ga) < abs(gb) else b


# --------------------------------------------------------------------------
# closed form (section 5)
# --------------------------------------------------------------------------
def i_closed_0_inf(p, d, b):
    b = mpf(b)
    c = d / p.s
    return ((p.s / p.wc) ** b * mp.gamma(b + 1) * mp.exp(-c * c / 4)
            * mp.pcfd(-b - 1, c) / mp.sqrt(2 * mp.pi))


# --------------------------------------------------------------------------
# check against MODEL.md
# --------------------------------------------------------------------------
KE_TABLE = [
    # psi, theta, h, d, P, Fs, Q, F, mu
    ('0.5', '0.003', '1.0', '-0.1486018655', '1.1522898584e-02', '1.7642859645e-03',
     '1.1028662054e-02', '9.7586126192e-03', '1.1301465161e+00'),
    ('1.0', '0.001', '2.0', '0.8513981345', '3.3988495467e-03', '1.4693402966e-04',
     '1.9370980416e-03', '3.2519155171e-03', '5.9567907943e-01'),
    ('2.0', '0.0', '0.5', '-0.6486018655', '7.9720740665e-02', '0',
     '2.8009985629e-03', '7.9720740665e-02', '3.5135129699e-02'),
    ('2.0', '0.003', '3.0', '1.8513981345', '3.8818884584e-04', '4.0297620855e-05',
     '9.0502167010e-05', '3.4789122498e-04', '2.6014501232e-01'),
    ('8.0', '0.0001', '1.5', '0.3513981345', '4.0489423603e-02', '1.9812879105e-05',
     '1.0336997658e-05', '4.0469610724e-02', '2.5542616973e-04'),
    ('1.0', '0.01', '0.0', '-1.1486018655', '7.6816667238e-02', '1.1374479790e-02',
     '2.5062021158e-02', '6.5442187448e-02', '3.8296429467e-01'),
]
KE_SOLVE = [
    # psi, theta, F, h, mu
    ('1.0', '0.001', '0.01', '1.4692414618', '5.2521087083e-01'),
    ('0.5', '0.01', '0.001', '1.6515021415', '3.9838855827e+00'),
    ('4.0', '0.0003', '0.05', '1.1505904053', '3.5943724864e-03'),
]
CEB_TABLE = [
    # psi, theta, h, P, Q, F, mu
    ('0.5', '0.003', '1.0', '1.1528941063e-02', '6.8333578436e-03', '9.7646550986e-03',
     '6.9980534639e-01'),
    ('1.0', '0.0', '2.0', '4.4051507593e-03', '6.9579625128e-04', '4.4051507593e-03',
     '1.5795061039e-01'),
    ('2.0', '0.003', '0.5', '9.9096463324e-02', '1.2904972585e-04', '9.6505293204e-02',
     '1.3372295090e-03'),
]
CEB_SOLVE = [
    ('0.5', '0.003', '0.001', '2.0906493680', '1.0474614811e+00'),
    ('1.0', '0.003', '0.01', '1.6029688916', '1.2586850626e-01'),
    ('2.0', '0.003', '0.0001', '3.4633463244', '3.0548269102e-02'),
]


def _half_ulp(text):
    """half a unit in the last printed digit of a decimal string"""
    t = text.lower().lstrip('+-')
    exp = 0
    if 'e' in t:
        t, e = t.split('e')
        exp = int(e)
    decs = len(t.split('.')[1]) if '.' in t else 0
    return mpf(5) * mpf(10) ** (exp - decs - 1)


class Checker:
    def __init__(self):
        self.n = 0
        self.fail = 0
        self.max_rel = {}
        self.not_rounding = 0

    def cmp(self, group, label, computed, quoted, rel_tol=mpf('5e-11')):
        """pass if |computed - quoted| <= half unit of the last quoted digit
        (so the computed value rounds to the printed one) or rel diff < rel_tol"""
        self.n += 1
        q = mpf(quoted)
        diff = abs(computed - q)
        rel = diff / abs(q) if q != 0 else diff
        rounds = diff <= _half_ulp(quoted) * (1 + mpf('1e-6'))
        ok = rounds or rel < rel_tol
        if q == 0:
            ok = rounds = computed == 0
        if not rounds:
            self.not_rounding += 1
        self.max_rel[group] = max(self.max_rel.get(group, mpf(0)), rel)
        if not ok:
            self.fail += 1
        print('  %-4s %-20s computed %-22s quoted %-17s rel %.2e%s' % (
            'ok' if ok else 'FAIL', label, mp.nstr(computed, 15), quoted, float(rel),
            '' if rounds else '  (does not round to the quoted digits)'))
        return ok

    def true(self, group, label, cond, info=''):
        self.n += 1
        if not cond:
            self.fail += 1
        print('  %-4s %s %s' % ('ok' if cond else 'FAIL', label, info))


def cmd_check():
    t0 = time.time()
    ck = Checker()
    print('x0 = %s' % mp.nstr(x0(), 20))
    # independent: real root of the cubic by mpmath.polyroots
    xr = [r for r in mp.polyroots([D('-0.01'), D('0.09'), D('-0.40'), D('0.85')])
          if abs(mp.im(r)) < mpf(10) ** -20][0]
    ck.true('misc', 'x0 = real root of the cubic (polyroots)',
            abs(x0() - mp.re(xr)) < mpf(10) ** -25, mp.nstr(mp.re(xr), 20))
    print('  note: MODEL.md section 3 prints x0 = 4.294625758..., the root is %s '
          '(Q is insensitive: its integrand vanishes at x0)' % mp.nstr(x0(), 14))
    pd = Params(1, 0)
    ck.cmp('misc', 'K(nu=0.3)', pd.K, '0.577')
    ck.cmp('misc', 's(beta=0.04)', pd.s, '0.87618')
    ck.cmp('misc', 'ys(beta=0.04)', pd.ys, '1.14860')
    print('CEB crossing(s):', [mp.nstr(x, 20) for x in ceb_cross(pd)])
    ck.cmp('misc', 'CEB crossing', ceb_cross(pd)[0], '0.951169')
    for x, v in (('0.1', '1.1372'), ('0.5', '0.43946'), ('0.951', '0.28193')):
        ck.cmp('misc', 'mu_CEB(%s)' % x, mu_ceb(pd, mpf(x)), v)

    print('\nMODEL.md section 7, KE at h*:')
    for psi, th, h, d, P, Fs, Q, F, mu in KE_TABLE:
        p = Params(mpf(psi), mpf(th))
        r = evaluate('ke', 'consistent', p, mpf(h))
        tag = 'psi=%s th=%s h=%s' % (psi, th, h)
        print(' ', tag)
        for k, qv in (('d_star', d), ('p_star', P), ('fs_star', Fs), ('q_star', Q),
                      ('f_star', F), ('mu', mu)):
            ck.cmp('ke_h:' + k, k, r[k], qv)

    print('\nMODEL.md section 7, KE solved at F*:')
    for psi, th, F, h, mu in KE_SOLVE:
        p = Params(mpf(psi), mpf(th))
        hs = solve_h('ke', p, mpf(F))
        r = evaluate('ke', 'consistent', p, hs)
        print('  psi=%s th=%s F=%s' % (psi, th, F))
        ck.cmp('ke_f:h_star', 'h_star', hs, h)
        ck.cmp('ke_f:mu', 'mu', r['mu'], mu)
        ck.cmp('ke_f:F_resid', 'F(h_star)', r['f_star'], F, rel_tol=mpf('1e-18'))

    print('\nMODEL.md section 8, CEB at h*:')
    for psi, th, h, P, Q, F, mu in CEB_TABLE:
        p = Params(mpf(psi), mpf(th))
        r = evaluate('ceb', None, p, mpf(h))
        print('  psi=%s th=%s h=%s' % (psi, th, h))
        for k, qv in (('p_star', P), ('q_star', Q), ('f_star', F), ('mu', mu)):
            ck.cmp('ceb_h:' + k, k, r[k], qv)

    print('\nMODEL.md section 8, CEB solved at F*:')
    for psi, th, F, h, mu in CEB_SOLVE:
        p = Params(mpf(psi), mpf(th))
        hs = solve_h('ceb', p, mpf(F))
        r = evaluate('ceb', None, p, hs)
        print('  psi=%s th=%s F=%s' % (psi, th, F))
        ck.cmp('ceb_f:h_star', 'h_star', hs, h)
        ck.cmp('ceb_f:mu', 'mu', r['mu'], mu)

    print('\nSection 5 closed form vs quadrature, I^b[0,1] + I^b[1,inf) = I^b[0,inf):')
    for b in ('1.5', '0.298', '0.982', '0.093', '1.263', '1.425', '1', '0', '4.425'):
        for psi, d in (('0.5', '-2'), ('1', '0.3'), ('4', '2.5'), ('8', '-6'), ('2', '9')):
            p = Params(mpf(psi), 0)
            d = mpf(d)
            cf = i_closed_0_inf(p, d, b)
            qd = I_pow(p, d, b, 0, 1) + I_pow(p, d, b, 1, mp.inf)
            rel = abs(qd - cf) / abs(cf)
            ck.max_rel['closed_form'] = max(ck.max_rel.get('closed_form', mpf(0)), rel)
            ck.true('closed_form', 'b=%-5s psi=%-3s d=%-3s' % (b, psi, d), rel < mpf('1e-22'),
                    'I=%s rel %.2e' % (mp.nstr(cf, 18), float(rel)))

    print('\nSection 6 sanity: the as-printed fit gives negative mu at psi >= 2:')
    p = Params(4, D('0.001'))
    r = evaluate('ke', 'as-printed', p, 1)
    ck.true('misc', 'as-printed mu(psi=4, th=1e-3, h=1) < 0', r['mu'] < 0,
            'mu=%s' % mp.nstr(r['mu'], 10))

    print('\nSelf-consistency: dps=30 against dps=45 at stress points:')
    stress = [  # model, fit, psi, theta, beta, nu, eps, d
        ('ke', 'consistent', 0.3, 0.03, 0.04, 0.3, 0.004, -6),
        ('ke', 'consistent', 12, 0.03, 0.04, 0.3, 0.004, 9),
        ('ke', 'consistent', 8, 0.01, 0.04, 0.3, 0.001, -6),
        ('ke', 'consistent', 0.5, 0.03, 0.04, 0.3, 0.004, 9),
        ('ke', 'consistent', 1, 0.01, 0.025, 0.0, 0.03, 0),
        ('ke', 'as-printed', 3, 0.005, 0.2, 0.49, 0.002, 2.5),
        ('ceb', None, 0.5, 0.01, 0.04, 0.3, 0.004, -3),
        ('ceb', None, 4, 0.01, 0.04, 0.3, 0.004, 6),
    ]
    for model, fit, psi, th, be, nu, ep, d in stress:
        vals = []
        for dps in (30, 45):
            with mp.workdps(dps):
                p = Params(psi, th, be, nu, ep)
                vals.append(evaluate(model, fit, p, p.ys + d))
        worst = max(abs(vals[0][k] - vals[1][k]) / abs(vals[1][k])
                    for k in ('p_star', 'fs_star', 'q_star', 'f_star'))
        ck.max_rel['dps30_vs_45'] = max(ck.max_rel.get('dps30_vs_45', mpf(0)), worst)
        ck.true('selfcons', '%s %s psi=%s th=%s beta=%s nu=%s eps=%s d=%s' % (
            model, fit, psi, th, be, nu, ep, d), worst < mpf('1e-20'),
            'rel %.2e' % float(worst))

    print('\nmax relative differences by group:')
    for k in sorted(ck.max_rel):
        print('  %-16s %.3e' % (k, float(ck.max_rel[k])))
    print('\n%d checks, %d failed; %d quoted values do not round to the printed '
          'digits (allowed if rel < 5e-11); %.1f s'
          % (ck.n, ck.fail, ck.not_rounding, time.time() - t0))
    print('PASS' if ck.fail == 0 else 'FAIL')
    return 0 if ck.fail == 0 else 1


# --------------------------------------------------------------------------
# generation of test points
# --------------------------------------------------------------------------
def _f(x):
    return None if x is None else float(x)


def _loguni(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def _record(model, fit, mode, psi, theta, beta, nu, eps, h, res):
    out = dict(model=model, fit=fit, mode=mode, psi=psi, theta=theta, beta=beta,
               nu=nu, eps_star=eps, h_star=_f(h))
    for k in ('d_star', 'p_star', 'fs_star', 'q_star', 'f_star', 'mu'):
        out[k] = _f(res[k])
    return out


def cmd_generate(path='tests/data/reference_points.json'):
    t0 = time.time()
    rng = random.Random(20261121)
    pts = []
    B, NU, EPS = 0.04, 0.3, 0.004

    def log(msg):
        print('[%6.1f s] %s' % (time.time() - t0, msg), flush=True)

    def h_point(model, fit, psi, theta, h, beta=B, nu=NU, eps=EPS):
        """Evaluates and records one point at separation h."""
        p = Params(psi, theta, beta, nu, eps)
        pts.append(_record(model, fit, 'h', psi, theta, beta, nu, eps, h,
                           evaluate(model, fit, p, mpf(h))))

    # 24 KE consistent at h*
    for i in range(24):
        psi = _loguni(rng, 0.5, 8)
        theta = 0.0 if rng.random() < 1 / 6 else _loguni(rng, 1e-4, 1e-2)
        h = rng.uniform(0, 3)
        h_point('ke', 'consistent', psi, theta, h)
    log('24 KE consistent h points')

    # 8 KE consistent, non-default constants
    for i in range(8):
        beta = rng.uniform(0.025, 0.2)
        nu = rng.uniform(0, 0.49)
        eps = _loguni(rng, 1e-3, 3e-2)
        psi = _loguni(rng, 0.3, 12)
        theta = _loguni(rng, 1e-4, 0.03)
        h = rng.uniform(-1, 4)
        h_point('ke', 'consistent', psi, theta, h, beta, nu, eps)
    log('8 KE non-default points')

    # 6 as-printed
    for i in range(6):
        psi = _loguni(rng, 0.5, 8)
        theta = rng.uniform(0, 0.01)
        h = rng.uniform(0, 3)
        h_point('ke', 'as-printed', psi, theta, h)
    log('6 as-printed points')

    # 6 CEB at h*
    for i in range(6):
        psi = _loguni(rng, 0.5, 4)
        theta = rng.uniform(0, 0.01)
        h = rng.uniform(0, 3)
        h_point('ceb', None, psi, theta, h)
    log('6 CEB points')

    # 10 KE at F*, 3 CEB at F*
    for model, nwant, psi_hi in (('ke', 10, 8), ('ceb', 3, 4)):
        got = 0
        while got < nwant:
            psi = _loguni(rng, 0.5, psi_hi)
            if model == 'ke':
                theta = 0.0 if rng.random() < 1 / 6 else _loguni(rng, 1e-4, 1e-2)
            else:
                theta = rng.uniform(0, 0.01)
            f = _loguni(rng, 1e-5, 0.1)
            p = Params(psi, theta, B, NU, EPS)
            try:
                h = solve_h(model, p, mpf(f))
            except NoSolution as e:
                log('  skip %s psi=%.4g theta=%.4g f=%.4g: %s' % (model, psi, theta, f, e))
                continue
            fit = 'consistent' if model == 'ke' else None
            res = evaluate(model, fit, p, h)
            if not (res['f_star'] > 0 and abs(res['f_star'] / f - 1) < mpf(10) ** -18):
                log('  skip (residual) %s psi=%.4g theta=%.4g f=%.4g' % (model, psi, theta, f))
                continue
            rec = _record(model, fit, 'f', psi, theta, B, NU, EPS, h, res)
            rec['f_star'] = f          # the input target (equal to F*(h*) to ~1e-20)
            pts.append(rec)
            got += 1
        log('%d %s f points' % (nwant, model))

    # closed-form points
    for b in (1.5, 0.298, 0.982, 0.093, 1.263, 1.425):
        psi = _loguni(rng, 0.5, 8)
        d = rng.uniform(-2, 3)
        p = Params(psi, 0, B, NU, EPS)
        dm = mpf(d)
        b = mpf(b)          # the exact double, as for all other inputs
        cf = i_closed_0_inf(p, dm, b)
        i01 = I_pow(p, dm, b, 0, 1)
        i1i = I_pow(p, dm, b, 1, mp.inf)
        rel = abs(i01 + i1i - cf) / cf
        if rel > mpf(10) ** -20:
            raise RuntimeError('closed form mismatch b=%s: %s' % (b, rel))
        pts.append(dict(kind='closed_form', b=float(mpf(b)), psi=psi, beta=B, d_star=d,
                        i_0_inf=float(cf), i_0_1=float(i01), i_1_inf=float(i1i)))
    log('6 closed-form points')

    doc = {
        'generator': ('tools/reference.py generate (Python %s, mpmath %s, mp.dps=%d, '
                      'tanh-sinh quadrature; seed random.Random(20261121)); '
                      'inputs are the exact doubles listed, outputs float(mpf) '
                      'rounded to nearest double'
                      % (sys.version.split()[0], mpmath.__version__, mp.dps)),
        'points': pts,
    }
    with open(path, 'w') as fh:
        fh.write(json.dumps(doc, indent=1))
        fh.write('\n')
    log('wrote %d points to %s' % (len(pts), path))
    return 0


def dispatch(argv, doc, commands):
    """Runs the command argv[1], one of ``commands`` (its name: a function
    of the arguments after it); for none or another, prints the usage
    ``doc`` and returns 2.  (tools/nongaussian_reference.py's too.)"""
    if len(argv) < 2 or argv[1] not in commands:
        print(doc)
        return 2
    return commands[argv[1]](argv[2:])


def cmd_point(args):
    model, fit, psi, theta, h = args[:5]
    p = Params(mpf(psi), mpf(theta))
    r = evaluate(model, None if fit == 'none' else fit, p, mpf(h))
    for k, v in r.items():
        print(k, v)
    return 0


def main(argv):
    return dispatch(argv, __doc__, {
        'check': lambda args: cmd_check(),
        'generate': lambda args: cmd_generate(*args[:1]),
        'point': cmd_point,
    })


if __name__ == '__main__':
    sys.exit(main(sys.argv))
