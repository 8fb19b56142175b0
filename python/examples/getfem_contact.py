#!/usr/bin/env python3
"""The friction law inside a finite-element solver: GetFEM's contact brick.

Usage: python3 python/examples/getfem_contact.py [--out DIR] [--psi P] [--theta T] [--hardness H]

An elastic steel block (plane strain, 10 mm wide, 5 mm tall) with a gently
rounded bottom (radius 20 m: a non-uniform contact pressure, highest in the
middle and falling to zero at the contact's edges) is pressed on a rigid
flat (y = 0) by a vertical displacement of its top, then sheared by a
horizontal displacement of its top, in steps, until it slides as a whole.
Frictional contact is GetFEM's nodal contact brick with a rigid obstacle
(Alart-Curnier augmented Lagrangian), whose friction coefficient is one
value per contact node: at each load step the nodes' contact pressures
p_i = |lambda_n,i| / A_i (the nodal force over the node's tributary area)
and the friction coefficients mu_i = mu(p_i) of ke_friction's
:class:`FrictionLaw` are iterated to a fixed point.

At gross sliding every node in contact slips, so the tangential reaction
at the top equals sum_i mu(p_i) p_i A_i; the example checks this to
TOLERANCE (2 %: the fixed point's and the solver's tolerances are far
smaller), that at least 100 nodes are in contact, and that mu varies over
the contact as the model says (higher where the pressure is lower). It
writes DIR/getfem_contact.json (the law's inputs, the nodes, the loads; 2-D:
forces and areas per metre of thickness) and DIR/getfem_contact.png
(pressure and mu along the contact; tangential force against the
displacement; only with matplotlib), and exits 1 when a check fails.

GetFEM comes from Debian (``apt-get install python3-getfem
python3-matplotlib``, for the system ``/usr/bin/python3``); install
ke_friction into a venv made with ``/usr/bin/python3 -m venv
--system-site-packages`` to see both, and upgrade no NumPy inside it
(Debian's getfem is built against Debian's NumPy). About 10 s.
python/examples/getfem_nitsche.py solves the same block in one Newton
solve per load step, mu(p) inside GetFEM's Nitsche brick.
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

#: The check's tolerance: |F_t - sum mu(p_i) p_i A_i| / sum mu(p_i) p_i A_i
#: at gross sliding.
TOLERANCE = 0.02
#: The fixed point pressure <-> mu stops when no node's mu changes by more.
FIXED_POINT_TOL = 1e-9
#: The solver's resolution of the nodal forces, relative to the largest:
#: a node is in contact when its normal force exceeds it (the solver leaves
#: forces of ~1e-315 N at open nodes), and slips when |lambda_t| is within
#: it of mu |lambda_n|.
FORCE_TOL = 1e-9
#: GetFEM's line search: "basic" took 113 Newton iterations for the 27
#: solves of the 80 x 8 ramp where "simplest" took 183 (the same Fx/Fy to
#: 1e-11).
LSEARCH = "basic"

# The body (SI units): 10 mm x 5 mm steel, bottom y = x^2 / (2 R).
WIDTH, HEIGHT, RADIUS = 10e-3, 5e-3, 20.0
YOUNG, POISSON = 210e9, 0.3
# Elements along the contact edge (321 nodes) and across the height: the
# mesh on which the nodal and the Nitsche bricks agree within the law's
# closed form's error (getfem_nitsche.py; docs/REFERENCE.md).
NX, NY = 320, 32
# The top's vertical displacement and the shear ramp's step.
PRESS, SHEAR_STEP, MAX_SHEAR_STEPS = 5e-7, 2e-7, 20

BOTTOM, TOP = 1, 2


def body(nx=NX, ny=NY):
    """The mesh (nx x ny Q1 quadrilaterals, bottom bent to the arc), its fems
    and integration method, and the regions BOTTOM and TOP."""
    xs = np.linspace(-WIDTH / 2, WIDTH / 2, nx + 1)
    ys = np.linspace(0.0, HEIGHT, ny + 1)
    # 'cartesian Q1': a 'cartesian' mesh whose points are moved can come
    # out cracked (duplicated dofs); nbdof is checked below.
    mesh = gf.Mesh("cartesian Q1", xs, ys)
    pts = mesh.pts()
    bottom = pts[0] ** 2 / (2 * RADIUS)
    pts[1] = bottom + pts[1] * (HEIGHT - bottom) / HEIGHT
    mesh.set_pts(pts)
    mesh.set_region(BOTTOM, mesh.outer_faces_with_direction([0.0, -1.0], 0.5))
    mesh.set_region(TOP, mesh.outer_faces_with_direction([0.0, 1.0], 0.5))
    mfu = gf.MeshFem(mesh, 2)
    mfu.set_classical_fem(1)
    if mfu.nbdof() != 2 * (nx + 1) * (ny + 1):
        raise RuntimeError(f"the mesh is cracked: {mfu.nbdof()} dofs, not {2 * (nx + 1) * (ny + 1)}")
    mfs = gf.MeshFem(mesh, 1)
    mfs.set_classical_fem(1)
    return mesh, mfu, mfs, gf.MeshIm(mesh, 4)


def contact_nodes(mfu, mfs, mim):
    """x of the contact nodes, in the brick's order (the x-dofs of BOTTOM in
    ascending order), and each node's tributary area (the integral of its
    shape function over the edge, m^2 per metre of thickness)."""
    dofs = np.sort(mfu.basic_dof_on_region(BOTTOM))[0::2]
    x = mfu.basic_dof_nodes(dofs)[0]
    sdofs = mfs.basic_dof_on_region(BOTTOM)
    lengths = gf.asm_generic(mim, 1, "Test_t", BOTTOM, "t", 1, mfs, np.zeros(mfs.nbdof()))[sdofs]
    sx = mfs.basic_dof_nodes(sdofs)[0]
    # Match the scalar fem's nodes to the brick's by coordinate.
    match = np.searchsorted(np.sort(sx), x)
    if not np.allclose(np.sort(sx)[match], x, rtol=0, atol=1e-12):
        raise RuntimeError("the contact nodes of the two fems differ")
    area = lengths[np.argsort(sx)][match] * 1.0  # x 1 m of thickness
    return x, area


def make_law(args):
    """The friction law mu(p) of the surfaces, in SI."""
    return kf.FrictionLaw(args.psi, args.theta, hardness=args.hardness, out_of_range="clamp")


def law_inputs(law):
    """The law's model inputs and hardness, for the JSON."""
    params = law.params
    keys = ("psi", "theta", "beta", "nu", "eps_star", "distribution", "skewness", "kurtosis")
    return {**{k: params[k] for k in keys}, "hardness": law.hardness,
            "pressure_range": list(law.range), "out_of_range": "clamp"}


