#!/usr/bin/env python3
"""Independent NumPy (float64) reference for the surface statistics of
MODEL.md section 10: sigma, Sk, K, the spectral moments m20, m02, m40, m04,
m2, m4 and the Greenwood-Williamson parameters alpha, eta, R, beta, sigma_s,
y_s derived from them, and the equivalent surface of two rough surfaces.
Test oracle for the Rust crate (src/topography/stats.rs); written from
MODEL.md section 10, it shares no code with the crate and imports nothing
from it.

Usage (from the repository root):

    python3 tools/surface_reference.py stats FILE.npy --dx DX [--dy DY]
            [--detrend plane|line|mean] [--derivative fd|spectral]
        the statistics of a height map (2-D, rows = y) or a profile (1-D
        array, or no --dy) in metres, NaN = missing, as JSON.
    python3 tools/surface_reference.py cases > tests/data/surface_reference.json
        the reference values of tests/it/topography_stats.rs: the synthetic
        surfaces described below, their statistics, and two combinations.
    python3 tools/surface_reference.py npy NAME FILE.npy
        writes the synthetic surface of case NAME to FILE.npy (debugging aid).

What it computes (MODEL.md section 10)
--------------------------------------
* Detrending, least squares over the valid (non-NaN) points only:
  plane z = a + b*x + c*y for a map, line z = a + b*x for a profile;
  "line" on a map fits a + b*x over the whole map (no y tilt); "mean"
  removes the mean only.  Solved with numpy.linalg.lstsq (SVD) in centred
  sample coordinates after removing the mean height.
* sigma, Sk, K: population central moments of the detrended heights
  (K not excess).
* Finite differences (default): m20 = mean(((r[i+1] - r[i])/dx)**2) over
  every adjacent pair along x of valid points, m40 =
  mean(((r[i+1] - 2 r[i] + r[i-1])/dx**2)**2) over every interior triple of
  valid points, r the detrended heights; m02, m04 the same along y with dy.
  The differences of r are taken as the differences of the raw heights less
  the fitted plane's increment (an identity, and exact to rounding even
  when the heights carry a large offset).
* Spectral (periodic): m20 = mean over rows of
  sum_k (2 pi f_k)**2 |Z_k|**2 / N**2 with Z = numpy.fft.fft of the row,
  f_k = numpy.fft.fftfreq(N, dx), the Nyquist term (k = N/2, N even)
  dropped; m40 with (2 pi f_k)**4; m02, m04 over the columns with dy.
* m2 = m20, m4 = m40 for a profile; (m20 + m02)/2, (m40 + m04)/2 for a map.
* alpha = m0 m4 / m2**2 (m0 = sigma**2), eta = m4 / (6 pi sqrt(3) m2),
  R = 0.375 sqrt(pi/m4), beta = sqrt(alpha) / (16 sqrt(3 pi)),
  sigma_s = sigma sqrt(1 - C/alpha) with C = 16/pi - 3 sqrt(3) + 1,
  y_s = 4 sqrt(m0/(pi alpha)).
* Two surfaces: m0, m20, m02, m40, m04, m2, m4 add; Sk sigma**3 and
  (K - 3) sigma**4 add (cumulants); alpha... recomputed from the sums.

The synthetic surfaces (the Rust test builds the same ones)
-----------------------------------------------------------
splitmix64(x): x += 0x9E3779B97F4A7C15; z = x; z = (z ^ z>>30) *
0xBF58476D1CE4E5B9; z = (z ^ z>>27) * 0x94D049BB133111EB; z ^ z>>31, all
mod 2**64.  uniform(seed, k) = (splitmix64(seed * 2**32 + k) >> 11) * 2**-53.
Point k = j*nx + i (i along x, j along y; j = 0 for a profile), with
i, j as floats:

    u = uniform(seed, k) - 0.5
    z = 1e-3 + 2e-8*i - 1e-8*j
        + 1e-7*(sin(0.21*i + 0.13*j + 0.5) + 0.6*cos(0.047*i - 0.09*j))
        + 3e-8*(u + 0.8*u*u)

(metres, evaluated left to right), missing (NaN) where
uniform(seed + 1, k) < missing.
"""

import argparse
import json
import math
import sys

import numpy as np

C_SIGMA_S = 16.0 / math.pi - 3.0 * math.sqrt(3.0) + 1.0
MASK64 = (1 << 64) - 1


# ---------------------------------------------------------------------------
# Synthetic surfaces.

def splitmix64(x):
    """splitmix64 of an array of Python ints (exact, arbitrary precision)."""
    x = (x + 0x9E3779B97F4A7C15) & MASK64
    z = x
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
    return z ^ (z >> 31)


def uniform(seed, n):
    """uniform(seed, k) for k = 0..n-1, as float64."""
    base = seed << 32
    return np.array([(splitmix64(base + k) >> 11) * 2.0 ** -53 for k in range(n)])


