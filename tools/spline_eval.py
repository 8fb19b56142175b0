#!/usr/bin/env python3
"""Evaluate a table's own interpolant from its NumPy export, with NumPy alone.

Usage:
    python3 tools/spline_eval.py [KEFRIC] [--npz FILE] [--points N]

Exports the embedded default table with `KEFRIC export --npz` (or reads
FILE), reads its `metadata`, evaluates ln(mu) from `spline_ln_mu` at N random
points of the domain (default 2000) plus its corners, and compares mu with
`KEFRIC lookup --csv --exact` (the table's exact f64 kernel) at the same
points. Fails (exit 1) if any relative difference exceeds 1e-12.
"""

import json
import os
import subprocess
import sys
import tempfile

import numpy as np

TOLERANCE = 1e-12


def spline_mu(z, psi, theta, f_star):
    """mu at the points (1-D arrays) from the export `z`: the few lines a user needs."""
    interp = json.loads(z["interpolant"].tobytes())
    coef = z[interp["coefficients"]]
    coords = [np.log(psi), np.sqrt(theta), np.log(f_star)]
    cells, weights = [], []
    for x, axis in zip(coords, interp["axes"]):
        s = (x - axis["first"]) / axis["step"]
        i = np.clip(np.floor(s), 0, axis["nodes"] - 2).astype(int)
        f = s - i
        w = np.stack([(1 - f) ** 3, 3 * f**3 - 6 * f**2 + 4, -3 * f**3 + 3 * f**2 + 3 * f + 1, f**3]) / 6
        cells.append(i)
        weights.append(w)
    ln_mu = np.zeros_like(psi)
    for a in range(4):
        for b in range(4):
            for c in range(4):
                c_abc = coef[cells[0] + a, cells[1] + b, cells[2] + c]
                ln_mu += weights[0][a] * weights[1][b] * weights[2][c] * c_abc
    return np.exp(ln_mu)


def main(argv):
    kefric = "target/release/kefric"
    npz, points = None, 2000
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--npz":
            npz = args.pop(0)
        elif a == "--points":
            points = int(args.pop(0))
        else:
            kefric = a
    with tempfile.TemporaryDirectory() as tmp:
        if npz is None:
            npz = os.path.join(tmp, "default.npz")
            subprocess.run([kefric, "export", "--quiet", "--npz", npz], check=True, stdout=subprocess.DEVNULL)
        z = np.load(npz)
        meta = json.loads(z["metadata"].tobytes())
        d = meta  # the table's record: ranges psi, theta, f_star at the top level
        rng = np.random.default_rng(15)
        psi = np.exp(rng.uniform(*np.log(d["psi"]), points))
        theta = rng.uniform(*np.sqrt(d["theta"]), points) ** 2
        f_star = np.exp(rng.uniform(*np.log(d["f_star"]), points))
        # exp(ln x) may round past the domain's ends.
        psi, theta, f_star = (np.clip(v, *d[k]) for v, k in ((psi, "psi"), (theta, "theta"), (f_star, "f_star")))
        corners = np.array(np.meshgrid(d["psi"], d["theta"], d["f_star"])).reshape(3, -1)
        psi, theta, f_star = (np.concatenate([v, c]) for v, c in zip((psi, theta, f_star), corners))
        ours = spline_mu(z, psi, theta, f_star)
        rows = "\n".join(f"{float(p)!r},{float(t)!r},{float(f)!r}" for p, t, f in zip(psi, theta, f_star))
        out = subprocess.run(  # noqa: PLW1510 (the status is checked below)
            [kefric, "lookup", "--csv", "--exact"] + (["--table", os.environ["KEFRIC_TABLE"]] if "KEFRIC_TABLE" in os.environ else []),
            input="psi,theta,f_star\n" + rows + "\n",
            capture_output=True,
            text=True,
        )
        if out.returncode != 0:
            print(f"spline_eval: FAILED: kefric lookup --csv: {out.stderr.strip()}")
            return 1
        out = out.stdout.splitlines()
        assert out[0] == "psi,theta,f_star,mu,dmu_df_star,h_star", out[0]
        table = np.array([float(line.split(",")[3]) for line in out[1:]])
        assert len(table) == len(ours), (len(table), len(ours))
        rel = np.abs(ours / table - 1)
        worst = int(np.argmax(rel))
        print(
            f"spline_eval: {meta['model']} table, {len(ours)} points: max relative difference "
            f"{rel[worst]:.2e} between NumPy and kefric lookup --exact "
            f"(at psi = {psi[worst]:.6g}, theta = {theta[worst]:.6g}, F* = {f_star[worst]:.6g})"
        )
        if not rel[worst] <= TOLERANCE:
            print(f"spline_eval: FAILED: above {TOLERANCE:g}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
