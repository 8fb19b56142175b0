#!/usr/bin/env python3
"""The friction law inside GetFEM's Newton solve: mu(p) as a GWFL function
in the Nitsche contact brick, against fixed points of the law.

Usage: python3 python/examples/getfem_nitsche.py [--out DIR] [--psi P] [--theta T] [--hardness H]
    [--nodal-json DIR/getfem_contact.json]

The block of python/examples/getfem_contact.py (an elastic steel block with
a gently rounded bottom, pressed on a rigid flat, then sheared to gross
sliding) with GetFEM's Nitsche contact brick, whose friction coefficient is
any GWFL expression, differentiated by GetFEM: mu(p) of the brick's own
contact pressure p (whose integral is the normal reaction) is a GWFL
function (``gf.asm_define_function``), so every load step is one Newton
solve, with no fixed point pressure <-> mu.

The GWFL function is a closed form of ke_friction's law: a polynomial in
the log-pressure (Chebyshev fit on the law's pressure range, clamped to it
as the law's "clamp" policy does), of the lowest degree whose relative
error against the law is within FIT_TOLERANCE at FIT_POINTS log-spaced
pressures; that error is measured and printed.

Three solves slide the block to gross sliding, where Fx/Fy is the mean of
mu(p) weighted by the contact pressure:
- the Nitsche brick, mu(p) in Newton;
- the same brick with mu frozen at its integration points and iterated to
  a fixed point with the law's own mu (same pressure, same points): the
  reference for the closed form, which must match it within the closed
  form's measured error;
- the nodal brick's fixed point (python/examples/getfem_contact.py, or its
  JSON with --nodal-json): another contact discretisation (nodes against
  integration points), which must match within the closed form's error
  too: on this mesh (320 x 32) the two formulations' own difference has
  fallen below it (the refinement study, getfem_refinement.py;
  docs/REFERENCE.md).
It prints the iterations and time of each, writes DIR/getfem_nitsche.json
and, with matplotlib, DIR/getfem_nitsche.png; exits 1 when a check fails,
2 on a bad input.

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
#: |Fx/Fy / (int mu(p) p / int p) - 1| at gross sliding (measured 5e-13:
#: p is the brick's contact pressure, the integral of p is Fy to 1e-14).
MEAN_MU_TOLERANCE = 1e-9
#: The Nitsche parameter gamma0 (the penalty gamma0/h), in units of E: 10
#: takes more Newton iterations than 1 (64 against 45 on the 160 x 16
#: ramp), but its Fx/Fy reaches the nodal brick's within 1e-5 from
#: 320 x 32 on, where 1 E is still 1.2e-4 off at 640 x 64
#: (docs/REFERENCE.md, "GetFEM").
GAMMA0_OVER_E = 10.0
#: The Nitsche fixed point stops when no integration point's mu changes
#: by more (as the nodal brick's, getfem_contact.FIXED_POINT_TOL).
FIXED_POINT_TOL = nodal.FIXED_POINT_TOL
#: GetFEM's line search in the Nitsche brick's Newton solve: "basic" takes
#: 11-14 iterations a load step (7-10 at gamma0 = E) where "simplest" took
#: 60-100 and "default" did not converge in 200 (the 160 x 16 block).
LSEARCH = "basic"
#: mu's argument: "contact", the brick's contact pressure (whose integral
#: is the normal reaction), or "stress", -sigma_nn of the displacement.
PRESSURE = "contact"
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


_DEFINED = {}


def gwfl_function(expression):
    """The name of a one-argument GWFL function (of t) with this
    expression, defined once per process (GetFEM's functions are global)."""
    if expression not in _DEFINED:
        name = f"kef_mu{len(_DEFINED)}"
        gf.asm_define_function(name, 1, expression)
        _DEFINED[expression] = name
    return _DEFINED[expression]


class Nitsche:
    """The block with the Nitsche contact brick on nx x ny elements.

    With `expression` (a GWFL expression of t, the pressure in Pa) the
    friction coefficient is that function of the pressure p (`pressure`:
    "contact", the brick's contact pressure, or "stress", -sigma_nn),
    inside the brick's Newton solve. Without it, mu is
    frozen at the contact edge's integration points (a GWFL im_data) and
    iterated to a fixed point: each Newton solve is followed by
    mu = law.mu(p) at the same integration points (p clamped to the law's
    range as the closed form does), until no point's mu changes by more
    than FIXED_POINT_TOL: the same pressure, the same points, the law's
    own mu instead of the closed form."""

    def __init__(self, law, expression=None, nx=nodal.NX, ny=nodal.NY, gamma0_over_e=GAMMA0_OVER_E,
                 pressure=PRESSURE):
        self.law = law
        self.mesh, self.mfu, mfs, self.mim = nodal.body(nx, ny)
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
        self.gamma0 = gamma0_over_e * nodal.YOUNG
        md.add_initialized_data("gamma0", [self.gamma0])
        neumann = md.Neumann_term("u", nodal.BOTTOM)
        # -sigma_nn, the normal stress on the contact edge, and the brick's
        # contact pressure [-sigma_n.n_o - gamma (g - u.n_o)]_+ with its own
        # normal n_o = -grad(g)/|grad(g)| (of the obstacle, not the edge),
        # gap g and gamma = gamma0 / h: its integral is the normal reaction.
        self.stress_expr = f"(-(({neumann}).Normal))"
        normal = "(-Normalized(Grad_obstacle))"
        self.contact_pressure_expr = (f"pos_part(-(({neumann}).{normal})"
                                      f"-(gamma0/element_size)*(obstacle-u.{normal}))")
        if pressure not in ("stress", "contact"):
            raise ValueError(f"pressure: {pressure!r} is not 'stress' or 'contact'")
        self.pressure_expr = self.stress_expr if pressure == "stress" else self.contact_pressure_expr
        self.frozen = expression is None
        if self.frozen:
            self.mimd = gf.MeshImData(self.mim, nodal.BOTTOM)
            md.add_im_data("mu_frozen", self.mimd)
            md.set_variable("mu_frozen", np.full(self.mimd.nbpts(), law.mu(law.range[0])))
            self.friction = "mu_frozen"
        else:
            self.friction = f"{gwfl_function(expression)}({self.pressure_expr})"
        md.add_Nitsche_contact_with_rigid_obstacle_brick(self.mim, "u", neumann, "obstacle", "gamma0",
                                                         nodal.BOTTOM, THETA, self.friction)
        self.md = md
        self.newton = 0
        self.solves = 0

    def mu_at_points(self):
        """The law's mu at the contact edge's integration points, of the
        current solution's pressure p clamped to the law's range."""
        p = self.md.interpolation(self.pressure_expr, self.mimd, nodal.BOTTOM)
        return self.law.mu(np.clip(p, *self.law.range))

    def solve(self, ux, uy):
        """Impose (ux, uy) on the top; one Newton solve (the GWFL mu(p)) or
        a fixed point of Newton solves (mu frozen). Returns the number of
        Newton solves."""
        self.md.set_variable("top", [ux, uy])
        for it in range(1, 51):
            nbit, converged = self.md.solve("max_res", 1e-9, "max_iter", 200, "lsearch", LSEARCH)
            if not converged:
                raise RuntimeError(f"Newton did not converge at top displacement ({ux:g}, {uy:g}) m")
            self.newton += nbit
            self.solves += 1
            if not self.frozen:
                return it
            mu_old = self.md.variable("mu_frozen")
            mu_new = self.mu_at_points()
            self.md.set_variable("mu_frozen", mu_new)
            if np.max(np.abs(mu_new - mu_old)) <= FIXED_POINT_TOL:
                return it
        raise RuntimeError(f"no fixed point pressure <-> mu at top displacement ({ux:g}, {uy:g}) m")

    def top_reaction(self):
        return -gf.asm_generic(self.mim, 0, "mult_on_u", nodal.TOP, self.md)

    def integral(self, expr):
        """The integral over the contact edge (per metre of thickness)."""
        return float(gf.asm_generic(self.mim, 0, expr, nodal.BOTTOM, self.md))


def ramp(c):
    """Press, then shear in steps to gross sliding (the tangential reaction
    stops changing); returns the ramp's (displacement, Fx, Fy, Newton
    solves, Newton iterations) and whether it reached the plateau."""
    before = c.newton
    it = c.solve(0.0, -nodal.PRESS)
    fx, fy = c.top_reaction()
    steps = [(0.0, float(fx), float(fy), it, c.newton - before)]
    for step in range(1, nodal.MAX_SHEAR_STEPS + 1):
        ux = step * nodal.SHEAR_STEP
        before = c.newton
        it = c.solve(ux, -nodal.PRESS)
        fx, fy = c.top_reaction()
        steps.append((ux, float(fx), float(fy), it, c.newton - before))
        if abs(abs(fx) - abs(steps[-2][1])) <= 1e-6 * abs(fx):
            return steps, True
    return steps, False


def nodal_ramp(n):
    """The nodal brick's ramp to gross sliding (every node in contact slips
    and the tangential reaction stops changing); returns the fixed point's
    iterations per load step and whether it reached the plateau."""
    iterations = [n.solve(0.0, -nodal.PRESS)]
    previous = 0.0
    for step in range(1, nodal.MAX_SHEAR_STEPS + 1):
        iterations.append(n.solve(step * nodal.SHEAR_STEP, -nodal.PRESS))
        ft = abs(n.top_reaction()[0])
        slip, closed = n.slipping()
        if slip.sum() == closed.sum() and abs(ft - previous) <= 1e-6 * ft:
            return iterations, True
        previous = ft
    return iterations, False


def nodal_from_json(path, law):
    """The nodal brick's result from getfem_contact.py's JSON (the same
    block, mesh and law; CI runs that example first): Fx, Fy, solves, the
    fixed point's iterations and seconds. ValueError when it is not that."""
    try:
        with open(path) as f:
            r = json.load(f)
        fx, fy = float(r["tangential_reaction"]), float(r["normal_load"])
        same = (r["law"] == json.loads(json.dumps(nodal.law_inputs(law)))
                and r["body"]["elements"] == [nodal.NX, nodal.NY] and r["checks"]["gross_sliding"])
        solves, iterations, seconds = int(r["solves"]), list(r["fixed_point_iterations"]), float(r["seconds"])
        cpu = float(r["cpu_seconds"])
    except (OSError, ValueError, KeyError, TypeError) as e:
        what = f"no key {e}" if isinstance(e, KeyError) else str(e)
        raise ValueError(f"--nodal-json: {path}: not getfem_contact.py's JSON ({what})") from None
    if not same:
        raise ValueError(f"--nodal-json: {path}: another law, mesh or no gross sliding "
                         f"(needs this run's law and {nodal.NX} x {nodal.NY} elements)")
    if not (fx > 0 and fy > 0):
        raise ValueError(f"--nodal-json: {path}: reactions {fx}, {fy} not positive")
    return {"fx": fx, "fy": fy, "fixed_point_iterations": iterations, "solves": solves, "seconds": seconds,
            "cpu_seconds": cpu, "plateau": True, "from": os.path.abspath(path)}


def run(args):
    law = nodal.make_law(args)
    # getfem_contact.py's result, read (and refused) before any solve.
    nd = nodal_from_json(args.nodal_json, law) if args.nodal_json else None
    gf.util_trace_level(0)
    expression, degree, fit_error = closed_form(law)

    # mu(p) in the brick's Newton solve.
    t0, cpu0 = time.perf_counter(), time.process_time()
    c = Nitsche(law, expression)
    steps, plateau = ramp(c)
    nitsche_seconds, nitsche_cpu = time.perf_counter() - t0, time.process_time() - cpu0
    fx, fy = abs(steps[-1][1]), abs(steps[-1][2])
    # The integrals of mu(p) p and p over the contact (p the brick's
    # contact pressure, mu the closed form's at it).
    int_p = c.integral(c.pressure_expr)
    int_mu_p = c.integral(f"{c.friction}*{c.pressure_expr}")

    # The same brick, mu frozen per iteration from the law itself.
    t0, cpu0 = time.perf_counter(), time.process_time()
    f = Nitsche(law, None)
    fixed_steps, fixed_plateau = ramp(f)
    fixed_seconds, fixed_cpu = time.perf_counter() - t0, time.process_time() - cpu0
    ffx, ffy = abs(fixed_steps[-1][1]), abs(fixed_steps[-1][2])

    # The nodal brick's fixed point (getfem_contact.py), unless its JSON.
    if nd is None:
        t0, cpu0 = time.perf_counter(), time.process_time()
        n = nodal.Contact(law)
        iterations, nodal_plateau = nodal_ramp(n)
        nfx, nfy = (abs(float(v)) for v in n.top_reaction())
        nd = {"fx": nfx, "fy": nfy, "fixed_point_iterations": iterations, "solves": n.solves,
              "seconds": time.perf_counter() - t0, "cpu_seconds": time.process_time() - cpu0,
              "plateau": nodal_plateau, "from": "solved here"}
    nd["fx_over_fy"] = nd["fx"] / nd["fy"]

    ratio, fixed_ratio = fx / fy, ffx / ffy
    expression_gap = ratio / fixed_ratio - 1
    formulation_gap = ratio / nd["fx_over_fy"] - 1
    checks = {
        "fit_within_tolerance": bool(fit_error <= FIT_TOLERANCE),
        "nitsche_gross_sliding": plateau,
        "fixed_point_gross_sliding": fixed_plateau,
        "nodal_gross_sliding": bool(nd["plateau"]),
        "one_newton_solve_per_step": bool(c.solves == len(steps)),
        # At gross sliding every point slips: Fx/Fy is the mean of mu(p)
        # weighted by the contact pressure (measured 5e-13).
        "nitsche_ratio_is_mean_mu": bool(abs(ratio / (int_mu_p / int_p) - 1) <= MEAN_MU_TOLERANCE),
        # The same brick, the same pressures at the same points: mu(p) in
        # Newton differs from the law's fixed point by the closed form's
        # error only, the weighted mean of a relative error within it.
        "newton_matches_fixed_point_within_fit_error": bool(abs(expression_gap) <= fit_error),
        # The two contact formulations differ by discretisation: on this
        # mesh the difference is below the closed form's error (the
        # refinement study measured 6.1e-4, 1.05e-4, 6.4e-5 on 40 x 4,
        # 80 x 8, 160 x 16, then 5.7e-6, 9.3e-6 on 320 x 32, 640 x 64;
        # with a constant mu, 1e-13).
        "nodal_matches_within_fit_error": bool(abs(formulation_gap) <= fit_error),
    }
    record = {
        "description": ("GetFEM 2-D plane-strain block sheared to gross sliding: the Nitsche contact brick with "
                        "mu(p) as a GWFL function (one Newton solve per load step), the same brick with mu frozen "
                        "per iteration from the law (a fixed point), and the nodal brick's fixed point"),
        "ke_friction": kf.__version__,
        "law": nodal.law_inputs(law),
        "mesh": [nodal.NX, nodal.NY],
        "closed_form": {"degree": degree, "max_relative_error": fit_error, "tolerance": FIT_TOLERANCE,
                        "points": FIT_POINTS, "expression": expression},
        "nitsche": {"fx": fx, "fy": fy, "fx_over_fy": ratio, "integral_mu_p": int_mu_p, "integral_p": int_p,
                    "newton_iterations": [s[4] for s in steps], "newton_total": c.newton, "seconds": nitsche_seconds,
                    "cpu_seconds": nitsche_cpu,
                    "gamma0": c.gamma0, "pressure": PRESSURE, "line_search": LSEARCH},
        "nitsche_fixed_point": {"fx": ffx, "fy": ffy, "fx_over_fy": fixed_ratio,
                                "fixed_point_iterations": [s[3] for s in fixed_steps], "solves": f.solves,
                                "newton_iterations": [s[4] for s in fixed_steps],
                                "newton_total": f.newton, "seconds": fixed_seconds,
                                "cpu_seconds": fixed_cpu},
        "nodal": nd,
        "expression_gap": expression_gap,
        "formulation_gap": formulation_gap,
        "formulation_gap_bound": fit_error,
        "ramp": [{"displacement": s[0], "fx": abs(s[1]), "fy": abs(s[2])} for s in steps],
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
    a.axhline(record["nitsche_fixed_point"]["fx"] / 1e3, color="C2", ls=":", label="Nitsche, fixed point of the law")
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
    parser.add_argument("--nodal-json", help="getfem_contact.py's JSON of the same law: its nodal result, not solved again")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    try:
        record = run(args)
    except ValueError as e:
        print(f"getfem_nitsche: {e}", file=sys.stderr)
        return 2
    with open(os.path.join(args.out, "getfem_nitsche.json"), "w") as f:
        json.dump(record, f, indent=1)
    plot(os.path.join(args.out, "getfem_nitsche.png"), record)
    ni, fp, no = record["nitsche"], record["nitsche_fixed_point"], record["nodal"]
    print(f"closed form: degree {record['closed_form']['degree']}, worst relative error "
          f"{record['closed_form']['max_relative_error']:.2e} against the law (tolerance {FIT_TOLERANCE:g})")
    print(f"Nitsche, mu(p) in Newton: Fx/Fy = {ni['fx_over_fy']:.6f}, {ni['newton_total']} Newton "
          f"iterations in {len(ni['newton_iterations'])} solves, {ni['seconds']:.1f} s ({ni['cpu_seconds']:.1f} s CPU)")
    print(f"Nitsche, fixed point of the law: Fx/Fy = {fp['fx_over_fy']:.6f}, {fp['solves']} solves "
          f"({fp['newton_total']} Newton iterations), {fp['seconds']:.1f} s ({fp['cpu_seconds']:.1f} s CPU)")
    print(f"nodal brick, fixed point: Fx/Fy = {no['fx_over_fy']:.6f}, {no['solves']} solves, {no['seconds']:.1f} s "
          f"({no['cpu_seconds']:.1f} s CPU)"
          + ("" if no["from"] == "solved here" else f" (from {no['from']})"))
    print(f"Newton against the fixed point {record['expression_gap']:+.2e} (the closed form's error "
          f"{record['closed_form']['max_relative_error']:.2e}); against the nodal brick "
          f"{record['formulation_gap']:+.2e} (the closed form's error again)")
    failed = [k for k, ok in record["checks"].items() if not ok]
    if failed:
        print("getfem_nitsche: FAILED: " + ", ".join(failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
