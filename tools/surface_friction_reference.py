#!/usr/bin/env python3
"""Independent end-to-end reference: from a measured (synthetic) surface to
the static friction coefficient, MODEL.md sections 10 -> 1-2 -> 4 (and 9).
Test oracle for tests/it/surface_friction.rs (the crate's
`topography::Surface` -> `Surface::params` -> `Load::friction`); it shares
no code with the crate and imports nothing from it.

Usage (from the repository root):

    python3 tools/surface_friction_reference.py > tests/data/surface_friction_reference.json

(about a minute or two: one root solve per case, load and distribution at
mp.dps = 30).

The chain, each step from another independent reference beside this file:

1. The height maps are the synthetic surfaces of tools/surface_reference.py
   (its splitmix64 generator and case list, imported; the Rust test rebuilds
   them as tests/it/topography_stats.rs does), and their statistics sigma,
   Sk, K, R, eta (plane detrend, finite differences) are its NumPy
   `stats` (MODEL.md section 10).
2. The materials below and MODEL.md sections 1-2, in mpmath from the float64
   statistics (each input taken as its exact binary value):
       1/E = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,   K = 0.454 + 0.41 nu1,
       beta = eta R sigma,   s = (1 - 3.717e-4/beta^2)^(1/2),
       sigma_s = s sigma,    psi = (2E/(pi K H)) (sigma_s/R)^(1/2),
       theta = dgamma/(sigma H),   eps* = eps/sigma,
       F* = F/(A_n H)        (nu = nu1, the softer material's).
   beta is also computed as alpha^(1/2)/(16 sqrt(3 pi)) from the section-10
   alpha as a consistency check (the two agree to rounding).
3. mu at F*: the Gaussian model of tools/reference.py (solve_h + evaluate,
   fit "consistent"), and the Pearson(Sk, K) model of
   tools/nongaussian_reference.py (its density and Model class, solved the
   way its solve_mu does: bracket at dps 15, secant at dps 30), both with
   the surface's beta, nu, eps* (not the defaults).

The materials (aluminium-like on steel) put psi in the paper's range
(0.5-8) and theta in 1e-4-1e-2 for the synthetic maps as they are
(sigma ~ 80 nm, R ~ 10-33 um on the grids of surface_reference.py);
10 N and 50 N on 10 mm^2 give F* = 1e-3 and 5e-3.

JSON: {"generator", "numpy", "mpmath", "materials": {e1, nu1, e2, nu2,
hardness, delta_gamma, epsilon}, "cases": [{"name", "nx", "ny", "dx", "dy",
"seed", "missing", "detrend", "derivative", "stats": {sigma, skewness,
kurtosis, radius, eta, alpha, beta (section 10, NumPy)}, "params": {psi,
theta, beta, nu, eps_star, e_star, k, s, sigma_s, beta_from_alpha},
"loads": [{"force", "area", "f_star", "gaussian": {...}, "pearson":
{...}}]}]}, each model result {"h_star", "d_star", "p_star", "fs_star",
"q_star", "mu", "separation" (h* sigma, m), "friction_force" (mu F, N)}
plus "pearson_type" for Pearson.  Numbers are doubles (repr, round-trip
exact); mpmath results are float(mpf), round to nearest.
"""

import json
import os
import sys
import time

import mpmath
import numpy as np
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nongaussian_reference as ng  # noqa: E402
import reference as ref  # noqa: E402
import surface_reference as sr  # noqa: E402

mp.dps = 30

MATERIALS = {
    "e1": 70e9,
    "nu1": 0.33,
    "e2": 200e9,
    "nu2": 0.31,
    "hardness": 1e9,
    "delta_gamma": 0.5,
    "epsilon": 0.4e-9,
}
CASE_NAMES = ["map_plane", "map_other"]
LOADS = [(10.0, 1e-5), (50.0, 1e-5)]  # (force N, nominal area m^2)


def D(s):
    return mpf(s)


def params(st, m):
    """MODEL.md sections 1-2 from the section-10 statistics (mpmath)."""
    sigma, radius, eta = mpf(st["sigma"]), mpf(st["radius"]), mpf(st["eta"])
    nu1, nu2 = mpf(m["nu1"]), mpf(m["nu2"])
    e_star = 1 / ((1 - nu1 ** 2) / mpf(m["e1"]) + (1 - nu2 ** 2) / mpf(m["e2"]))
    k = D("0.454") + D("0.41") * nu1
    beta = eta * radius * sigma
    s = mp.sqrt(1 - D("3.717e-4") / beta ** 2)
    sigma_s = s * sigma
    h = mpf(m["hardness"])
    psi = 2 * e_star / (mp.pi * k * h) * mp.sqrt(sigma_s / radius)
    theta = mpf(m["delta_gamma"]) / (sigma * h)
    eps_star = mpf(m["epsilon"]) / sigma
    beta_alpha = mp.sqrt(mpf(st["alpha"])) / (16 * mp.sqrt(3 * mp.pi))
    return {
        "psi": psi, "theta": theta, "beta": beta, "nu": nu1, "eps_star": eps_star,
        "e_star": e_star, "k": k, "s": s, "sigma_s": sigma_s, "beta_from_alpha": beta_alpha,
    }