def synthetic(nx, ny, seed, missing):
    """The synthetic surface: (ny, nx) array of heights in metres."""
    n = nx * ny
    k = np.arange(n)
    i = (k % nx).astype(float)
    j = (k // nx).astype(float)
    u = uniform(seed, n) - 0.5
    z = (1e-3 + 2e-8 * i - 1e-8 * j
         + 1e-7 * (np.sin(0.21 * i + 0.13 * j + 0.5) + 0.6 * np.cos(0.047 * i - 0.09 * j))
         + 3e-8 * (u + 0.8 * u * u))
    if missing > 0:
        z[uniform(seed + 1, n) < missing] = np.nan
    return z.reshape(ny, nx)


# ---------------------------------------------------------------------------
# Statistics.

def detrend_coefficients(z, detrend, profile):
    """(shift, offset, slope per sample along x, slope per sample along y):
    the least-squares fit z - shift = offset + bx*u + by*v over the valid
    points, in centred sample coordinates (u = i - (nx-1)/2,
    v = j - (ny-1)/2), shift the mean height (removed first, so that the
    residuals do not round at the scale of a large height offset)."""
    ny, nx = z.shape
    valid = ~np.isnan(z)
    jj, ii = np.nonzero(valid)
    zv = z[valid]
    shift = zv.mean()
    zs = zv - shift
    u = ii - 0.5 * (nx - 1)
    v = jj - 0.5 * (ny - 1)
    if detrend == "mean":
        cols = [np.ones_like(u)]
    elif detrend == "line" or profile:
        cols = [np.ones_like(u), u]
    else:
        cols = [np.ones_like(u), u, v]
    coef, *_ = np.linalg.lstsq(np.column_stack(cols), zs, rcond=None)
    coef = list(coef) + [0.0] * (3 - len(coef))
    return shift, coef[0], coef[1], coef[2]


def fd_moments(z, h, slope):
    """Mean squares of the first differences (less the plane's increment
    `slope` per sample) over h**2 and of the second differences over h**4,
    along the last axis, over the differences whose points are all valid."""
    d1 = np.diff(z, axis=-1) - slope
    d2 = np.diff(z, n=2, axis=-1)
    d1 = d1[~np.isnan(d1)]
    d2 = d2[~np.isnan(d2)]
    return np.mean(d1 * d1) / h ** 2, np.mean(d2 * d2) / h ** 4


def spectral_moments(r, h):
    """Periodic spectral moments along the last axis, mean over the lines."""
    n = r.shape[-1]
    spec = np.abs(np.fft.fft(r, axis=-1)) ** 2 / n ** 2
    w = (2 * np.pi * np.fft.fftfreq(n, h)) ** 2
    if n % 2 == 0:
        w[n // 2] = 0.0
    return np.mean(spec @ w), np.mean(spec @ (w * w))


def derived(m0, m2, m4):
    alpha = m0 * m4 / m2 ** 2
    return {
        "alpha": alpha,
        "eta": m4 / (6 * np.pi * np.sqrt(3) * m2),
        "radius": 0.375 * np.sqrt(np.pi / m4),
        "beta": np.sqrt(alpha) / (16 * np.sqrt(3 * np.pi)),
        "sigma_s": np.sqrt(m0) * np.sqrt(1 - C_SIGMA_S / alpha),
        "y_s": 4 * np.sqrt(m0 / (np.pi * alpha)),
    }


def stats(z, dx, dy=None, detrend="plane", derivative="fd"):
    """The statistics of a map (2-D, rows = y) or a profile (dy None)."""
    z = np.asarray(z, dtype=float)
    profile = dy is None
    if z.ndim == 1:
        z = z[None, :]
    ny, nx = z.shape
    valid = ~np.isnan(z)
    shift, a, b, c = detrend_coefficients(z, detrend, profile)
    jj, ii = np.mgrid[0:ny, 0:nx]
    r = (z - shift) - (a + b * (ii - 0.5 * (nx - 1)) + c * (jj - 0.5 * (ny - 1)))
    rv = r[valid]
    rc = rv - rv.mean()
    m0 = np.mean(rc ** 2)
    sigma = np.sqrt(m0)
    out = {
        "points": int(valid.sum()),
        "missing": int((~valid).sum()),
        "nx": nx,
        "ny": ny,
        "dx": dx,
        "dy": dy,
        "sigma": sigma,
        "skewness": np.mean(rc ** 3) / sigma ** 3,
        "kurtosis": np.mean(rc ** 4) / m0 ** 2,
    }
    if derivative == "spectral":
        assert valid.all(), "spectral moments need every point"
        m20, m40 = spectral_moments(r, dx)
        if not profile:
            m02, m04 = spectral_moments(r.T, dy)
    else:
        m20, m40 = fd_moments(z, dx, b)
        if not profile:
            m02, m04 = fd_moments(z.T, dy, c)
    if profile:
        m02 = m04 = None
        m2, m4 = m20, m40
    else:
        m2, m4 = (m20 + m02) / 2, (m40 + m04) / 2
    out.update({"m20": m20, "m02": m02, "m40": m40, "m04": m04, "m2": m2, "m4": m4})
    out.update(derived(m0, m2, m4))
    out["anisotropy_m2"] = None if profile else m20 / m02
    out["anisotropy_m4"] = None if profile else m40 / m04
    return {k: (float(v) if isinstance(v, (float, np.floating)) else v) for k, v in out.items()}


def combine(s, t):
    """The equivalent surface of two rough surfaces (MODEL.md section 10)."""
    va, vb = s["sigma"] ** 2, t["sigma"] ** 2
    m0 = va + vb
    out = dict(s)
    out["sigma"] = math.sqrt(m0)
    out["skewness"] = (s["skewness"] * va ** 1.5 + t["skewness"] * vb ** 1.5) / m0 ** 1.5
    out["kurtosis"] = 3 + ((s["kurtosis"] - 3) * va ** 2 + (t["kurtosis"] - 3) * vb ** 2) / m0 ** 2
    for key in ["m20", "m02", "m40", "m04", "m2", "m4"]:
        out[key] = None if s[key] is None else s[key] + t[key]
    out.update({k: float(v) for k, v in derived(m0, out["m2"], out["m4"]).items()})
    if out["m02"] is not None:
        out["anisotropy_m2"] = out["m20"] / out["m02"]
        out["anisotropy_m4"] = out["m40"] / out["m04"]
    return out


# ---------------------------------------------------------------------------
# The test cases.

CASES = [
    # name, nx, ny (None = profile), dx, dy, seed, missing, detrend, derivative
    ("map_plane", 96, 64, 0.5e-6, 0.8e-6, 1, 0.0, "plane", "fd"),
    ("map_plane_masked", 96, 64, 0.5e-6, 0.8e-6, 1, 0.03, "plane", "fd"),
    ("map_line_masked", 96, 64, 0.5e-6, 0.8e-6, 1, 0.03, "line", "fd"),
    ("map_mean_masked", 96, 64, 0.5e-6, 0.8e-6, 1, 0.03, "mean", "fd"),
    ("map_other", 64, 80, 1.1e-6, 1.0e-6, 7, 0.0, "plane", "fd"),
    ("profile_line", 2000, None, 1e-7, None, 3, 0.0, "plane", "fd"),
    ("profile_line_masked", 2000, None, 1e-7, None, 3, 0.02, "plane", "fd"),
    ("profile_mean", 2000, None, 1e-7, None, 3, 0.0, "mean", "fd"),
    ("map_spectral_mean", 60, 48, 0.5e-6, 0.8e-6, 5, 0.0, "mean", "spectral"),
    ("map_spectral_plane", 64, 64, 0.5e-6, 0.5e-6, 5, 0.0, "plane", "spectral"),
    ("profile_spectral", 1000, None, 1e-7, None, 9, 0.0, "mean", "spectral"),
]

COMBINATIONS = [("map_plane", "map_other"), ("profile_line", "profile_mean")]


def case_surface(case):
    name, nx, ny, dx, dy, seed, missing, detrend, derivative = case
    return synthetic(nx, 1 if ny is None else ny, seed, missing)


def cmd_cases(_args):
    cases = []
    by_name = {}
    for case in CASES:
        name, nx, ny, dx, dy, seed, missing, detrend, derivative = case
        s = stats(case_surface(case), dx, dy, detrend, derivative)
        by_name[name] = s
        cases.append({
            "name": name, "nx": nx, "ny": ny, "dx": dx, "dy": dy, "seed": seed,
            "missing": missing, "detrend": detrend, "derivative": derivative, "stats": s,
        })
    combos = [{"first": a, "second": b, "stats": combine(by_name[a], by_name[b])} for a, b in COMBINATIONS]
    doc = {
        "generator": "python3 tools/surface_reference.py cases > tests/data/surface_reference.json",
        "numpy": np.__version__,
        "cases": cases,
        "combinations": combos,
    }
    json.dump(doc, sys.stdout, indent=1)
    sys.stdout.write("\n")


def cmd_stats(args):
    z = np.load(args.file)
    if z.ndim == 1 and args.dy is not None:
        sys.exit("a 1-D array is a profile: no --dy")
    dy = None if z.ndim == 1 else (args.dy if args.dy is not None else args.dx)
    json.dump(stats(z, args.dx, dy, args.detrend, args.derivative), sys.stdout, indent=1)
    sys.stdout.write("\n")


def cmd_npy(args):
    for case in CASES:
        if case[0] == args.name:
            z = case_surface(case)
            np.save(args.file, z[0] if case[2] is None else z)
            return
    sys.exit(f"no case {args.name}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("stats")
    s.add_argument("file")
    s.add_argument("--dx", type=float, required=True)
    s.add_argument("--dy", type=float)
    s.add_argument("--detrend", choices=["plane", "line", "mean"], default="plane")
    s.add_argument("--derivative", choices=["fd", "spectral"], default="fd")
    sub.add_parser("cases")
    n = sub.add_parser("npy")
    n.add_argument("name")
    n.add_argument("file")
    args = p.parse_args()
    {"stats": cmd_stats, "cases": cmd_cases, "npy": cmd_npy}[args.cmd](args)


if __name__ == "__main__":
    main()
