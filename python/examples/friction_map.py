#!/usr/bin/env python3
"""A map of the static friction coefficient mu over (psi, F*) at one theta.

Usage: MPLBACKEND=Agg python3 python/examples/friction_map.py [OUT.png] [--theta T]

Evaluates the default table on a 200 x 200 grid in one vectorised call and
writes a PNG (default: friction_map.png in the current directory).
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ke_friction as kf  # noqa: E402


def main(argv):
    out = next((a for a in argv if not a.startswith("--")), "friction_map.png")
    theta = float(argv[argv.index("--theta") + 1]) if "--theta" in argv else 0.003
    table = kf.Table.default()
    info = table.info
    psi = np.geomspace(*info["psi"], 200)
    f_star = np.clip(np.geomspace(*info["f_star"], 200), *info["f_star"])
    mu = table.mu(psi[np.newaxis, :], theta, f_star[:, np.newaxis])  # shape (F*, psi)

    fig, ax = plt.subplots(figsize=(8, 6), dpi=150)
    mesh = ax.pcolormesh(psi, f_star, mu, shading="auto", norm=matplotlib.colors.LogNorm())
    levels = [0.01, 0.03, 0.1, 0.3, 1.0]
    lines = ax.contour(psi, f_star, mu, levels=levels, colors="white", linewidths=0.8)
    ax.clabel(lines, fmt="%g", fontsize=8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("plasticity index ψ")
    ax.set_ylabel("external force F* = F/(A_n·H)")
    ax.set_title(f"static friction coefficient μ (Kogut–Etsion, θ = {theta:g}, default table)")
    fig.colorbar(mesh, ax=ax, label="μ")
    fig.tight_layout()
    fig.savefig(out)
    print(f"wrote {out}: mu from {mu.min():.3g} to {mu.max():.3g} on a {mu.shape[1]} x {mu.shape[0]} grid")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
