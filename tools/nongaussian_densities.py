"""The standardised height densities of tools/nongaussian_reference.py
(MODEL.md section 9): Gaussian, Pearson (types 0 to VII) and Weibull, each
a Density with ln g and its split points, normalised by the quadrature of
nongaussian_quadrature.py."""

import os
import sys

from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(__file__))
from nongaussian_quadrature import integrate_std  # noqa: E402
from reference import D  # noqa: E402


# ==========================================================================
# standardised densities
# ==========================================================================
class Density:
    """Standardised density g (mean 0, variance 1) on (lo, hi).

    logg(y, dlo, dhi): unnormalised ln g at y, where dlo = y - lo and
    dhi = hi - y are supplied accurately by the caller (used instead of y
    next to a finite end).  logZ: ln of the integral of exp(logg)."""
    kind = None
    ptype = None
    lo = -mp.inf
    hi = mp.inf
    light_lo = False    # tails that may be cut (exponential or faster decay)
    light_hi = False

    def split_points(self):
        """special interior points (mode / antimode) in standardised units"""
        return []

    def pdf(self, y):
        if not (self.lo < y < self.hi):
            return mpf(0)
        return mp.exp(self.logg(y, y - self.lo, self.hi - y) - self.logZ)

    def _normalise(self):
        self.logZ = mpf(0)
        Z = integrate_std(self, lambda y: 1)
        self.logZ = mp.log(Z)

    def moments(self):
        """(mean, variance, skewness, kurtosis) by quadrature"""
        m = [integrate_std(self, (lambda k: (lambda y: y ** k))(k)) for k in range(5)]
        m0 = m[0]
        mean = m[1] / m0
        c2 = m[2] / m0 - mean ** 2
        c3 = m[3] / m0 - 3 * mean * m[2] / m0 + 2 * mean ** 3
        c4 = m[4] / m0 - 4 * mean * m[3] / m0 + 6 * mean ** 2 * m[2] / m0 - 3 * mean ** 4
        return m0, mean, c2, c3 / c2 ** D('1.5'), c4 / c2 ** 2


class Gaussian(Density):
    kind = 'gaussian'
    ptype = None
    light_lo = light_hi = True

    def __init__(self):
        self.sk, self.K = mpf(0), mpf(3)
        self.mode = mpf(0)
        self.logZ = mp.log(2 * mp.pi) / 2

    def logg(self, y, dlo, dhi):
        return -y * y / 2

    def split_points(self):
        return [mpf(0)]


