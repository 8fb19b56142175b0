#!/usr/bin/env python3
"""A map of the static friction coefficient mu over (psi, F*) at one theta.

Usage: python3 python/examples/friction_map.py [OUT.png] [--theta T] [--table FILE]

Looks up mu in the default table (or a table file from `kefric build`) on a
300 x 300 grid, log-spaced in psi and F*, in one vectorised call, and draws
it with Matplotlib's Agg backend (no display needed) to OUT.png (default:
friction_map.png in the system's temporary directory).
"""

import argparse
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # headless, whatever MPLBACKEND says
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

import ke_friction as kf  # noqa: E402


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", nargs="?", default=os.path.join(tempfile.gettempdir(), "friction_map.png"),
                        help="the PNG to write (default: %(default)s)")
    parser.add_argument("--theta", type=float, default=0.003, help="adhesion parameter (default: %(default)s)")
    parser.add_argument("--table", help="a table file (default: the built-in table)")
    args = parser.parse_args(argv)

    table = kf.Table.load(args.table) if args.table else kf.Table.default()
    info = table.info
    lo, hi = info["theta"]
    if not lo <= args.theta <= hi:
        parser.error(f"--theta {args.theta:g} is outside the table's range [{lo:g}, {hi:g}]")
    psi = np.geomspace(*info["psi"], 300).clip(*info["psi"])
    f_star = np.geomspace(*info["f_star"], 300).clip(*info["f_star"])
    mu = table.mu(psi, args.theta, f_star[:, np.newaxis])  # broadcasts to shape (F*, psi)

    fig, ax = plt.subplots(figsize=(8, 6), dpi=150)
    ax.set_xscale("log")  # before the contour labels, which cut their gaps in screen space
    ax.set_yscale("log")
    mesh = ax.pcolormesh(psi, f_star, mu, shading="gouraud", norm=LogNorm())
    lines = ax.contour(psi, f_star, mu, levels=[0.01, 0.03, 0.1, 0.3, 1.0], colors="white", linewidths=0.8)
    ax.clabel(lines, fmt="μ = %g", fontsize=8)
    ax.set_xlabel("plasticity index ψ")
    ax.set_ylabel("external force F* = F/(A_n·H)")
    ax.set_title(f"Static friction coefficient μ, Kogut–Etsion ({info['model']}, {info['fit']}), θ = {args.theta:g}")
    fig.colorbar(mesh, ax=ax, label="μ")
    fig.tight_layout()
    fig.savefig(args.out)
    print(f"wrote {args.out}: mu from {mu.min():.3g} to {mu.max():.3g} on a {mu.shape[1]} x {mu.shape[0]} grid")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
