#!/usr/bin/env python3
"""Mesh refinement of the GetFEM contact examples: where the Nitsche brick
and the nodal brick differ, and by how much.

Usage: python3 python/examples/getfem_refinement.py [--meshes 80x8,160x16,320x32]
    [--solvers newton,fixed,nodal] [--constant-mu MU] [--gamma0 G] [--out DIR]

The block of python/examples/getfem_contact.py, sheared to gross sliding,
on each mesh (elements along x by elements along y), with any of
- ``newton``: the Nitsche brick, mu(p) the GWFL closed form inside its
  Newton solve (python/examples/getfem_nitsche.py);
- ``fixed``: the Nitsche brick, mu frozen at its integration points and
  iterated to a fixed point with the law's own mu (the same pressure at the
  same points: it differs from ``newton`` by the closed form's error only);
- ``nodal``: the nodal brick's fixed point (getfem_contact.py).
It prints and writes (DIR/getfem_refinement.json) each one's Fx/Fy, Fy,
Newton solves or iterations and seconds, and the relative gaps between
them. ``--constant-mu`` replaces the law by a constant (the ablation: at
gross sliding Fx/Fy is then mu in every formulation, whatever the pressure
field); ``--gamma0`` sets the Nitsche parameter in units of E. A study,
not a CI stage: 320 x 32 takes minutes. docs/REFERENCE.md ("GetFEM")
records its results.
"""

import argparse
import json
import os
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import getfem_contact as nodal  # noqa: E402
import getfem_nitsche as nitsche  # noqa: E402

import getfem as gf  # noqa: E402


class ConstantLaw:
    """A friction law with one mu at every pressure (the ablation)."""

    def __init__(self, mu, law):
        self.value = mu
        self.range = law.range

    def mu(self, p):
        return np.full(np.shape(p), self.value) if np.ndim(p) else self.value


def mesh_list(text):
    out = []
    for item in text.split(","):
        try:
            nx, ny = (int(v) for v in item.lower().split("x"))
        except ValueError:
            raise argparse.ArgumentTypeError(f"{item!r} is not NXxNY (e.g. 160x16)") from None
        if not (2 <= nx <= 2000 and 1 <= ny <= 200):
            raise argparse.ArgumentTypeError(f"{item!r} outside 2..2000 x 1..200 elements")
        out.append((nx, ny))
    return out


def solver_list(text):
    names = text.split(",")
    for n in names:
        if n not in ("newton", "fixed", "nodal"):
            raise argparse.ArgumentTypeError(f"{n!r} is not one of newton, fixed, nodal")
    return names


def one(kind, law, expression, nx, ny, gamma0, pressure):
    t0, cpu0 = time.perf_counter(), time.process_time()
    if kind == "nodal":
        c = nodal.Contact(law, nx, ny)
        iterations, plateau = nitsche.nodal_ramp(c)
        work = {"solves": c.solves, "fixed_point_iterations": iterations}
    else:
        c = nitsche.Nitsche(law, expression if kind == "newton" else None, nx, ny, gamma0, pressure)
        steps, plateau = nitsche.ramp(c)
        work = {"solves": c.solves, "newton_iterations": c.newton}
    seconds, cpu = time.perf_counter() - t0, time.process_time() - cpu0
    fx, fy = (abs(float(v)) for v in c.top_reaction())
    return {"fx": fx, "fy": fy, "fx_over_fy": fx / fy, "gross_sliding": plateau, "seconds": seconds, "cpu_seconds": cpu,
            **work}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--meshes", type=mesh_list, default=mesh_list("80x8,160x16,320x32"))
    parser.add_argument("--solvers", type=solver_list, default=solver_list("newton,fixed,nodal"))
    parser.add_argument("--constant-mu", type=float, default=None, help="a constant mu instead of the law")
    parser.add_argument("--gamma0", type=float, default=nitsche.GAMMA0_OVER_E,
                        help="the Nitsche parameter in units of E (default: %(default)s)")
    parser.add_argument("--pressure", choices=("contact", "stress"), default=nitsche.PRESSURE,
                        help="mu's argument in the Nitsche brick (default: %(default)s)")
    parser.add_argument("--out", default=tempfile.gettempdir(), help="the folder to write to (default: %(default)s)")
    parser.add_argument("--psi", type=float, default=1.0)
    parser.add_argument("--theta", type=float, default=0.001)
    parser.add_argument("--hardness", type=float, default=2e9)
    args = parser.parse_args(argv)
    if args.constant_mu is not None and not (0 < args.constant_mu <= 10):
        parser.error(f"--constant-mu: {args.constant_mu} outside (0, 10]")
    if not (0 < args.gamma0 <= 1e6):
        parser.error(f"--gamma0: {args.gamma0} outside (0, 1e6]")
    gf.util_trace_level(0)
    try:
        law = nodal.make_law(args)
    except ValueError as e:
        parser.error(str(e))
    expression, degree, fit_error = nitsche.closed_form(law)
    if args.constant_mu is not None:
        law = ConstantLaw(args.constant_mu, law)
        expression, fit_error = f"({args.constant_mu!r}+0*t)", 0.0
    rows = []
    for nx, ny in args.meshes:
        row = {"mesh": [nx, ny], "h": nodal.WIDTH / nx}
        for kind in args.solvers:
            row[kind] = one(kind, law, expression, nx, ny, args.gamma0, args.pressure)
            r = row[kind]
            print(f"{nx}x{ny} {kind:6s} Fx/Fy {r['fx_over_fy']:.6f} Fy {r['fy']:.6g} N/m, {r['solves']} solves"
                  + (f" ({r['newton_iterations']} Newton iterations)" if "newton_iterations" in r else "")
                  + f", {r['seconds']:.1f} s ({r['cpu_seconds']:.1f} s CPU)" + ("" if r["gross_sliding"] else " NO PLATEAU"), flush=True)
        for a, b in (("newton", "fixed"), ("newton", "nodal"), ("fixed", "nodal")):
            if a in row and b in row:
                row[f"{a}_vs_{b}"] = row[a]["fx_over_fy"] / row[b]["fx_over_fy"] - 1
                row[f"{a}_vs_{b}_fy"] = row[a]["fy"] / row[b]["fy"] - 1
                print(f"{nx}x{ny} {a} vs {b}: Fx/Fy {row[f'{a}_vs_{b}']:+.3e}, Fy {row[f'{a}_vs_{b}_fy']:+.3e}")
        rows.append(row)
    record = {"constant_mu": args.constant_mu, "gamma0_over_e": args.gamma0, "pressure": args.pressure, "fit_error": fit_error,
              "law": None if args.constant_mu is not None else nodal.law_inputs(law), "rows": rows}
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "getfem_refinement.json"), "w") as f:
        json.dump(record, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
