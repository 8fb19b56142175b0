"""The piecewise tanh-sinh quadrature of tools/nongaussian_reference.py
(its docstring, "Numerics"): int w(z - dref) g(z/s) dz over a standardised
density's support, split at the regime boundaries, the support's ends, the
mode and multiples of s, each piece bisected until its error estimate is
below rtol of the sum; light tails cut where the density has dropped by
exp(-TAIL_LOG).  A density is any object with the attributes of
nongaussian_densities.Density (duck-typed: this file imports none)."""

import sys

from mpmath import mp, mpf

TAIL_LOG = mpf(120)


def _fmt(v):
    return mp.nstr(v, 12)


# ==========================================================================
# piecewise tanh-sinh quadrature of  w(z - dref) * g(z/s)  dz
# ==========================================================================
def _std_splits():
    ks = list(range(-16, 17))
    v = 16
    while v < 1024:
        v = v * 2
        ks += [v, -v]
    return sorted(set(ks))


STD_SPLITS = _std_splits()


def _tail_cut(dens, y0, direction):
    """for a light tail: a point beyond which exp(logg) < exp(logg(y0') - 120),
    y0' = y0 moved to the mode if the mode lies further out"""
    ym = dens.mode if dens.mode is not None else mpf(0)
    if direction > 0:
        ystart = max(y0, ym)
    else:
        ystart = min(y0, ym)

    def lg(y):
        return dens.logg(y, y - dens.lo, dens.hi - y)
    ref = lg(ystart)
    step = mpf(1)
    y = ystart + direction * step
    while lg(y) > ref - TAIL_LOG:
        step *= 2
        y = ystart + direction * step
    return y


def integrate(dens, s, wfun, zA, zB, dref, extra=(), rtol=None, logZ=None):
    """int_{zA}^{zB} wfun(z - dref) * exp(logg(z/s) - logZ) dz over the part
    inside the support.  Pieces are split at extra, at s*k, at s*mode etc."""
    if rtol is None:
        rtol = mpf(10) ** (4 - mp.dps) if mp.dps < 30 else mpf(10) ** -24
    if logZ is None:
        logZ = dens.logZ
    zlo, zhi = s * dens.lo, s * dens.hi
    a = max(zA, zlo)
    b = min(zB, zhi)
    if not a < b:
        return mpf(0)
    # light tails: cut where the density is exp(-120) below its value at
    # max(dref, mode) (upper tail) or min(dref, mode) (lower tail), i.e. below
    # the largest density on the domain of the model's integrals
    if b == mp.inf and dens.light_hi:
        b = s * _tail_cut(dens, dref / s, +1)
    if a == -mp.inf and dens.light_lo:
        a = s * _tail_cut(dens, dref / s, -1)
    if not a < b:
        return mpf(0)
    pts = set([a, b])
    for y in STD_SPLITS:
        z = s * y
        if a < z < b:
            pts.add(z)
    for y in dens.split_points():
        z = s * y
        if a < z < b:
            pts.add(z)
    for z in extra:
        if a < z < b:
            pts.add(z)
    pts = sorted(pts)
    special = set([zlo, zhi, dref])

    def make(p, q, side):
        """integrand in tau measured from p (side 'lo') or q (side 'hi')"""
        if side == 'lo':
            e0, l0, h0, sg = p - dref, p - zlo, zhi - p, 1
            z0 = p
        else:
            e0, l0, h0, sg = q - dref, q - zlo, zhi - q, -1
            z0 = q

        def f(tau):
            e = e0 + sg * tau
            wv = wfun(e)
            if wv == 0:
                return wv
            y = (z0 + sg * tau) / s
            dlo = (l0 + sg * tau) / s
            dhi = (h0 - sg * tau) / s
            return wv * mp.exp(dens.logg(y, dlo, dhi) - logZ)
        return f

    pieces = []

    def add(p, q):
        if q == mp.inf:
            pieces.append((p, q, 'lo'))
            return
        ps, qs = p in special, q in special
        if ps and qs:
            m = (p + q) / 2
            pieces.append((p, m, 'lo'))
            pieces.append((m, q, 'hi'))
        elif qs:
            pieces.append((p, q, 'hi'))
        else:
            pieces.append((p, q, 'lo'))

    for p, q in zip(pts, pts[1:]):
        if a == -mp.inf and p == -mp.inf:
            pieces.append((p, q, 'hi'))
        else:
            add(p, q)

    # mpmath's tanh-sinh error estimate is absolute (floored near 10^-dps):
    # integrate a normalised integrand (pieces of order one), scale back
    S = mpf(0)
    for p, q, side in pieces:
        f = make(p, q, side)
        if p == -mp.inf or q == mp.inf:
            S = max(S, abs(f(s)) * s)
        else:
            S = max(S, abs(f((q - p) / 2)) * (q - p))
    if S == 0:
        S = mpf(1)

    ends = getattr(dens, 'ends', {})

    def q1(p, q, side):
        f0 = make(p, q, side)
        f = lambda tau: f0(tau) / S
        if p == -mp.inf or q == mp.inf:
            v, e = mp.quad(f, [0, mp.inf], error=True)
            return v * S, e * S
        L = q - p
        m = None
        if side == 'lo' and p == zlo:
            m = ends.get('lo')
        elif side == 'hi' and q == zhi:
            m = ends.get('hi')
        if m is not None and m < 0:
            # g ~ tau^m (m > -1) at this end: tau = L u^n, n = ceil(1/(m+1)),
            # makes the integrand bounded and smooth in u; tau stays exact
            n = max(2, int(mp.ceil(1 / (m + 1))))
            g = lambda u: f(L * u ** n) * u ** (n - 1)
            v, e = mp.quad(g, [0, 1], error=True)
            return v * S * L * n, e * S * L * n
        v, e = mp.quad(f, [0, L], error=True)
        return v * S, e * S

    res = [q1(*pc) for pc in pieces]
    scale = sum(abs(v) for v, e in res)
    if scale == 0:
        return mpf(0)
    tot = mpf(0)
    for pc, (v, err) in zip(pieces, res):
        if err <= rtol * scale:
            tot += v
        else:
            tot += _refine(q1, pc, scale, rtol, s, 0)
    return tot


def _refine(q1, pc, scale, rtol, s, depth):
    p, q, side = pc
    if q == mp.inf or p == -mp.inf:
        # split the infinite piece at a finite distance
        L = s * 2 ** (depth + 2)
        if q == mp.inf:
            subs = [(p, p + L, 'lo'), (p + L, q, 'lo')]
        else:
            subs = [(q - L, q, 'hi'), (p, q - L, 'hi')]
    else:
        m = (p + q) / 2
        subs = [(p, m, 'lo'), (m, q, 'hi')] if side == 'hi' else [(p, m, 'lo'), (m, q, 'lo')]
        if side == 'hi':
            subs = [(p, m, 'lo'), (m, q, 'hi')]
    tot = mpf(0)
    for sp in subs:
        v, err = q1(*sp)
        if err <= rtol * scale or depth >= 10:
            if err > rtol * scale:
                print('warning: quadrature did not converge on [%s, %s] err %s scale %s'
                      % (_fmt(sp[0]), _fmt(sp[1]), mp.nstr(err, 3), mp.nstr(scale, 3)),
                      file=sys.stderr)
            tot += v
        else:
            tot += _refine(q1, sp, scale, rtol, s, depth + 1)
    return tot


def integrate_std(dens, fun):
    """int fun(y) g_unnorm(y) dy / exp(logZ) over the whole support (s = 1)"""
    return integrate(dens, mpf(1), fun, -mp.inf, mp.inf, mpf(0))
