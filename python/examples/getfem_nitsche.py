#!/usr/bin/env python3
"""The friction law inside GetFEM's Newton solve: mu(p) as a GWFL function
in the Nitsche contact brick, against the nodal brick's fixed point.

Usage: python3 python/examples/getfem_nitsche.py [--out DIR] [--psi P] [--theta T] [--hardness H]

The block of python/examples/getfem_contact.py (an elastic steel block with
a gently rounded bottom, pressed on a rigid flat, then sheared to gross
sliding) with GetFEM's Nitsche contact brick, whose friction coefficient is
any GWFL expression, differentiated by GetFEM: mu(p) of the normal stress
p = -sigma_nn is a GWFL function (``gf.asm_define_function``), so every
load step is one Newton solve, with no fixed point pressure <-> mu.

The GWFL function is a closed form of ke_friction's law: a polynomial in
the log-pressure (Chebyshev fit on the law's pressure range, clamped to it
as the law's "clamp" policy does), of the lowest degree whose relative
error against the law is within FIT_TOLERANCE at FIT_POINTS log-spaced
pressures; that error is measured and printed.

Both solves slide the block: at gross sliding Fx/Fy is the mean of mu(p)
weighted by the pressure over the contact (checked against the Nitsche
solution's own integrals to 1e-3). The example checks that the
Nitsche solve's reaction ratio Fx/Fy matches the nodal brick's fixed point
(python/examples/getfem_contact.py, the same block and ramp) within
COMPARE_TOLERANCE, and prints the iterations and time of both. It writes
DIR/getfem_nitsche.json and, with matplotlib, DIR/getfem_nitsche.png;
exits 1 when a check fails.

GetFEM comes from Debian (``apt-get install python3-getfem
python3-matplotlib``, for the system ``/usr/bin/python3``); ke_friction
goes into a venv made with ``/usr/bin/python3 -m venv
--system-site-packages``, with no NumPy upgrade inside it.
"""

import argparse
import json
import os
import sys
import tempfile
import time

import numpy as np

import getfem as gf
import ke_friction as kf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import getfem_contact as nodal  # noqa: E402

#: The closed form's worst relative error against the law, at FIT_POINTS
#: log-spaced pressures over the law's range.
FIT_TOLERANCE = 1e-4
FIT_POINTS = 4001
#: The Nitsche solve's Fx/Fy against the nodal fixed point's, relative:
#: the two discretise the contact differently (integration points against
#: nodes), which shifts the pressures a little; mu(p) then moves by
#: dmu/dlnp times that shift.
COMPARE_TOLERANCE = 5e-3
#: The Nitsche parameter gamma0 (the penalty gamma0/h), in units of E.
GAMMA0_OVER_E = 1.0
#: The Nitsche variant: 0 (no second derivative of the Neumann term), 1
#: (symmetric) or -1 (skew-symmetric).
THETA = 0.0


def closed_form(law, tolerance=FIT_TOLERANCE, points=FIT_POINTS):
    """A GWFL expression of t (a pressure, Pa) for mu(t): a polynomial in
    the scaled log-pressure s in [-1, 1], t clamped to the law's range;
    the lowest degree within `tolerance`. Returns (expression, degree,
    measured error)."""
    lo, hi = law.range
    p = np.geomspace(lo, hi, points)
    mu = law.mu(p)
    a, b = np.log(lo), np.log(hi)
    s = (2 * np.log(p) - a - b) / (b - a)
    for degree in range(2, 31):
        coef = np.polynomial.chebyshev.Chebyshev.fit(s, mu, degree, domain=[-1, 1]).convert(
            kind=np.polynomial.Polynomial).coef
        error = float(np.max(np.abs(np.polynomial.polynomial.polyval(s, coef) / mu - 1)))
        if error <= tolerance:
            break
    else:
        raise RuntimeError(f"no polynomial of degree <= 30 fits the law within {tolerance}")
    arg = f"((2*log(min(max(t,{lo!r}),{hi!r}))-({a + b!r}))/({b - a!r}))"
    horner = repr(coef[-1])
    for c in coef[-2::-1]:
        horner = f"({horner})*s+({c!r})"
    return horner.replace("s", arg), degree, error


