#!/usr/bin/env python3
"""Check `kefric export` from the NumPy side.

Usage:
    python3 tools/check_export.py [KEFRIC] [--npz FILE]

KEFRIC is the kefric binary (e.g. target/release/kefric); without it the
script builds one with `cargo build --release` and uses that. The default
table is exported to a temporary .npz (or FILE, with --npz, is checked
instead; it must be an export of the embedded default table) and checked:

  * the array names, shapes and dtypes of the contract (README, `kefric
    export`): psi, theta, f_star (1-D, the table's nodes), mu and h_star
    (psi x theta x f_star), grid_psi, grid_theta, grid_h_star and grid_p_star,
    grid_fs_star, grid_q_star, grid_f_star, grid_mu (psi x theta x h*), the
    0-d constants beta, nu, eps_star, the interpolant spline_ln_mu and
    knots_psi, knots_theta, knots_f_star; all float64; and metadata, interpolant (1-D
    uint8, JSON with the model, fit, constants, tolerance, accuracy, format
    version and interpolation coordinates);
  * grid_mu is NaN exactly where grid_f_star <= 0;
  * the grid against `kefric eval --json --h-star` at a few grid nodes, to
    GRID_REL relative;
  * mu at a few nodes against `kefric lookup --json` (the same numbers);
  * scipy's RegularGridInterpolator over (ln psi, theta, ln f_star) of
    ln(mu), at off-node points (random ones and cell centres, the worst
    case), against `kefric eval --json --f-star` (direct integration) and
    `kefric lookup --json`, to INTERP_REL[method].

Prints "check_export: N passed, M failed" and exits 1 if anything failed.
"""

import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import scipy
from scipy.interpolate import RegularGridInterpolator

# The grid is the same computation as `kefric eval --h-star` at the same
# doubles; agreement is exact in practice.
GRID_REL = 1e-12
# Table lookups at the exported nodes are the exported numbers (printed with
# 17 significant digits, so they round-trip): equal in practice, but `kefric
# lookup` goes through `mu_with_slope`, whose arithmetic may differ from
# `mu`'s in the last bits of ln mu (|ln mu| < 10, so a few ulp is ~1e-14).
NODE_REL = 1e-13
# Relative error of mu from RegularGridInterpolator on the exported 33^3
# nodes, measured against `kefric lookup` at 2000 points (half random, half
# cell centres in (ln psi, sqrt theta, ln F*)) of the default table:
#   cubic:  max 3.6e-4, 99th percentile 2.6e-4, median 7.5e-6;
#   linear: max 1.3e-2, 99th percentile 1.0e-2, median 1.2e-3.
# Direct integration differs from the lookup by at most the table's 1e-4.
# The bounds asserted (about twice the measured worst case):
INTERP_REL = {"cubic": 1e-3, "linear": 3e-2}
# The table's own promise (lookup vs direct integration).
TABLE_REL = 1e-4

SCALARS = ["beta", "nu", "eps_star"]


class Checker:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print(f"FAIL: {what}", file=sys.stderr)
        return ok


def rel(a, b):
    a, b = float(a), float(b)
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def find_kefric(root):
    """Builds the release binary with cargo and returns its path."""
    out = subprocess.run(
        ["cargo", "build", "--release", "--quiet", "--bin", "kefric",
         "--message-format=json"],
        cwd=root, capture_output=True, text=True, check=True,
    ).stdout
    for line in out.splitlines():
        msg = json.loads(line)
        if msg.get("reason") == "compiler-artifact" and msg.get("executable"):
            if msg["target"]["name"] == "kefric":
                return msg["executable"]
    sys.exit("check_export: cargo built no kefric executable")


def kefric_json(kefric, *args):
    out = subprocess.run(
        [kefric, *args, "--json"], capture_output=True, text=True
    )
    if out.returncode != 0:
        raise RuntimeError(f"kefric {' '.join(args)}: {out.stderr.strip()}")
    return [json.loads(line) for line in out.stdout.splitlines()]


def num(x):
    """A float as a command-line argument that round-trips exactly."""
    return repr(float(x))


