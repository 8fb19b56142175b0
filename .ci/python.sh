#!/usr/bin/env bash
# CI stage python-package: the Python package ke_friction. Installs the
# tools with pip, builds and installs the package with `pip install
# ./python` (maturin; it reuses the workspace's target directory), runs its
# tests (Dask's too: dask[distributed] is installed, and KEF_REQUIRE_DASK
# makes tests/test_dask.py fail rather than skip without it), the examples
# (headless) and the benchmark's accuracy check; then builds the abi3
# manylinux2014 wheel users install (linked by zig, from PyPI's ziglang),
# installs it into a fresh venv with no cargo on PATH and runs the tests
# against it.
# Runs from anywhere in a checkout; exits non-zero on any failure.
#
# Environment: KEFRIC (the CLI, for reference values and the export; default
# $CARGO_TARGET_DIR or target, /release/kefric, built if missing), PYTHON
# (default python3), KEF_TOPOGRAPHIES (the instruments' example files;
# default ../shared/topographies beside the checkout).
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

# ziglang: the zig that links the wheel against glibc 2.17 (below).
# SurfaceTopography: the oracle of tests/test_formats_a.py (the
# instruments' files read by its readers; a binary wheel, ~20 s when
# missing).
# pandas: tests/test_law.py reads `kefric law`'s CSV with its defaults.
"$py" -m pip install --quiet maturin ziglang pytest numpy scipy matplotlib pandas 'dask[distributed]' SurfaceTopography
export KEF_REQUIRE_DASK=1 KEF_REQUIRE_PANDAS=1

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
# The library's raw reading of the instruments' files (test_formats_a.py),
# and the files: ../shared/topographies beside the checkout unless
# KEF_TOPOGRAPHIES says otherwise (the test skips, saying so, without them).
cargo build --release --quiet -p ke-friction --features topography --example read_dump
export KEF_READ_DUMP=$target/release/examples/read_dump
export KEF_TOPOGRAPHIES=${KEF_TOPOGRAPHIES:-$root/../shared/topographies}
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

"$py" python/examples/dask_friction_map.py --size 400 --chunk 100 --surfaces 4 --out "$out/dask_map.npz"
test -s "$out/dask_map.npz" || { echo "python: the Dask example wrote no $out/dask_map.npz"; exit 1; }

# Speed ratios are not checked (two shared cores: timings swing 1.5x);
# the accuracy ratio against SciPy is.
"$py" python/bench.py --quick

# The wheel: abi3 (one wheel for CPython >= 3.9), manylinux2014 (glibc
# 2.17, the oldest the Rust compiler supports), checked by maturin's
# auditwheel step. Linked by zig (--zig) against glibc 2.17's symbols: a
# plain build on Debian 12 links hypot@GLIBC_2.35 and gets no lower than
# manylinux_2_35. maturin finds the zig of the pip package ziglang on PATH.
# --zig builds for an explicit --target, in a target directory of its own
# ($target/x86_64-unknown-linux-gnu): ~30 s cold on two cores, where a
# plain build reused pip install's artifacts.
# Installed into a fresh venv whose PATH has no cargo, so nothing can be
# built from source there.
t0=$SECONDS
wheels=$out/wheels
zig_dir=$("$py" -c 'import os, ziglang; print(os.path.dirname(ziglang.__file__))')
if ! PATH=$zig_dir:$PATH "$py" -m maturin build --release --zig --compatibility manylinux2014 \
  -m python/Cargo.toml --out "$wheels" > "$out/maturin-build.log" 2>&1; then
  cat "$out/maturin-build.log"; echo "python: maturin build failed"; exit 1
fi
grep -E 'Built wheel' "$out/maturin-build.log" || true
wheel=$(ls "$wheels"/ke_friction-*-cp39-abi3-manylinux2014_x86_64.manylinux_2_17_x86_64.whl 2>/dev/null | head -1)
[ -n "$wheel" ] || { echo "python: no abi3 manylinux2014 wheel in $wheels"; ls "$wheels"; exit 1; }
nocargo=$(printf '%s' "$PATH" | tr ':' '\n' | while read -r d; do [ -x "$d/cargo" ] || printf '%s:' "$d"; done)
nocargo=${nocargo%:}
venv=$out/wheel-venv
"$py" -m venv "$venv"
(
  export PATH=$venv/bin:$nocargo
  unset CARGO_HOME RUSTUP_HOME
  if command -v cargo > /dev/null; then echo "python: cargo is still on PATH"; exit 1; fi
  python -m pip install --quiet --only-binary ke-friction "$wheel" pytest pandas 'dask[distributed]'
  cd "$out"
  python -c "import ke_friction, sys; assert ke_friction.__file__.startswith(sys.prefix), ke_friction.__file__"
  python -m pytest -q -p no:cacheprovider "$root/python/tests"
)
echo "python: the wheel ($(basename "$wheel")), its venv and its tests took $((SECONDS - t0)) s"
