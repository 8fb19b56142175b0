#!/usr/bin/env python3
"""Table.mu against SciPy's RegularGridInterpolator on `kefric export` output.

Usage: python3 python/bench.py [--rounds N] [--quick]

Same 100,000 random in-domain points for every contender; the contenders
run interleaved, ROUNDS times, and the median time per query is reported.
RGI interpolates ln(mu) over the table's own coordinates (ln psi, sqrt theta,
ln F*) on the exported nodes (linear and cubic). Errors are against direct
integration (kf.Model) at 2,000 of the points. Also Curve.mu on 10^6 loads.
--quick (CI) runs fewer rounds and checks only the accuracy ratio.
"""

import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.interpolate import RegularGridInterpolator

import ke_friction as kf

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KEFRIC = os.environ.get("KEFRIC", os.path.join(ROOT, "target", "release", "kefric"))


def main(argv):
    quick = "--quick" in argv
    rounds = int(argv[argv.index("--rounds") + 1]) if "--rounds" in argv else (3 if quick else 15)
    table = kf.Table.default()
    info = table.info
    with tempfile.TemporaryDirectory() as tmp:
        npz = os.path.join(tmp, "default.npz")
        subprocess.run([KEFRIC, "export", "--quiet", "--npz", npz], check=True, stdout=subprocess.DEVNULL)
        z = np.load(npz)
        grid = (np.log(z["psi"]), np.sqrt(z["theta"]), np.log(z["f_star"]))
        values = np.log(z["mu"])
    rgi = {m: RegularGridInterpolator(grid, values, method=m) for m in ("linear", "cubic")}

    rng = np.random.default_rng(2004)
    n = 100_000
    lo_hi = lambda k: info[k]  # noqa: E731
    psi = np.clip(np.exp(rng.uniform(*np.log(lo_hi("psi")), n)), *lo_hi("psi"))
    theta = np.clip(rng.uniform(*np.sqrt(lo_hi("theta")), n) ** 2, *lo_hi("theta"))
    f = np.clip(np.exp(rng.uniform(*np.log(lo_hi("f_star")), n)), *lo_hi("f_star"))
    coords = np.column_stack([np.log(psi), np.sqrt(theta), np.log(f)])

    contenders = {
        "Table.mu": lambda: table.mu(psi, theta, f),
        "RGI linear": lambda: np.exp(rgi["linear"](coords)),
        "RGI cubic": lambda: np.exp(rgi["cubic"](coords)),
    }
    times = {k: [] for k in contenders}
    results = {}
    for _ in range(rounds):
        for name, run in contenders.items():
            t0 = time.perf_counter()
            results[name] = run()
            times[name].append((time.perf_counter() - t0) / n * 1e9)

    m = 2000
    exact = np.array([kf.Model(psi[i], theta[i]).at_f_star(f[i]).mu for i in range(m)])
    errors = {k: float(np.max(np.abs(results[k][:m] / exact - 1))) for k in contenders}
    ns = {k: statistics.median(v) for k, v in times.items()}
    print(f"{n} random points in the default table's domain, median of {rounds} interleaved rounds;")
    print(f"max relative error against direct integration at {m} of them")
    print(f"{'contender':<12} {'ns/query':>10} {'speed-up':>9} {'max error':>10} {'error ratio':>12}")
    for k in contenders:
        print(f"{k:<12} {ns[k]:>10.1f} {ns[k] / ns['Table.mu']:>8.1f}x {errors[k]:>10.2e} "
              f"{errors[k] / errors['Table.mu']:>11.0f}x")

    curve = table.curve(1.0, 0.003)
    loads = np.clip(np.exp(rng.uniform(np.log(1e-5), np.log(0.1), 1_000_000)), 1e-5, 0.1)
    ct = []
    for _ in range(rounds):
        t0 = time.perf_counter()
        curve.mu(loads)
        ct.append((time.perf_counter() - t0) / loads.size * 1e9)
    print(f"Curve.mu     {statistics.median(ct):>10.1f} ns/query over 10^6 loads")

    ratio = errors["RGI linear"] / errors["Table.mu"]
    if quick:
        ok = ratio >= 100
        print(f"bench --quick: error ratio against linear RGI {ratio:.0f}x ({'ok' if ok else 'FAILED: < 100x'})")
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
