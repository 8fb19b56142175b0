#!/usr/bin/env bash
# CI stage python-package: the Python package ke_friction. Installs the
# tools with pip, builds and installs the package with `pip install
# ./python` (maturin; it reuses the workspace's target directory), runs its
# tests, the example (headless) and the benchmark's accuracy check.
# Runs from anywhere in a checkout; exits non-zero on any failure.
#
# Environment: KEFRIC (the CLI, for reference values and the export; default
# $CARGO_TARGET_DIR or target, /release/kefric, built if missing), PYTHON
# (default python3).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
py=${PYTHON:-python3}
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_ROOT_USER_ACTION=ignore MPLBACKEND=Agg

target=${CARGO_TARGET_DIR:-target}
case $target in /*) ;; *) target=$root/$target ;; esac
export KEFRIC=${KEFRIC:-$target/release/kefric}
if [ ! -x "$KEFRIC" ]; then
  echo "python: $KEFRIC is missing; building it"
  cargo build --release --quiet -p kefric
  [ -x "$KEFRIC" ] || { echo "python: no $KEFRIC after the build (set KEFRIC)"; exit 1; }
fi

"$py" -m pip install --quiet maturin pytest numpy scipy matplotlib

t0=$SECONDS
# --force-reinstall: the version does not change from one commit to the next.
"$py" -m pip install --quiet --force-reinstall --no-deps ./python
echo "python: pip install ./python took $((SECONDS - t0)) s"

out=$target/ci-python
rm -rf "$out" && mkdir -p "$out"
# The crafted table files the tests load (test_errors.py).
cargo build --release --quiet -p ke-friction --example crafted_tables
export KEF_CRAFTED_DIR=$out/crafted
"$target/release/examples/crafted_tables" "$KEF_CRAFTED_DIR" > /dev/null
# From outside python/, so that the installed package is what is tested
# (not python/pysrc, which has no native module).
(cd "$out" && "$py" -m pytest -q -p no:cacheprovider "$root/python/tests")

"$py" python/examples/friction_map.py "$out/friction_map.png"
test -s "$out/friction_map.png" || { echo "python: the example wrote no $out/friction_map.png"; exit 1; }
"$py" - "$out/friction_map.png" <<'EOF'
import sys
from matplotlib.image import imread
image = imread(sys.argv[1])
assert image.ndim == 3 and image.shape[0] > 500 and image.shape[1] > 500, image.shape
assert image[..., :3].std() > 0.05, "a blank image"
EOF

# Speed ratios are not checked (two shared cores: timings swing 1.5x);
# the accuracy ratio against SciPy is.
"$py" python/bench.py --quick