class Pearson(Density):
    kind = 'pearson'

    def __init__(self, sk, K):
        sk_f, K_f = sk, K
        sk, K = mpf(sk), mpf(K)
        if not (mp.isfinite(sk) and mp.isfinite(K)):
            raise ValueError('Pearson: skewness and kurtosis must be finite')
        if not K > sk ** 2 + 1:
            raise ValueError('Pearson: kurtosis K = %r must exceed Sk^2 + 1 = %s '
                             '(the bound K > Sk^2 + 1; K is not excess kurtosis, 3 for a '
                             'Gaussian)' % (K_f, mp.nstr(sk ** 2 + 1, 17)))
        self.sk, self.K = sk, K
        with mp.workprec(mp.prec + 300):      # exact for double inputs
            S2 = sk * sk
            A1 = 10 * K - 12 * S2 - 18
            A0 = sk * (K + 3)
            B0 = 4 * K - 3 * S2
            B1 = A0
            B2 = 2 * K - 3 * S2 - 6
            Dd = B1 * B1 - 4 * B0 * B2
        tol = mpf(2) ** (10 - mp.prec)
        if (sk == 0 and K == 3) or (abs(B2) <= tol * B0 and abs(B1) <= tol * B0):
            t = '0'
        elif abs(B2) <= tol * B0:
            t = 'III'
        elif B2 < 0:
            t = 'II' if B1 == 0 else 'I'
        elif abs(Dd) <= tol * B0 ** 2:
            t = 'V'
        elif Dd > 0:
            t = 'VI'
        else:
            t = 'VII' if B1 == 0 else 'IV'
        self.ptype = t
        guard = 10
        if t not in ('0', 'III'):
            guard += max(0, int(mp.ceil(mp.log10(B0 / abs(B2)))))
        if t not in ('0', 'III', 'V') and Dd != 0:
            guard += max(0, int(mp.ceil(mp.log10(B0 ** 2 / abs(Dd)))))
        self.guard = min(guard, 120)
        self.light_lo = self.light_hi = False
        with mp.workdps(mp.dps + self.guard):
            A1, A0, B0, B1, B2, Dd = [+v for v in (A1, A0, B0, B1, B2, Dd)]
            self.A1, self.A0, self.B0, self.B1, self.B2, self.D = A1, A0, B0, B1, B2, Dd
            self.ends = {}              # 'lo'/'hi' -> exponent m (g ~ dist^m)
            if t == '0':
                self.light_lo = self.light_hi = True
            elif t in ('I', 'II', 'VI'):
                sq = mp.sqrt(Dd)
                q = -(B1 + (sq if B1 > 0 else -sq)) / 2 if B1 != 0 else -sq / 2
                ra, rb = q / B2, B0 / q
                ca = (A1 * ra + A0) / (B2 * (ra - rb))
                cb = (A1 * rb + A0) / (B2 * (rb - ra))
                self.roots = [(ra, ca), (rb, cb)]
                if t in ('I', 'II'):
                    self.lo, self.hi = min(ra, rb), max(ra, rb)
                else:
                    near = min((ra, rb), key=abs)
                    if near < 0:
                        self.lo = near
                    else:
                        self.hi = near
                for r, c in self.roots:
                    if r == self.lo:
                        self.ends['lo'] = -c
                    elif r == self.hi:
                        self.ends['hi'] = -c
            elif t == 'III':
                self.e = -B0 / B1
                self.c1 = -A1 / B1
                self.c2 = -(A0 - A1 * B0 / B1) / B1
                self.lnfac = mp.log(abs(B1) / B0)
                if B1 > 0:
                    self.lo = self.e
                    self.light_hi = True
                    self.ends['lo'] = self.c2
                else:
                    self.hi = self.e
                    self.light_lo = True
                    self.ends['hi'] = self.c2
            elif t == 'V':
                r = -B1 / (2 * B2)
                self.r = r
                self.cv1 = -A1 / B2
                self.cv2 = (A1 * r + A0) / B2
                self.lnr = mp.log(abs(r))
                if r < 0:
                    self.lo = r
                else:
                    self.hi = r
            else:  # IV, VII
                w = mp.sqrt(-Dd)
                self.w = w
                self.v = B1 / w
                self.c4a = -A1 / (2 * B2)
                self.c4b = -(A0 - A1 * B1 / (2 * B2)) * 2 / w
        # mode / antimode
        self.stationary = -self.A0 / self.A1 if self.A1 != 0 else None
        st = self.stationary
        if self.A1 > 0 and st is not None and self.lo < st < self.hi:
            self.mode = st
        else:
            # J- or U-shaped (A1 <= 0): the maximum sits at an end where g -> inf
            cands = [(m, e) for e, m in self.ends.items() if m < 0]
            if cands:
                e = min(cands)[1]
                self.mode = self.lo if e == 'lo' else self.hi
            else:
                self.mode = st
        self._normalise()

    def split_points(self):
        st = self.stationary
        if st is not None and self.lo < st < self.hi:
            return [st]
        return []

    def logg(self, y, dlo, dhi):
        t = self.ptype
        if t == '0':
            return -y * y / 2
        with mp.workdps(mp.dps + self.guard):
            if t in ('I', 'II', 'VI'):
                tot = mpf(0)
                for r, c in self.roots:
                    if r == self.hi:
                        L = mp.log(dhi / r)
                    elif r == self.lo:
                        L = mp.log(dlo / (-r))
                    else:
                        L = mp.log1p(-y / r)
                    tot -= c * L
                return +tot
            if t == 'III':
                dist = dlo if self.B1 > 0 else dhi
                return self.c1 * y + self.c2 * (self.lnfac + mp.log(dist))
            if t == 'V':
                r = self.r
                if r < 0:
                    L = mp.log(dlo) - self.lnr
                    ymr = dlo
                else:
                    L = mp.log(dhi) - self.lnr
                    ymr = -dhi
                return self.cv1 * L + self.cv2 * (1 / ymr + 1 / r)
            # IV, VII
            B0, B1, B2, w = self.B0, self.B1, self.B2, self.w
            u = (2 * B2 * y + B1) / w
            return (self.c4a * mp.log1p((B1 * y + B2 * y * y) / B0)
                    + self.c4b * mp.atan2(2 * B2 * y / w, 1 + u * self.v))