class Contact:
    """The GetFEM model: elasticity, the top's imposed displacement, the
    nodal contact brick with one friction coefficient per node; nx x ny
    elements."""

    def __init__(self, law, nx=NX, ny=NY):
        self.law = law
        self.mesh, self.mfu, mfs, self.mim = body(nx, ny)
        self.x, self.area = contact_nodes(self.mfu, mfs, self.mim)
        n = len(self.x)
        lam = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON))
        shear = YOUNG / (2 * (1 + POISSON))
        md = gf.Model("real")
        md.add_fem_variable("u", self.mfu)
        md.add_initialized_data("lambda", [lam])
        md.add_initialized_data("mu_lame", [shear])
        md.add_isotropic_linearized_elasticity_brick(self.mim, "u", "lambda", "mu_lame")
        md.add_initialized_data("top", [0.0, 0.0])
        md.add_Dirichlet_condition_with_multipliers(self.mim, "u", self.mfu, TOP, "top")
        md.add_variable("lambda_n", n)
        md.add_variable("lambda_t", n)
        md.add_initialized_data("r", [YOUNG])
        md.add_initialized_data("mu", np.full(n, law.mu(law.range[0])))
        md.add_nodal_contact_with_rigid_obstacle_brick(self.mim, "u", "lambda_n", "lambda_t", "r", "mu",
                                                       BOTTOM, "y", 1)
        self.md = md
        self.solves = 0

    def solve(self, ux, uy):
        """Impose (ux, uy) on the top and iterate pressure <-> mu to a fixed
        point; returns the number of iterations."""
        self.md.set_variable("top", [ux, uy])
        for it in range(1, 51):
            self.md.solve("max_res", 1e-9, "max_iter", 200, "lsearch", LSEARCH)
            self.solves += 1
            mu_old = self.md.variable("mu")
            mu_new = self.mu_of_nodes()
            self.md.set_variable("mu", mu_new)
            if np.max(np.abs(mu_new - mu_old)) <= FIXED_POINT_TOL:
                return it
        raise RuntimeError(f"no fixed point pressure <-> mu at top displacement ({ux:g}, {uy:g}) m")

    def normal_forces(self):
        """The nodes' normal forces (N per metre; 0 where open)."""
        f = np.maximum(-self.md.variable("lambda_n"), 0.0)
        return np.where(f > FORCE_TOL * f.max(), f, 0.0)

    def pressure(self):
        """The nodes' contact pressures (Pa; 0 where open)."""
        return self.normal_forces() / self.area

    def mu_of_nodes(self):
        """mu(p_i) at the nodes in contact; an open node (p = 0, where the law
        is undefined) keeps the law's value at the range's lower end, which
        the brick never uses there."""
        p = self.pressure()
        closed = p > 0
        mu = np.full(p.shape, self.law.mu(self.law.range[0]))
        mu[closed] = self.law.mu(p[closed])
        return mu

    def top_reaction(self):
        """The force the top's imposed displacement takes (N per metre)."""
        return -gf.asm_generic(self.mim, 0, "mult_on_u", TOP, self.md)

    def slipping(self):
        """Which nodes in contact slip (|lambda_t| at mu |lambda_n|)."""
        fn, lt, mu = self.normal_forces(), self.md.variable("lambda_t"), self.md.variable("mu")
        closed = fn > 0
        return closed & (np.abs(lt) >= mu * fn - FORCE_TOL * fn.max()), closed


