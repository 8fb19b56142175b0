#!/usr/bin/env python3
"""Filtered surface statistics, kefric against an independent NumPy
pipeline: ISO 16610-61 Gaussian S-filter (lambda_s) -> plane detrending
(the F-operation) -> L-filter (lambda_c: the roughness z - G[z]) ->
statistics, each step from this folder's references written from the
definitions (filter_reference.lowpass: normalised convolution point by
point; surface_reference: detrending and statistics of MODEL.md section 10),
on the same heights in an .npy file, an X3P file and a text file (the
statistics must agree across the formats too).

usage: filtered_stats_check.py KEFRIC    (exits 1 on a mismatch; the last
line is `filtered_stats_check: N passed, M failed`)
"""

import json
import os
import subprocess
import sys
import tempfile
import zipfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import filter_reference  # noqa: E402
import surface_reference  # noqa: E402

TOL = 1e-9
NAMES = ["sigma", "skewness", "kurtosis", "m20", "m02", "m40", "m04", "m2", "m4", "alpha", "eta", "radius", "beta"]


def heights(nx, ny, dx, dy, missing):
    rng = np.random.default_rng(7)
    x = np.arange(nx) * dx
    y = np.arange(ny)[:, None] * dy
    z = np.zeros((ny, nx))
    for _ in range(30):
        lam = 3e-6 * 10 ** rng.uniform(0, 1.5)
        a = rng.uniform(0, np.pi)
        z += 1e-7 * (lam / 3e-6) ** 0.8 * np.sin(2 * np.pi / lam * (x * np.cos(a) + y * np.sin(a)) + rng.uniform(0, 6.3))
    z += 2e-8 * x / dx + 1e-7  # a tilt and an offset for the F-operation
    for j, i in missing:
        z[j, i] = np.nan
    return z


def reference(z, dx, dy, lambda_s, lambda_c):
    zs = filter_reference.lowpass(z, dx, dy, lambda_s) if lambda_s else z
    if lambda_c:
        shift, a, b, c = surface_reference.detrend_coefficients(zs, "plane", False)
        ny, nx = zs.shape
        u = np.arange(nx) - 0.5 * (nx - 1)
        v = (np.arange(ny) - 0.5 * (ny - 1))[:, None]
        d = zs - shift - (a + b * u + c * v)
        r = d - filter_reference.lowpass(d, dx, dy, lambda_c)
        return surface_reference.stats(r, dx, dy, detrend="mean")
    return surface_reference.stats(zs, dx, dy, detrend="plane")


def write_x3p(path, z, dx, dy):
    ny, nx = z.shape
    valid = ~np.isnan(z)
    bits = np.packbits(valid.ravel(), bitorder="little").tobytes()
    xml = f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2"><Record1><Revision>ISO5436 - 2000</Revision>
<FeatureType>SUR</FeatureType><Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{dx!r}</Increment>
<Offset>0</Offset></CX><CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{dy!r}</Increment><Offset>0</Offset>
</CY><CZ><AxisType>A</AxisType><DataType>D</DataType></CZ></Axes></Record1><Record3><MatrixDimension><SizeX>{nx}</SizeX>
<SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension><DataLink><PointDataLink>bindata/data.bin</PointDataLink>
<ValidPointsLink>bindata/valid.bin</ValidPointsLink></DataLink></Record3></p:ISO5436_2>"""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as f:
        f.writestr("main.xml", xml)
        f.writestr("bindata/data.bin", np.nan_to_num(z, nan=0.0).astype("<f8").tobytes())
        f.writestr("bindata/valid.bin", bits)


def main():
    kefric = sys.argv[1]
    dx, dy = 1e-6, 1.5e-6
    z = heights(72, 60, dx, dy, [(3, 5), (30, 40), (59, 71)])
    passed = failed = 0
    worst = 0.0
    with tempfile.TemporaryDirectory() as d:
        files = {
            "npy": (os.path.join(d, "z.npy"), ["--dx", repr(dx), "--dy", repr(dy)]),
            "x3p": (os.path.join(d, "z.x3p"), []),
            "text": (os.path.join(d, "z.txt"), ["--dx", repr(dx), "--dy", repr(dy)]),
        }
        np.save(files["npy"][0], z)
        write_x3p(files["x3p"][0], z, dx, dy)
        np.savetxt(files["text"][0], z, fmt="%.17g")
        for lambda_s, lambda_c in [(4e-6, None), (None, 40e-6), (4e-6, 40e-6), (6.5e-6, 55e-6)]:
            want = reference(z, dx, dy, lambda_s, lambda_c)
            flags = (["--lambda-s", repr(lambda_s)] if lambda_s else []) + (
                ["--lambda-c", repr(lambda_c)] if lambda_c else []
            )
            for fmt, (path, extra) in files.items():
                out = subprocess.run([kefric, "surface", path, *extra, *flags, "--json"], capture_output=True, text=True)
                if out.returncode != 0:
                    print(f"FAIL {fmt} {flags}: exit {out.returncode}: {out.stderr.strip()}")
                    failed += 1
                    continue
                got = json.loads(out.stdout)["surface"]
                bad = []
                for name in NAMES:
                    w, g = want[name], got[name]
                    rel = abs(g - w) / abs(w)
                    worst = max(worst, rel)
                    if not rel <= TOL:
                        bad.append(f"{name} {g!r} vs {w!r} ({rel:.1e})")
                if got["lambda_s"] != lambda_s or got["lambda_c"] != lambda_c:
                    bad.append(f"lambda_s/lambda_c recorded as {got['lambda_s']}, {got['lambda_c']}")
                if bad:
                    failed += 1
                    print(f"FAIL {fmt} {flags}: " + "; ".join(bad))
                else:
                    passed += 1
    print(f"largest relative difference {worst:.2e} (tolerance {TOL:g})")
    print(f"filtered_stats_check: {passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