WEIBULL_SK_MIN = mpf(-1.1395)      # the double nearest -1.1395 (bound exclusive)
WEIBULL_SK_MAX = D(2)


def weibull_skew(k):
    g1 = mp.gamma(1 + 1 / k)
    g2 = mp.gamma(1 + 2 / k)
    g3 = mp.gamma(1 + 3 / k)
    v = g2 - g1 ** 2
    return (g3 - 3 * g1 * v - g1 ** 3) / v ** D('1.5')


class Weibull(Density):
    kind = 'weibull'
    ptype = None
    light_hi = True

    def __init__(self, sk):
        sk_f = sk
        sk = mpf(sk)
        if not mp.isfinite(sk) or not (WEIBULL_SK_MIN < sk <= WEIBULL_SK_MAX):
            raise ValueError('Weibull: skewness Sk = %r out of range: must satisfy '
                             '-1.1395 < Sk <= 2 (the bounds of the Weibull family)' % sk_f)
        self.sk = sk
        if sk == 2:
            k = mpf(1)
        else:
            a, b = mpf(1), mpf(2)
            while weibull_skew(b) > sk:
                a, b = b, 2 * b
            # bisection-safe root (Sk decreasing in k)
            k = mp.findroot(lambda k: weibull_skew(k) - sk, (a, b), solver='anderson')
            if not (a <= k <= b):
                raise RuntimeError('Weibull: root for k left its bracket')
        self.k = k
        g1 = mp.gamma(1 + 1 / k)
        g2 = mp.gamma(1 + 2 / k)
        g4 = mp.gamma(1 + 4 / k)
        g3 = mp.gamma(1 + 3 / k)
        self.mu_k = g1
        self.sig_k = mp.sqrt(g2 - g1 ** 2)
        c4 = g4 - 4 * g1 * g3 + 6 * g1 ** 2 * g2 - 3 * g1 ** 4
        self.K = c4 / self.sig_k ** 4
        self.lo = -self.mu_k / self.sig_k
        self.hi = mp.inf
        self.lnc = mp.log(self.sig_k * k)
        if k > 1:
            wm = ((k - 1) / k) ** (1 / k)
            self.mode = (wm - self.mu_k) / self.sig_k
        else:
            self.mode = self.lo
        self._normalise()

    def split_points(self):
        return [self.mode] if self.lo < self.mode else []

    def logg(self, y, dlo, dhi):
        w = self.sig_k * dlo
        k = self.k
        return self.lnc + (k - 1) * mp.log(w) - w ** k


def make_density(dist, sk=None, K=None):
    if dist == 'gaussian':
        return Gaussian()
    if dist == 'pearson':
        return Pearson(sk, K)
    if dist == 'weibull':
        return Weibull(sk)
    raise ValueError('distribution must be gaussian, pearson or weibull: %r' % dist)