def run(args):
    law = make_law(args)
    t0, cpu0 = time.perf_counter(), time.process_time()
    gf.util_trace_level(0)
    c = Contact(law)
    iterations = [c.solve(0.0, -PRESS)]
    ramp = [(0.0, 0.0)]
    plateau = False
    for step in range(1, MAX_SHEAR_STEPS + 1):
        ux = step * SHEAR_STEP
        iterations.append(c.solve(ux, -PRESS))
        ft = abs(c.top_reaction()[0])
        slip, closed = c.slipping()
        ramp.append((ux, ft))
        if slip.sum() == closed.sum() and abs(ft - ramp[-2][1]) <= 1e-6 * ft:
            plateau = True
            break
    seconds, cpu_seconds = time.perf_counter() - t0, time.process_time() - cpu0

    p = c.pressure()
    closed = p > 0
    mu = law.mu(p[closed])  # afresh from the law: the check's own mu(p_i)
    area = c.area[closed]
    expected = float(np.sum(mu * p[closed] * area))
    fx, fy = c.top_reaction()
    normal, tangential = abs(float(fy)), abs(float(fx))
    error = abs(tangential - expected) / expected
    order = np.argsort(p[closed])
    spread = (mu.max() - mu.min()) / mu.mean()
    checks = {
        "gross_sliding": plateau,
        "nodes_in_contact_at_least_100": bool(closed.sum() >= 100),
        "reaction_matches_sum_mu_p_area": bool(error <= TOLERANCE),
        "mu_not_uniform": bool(spread > 0.01),
        # mu(p) is non-increasing: higher where the pressure is lower.
        "mu_higher_where_pressure_lower": bool(np.all(np.diff(mu[order]) <= 1e-12)),
    }
    record = {
        "description": ("GetFEM 2-D plane-strain contact of an elastic block with a rounded bottom on a rigid "
                        "flat, sheared to gross sliding; mu per contact node from ke_friction.FrictionLaw"),
        "per_unit_thickness": "2-D plane strain: forces in N and areas in m^2 per metre of thickness",
        "units": {"x": "m", "pressure": "Pa", "area": "m^2", "mu": "1", "normal_load": "N",
                  "tangential_reaction": "N"},
        "ke_friction": kf.__version__,
        "law": law_inputs(law),
        "body": {"width": WIDTH, "height": HEIGHT, "bottom_radius": RADIUS, "young": YOUNG, "poisson": POISSON,
                 "elements": [NX, NY], "top_displacement": [ramp[-1][0], -PRESS]},
        "contact_edge_nodes": len(c.x),
        "nodes": [{"x": float(x), "pressure": float(q), "area": float(a), "mu": float(m)}
                  for x, q, a, m in zip(c.x[closed], p[closed], area, mu)],
        "normal_load": normal,
        "tangential_reaction": tangential,
        "sum_mu_pressure_area": expected,
        "relative_difference": float(error),
        "tolerance": TOLERANCE,
        "clamped_nodes": int(np.sum(p[closed] < law.range[0])),
        "ramp": [{"displacement": u, "tangential_force": f} for u, f in ramp],
        "fixed_point_iterations": iterations,
        "solves": c.solves,
        "seconds": seconds,
        "cpu_seconds": cpu_seconds,
        "checks": checks,
    }
    return record, c.x[closed], p[closed], mu


