#!/usr/bin/env python3
"""Cross-check the library's scale-dependent statistics against SurfaceTopography.

Usage:
    python3 tools/scale_check.py [SCALE_DUMP] [--no-timing]

Writes synthetic height arrays (NumPy .npy, float64: profiles, and maps of
shape (ny, nx), rows along x, with dx != dy) to a temporary directory, has
the library compute them with `examples/scale_dump.rs` (SCALE_DUMP: the
built example; without it the script runs `cargo run --release --features
topography --example scale_dump`), and compares with SurfaceTopography
(PyPI `SurfaceTopography`, non-periodic containers; Sanner et al., Appl.
Surf. Sci. Adv. 7, 100190, 2022, doi 10.1016/j.apsadv.2021.100190):

  * rms slope:     sqrt of scale_dependent_statistical_property(
                   lambda x, y=None: np.mean(x*x), n=1, distance=...,
                   reliable=False), along x, and with np.mean(y*y) along y
                   for maps;
  * rms curvature: the same with n=2;
  * tip cut-off:   scanning_probe_reliability_cutoff(R, 1/2) for a small,
                   an intermediate (a root inside the bracket) and a large
                   tip radius R.

The distances mix integer multiples of the pixel size, fractions, values
an ulp from a multiple (the trimmed edge is ceil(d/(n*px))) and lengths
close to the size (too few points: NaN). The rms values must agree to
REL = 1e-10 relative (NaN with NaN), the cut-offs to CUT_REL = 1e-6
(None with None). Then times the rms slope (both directions) at 16
distances on a 1024 x 1024 map, one thread, SurfaceTopography against the
library's best of 3, and prints the ratio (--no-timing skips it). Prints
"scale_check: N passed, M failed"; exits 1 if anything failed.

Needs numpy and SurfaceTopography, e.g. in a venv:
    python3 -m venv target/venv
    target/venv/bin/pip install SurfaceTopography numpy
    target/venv/bin/python tools/scale_check.py
"""

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import json  # noqa: E402
import math  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from SurfaceTopography import Topography, UniformLineScan  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synthetic import rough  # noqa: E402

REL = 1e-10
CUT_REL = 1e-6
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def cases(rng):
    """(name, heights, dx, dy) with dy None for a profile."""
    yield "profile_1024", rough((1024,), rng), 1e-6, None
    yield "profile_999", rough((999,), rng), 0.37e-6, None
    yield "profile_60_white", rng.standard_normal(60) * 1e-7, 2e-6, None
    x = np.arange(500) * 0.2e-6
    yield "profile_sine", 0.5e-6 * np.sin(2 * np.pi * x / 13e-6), 0.2e-6, None
    yield "map_64x64", rough((64, 64), rng), 1e-6, 1e-6
    yield "map_100x60", rough((60, 100), rng), 1.3e-6, 0.9e-6
    yield "map_45x77", rough((77, 45), rng), 2e-6, 1e-6
    yield "map_128x96_white", rng.standard_normal((96, 128)) * 1e-7 + 1e-6, 1e-6, 1.7e-6
    yield "map_200x150", rough((150, 200), rng), 0.31e-6, 0.5e-6


def container(h, dx, dy):
    if dy is None:
        return UniformLineScan(h, len(h) * dx, periodic=False)
    ny, nx = h.shape
    return Topography(h.T.copy(), (nx * dx, ny * dy), periodic=False)  # ST: first axis = x


def distances(t):
    """Stencil lengths: multiples, fractions, near-multiples, near the size."""
    px = float(np.min(t.pixel_size))
    size = float(np.min(t.physical_sizes))
    ds = [px, 2 * px, 3 * px, 1.5 * px, 2.7 * px, 7 * px, 10.25 * px,
          np.nextafter(4 * px, np.inf), np.nextafter(4 * px, 0),
          0.1 * size, 0.33 * size, 0.49 * size, 0.9 * size, 0.99 * size]
    return [float(d) for d in ds]


def dump(exe, path, px, py, ds, tip=None, repeat=0):
    args = [path, f"dx={px!r}"] + ([f"dy={py!r}"] if py is not None else [])
    args += ["d=" + ",".join(repr(d) for d in ds)]
    if tip is not None:
        args += [f"tip={tip!r}", "f=0.5"]
    if repeat:
        args += [f"repeat={repeat}"]
    if exe:
        cmd = [exe] + args
    else:
        cmd = ["cargo", "run", "--release", "-q", "--features", "topography", "--example", "scale_dump", "--"] + args
    out = subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def reference(t, ds, n):
    """(x, y) rms per distance, y None for a profile."""
    if t.dim == 1:
        _, s = t.scale_dependent_statistical_property(lambda x, y=None: np.mean(x * x), n=n, distance=ds,
                                                      reliable=False)
        return [(math.sqrt(v), None) for v in np.asarray(s, float)]
    _, s = t.scale_dependent_statistical_property(lambda x, y: np.array([np.mean(x * x), np.mean(y * y)]), n=n,
                                                  distance=ds, reliable=False)
    return [(math.sqrt(a), math.sqrt(b)) for a, b in np.asarray(s, float)]