def main(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    npz_path = None
    kefric = None
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--npz":
            npz_path = args.pop(0)
        elif a in ("-h", "--help"):
            print(__doc__)
            return 0
        elif kefric is None:
            kefric = a
        else:
            sys.exit(f"check_export: unexpected argument {a!r}")
    kefric = os.path.abspath(kefric) if kefric else find_kefric(root)
    c = Checker()

    with tempfile.TemporaryDirectory() as tmp:
        if npz_path is None:
            npz_path = os.path.join(tmp, "t.npz")
            subprocess.run(
                [kefric, "export", "--quiet", "--npz", npz_path], check=True,
                stdout=subprocess.DEVNULL,
            )
        with np.load(npz_path) as z:
            a = {k: z[k] for k in z.files}

    # Names, dtypes, shapes.
    n = {k: a[k].shape[0] if a.get(k) is not None and a[k].ndim == 1 else -1
         for k in ["psi", "theta", "f_star", "grid_psi", "grid_theta", "grid_h_star"]}
    cube = (n["psi"], n["theta"], n["f_star"])
    gcube = (n["grid_psi"], n["grid_theta"], n["grid_h_star"])
    shapes = {
        "psi": (n["psi"],), "theta": (n["theta"],), "f_star": (n["f_star"],),
        "mu": cube, "h_star": cube,
        "grid_psi": (n["grid_psi"],), "grid_theta": (n["grid_theta"],),
        "grid_h_star": (n["grid_h_star"],),
        **{k: gcube for k in ["grid_p_star", "grid_fs_star", "grid_q_star",
                              "grid_f_star", "grid_mu"]},
        **{k: () for k in SCALARS},
    }
    # The table's own interpolant and the self-description.
    texts = {}
    for name in ["metadata", "interpolant"]:
        c.check(a.get(name) is not None and a[name].dtype == np.uint8 and a[name].ndim == 1,
                f"{name}: not 1-D uint8")
        texts[name] = json.loads(a[name].tobytes()) if name in a else {}
    meta, interp = texts["metadata"], texts["interpolant"]
    # The table's record: the names of `kefric info --json` and Python's Table.info.
    for key in ["psi", "theta", "f_star", "model", "fit", "beta", "nu", "eps_star", "tolerance", "accuracy",
                "build", "precision", "format_version", "bytes", "crc32"]:
        c.check(key in meta, f"metadata: {key} missing")
    c.check(set(meta.get("accuracy", {})) == {"max_rel", "p99_rel", "samples", "worst"}, "metadata: accuracy keys")
    axes = interp.get("axes", [])
    c.check([x.get("coordinate") for x in axes] == ["ln(psi)", "sqrt(theta)", "ln(f_star)"]
            and interp.get("quantity") == "ln(mu)", "interpolant: interpolation coordinates")
    if len(axes) == 3:
        shapes["spline_ln_mu"] = tuple(x["nodes"] + 2 for x in axes)
        for k, x in zip(["psi", "theta", "f_star"], axes):
            shapes[f"knots_{k}"] = (x["nodes"],)
    c.check(set(a) - {"metadata", "interpolant"} == set(shapes),
            f"array names {sorted(a)} != {sorted(shapes)} + metadata, interpolant")
    for k, shape in shapes.items():
        if not c.check(k in a, f"{k} missing"):
            continue
        c.check(a[k].dtype == np.float64, f"{k}: dtype {a[k].dtype}")
        c.check(a[k].shape == shape and min(shape, default=5) >= 5,
                f"{k}: shape {a[k].shape}, want {shape}")
    if c.failed:
        return finish(c)

    # Axes and values.
    for k in ["psi", "theta", "f_star", "grid_psi", "grid_theta", "grid_h_star"]:
        c.check(np.all(np.diff(a[k]) > 0), f"{k} is not increasing")
    c.check(a["psi"][0] > 0 and a["f_star"][0] > 0 and a["theta"][0] >= 0,
            "axes start outside the model's range")
    c.check(np.all(np.isfinite(a["mu"])) and np.all(a["mu"] > 0), "mu not finite and positive")
    c.check(np.all(np.isfinite(a["h_star"])), "h_star not finite")
    for k in ["grid_p_star", "grid_fs_star", "grid_q_star", "grid_f_star"]:
        c.check(np.all(np.isfinite(a[k])), f"{k} not finite")
    nan = np.isnan(a["grid_mu"])
    c.check(np.array_equal(nan, a["grid_f_star"] <= 0),
            f"grid_mu NaN at {nan.sum()} nodes, grid_f_star <= 0 at "
            f"{(a['grid_f_star'] <= 0).sum()}")
    c.check(np.all(np.isfinite(a["grid_mu"][~nan])), "grid_mu not finite where F* > 0")

    # The model constants (eval reports its defaults, which the default table uses).
    ref = kefric_json(kefric, "eval", "--psi", "1", "--theta", "0", "--h-star", "1")[0]
    for k in SCALARS:
        c.check(float(a[k]) == ref[k], f"{k} = {float(a[k])}, eval says {ref[k]}")
    model = [f for k in SCALARS for f in (f"--{k.replace('_', '-')}", num(a[k]))]

    # The integration grid against direct evaluation at h*.
    gi, gj, gk = gcube
    nodes = [(0, 0, 0), (gi - 1, gj - 1, gk - 1), (gi // 2, gj // 3, gk // 4),
             (gi // 3, gj - 2, gk // 2), (2, 5, gk - 3)]
    # One node where F* <= 0 (mu null), if any.
    bad = np.argwhere(nan)
    if len(bad):
        nodes.append(tuple(bad[len(bad) // 2]))
    for i, j, k in nodes:
        row = kefric_json(kefric, "eval", "--psi", num(a["grid_psi"][i]),
                          "--theta", num(a["grid_theta"][j]),
                          "--h-star", num(a["grid_h_star"][k]), *model)[0]
        for q in ["p_star", "fs_star", "q_star", "f_star", "mu"]:
            got = a["grid_" + q][i, j, k]
            want = row[q]
            if want is None:
                c.check(np.isnan(got), f"grid_{q}[{i},{j},{k}] = {got}, eval: null")
            else:
                c.check(rel(got, want) <= GRID_REL,
                        f"grid_{q}[{i},{j},{k}] = {got!r}, eval: {want!r} "
                        f"(rel {rel(got, want):.2e} > {GRID_REL:g})")

    # mu at table nodes: the lookup's numbers, within the table's promise of direct integration.
    ni, nj, nk = cube
    for i, j, k in [(0, 0, 0), (ni - 1, nj - 1, nk - 1), (ni // 2, nj // 2, nk // 2),
                    (3, nj - 4, 7), (ni - 5, 1, nk - 2)]:
        p, t, f = a["psi"][i], a["theta"][j], a["f_star"][k]
        look = kefric_json(kefric, "lookup", "--psi", num(p), "--theta", num(t),
                           "--f-star", num(f))[0]["mu"]
        c.check(rel(a["mu"][i, j, k], look) <= NODE_REL,
                f"mu[{i},{j},{k}] = {a['mu'][i, j, k]!r}, lookup: {look!r}")
        exact = kefric_json(kefric, "eval", "--psi", num(p), "--theta", num(t),
                            "--f-star", num(f), *model)[0]
        c.check(rel(a["mu"][i, j, k], exact["mu"]) <= TABLE_REL,
                f"mu[{i},{j},{k}] = {a['mu'][i, j, k]!r}, direct: {exact['mu']!r}")
        c.check(abs(a["h_star"][i, j, k] - exact["h_star"]) <= TABLE_REL * max(1.0, abs(exact["h_star"])),
                f"h_star[{i},{j},{k}] = {a['h_star'][i, j, k]!r}, direct: {exact['h_star']!r}")

    # Interpolation off the nodes.
    axes = (np.log(a["psi"]), a["theta"], np.log(a["f_star"]))
    try:
        interp = RegularGridInterpolator(axes, np.log(a["mu"]), method="cubic")
        method = "cubic"
    except ValueError:
        interp = RegularGridInterpolator(axes, np.log(a["mu"]), method="linear")
        method = "linear"
    tol = INTERP_REL[method]
    rng = np.random.default_rng(2004)
    sq = np.sqrt(a["theta"])
    points = []
    for m in range(24):
        if m % 2 == 0:  # uniform in the table's coordinates
            p = rng.uniform(axes[0][0], axes[0][-1])
            t = rng.uniform(sq[0], sq[-1]) ** 2
            f = rng.uniform(axes[2][0], axes[2][-1])
        else:  # the centre of a random cell: where interpolation errs most
            i, j, k = (rng.integers(0, len(x) - 1) for x in axes)
            p = (axes[0][i] + axes[0][i + 1]) / 2
            t = ((sq[j] + sq[j + 1]) / 2) ** 2
            f = (axes[2][k] + axes[2][k + 1]) / 2
        points.append((float(np.exp(p)), float(t), float(np.exp(f))))
    worst = {"eval": 0.0, "lookup": 0.0, "table": 0.0}
    for p, t, f in points:
        got = float(np.exp(interp([[np.log(p), t, np.log(f)]])[0]))
        exact = kefric_json(kefric, "eval", "--psi", num(p), "--theta", num(t),
                            "--f-star", num(f), *model)[0]["mu"]
        look = kefric_json(kefric, "lookup", "--psi", num(p), "--theta", num(t),
                           "--f-star", num(f))[0]["mu"]
        for name, want, bound in [("eval", exact, tol), ("lookup", look, tol),
                                  ("table", None, TABLE_REL)]:
            e = rel(look, exact) if name == "table" else rel(got, want)
            worst[name] = max(worst[name], e)
            c.check(e <= bound,
                    f"{name} at psi={p!r}, theta={t!r}, f_star={f!r}: rel {e:.2e} > {bound:g}")
    print(f"  scipy {scipy.__version__} {method} interpolation of ln mu over "
          f"(ln psi, theta, ln f_star), {len(points)} off-node points: max rel error "
          f"{worst['eval']:.2e} vs eval, {worst['lookup']:.2e} vs lookup (bound {tol:g}); "
          f"lookup vs eval {worst['table']:.2e} (bound {TABLE_REL:g})")
    return finish(c)


def finish(c):
    print(f"check_export: {c.passed} passed, {c.failed} failed")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