def pyplot():
    """matplotlib's pyplot, headless, or None when matplotlib is missing
    (the example runs without it; only the PNG needs it)."""
    try:
        import matplotlib
    except ImportError:
        return None
    matplotlib.use("Agg")  # headless, whatever MPLBACKEND says
    import matplotlib.pyplot as plt
    return plt


def plot(path, record, x, p, mu):
    plt = pyplot()
    if plt is None:
        print(f"matplotlib is missing: no {path}")
        return
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2), dpi=110)
    a.plot(x * 1e3, p / 1e6, color="C0")
    a.set_xlabel("x (mm)")
    a.set_ylabel("contact pressure p (MPa)", color="C0")
    a2 = a.twinx()
    a2.plot(x * 1e3, mu, color="C3", marker=".", ms=3, lw=0.8)
    a2.set_ylabel("mu(p)", color="C3")
    a.set_title("pressure and friction coefficient along the contact")
    u = np.array([r["displacement"] for r in record["ramp"]])
    f = np.array([r["tangential_force"] for r in record["ramp"]])
    b.plot(u * 1e6, f / 1e3, marker="o", ms=3, label="tangential reaction (GetFEM)")
    b.axhline(record["sum_mu_pressure_area"] / 1e3, color="C3", ls="--", label="sum mu(p_i) p_i A_i")
    b.set_xlabel("top displacement (um)")
    b.set_ylabel("tangential force (kN per m)")
    b.set_title("shear to gross sliding")
    b.legend(loc="lower right")
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
    record, x, p, mu = run(args)
    with open(os.path.join(args.out, "getfem_contact.json"), "w") as f:
        json.dump(record, f, indent=1)
    plot(os.path.join(args.out, "getfem_contact.png"), record, x, p, mu)
    print(f"{len(x)} of {record['contact_edge_nodes']} nodes in contact; normal load {record['normal_load']:.6g} N/m; "
          f"at gross sliding the tangential reaction is {record['tangential_reaction']:.6g} N/m, "
          f"sum mu(p_i) p_i A_i = {record['sum_mu_pressure_area']:.6g} N/m "
          f"(relative difference {record['relative_difference']:.2e}, tolerance {TOLERANCE:g}); "
          f"mu from {mu.min():.4f} to {mu.max():.4f}; {record['solves']} solves, {record['seconds']:.1f} s "
          f"({record['cpu_seconds']:.1f} s CPU)")
    failed = [k for k, ok in record["checks"].items() if not ok]
    if failed:
        print("getfem_contact: FAILED: " + ", ".join(failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
