#!/usr/bin/env python3
"""Cross-check the library's power spectral densities against SurfaceTopography.

Usage:
    python3 tools/psd_check.py [PSD_DUMP]

Writes synthetic height arrays (NumPy .npy, float64: profiles, and maps of
shape (ny, nx), rows along x, with powers of two, odd and other sizes and
dx != dy) to a temporary directory, has the library compute their PSDs with
`examples/psd_dump.rs` (PSD_DUMP: the built example; without it the script
runs `cargo run --release --features topography --example psd_dump`), and
compares, for both windows (none, hann), with SurfaceTopography (PyPI
`SurfaceTopography`, non-periodic containers, `reliable=False`):

  * x:    power_spectrum_from_profile(window, resampling_method=None) of the
          profile or of the map (the mean over its rows);
  * y:    the same of the transposed map (the mean over its columns);
  * area: power_spectrum_from_area(window) (the radial bin average, its
          only method for a map, defaults collocation='log',
          nb_points_per_decade=10), empty (masked) bins left out.

q and C must agree to REL = 1e-10 relative, point by point, except that a
deviation below FLOOR = 1e-14 of the largest C of the spectrum passes (the
rounding of two different FFTs, numpy's pocketfft and rustfft, is about
1e-16 of the largest term: a power-law spectrum spanning 13 decades has
points whose own relative deviation is larger than REL for that reason
alone). Prints the largest deviations, both point by point and relative to
the largest C, and "psd_check: N passed, M failed"; exits 1 if anything
failed.

Needs numpy and SurfaceTopography, e.g. in a venv:
    python3 -m venv target/venv
    target/venv/bin/pip install SurfaceTopography numpy
    target/venv/bin/python tools/psd_check.py
"""

import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synthetic import rough  # noqa: E402

REL = 1e-10
FLOOR = 1e-14
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def cases(rng):
    """(name, heights, dx, dy) with dy None for a profile."""
    yield "profile_1024", rough((1024,), rng), 1e-6, None
    yield "profile_999", rough((999,), rng), 0.37e-6, None
    yield "profile_100", rng.standard_normal(100) * 1e-7, 2e-6, None
    yield "map_64x64", rough((64, 64), rng), 1e-6, 1e-6
    yield "map_100x60", rough((60, 100), rng), 1.3e-6, 0.9e-6
    yield "map_243x17", rough((17, 243), rng), 0.5e-6, 2.5e-6
    yield "map_45x77", rough((77, 45), rng), 2e-6, 1e-6
    yield "map_128x96_white", rng.standard_normal((96, 128)) * 1e-7 + 1e-6, 1e-6, 1.2e-6


def dump(exe, path, dx, dy, window):
    args = [path, repr(dx)] + ([repr(dy)] if dy is not None else []) + [window]
    if exe:
        cmd = [exe] + args
    else:
        cmd = ["cargo", "run", "--release", "-q", "--features", "topography", "--example", "psd_dump", "--"] + args
    out = subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def reference(h, dx, dy, window):
    """SurfaceTopography's PSDs of heights h (NumPy layout (ny, nx))."""
    from SurfaceTopography import Topography, UniformLineScan

    win = "hann" if window == "hann" else "None"
    out = {}
    if dy is None:
        n = h.shape[0]
        t = UniformLineScan(h, n * dx, periodic=False)
        out["x"] = t.power_spectrum_from_profile(window=win, reliable=False, resampling_method=None)
        return out
    ny, nx = h.shape
    # SurfaceTopography indexes heights [x, y].
    t = Topography(h.T.copy(), (nx * dx, ny * dy), periodic=False)
    out["x"] = t.power_spectrum_from_profile(window=win, reliable=False, resampling_method=None)
    ty = Topography(h.copy(), (ny * dy, nx * dx), periodic=False)
    out["y"] = ty.power_spectrum_from_profile(window=win, reliable=False, resampling_method=None)
    q, c = t.power_spectrum_from_area(window=win, reliable=False)
    out["area"] = (np.ma.compressed(q), np.ma.compressed(c))
    return out


def deviation(got, want):
    """(largest |got - want| / |want| (0/0 = 0), largest |got - want| /
    max |want|, whether every point is within REL or the FLOOR)."""
    got, want = np.asarray(got, float), np.asarray(want, float)
    if want.size == 0:
        return 0.0, 0.0, True
    diff = np.abs(got - want)
    scale = np.abs(want)
    top = scale.max()
    rel = np.where(scale > 0, diff / np.where(scale > 0, scale, 1), np.where(diff > 0, np.inf, 0))
    ok = bool(np.all((diff <= REL * scale) | (diff <= FLOOR * top)))
    return float(rel.max()), float(diff.max() / top) if top > 0 else float(diff.max()), ok


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else None
    rng = np.random.default_rng(20261127)
    passed = failed = 0
    worst = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, h, dx, dy in cases(rng):
            path = os.path.join(tmp, name + ".npy")
            np.save(path, h)
            for window in ("none", "hann"):
                got = dump(exe, path, dx, dy, window)
                want = reference(h, dx, dy, window)
                for kind, (wq, wc) in want.items():
                    g = got[kind]
                    label = f"{name} {window} {kind}"
                    if len(g["q"]) != len(wq):
                        print(f"FAIL {label}: {len(g['q'])} points, SurfaceTopography has {len(wq)}")
                        failed += 1
                        continue
                    dq, _, ok_q = deviation(g["q"], wq)
                    dc, dc_top, ok_c = deviation(g["c"], wc)
                    key = (kind, window)
                    old = worst.get(key, (0.0, 0.0, 0.0))
                    worst[key] = (max(old[0], dq), max(old[1], dc), max(old[2], dc_top))
                    if ok_q and ok_c:
                        passed += 1
                    else:
                        print(f"FAIL {label}: q {dq:.2e}, C {dc:.2e} relative ({dc_top:.2e} of the largest C)")
                        failed += 1
    for (kind, window), (dq, dc, dc_top) in sorted(worst.items()):
        print(f"largest deviation {kind:4} window {window:4}: q {dq:.2e}, C {dc:.2e} relative, "
              f"{dc_top:.2e} of the largest C")
    print(f"psd_check: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