class Nitsche:
    """The block with the Nitsche contact brick, friction kef_mu(p)."""

    def __init__(self, law, expression):
        self.law = law
        self.mesh, self.mfu, mfs, self.mim = nodal.body()
        gf.asm_define_function("kef_mu", 1, expression)
        lam = nodal.YOUNG * nodal.POISSON / ((1 + nodal.POISSON) * (1 - 2 * nodal.POISSON))
        shear = nodal.YOUNG / (2 * (1 + nodal.POISSON))
        md = gf.Model("real")
        md.add_fem_variable("u", self.mfu)
        md.add_initialized_data("lambda", [lam])
        md.add_initialized_data("mu_lame", [shear])
        md.add_isotropic_linearized_elasticity_brick(self.mim, "u", "lambda", "mu_lame")
        md.add_initialized_data("top", [0.0, 0.0])
        md.add_Dirichlet_condition_with_multipliers(self.mim, "u", self.mfu, nodal.TOP, "top")
        # The obstacle y = 0: the signed distance is y.
        md.add_initialized_fem_data("obstacle", mfs, mfs.basic_dof_nodes()[1])
        md.add_initialized_data("gamma0", [GAMMA0_OVER_E * nodal.YOUNG])
        neumann = md.Neumann_term("u", nodal.BOTTOM)
        # p = -sigma_nn, the normal stress on the contact edge.
        self.pressure_expr = f"(-(({neumann}).Normal))"
        self.friction = f"kef_mu({self.pressure_expr})"
        md.add_Nitsche_contact_with_rigid_obstacle_brick(self.mim, "u", neumann, "obstacle", "gamma0",
                                                         nodal.BOTTOM, THETA, self.friction)
        self.md = md
        self.newton = 0

    def solve(self, ux, uy):
        self.md.set_variable("top", [ux, uy])
        nbit, converged = self.md.solve("max_res", 1e-9, "max_iter", 200, "lsearch", "simplest")
        if not converged:
            raise RuntimeError(f"Newton did not converge at top displacement ({ux:g}, {uy:g}) m")
        self.newton += nbit
        return nbit

    def top_reaction(self):
        return -gf.asm_generic(self.mim, 0, "mult_on_u", nodal.TOP, self.md)

    def integral(self, expr):
        """The integral over the contact edge (per metre of thickness)."""
        return float(gf.asm_generic(self.mim, 0, expr, nodal.BOTTOM, self.md))


def ramp(c):
    """Press, then shear in steps to gross sliding (the tangential reaction
    stops changing); returns the ramp's (displacement, Fx, Fy, iterations)."""
    it = c.solve(0.0, -nodal.PRESS)
    fx, fy = c.top_reaction()
    steps = [(0.0, float(fx), float(fy), it)]
    for step in range(1, nodal.MAX_SHEAR_STEPS + 1):
        ux = step * nodal.SHEAR_STEP
        it = c.solve(ux, -nodal.PRESS)
        fx, fy = c.top_reaction()
        steps.append((ux, float(fx), float(fy), it))
        if abs(abs(fx) - abs(steps[-2][1])) <= 1e-6 * abs(fx):
            return steps, True
    return steps, False


