#!/usr/bin/env python3
"""How the error of a tensor spline of ln μ depends on its degree and spacing.

Reads the `.npz` export of a dense table, whose `mu` holds μ at the table's
nodes (exact there, since the table interpolates its nodes), takes every
k-th node on each axis, fits the interpolating tensor spline of degree 2
(C¹, 3×3×3 coefficients per lookup) or 3 (C², 4×4×4, what the tables use)
in the table's coordinates (ln ψ, √θ, ln F*), and reports the largest
relative error of μ at all dense nodes in the middle half of each axis (away
from the ends, where scipy's end conditions differ from the tables' ghost
nodes).

    cargo run --release -- build --nodes 97,97,97 --precision f64 \
        --tolerance 1e-3 --quiet --out /tmp/dense.kft
    cargo run --release -- export --table /tmp/dense.kft --npz /tmp/dense.npz
    python3 tools/interp_order.py /tmp/dense.npz
"""
import sys

import numpy as np
from scipy.interpolate import make_interp_spline


def main(path):
    d = np.load(path)
    mu = d["mu"]
    coords = [np.log(d["psi"]), np.sqrt(d["theta"]), np.log(d["f_star"])]
    n = mu.shape[0] - 1
    if any(m != n + 1 for m in mu.shape):
        sys.exit(f"{path}: expected a cubic grid, got {mu.shape}")
    mid = slice(n // 4, n - n // 4 + 1)
    print("degree  intervals per axis  max relative error of mu (middle half)")
    for degree in (2, 3):
        for k in range(2, 9):
            if n % k:
                continue
            idx = np.arange(0, n + 1, k)
            values = np.log(mu)[np.ix_(idx, idx, idx)]
            for axis in range(3):
                spline = make_interp_spline(coords[axis][idx], values, k=degree, axis=axis)
                values = spline(coords[axis])
            err = np.abs(np.exp(values) / mu - 1)[mid, mid, mid]
            print(f"{degree:6}  {n // k:18}  {err.max():.2e}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: interp_order.py DENSE.npz")
    main(sys.argv[1])
