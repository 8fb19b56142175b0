#!/usr/bin/env python3
"""Independent NumPy (float64) reference for the ISO 16610 Gaussian filters
(ISO 16610-21 profiles, ISO 16610-61 maps) of src/topography/filter.rs.
Test oracle for tests/it/topography_filter.rs; written from the definition
below, it shares no code with the crate and imports nothing from it.

Usage (from the repository root):

    python3 tools/filter_reference.py cases > tests/data/filter/reference.json
        the fixture: the surfaces described below and their Gaussian
        low-pass at two cut-offs each.
    python3 tools/filter_reference.py check
        recomputes the fixture and compares it with the committed one
        (exit status 1 on a difference).

The definition
--------------
Weighting function s(x) = exp(-pi (x/(alpha lam))^2)/(alpha lam),
alpha = sqrt(ln 2/pi); for a map s(x) s(y).  Truncated at |x| <= lam and
|y| <= lam: the weights are s(k dx) for |k| <= floor(lam/dx) along x and
s(l dy) for |l| <= floor(lam/dy) along y (a ratio within 1e-9 of an
integer counts as that integer).  The filtered height at a valid point is
the normalised convolution over the valid points of its window:

    G[z](i, j) = sum w z / sum w,  w = s(k dx) s(l dy),

both sums over the (k, l) of the window whose point (i+k, j+l) is inside
the map and not missing (NaN).  A missing point stays missing.

Computed here point by point with the two-dimensional window (the crate
uses two one-dimensional passes and FFTs: the same sums, grouped
differently).

The surfaces
------------
* "map": 40 x 30 points (nx x ny), dx = 1.0 um, dy = 1.5 um, heights
  2 um + waves + hash noise (about 0.1 um), 8 % of the points missing at
  random, a missing 4 x 3 block and the corner point (0, 0) missing;
  cut-offs 5.3 um (reach 5 x 3 points) and 24.7 um (reach 24 x 16 points:
  most points near an edge).
* "profile": 200 points every 0.5 um, 5 % missing; cut-offs 4.1 um (reach
  8) and 80.3 um (reach 160).
* "profile_full": the same profile with no point missing, cut-off 12.2 um.
"""

import json
import math
import sys

import numpy as np

ALPHA = math.sqrt(math.log(2.0) / math.pi)
FIXTURE = "tests/data/filter/reference.json"


def s(x, lam):
    """The ISO 16610-21 weighting function."""
    a = ALPHA * lam
    return np.exp(-math.pi * (x / a) ** 2) / a


def reach(lam, delta):
    r = lam / delta
    return int(math.floor(r + 1e-9 * max(r, 1.0)))


def lowpass(z, dx, dy, lam):
    """G_lam[z] of a map (2-D array, rows = y) or a profile (1-D, dy None)."""
    profile = z.ndim == 1
    z2 = z[None, :] if profile else z
    ny, nx = z2.shape
    kx = reach(lam, dx)
    wx = s(np.arange(-kx, kx + 1) * dx, lam)
    if profile:
        ky = 0
        wy = np.ones(1)
    else:
        ky = reach(lam, dy)
        wy = s(np.arange(-ky, ky + 1) * dy, lam)
    w2 = np.outer(wy, wx)
    valid = ~np.isnan(z2)
    out = np.full(z2.shape, np.nan)
    for j in range(ny):
        for i in range(nx):
            if not valid[j, i]:
                continue
            j0, j1 = max(j - ky, 0), min(j + ky, ny - 1)
            i0, i1 = max(i - kx, 0), min(i + kx, nx - 1)
            win = z2[j0 : j1 + 1, i0 : i1 + 1]
            ok = valid[j0 : j1 + 1, i0 : i1 + 1]
            w = w2[j0 - j + ky : j1 - j + ky + 1, i0 - i + kx : i1 - i + kx + 1]
            num = np.sum(np.where(ok, w * np.where(ok, win, 0.0), 0.0))
            den = np.sum(np.where(ok, w, 0.0))
            out[j, i] = num / den
    return out[0] if profile else out


def splitmix64(x):
    m = (1 << 64) - 1
    z = (x + 0x9E3779B97F4A7C15) & m
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & m
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & m
    return z ^ (z >> 31)


def uniform(seed, k):
    return (splitmix64((seed << 32) + k) >> 11) * 2.0**-53


def surface(nx, ny, seed, missing):
    z = np.empty((ny, nx))
    for j in range(ny):
        for i in range(nx):
            k = j * nx + i
            u = uniform(seed, k) - 0.5
            h = 2e-6 + 1e-7 * (math.sin(0.37 * i + 0.23 * j + 0.5) + 0.6 * math.cos(0.071 * i - 0.19 * j)) + 3e-8 * u
            if uniform(seed + 1, k) < missing:
                h = math.nan
            z[j, i] = h
    return z


def listed(a):
    return [None if math.isnan(v) else float(v) for v in np.ravel(a)]


def case(name, z, dx, dy, lambdas):
    """A fixture's case: heights ``z`` (a row of a profile, ``dy`` None),
    and their low-pass at each cut-off of ``lambdas``."""
    ny, nx = (1, z.size) if dy is None else z.shape
    return {
        "name": name,
        "nx": nx,
        "ny": ny,
        "dx": dx,
        "dy": dy,
        "heights": listed(z),
        "lowpass": [{"lambda": lam, "heights": listed(lowpass(z, dx, dy, lam))} for lam in lambdas],
    }


def cases():
    z = surface(40, 30, 11, 0.08)
    z[10:13, 20:24] = np.nan
    z[0, 0] = np.nan
    p = surface(200, 1, 23, 0.05)[0]
    q = surface(200, 1, 23, 0.0)[0]
    out = [
        case("map", z, 1.0e-6, 1.5e-6, (5.3e-6, 24.7e-6)),
        case("profile", p, 0.5e-6, None, (4.1e-6, 80.3e-6)),
        case("profile_full", q, 0.5e-6, None, (12.2e-6,)),
    ]
    return {
        "about": "ISO 16610 Gaussian low-pass reference of tools/filter_reference.py (see its docstring); "
        "heights in metres, row-major (x fastest), null = missing",
        "cases": out,
    }


def check():
    with open(FIXTURE) as f:
        old = json.load(f)
    new = cases()
    worst = 0.0
    for a, b in zip(old["cases"], new["cases"], strict=True):
        assert a["name"] == b["name"] and a["heights"] == b["heights"], a["name"]
        for la, lb in zip(a["lowpass"], b["lowpass"], strict=True):
            assert la["lambda"] == lb["lambda"]
            x = np.array([np.nan if v is None else v for v in la["heights"]])
            y = np.array([np.nan if v is None else v for v in lb["heights"]])
            assert np.array_equal(np.isnan(x), np.isnan(y)), a["name"]
            ok = ~np.isnan(x)
            span = np.ptp(y[ok])
            err = np.max(np.abs(x[ok] - y[ok])) / span
            worst = max(worst, err)
            print(f"{a['name']:<13} lambda = {la['lambda']:.3g} m: max |diff| / range = {err:.2e}")
    if worst > 1e-13:
        print(f"FAIL: {worst:.2e} > 1e-13")
        return 1
    print("ok: the committed fixture matches the reference")
    return 0


def main(argv):
    if len(argv) == 2 and argv[1] == "cases":
        json.dump(cases(), sys.stdout, allow_nan=False)
        sys.stdout.write("\n")
        return 0
    if len(argv) == 2 and argv[1] == "check":
        return check()
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
