#!/usr/bin/env bash
# CI stage getfem: the friction law inside a real finite-element solver.
# GetFEM comes from Debian (python3-getfem, for the system python3; with
# python3-matplotlib, installed here when missing); ke_friction goes into a
# venv made with --system-site-packages beside it (the abi3 wheel
# .ci/python.sh built, or `pip install ./python` without one; --no-deps:
# Debian's NumPy 1.24, which getfem is built against, must stay). Runs
# python/examples/getfem_contact.py (~10 s of CPU) and checks its JSON and
# PNG, then python/examples/getfem_nitsche.py (mu(p) inside the Nitsche
# brick's Newton solve against the same brick's fixed point and the nodal
# fixed point; ~11 s of CPU; it exits 1 when its own checks fail). The
# nodal example's checks: at gross sliding the tangential reaction equals
# sum mu(p_i) p_i A_i within the stated tolerance, >= 100 nodes in
# contact, mu not uniform and higher where the pressure is lower.
# Runs from anywhere in a checkout; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
target=${CARGO_TARGET_DIR:-target}
case $target in /*) ;; *) target=$root/$target ;; esac
out=$target/ci-getfem
rm -rf "$out" && mkdir -p "$out"
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_ROOT_USER_ACTION=ignore MPLBACKEND=Agg

# The set-up the README states, step by step: Debian's getfem and
# matplotlib for /usr/bin/python3, a venv from /usr/bin/python3 with
# --system-site-packages, ke_friction installed with --no-deps (no NumPy
# upgrade inside the venv: Debian's getfem is built against Debian's).
sys=/usr/bin/python3
if ! "$sys" -c 'import getfem, matplotlib' 2> /dev/null; then
  echo "getfem: apt-get update; apt-get install python3-getfem python3-matplotlib"
  export DEBIAN_FRONTEND=noninteractive
  { apt-get update -q && apt-get install -y -q python3-getfem python3-matplotlib; } > "$out/apt.log" 2>&1 \
    || { tail -20 "$out/apt.log"; exit 1; }
fi

venv=$out/venv
"$sys" -m venv --system-site-packages "$venv"
wheel=$(ls "$target"/ci-python/wheels/ke_friction-*-abi3-*.whl 2> /dev/null | head -1 || true)
if [ -n "$wheel" ]; then
  "$venv/bin/python" -m pip install --quiet --no-deps "$wheel"
else
  "$venv/bin/python" -m pip install --quiet --no-deps ./python
fi

(cd "$out" && "$venv/bin/python" "$root/python/examples/getfem_contact.py" --out "$out")
"$venv/bin/python" - "$out" <<'EOF'
import json, os, sys
import numpy as np
from matplotlib.image import imread
out = sys.argv[1]
r = json.load(open(os.path.join(out, "getfem_contact.json")))
for key in ("psi", "theta", "beta", "nu", "eps_star", "distribution", "skewness", "kurtosis", "hardness"):
    assert key in r["law"], key
assert "per metre of thickness" in r["per_unit_thickness"]
nodes = r["nodes"]
assert len(nodes) >= 100, len(nodes)
p = np.array([n["pressure"] for n in nodes]); mu = np.array([n["mu"] for n in nodes])
area = np.array([n["area"] for n in nodes])
assert np.all(p > 0) and np.all(area > 0)
expected = float(np.sum(mu * p * area))
assert abs(expected / r["sum_mu_pressure_area"] - 1) < 1e-12
assert r["tolerance"] <= 0.02
assert abs(r["tangential_reaction"] - expected) <= r["tolerance"] * expected, (r["tangential_reaction"], expected)
assert (mu.max() - mu.min()) / mu.mean() > 0.01, "mu is uniform"
order = np.argsort(p)
assert np.all(np.diff(mu[order]) <= 1e-12), "mu is not higher where the pressure is lower"
assert all(r["checks"].values()), r["checks"]
image = imread(os.path.join(out, "getfem_contact.png"))
assert image.ndim == 3 and image[..., :3].std() > 0.05, "a blank image"
print(f"getfem: {len(nodes)} nodes in contact, reaction {r['tangential_reaction']:.6g} N/m against "
      f"sum mu p A {expected:.6g} N/m (relative {r['relative_difference']:.1e}), mu {mu.min():.4f} to {mu.max():.4f}")
EOF

# mu(p) in one Newton solve per load step (Nitsche brick, a GWFL closed
# form of the law) against the same brick's fixed point of the law itself
# (within the closed form's measured error) and against the nodal brick's
# fixed point above (its JSON; within the bound of the mesh refinement
# study, docs/REFERENCE.md "GetFEM"); it exits 1 when a check fails.
(cd "$out" && "$venv/bin/python" "$root/python/examples/getfem_nitsche.py" --out "$out" \
  --nodal-json "$out/getfem_contact.json")
"$venv/bin/python" - "$out" <<'EOF'
import json, os, sys
r = json.load(open(os.path.join(sys.argv[1], "getfem_nitsche.json")))
assert all(r["checks"].values()), r["checks"]
fit = r["closed_form"]["max_relative_error"]
assert fit <= r["closed_form"]["tolerance"] <= 1e-4
assert abs(r["expression_gap"]) <= fit, (r["expression_gap"], fit)
assert abs(r["formulation_gap"]) <= fit, (r["formulation_gap"], fit)
# one Newton solve a load step; the fixed point needs more
assert len(r["nitsche"]["newton_iterations"]) == len(r["ramp"])
assert r["nitsche_fixed_point"]["solves"] > len(r["ramp"])
assert os.path.getsize(os.path.join(sys.argv[1], "getfem_nitsche.png")) > 0
n, f, d = r["nitsche"], r["nitsche_fixed_point"], r["nodal"]
print(f"getfem: Fx/Fy Nitsche-Newton {n['fx_over_fy']:.6f} ({len(n['newton_iterations'])} solves, "
      f"{n['newton_total']} Newton iterations, {n['seconds']:.1f} s), Nitsche fixed point "
      f"{f['fx_over_fy']:.6f} ({f['solves']} solves, {f['seconds']:.1f} s), nodal {d['fx_over_fy']:.6f} "
      f"({d['solves']} solves, {d['seconds']:.1f} s); gaps {r['expression_gap']:+.1e} (fit {fit:.1e}), "
      f"{r['formulation_gap']:+.1e} (bound {r['formulation_gap_bound']:g})")
EOF
# Another law's nodal JSON is refused before any solve (exit 2, one line
# naming the flag), not compared silently.
set +e
"$venv/bin/python" python/examples/getfem_nitsche.py --out "$out/refused" --psi 2 \
  --nodal-json "$out/getfem_contact.json" > "$out/refused.out" 2> "$out/refused.err"
status=$?
set -e
[ "$status" = 2 ] && [ "$(wc -l < "$out/refused.err")" = 1 ] && grep -q -- '--nodal-json: .*another law' "$out/refused.err" \
  || { echo "getfem: another law's --nodal-json not refused (exit $status)"; cat "$out/refused.err"; exit 1; }