def gaussian_mu(p, f):
    """h* and the contact at F* = f, Gaussian heights (tools/reference.py).
    Inputs are the doubles of the JSON (what the Rust side is fed)."""
    q = ref.Params(p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"])
    h = ref.solve_h("ke", q, mpf(f))
    r = ref.evaluate("ke", "consistent", q, h)
    r["h_star"] = h
    return r, None


def pearson_mu(p, f, sk, kurt):
    """h* and the contact at F* = f, Pearson(Sk, K) asperity heights
    (tools/nongaussian_reference.py's solve_mu, with the surface's beta, nu
    and eps*)."""
    _, r, dens = ng.solve_mu(p["psi"], p["theta"], "pearson", sk, kurt, f, dps=mp.dps,
                             beta=p["beta"], nu=p["nu"], eps_star=p["eps_star"])
    return r, dens.ptype


def record(r, sigma, force):
    out = {k: float(r[k]) for k in ("h_star", "d_star", "p_star", "fs_star", "q_star", "f_star")}
    out["mu"] = float(r["mu"])
    out["separation"] = float(r["h_star"] * mpf(sigma))
    out["friction_force"] = float(r["mu"] * mpf(force))
    return out


def main():
    t0 = time.time()
    cases = []
    for case in sr.CASES:
        name, nx, ny, dx, dy, seed, missing, detrend, derivative = case
        if name not in CASE_NAMES:
            continue
        st = sr.stats(sr.case_surface(case), dx, dy, detrend, derivative)
        pm = params(st, MATERIALS)
        pd = {k: float(v) for k, v in pm.items()}
        loads = []
        for force, area in LOADS:
            f = float(mpf(force) / (mpf(area) * mpf(MATERIALS["hardness"])))
            g, _ = gaussian_mu(pd, f)
            pr, ptype = pearson_mu(pd, f, st["skewness"], st["kurtosis"])
            for r in (g, pr):
                if r["mu"] is None or abs(r["f_star"] / mpf(f) - 1) > mpf("1e-18"):
                    sys.exit(f"{name}: F* = {f}: no solution (F*(h*) = {r['f_star']})")
            rp = record(pr, st["sigma"], force)
            rp["pearson_type"] = ptype
            loads.append({
                "force": force, "area": area, "f_star": f,
                "gaussian": record(g, st["sigma"], force), "pearson": rp,
            })
            print("[%6.1f s] %s F = %g N: F* = %g, psi = %.6g, theta = %.6g, beta = %.6g, "
                  "eps* = %.6g; Gaussian h* = %.10f mu = %.10g; Pearson(%.4g, %.4g) type %s "
                  "h* = %.10f mu = %.10g"
                  % (time.time() - t0, name, force, f, pd["psi"], pd["theta"], pd["beta"],
                     pd["eps_star"], g["h_star"], g["mu"], st["skewness"], st["kurtosis"],
                     ptype, pr["h_star"], pr["mu"]), file=sys.stderr, flush=True)
        keep = ("sigma", "skewness", "kurtosis", "radius", "eta", "alpha", "beta", "m2", "m4")
        cases.append({
            "name": name, "nx": nx, "ny": ny, "dx": dx, "dy": dy, "seed": seed,
            "missing": missing, "detrend": detrend, "derivative": derivative,
            "stats": {k: st[k] for k in keep}, "params": pd, "loads": loads,
        })
    doc = {
        "generator": ("python3 tools/surface_friction_reference.py > "
                      "tests/data/surface_friction_reference.json (Python %s, mp.dps = %d)"
                      % (sys.version.split()[0], mp.dps)),
        "numpy": np.__version__,
        "mpmath": mpmath.__version__,
        "materials": MATERIALS,
        "cases": cases,
    }
    json.dump(doc, sys.stdout, indent=1)
    sys.stdout.write("\n")
    print("done in %.0f s" % (time.time() - t0), file=sys.stderr)


if __name__ == "__main__":
    main()