def close(a, b, rel):
    if a is None or b is None:
        return a is None and b is None
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= rel * max(abs(a), abs(b))


def rel_dev(a, b):
    if a is None or b is None or math.isnan(float(a)) or math.isnan(float(b)):
        return 0.0
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def tips(t):
    """Tip radii: small (no cut-off), intermediate (a root), large (none reliable)."""
    lower, upper = t.bandwidth()
    def cmin(d):
        der = t.derivative(n=2, distance=d)
        der = der if t.dim == 1 else der[0]
        return float(np.min(der)) if np.size(der) else -1.0
    c_small = abs(cmin(2 * lower))
    c_large = abs(cmin(upper / 2)) or c_small * 1e-6
    mid = 0.5 / math.sqrt(c_small * c_large)
    return [0.5 / c_small * 1e-3, mid, 0.5 / c_large * 1e3]


def main():
    argv = [a for a in sys.argv[1:] if not a.startswith("--")]
    exe = argv[0] if argv else None
    timing = "--no-timing" not in sys.argv
    rng = np.random.default_rng(20261127)
    passed = failed = 0
    worst = {"slope": 0.0, "curvature": 0.0, "cutoff": 0.0}
    with tempfile.TemporaryDirectory() as tmp:
        for name, h, dx, dy in cases(rng):
            path = os.path.join(tmp, name + ".npy")
            np.save(path, h)
            t = container(h, dx, dy)
            px = float(t.pixel_size[0])
            py = None if dy is None else float(t.pixel_size[1])
            ds = distances(t)
            radii = tips(t)
            ours = dump(exe, path, px, py, ds, tip=radii[0])
            for key, n in (("slope", 1), ("curvature", 2)):
                ref = reference(t, ds, n)
                for d, (rx, ry), row in zip(ds, ref, ours[key]):
                    ox = row["x"] if row["x"] is not None else float("nan")
                    oy = row["y"] if (row["y"] is not None or dy is None) else float("nan")
                    ok = close(ox, rx, REL) and (dy is None or close(oy, ry, REL))
                    worst[key] = max(worst[key], rel_dev(ox, rx), rel_dev(oy, ry) if dy is not None else 0.0)
                    if ok:
                        passed += 1
                    else:
                        failed += 1
                        print(f"FAIL {name} {key} d={d!r}: ours ({ox}, {oy}) SurfaceTopography ({rx}, {ry})")
            cuts = []
            for i, r in enumerate(radii):
                got = ours["cutoff"] if i == 0 else dump(exe, path, px, py, ds[:1], tip=r)["cutoff"]
                want = t.scanning_probe_reliability_cutoff(r, 0.5)
                want = None if want is None else float(want)
                cuts.append("none" if got is None else f"{got:.6g}")
                worst["cutoff"] = max(worst["cutoff"], rel_dev(got, want))
                if close(got, want, CUT_REL):
                    passed += 1
                else:
                    failed += 1
                    print(f"FAIL {name} cutoff R={r!r}: ours {got} SurfaceTopography {want}")
            nan = sum(1 for row in ours["slope"] + ours["curvature"] if row["x"] is None)
            print(f"{name}: {len(ds)} distances ({nan} rows NaN: too few points); "
                  f"cut-offs {', '.join(f'R={r:.3g}: {c}' for r, c in zip(radii, cuts))}")
        print(f"largest relative deviations: slope {worst['slope']:.2e}, curvature {worst['curvature']:.2e}, "
              f"cut-off {worst['cutoff']:.2e}")

        if timing:
            n = 1024
            h = rough((n, n), rng)
            path = os.path.join(tmp, "speed.npy")
            np.save(path, h)
            t = container(h, 1e-6, 1e-6)
            px, py = (float(p) for p in t.pixel_size)
            ds = [float(d) for d in np.geomspace(px, 0.5 * n * px, 16)]
            start = time.perf_counter()
            ref = reference(t, ds, 1)
            python_seconds = time.perf_counter() - start
            ours = dump(exe, path, px, py, ds, repeat=3)
            rust_seconds = ours["slope_seconds"]
            for d, (rx, ry), row in zip(ds, ref, ours["slope"]):
                if close(row["x"], rx, REL) and close(row["y"], ry, REL):
                    passed += 1
                else:
                    failed += 1
                    print(f"FAIL speed map slope d={d!r}: ours ({row['x']}, {row['y']}) SurfaceTopography ({rx}, {ry})")
            ratio = python_seconds / rust_seconds
            print(f"timing: rms slope (x and y), 16 distances, 1024 x 1024 map, one thread: "
                  f"SurfaceTopography {python_seconds:.3f} s, library {rust_seconds * 1e3:.1f} ms, ratio {ratio:.0f}x")
            if ratio >= 20:
                passed += 1
            else:
                failed += 1
                print(f"FAIL speed: ratio {ratio:.1f} < 20")

    print(f"scale_check: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