def run(args):
    law = nodal.make_law(args)
    gf.util_trace_level(0)
    expression, degree, fit_error = closed_form(law)

    t0 = time.perf_counter()
    c = Nitsche(law, expression)
    steps, plateau = ramp(c)
    nitsche_seconds = time.perf_counter() - t0
    fx, fy = abs(steps[-1][1]), abs(steps[-1][2])
    # The integrals of mu(p) p and p over the contact, with the law's own
    # mu at the solution's pressures (p > 0 where in contact).
    p_expr = f"max({c.pressure_expr}, 0)"
    int_p = c.integral(p_expr)
    int_mu_p = c.integral(f"kef_mu({c.pressure_expr})*{p_expr}")

    t0 = time.perf_counter()
    n = nodal.Contact(law)
    iterations = [n.solve(0.0, -nodal.PRESS)]
    nodal_plateau = False
    previous = 0.0
    for step in range(1, nodal.MAX_SHEAR_STEPS + 1):
        iterations.append(n.solve(step * nodal.SHEAR_STEP, -nodal.PRESS))
        ft = abs(n.top_reaction()[0])
        slip, closed = n.slipping()
        if slip.sum() == closed.sum() and abs(ft - previous) <= 1e-6 * ft:
            nodal_plateau = True
            break
        previous = ft
    nodal_seconds = time.perf_counter() - t0
    nfx, nfy = (abs(float(v)) for v in n.top_reaction())

    ratio, nodal_ratio = fx / fy, nfx / nfy
    difference = abs(ratio / nodal_ratio - 1)
    checks = {
        "fit_within_tolerance": bool(fit_error <= FIT_TOLERANCE),
        "nitsche_gross_sliding": plateau,
        "nodal_gross_sliding": nodal_plateau,
        "one_newton_solve_per_step": True,  # solve() raises otherwise
        # At gross sliding Fx/Fy is the pressure-weighted mean of mu(p)
        # (the friction is the GWFL function's): against its own integrals
        # of the normal stress (which is not exactly Nitsche's contact
        # pressure, hence 1e-3; measured 6e-4).
        "nitsche_ratio_is_mean_mu": bool(abs(ratio / (int_mu_p / int_p) - 1) <= 1e-3),
        "matches_nodal_fixed_point": bool(difference <= COMPARE_TOLERANCE),
    }
    record = {
        "description": ("GetFEM 2-D plane-strain block sheared to gross sliding: the Nitsche contact brick with "
                        "mu(p) as a GWFL function (one Newton solve per load step) against the nodal brick's "
                        "fixed point pressure <-> mu"),
        "ke_friction": kf.__version__,
        "law": nodal.law_inputs(law),
        "closed_form": {"degree": degree, "max_relative_error": fit_error, "tolerance": FIT_TOLERANCE,
                        "points": FIT_POINTS, "expression": expression},
        "nitsche": {"fx": fx, "fy": fy, "fx_over_fy": ratio, "integral_mu_p": int_mu_p, "integral_p": int_p,
                    "newton_iterations": [s[3] for s in steps], "seconds": nitsche_seconds,
                    "gamma0": GAMMA0_OVER_E * nodal.YOUNG},
        "nodal": {"fx": nfx, "fy": nfy, "fx_over_fy": nodal_ratio, "fixed_point_iterations": iterations,
                  "solves": n.solves, "seconds": nodal_seconds},
        "relative_difference_fx_over_fy": difference,
        "compare_tolerance": COMPARE_TOLERANCE,
        "ramp": [{"displacement": u, "fx": abs(a), "fy": abs(b)} for u, a, b, _ in steps],
        "checks": checks,
    }
    return record


def plot(path, record):
    plt = nodal.pyplot()
    if plt is None:
        print(f"matplotlib is missing: no {path}")
        return
    fig, a = plt.subplots(figsize=(6, 4.2), dpi=110)
    u = np.array([r["displacement"] for r in record["ramp"]])
    f = np.array([r["fx"] for r in record["ramp"]])
    a.plot(u * 1e6, f / 1e3, marker="o", ms=3, label="Nitsche, mu(p) in GWFL")
    a.axhline(record["nodal"]["fx"] / 1e3, color="C3", ls="--", label="nodal brick, fixed point")
    a.set_xlabel("top displacement (um)")
    a.set_ylabel("tangential reaction (kN per m)")
    a.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=tempfile.gettempdir(), help="the folder to write to (default: %(default)s)")
    parser.add_argument("--psi", type=float, default=1.0, help="plasticity index (default: %(default)s)")
    parser.add_argument("--theta", type=float, default=0.001, help="adhesion parameter (default: %(default)s)")
    parser.add_argument("--hardness", type=float, default=2e9, help="hardness H in Pa (default: %(default)s)")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    record = run(args)
    with open(os.path.join(args.out, "getfem_nitsche.json"), "w") as f:
        json.dump(record, f, indent=1)
    plot(os.path.join(args.out, "getfem_nitsche.png"), record)
    ni, no = record["nitsche"], record["nodal"]
    print(f"closed form: degree {record['closed_form']['degree']}, worst relative error "
          f"{record['closed_form']['max_relative_error']:.2e} against the law (tolerance {FIT_TOLERANCE:g})")
    print(f"Nitsche, mu(p) in Newton: Fx/Fy = {ni['fx_over_fy']:.6f}, {sum(ni['newton_iterations'])} Newton "
          f"iterations in {len(ni['newton_iterations'])} solves, {ni['seconds']:.1f} s")
    print(f"nodal brick, fixed point: Fx/Fy = {no['fx_over_fy']:.6f}, {no['solves']} solves "
          f"({sum(no['fixed_point_iterations'])} fixed-point iterations), {no['seconds']:.1f} s")
    print(f"relative difference {record['relative_difference_fx_over_fy']:.2e} (tolerance {COMPARE_TOLERANCE:g})")
    failed = [k for k, ok in record["checks"].items() if not ok]
    if failed:
        print("getfem_nitsche: FAILED: " + ", ".join(failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
